"""Exact values as Python objects: rationals as ``fractions.Fraction``, surds as :class:`Surd`,
and the JSON records of the command line as :class:`Record` (attribute access, exact values)."""

from __future__ import annotations

import contextlib
import copy
import decimal
import html
import json
import numbers
import re
import sys
from fractions import Fraction
from typing import Any, Dict, Iterator, Mapping, Optional, Union

__all__ = ["Surd", "Record", "Report", "Exact", "exact", "as_text"]

_RATIONAL = re.compile(r"-?[0-9]+(?:/[0-9]+)?")


@contextlib.contextmanager
def _long_ints(text: str) -> Iterator[None]:
    """Lifts CPython's limit on the digits of ``int(str)`` (3.11+: 4300) while ``text`` is
    read, when it is that long; exact answers may have more digits than the limit."""
    get = getattr(sys, "get_int_max_str_digits", None)
    if get is None or len(text) < 4000:
        yield
        return
    before = get()
    sys.set_int_max_str_digits(0)
    try:
        yield
    finally:
        sys.set_int_max_str_digits(before)


def _fraction(text: str) -> Fraction:
    with _long_ints(text):
        return Fraction(text)


class Surd:
    """An exact real number of the form ``x + y*sqrt(d)`` (x, y rational, d a non-square
    rational), as the command line prints it: ``exact`` is the canonical text
    (``"sqrt(6)/3"``, ``"3/4 + sqrt(2)/2"``), ``decimal`` its correctly rounded decimal.

    ``float(s)`` is the nearest double, ``s.sympy()`` the SymPy expression (SymPy is imported
    only then). Two surds are equal when their canonical texts are (the form is canonical, so
    this is exact equality); a surd is never equal to a rational (a rational value is always
    given as a ``Fraction``).

    >>> s = Surd("sqrt(6)/3", "0.816496580927726032732428024902")
    >>> float(s)
    0.816496580927726
    >>> s.exact
    'sqrt(6)/3'
    """

    __slots__ = ("exact", "decimal", "squared")

    def __init__(self, exact: str, decimal: str, squared: Optional[Fraction] = None) -> None:
        self.exact = exact
        self.decimal = decimal
        #: The square of the value, when the command line gives it (``a_star``'s ``squared``).
        self.squared = squared

    def __float__(self) -> float:
        return float(self.decimal)

    def sympy(self) -> Any:
        """The value as an exact SymPy expression (``sqrt(6)/3``); needs SymPy installed."""
        import sympy

        return sympy.sympify(self.exact, rational=True)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Surd):
            return self.exact == other.exact
        if isinstance(other, (numbers.Rational, str)):
            return False if not isinstance(other, str) else self.exact == other
        return NotImplemented

    def __hash__(self) -> int:
        return hash(("Surd", self.exact))

    def __repr__(self) -> str:
        return f"Surd({self.exact!r})"

    def __str__(self) -> str:
        return self.exact

    def _repr_latex_(self) -> str:
        return f"${surd_latex(self.exact)}$"


def surd_latex(exact: str) -> str:
    """LaTeX of an exact value in the command line's notation: ``3/5`` as ``\\frac{3}{5}``,
    ``sqrt(6)/3`` as ``\\frac{\\sqrt{6}}{3}``; SymPy's typesetting when SymPy is installed."""
    try:
        import sympy

        return sympy.latex(sympy.sympify(exact, rational=True))
    except Exception:  # SymPy missing, or a number too long for it: plain, still exact
        pass
    m = re.fullmatch(r"(-?)([0-9]+)/([0-9]+)", exact)
    if m:
        return f"{m.group(1)}\\frac{{{m.group(2)}}}{{{m.group(3)}}}"
    return re.sub(r"sqrt\(([^()]*)\)", r"\\sqrt{\1}", exact).replace("*", " ")


#: What an exact value of a result is: a rational (``Fraction``) or a surd.
Exact = Union[Fraction, Surd]


