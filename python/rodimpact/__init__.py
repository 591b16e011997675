"""rodimpact: exact answers to rigid-body impact, from Python.

A projectile of mass ``m`` and speed ``v0`` strikes a rod (mass ``M``, half-length ``l``) lying
at rest on a frictionless table, perpendicularly, at distance ``a`` from its centre; and any
planar impact given as bodies and contacts. Every answer is exact: rationals are
``fractions.Fraction``, square roots are :class:`Surd`. The functions are those of the command
line, computed by the same Rust library, and each result's ``to_dict()`` is the command line's
JSON:

>>> import rodimpact
>>> rodimpact.solve(m=1, M=1, a="1/2").omega
Fraction(12, 11)

- :func:`solve` one scene (``rodimpact solve --json``)
- :func:`formula` the answer in symbols (``rodimpact formula``), SymPy expressions when SymPy
  is installed
- :func:`check` published answers against the exact ones (``rodimpact check``)
- :func:`impact` any planar impact from a TOML file or a dict (``rodimpact impact``)
- :func:`audit` many scenes, an engine's output audited (``rodimpact batch``), as a pandas
  DataFrame
- :func:`audit_impacts` an engine's output on planar impacts audited (``rodimpact impact
  --batch``), against the physical laws, the engines' own laws and the engine's replayed step

Numbers are given as ``int``, ``Fraction`` or strings (``"3/7"``, ``"0.25"``, ``"1.5e-3"``,
``"100 g"``), read exactly; a Python ``float`` is refused (it is a binary approximation: pass
``"0.1"``, not ``0.1``). Bad input raises ``ValueError`` with the command line's message
(``"M: must be > 0, got -1"``). The full guide is ``docs/python.md``.
"""

from __future__ import annotations

import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Tuple, Union

from . import _native
from ._values import Exact, Record, Report, Surd, as_text, exact
from ._audit import AuditSummary, audit
from ._impact_audit import ImpactAuditSummary, audit_impacts

__all__ = [
    "solve",
    "formula",
    "check",
    "impact",
    "audit",
    "audit_impacts",
    "Solution",
    "Formulas",
    "Check",
    "Impact",
    "Record",
    "AuditSummary",
    "ImpactAuditSummary",
    "Surd",
    "Exact",
    "exact",
    "SCENE_KEYS",
]

__version__ = "0.1.0"

#: The scene's keyword arguments, in the order a scene is read, each with the command-line
#: flag it stands for: ``from_end`` is ``--from-end``, ``rod_v`` is ``--rod-v``, ...
SCENE_KEYS: Tuple[str, ...] = tuple(name.replace("-", "_") for name, _, _ in _native.scene_keys())


def _pairs(scene: Mapping[str, Any], symbols: bool = False) -> List[Tuple[str, str]]:
    """The scene's ``(flag, text)`` pairs for the library, in the order of :data:`SCENE_KEYS`;
    ``None`` means not given."""
    unknown = [k for k in scene if k not in SCENE_KEYS]
    if unknown:
        raise TypeError(
            f"unexpected keyword argument {unknown[0]!r} (scene inputs: {', '.join(SCENE_KEYS)})"
        )
    return [
        (key.replace("_", "-"), as_text(key, scene[key], symbols))
        for key in SCENE_KEYS
        if scene.get(key) is not None
    ]


def _digits(digits: Any) -> Optional[str]:
    if digits is None:
        return None
    if isinstance(digits, bool) or not isinstance(digits, (int, str)):
        raise ValueError(f"digits: must be a whole number from 1 to 10000, got {digits!r}")
    return str(digits)


class Solution(Report):
    """The whole answer to one scene, as ``rodimpact solve --json`` gives it.

    Attributes are the JSON keys with exact values: ``v``, ``V``, ``omega`` (``Fraction``),
    ``energy.before``/``after``/``lost``, ``residuals``, ``a_star`` (a :class:`Surd`, or a
    ``Fraction`` when rational, with ``.squared``), ``omega_max``, ``argmax``, ...; only the
    keys that apply to the scene are present (``pivot_impulse`` on a pivot; ``vt``, ``Vt``,
    ``contact`` for an oblique scene). ``str()`` is the CLI's text report, ``to_dict()`` its
    JSON, and Jupyter shows a table.
    """

    __slots__ = ()

    @property
    def laws_hold(self) -> bool:
        """Whether every conservation law that applies held exactly (the CLI's exit 0)."""
        return self._verdict


