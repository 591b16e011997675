"""``impact``: any planar impact with bodies and contacts as data (``rodimpact impact``)."""

from __future__ import annotations

import decimal
import json
import numbers
import os
import re
from typing import Any, Dict, Mapping, Optional, Union

from . import _native
from ._values import Record, Report

__all__ = ["impact", "Impact"]


class Impact(Report):
    """A planar impact answered, as ``rodimpact impact --format json`` gives it.

    One contact: ``laws``, one record per restitution law (``law``, ``bodies`` with each
    moving body's ``velocity`` and ``omega`` after, ``impulse``, ``contact_velocity``,
    ``energy``, ``energy_gain``, ``laws_hold``, ...); several contacts: ``models``. Every
    number is exact (``Fraction`` or :class:`Surd`). ``law("newton")`` picks one law;
    ``all_agree`` says whether the file's published answers (``[[claim]]``) all agree;
    ``str()`` is the CLI's text report and ``to_dict()`` its JSON.
    """

    __slots__ = ()

    @property
    def all_agree(self) -> bool:
        """Whether the scene's published answers all agree (true when it has none)."""
        return self._verdict

    def law(self, name: str) -> Record:
        """The answer under the law ``name`` (``"newton"``, ``"poisson"``, ``"energetic"``,
        ``"lcp-newton"``, ``"lcp-poisson"``, ``"split"``); an engine's step is
        :attr:`engine_step`."""
        for answer in self._data.get("laws", []):
            if answer.get("law") == name and answer.get("engine") is None:
                return Record(answer)
        why = self.not_answered.get(name)
        if why is not None:
            raise KeyError(f"{name}: not answered: {why}")
        raise KeyError(f"no law {name!r} in this answer")

    @property
    def not_answered(self) -> Dict[str, str]:
        """One contact: the laws (or the engine) that give no answer while others do, each with
        why (``{"newton": "under newton's law the impact never ends: ..."}``); empty when every
        law asked for answers."""
        return {n["law"]: n["why"] for n in self._data.get("not_answered", [])}

    @property
    def engine_step(self) -> Optional[Record]:
        """The answer of the engine asked for with ``engine=`` (one step of its solver replayed
        exactly, or the law it converges to): with one contact the record whose ``engine`` is
        its name, with several the model named after it (``answers``, as every model's); ``None``
        without ``engine=``."""
        for answer in self._data.get("laws", []) + self._data.get("models", []):
            if answer.get("engine") is not None:
                return Record(answer)
        return None

    def __repr__(self) -> str:
        kind = "laws" if "laws" in self._data else "models"
        names = [a.get("law") or a.get("model") for a in self._data.get(kind, [])]
        return f"Impact({kind}: {', '.join(map(str, names))})"

    def _repr_html_(self) -> str:
        import html

        return f"<pre>{html.escape(self._text)}</pre>"


#: The plural a dict may use for each of the file's array-of-tables keys.
_PLURALS = {"bodies": "body", "contacts": "contact", "pins": "pin", "claims": "claim"}


def _singular_keys(scene: Mapping[str, Any]) -> Dict[str, Any]:
    """The scene with ``bodies``, ``contacts``, ``pins`` and ``claims`` (the natural plurals
    in a dict) under the file's keys ``body``, ``contact``, ``pin``, ``claim``; both spellings
    of one key are refused."""
    out: Dict[str, Any] = {}
    for key, value in scene.items():
        singular = _PLURALS.get(str(key), str(key))
        if singular in out:
            raise ValueError(f"scene: both '{singular}' and '{key}' given; give one")
        out[singular] = value
    return out


def _plain(value: Any, where: str, inside: frozenset = frozenset()) -> Any:
    """The dict's values as the scene file has them: exact numbers as text. A dict or list
    that contains itself is refused, naming where (``inside``: the containers above)."""
    if isinstance(value, (Mapping, list, tuple)):
        if id(value) in inside:
            raise ValueError(f"{where or 'scene'}: contains itself")
        inside = inside | {id(value)}
    if isinstance(value, Mapping):
        return {
            str(k): _plain(v, f"{where}.{k}" if where else str(k), inside)
            for k, v in value.items()
        }
    if isinstance(value, (list, tuple)):
        return [_plain(v, f"{where}[{i}]", inside) for i, v in enumerate(value)]
    if isinstance(value, (str, bool)) or value is None:
        return value
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Rational):
        return f"{value.numerator}/{value.denominator}"
    if isinstance(value, decimal.Decimal) and value.is_finite():
        return str(value)
    if isinstance(value, numbers.Real):
        raise ValueError(
            f"{where}: the float {value!r} is not exact (a binary approximation); "
            f"pass the number as a string ('{value!r}') or a fractions.Fraction"
        )
    raise ValueError(f"{where}: expected a number, a string, a list or a table, got {type(value).__name__}")


def impact(
    scene: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    *,
    law: Optional[str] = None,
    model: Optional[str] = None,
    digits: Optional[int] = None,
    engine: Optional[str] = None,
) -> Impact:
    """Answers a planar impact exactly, as ``rodimpact impact``.

    ``scene``: the path of a TOML scene file (``examples/impacts/*.toml``), or a dict with the
    file's structure: ``{"body": [{"name": "rod", "mass": "1", "inertia": "1/3", ...},
    {"name": "floor", "fixed": True}], "contact": [{"bodies": ["rod", "floor"], "point": [...],
    "normal": [...], "e": "1"}]}`` (numbers as strings, ints or Fractions; a float is
    refused; ``bodies``, ``contacts``, ``pins`` are taken for ``body``, ``contact``, ``pin``). ``law``: ``"newton"``, ``"poisson"``, ``"energetic"`` (``"stronge"``), the
    laws engines converge to, ``"lcp-newton"``, ``"lcp-poisson"``, ``"split"``, or ``"all"``
    (one contact; default the three physical laws); ``model`` for several contacts:
    ``"simultaneous-newton"``, ``"simultaneous-poisson"``, ``"split"``, ``"sequential"``,
    ``"sequential:2,1"``, ``"pgs:K"`` or ``"all"`` (default). ``engine``: also answer as an
    engine's solver does (``"pymunk-7"``, ``"box2d-2.3"``, ``"box2d-2.3:scale=16"``,
    ``"box2d-3"``, ``"rapier-0.36"``, ``"bullet-3"``). ``digits``: significant digits of the
    decimals (at least 30).
    """
    if digits is not None and (isinstance(digits, bool) or not isinstance(digits, (int, str))):
        raise ValueError(f"digits: must be a whole number from 1 to 10000, got {digits!r}")
    text_digits = None if digits is None else str(digits)
    if isinstance(scene, Mapping):
        path, text_scene = None, json.dumps(_plain(_singular_keys(scene), ""))
    elif isinstance(scene, (str, os.PathLike)):
        path, text_scene = os.fspath(scene), None
    else:
        raise ValueError(
            f"scene: expected a path or a dict, got {type(scene).__name__}"
        )
    try:
        data, agree, text = _native.impact_json(
            path, text_scene, "scene", law, model, text_digits, engine
        )
    except ValueError as error:
        # The library names the command line's flags; here they are keyword arguments.
        raise ValueError(_FLAGS.sub(r"\1=", str(error))) from None
    return Impact(json.loads(data), agree, text)


#: The command line's flags that are this function's keyword arguments, as messages name them.
_FLAGS = re.compile(r"--(law|model|engine|digits)\b")
