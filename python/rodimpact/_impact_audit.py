"""``audit_impacts``: the audit of ``rodimpact impact --batch``, as a DataFrame."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, List, Mapping, Optional

from . import _native
from ._audit import _option

__all__ = ["audit_impacts", "ImpactAuditSummary"]


class ImpactAuditSummary:
    """What ``rodimpact impact --batch`` prints on standard error: ``str(summary)`` is that
    text, ``data`` the JSON ``--summary-json`` writes (``scenes``, ``claimed``, ``matched``,
    ``closest``, ``findings``, ``passed``) as a dict, ``ok`` the CLI's exit 0.
    ``DataFrame.attrs["summary"]``."""

    __slots__ = ("text", "data", "ok")

    def __init__(self, text: str, data: Dict[str, Any], ok: bool) -> None:
        self.text = text
        self.data = data
        self.ok = ok

    @property
    def scenes(self) -> int:
        """The number of scenes audited."""
        return int(self.data["scenes"])

    @property
    def findings(self) -> Dict[str, List[str]]:
        """Each finding's scenes by the finding's name: the first 100 ids of each (the
        count of all is ``data["findings"][name]["count"]``)."""
        return {name: list(f["scenes"]) for name, f in self.data["findings"].items()}

    def __str__(self) -> str:
        return self.text

    def __contains__(self, text: str) -> bool:
        return text in self.text

    def __repr__(self) -> str:
        return f"ImpactAuditSummary(ok={self.ok}, scenes={self.scenes})"

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(self.text)}</pre>"


#: The columns of the result, in order.
COLUMNS = (
    "id",
    "engine",
    "contacts",
    "closest",
    "matches",
    "diagnosis",
    "rel_error",
    "equal",
    "error_split",
    "exact",
)


def audit_impacts(
    source: Any,
    *,
    rtol: Any = None,
    atol: Any = None,
    ulps: Any = None,
    float_format: Optional[str] = None,
    engine: Optional[str] = None,
    expect: Any = None,
) -> Any:
    """Audits an engine's output on planar impacts, as ``rodimpact impact --batch``: each scene
    answered exactly under every law or model, under the engines' own laws (``lcp-newton``,
    ``lcp-poisson``, ``split``, ``pgs:K``) and by the claiming engine's step replayed exactly,
    and the engine's claimed state compared with each.

    ``source``: a path to a JSON-lines file (one scene per line, with its ``"claimed"``
    state), or an iterable of scenes as dicts (the same structure; numbers as strings, read
    exactly). ``rtol`` (the error in energy, ``sqrt(K(claim - exact)/K(before))``, default
    1e-9), ``atol`` (per component), ``ulps`` with ``float_format`` ``"f32"``/``"f64"``: when a
    claim matches. ``engine``: compare every scene with this engine's step (``"pymunk-7"``,
    ``"box2d-2.3:scale=16"``, ``"bullet-3"``, ..., or ``"all"``) instead of the step of the
    engine each claim names. ``expect``: a CSV file of known findings (``id,finding``), as
    ``--expect``: the summary's ``ok`` is then false only on a finding the file does not allow.

    Returns one row per scene (a pandas ``DataFrame``, a list of dicts without pandas) with the
    columns ``id``, ``engine``, ``contacts``, ``closest`` (the answer the claim is nearest),
    ``matches`` (the answers within the tolerance, a list), ``diagnosis``, ``rel_error`` (a dict
    of each answer's error, floats), ``equal`` (the answers equal to another, by its first
    name), ``error_split`` (where the engine's step is replayed: ``of_law``,
    ``of_iterations``, ``of_rounding`` as floats, with the profile and laws named; ``None``
    otherwise) and ``exact`` (every answer's bodies, exact strings). ``attrs["summary"]`` (or
    the list's ``summary`` attribute) is an :class:`ImpactAuditSummary`.

    Raises ``ValueError`` with the CLI's message at the first bad line (``scenes: line 2:
    body[0].mass: must be > 0, got -1``) or bad option.

    >>> import rodimpact
    >>> scene = {"id": "wall", "body": [{"name": "p", "mass": "1", "velocity": ["1", "0"]},
    ...          {"name": "wall", "fixed": True}],
    ...          "contact": [{"bodies": ["p", "wall"], "point": ["0", "0"], "normal": ["-1", "0"]}],
    ...          "claimed": {"bodies": {"p": {"velocity": ["-1", "0"], "omega": "0"}}}}
    >>> rows = rodimpact.audit_impacts([scene])
    >>> list(rows["diagnosis"]) if hasattr(rows, "columns") else [r["diagnosis"] for r in rows]
    ['ok']
    """
    options = dict(
        rtol=_option("rtol", rtol),
        atol=_option("atol", atol),
        ulps=_option("ulps", ulps),
        float=float_format,
        engine=engine,
        expect=os.fsdecode(expect) if expect is not None else None,
    )
    if isinstance(source, (str, bytes, os.PathLike)):
        lines, summary, text, ok = _native.impact_audit_json(
            os.fsdecode(source), None, "scenes", **options
        )
    elif isinstance(source, Mapping):
        raise ValueError(
            "scenes: expected a path or an iterable of scenes, got one scene (wrap it in a list)"
        )
    else:
        lines, summary, text, ok = _native.impact_audit_json(
            None, _json_lines(source), "scenes", **options
        )
    rows = [_row(json.loads(line)) for line in lines]
    result = _frame(rows)
    _attach(result, ImpactAuditSummary(text, json.loads(summary), ok))
    return result


def _json_lines(scenes: Iterable[Any]) -> str:
    out = []
    for number, scene in enumerate(scenes, start=1):
        if not isinstance(scene, Mapping):
            raise ValueError(
                f"scenes: line {number}: expected a scene as a dict, got {type(scene).__name__}"
            )
        try:
            out.append(json.dumps(scene, separators=(",", ":")))
        except TypeError as e:
            raise ValueError(f"scenes: line {number}: {e} (give numbers as strings)") from None
    return "\n".join(out) + "\n"


def _floats(values: Mapping[str, str]) -> Dict[str, float]:
    return {name: float(value) for name, value in values.items()}


def _row(audit: Mapping[str, Any]) -> Dict[str, Any]:
    split = audit.get("error_split")
    if split is not None:
        split = {
            key: (float(value) if key.startswith("of_") else value) for key, value in split.items()
        }
    return {
        "id": audit.get("id"),
        "engine": audit.get("engine"),
        "contacts": audit.get("contacts"),
        "closest": audit.get("closest"),
        "matches": list(audit.get("matches", [])),
        "diagnosis": audit.get("diagnosis"),
        "rel_error": _floats(audit.get("rel_error", {})),
        "equal": audit.get("equal", {}),
        "error_split": split,
        "exact": audit.get("exact", {}),
    }


class _Rows(list):
    """The rows as a list of dicts, where pandas is not installed; ``summary`` the summary."""

    summary: Optional[ImpactAuditSummary] = None


def _frame(rows: List[Dict[str, Any]]) -> Any:
    try:
        import pandas as pd
    except ImportError:  # pragma: no cover - depends on the environment
        return _Rows(rows)
    return pd.DataFrame(rows, columns=list(COLUMNS))


def _attach(result: Any, summary: ImpactAuditSummary) -> None:
    if isinstance(result, _Rows):
        result.summary = summary
    else:
        result.attrs["summary"] = summary
