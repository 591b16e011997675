#!/usr/bin/env python3
"""Score engine output against the exact answers, independently of rodimpact.

Usage:
    python3 engines/check.py [--by class|dt|iters|e] [--markdown | --rows] ENGINE.csv [...]

Reads the scene cells of every row (`m,M,l,a,v0,rod,e,pivot`, exact rationals), solves the
impact exactly with `fractions.Fraction` (closed forms derived below, each checked against the
balance laws they come from), converts each claimed float to the exact rational it denotes, and
prints, per engine, version, float and group (scene class by default): the number of rows, the
worst relative error of v, V and omega, the kinetic-energy excess over the exact after-impact
energy (in units of the energy before; + = the engine made energy, - = it lost energy the law
does not lose), and counts of the diagnoses below. Standard library only.

Relative error: |claim - exact| / |exact|; when the exact value is 0 (omega for a = 0, V for a
pivot at the centre, v when the projectile stops) the error is divided by v0 (by v0/l for
omega) instead.

Diagnoses (a row can have several; "ok" when none applies):
  nan                 a claimed value is NaN or infinite
  no-contact          v, V, omega are the state before the impact (v = v0, V = omega = 0), within
                      1e-6 v0
  restitution-ignored e > 0 and the claim is within 1 % (relative to v0) of the e = 0 answer and
                      nearer to it than to the exact answer
  above-omega-max     |omega| exceeds, exactly, the largest |omega| any impact point on this rod
                      (this pivot) can give with this e: (1+e) v0 / (2 d*) with d*^2 = I_p (1/m + 1/M')
                      (free rod: I_p = I, 1/M' = 1/M; pivot: I_p = I + M p^2, 1/M' = 0), or the
                      value at the farthest point when d* is beyond it
  energy-gain         energy_after (the engine's state) exceeds the energy before the impact by
                      more than 1e-3 of it: energy was created
  energy-loss         energy_after falls short of the exact after-impact energy (the loss the law
                      allows for this e) by more than 1e-3 of the energy before
  off                 none of the above, but some relative error of v, V, omega exceeds 1e-3
"""

import argparse
import csv
import math
import sys
from collections import defaultdict
from fractions import Fraction as Q


def rational(text):
    """An exact rational from a suite cell: integer, p/q or decimal."""
    return Q(text.strip())


def rod_inertia(rod, M, l):
    if rod == "uniform":
        return M * l * l / 3
    if rod == "dumbbell":
        return M * l * l
    if rod.startswith("rg="):
        r = rational(rod[3:])
        return M * r * r
    if rod.startswith("I="):
        return rational(rod[2:])
    raise ValueError(f"rod '{rod}' is not uniform, dumbbell, rg=Q or I=Q")


class Exact:
    """The exact state right after the impact, with the laws it satisfies checked exactly.

    Free rod (DESIGN convention: the rod point at y moves along x with V + omega y):
        1/k = 1/m + 1/M + a^2/I,  J = (1+e) v0 k,  v = v0 - J/m,  V = J/M,  omega = J a / I.
    Pivot at p (d = a - p, I_p = I + M p^2): the pivot's impulse has no moment about the pivot,
    so  m v0 d = m v d + I_p omega;  Newton at the contact: omega d - v = e v0.  Hence
        omega = (1+e) m d v0 / (I_p + m d^2),  v = omega d - e v0,  V = -omega p,
        J = m (v0 - v) (on the rod),  pivot impulse P = M V - J.
    """

    def __init__(self, m, M, l, a, v0, I, e, p):
        self.m, self.M, self.l, self.a, self.v0, self.I, self.e, self.p = m, M, l, a, v0, I, e, p
        if p is None:
            k = 1 / (1 / m + 1 / M + a * a / I)
            J = (1 + e) * v0 * k
            v, V, w = v0 - J / m, J / M, J * a / I
            # laws: linear momentum, angular momentum about the rod's centre, restitution
            assert m * v0 == m * v + M * V
            assert m * v0 * a == m * v * a + I * w
            assert (V + w * a) - v == e * v0
        else:
            d = a - p
            Ip = I + M * p * p
            w = (1 + e) * m * d * v0 / (Ip + m * d * d)
            v = w * d - e * v0
            V = -w * p
            J = m * (v0 - v)
            # laws: angular momentum about the pivot, restitution, the rod's own momentum balance
            assert m * v0 * d == m * v * d + Ip * w
            assert (V + w * a) - v == e * v0
            assert M * V == J + (M * V - J)
            # the rod's angular momentum about its centre changes only by the contact's moment
            # plus the pivot impulse's moment: I w = J a + (M V - J) p
            assert I * w == J * a + (M * V - J) * p
        self.v, self.V, self.omega, self.J = v, V, w, J
        self.energy_before = m * v0 * v0 / 2
        self.energy_after = (m * v * v + M * V * V + I * w * w) / 2
        if e == 1:
            assert self.energy_after == self.energy_before

    def with_e(self, e):
        return Exact(self.m, self.M, self.l, self.a, self.v0, self.I, e, self.p)

    def above_omega_max(self, omega):
        """Is |omega| above the largest |omega| any impact point can give? Decided exactly."""
        p = self.p if self.p is not None else Q(0)
        Ip = self.I + self.M * p * p
        inv_mass = 1 / self.m + (1 / self.M if self.p is None else 0)
        d_star_sq = Ip * inv_mass
        reach = self.l + abs(p)  # farthest impact point from the pivot (centre)
        w = abs(omega)
        top = (1 + self.e) * abs(self.v0)
        if d_star_sq <= reach * reach:
            # |omega| > top / (2 d*)  <=>  omega^2 4 d*^2 > top^2
            return w * w * 4 * d_star_sq > top * top
        # the maximum is at the farthest point: omega(d) = top d / (d*^2 + d^2) with d = reach
        return w > top * reach / (d_star_sq + reach * reach)


