#!/usr/bin/env python3
"""Score engines' planar impacts exactly (Python `fractions`, standard library only).

Reads fixture lines (tests/data/engines/impacts/*.jsonl: a scene of engines/impacts.jsonl plus
"claimed", the engine's velocities and spins after the impact) and compares each claim with the
exact answers of the lead's oracles, imported from tests/oracles/:
  * one contact (planar_impact.py): Routh's process under Newton's, Poisson's and Stronge's
    (energetic) laws, `newton`, `poisson`, `energetic`; and, for a scene without a pin, the one-
    phase complementarity models of multi_contact.py that projected Gauss-Seidel solvers aim at,
    `lcp-newton` (Newton's law on the final normal velocity, Coulomb's law on the final slip) and
    `lcp-poisson` (two phases, Coulomb in each);
  * several contacts (multi_contact.py): `sim-newton`, `sim-poisson`, `sequential` (each distinct
    outcome over the orders), `pgs:1`, `pgs:2`, `pgs:3`, `pgs:10` (frictionless scenes only: the
    oracle runs sequential and PGS without friction);
  * `split` (any scene without a pin; computed here from multi_contact.py's exact LCP solvers):
    the two-pass reading of engines that solve the contact without restitution, friction
    included, and then apply restitution in an end-of-step pass with no friction (Box2D 3;
    Rapier 0.36's `solve_restitution`): see `split_model`.
Answers that are equal are merged into one candidate named by all its models
(`newton=poisson=...`). A surd (Stronge's law) is replaced by a rational within 1e-40.

Error of a claim against an answer: the kinetic-energy norm of the difference of the velocity
states over the energy before, sqrt(T(claim - answer) / T(before)) (every moving body, both
velocity components and spin, weighted by the scene's masses and inertias; dimensionless and
independent of units). The claim's floats are read as the exact decimals they print.

Also per line: the engine's energy change (T(claim) - T(before)) / T(before); `sinks` when a
contact's normal velocity after is below -1e-6 of the largest approach speed; for one frictional
contact the engine's impulse (from a free body's momentum change) as tau / (mu lam): 1 on the
cone, below 1 inside it (sticking, or a friction bounded differently), above 1 outside it.

Usage: python3 engines/check_impacts.py [--rows] [--markdown] [FILE.jsonl ...]
  (default: every tests/data/engines/impacts/*.jsonl; --rows: one line per scene, with the error
  against every candidate)
"""

import glob
import json
import math
import os
import sys
from fractions import Fraction as F

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "oracles"))
import multi_contact  # noqa: E402
import planar_impact  # noqa: E402

SURD_DIGITS = 40


def exact(v):
    """A Fraction from a Fraction, a QSqrt (to within 1e-40) or an exact string."""
    if isinstance(v, planar_impact.QSqrt):
        scale = 10 ** SURD_DIGITS
        root = F(math.isqrt(v.d * scale * scale), scale)
        return v.x + v.y * root
    return F(v)


def state_of(bodies):
    """{name: (vx, vy, w)} from an oracle's or a claim's "bodies"."""
    return {name: (exact(b["velocity"][0]), exact(b["velocity"][1]), exact(b["omega"]))
            for name, b in bodies.items()}


class Masses:
    def __init__(self, line):
        self.m, self.I, self.before = {}, {}, {}
        for b in planar_impact.Scene(dict(line, contact=line["contact"][:1])).moving():
            self.m[b.name], self.I[b.name] = b.mass, b.inertia
            self.before[b.name] = (b.velocity[0], b.velocity[1], b.omega)

    def energy(self, state):
        return sum((self.m[k] * (v[0] ** 2 + v[1] ** 2) + self.I[k] * v[2] ** 2) / 2
                   for k, v in state.items())

    def error(self, claim, answer):
        diff = {k: tuple(claim[k][i] - answer[k][i] for i in range(3)) for k in answer}
        return math.sqrt(self.energy(diff) / self.energy(self.before))


