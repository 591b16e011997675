#!/usr/bin/env python3
"""Deterministic fuzzed inputs for bench/compare, and the command lines that run them.

    python3 bench/compare/fuzz.py SEED OUTDIR [--bin RODIMPACT] [--quick]

Writes into OUTDIR (created; it should be new or empty):

  paper-NN.csv    (a) 20 batch CSVs of the paper's scene: random valid scenes (small numbers and
                  19-digit ones, decimals, e-notation, fractions, units, pivots, the four rod
                  kinds, moving rods, pass-through columns, shuffled column order); the odd-
                  numbered ones turn hostile after a random row (~7% of cells: negative masses,
                  |a| > l, e outside [0, 1], garbage text, empty cells, ...)
  oblique-NN.csv  (b) 20 oblique batch CSVs (v0t, mu, radius, spin, rod-v, rod-vt, rod-omega);
                  hostile like (a) in the odd-numbered ones
  engine-NN.csv   (c) 30 engine-style logs (id, engine, dt, ... and claimed v, V, omega, J,
                  energies, or vt, Vt, spin_after, tangential_impulse), the claims made from the
                  binary's own exact answers: correctly rounded, f32-rounded, a few ulps off,
                  relatively off, sign-flipped, NaN, inf, empty; engine-NN-expect.csv beside each
                  with part of its findings (for --expect)
  scene-NN.toml   (d) 40 random `impact` scenes: one contact between a disc, box, rod (thin or
                  thick), polygon or point body and a fixed floor or another body, with or
                  without friction, sometimes pinned; and scenes of 2-4 contacts (chains of discs
                  like a cradle, columns on a floor, boxes and rods landing flat, a rod on
                  balls). Contact points lie on the shapes' boundaries exactly (box corners and
                  edges along Pythagorean axes, disc points from Pythagorean triples, rod points,
                  polygon vertices and edges). hostile-NN.toml: 8 broken scenes.
  claims-N.jsonl  (e) `impact --batch` lines built from the scenes of (d), each with a "claimed"
                  object made from the binary's own exact answers (one law or model, perturbed,
                  the state before the impact, nonsense, NaN and infinities)
  commands.txt    the command lines that run all of these, in the corpus syntax of
                  commands.txt ({F} stands for OUTDIR)

The binary (default: the baseline /work/baseline/rodimpact-193b69f, else `rodimpact` on PATH)
is used only to make the inputs: to drop a row that it refuses from a file meant to be valid, to
retry a scene it refuses, and to compute the exact answers the claims are made from. So the
inputs depend only on SEED and on the binary's answers. --quick writes the first few inputs of
each kind only (the same files as the full set, as each file has its own random stream).
Python 3.11 standard library only.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import random
import re
import shutil
import struct
import subprocess
import sys
from fractions import Fraction as F
from pathlib import Path

BASELINE = "/work/baseline/rodimpact-193b69f"

# ------------------------------------------------------------------------------ numbers as text

TRIPLES = [(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25), (20, 21, 29), (9, 40, 41), (12, 35, 37)]


def dec_text(x: F) -> str | None:
    """x as an exact decimal, if it has one (denominator 2^a 5^b), else None."""
    d = x.denominator
    k2 = k5 = 0
    while d % 2 == 0:
        d //= 2
        k2 += 1
    while d % 5 == 0:
        d //= 5
        k5 += 1
    if d != 1:
        return None
    k = max(k2, k5)
    n = x * 10**k
    assert n.denominator == 1
    n = n.numerator
    sign = "-" if n < 0 else ""
    s = str(abs(n)).rjust(k + 1, "0")
    if k == 0:
        return sign + s
    return f"{sign}{s[:-k]}.{s[-k:]}"


def exp_text(x: F, rng: random.Random) -> str | None:
    """x in e-notation (exact), if it is a decimal: `1.25e-3`, `125E-5`, `1.25e+2`."""
    if dec_text(x) is None:
        return None
    if x == 0:
        return "0e0"
    k = 0
    while (x * 10**k).denominator != 1:
        k += 1
    n = (x * 10**k).numerator
    sign = "-" if n < 0 else ""
    digits = str(abs(n))
    if rng.random() < 0.3:
        return f"{sign}{digits}e-{k}" if k else f"{sign}{digits}e0"
    e = len(digits) - 1 - k
    rest = digits[1:].rstrip("0")
    mant = digits[0] + ("." + rest if rest else "")
    mark = rng.choice(["e", "E"])
    plus = "+" if e >= 0 and rng.random() < 0.3 else ""
    return f"{sign}{mant}{mark}{plus}{e}"


def text_of(x: F, rng: random.Random, styles=("int", "frac", "dec", "exp")) -> str:
    """An exact text for x in one of the styles that can spell it."""
    opts = []
    if x.denominator == 1 and "int" in styles:
        opts.append(str(x.numerator))
    if "frac" in styles:
        opts.append(f"{x.numerator}/{x.denominator}")
        if x.denominator == 1:
            opts.append(f"{x.numerator * 3}/3")
    d = dec_text(x)
    if d is not None and "dec" in styles:
        opts.append(d)
        if "." in d and rng.random() < 0.3:
            opts.append(d + "0")
    if d is not None and "exp" in styles:
        t = exp_text(x, rng)
        if t:
            opts.append(t)
    return rng.choice(opts)


def rand_pos(rng: random.Random, kind: str) -> F:
    """A random positive value of one magnitude class."""
    if kind == "small":
        return rng.choice([
            F(rng.randint(1, 20)),
            F(rng.randint(1, 60), rng.randint(1, 60)),
            F(rng.randint(1, 9999), 10 ** rng.randint(1, 4)),
            F(rng.randint(1, 99), 4 ** rng.randint(0, 3)),
        ])
    if kind == "big":  # 19 digits
        return rng.choice([
            F(rng.randint(10**18, 10**19 - 1)),
            F(rng.randint(10**18, 10**19 - 1), rng.randint(10**18, 10**19 - 1)),
            F(rng.randint(10**18, 10**19 - 1), 10**19),
        ])
    if kind == "extreme":
        return F(rng.randint(1, 99), 10) * F(10) ** rng.randint(-40, 40)
    raise ValueError(kind)


def rand_unit(rng: random.Random) -> tuple[F, F]:
    """A rational unit vector (from a Pythagorean triple, or an axis)."""
    if rng.random() < 0.3:
        return rng.choice([(F(1), F(0)), (F(0), F(1)), (F(-1), F(0)), (F(0), F(-1))])
    a, b, c = rng.choice(TRIPLES)
    if rng.random() < 0.5:
        a, b = b, a
    return (F(a * rng.choice([1, -1]), c), F(b * rng.choice([1, -1]), c))


def small_signed(rng: random.Random, zero_p=0.2) -> F:
    if rng.random() < zero_p:
        return F(0)
    return F(rng.randint(-12, 12), rng.choice([1, 2, 3, 4, 5, 10]))


def qs(x: F) -> str:
    """A Fraction as a scene-file string."""
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


# ------------------------------------------------------------------------------ running the binary


class Bin:
    def __init__(self, path: str):
        self.path = path

    def run(self, args: list[str], cwd: Path) -> subprocess.CompletedProcess:
        return subprocess.run([self.path, *args], cwd=cwd, capture_output=True, timeout=600)


ROW_ERR = re.compile(rb"row (\d+)")


def repair_csv(b: Bin, path: Path, cwd: Path, max_rounds: int = 200) -> int:
    """Drop every data row the binary refuses (exit 2 naming `row N`) from a file meant to be
    valid. Returns the number of rows dropped."""
    dropped = 0
    for _ in range(max_rounds):
        r = b.run(["batch", str(path), "--out", str(cwd / "repair.out.csv")], cwd)
        if r.returncode != 2:
            return dropped
        m = ROW_ERR.search(r.stderr)
        if not m:
            return dropped  # a file-level refusal: keep it, it is compared all the same
        n = int(m.group(1))
        rows = list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"))))
        if n < 1 or n >= len(rows):
            return dropped
        del rows[n]
        write_csv(path, rows[0], rows[1:])
        dropped += 1
    return dropped


def write_csv(path: Path, header: list[str], rows: list[list[str]]) -> None:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(header)
    w.writerows(rows)
    path.write_text(buf.getvalue(), encoding="utf-8")


# ------------------------------------------------------------------------------ (a), (b) batch CSVs

HOSTILE_CELLS = {
    "m": ["-1", "0", "-3/7", "", "abc", "1/0", "1e10001", "1 m/s", "NaN", "-0"],
    "M": ["-2", "0", "", "x", "1..2", "inf", "2 km/h", "0x10"],
    "l": ["0", "-1", "1/0", "", "--1", "1e", "1 kg"],
    "a": ["5", "-5", "1e3", "abc", "3/", "1 s"],
    "v0": ["0", "-1", "", "fast", "1e-10001"],
    "e": ["2", "-1/2", "1.0000001", "elastic", "1/0", "1e1"],
    "pivot": ["7", "-7", "p", "2/0"],
    "rod": ["steel", "rg=0", "rg=-1", "I=0", "I=-1", "rg=5", "I=", "uniform ", "Uniform", "dumbel"],
    "rod-v": ["5", "x", "1/0"],
    "rod-omega": ["50", "z"],
    "v0t": ["y", "1/0"],
    "mu": ["-1", "-1/3", "mu"],
    "radius": ["0", "-1", "r"],
    "spin": ["w", "1/0"],
    "rod-vt": ["q"],
}
GARBAGE = ["\u00bd", "1,5", "\"1\"", "1;2", " ", "1 1", "\u00e9", "\u22121", "+-1", "1e+", "0b1", "#1"]


def paper_scene(rng: random.Random, cls: str, oblique: bool, moving: bool,
                cols: list[str] | None = None) -> dict[str, F | str | None]:
    """One valid scene of the paper's family (or an oblique one) as exact values. A column
    not in `cols` takes the program's default (l = 1, a = l, v0 = 1, ...), and the scene is
    made valid under those defaults."""
    has = (lambda c: True) if cols is None else (lambda c: c in cols)
    s: dict[str, F | str | None] = {}
    s["m"] = rand_pos(rng, cls)
    s["M"] = rand_pos(rng, cls)
    s["l"] = rand_pos(rng, cls) if (rng.random() < 0.7 and has("l")) else F(1)
    l = s["l"]
    t = rng.choice([F(0), F(1), F(-1), F(rng.randint(-100, 100), 100), F(rng.randint(-7, 7), 7)])
    if cls == "big" and rng.random() < 0.5:
        t = F(rng.randint(-(10**18), 10**18), 10**18)
    s["a"] = t * l if has("a") else l
    s["v0"] = rand_pos(rng, cls) if has("v0") else F(1)
    kind = rng.choice(["uniform", "dumbbell", "rg", "I", None])
    if kind == "rg":
        r = l * F(rng.randint(1, 100), 100)
        s["rod"] = "rg=" + text_of(r, rng)
    elif kind == "I":
        x = s["M"] * l * l * F(rng.randint(1, 100), 100)
        s["rod"] = "I=" + text_of(x, rng)
    else:
        s["rod"] = kind
    s["e"] = rng.choice([None, F(1), F(0), F(1, 2), F(rng.randint(0, 100), 100), F(rng.randint(0, 7), 7)])
    s["pivot"] = None
    if rng.random() < 0.3 and has("pivot"):
        s["pivot"] = rng.choice([F(0), -l, l, l * F(rng.randint(-10, 10), 10)])
    if moving:
        s["rod-v"] = None if rng.random() < 0.3 else s["v0"] * F(rng.randint(-20, 9), 10)
        s["rod-omega"] = None if rng.random() < 0.4 else s["v0"] / l * F(rng.randint(-10, 10), 20)
        if s["pivot"] is not None:
            s["rod-v"] = None
        # keep an approach: u_n = v0 - (V0 + omega0 a) > 0
        if not has("rod-v"):
            s["rod-v"] = None
        if not has("rod-omega"):
            s["rod-omega"] = None
        rv = s["rod-v"] or F(0)
        ro = s["rod-omega"] or F(0)
        if s["v0"] - (rv + ro * s["a"]) <= 0:
            s["rod-v"] = None if s["pivot"] is not None else -s["v0"] / 2
            s["rod-omega"] = None
    if oblique:
        s["v0t"] = rng.choice([None, F(0), s["v0"] * F(rng.randint(-20, 20), 10)])
        s["mu"] = rng.choice([None, F(0), F(rng.randint(1, 20), 10), F(1, 3), F(rng.randint(1, 1000), 1000)])
        if rng.random() < 0.5:
            s["radius"] = l * F(rng.randint(1, 20), 40)
            s["spin"] = rng.choice([None, F(0), s["v0"] / s["radius"] * F(rng.randint(-20, 20), 10)])
        else:
            s["radius"] = None
            s["spin"] = None
        s["rod-vt"] = None if (s["pivot"] is not None or rng.random() < 0.5) else s["v0"] * F(rng.randint(-10, 10), 10)
    return s


UNITS = {"m": [("g", F(1, 1000)), ("kg", F(1)), ("lb", F(45359237, 100000000))],
         "M": [("g", F(1, 1000)), ("kg", F(1))],
         "l": [("cm", F(1, 100)), ("mm", F(1, 1000)), ("m", F(1))],
         "v0": [("km/h", F(1000, 3600)), ("cm/s", F(1, 100)), ("m/s", F(1))]}


def cell_text(key: str, x: F | str | None, rng: random.Random, allow_units: bool) -> str:
    if x is None:
        return ""
    if isinstance(x, str):
        return x
    if allow_units and key in UNITS and rng.random() < 0.08:
        unit, factor = rng.choice(UNITS[key])
        v = x / factor
        return text_of(v, rng) + rng.choice([" ", ""]) + unit
    return text_of(x, rng)


def gen_scene_csv(path: Path, rng: random.Random, oblique: bool, hostile: bool, nrows: int) -> None:
    base = ["m", "M", "l", "a", "v0", "rod", "e", "pivot"]
    moving = rng.random() < 0.5
    extra = ["rod-v", "rod-omega"] if moving or oblique else []
    if oblique:
        extra += ["v0t", "mu", "radius", "spin", "rod-vt"]
    cols = ["m", "M"] + [c for c in base[2:] if rng.random() < 0.8] + [c for c in extra if rng.random() < 0.85]
    if oblique and "v0t" not in cols and "mu" not in cols:
        cols += ["v0t", "mu"]
    rng.shuffle(cols)
    passthrough = []
    if rng.random() < 0.6:
        passthrough.append("id")
    if rng.random() < 0.3:
        passthrough.append(rng.choice(["note", "engine", "run", "Label with space"]))
    header = cols + passthrough
    rng.shuffle(header)
    rows = []
    hostile_from = rng.randint(0, max(0, nrows - 1)) if hostile else None
    classes = ["small"] * 6 + ["big"] * 2 + ["extreme"]
    for i in range(nrows):
        s = paper_scene(rng, rng.choice(classes), oblique, moving or oblique, cols)
        row = []
        for c in header:
            if c == "id":
                row.append(f"{path.stem}-{i + 1}")
            elif c in passthrough:
                row.append(rng.choice(["", "x", "a b", "1/2", "n\u00b0 3", "\u00e9t\u00e9", "-"]))
            else:
                v = s.get(c)
                row.append(cell_text(c, v, rng, allow_units=True))
        # spin without a radius column or value is refused: keep clean rows consistent
        if "spin" in header and ("radius" not in header or row[header.index("radius")] == ""):
            row[header.index("spin")] = ""
        if hostile_from is not None and i >= hostile_from:
            for j, c in enumerate(header):
                if c in passthrough:
                    continue
                if rng.random() < 0.07:
                    row[j] = rng.choice(HOSTILE_CELLS.get(c, []) + GARBAGE) if rng.random() < 0.85 else ""
            if rng.random() < 0.01:
                row = row[:-1]  # a short row
        rows.append(row)
    write_csv(path, header, rows)


# ------------------------------------------------------------------------------ (c) engine logs


def f32(x: float) -> float:
    try:
        return struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)


def f32_text(x: float) -> str:
    y = f32(x)
    if math.isinf(y) or math.isnan(y):
        return repr(y)
    for p in range(6, 10):
        t = f"{y:.{p}g}"
        if f32(float(t)) == y:
            return t
    return f"{y:.9g}"


def to_float(x: F) -> float:
    try:
        return float(x)
    except OverflowError:
        return math.copysign(math.inf, x)


def claim_text(exact: F, rng: random.Random, fmt: str) -> str:
    """A claimed value near (or far from) the exact one, as an engine would log it."""
    x = to_float(exact)
    r = rng.random()
    if r < 0.45:
        y = x
    elif r < 0.65:
        y = x
        for _ in range(rng.randint(1, 40)):
            y = math.nextafter(y, rng.choice([math.inf, -math.inf]))
    elif r < 0.80:
        y = x * (1 + rng.choice([1e-12, 1e-9, 3e-7, 1e-6, 1e-4, 1e-2]) * rng.choice([1, -1]))
    elif r < 0.84:
        y = -x
    elif r < 0.87:
        y = 0.0
    elif r < 0.89:
        return rng.choice(["NaN", "nan", "inf", "-inf", "Infinity"])
    elif r < 0.91:
        return ""
    elif r < 0.94:
        return f"{exact.numerator}/{exact.denominator}"  # an exact claim
    elif r < 0.96:
        y = x + rng.choice([1e-13, -1e-13, 1e-300])
    else:
        y = x * rng.choice([2, 0.5, 10, -3])
    if fmt == "f32":
        return f32_text(y)
    return repr(y)


ENGINE_CLAIMS = ["v", "V", "omega", "J", "energy_before", "energy_after"]
OBLIQUE_CLAIMS = ["v", "V", "omega", "vt", "Vt", "spin_after", "tangential_impulse"]


def gen_engine_csv(b: Bin, path: Path, expect_path: Path, rng: random.Random, idx: int, work: Path) -> dict:
    oblique = idx % 3 == 2
    fmt = "f32" if idx % 4 == 1 else "f64"
    engine = rng.choice(["fuzzphys", "rapier-like", "box2d-like", "bullet-like"])
    scene_cols = ["m", "M", "l", "a", "v0", "rod", "e", "pivot"]
    if oblique:
        scene_cols += ["v0t", "mu", "radius", "spin", "rod-v", "rod-vt", "rod-omega"]
    elif rng.random() < 0.3:
        scene_cols += ["rod-v", "rod-omega"]
    claims = OBLIQUE_CLAIMS if oblique else ENGINE_CLAIMS
    if "rod-v" in scene_cols and not oblique:
        claims = ["v", "V", "omega"]  # J and the energies are checked for the paper's scene only
    claims = [c for c in claims if rng.random() < 0.9] or claims[:3]
    tags = ["id", "engine", "version", "float", "dt", "iters", "class"]
    nscenes = rng.randint(5, 60)
    runs = rng.choice([1, 2, 4])
    classes = ["small"] * 8 + ["big", "extreme"]
    scenes = []
    for i in range(nscenes):
        cls = rng.choice(classes)
        s = paper_scene(rng, cls, oblique, "rod-v" in scene_cols, scene_cols)
        if "spin" in s and s.get("radius") is None:
            s["spin"] = None
        scenes.append((f"{'obl' if oblique else 'free'}-{cls}-{i + 1}", s))
    header = tags + scene_cols + claims
    rows = []
    for sid, s in scenes:
        for k in range(runs):
            row = {
                "id": sid, "engine": engine, "version": "0.1", "float": fmt,
                "dt": rng.choice(["1/60", "1/240", "1/1000"]), "iters": str(rng.choice([1, 4, 10, 50])),
                "class": ("pivot" if s.get("pivot") is not None else "oblique" if oblique else "free"),
            }
            for c in scene_cols:
                row[c] = cell_text(c, s.get(c), rng, allow_units=False)
            if row.get("spin") and not row.get("radius"):
                row["spin"] = ""
            for c in claims:
                row[c] = "0"
            rows.append([row[h] for h in header])
    write_csv(path, header, rows)
    # the exact answers: the binary's own, from its *_exact columns (valid rows only)
    repair_csv(b, path, work)
    out = work / "engine.exact.csv"
    b.run(["batch", str(path), "--out", str(out)], work)
    if not out.exists():
        return {"oblique": oblique, "fmt": fmt}
    rows_in = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))
    rows_out = list(csv.reader(io.StringIO(out.read_text(encoding="utf-8"))))
    head_out = rows_out[0]
    final = []
    for rin, rout in zip(rows_in, rows_out[1:]):
        for c in claims:
            col = f"{c}_exact"
            if col in head_out:
                t = rout[head_out.index(col)]
                try:
                    ex = F(t)
                except (ValueError, ZeroDivisionError):
                    rin[c] = t
                    continue
                rin[c] = claim_text(ex, rng, fmt)
            else:
                rin[c] = ""
        final.append([rin[h] for h in header])
    write_csv(path, header, final)
    # an --expect baseline: part of the findings this log has, by id
    r = b.run(["batch", str(path), "--out", str(out)], work)
    allowed = []
    if out.exists():
        res = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8"))))
        seen = set()
        for row in res:
            d = row.get("diagnosis") or ""
            for finding in d.split(";"):
                if finding in ("", "ok", "-"):  # "-": a row without a diagnosis (oblique)
                    continue
                if (row["id"], finding) not in seen:
                    seen.add((row["id"], finding))
                    if rng.random() < 0.7:
                        allowed.append((row["id"], finding))
        # a wildcard class and a stale line
        if allowed and rng.random() < 0.5:
            allowed.append((allowed[0][0].split("-")[0] + "-*", allowed[0][1]))
        allowed.append(("no-such-row", "energy-gain"))
    lines = ["# fuzz.py: findings allowed for " + path.name, "id,finding"] + [f"{i},{f}" for i, f in allowed]
    expect_path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return {"oblique": oblique, "fmt": fmt}


# ------------------------------------------------------------------------------ (d) impact scenes


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def vmul(k, a):
    return (k * a[0], k * a[1])


def perp(a):
    return (-a[1], a[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


class Body:
    def __init__(self, name: str):
        self.name = name
        self.fixed = False
        self.shape: str | None = None
        self.keys: dict[str, object] = {}
        self.centre = (F(0), F(0))
        self.mass = F(1)
        self.inertia: F | None = None
        self.v = (F(0), F(0))
        self.omega = F(0)
        self.vertices: list[tuple[F, F]] | None = None
        self.write_position = True

    def toml(self) -> str:
        out = ["[[body]]", f'name = "{self.name}"']
        if self.fixed:
            out.append("fixed = true")
            return "\n".join(out)
        out.append(f'mass = "{qs(self.mass)}"')
        if self.shape:
            out.append(f'shape = "{self.shape}"')
        for k, v in self.keys.items():
            if isinstance(v, tuple):
                out.append(f'{k} = ["{qs(v[0])}", "{qs(v[1])}"]')
            elif isinstance(v, list):
                out.append(f"{k} = [" + ", ".join(f'["{qs(p[0])}", "{qs(p[1])}"]' for p in v) + "]")
            else:
                out.append(f'{k} = "{qs(v)}"')
        if self.inertia is not None:
            out.append(f'inertia = "{qs(self.inertia)}"')
        if self.write_position:
            out.append(f'position = ["{qs(self.centre[0])}", "{qs(self.centre[1])}"]')
        out.append(f'velocity = ["{qs(self.v[0])}", "{qs(self.v[1])}"]')
        out.append(f'omega = "{qs(self.omega)}"')
        return "\n".join(out)

    def json(self) -> dict:
        d: dict[str, object] = {"name": self.name}
        if self.fixed:
            d["fixed"] = True
            return d
        d["mass"] = qs(self.mass)
        if self.shape:
            d["shape"] = self.shape
        for k, v in self.keys.items():
            if isinstance(v, tuple):
                d[k] = [qs(v[0]), qs(v[1])]
            elif isinstance(v, list):
                d[k] = [[qs(p[0]), qs(p[1])] for p in v]
            else:
                d[k] = qs(v)
        if self.inertia is not None:
            d["inertia"] = qs(self.inertia)
        if self.write_position:
            d["position"] = [qs(self.centre[0]), qs(self.centre[1])]
        d["velocity"] = [qs(self.v[0]), qs(self.v[1])]
        d["omega"] = qs(self.omega)
        return d

    def point_velocity(self, p):
        if self.fixed:
            return (F(0), F(0))
        r = vsub(p, self.centre)
        return vadd(self.v, vmul(self.omega, perp(r)))


def centroid(vs):
    a2 = cx = cy = F(0)
    for i in range(len(vs)):
        a, b = vs[i], vs[(i + 1) % len(vs)]
        cr = a[0] * b[1] - a[1] * b[0]
        cx += (a[0] + b[0]) * cr
        cy += (a[1] + b[1]) * cr
        a2 += cr
    return (cx / (3 * a2), cy / (3 * a2))


def make_shape(rng: random.Random, name: str, kind: str) -> Body:
    b = Body(name)
    b.mass = rng.choice([F(1), F(2), F(1, 2), F(rng.randint(1, 9), rng.randint(1, 4))])
    b.shape = kind
    if kind == "disc":
        b.keys["radius"] = rng.choice([F(1), F(1, 2), F(rng.randint(1, 6), rng.randint(1, 4))])
    elif kind == "box":
        b.keys["width"] = F(rng.randint(1, 6), rng.choice([1, 2]))
        b.keys["height"] = F(rng.randint(1, 6), rng.choice([1, 2]))
        u = rand_unit(rng)
        k = rng.choice([1, 5, 13]) if rng.random() < 0.5 else 1
        b.keys["axis"] = (u[0] * k, u[1] * k)  # not normalised on purpose, sometimes
    elif kind == "rod":
        b.keys["length"] = F(rng.randint(1, 8), rng.choice([1, 2]))
        if rng.random() < 0.3:
            b.keys["thickness"] = F(rng.randint(1, 4), rng.choice([4, 8]))
        u = rand_unit(rng)
        b.keys["axis"] = u
    elif kind == "polygon":
        n = rng.randint(3, 6)
        R = F(rng.randint(1, 4), rng.choice([1, 2]))
        dirs = set()
        while len(dirs) < n:
            dirs.add(rand_unit(rng))
        pts = sorted(dirs, key=lambda d: math.atan2(float(d[1]), float(d[0])))
        b.vertices = [vmul(R, d) for d in pts]
        b.write_position = rng.random() < 0.5
    elif kind == "point":
        pass
    if rng.random() < 0.1 and kind != "polygon":
        # a body given by its inertia alone (not checked against a shape)
        b.shape = None
        b.keys = {}
        b.inertia = F(rng.randint(1, 12), rng.randint(1, 12))
    return b


def unit_of(axis) -> tuple[F, F]:
    n2 = dot(axis, axis)
    n = F(math.isqrt(n2.numerator), math.isqrt(n2.denominator))
    assert n * n == n2, axis
    return (axis[0] / n, axis[1] / n)


def boundary_offset(rng: random.Random, b: Body):
    """A point on b's boundary, as an offset from its centre (for a polygon: from the origin of
    its vertex list, i.e. a vertex or a point of an edge)."""
    if b.shape is None:
        return (F(0), F(0))  # no shape: nothing is checked
    if b.shape == "point":
        return (F(0), F(0))
    if b.shape == "disc":
        u = rand_unit(rng)
        return vmul(b.keys["radius"], u)
    if b.shape in ("box", "rod"):
        u = unit_of(b.keys["axis"])
        w = b.keys.get("width", b.keys.get("length"))
        h = b.keys.get("height", b.keys.get("thickness", F(0)))
        if h == 0:
            t = rng.choice([F(1), F(-1), F(rng.randint(-8, 8), 8)])
            return vmul(t * w / 2, u)
        if rng.random() < 0.6:  # a corner
            s1, s2 = rng.choice([1, -1]), rng.choice([1, -1])
            return vadd(vmul(s1 * w / 2, u), vmul(s2 * h / 2, perp(u)))
        t = F(rng.randint(-8, 8), 8)
        if rng.random() < 0.5:
            return vadd(vmul(rng.choice([1, -1]) * w / 2, u), vmul(t * h / 2, perp(u)))
        return vadd(vmul(t * w / 2, u), vmul(rng.choice([1, -1]) * h / 2, perp(u)))
    if b.shape == "polygon":
        vs = b.vertices
        i = rng.randrange(len(vs))
        if rng.random() < 0.6:
            return vs[i]
        a, c = vs[i], vs[(i + 1) % len(vs)]
        t = F(rng.randint(1, 7), 8)
        return vadd(a, vmul(t, vsub(c, a)))
    raise ValueError(b.shape)


def place(b: Body, centre) -> None:
    if b.shape == "polygon":
        shift = vsub(centre, (F(0), F(0)))
        b.vertices = [vadd(v, shift) for v in b.vertices]
        b.keys["vertices"] = b.vertices
        b.centre = centroid(b.vertices)
    else:
        b.centre = centre


def place_with_boundary_at(rng: random.Random, b: Body, p) -> None:
    """Put b so that p lies on its boundary."""
    off = boundary_offset(rng, b)
    if b.shape == "polygon":
        # off is a point of the polygon as listed around the origin: shift it onto p
        b.vertices = [vadd(v, vsub(p, off)) for v in b.vertices]
        b.keys["vertices"] = b.vertices
        b.centre = centroid(b.vertices)
    else:
        b.centre = vsub(p, off)


def rand_normal(rng: random.Random):
    return rng.choice([(F(0), F(1)), (F(1), F(0)), (F(0), F(2)), (F(3), F(4)), (F(-1), F(2)), (F(-4), F(3)),
                       (F(1), F(1)), (F(0), F(-1)), (F(5), F(-12))])


def approach_ok(bodies: dict[str, Body], contacts: list[dict]) -> list[F]:
    out = []
    for c in contacts:
        a, b = bodies[c["bodies"][0]], bodies[c["bodies"][1]]
        u = vsub(a.point_velocity(c["point"]), b.point_velocity(c["point"]))
        out.append(dot(u, c["normal"]))
    return out


def random_motion(rng: random.Random, b: Body) -> None:
    if b.fixed:
        return
    b.v = (small_signed(rng, 0.15), small_signed(rng, 0.15))
    b.omega = small_signed(rng, 0.4)


def flip(bodies) -> None:
    for b in bodies.values():
        b.v = (-b.v[0], -b.v[1])
        b.omega = -b.omega


def contact_law(rng: random.Random, c: dict, friction_ok: bool) -> None:
    c["e"] = rng.choice([None, F(1), F(0), F(1, 2), F(9, 10), F(rng.randint(0, 10), 10)])
    c["mu"] = rng.choice([None, F(0), F(1, 3), F(1, 2), F(1), F(2)]) if friction_ok else None


def scene_single(rng: random.Random):
    kinds = ["disc", "box", "rod", "polygon", "point"]
    a = make_shape(rng, "A" if rng.random() < 0.5 else rng.choice(["ball", "crate", "bar", "plate", "puck"]), rng.choice(kinds))
    place(a, (small_signed(rng, 0.3), small_signed(rng, 0.3) + 2))
    if a.shape == "polygon":
        p = boundary_offset_world(rng, a)
    else:
        p = vadd(a.centre, boundary_offset(rng, a))
    bodies = {a.name: a}
    if rng.random() < 0.45:
        fl = Body(rng.choice(["floor", "wall", "ground"]))
        fl.fixed = True
        other = fl
    else:
        other = make_shape(rng, "B" if a.name != "B" else "C", rng.choice(kinds))
        place_with_boundary_at(rng, other, p)
        random_motion(rng, other)
    bodies[other.name] = other
    random_motion(rng, a)
    pins = []
    if rng.random() < 0.15 and not a.fixed:
        q = rng.choice([a.centre, vadd(a.centre, (F(1), F(0))), p]) if a.shape != "point" else a.centre
        if q == p:
            q = a.centre
        a.v = vmul(-1, vmul(a.omega, perp(vsub(q, a.centre))))
        if a.shape == "point" or a.shape is None and a.inertia is None:
            q = a.centre
            a.v = (F(0), F(0))
        pins.append({"body": a.name, "point": q})
    c = {"bodies": [a.name, other.name], "point": p, "normal": rand_normal(rng)}
    contact_law(rng, c, True)
    return bodies, [c], pins


def boundary_offset_world(rng: random.Random, a: Body):
    vs = a.vertices
    i = rng.randrange(len(vs))
    if rng.random() < 0.6:
        return vs[i]
    b = vs[(i + 1) % len(vs)]
    t = F(rng.randint(1, 7), 8)
    return vadd(vs[i], vmul(t, vsub(b, vs[i])))


def scene_chain(rng: random.Random):
    n = rng.randint(3, 5)
    u = rand_unit(rng)
    R = rng.choice([F(1, 2), F(1), F(1, 4)])
    bodies = {}
    names = [f"ball{i + 1}" for i in range(n)]
    start = (small_signed(rng, 0.5), small_signed(rng, 0.5))
    for i, name in enumerate(names):
        b = Body(name)
        b.shape = "disc"
        b.keys["radius"] = R
        b.mass = F(1) if rng.random() < 0.6 else F(rng.randint(1, 4), rng.randint(1, 3))
        b.centre = vadd(start, vmul(2 * R * i, u))
        bodies[name] = b
    first = bodies[names[0]]
    first.v = vmul(rng.choice([F(1), F(2), F(1, 2)]), u)
    if rng.random() < 0.3:
        first.v = vadd(first.v, vmul(F(1, 3), perp(u)))
    if rng.random() < 0.3:
        bodies[names[-1]].v = vmul(F(-1, 2), u)
    contacts = []
    friction = rng.random() < 0.3 and n - 1 <= 4
    for i in range(n - 1):
        a, b = names[i + 1], names[i]
        c = {"bodies": [a, b], "point": vadd(bodies[b].centre, vmul(R, u)), "normal": vmul(rng.choice([1, 1, 2]), u)}
        contact_law(rng, c, friction)
        contacts.append(c)
    if n - 1 > 4:
        contacts = contacts[:4]
    return bodies, contacts, []


def scene_column(rng: random.Random):
    k = rng.randint(1, 3)
    R = rng.choice([F(1, 2), F(1)])
    bodies = {}
    fl = Body("floor")
    fl.fixed = True
    bodies["floor"] = fl
    names = [f"ball{i + 1}" for i in range(k)] + ["top"]
    for i, name in enumerate(names):
        b = Body(name)
        b.shape = "disc"
        b.keys["radius"] = R
        b.mass = F(1) if rng.random() < 0.7 else F(rng.randint(1, 3))
        b.centre = (F(0), R + 2 * R * i)
        bodies[name] = b
    bodies["top"].v = (F(0), -rng.choice([F(1), F(2), F(1, 2)]))
    contacts = [{"bodies": [names[0], "floor"], "point": (F(0), F(0)), "normal": (F(0), F(1))}]
    for i in range(len(names) - 1):
        contacts.append({"bodies": [names[i + 1], names[i]], "point": (F(0), 2 * R * (i + 1)), "normal": (F(0), F(1))})
    for c in contacts:
        contact_law(rng, c, False)
    return bodies, contacts[:4], []


def scene_flat(rng: random.Random):
    kind = rng.choice(["box", "rod"])
    b = Body(rng.choice(["box", "crate"]) if kind == "box" else "rod")
    b.shape = kind
    w = F(rng.randint(1, 4))
    if kind == "box":
        h = F(rng.randint(1, 4), 2)
        b.keys.update({"width": w, "height": h})
        b.centre = (F(0), h / 2)
    else:
        h = F(0)
        b.keys.update({"length": w})
        b.centre = (F(0), F(0))
    b.mass = F(rng.randint(1, 3))
    b.v = (small_signed(rng, 0.5), -rng.choice([F(1), F(2), F(1, 2)]))
    b.omega = rng.choice([F(0), F(0), F(1, 2), F(-1), F(rng.randint(-6, 6), 2)])
    fl = Body("floor")
    fl.fixed = True
    bodies = {b.name: b, "floor": fl}
    friction = rng.random() < 0.5
    contacts = []
    for sx in (-1, 1):
        c = {"bodies": [b.name, "floor"], "point": (sx * w / 2, F(0)), "normal": (F(0), F(1))}
        contact_law(rng, c, friction)
        contacts.append(c)
    return bodies, contacts, []


def scene_rod_on_balls(rng: random.Random):
    L = F(rng.randint(2, 4))
    rod = Body("rod")
    rod.shape = "rod"
    rod.keys["length"] = L
    rod.centre = (F(0), F(1))
    rod.mass = F(rng.randint(1, 3))
    rod.v = (small_signed(rng, 0.6), -F(1))
    rod.omega = small_signed(rng, 0.3)
    bodies = {"rod": rod}
    contacts = []
    nballs = rng.randint(2, 3)
    xs = sorted(set(F(rng.randint(-4, 4), 4) * L / 2 for _ in range(nballs)))
    if len(xs) < 2:
        xs = [-L / 2, L / 2]
    for i, x in enumerate(xs):
        R = F(1, 2)
        ball = Body(f"ball{i + 1}")
        ball.shape = "disc"
        ball.keys["radius"] = R
        ball.mass = F(rng.randint(1, 3))
        ball.centre = (x, F(1) - R)
        bodies[ball.name] = ball
        c = {"bodies": ["rod", ball.name], "point": (x, F(1)), "normal": (F(0), rng.choice([F(1), F(2)]))}
        contact_law(rng, c, rng.random() < 0.3)
        contacts.append(c)
    return bodies, contacts, []


def scene_to_toml(title: str, bodies, contacts, pins) -> str:
    out = [f'title = "{title}"', ""]
    for b in bodies.values():
        out.append(b.toml())
        out.append("")
    for c in contacts:
        out.append("[[contact]]")
        out.append(f'bodies = ["{c["bodies"][0]}", "{c["bodies"][1]}"]')
        out.append(f'point = ["{qs(c["point"][0])}", "{qs(c["point"][1])}"]')
        out.append(f'normal = ["{qs(c["normal"][0])}", "{qs(c["normal"][1])}"]')
        if c.get("e") is not None:
            out.append(f'e = "{qs(c["e"])}"')
        if c.get("mu") is not None:
            out.append(f'mu = "{qs(c["mu"])}"')
        out.append("")
    for p in pins:
        out.append("[[pin]]")
        out.append(f'body = "{p["body"]}"')
        out.append(f'point = ["{qs(p["point"][0])}", "{qs(p["point"][1])}"]')
        out.append("")
    return "\n".join(out)


def scene_to_json(sid: str, title: str, bodies, contacts, pins) -> dict:
    d: dict[str, object] = {"id": sid, "title": title, "body": [b.json() for b in bodies.values()]}
    cs = []
    for c in contacts:
        x = {"bodies": list(c["bodies"]), "point": [qs(c["point"][0]), qs(c["point"][1])],
             "normal": [qs(c["normal"][0]), qs(c["normal"][1])]}
        if c.get("e") is not None:
            x["e"] = qs(c["e"])
        if c.get("mu") is not None:
            x["mu"] = qs(c["mu"])
        cs.append(x)
    d["contact"] = cs
    if pins:
        d["pin"] = [{"body": p["body"], "point": [qs(p["point"][0]), qs(p["point"][1])]} for p in pins]
    return d


def gen_impact_scene(b: Bin, rng: random.Random, idx: int, work: Path):
    """A valid scene (the binary answers it, exit 0 or 1); retried with the same stream."""
    families = [scene_single] * 5 + [scene_chain, scene_column, scene_flat, scene_rod_on_balls]
    for attempt in range(60):
        fam = scene_single if idx < 24 else rng.choice(families[5:]) if idx < 36 else rng.choice(families)
        bodies, contacts, pins = fam(rng)
        u = approach_ok(bodies, contacts)
        if all(x >= 0 for x in u):
            flip(bodies)
            u = approach_ok(bodies, contacts)
        if not any(x < 0 for x in u):
            continue
        if len(contacts) == 1 and u[0] >= 0:
            continue
        title = f"fuzz scene {idx + 1}: {fam.__name__[6:]}, {len(contacts)} contact(s), attempt {attempt + 1}"
        text = scene_to_toml(title, bodies, contacts, pins)
        p = work / "probe.toml"
        p.write_text(text, encoding="utf-8")
        r = b.run(["impact", str(p), "--format", "json"], work)
        if r.returncode in (0, 1):
            return text, (bodies, contacts, pins, title), len(contacts)
    return text, (bodies, contacts, pins, title), len(contacts)  # the last try, refused: kept


def hostile_scene(rng: random.Random, text: str, k: int) -> str:
    """A broken copy of a valid scene file."""
    def in_first_contact(t: str, fn) -> str:
        i = t.index("[[contact]]")
        j = t.find("[[", i + 2)
        j = len(t) if j < 0 else j
        return t[:i] + fn(t[i:j]) + t[j:]

    def set_key(block: str, key: str, value: str) -> str:
        if re.search(rf"^{key} = ", block, re.M):
            return re.sub(rf"^{key} = .*$", f"{key} = {value}", block, count=1, flags=re.M)
        return block.replace("[[contact]]\n", f"[[contact]]\n{key} = {value}\n", 1)

    def off_shape(t: str) -> str:  # the contact point moved by 1/1000 along x: off the shapes
        def move(block: str) -> str:
            m = re.search(r'point = \["([^"]*)"', block)
            x = F(m.group(1)) + F(1, 1000)
            return block[: m.start(1)] + qs(x) + block[m.end(1):]
        return in_first_contact(t, move)

    def duplicate_name(t: str) -> str:
        name = re.search(r'name = "([^"]*)"', t).group(1)
        return t + f'\n[[body]]\nname = "{name}"\nfixed = true\n'

    muts = [
        off_shape,
        lambda t: re.sub(r'mass = "[^"]*"', 'mass = "-1"', t, count=1),
        lambda t: re.sub(r'mass = "[^"]*"', "mass = 0.5", t, count=1),
        lambda t: t + '\n[[contact]]\nbodies = ["nobody", "floor"]\npoint = ["0", "0"]\nnormal = ["0", "1"]\n',
        lambda t: re.sub(r'normal = \[[^\]]*\]', 'normal = ["0", "0"]', t, count=1),
        lambda t: in_first_contact(t, lambda b: set_key(b, "e", '"3/2"')),
        lambda t: in_first_contact(t, lambda b: set_key(b, "mu", '"-1"')),
        lambda t: t.replace("[[body]]", '[[body]]\ncolour = "red"', 1),
        duplicate_name,
        lambda t: re.sub(r'omega = "[^"]*"', 'omega = "1e10001"', t, count=1),
        lambda t: t + '\n[[pin]]\nbody = "nobody"\npoint = ["0", "0"]\n',
        lambda t: re.sub(r'velocity = \[[^\]]*\]', 'velocity = ["0", "0"]', t),
    ]
    return muts[k % len(muts)](text)


# ------------------------------------------------------------------------------ (e) JSONL claims


def decimal_of(x: str) -> float:
    try:
        return float(F(x))
    except (ValueError, ZeroDivisionError):
        return float("nan")


def exact_answers(b: Bin, scenes: list[dict], work: Path) -> list[dict]:
    """The binary's exact answers per law or model for each scene (impact --batch's "exact")."""
    p = work / "probe.jsonl"
    p.write_text("".join(json.dumps(s) + "\n" for s in scenes), encoding="utf-8")
    r = b.run(["impact", "--batch", str(p)], work)
    out = []
    for line in r.stdout.decode("utf-8", "replace").splitlines():
        try:
            out.append(json.loads(line).get("exact", {}))
        except json.JSONDecodeError:
            out.append({})
    return out


def perturb(x: str, rng: random.Random, how: str) -> str:
    """A claimed number (as a string: the shortest text of a float) from an exact answer."""
    if x is None:
        return "0"
    try:
        v = float(F(x))
    except (ValueError, ZeroDivisionError):
        v = decimal_of_surd(x)
    if how == "exact":
        return repr(v)
    if how == "ulps":
        for _ in range(rng.randint(1, 8)):
            v = math.nextafter(v, math.inf)
        return repr(v)
    if how == "rel":
        return repr(v * (1 + rng.choice([1e-12, 1e-6, 1e-4, 1e-2, -1e-3])) + rng.choice([0, 1e-12]))
    if how == "f32":
        return f32_text(v)
    if how == "nan":
        return rng.choice(["NaN", "inf", "-inf", repr(v)])
    return repr(v)


SURD = re.compile(r"^\(?(-?[0-9/]+)?\s*([+-])?\s*(-?[0-9/]*)\*?sqrt\((\d+)\)\)?(?:/(\d+))?$")


def decimal_of_surd(x: str) -> float:
    """A float for a surd answer such as `1/2 + 3/4*sqrt(5)` (best effort; the claims only need
    to be near)."""
    t = x.replace(" ", "")
    m = re.findall(r"sqrt\((\d+)\)", t)
    if not m:
        return float("nan")
    try:
        expr = re.sub(r"sqrt\((\d+)\)", r"math.sqrt(\1)", t)
        expr = re.sub(r"(\d+)/(\d+)", r"(\1/\2)", expr)
        return float(eval(expr, {"math": math, "__builtins__": {}}))  # noqa: S307 (own text)
    except Exception:
        return float("nan")


def claimed_from(ex: dict, scene: dict, rng: random.Random) -> dict:
    movers = [bd["name"] for bd in scene["body"] if not bd.get("fixed")]
    labels = list(ex.keys())
    how = rng.choice(["exact", "exact", "ulps", "rel", "rel", "f32", "before", "random", "nan"])
    bodies = {}
    if how == "before" or not labels:
        for bd in scene["body"]:
            if not bd.get("fixed"):
                bodies[bd["name"]] = {"velocity": list(bd.get("velocity", ["0", "0"])), "omega": bd.get("omega", "0")}
    elif how == "random":
        for n in movers:
            bodies[n] = {"velocity": [repr(rng.uniform(-3, 3)), repr(rng.uniform(-3, 3))], "omega": repr(rng.uniform(-3, 3))}
    else:
        lab = rng.choice(labels)
        ans = ex[lab]
        for n in movers:
            a = ans.get(n, {"velocity": ["0", "0"], "omega": "0"})
            bodies[n] = {"velocity": [perturb(a["velocity"][0], rng, how), perturb(a["velocity"][1], rng, how)],
                         "omega": perturb(a["omega"], rng, how)}
    return {"engine": f"fuzz-{how}", "bodies": bodies}


# ------------------------------------------------------------------------------ main


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("seed", type=int)
    ap.add_argument("outdir", type=Path)
    ap.add_argument("--bin", default=BASELINE if os.path.exists(BASELINE) else shutil.which("rodimpact"))
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    if not args.bin:
        print("fuzz.py: no rodimpact binary (--bin)", file=sys.stderr)
        return 2
    b = Bin(str(Path(args.bin).resolve()))
    out: Path = args.outdir
    out.mkdir(parents=True, exist_ok=True)
    work = out / ".work"
    work.mkdir(exist_ok=True)
    n_paper, n_obl, n_eng, n_scene, n_host = (20, 20, 30, 40, 8) if not args.quick else (3, 3, 4, 6, 2)
    cmds: list[str] = ["# written by fuzz.py; {F} is the directory of the fuzzed inputs"]
    modes = ["", "--backend f64", "--ulps 16", "--rtol 1e-6"]

    def rng_for(kind: str, i: int) -> random.Random:
        return random.Random(f"{args.seed}/{kind}/{i}")

    # (a) and (b)
    for kind, count, oblique in (("paper", n_paper, False), ("oblique", n_obl, True)):
        for i in range(count):
            rng = rng_for(kind, i)
            hostile = i % 2 == 1
            nrows = 4500 if (i == 0 and kind == "paper") else rng.choice([1, 5, 40, 200, 700])
            p = out / f"{kind}-{i:02d}.csv"
            gen_scene_csv(p, rng, oblique, hostile, nrows)
            if not hostile:
                repair_csv(b, p, work)
            for mode in modes:
                cmds.append(f"rodimpact batch {{F}}/{p.name} {mode}".rstrip())
            cmds.append(f"rodimpact batch {{F}}/{p.name} --out out.csv --summary-json s.json")
            cmds.append(f"rodimpact batch {{F}}/{p.name} --ulps 4 --out out.csv")
            if i % 4 == 0:
                cmds.append(f"rodimpact batch {{F}}/{p.name} --jobs 1")

    # (c)
    for i in range(n_eng):
        rng = rng_for("engine", i)
        p = out / f"engine-{i:02d}.csv"
        e = out / f"engine-{i:02d}-expect.csv"
        info = gen_engine_csv(b, p, e, rng, i, work)
        for mode in modes:
            cmds.append(f"rodimpact batch {{F}}/{p.name} {mode}".rstrip())
        cmds.append(f"rodimpact batch {{F}}/{p.name} --ulps 16 --out out.csv --summary-json s.json")
        if info.get("fmt") == "f32":
            cmds.append(f"rodimpact batch {{F}}/{p.name} --ulps 16 --float f32")
        cmds.append(f"rodimpact batch {{F}}/{p.name} --rtol 1e-6 --atol 1e-12")
        if e.exists():
            cmds.append(f"rodimpact batch {{F}}/{p.name} --ulps 16 --expect {{F}}/{e.name} --summary-json s.json --out out.csv")
        cmds.append(f"rodimpact batch {{F}}/{p.name} --tolerance pivot=rtol:1e-6 --tolerance free=ulps:16 --tolerance 'id:*-big-*=exact'")

    # (d)
    scenes_json = []
    for i in range(n_scene):
        rng = rng_for("scene", i)
        text, (bodies, contacts, pins, title), nc = gen_impact_scene(b, rng, i, work)
        p = out / f"scene-{i:02d}.toml"
        p.write_text(text, encoding="utf-8")
        scenes_json.append((f"scene-{i:02d}", scene_to_json(f"scene-{i:02d}", title, bodies, contacts, pins), nc))
        if nc == 1:
            for law in ("newton", "poisson", "energetic", "all"):
                for fmt in ("text", "json"):
                    cmds.append(f"rodimpact impact {{F}}/{p.name} --law {law} --format {fmt}")
            cmds.append(f"rodimpact impact {{F}}/{p.name} --digits 40")
        else:
            for model in ("simultaneous-newton", "simultaneous-poisson", "sequential", "pgs:1", "pgs:10", "all"):
                for fmt in ("text", "json"):
                    cmds.append(f"rodimpact impact {{F}}/{p.name} --model {model} --format {fmt}")
            order = ",".join(str(j) for j in range(nc, 0, -1))
            cmds.append(f"rodimpact impact {{F}}/{p.name} --model sequential:{order} --format json")
            cmds.append(f"rodimpact impact {{F}}/{p.name} --digits 40")
    for k in range(n_host):
        rng = rng_for("hostile", k)
        base = (out / f"scene-{k * 3 % n_scene:02d}.toml").read_text(encoding="utf-8")
        p = out / f"hostile-{k:02d}.toml"
        p.write_text(hostile_scene(rng, base, k), encoding="utf-8")
        cmds.append(f"rodimpact impact {{F}}/{p.name}")
        cmds.append(f"rodimpact impact {{F}}/{p.name} --format json")

    # (e)
    answers = exact_answers(b, [s for _, s, _ in scenes_json], work)
    groups = {"claims-1.jsonl": [], "claims-2.jsonl": [], "claims-3.jsonl": []}
    for (sid, scene, nc), ex in zip(scenes_json, answers):
        rng = rng_for("claims", int(sid.split("-")[1]))
        for rep in range(2):
            s = json.loads(json.dumps(scene))
            s["id"] = f"{sid}-{rep + 1}"
            s["claimed"] = claimed_from(ex, scene, rng)
            groups["claims-1.jsonl" if nc == 1 else "claims-2.jsonl"].append(s)
            if rng.random() < 0.5:
                groups["claims-3.jsonl"].append(s)
    # claims-3: a mixed file, also some lines without a claim
    extra = []
    for sid, scene, nc in scenes_json[::5]:
        s = json.loads(json.dumps(scene))
        s["id"] = sid + "-noclaim"
        extra.append(s)
    groups["claims-3.jsonl"] += extra
    random.Random(f"{args.seed}/shuffle").shuffle(groups["claims-3.jsonl"])
    for name, lines in groups.items():
        (out / name).write_text("".join(json.dumps(x) + "\n" for x in lines), encoding="utf-8")
        for flags in ("", "--rtol 1e-3", "--rtol 1e-2", "--rtol 0"):
            cmds.append(f"rodimpact impact --batch {{F}}/{name} {flags}".rstrip())
    # a hostile JSONL: a claim without a moving body, bad numbers, a bad line in the middle
    lines = [json.dumps(x) for x in groups["claims-1.jsonl"][:6]]
    if lines:
        bad = json.loads(lines[0])
        bad["claimed"]["bodies"] = {}
        lines.insert(2, json.dumps(bad))
        lines.insert(4, "{not json")
    (out / "claims-hostile.jsonl").write_text("\n".join(lines) + "\n", encoding="utf-8")
    cmds.append("rodimpact impact --batch {F}/claims-hostile.jsonl")

    shutil.rmtree(work)
    (out / "commands.txt").write_text("\n".join(cmds) + "\n", encoding="utf-8")
    print(f"fuzz.py: {len(cmds) - 1} command lines over the inputs in {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