def exact(value: Mapping[str, Any]) -> Exact:
    """The exact number of a JSON value ``{"exact": ..., "decimal": ...}``: a ``Fraction``
    when ``exact`` is an integer or ``p/q``, else a :class:`Surd`.

    >>> exact({"exact": "-1/5", "decimal": "-0.2"})
    Fraction(-1, 5)
    """
    text = value["exact"]
    if _RATIONAL.fullmatch(text):
        return _fraction(text)
    squared = value.get("squared")
    return Surd(
        text,
        value["decimal"],
        _fraction(squared) if isinstance(squared, str) and _RATIONAL.fullmatch(squared) else None,
    )


#: The keys a JSON value of the CLI may hold beside ``exact`` and ``decimal`` (``a_star``'s
#: bounds and placement, ``rod_omega_max``'s arm).
_VALUE_KEYS = frozenset(
    ["exact", "decimal", "squared", "lower", "upper", "within_rod", "placement", "threshold_M",
     "arm", "argmax", "other_arm"]
)


def _is_value(x: Any) -> bool:
    """Whether ``x`` is a JSON value of the CLI (``{"exact", "decimal", ...}``), not a record
    that merely holds those keys among others (a checked claim)."""
    return (
        isinstance(x, dict)
        and isinstance(x.get("exact"), str)
        and isinstance(x.get("decimal"), str)
        and x.keys() <= _VALUE_KEYS
    )


def _convert(x: Any) -> Any:
    if _is_value(x):
        return exact(x)
    if isinstance(x, dict):
        return Record(x)
    if isinstance(x, list):
        return [_convert(v) for v in x]
    return x


class Record:
    """A JSON object of the command line with attribute access: ``r.omega`` is the exact value
    of the key ``omega`` (a ``Fraction`` or a :class:`Surd` for ``{"exact", "decimal"}``
    values), a nested object is a ``Record``, anything else as in the JSON. ``r["key"]`` is the
    JSON value itself, and :meth:`to_dict` the whole object exactly as the CLI prints it."""

    __slots__ = ("_data",)

    def __init__(self, data: Dict[str, Any]) -> None:
        object.__setattr__(self, "_data", data)

    def __getattr__(self, name: str) -> Any:
        data = object.__getattribute__(self, "_data")
        if name in data:
            return _convert(data[name])
        raise AttributeError(f"no {name!r} in this result (keys: {', '.join(data)})")

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("results are read-only")

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __contains__(self, key: object) -> bool:
        return key in self._data

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def keys(self) -> Any:
        """The JSON keys, in the CLI's order."""
        return self._data.keys()

    def __dir__(self) -> Any:
        return list(super().__dir__()) + [k for k in self._data if k.isidentifier()]

    def to_dict(self) -> Dict[str, Any]:
        """The result as the CLI's JSON (``--json``), as a new dict: ``json.dumps`` of it is
        the CLI's output up to whitespace."""
        return copy.deepcopy(self._data)

    def to_json(self, indent: Optional[int] = 2) -> str:
        """The JSON text, as the CLI prints it with ``--json`` (2-space indent)."""
        return json.dumps(self._data, indent=indent, ensure_ascii=False)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Record):
            return self._data == other._data
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = []
        for k, v in self._data.items():
            if _is_value(v):
                shown.append(f"{k}={v['exact']}")
        inner = ", ".join(shown) if shown else ", ".join(self._data)
        return f"{type(self).__name__}({inner})"

    def _value_rows(self) -> Iterator[tuple]:
        """(name, exact, decimal) of every exact value, nested ones named ``outer.inner``."""

        def walk(prefix: str, data: Dict[str, Any]) -> Iterator[tuple]:
            for k, v in data.items():
                name = f"{prefix}{k}"
                if _is_value(v):
                    yield name, v["exact"], v["decimal"]
                elif isinstance(v, dict) and k != "scene":
                    yield from walk(name + ".", v)

        return walk("", self._data)

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td><code>{html.escape(n)}</code></td><td>{html.escape(e)}</td>"
            f"<td>{html.escape(_short(d))}</td></tr>"
            for n, e, d in self._value_rows()
        )
        return (
            f"<table><caption>{html.escape(type(self).__name__)}</caption>"
            "<tr><th>quantity</th><th>exact</th><th>decimal</th></tr>"
            f"{rows}</table>"
        )

    def _repr_latex_(self) -> str:
        lines = [
            f"\\mathrm{{{_latex_name(n)}}} &= {surd_latex(e) if len(e) < 200 else _short(d)}"
            for n, e, d in self._value_rows()
        ]
        return "$\\begin{aligned}" + " \\\\ ".join(lines) + "\\end{aligned}$"


