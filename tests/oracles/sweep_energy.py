#!/usr/bin/env python3
"""Rational sweep: does any law gain kinetic energy in ONE frictional contact?

Random exact scenes of two families, solved by planar_impact.py under the three laws, the sign of
each energy change decided exactly (a surd's sign by comparing squares):
  * tilted rod: a uniform rod (random mass, length) at a random Pythagorean tilt
    (cos, sin) = (a, b)/c, its lower end on the floor y = 0;
  * box corner: a random box (mass, width, height) at a random Pythagorean tilt, its lowest corner
    on the floor;
  * pendulum: the tilted rod pinned at a random point of its axis (not its lower end), turning
    about the pin (W has rank one);
with random velocity (falling: the contact approaches), spin, mu (a quarter of the scenes
frictionless) and e (0 and 1 included).  Reports how often each law gains energy, the largest
relative gain, how often the laws coincide, and every scene where Poisson's or the energetic law
gains (none expected: Stronge 1991; Poisson can gain only with several contacts, Glocker 2013).

Also checked on every scene: a Newton gain has W_nt != 0 and a mode change inside the impact; with
mu = 0 the three laws give the same answer, and when the u_n
slope never changes before the largest lam_f (W_nt = 0, or no mode change in the window) they
coincide too.

    python3 tests/oracles/sweep_energy.py [N] [SEED] [--stepping K]
        N solved scenes per family (default 2000), seed 1; --stepping K also compares the first K
        scenes of each family with check_planar.py's float march in lam (needs sympy).
"""

import random
import sys
from fractions import Fraction as F

import planar_impact as pi