def candidates(line):
    """[(model name, exact state)] for the scene."""
    out = []
    one = len(line["contact"]) == 1
    if one:
        result = planar_impact.solve(planar_impact.Scene(line), fmt=lambda v: v)
        for law in result["laws"]:
            out.append((law["law"], state_of(law["bodies"])))
    if "pin" in line and line["pin"]:
        return out
    sc = multi_contact.Scene(line, line["id"])
    res = multi_contact.analyse(sc)
    for m in res["models"]:
        name = m["model"]
        if name in ("sequential-priority", "pgs:limit"):
            continue
        if name == "sequential":
            groups = m["agreement"]
            for k, g in enumerate(groups):
                label = "sequential" if len(groups) == 1 else f"sequential[{','.join(g['orders'][:2])}{'...' if len(g['orders']) > 2 else ''}]"
                out.append((label, state_of(g["bodies"])))
            continue
        label = name.replace("simultaneous-", "sim-")
        if one:
            if not name.startswith("simultaneous"):
                continue
            label = label.replace("sim-", "lcp-")
        sols = m["solutions"] if "solutions" in m else [m]
        for k, s in enumerate(sols):
            if "bodies" in s:
                out.append((label if len(sols) == 1 else f"{label}#{k + 1}", state_of(s["bodies"])))
    for k, st in enumerate(split_model(sc)):
        out.append(("split" if k == 0 else f"split#{k + 1}", st))
    return out


def merge(cands, masses):
    """Candidates with equal answers merged into one, named by all (a surd's rational stand-in
    counts as equal when within 1e-30 in the error norm)."""
    merged = []
    for name, st in cands:
        for i, (n2, s2) in enumerate(merged):
            if s2 == st or masses.error(st, s2) < 1e-30:
                merged[i] = (f"{n2}={name}", s2)
                break
        else:
            merged.append((name, st))
    return merged


def split_model(sc):
    """`split`: the engines' two-pass reading (Box2D 3 and this Rapier solve the contact without
    restitution, friction included, then apply restitution in one end-of-step pass with no
    friction): the compression LCP (Newton's law with e = 0 and Coulomb's law on the velocities
    at its end, every solution), then one Gauss-Seidel sweep in file order over the contacts
    that approached and took an impulse, lam_i <- max(0, lam_i - (u_i + e_i u0_i)/W_ii), normal
    impulses only. Exact states, one per compression solution."""
    s0 = sc.initial_state()
    u0, n = sc.un(s0), sc.n
    W = sc.delassus(sc.rows_n, sc.rows_n)
    if sc.friction:
        comps = [(LN, LT) for LN, LT, *_ in multi_contact.phase_solve(
            sc, u0, sc.ut(s0), [F(0)] * n, [F(0)] * n)]
    else:
        comps = [(lam, None) for lam in multi_contact.solve_lcp(W, u0)[0]]
    states = []
    for LN, LT in comps:
        state = sc.after(LN, LT)
        lam = list(LN)
        for i in range(n):
            if u0[i] < 0 and lam[i] > 0:
                u = sc.rowvel(sc.rows_n[i], state)
                new = max(F(0), lam[i] - (u + sc.contacts[i].e * u0[i]) / W[i][i])
                sc.apply(state, sc.rows_n[i], new - lam[i])
                lam[i] = new
        st = {b.name: tuple(state[i]) for i, b in enumerate(sc.bodies) if not b.fixed}
        if st not in states:
            states.append(st)
    return states


def contact_report(line, claim):
    """(sinking contacts, tau/(mu lam) for one frictional contact or None)."""
    bodies = {b["name"]: b for b in line["body"]}
    pins = {p["body"] for p in line.get("pin", [])}

    def point_velocity(name, x):
        if bodies[name].get("fixed"):
            return (F(0), F(0))
        c = [F(v) for v in bodies[name].get("position", ["0", "0"])]
        vx, vy, w = claim[name]
        return (vx - w * (x[1] - c[1]), vy + w * (x[0] - c[0]))

    approach = max(abs(u) for u in multi_contact_un(line))
    sinking, ratio = [], None
    for k, c in enumerate(line["contact"]):
        x = [F(v) for v in c["point"]]
        n = [F(v) for v in c["normal"]]
        a, b = (point_velocity(name, x) for name in c["bodies"])
        un = ((a[0] - b[0]) * n[0] + (a[1] - b[1]) * n[1]) / math.sqrt(n[0] ** 2 + n[1] ** 2)
        if un < -F(1, 10 ** 6) * approach:
            sinking.append(k + 1)
    if len(line["contact"]) == 1 and F(line["contact"][0].get("mu", "0")) > 0:
        c = line["contact"][0]
        n = [F(v) for v in c["normal"]]
        t = (-n[1], n[0])
        for name, sign in zip(c["bodies"], (1, -1)):
            b = bodies[name]
            if b.get("fixed") or name in pins:
                continue
            m = F(b["mass"])
            v0 = [F(v) for v in b.get("velocity", ["0", "0"])]
            P = [sign * m * (claim[name][i] - v0[i]) for i in range(2)]
            nn = n[0] ** 2 + n[1] ** 2
            lam, tau = (P[0] * n[0] + P[1] * n[1]) / nn, (P[0] * t[0] + P[1] * t[1]) / nn
            if lam > 0:
                ratio = float(abs(tau) / (F(c["mu"]) * lam))
            break
    return sinking, ratio


