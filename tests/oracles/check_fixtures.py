#!/usr/bin/env python3
"""Re-check every fixture in tests/data/impacts/ from its own numbers and its scene file.

Written apart from multi_contact.py (no import of it) so that a slip in the oracle's Jacobian rows
or Delassus matrix would show here: the impulses of each model are applied to the bodies as
vectors (P = lambda n + tau t on A, -P on B; dv = P/m, domega = (r x P)/I), the contact velocities
are taken from the material points' velocities, and then each model's defining conditions are
tested exactly:

  simultaneous-newton   lambda >= 0, w = u+ + e min(u0, 0) >= 0, lambda w = 0 (Coulomb on u+ with friction)
  simultaneous-poisson  the compression and expansion conditions, phase by phase
  sequential            the listed impacts replayed from the velocities before, each one checked to be
                        the next firing of the pass rule, the final state nobody approaching
  sequential-priority   the same with the first-approaching-contact rule
  pgs:K                 K sweeps re-run from scratch with the effective masses computed per contact
  ledger                momentum, angular momentum about the origin, energy, normal velocities after

Prints one line per fixture and exits 1 on the first failure.
"""

import json
import sys
import tomllib
from fractions import Fraction as Q
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def num(x):
    s = str(x).strip()
    if "/" in s:
        a, b = s.split("/", 1)
        return num(a) / num(b)
    return Q(s)


def load_scene(path):
    data = tomllib.loads(Path(path).read_text())
    bodies = {}
    for t in data["body"]:
        b = {"fixed": bool(t.get("fixed", False)),
             "c": [num(v) for v in t.get("position", ["0", "0"])],
             "v": [num(v) for v in t.get("velocity", ["0", "0"])],
             "w": num(t.get("omega", "0"))}
        if not b["fixed"]:
            m = num(t["mass"])
            if "inertia" in t:
                I = num(t["inertia"])
            else:
                sh = t["shape"]
                I = {"rod": lambda: m * num(t["length"]) ** 2 / 12,
                     "disc": lambda: m * num(t["radius"]) ** 2 / 2,
                     "box": lambda: m * (num(t["width"]) ** 2 + num(t["height"]) ** 2) / 12,
                     "point": lambda: Q(0)}[sh]()
            b["m"], b["I"] = m, I
        bodies[t["name"]] = b
    contacts = []
    for t in data["contact"]:
        n = [num(v) for v in t["normal"]]
        contacts.append({"A": t["bodies"][0], "B": t["bodies"][1], "p": [num(v) for v in t["point"]],
                         "n": n, "t": [-n[1], n[0]], "e": num(t.get("e", "0")), "mu": num(t.get("mu", "0"))})
    return bodies, contacts


def state0(bodies):
    return {k: [b["v"][0], b["v"][1], b["w"]] for k, b in bodies.items()}


def point_velocity(bodies, st, name, p):
    b = bodies[name]
    r = [p[0] - b["c"][0], p[1] - b["c"][1]]
    vx, vy, w = st[name]
    return [vx - w * r[1], vy + w * r[0]]


def rel(bodies, st, c, d):
    va = point_velocity(bodies, st, c["A"], c["p"])
    vb = point_velocity(bodies, st, c["B"], c["p"])
    return (va[0] - vb[0]) * d[0] + (va[1] - vb[1]) * d[1]


def push(bodies, st, c, ln, lt=Q(0)):
    P = [ln * c["n"][0] + lt * c["t"][0], ln * c["n"][1] + lt * c["t"][1]]
    for name, s in ((c["A"], 1), (c["B"], -1)):
        b = bodies[name]
        if b["fixed"]:
            continue
        r = [c["p"][0] - b["c"][0], c["p"][1] - b["c"][1]]
        st[name][0] += s * P[0] / b["m"]
        st[name][1] += s * P[1] / b["m"]
        if b["I"] != 0:
            st[name][2] += s * (r[0] * P[1] - r[1] * P[0]) / b["I"]


def eff(bodies, c, d):
    """1/W_ii along direction d: the velocity change at the contact per unit impulse along d."""
    st = {k: [Q(0), Q(0), Q(0)] for k in bodies}
    cc = dict(c, n=d, t=[Q(0), Q(0)])
    push(bodies, st, cc, Q(1))
    return rel(bodies, st, c, d)


def apply_all(bodies, contacts, ln, lt=None):
    st = state0(bodies)
    for i, c in enumerate(contacts):
        push(bodies, st, c, ln[i], lt[i] if lt else Q(0))
    return st