def exact_for(row):
    m, M, l = rational(row["m"]), rational(row["M"]), rational(row["l"])
    a, v0, e = rational(row["a"]), rational(row["v0"]), rational(row["e"])
    p = rational(row["pivot"]) if row["pivot"].strip() else None
    return Exact(m, M, l, a, v0, rod_inertia(row["rod"].strip(), M, l), e, p)


def claim(text):
    """The exact rational a printed float denotes, or None for NaN/inf."""
    x = float(text)
    if math.isnan(x) or math.isinf(x):
        return None
    return Q(text.strip())


def rel_error(c, x, scale):
    return abs(c - x) / (abs(x) if x != 0 else scale)


def diagnose(row, ex):
    """Relative errors, energy excess and diagnoses of one row."""
    v, V, w = claim(row["v"]), claim(row["V"]), claim(row["omega"])
    K1 = claim(row["energy_after"]) if row.get("energy_after", "").strip() else None
    if v is None or V is None or w is None:
        return None, None, ["nan"]
    errs = (
        rel_error(v, ex.v, ex.v0),
        rel_error(V, ex.V, ex.v0),
        rel_error(w, ex.omega, ex.v0 / ex.l),
    )
    excess = None if K1 is None else (K1 - ex.energy_after) / ex.energy_before
    diags = []
    tol_state = Q(1, 10**6) * abs(ex.v0)
    if abs(v - ex.v0) <= tol_state and abs(V) <= tol_state and abs(w) * ex.l <= tol_state:
        diags.append("no-contact")
    if ex.e > 0:
        stuck = ex.with_e(Q(0))
        dist0 = max(abs(v - stuck.v), abs(V - stuck.V), abs(w - stuck.omega) * ex.l)
        dist1 = max(abs(v - ex.v), abs(V - ex.V), abs(w - ex.omega) * ex.l)
        if dist0 <= Q(1, 100) * abs(ex.v0) and dist0 < dist1:
            diags.append("restitution-ignored")
    if ex.above_omega_max(w * (1 - Q(1, 10**5))):
        diags.append("above-omega-max")
    if K1 is not None and K1 > ex.energy_before * (1 + Q(1, 1000)):
        diags.append("energy-gain")
    if excess is not None and excess < -Q(1, 1000):
        diags.append("energy-loss")
    if not diags and max(errs) > Q(1, 1000):
        diags.append("off")
    return errs, excess, diags or ["ok"]


def fmt(x):
    return "-" if x is None else f"{float(x):.2g}"


def fmt_signed(x):
    return "-" if x is None else f"{float(x):+.2g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+")
    ap.add_argument("--by", default="class", help="group column (class, dt, iters, e, ...)")
    ap.add_argument("--markdown", action="store_true", help="print a Markdown table")
    ap.add_argument("--rows", action="store_true",
                    help="print every row's errors and diagnoses instead of the summary")
    args = ap.parse_args()

    groups = defaultdict(lambda: {"rows": 0, "err": [Q(0)] * 3, "gain": None, "loss": None,
                                  "diags": defaultdict(int)})
    exact_cache = {}
    for path in args.files:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                key_scene = tuple(row[c] for c in ("m", "M", "l", "a", "v0", "rod", "e", "pivot"))
                if key_scene not in exact_cache:
                    exact_cache[key_scene] = exact_for(row)
                ex = exact_cache[key_scene]
                errs, excess, diags = diagnose(row, ex)
                if args.rows:
                    print(",".join([row["id"], row["engine"], row["float"], row["dt"], row["iters"],
                                    *(["nan"] * 3 if errs is None else map(fmt, errs)),
                                    fmt_signed(excess), ";".join(diags)]))
                    continue
                key = (row["engine"], row["version"], row["float"], row[args.by])
                g = groups[key]
                g["rows"] += 1
                if errs is not None:
                    g["err"] = [max(a, b) for a, b in zip(g["err"], errs)]
                if excess is not None:
                    g["gain"] = excess if g["gain"] is None else max(g["gain"], excess)
                    g["loss"] = excess if g["loss"] is None else min(g["loss"], excess)
                for d in diags:
                    g["diags"][d] += 1

    if args.rows:
        return
    header = ["engine", "version", "float", args.by, "rows", "max rel err v", "V", "omega",
              "energy excess min", "max", "diagnoses"]
    lines = []
    for key in sorted(groups, key=lambda k: (k[0], k[1], k[2], str(k[3]))):
        g = groups[key]
        diag = ", ".join(f"{d} {n}" for d, n in sorted(g["diags"].items()))
        lines.append([*map(str, key), str(g["rows"]), *map(fmt, g["err"]),
                      fmt_signed(g["loss"]), fmt_signed(g["gain"]), diag])
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for line in lines:
            print("| " + " | ".join(line) + " |")
    else:
        w = csv.writer(sys.stdout)
        w.writerow(header)
        w.writerows(lines)


if __name__ == "__main__":
    main()