def multi_contact_un(line):
    sc = multi_contact.Scene(line, line["id"])
    return [u for u in sc.un(sc.initial_state())] or [F(1)]


def check(line):
    claim = state_of(line["claimed"]["bodies"])
    masses = Masses(line)
    cands = merge(candidates(line), masses)
    errors = [(name, masses.error(claim, st)) for name, st in cands]
    best = min(errors, key=lambda ne: ne[1])
    e0 = masses.energy(masses.before)
    best_energy = float((masses.energy(dict(cands)[best[0]]) - e0) / e0)
    gain = float((masses.energy(claim) - e0) / e0)
    sinking, ratio = contact_report(line, claim)
    return {"id": line["id"], "class": line["class"], "engine": line["claimed"]["engine"],
            "errors": errors, "best": best, "energy": gain, "best_energy": best_energy, "sinking": sinking, "cone": ratio}


def main(argv):
    rows = "--rows" in argv
    markdown = "--markdown" in argv
    files = [a for a in argv[1:] if not a.startswith("--")] or sorted(
        glob.glob(os.path.join(ROOT, "tests", "data", "engines", "impacts", "*.jsonl")))
    results = []
    for path in files:
        with open(path) as f:
            for text in f:
                if text.strip():
                    results.append(check(json.loads(text)))
    if rows:
        for r in results:
            errs = "  ".join(f"{n} {e:.2e}" for n, e in r["errors"])
            extra = f" dE/E {r['energy']:+.4f} (closest's {r['best_energy']:+.4f})"
            if r["sinking"]:
                extra += f" SINKS at {r['sinking']}"
            if r["cone"] is not None:
                extra += f" tau/(mu lam) {r['cone']:.4f}"
            print(f"{r['engine']:16} {r['id']:34} {r['class']:24} best {r['best'][0]} "
                  f"({r['best'][1]:.2e}){extra}\n    {errs}")
        print()
    # summary: per engine and class, how many scenes are closest to each candidate, the median
    # error of the closest, energy gains and sinking contacts
    table = {}
    for r in results:
        key = (r["engine"], r["class"])
        entry = table.setdefault(key, {"n": 0, "best": {}, "errs": [], "gain": 0, "sink": 0,
                                       "cone": []})
        entry["n"] += 1
        entry["best"][r["best"][0]] = entry["best"].get(r["best"][0], 0) + 1
        entry["errs"].append(r["best"][1])
        entry["gain"] += r["energy"] > 1e-6
        entry["model_gain"] = entry.get("model_gain", 0) + (r["best_energy"] > 0)
        entry["sink"] += bool(r["sinking"])
        if r["cone"] is not None:
            entry["cone"].append(r["cone"])
    head = ["engine", "class", "n", "closest to (scenes)", "max err of closest",
            "gains E (closest gains)", "sinks", "tau/(mu lam)"]
    out = []
    for (engine, cls), e in sorted(table.items()):
        best = ", ".join(f"{k} {v}" for k, v in sorted(e["best"].items(), key=lambda kv: -kv[1]))
        cone = f"{min(e['cone']):.3f}-{max(e['cone']):.3f}" if e["cone"] else ""
        out.append([engine, cls, str(e["n"]), best, f"{max(e['errs']):.1e}", f"{e['gain']} ({e['model_gain']})",
                    str(e["sink"]), cone])
    if markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for row in out:
            print("| " + " | ".join(row) + " |")
    else:
        widths = [max(len(x) for x in col) for col in zip(head, *out)]
        for row in [head] + out:
            print("  ".join(x.ljust(w) for x, w in zip(row, widths)).rstrip())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