def fail(msg):
    print("FAIL", msg)
    sys.exit(1)


def check_state(bodies, st, res, where):
    for name, b in bodies.items():
        if b["fixed"]:
            continue
        got = res["bodies"][name]
        if [num(x) for x in got["velocity"]] != st[name][:2] or num(got["omega"]) != st[name][2]:
            fail(f"{where}: body {name} {got} != {st[name]}")


def check_ledger(bodies, contacts, st, res, where):
    L = res["ledger"]
    free = [(k, b) for k, b in bodies.items() if not b["fixed"]]
    s0 = state0(bodies)

    def mom(s):
        return [sum((b["m"] * s[k][0] for k, b in free), Q(0)), sum((b["m"] * s[k][1] for k, b in free), Q(0))]

    def ang(s):
        return sum((b["I"] * s[k][2] + b["m"] * (b["c"][0] * s[k][1] - b["c"][1] * s[k][0]) for k, b in free), Q(0))

    def ke(s):
        return sum((b["m"] * (s[k][0] ** 2 + s[k][1] ** 2) / 2 + b["I"] * s[k][2] ** 2 / 2 for k, b in free), Q(0))

    ok = ([num(x) for x in L["momentum"]["before"]] == mom(s0) and [num(x) for x in L["momentum"]["after"]] == mom(st)
          and num(L["angular_momentum_origin"]["before"]) == ang(s0) and num(L["angular_momentum_origin"]["after"]) == ang(st)
          and num(L["energy"]["before"]) == ke(s0) and num(L["energy"]["after"]) == ke(st)
          and num(L["energy"]["change"]) == ke(st) - ke(s0) and L["energy_gain"] == (ke(st) > ke(s0)))
    if not ok:
        fail(f"{where}: ledger")
    un = [rel(bodies, st, c, c["n"]) for c in contacts]
    if [num(x) for x in L["normal_velocity_after"]] != un:
        fail(f"{where}: normal velocities after")
    if L["sinking_contacts"] != [i + 1 for i, u in enumerate(un) if u < 0]:
        fail(f"{where}: sinking contacts")


def coulomb(c, LN, LT, uT, where):
    if abs(LT) > c["mu"] * LN:
        fail(f"{where}: outside the friction cone")
    if uT != 0 and LT != -c["mu"] * LN * (1 if uT > 0 else -1):
        fail(f"{where}: friction not opposing the slip")


def check_model(bodies, contacts, m, u0):
    name = m["model"]
    sols = m.get("solutions", [m] if "bodies" in m else [])
    friction = any(c["mu"] > 0 for c in contacts)
    for k, res in enumerate(sols):
        where = f"{name}[{k}]"
        ln = [num(i["normal"]) for i in res["impulses"]]
        lt = [num(i.get("tangential", "0")) for i in res["impulses"]]
        st = apply_all(bodies, contacts, ln, lt)
        check_state(bodies, st, res, where)
        check_ledger(bodies, contacts, st, res, where)
        un = [rel(bodies, st, c, c["n"]) for c in contacts]
        ut = [rel(bodies, st, c, c["t"]) for c in contacts]
        if name == "simultaneous-newton" or name == "pgs:limit":
            for i, c in enumerate(contacts):
                w = un[i] + c["e"] * min(u0[i], Q(0))
                if ln[i] < 0 or w < 0 or ln[i] * w != 0:
                    fail(f"{where}: Newton complementarity at contact {i + 1}")
                if friction:
                    coulomb(c, ln[i], lt[i], ut[i], where)
        if name == "simultaneous-poisson":
            C, E = res["compression"], res["expansion"]
            if friction:
                lnc = [num(x) for x in C["normal_impulses"]]
                ltc = [num(x) for x in C["tangential_impulses"]]
                lne = [num(x) for x in E["normal_impulses"]]
                lte = [num(x) for x in E["tangential_impulses"]]
            else:
                lnc = [num(x) for x in C["impulses"]]
                ltc = [Q(0)] * len(contacts)
                lne = [num(x) for x in E["impulses"]]
                lte = [Q(0)] * len(contacts)
            sc = apply_all(bodies, contacts, lnc, ltc)
            for i, c in enumerate(contacts):
                unc = rel(bodies, sc, c, c["n"])
                if lnc[i] < 0 or unc < 0 or lnc[i] * unc != 0:
                    fail(f"{where}: compression complementarity at {i + 1}")
                if friction:
                    coulomb(c, lnc[i], ltc[i], rel(bodies, sc, c, c["t"]), where + " compression")
                x = lne[i] - c["e"] * lnc[i]
                if x < 0 or un[i] < 0 or x * un[i] != 0:
                    fail(f"{where}: expansion complementarity at {i + 1}")
                if friction:
                    coulomb(c, lne[i], lte[i], ut[i], where + " expansion")
                if lnc[i] + lne[i] != ln[i] or ltc[i] + lte[i] != lt[i]:
                    fail(f"{where}: phases do not add up")