def rnd(rng, lo, hi, den=(1, 2, 3, 4, 5, 6, 8, 10)):
    d = rng.choice(den)
    lo_n, hi_n = -((-lo.numerator * d) // lo.denominator) if isinstance(lo, F) else lo * d, \
        (hi.numerator * d) // hi.denominator if isinstance(hi, F) else hi * d
    return F(rng.randint(lo_n, hi_n), d)        # a multiple of 1/d in [lo, hi]


def triple(rng):
    while True:
        m, n = rng.randint(2, 7), rng.randint(1, 6)
        if n < m:
            return (m * m - n * n, 2 * m * n, m * m + n * n)


def s(v):
    return f"{v.numerator}/{v.denominator}"


def scene(rng, kind):
    a, b, c = triple(rng)
    if rng.random() < 0.5:
        a, b = b, a
    if rng.random() < 0.5:
        a = -a                                   # tilt left or right
    ax, ay = F(a, c), F(b, c)                     # unit axis, ay > 0
    mass = rnd(rng, F(1, 2), 3)
    vx, vy = rnd(rng, -2, 2), rnd(rng, -2, F(-1, 10))
    w = rnd(rng, -3, 3)
    mu = F(0) if rng.random() < 0.25 else rnd(rng, 0, 2, den=(2, 3, 4, 5, 8, 10, 20))
    e = rng.choice([F(0), F(1), rnd(rng, 0, 1)])
    if kind in ("rod", "pendulum"):
        L = rnd(rng, F(1, 2), 3)
        cx, cy = F(0), L / 2 * ay
        px, py = cx - L / 2 * ax, F(0)
        body = {"name": "rod", "mass": s(mass), "shape": "rod", "length": s(L),
                "axis": [str(a), str(b)]}
    else:
        W, H = rnd(rng, F(1, 2), 3), rnd(rng, F(1, 5), 2)
        bx, by = -ay, ax                          # the height side's direction
        best = None
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                ox, oy = s1 * W / 2 * ax + s2 * H / 2 * bx, s1 * W / 2 * ay + s2 * H / 2 * by
                if best is None or oy < best[1]:
                    best = (ox, oy)
        cx, cy = F(0), -best[1]
        px, py = best[0], F(0)
        body = {"name": "box", "mass": s(mass), "shape": "box", "width": s(W), "height": s(H),
                "axis": [str(a), str(b)]}
    doc = {"title": kind, "body": [body, {"name": "floor", "fixed": True}],
           "contact": [{"bodies": [body["name"], "floor"], "point": [s(px), s(py)],
                        "normal": ["0", "1"], "e": s(e), "mu": s(mu)}]}
    if kind == "pendulum":
        # pinned at c + k (L/2) axis, k in (-1, 1]; v = w (c - q)^perp so the pin is at rest
        k = rnd(rng, F(-9, 10), 1)
        qx, qy = cx + k * L / 2 * ax, cy + k * L / 2 * ay
        vx, vy = -w * (cy - qy), w * (cx - qx)
        doc["pin"] = [{"body": "rod", "point": [s(qx), s(qy)]}]
    body.update(position=[s(cx), s(cy)], velocity=[s(vx), s(vy)], omega=s(w))
    return doc


STEP_CHECK = 0


def main(argv):
    global STEP_CHECK
    if "--stepping" in argv:                # --stepping K: also march the first K per family
        k = argv.index("--stepping")
        STEP_CHECK = int(argv[k + 1])
        argv = argv[:k] + argv[k + 2:]
    N = int(argv[0]) if argv else 2000
    rng = random.Random(int(argv[1]) if len(argv) > 1 else 1)
    ident = lambda v: v
    kinds = ("rod", "box", "pendulum")
    stats = {k: {"n": 0, "gain": {l: 0 for l in pi.LAWS}, "differ": 0, "max_gain": F(0),
                 "max_scene": None, "refused": {}, "modes": {}, "example": {}} for k in kinds}
    bad = []
    i = 0
    while min(stats[k]["n"] for k in kinds) < N:
        kind = kinds[i % 3]
        i += 1
        st = stats[kind]
        if st["n"] >= N:
            continue
        doc = scene(rng, kind)
        try:
            res = pi.solve(pi.Scene(doc), fmt=ident)
        except pi.SceneError as exc:
            why = str(exc).split(":")[0]
            st["refused"][why] = st["refused"].get(why, 0) + 1
            if why != "no approach":
                st["example"].setdefault(why, doc)
            continue
        st["n"] += 1
        if st["n"] <= STEP_CHECK:
            # cross-check with check_planar's float march in lam (a different algorithm)
            from check_planar import stepping
            W = res["contact"]["W"]
            for L in res["laws"]:
                cv = L["contact_velocity"]["before"]
                got = stepping(W["nn"], W["nt"], W["tt"], cv["n"], cv["t"],
                               res["contact"]["mu"], res["contact"]["e"], L["law"], steps=20000)
                sc = float(abs(cv["n"]) / W["nn"])
                if got is None or abs(got[0] - float(L["lam_f"])) > 1e-2 * sc or \
                        abs(got[1] - float(L["impulse_coefficients"]["tau"])) > 1e-2 * sc:
                    bad.append(("stepping", L["law"], doc, got))
            st["stepped"] = st.get("stepped", 0) + 1
        laws = {L["law"]: L for L in res["laws"]}
        E0 = laws["newton"]["energy"]["before"]
        for law, L in laws.items():
            if L["energy_gain"]:
                st["gain"][law] += 1
                if law == "newton":
                    # a gain needs coupling (W_nt != 0) and a mode change inside the impact
                    if res["contact"]["W"]["nt"] == 0 or len(L["phases"]) < 2:
                        bad.append(("newton gain without coupling and mode change", doc))
                    rel = L["energy"]["change"] / E0
                    if rel > st["max_gain"]:
                        st["max_gain"], st["max_scene"] = rel, doc
                else:
                    bad.append((law, doc, L["energy"]["change"]))
        ends = [laws[l]["lam_f"] for l in pi.LAWS]
        same = all(pi.sign(x - ends[0]) == 0 for x in ends)
        if not same:
            st["differ"] += 1
        key = "/".join(p["mode"] for p in laws["newton"]["phases"])
        st["modes"][key] = st["modes"].get(key, 0) + 1
        # coincidence rules
        W = res["contact"]["W"]
        lam_max = max(ends, key=float)
        slopes_change = any(p["from"] > 0 and pi.sign(p["from"] - lam_max) < 0
                            for p in res["path"])
        must_coincide = res["contact"]["mu"] == 0 or W["nt"] == 0 or not slopes_change
        if must_coincide and not same:
            bad.append(("coincidence", doc, ends))
    for kind, st in stats.items():
        print(f"{kind}: {st['n']} scenes solved, {st.get('stepped', 0)} also marched in floats (drawn and refused: {st['refused']}); "
              f"energy gains: newton {st['gain']['newton']}, poisson {st['gain']['poisson']}, "
              f"energetic {st['gain']['energetic']}; laws differ in {st['differ']}")
        print(f"  newton's largest relative gain {st['max_gain']} = {float(st['max_gain']):.4f}")
        print(f"  newton's phase sequences: {dict(sorted(st['modes'].items()))}")
        if st["max_scene"]:
            print(f"  in {st['max_scene']}")
        for why, doc in st["example"].items():
            print(f"  refused ({why}), e.g. {doc}")
    print(f"violations (poisson/energetic gain, or laws not coinciding where they must): {len(bad)}")
    for b in bad[:20]:
        print("  ", b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
