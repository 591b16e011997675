"""``audit``: the batch audit of ``rodimpact batch``, streamed, as a DataFrame."""

from __future__ import annotations

import math
import numbers
import os
import struct
from fractions import Fraction
from typing import Any, Dict, List, Optional, Union

from . import _native

__all__ = ["audit", "AuditSummary"]

#: Rows handed to the library per piece when a table is fed.
_FEED_ROWS = 1 << 15


class AuditSummary:
    """What ``rodimpact batch`` prints on standard error after the rows: ``str(summary)`` is
    that text; ``ok`` is the CLI's exit 0 (no wrong claim, every law held, no finding),
    ``rows`` the number of rows, ``passed_through`` the input columns passed through,
    ``agreement`` the rule claims agree by, in words (``None`` for the default).
    ``DataFrame.attrs["summary"]``."""

    __slots__ = ("text", "ok", "rows", "passed_through", "agreement")

    def __init__(
        self, text: str, ok: bool, rows: int, passed_through: List[str], agreement: Optional[str]
    ) -> None:
        self.text = text
        self.ok = ok
        self.rows = rows
        self.passed_through = list(passed_through)
        self.agreement = agreement

    def __str__(self) -> str:
        return self.text

    def __contains__(self, text: str) -> bool:
        return text in self.text

    def __repr__(self) -> str:
        return f"AuditSummary(ok={self.ok}, rows={self.rows})"

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(self.text)}</pre>"


def _option(name: str, value: Any) -> Optional[str]:
    """A tolerance as the library's text: a string as it is, an int or a rational exactly, a
    float by its shortest repr (``1e-9`` is read as 1/10^9: the number written)."""
    if value is None:
        return None
    if isinstance(value, bool):
        raise ValueError(f"{name}: expected a number, got the bool {value}")
    if isinstance(value, str):
        return value
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Rational):
        return f"{value.numerator}/{value.denominator}"
    if isinstance(value, float):
        return repr(value)
    raise ValueError(f"{name}: expected a number, got {type(value).__name__}")


def audit(
    source: Any,
    *,
    rtol: Any = None,
    ulps: Any = None,
    float_format: Optional[str] = None,
    atol: Any = None,
    backend: str = "exact",
    jobs: Optional[int] = None,
) -> Any:
    """Audits many scenes, as ``rodimpact batch``: each row's scene solved exactly, its claimed
    ``v``, ``V``, ``omega`` (a physics engine's output, say) compared and diagnosed.

    ``source``: a path to a CSV file (read by the library itself, streamed), a pandas
    ``DataFrame`` or a pyarrow ``Table``, whose columns are named as the CSV's header: scene
    columns among ``m, M, l, a, v0, rod, e, pivot`` (and the oblique ``v0t, mu, radius, spin,
    rod-v, rod-vt, rod-omega``), claims ``v, V, omega, J, energy_before, energy_after``, and
    any other columns, passed through. A table's cells are sent as text: strings as they are,
    integers exactly, floats by their shortest repr (the number an engine's CSV would hold),
    ``Fraction`` objects as ``p/q``, missing values as empty cells (the default, or no claim).

    ``rtol`` (``--rtol``), or ``ulps`` with ``float_format`` ``"f32"``/``"f64"`` (``--ulps``,
    ``--float``), set when a claim agrees; ``atol`` (``--atol``) an absolute floor in the scene's
    units; ``backend`` ``"exact"`` or ``"f64"``; ``jobs`` worker threads (default: one per core).
    Tolerances may be strings, ints, Fractions or floats (a float is read as its shortest
    repr: ``1e-9`` is 1/10^9).

    Returns the CLI's output rows as a pandas ``DataFrame`` whenever pandas is installed (a
    pyarrow ``Table`` without pandas, a list of dicts of text without either; a table as the
    source needs pyarrow): the input's columns (a DataFrame's own columns and index as they were; a
    file's as text), then the appended ones: exact values as text (``"3/5"``; ``Fraction(x)``
    reads one), ``laws_held`` and ``*_ok`` as booleans, ``*_rel_error`` and ``energy_change``
    as floats (missing where the CLI writes ``-`` or nothing), ``diagnosis`` as text.
    ``result.attrs["summary"]`` is the CLI's summary (an :class:`AuditSummary`).

    Raises ``ValueError`` with the CLI's message at the first bad row (``row 2, column M: must
    be > 0, got -1``) or bad option.
    """
    options = dict(
        backend=backend,
        rtol=_option("rtol", rtol),
        ulps=_option("ulps", ulps),
        float=float_format,
        atol=_option("atol", atol),
        jobs=jobs,
    )
    if isinstance(source, (str, bytes, os.PathLike)):
        path = os.fsdecode(source)
        stream = _native.AuditStream.from_path(path, **options)
        return _collect(stream, feed=None, original=None)
    table, original = _as_table(source)
    for name in table.column_names:
        if "," in name or "\n" in name:
            raise ValueError(f"header: column name {name!r} holds a comma or a line break")
    stream = _native.AuditStream.from_header(",".join(table.column_names) + "\n", **options)
    return _collect(stream, feed=table, original=original)