def check_sequential(bodies, contacts, m):
    for o in m["orders"]:
        where = o["model"]
        order = [i - 1 for i in o["order"]]
        st = state0(bodies)
        listed = [(i["contact"] - 1, num(i["impulse"])) for i in o["impacts"]]
        k = 0
        if not o["terminated"]:
            print("  (", where, "does not terminate: replay skipped)")
            continue
        while True:
            fired = False
            for i in order:
                c = contacts[i]
                u = rel(bodies, st, c, c["n"])
                if u < 0:
                    lam = -(1 + c["e"]) * u / eff(bodies, c, c["n"])
                    if k >= len(listed) or listed[k] != (i, lam):
                        fail(f"{where}: impact {k + 1} should be contact {i + 1} with {lam}")
                    push(bodies, st, c, lam)
                    k += 1
                    fired = True
            if not fired:
                break
        if k != len(listed):
            fail(f"{where}: extra impacts listed")
        check_state(bodies, st, o, where)
        check_ledger(bodies, contacts, st, o, where)


def check_sequential_priority(bodies, contacts, m):
    for o in m["orders"]:
        where = o["model"]
        if not o["terminated"]:
            continue
        order = [i - 1 for i in o["order"]]
        st = state0(bodies)
        k = 0
        listed = [(i["contact"] - 1, num(i["impulse"])) for i in o["impacts"]]
        while True:
            nxt = next((i for i in order if rel(bodies, st, contacts[i], contacts[i]["n"]) < 0), None)
            if nxt is None:
                break
            c = contacts[nxt]
            lam = -(1 + c["e"]) * rel(bodies, st, c, c["n"]) / eff(bodies, c, c["n"])
            if k < len(listed) and listed[k] != (nxt, lam):
                fail(f"{where}: impact {k + 1} should be contact {nxt + 1} with {lam}")
            push(bodies, st, c, lam)
            k += 1
        if k != o["number_of_impacts"]:
            fail(f"{where}: number of impacts")
        check_state(bodies, st, o, where)
        check_ledger(bodies, contacts, st, o, where)


def check_pgs(bodies, contacts, models, u0):
    for m in models:
        if not m["model"].startswith("pgs:") or m["model"] == "pgs:limit":
            continue
        K = int(m["model"][4:])
        st = state0(bodies)
        lam = [Q(0)] * len(contacts)
        for _ in range(K):
            for i, c in enumerate(contacts):
                u = rel(bodies, st, c, c["n"])
                new = max(Q(0), lam[i] - (u + c["e"] * min(u0[i], Q(0))) / eff(bodies, c, c["n"]))
                push(bodies, st, c, new - lam[i])
                lam[i] = new
        if [num(i["normal"]) for i in m["impulses"]] != lam:
            fail(f"{m['model']}: accumulated impulses")
        check_state(bodies, st, m, m["model"])
        check_ledger(bodies, contacts, st, m, m["model"])


def main():
    files = sorted((ROOT / "tests" / "data" / "impacts").glob("*.json"))
    for f in files:
        d = json.loads(f.read_text())
        if "models" not in d:
            continue  # one contact: planar_impact.py's fixture, checked by check_planar.py
        bodies, contacts = load_scene(ROOT / d["scene"]["file"])
        s0 = state0(bodies)
        u0 = [rel(bodies, s0, c, c["n"]) for c in contacts]
        if [num(x) for x in d["normal_velocity_before"]] != u0:
            fail(f"{f.name}: normal velocities before")
        n = 0
        for m in d["models"]:
            if m["model"] == "sequential":
                check_sequential(bodies, contacts, m)
            elif m["model"] == "sequential-priority":
                check_sequential_priority(bodies, contacts, m)
            else:
                check_model(bodies, contacts, m, u0)
            n += 1
        check_pgs(bodies, contacts, d["models"], u0)
        print(f"ok {f.name}: {n} models")
    return 0


if __name__ == "__main__":
    sys.exit(main())