def _latex_name(name: str) -> str:
    return name.replace("_", r"\_")


def _short(decimal_text: str) -> str:
    return decimal_text if len(decimal_text) <= 20 else decimal_text[:18] + "…"


#: The library's limit on the digits of one number (``number::MAX_DIGITS``).
MAX_DIGITS = 10_000


def _int_text(name: str, n: int) -> str:
    """``n`` in decimal, past CPython's 4,300-digit guard on ``str(int)`` up to the library's
    own limit; a longer one is refused with the library's message, before it is converted."""
    if n.bit_length() > 33_300:  # more than 10,000 digits for certain (10^10000 < 2^33220)
        raise ValueError(f"{name}: more than {MAX_DIGITS} digits (limit on digits per number)")
    get = getattr(sys, "get_int_max_str_digits", None)
    if get is None or n.bit_length() < 14_000:
        return str(n)
    before = get()
    sys.set_int_max_str_digits(0)
    try:
        return str(n)
    finally:
        sys.set_int_max_str_digits(before)


def as_text(name: str, value: Any, symbols: bool = False) -> str:
    """The text the library parses for one input ``name``: a ``str`` as it is (``"3/7"``,
    ``"0.25"``, ``"1.5e-3"``, ``"100 g"``); an ``int`` or any rational (``Fraction``,
    ``decimal.Decimal``, a SymPy ``Rational``) exactly as ``p/q``. A ``float`` is refused: it
    is a binary approximation, not the number written (``0.1`` is not 1/10); pass the number
    as a string or a ``Fraction``. With ``symbols``, a SymPy expression is passed as its text
    (``**`` written ``^``)."""
    if isinstance(value, str):
        try:
            value.encode("utf-8")
        except UnicodeEncodeError:
            raise ValueError(f"{name}: not text the library can read (a lone surrogate)") from None
        return value
    if isinstance(value, bool):
        raise ValueError(f"{name}: expected a number, got the bool {value}")
    if isinstance(value, numbers.Integral):
        return _int_text(name, int(value))
    if isinstance(value, numbers.Real) and not isinstance(value, numbers.Rational):
        raise ValueError(
            f"{name}: the float {value!r} is not exact (a binary approximation); "
            f"pass the number as a string ('{value!r}') or a fractions.Fraction"
        )
    if isinstance(value, numbers.Rational):
        return f"{_int_text(name, int(value.numerator))}/{_int_text(name, int(value.denominator))}"
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            raise ValueError(f"{name}: expected a finite number, got {value}")
        # Its own text ("1E+999999999"), which the library reads exactly within its limits:
        # Fraction(value) would first build every digit of a huge exponent.
        return str(value)
    if symbols and type(value).__module__.startswith("sympy"):
        return str(value).replace("**", "^")
    raise ValueError(
        f"{name}: expected a number as a string ('3/7', '0.25'), an int or a Fraction, "
        f"got {type(value).__name__}"
    )


class Report(Record):
    """A :class:`Record` that also carries the CLI's text report (``str()``) and its verdict
    (the CLI's exit 0): the base of ``Solution``, ``Check`` and ``Impact``."""

    __slots__ = ("_verdict", "_text")

    def __init__(self, data: Dict[str, Any], verdict: bool, text: str) -> None:
        super().__init__(data)
        object.__setattr__(self, "_verdict", verdict)
        object.__setattr__(self, "_text", text)

    def __str__(self) -> str:
        return self._text