def _pyarrow() -> Any:
    try:
        import pyarrow
        import pyarrow.compute  # noqa: F401
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "audit of a table needs pyarrow (python3 -m pip install pyarrow pandas)"
        ) from e
    return pyarrow


def _as_table(source: Any) -> Any:
    """The pyarrow Table of a DataFrame or Table, and the DataFrame itself (to hand back its
    columns unchanged)."""
    kind = type(source)
    if not any(c.__module__.split(".")[0] in ("pandas", "pyarrow") for c in kind.__mro__):
        raise TypeError(
            f"audit: expected a path, a pandas DataFrame or a pyarrow Table, got {kind.__name__}"
        )
    pa = _pyarrow()
    if isinstance(source, pa.Table):
        return source, None
    if isinstance(source, pa.RecordBatch):
        return pa.Table.from_batches([source]), None
    try:
        import pandas as pd
    except ImportError:
        pd = None
    if pd is not None and isinstance(source, pd.DataFrame):
        frame = source
        columns = {}
        for name in frame.columns:
            if not isinstance(name, str):
                raise ValueError(f"header: column names must be strings, got {name!r}")
            col = frame[name]
            if col.dtype == object:
                col = col.map(_cell)
            columns[name] = col
        converted = pd.DataFrame(columns, index=frame.index)
        return pa.Table.from_pandas(converted, preserve_index=False), frame
    raise ValueError(
        f"audit: expected a path, a pandas DataFrame or a pyarrow Table, got {type(source).__name__}"
    )


def _cell(x: Any) -> Optional[str]:
    """One cell of an object column as the text the library reads."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return None
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, str):
        return x
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, numbers.Rational):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, float):
        return repr(x)
    return str(x)


def _csv_piece(batch: Any) -> bytes:
    """The rows of a record batch as CSV lines (no header, no quoting: the batch reader splits
    at every comma, so a cell holding one makes its row too long, which the library refuses;
    :func:`_separators` then names the cell)."""
    pa = _pyarrow()
    pc = pa.compute
    texts = []
    for name, column in zip(batch.schema.names, batch.columns):
        if pa.types.is_dictionary(column.type):
            column = column.dictionary_decode()
        texts.append(column.cast(pa.large_string()))
    lines = pc.binary_join_element_wise(
        *texts, pa.scalar(",", pa.large_string()), null_handling="replace", null_replacement=""
    )
    lines = pc.binary_join_element_wise(
        lines, pa.scalar("", pa.large_string()), pa.scalar("\n", pa.large_string())
    )
    return _data_of(lines) if len(lines) else b""


def _separators(table: Any) -> None:
    """Raises the ValueError naming the first text cell of ``table`` that holds a comma or a
    line break (looked for only after the library found a row of the wrong length: a scan of
    every cell would cost as much as the audit)."""
    pa = _pyarrow()
    pc = pa.compute
    for name, column in zip(table.column_names, table.columns):
        if pa.types.is_string(column.type) or pa.types.is_large_string(column.type):
            found = pc.match_substring_regex(column, "[,\\n\\r]")
            if pc.any(found).as_py():
                row = pc.index(found, True).as_py() + 1
                raise ValueError(f"row {row}, column {name}: a cell holds a comma or a line break")


def _data_of(strings: Any) -> bytes:
    """The bytes of a string array's values, one after another."""
    pa = _pyarrow()
    strings = strings.cast(pa.large_string()) if strings.type != pa.large_string() else strings
    _, offsets, data = strings.buffers()
    if data is None:
        return b""
    (first,) = struct.unpack_from("<q", offsets, strings.offset * 8)
    (last,) = struct.unpack_from("<q", offsets, (strings.offset + len(strings)) * 8)
    return data.slice(first, last - first).to_pybytes()


_TRUE_FALSE = {"true": True, "false": False}


def _typed(name: str, column: Any) -> Any:
    """An appended column with its type: booleans, floats (the rounded relative errors and
    energy changes), text for the exact values and the diagnosis."""
    pa = _pyarrow()
    pc = pa.compute
    if name == "laws_held" or name.endswith("_ok"):
        return pc.if_else(
            pc.equal(column, "true"), True, pc.if_else(pc.equal(column, "false"), False, None)
        )
    if name.endswith("_rel_error") or name == "energy_change" or name.endswith("_f64"):
        missing = pc.or_(pc.equal(column, "-"), pc.equal(column, ""))
        cleaned = pc.utf8_ltrim(pc.if_else(missing, None, column), characters="+")
        return pc.cast(cleaned, pa.float64())
    return column