def solve(m: Any = None, M: Any = None, *, digits: Any = None, **scene: Any) -> Solution:
    """Solves one scene exactly, as ``rodimpact solve --json``.

    Scene inputs (each an ``int``, a ``Fraction`` or a string such as ``"3/7"``, ``"0.25"``,
    ``"1.5e-3"`` or ``"100 g"``; ``None`` or absent for the default):
    ``m`` projectile mass and ``M`` rod mass (required), ``l`` half-length (1) or ``length``
    (2l), ``a`` signed impact distance from the centre (``l``, the end) or ``from_end``,
    ``v0`` projectile speed (1), ``rod`` (``"uniform"``, ``"dumbbell"``, ``"rg=R"``,
    ``"I=X"``), ``e`` restitution (1), ``pivot`` position of a fixed pivot; oblique and
    frictional scenes: ``v0t``, ``mu``, ``radius``, ``spin``, ``rod_v``, ``rod_vt``,
    ``rod_omega``. ``digits``: significant digits of the decimals (at least 30) and of the
    a* bounds.

    Raises ``ValueError`` with the CLI's message for a bad input.

    >>> s = solve(m=1, M=1)
    >>> s.v, s.V, s.omega
    (Fraction(3, 5), Fraction(2, 5), Fraction(6, 5))
    >>> s.a_star
    Surd('sqrt(6)/3')
    """
    pairs = _pairs({"m": m, "M": M, **scene})
    data, laws_hold, text = _native.solve_json(pairs, _digits(digits))
    return Solution(_loads(data), laws_hold, text)


def _loads(text: str) -> Dict[str, Any]:
    import json

    return json.loads(text)


class Formulas(Record):
    """The exact answer of a scene as formulas in its free symbols (``rodimpact formula``).

    ``f.omega``, ``f.v``, ... are SymPy expressions when SymPy is installed (symbols named as
    in the command line: ``m M l a v0 e p I r``, plain ``sympy.Symbol``), else the formula's
    text; ``f.free_symbols`` and ``f.defaults`` as in the JSON; ``f.text(key)`` and
    ``f.latex(key)`` a formula's text and LaTeX; ``to_dict()`` is ``formula --format json``;
    ``str()`` the text report; Jupyter typesets the whole answer (``_repr_latex_``).
    """

    __slots__ = ("_latex", "_text")

    def __init__(self, data: Dict[str, Any], latex: str, text: str) -> None:
        super().__init__(data)
        object.__setattr__(self, "_latex", latex)
        object.__setattr__(self, "_text", text)

    def __getattr__(self, name: str) -> Any:
        data = object.__getattribute__(self, "_data")
        value = data.get(name)
        if isinstance(value, dict) and "text" in value:
            return _expression(value["text"], data.get("free_symbols", []))
        return super().__getattr__(name)

    def text(self, key: str) -> str:
        """The formula ``key`` (``"omega"``, ...) in the CLI's syntax (``+ - * / ^ sqrt()``)."""
        return self._data[key]["text"]

    def latex(self, key: str) -> str:
        """The formula ``key`` in LaTeX, as ``formula --format json`` gives it."""
        return self._data[key]["latex"]

    def __str__(self) -> str:
        return self._text

    def __repr__(self) -> str:
        keys = [k for k, v in self._data.items() if isinstance(v, dict) and "text" in v]
        return f"Formulas({', '.join(keys)}; free symbols {', '.join(self._data['free_symbols'])})"

    def _repr_latex_(self) -> str:
        # Notebooks render the align* block; the \noindent paragraphs are text.
        body = self._latex
        start, end = body.find("\\begin{align*}"), body.rfind("\\end{align*}")
        if start >= 0 and end > start:
            inner = body[start + len("\\begin{align*}") : end]
            return f"$$\\begin{{aligned}}{inner}\\end{{aligned}}$$"
        return f"$${body}$$"

    def _repr_html_(self) -> Optional[str]:
        return None


def _expression(text: str, free: Iterable[str]) -> Any:
    """The formula ``text`` as a SymPy expression in plain symbols named as ``free``, or the
    text itself when SymPy is not installed."""
    try:
        import sympy
    except ImportError:
        return text
    names = {name: sympy.Symbol(name) for name in free}
    for name in ("m", "M", "l", "a", "v0", "e", "p", "I", "r", "L", "d"):
        names.setdefault(name, sympy.Symbol(name))
    return sympy.sympify(text.replace("^", "**"), locals=names, rational=True)


def formula(**scene: Any) -> Formulas:
    """The exact answer as formulas in the scene's free symbols, as ``rodimpact formula``.

    Every scene input of :func:`solve` may be a number or an expression in the symbols
    ``m M l a v0 e p I r`` (a string such as ``"2*m"``, or a SymPy expression); an input not
    given is its own symbol, except the collision law (elastic, e = 1, unless ``e="e"``) and
    the rod (uniform), as in :func:`solve`.

    >>> f = formula(M="2*m", e="e")
    >>> f.text("omega")
    '(a*e*v0 + a*v0)/(a^2 + l^2)'
    """
    data, latex, text = _native.formula_json(_pairs(scene, symbols=True))
    return Formulas(_loads(data), latex, text)


from ._check import Check, check  # noqa: E402
from ._impact import Impact, impact  # noqa: E402
