"""Type stubs of rodimpact: exact answers to rigid-body impact (see docs/python.md)."""

import os
from fractions import Fraction
from typing import Any, Dict, Iterable, Iterator, KeysView, List, Mapping, Optional, Tuple, Union

__version__: str

#: A number as the library reads it exactly: an int, a rational (Fraction, Decimal) or text
#: such as "3/7", "0.25", "1.5e-3", "100 g". A float is refused (ValueError).
Number = Union[int, Fraction, str, Any]
#: A path of a file.
PathLike = Union[str, "os.PathLike[str]"]

#: What an exact value of a result is: a rational or a surd.
Exact = Union[Fraction, "Surd"]

SCENE_KEYS: Tuple[str, ...]

class Surd:
    """An exact x + y*sqrt(d) (x, y rational, d a non-square rational)."""

    exact: str
    decimal: str
    squared: Optional[Fraction]
    def __init__(self, exact: str, decimal: str, squared: Optional[Fraction] = ...) -> None: ...
    def __float__(self) -> float: ...
    def sympy(self) -> Any: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def _repr_latex_(self) -> str: ...

def exact(value: Mapping[str, Any]) -> Exact:
    """The exact number of a JSON value {"exact": ..., "decimal": ...}."""

class Record:
    """A JSON object of the command line with attribute access to exact values."""

    def __init__(self, data: Dict[str, Any]) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, key: str) -> Any: ...
    def __contains__(self, key: object) -> bool: ...
    def __iter__(self) -> Iterator[str]: ...
    def keys(self) -> KeysView[str]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_json(self, indent: Optional[int] = ...) -> str: ...
    def _repr_html_(self) -> Optional[str]: ...
    def _repr_latex_(self) -> Optional[str]: ...

class Solution(Record):
    """The whole answer to one scene (``rodimpact solve --json``)."""

    v: Fraction
    V: Fraction
    omega: Fraction
    a_star: Exact
    omega_max: Exact
    argmax: str
    @property
    def laws_hold(self) -> bool: ...

class Formulas(Record):
    """The answer as formulas (``rodimpact formula``): SymPy expressions, or text."""

    free_symbols: List[str]
    defaults: List[str]
    def text(self, key: str) -> str: ...
    def latex(self, key: str) -> str: ...

class Check(Record):
    """Claims checked (``rodimpact check --json``)."""

    @property
    def all_agree(self) -> bool: ...

class Impact(Record):
    """A planar impact answered (``rodimpact impact --format json``)."""

    @property
    def all_agree(self) -> bool: ...
    def law(self, name: str) -> Record: ...
    @property
    def engine_step(self) -> Optional[Record]: ...
    @property
    def not_answered(self) -> Dict[str, str]: ...

class AuditSummary:
    """What ``rodimpact batch`` prints on standard error after the rows."""

    text: str
    ok: bool
    rows: int
    passed_through: List[str]
    agreement: Optional[str]
    def __contains__(self, text: str) -> bool: ...

def solve(
    m: Optional[Number] = ...,
    M: Optional[Number] = ...,
    *,
    l: Optional[Number] = ...,
    length: Optional[Number] = ...,
    a: Optional[Number] = ...,
    from_end: Optional[Number] = ...,
    v0: Optional[Number] = ...,
    rod: Optional[str] = ...,
    e: Optional[Number] = ...,
    pivot: Optional[Number] = ...,
    v0t: Optional[Number] = ...,
    mu: Optional[Number] = ...,
    radius: Optional[Number] = ...,
    spin: Optional[Number] = ...,
    rod_v: Optional[Number] = ...,
    rod_vt: Optional[Number] = ...,
    rod_omega: Optional[Number] = ...,
    digits: Optional[Union[int, str]] = ...,
) -> Solution:
    """Solves one scene exactly, as ``rodimpact solve --json``."""

def formula(
    *,
    m: Optional[Any] = ...,
    M: Optional[Any] = ...,
    l: Optional[Any] = ...,
    length: Optional[Any] = ...,
    a: Optional[Any] = ...,
    from_end: Optional[Any] = ...,
    v0: Optional[Any] = ...,
    rod: Optional[str] = ...,
    e: Optional[Any] = ...,
    pivot: Optional[Any] = ...,
    v0t: Optional[Any] = ...,
    mu: Optional[Any] = ...,
    radius: Optional[Any] = ...,
    spin: Optional[Any] = ...,
    rod_v: Optional[Any] = ...,
    rod_vt: Optional[Any] = ...,
    rod_omega: Optional[Any] = ...,
) -> Formulas:
    """The exact answer as formulas in the scene's free symbols (``rodimpact formula``)."""

def check(
    problems: Optional[PathLike] = ...,
    *,
    claims: Union[Mapping[str, Any], Iterable[str], None] = ...,
    sig: Optional[int] = ...,
    m: Optional[Any] = ...,
    M: Optional[Any] = ...,
    l: Optional[Any] = ...,
    length: Optional[Any] = ...,
    a: Optional[Any] = ...,
    from_end: Optional[Any] = ...,
    v0: Optional[Any] = ...,
    rod: Optional[str] = ...,
    e: Optional[Any] = ...,
    pivot: Optional[Any] = ...,
    v0t: Optional[Any] = ...,
    mu: Optional[Any] = ...,
    radius: Optional[Any] = ...,
    spin: Optional[Any] = ...,
    rod_v: Optional[Any] = ...,
    rod_vt: Optional[Any] = ...,
    rod_omega: Optional[Any] = ...,
) -> Check:
    """Checks published answers against the exact ones (``rodimpact check``)."""

def impact(
    scene: Union[PathLike, Mapping[str, Any]],
    *,
    law: Optional[str] = ...,
    model: Optional[str] = ...,
    digits: Optional[Union[int, str]] = ...,
) -> Impact:
    """Answers a planar impact exactly (``rodimpact impact``)."""

def audit(
    source: Any,
    *,
    rtol: Optional[Union[str, int, Fraction, float]] = ...,
    ulps: Optional[Union[str, int]] = ...,
    float_format: Optional[str] = ...,
    atol: Optional[Union[str, int, Fraction, float]] = ...,
    backend: str = ...,
    jobs: Optional[int] = ...,
) -> Any:
    """The batch audit (``rodimpact batch``) as a pandas DataFrame."""

class ImpactAuditSummary:
    """What ``rodimpact impact --batch`` prints on standard error, and its JSON summary."""

    text: str
    data: Dict[str, Any]
    ok: bool
    @property
    def scenes(self) -> int: ...
    @property
    def findings(self) -> Dict[str, List[str]]: ...
    def __contains__(self, text: str) -> bool: ...

def audit_impacts(
    source: Any,
    *,
    rtol: Optional[Union[str, int, Fraction, float]] = ...,
    atol: Optional[Union[str, int, Fraction, float]] = ...,
    ulps: Optional[Union[str, int]] = ...,
    float_format: Optional[str] = ...,
    engine: Optional[str] = ...,
    expect: Optional[Union[str, os.PathLike]] = ...,
) -> Any:
    """The audit of an engine's planar impacts (``rodimpact impact --batch``) as a pandas
    DataFrame."""
