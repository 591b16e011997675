#!/usr/bin/env python3
"""Write the engine suite of planar impacts, engines/impacts.jsonl (standard library only).

One scene per line: the JSON form of a scene file of `rodimpact impact` (docs/impacts.md: the
TOML's structure, "title", "body": [...], "contact": [...], "pin": [...], every number an exact
string) plus "id" and "class". The lines are, in order:

  * every scene of examples/impacts/*.toml (not examples/impacts/published/), converted as it
    is, its id the file's stem;
  * generated coupled scenes with one contact, every velocity scaled so that the contact
    approaches at 2 (above Box2D 2.3's compiled-in 1 m/s restitution threshold):
      - rod-end-*: a uniform rod (length 2, mass 1, I = 1/3) with its axis along (3, 4), (4, 3),
        (5, 12), (12, 5) or (8, 15) lands on its lower end on the rough floor y = 0, falling at 2
        without spin; the end slides throughout (sliding at 3 with mu = 1/10, or away from the
        foot at 1 with mu = 1/5, where the slip grows), sticks (mu = 1, e = 1: Newton's law gains
        energy on every tilt), reverses (mu = 1/4, e = 1) or meets a frictionless floor;
      - box-corner-*: a 2 x 1 box (mass 1, I = 5/12), its width side along (4, 3), (3, 4) or
        (12, 5), lands on its lowest corner: slides, sticks, reverses, frictionless;
      - thick-rod-*: a puck (a point mass 1) strikes a free thick rod (a 2 x h box, mass 1) on its
        upper face at a along it, h/2 off its axis: slides, sticks, reverses, frictionless.

The class of a single-contact scene is its kind (rod-end, box-corner, thick-rod, or the
example's) and what the exact contact does, computed here with the oracle
tests/oracles/planar_impact.py under all three laws: `frictionless` (mu = 0), `slide` (one
slide phase to the end), `stick` (the slip stops and sticks), `reverse` (it stops and slides
back); the generator checks that a generated scene's class is the one intended and that all
three laws agree on it. Scenes with several contacts are classed multi-cradle, multi-column,
multi-landing and multi-friction.

Usage: python3 engines/impact_suite.py [OUT.jsonl]      (default engines/impacts.jsonl)
"""

import json
import os
import sys
import tomllib
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "oracles"))
import planar_impact  # noqa: E402  (the lead's exact one-contact oracle, standard library only)

# The kind of each example (single contact: a prefix, its class computed; several: the class).
EXAMPLES = {
    "ball-on-column": "multi-column",
    "ball-spin-rough-floor": "disc-floor",
    "box-corner": "box-corner",
    "box-lands-flat": "multi-landing",
    "box-lands-flat-friction": "multi-friction",
    "box-lands-flat-friction-stick": "multi-friction",
    "box-lands-flat-spin-window": "multi-landing",
    "box-lands-flat-spinning": "multi-landing",
    "cradle-3": "multi-cradle",
    "cradle-5": "multi-cradle",
    "cradle-unequal": "multi-cradle",
    "newton-gains-energy": "rod-end",
    "paper-as-bodies": "paper",
    "paper-pivot-as-bodies": "paper",
    "rod-lands-flat": "multi-landing",
    "rod-strikes-two-balls": "multi-landing",
    "thick-rod-off-axis": "thick-rod",
    "tilted-rod-rough-floor": "rod-end",
    "tilted-rod-sticks": "rod-end",
    "two-contact-poisson-energy": "multi-friction",
}

TILTS = {(3, 4): 5, (4, 3): 5, (5, 12): 13, (12, 5): 13, (8, 15): 17}


def q(x):
    """An exact number as the scene file writes it: "p/q", or "p" for an integer."""
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def stringify(value):
    """TOML values as the JSON form keeps them: numbers as exact strings, booleans as they are."""
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, F)):
        return q(value)
    if isinstance(value, dict):
        return {k: stringify(v) for k, v in value.items()}
    if isinstance(value, list):
        return [stringify(v) for v in value]
    return value


def contact_class(doc):
    """frictionless | slide | stick | reverse, from the exact path under the three laws (which
    must agree), for a scene with one contact."""
    if F(doc["contact"][0].get("mu", "0")) == 0:
        return "frictionless"
    result = planar_impact.solve(planar_impact.Scene(doc))
    kinds = set()
    for law in result["laws"]:
        modes = [p["mode"] for p in law["phases"]]
        kinds.add("slide" if len(modes) == 1 else "stick" if modes[-1] == "stick" else "reverse")
    if len(kinds) != 1:
        raise SystemExit(f"error: the laws' paths differ ({sorted(kinds)}): {doc.get('title')}")
    return kinds.pop()


def line(ident, cls, doc):
    out = {"id": ident, "class": cls}
    for key in ("title", "body", "contact", "pin"):
        if key in doc:
            out[key] = stringify(doc[key])
    return out


def examples():
    folder = os.path.join(ROOT, "examples", "impacts")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".toml"):
            continue
        stem = name[:-5]
        with open(os.path.join(folder, name), "rb") as f:
            doc = tomllib.load(f)
        kind = EXAMPLES[stem]
        if len(doc["contact"]) == 1:
            kind = f"{kind}-{contact_class(doc)}"
        yield line(stem, kind, doc)


def floor_contact(point_x, e, mu):
    return {"bodies": None, "point": [q(point_x), "0"], "normal": ["0", "1"],
            "e": q(e), "mu": q(mu)}


