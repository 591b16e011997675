"""``check``: published answers against the exact ones (``rodimpact check``)."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, Mapping, Optional, Union

from . import _native
from ._values import Record, Report, as_text

__all__ = ["check", "Check"]


class Check(Report):
    """Claims checked against the exact answers, as ``rodimpact check --json`` gives them.

    For scene inputs with claims: ``claims`` (one record per claim: ``name``, ``claim``,
    ``exact``, ``decimal``, ``rel_error``, ``verdict``, ``counterexample``, ``notes``) and
    ``summary``; for a problem file: ``problems``, each with its ``claims``. ``all_agree`` is
    the CLI's exit 0; ``str()`` the CLI's table; ``to_dict()`` its JSON. ``exact`` of a claim
    is text (``rodimpact.exact(claim)`` makes it a ``Fraction`` or a ``Surd``; a symbolic
    claim's exact value is a formula).
    """

    __slots__ = ()

    @property
    def all_agree(self) -> bool:
        """Whether every claim agrees with the exact answer (the CLI's exit 0)."""
        return self._verdict

    def __repr__(self) -> str:
        return f"Check(all_agree={self._verdict})"

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(self._text)}</pre>"

    def _repr_latex_(self) -> Optional[str]:
        return None


def _claim_list(claims: Union[Mapping[str, Any], Iterable[str]]) -> list:
    if isinstance(claims, str):
        return [claims]
    if isinstance(claims, Mapping):
        return [f"{name}={as_text(name, value, symbols=True)}" for name, value in claims.items()]
    out = []
    for claim in claims:
        if not isinstance(claim, str):
            raise ValueError(f"claim: expected NAME=VALUE text, got {type(claim).__name__}")
        out.append(claim)
    return out


def check(
    problems: Union[str, "os.PathLike[str]", None] = None,
    *,
    claims: Union[Mapping[str, Any], Iterable[str], None] = None,
    sig: Optional[int] = None,
    **scene: Any,
) -> Check:
    """Checks published answers against the exact ones, as ``rodimpact check``.

    Either a problem file (``check("examples/textbook.toml")``), or scene inputs as in
    :func:`solve` (numbers or formulas in ``m M l L a d v0 e p I r``) with ``claims``: a
    mapping ``{"omega": "1.2", "v": "3/5"}`` or ``NAME=VALUE`` strings. A claim's value is the
    number as printed (its significant figures count: ``"2.0"`` has two), an exact fraction,
    or a formula, decided as an identity. Give claimed numbers as strings: a ``float`` is
    refused, since it has lost the figures as printed. ``sig`` overrides every claim's
    significant figures.

    >>> check(m=1, M=1, claims={"omega": "1.2"}).all_agree
    True
    """
    from . import _pairs

    if sig is not None and (isinstance(sig, bool) or not isinstance(sig, int) or sig < 0):
        raise ValueError(f"sig: expected a whole number, got {sig!r}")
    if problems is not None:
        if claims is not None or any(v is not None for v in scene.values()):
            shown = os.fspath(problems)[:40]
            raise ValueError(
                f"check: give either a problem file ('{shown}') or scene flags with --claim, not both"
            )
        data, agree, text = _native.check_file_json(os.fspath(problems), sig)
        return Check(json.loads(data), agree, text)
    data, agree, text = _native.check_json(
        _pairs(scene, symbols=True), _claim_list(claims or []), sig
    )
    return Check(json.loads(data), agree, text)