def _collect(stream: Any, feed: Any, original: Any) -> Any:
    names: List[str] = stream.columns
    blocks: List[List[Any]] = [[] for _ in names]
    try:
        pa = _pyarrow()
    except ImportError:
        pa = None
    raw: List[Any] = []

    def take(block: Any) -> None:
        rows, columns = block
        if pa is None:
            raw.append(block)
            return
        for k, (data, offsets) in enumerate(columns):
            blocks[k].append(
                pa.Array.from_buffers(
                    pa.large_string(), rows, [None, pa.py_buffer(offsets), pa.py_buffer(data)]
                )
            )

    if feed is not None:
        for batch in feed.to_batches(max_chunksize=_FEED_ROWS):
            if not stream.feed(_csv_piece(batch)):
                break
            while (block := stream.next_block(False)) is not None:
                take(block)
        stream.close()
    while (block := stream.next_block(True)) is not None:
        take(block)
    try:
        text, ok, rows = stream.finish()  # the first bad row's ValueError, after its good rows
    except ValueError as error:
        if feed is not None and "cells, got" in str(error):
            _separators(feed)
        raise
    summary = AuditSummary(text, ok, rows, stream.passed_through, stream.agreement)
    if pa is None:
        return _without_pyarrow(names, raw, summary)
    columns = {}
    for k, name in enumerate(names):
        chunked = pa.chunked_array(blocks[k], type=pa.large_string())
        if k < stream.input_width:
            if feed is None:  # a file's own columns, as text
                columns[name] = chunked
            continue  # a table's own columns are handed back as they were
        columns[name] = _typed(name, chunked)
    table = pa.table(columns)
    try:
        import pandas as pd
    except ImportError:
        if feed is not None:
            table = _join_tables(feed, table)
        return _with_summary_table(table, summary)
    # Booleans as pandas' nullable "boolean" whether or not a cell is missing, so that a
    # column's dtype does not depend on the data.
    out = table.to_pandas(types_mapper={pa.bool_(): pd.BooleanDtype()}.get)
    if feed is not None:
        base = original if original is not None else feed.to_pandas()
        out.index = base.index
        out = pd.concat([base, out], axis=1)
    out.attrs["summary"] = summary
    return out


def _join_tables(left: Any, right: Any) -> Any:
    for name, column in zip(right.column_names, right.columns):
        left = left.append_column(name, column)
    return left


def _with_summary_table(table: Any, summary: AuditSummary) -> Any:
    meta = dict(table.schema.metadata or {})
    meta[b"rodimpact.summary"] = str(summary).encode()
    return table.replace_schema_metadata(meta)


def _without_pyarrow(names: List[str], raw: List[Any], summary: AuditSummary) -> Any:
    """The rows of a file's audit without pyarrow: a pandas DataFrame typed as with pyarrow
    (text, nullable booleans, floats) when pandas is installed, else a list of dicts of text."""
    columns: List[List[str]] = [[] for _ in names]
    for count, blocks in raw:
        for k, (data, offsets) in enumerate(blocks):
            ends = [int.from_bytes(offsets[8 * i : 8 * i + 8], "little") for i in range(count + 1)]
            columns[k].extend(data[ends[i] : ends[i + 1]].decode() for i in range(count))
    try:
        import pandas as pd
    except ImportError:
        rows = len(columns[0]) if columns else 0
        return [{name: columns[k][i] for k, name in enumerate(names)} for i in range(rows)]
    typed = {name: _typed_by_pandas(pd, name, column) for name, column in zip(names, columns)}
    out = pd.DataFrame(typed, columns=names)
    out.attrs["summary"] = summary
    return out


def _typed_by_pandas(pd: Any, name: str, cells: List[str]) -> Any:
    """An output column as pandas holds it, with the types :func:`_typed` gives through
    pyarrow: booleans (``laws_held``, ``*_ok``) as nullable ``boolean``, the rounded relative
    errors and energy changes as floats (missing where the CLI writes ``-`` or nothing), the
    rest as text."""
    if name == "laws_held" or name.endswith("_ok"):
        return pd.array([_TRUE_FALSE.get(c) for c in cells], dtype="boolean")
    if name.endswith("_rel_error") or name == "energy_change" or name.endswith("_f64"):
        return pd.array(
            [None if c in ("-", "") else float(c.lstrip("+")) for c in cells], dtype="float64"
        )
    return pd.array(cells, dtype=object)