def rod_end(p, s, vx, mu, e):
    r = TILTS[(p, s)]
    c, sn = F(p, r), F(s, r)
    contact = floor_contact(-c, e, mu)
    contact["bodies"] = ["rod", "floor"]
    slip = "at rest" if vx == 0 else f"sliding at {q(abs(vx))} {'away from' if vx < 0 else 'towards'} its foot"
    return {
        "title": (f"A uniform rod along ({p}, {s}) lands on its lower end falling at 2, "
                  f"{slip}, e = {q(e)}, mu = {q(mu)}"),
        "body": [{"name": "rod", "mass": "1", "shape": "rod", "length": "2",
                  "axis": [str(p), str(s)], "position": ["0", q(sn)],
                  "velocity": [q(vx), "-2"], "omega": "0"},
                 {"name": "floor", "fixed": True}],
        "contact": [contact],
    }


def box_corner(p, s, vx, mu, e, w=F(2), h=F(1)):
    r = TILTS[(p, s)]
    a = (F(p, r), F(s, r))
    b = (-a[1], a[0])
    corner = (-w / 2 * a[0] - h / 2 * b[0], -w / 2 * a[1] - h / 2 * b[1])
    contact = floor_contact(corner[0], e, mu)
    contact["bodies"] = ["box", "floor"]
    return {
        "title": (f"A {q(w)} x {q(h)} box, its width along ({p}, {s}), lands on its lowest corner "
                  f"falling at 2 and sliding at {q(vx)}, e = {q(e)}, mu = {q(mu)}"),
        "body": [{"name": "box", "mass": "1", "shape": "box", "width": q(w), "height": q(h),
                  "axis": [str(p), str(s)], "position": ["0", q(-corner[1])],
                  "velocity": [q(vx), "-2"], "omega": "0"},
                 {"name": "floor", "fixed": True}],
        "contact": [contact],
    }


def thick_rod(a, h, vx, mu, e):
    a, h = F(a), F(h)
    point = [q(a), q(h / 2)]
    return {
        "title": (f"A puck moving at ({q(vx)}, -2) strikes a free 2 x {q(h)} rod on its upper face "
                  f"at {q(a)} along it, {q(h / 2)} off its axis, e = {q(e)}, mu = {q(mu)}"),
        "body": [{"name": "puck", "mass": "1", "shape": "point", "position": point,
                  "velocity": [q(vx), "-2"]},
                 {"name": "rod", "mass": "1", "shape": "box", "width": "2", "height": q(h),
                  "position": ["0", "0"], "velocity": ["0", "0"], "omega": "0"}],
        "contact": [{"bodies": ["puck", "rod"], "point": point, "normal": ["0", "1"],
                     "e": q(e), "mu": q(mu)}],
    }


def generated():
    """(id, intended class, scene)."""
    for (p, s) in TILTS:
        t = f"{p}-{s}"
        yield f"rod-end-{t}-slide", "rod-end-slide", rod_end(p, s, 3, F(1, 10), F(1, 2))
        if (p, s) in ((3, 4), (12, 5)):
            yield f"rod-end-{t}-slide-away", "rod-end-slide", rod_end(p, s, -1, F(1, 5), F(1, 2))
        yield f"rod-end-{t}-stick", "rod-end-stick", rod_end(p, s, 1, 1, 1)
        yield f"rod-end-{t}-reverse", "rod-end-reverse", rod_end(p, s, 1, F(1, 4), 1)
        yield f"rod-end-{t}-frictionless", "rod-end-frictionless", rod_end(p, s, 1, 0, F(1, 2))
    for (p, s), mu_reverse in (((4, 3), F(1, 4)), ((3, 4), F(1, 8)), ((12, 5), F(1, 4))):
        t = f"{p}-{s}"
        yield f"box-corner-{t}-slide", "box-corner-slide", box_corner(p, s, 3, F(1, 10), F(1, 2))
        yield f"box-corner-{t}-stick", "box-corner-stick", box_corner(p, s, 1, 1, 1)
        yield f"box-corner-{t}-reverse", "box-corner-reverse", box_corner(p, s, 1, mu_reverse, 1)
        yield (f"box-corner-{t}-frictionless", "box-corner-frictionless",
               box_corner(p, s, 1, 0, F(1, 2)))
    yield "thick-rod-slide", "thick-rod-slide", thick_rod("3/4", "1/5", 3, F(1, 10), 1)
    yield "thick-rod-stick", "thick-rod-stick", thick_rod("3/4", "1/5", 1, F(1, 2), 1)
    yield "thick-rod-half-stick", "thick-rod-stick", thick_rod("1/2", "1/2", -1, F(1, 2), 1)
    yield "thick-rod-half-reverse", "thick-rod-reverse", thick_rod("1/2", "1/2", F(1, 4), F(1, 10), 1)
    yield "thick-rod-frictionless", "thick-rod-frictionless", thick_rod("3/4", "1/5", 1, 0, 1)
    yield ("thick-rod-half-frictionless", "thick-rod-frictionless",
           thick_rod("1/2", "1/2", 1, 0, F(1, 2)))


def main(argv):
    out_path = argv[1] if len(argv) > 1 else os.path.join(HERE, "impacts.jsonl")
    lines = list(examples())
    for ident, cls, doc in generated():
        found = f"{cls.rsplit('-', 1)[0]}-{contact_class(doc)}"
        if found != cls:
            raise SystemExit(f"error: {ident} is {found}, not {cls}")
        lines.append(line(ident, cls, doc))
    ids = [entry["id"] for entry in lines]
    if len(set(ids)) != len(ids):
        raise SystemExit("error: duplicate ids")
    with open(out_path, "w") as f:
        for entry in lines:
            f.write(json.dumps(entry, separators=(", ", ": ")) + "\n")
    classes = {}
    for entry in lines:
        classes[entry["class"]] = classes.get(entry["class"], 0) + 1
    print(f"{len(lines)} scenes -> {out_path}", file=sys.stderr)
    for cls, count in sorted(classes.items()):
        print(f"  {cls}: {count}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
