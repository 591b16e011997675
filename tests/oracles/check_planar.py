#!/usr/bin/env python3
"""Second, differently written check of the single-contact planar impact fixtures.

For every scene examples/impacts/<scene>.toml and its fixture tests/data/impacts/<scene>.json
(written by planar_impact.py), this script re-reads the scene with its own parser (SymPy's
exact Rational), takes the fixture's numbers as SymPy expressions (a surd {"x","y","d"} becomes
x + y*sqrt(d)), and checks, with SymPy and without calling the oracle:

  1. impulse-momentum for every moving body: m (v' - v) = +-P (free body; for a pinned body the
     pin's impulse is what is left, and it must equal the fixture's pin_impulse), and the angular
     momentum about the contact point (I w + m (c - x) x v) is unchanged by the contact impulse
     (for a pinned body it changes by the moment of the pin's impulse about the contact point);
     the fixture's P equals lam n + tau t;
  2. the law: newton  u_n after = -e u_n before;  poisson  lam_f = (1 + e) lam_c;  energetic  the
     work of the normal impulse in restitution equals -e^2 times its work in compression,
     integrating u_n(lam) with sympy.integrate along the fixture's phases, rebuilt from an
     impulse-space model written from scratch (velocities as sympy functions of the impulse);
  3. the phases: each starts where the previous ends, starts at 0; slide+ has u_t >= 0 and the
     tangential rate -mu, slide- u_t <= 0 and rate +mu, stick u_t = 0 with a rate inside the cone;
     a phase ends only where u_t = 0; lam_c is where u_n first vanishes;
  4. Coulomb: |tau| <= mu lam;
  5. the energies before/after/change and energy_gain, recomputed from the bodies, and the works
     (normal in compression and in restitution, friction <= 0) integrated along the path; the
     law's phase list is the path cut at lam_f; contact velocities also in the world frame;
  6. closed forms worked by hand: any frictionless scene (J = (1+e)(-u_n)/(n.K.n), the same for
     all laws), the paper's scene (v = 3/11, V = 8/11, omega = -12/11), the pinned paper scene
     (v = 11/43, omega = -36/43), the backspin ball, the energy witness (gain exactly 1/10), and
     any Newton answer whose last phase sticks (P = K^-1 (u_after - u_before)).
  7. the contact point lies on both bodies' outlines (a fixed body without shape: on the line
     through its position perpendicular to the normal).
  8. with --regenerate-check: re-running the oracle gives the fixture byte for byte.
  9. a float march in lam that projects each tangential increment onto the Coulomb cone (the
     way time-stepping engines do; Routh's modes are never named) ends near the same lam_f, tau_f;

Run:  python3 tests/oracles/check_planar.py         (needs sympy; exit status 1 on any failure)
"""

import json
import pathlib
import subprocess
import sys
import tomllib

import sympy as sp

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "examples" / "impacts"
FIXTURES = ROOT / "tests" / "data" / "impacts"

failures = []


def expect(cond, what):
    if not bool(cond):
        failures.append(what)
        print("   FAIL", what)


def R(text):
    """An input number as an exact SymPy Rational (SymPy's own parser, not the oracle's)."""
    if isinstance(text, int):
        return sp.Integer(text)
    q = sp.Rational(str(text).strip())
    assert q.is_Rational
    return q


def X(v):
    """A fixture number as a SymPy expression."""
    if isinstance(v, dict):
        return sp.Rational(v["x"]) + sp.Rational(v["y"]) * sp.sqrt(sp.Integer(v["d"]))
    return sp.Rational(v)


def exact(expr):
    """Canonical exact form (no floats are ever introduced: no nsimplify, no evalf)."""
    return sp.simplify(sp.expand(sp.radsimp(sp.expand(expr))))


def zero(expr):
    return exact(expr) == 0


def nonneg(expr):
    expr = exact(expr)
    return bool(expr >= 0) if expr.is_number else False


def vec(pair):
    return sp.Matrix([R(pair[0]), R(pair[1])])


def cr(a, b):
    """z-component of a x b."""
    return a[0] * b[1] - a[1] * b[0]


def rot(a):
    return sp.Matrix([-a[1], a[0]])


class Rigid:
    """A body as the scene file states it (re-read here, independently of the oracle)."""

    def __init__(self, t):
        self.name = t["name"]
        self.fixed = t.get("fixed", False)
        self.shape = t.get("shape")
        self.c = vec(t.get("position", ["0", "0"]))
        self.pin = None
        if self.fixed:
            self.m = None
            self.v = sp.zeros(2, 1)
            self.w = sp.Integer(0)
            return
        self.m = R(t["mass"])
        self.v = vec(t.get("velocity", ["0", "0"]))
        self.w = R(t.get("omega", "0"))
        self.axis = vec(t.get("axis", ["1", "0"]))
        s, m = self.shape, self.m
        self.dims = {k: R(t[k]) for k in ("length", "radius", "width", "height") if k in t}
        if "inertia" in t:
            self.I = R(t["inertia"])
        elif s == "rod":
            self.I = m * self.dims["length"] ** 2 / 12
        elif s == "disc":
            self.I = m * self.dims["radius"] ** 2 / 2
        elif s == "box":
            self.I = m * (self.dims["width"] ** 2 + self.dims["height"] ** 2) / 12
        elif s == "point":
            self.I = sp.Integer(0)

    def vel_at(self, x, v, w):
        """Velocity of the material point at x for centre velocity v and spin w."""
        return v + w * rot(x - self.c)

    def L_about(self, x, v, w):
        """Angular momentum about the fixed point x: I w + m (c - x) x v."""
        return self.I * w + self.m * cr(self.c - x, v)

    def energy(self, v, w):
        return self.m * (v[0] ** 2 + v[1] ** 2) / 2 + self.I * w ** 2 / 2

    def response(self, x, P):
        """(v', w') after an impulse P at x, for symbolic P (free: Newton-Euler; pinned: angular
        momentum about the pin, the pin supplying the rest)."""
        if self.fixed:
            return self.v, self.w
        if self.pin is not None:
            q = self.pin
            Iq = self.I + self.m * (self.c - q).dot(self.c - q)
            w = self.w + cr(x - q, P) / Iq
            return w * rot(self.c - q), w
        v = self.v + P / self.m
        w = self.w if self.I == 0 else self.w + cr(x - self.c, P) / self.I
        return v, w

    def on_outline(self, x, n):
        r = x - self.c
        if self.fixed and self.shape is None:
            return zero(r.dot(n))
        if self.shape == "point":
            return zero(r.norm())
        if self.shape == "disc":
            return zero(r.norm() - self.dims["radius"])
        a = self.axis / self.axis.norm()          # unit vectors: irrational norms are fine here
        xi, eta = exact(r.dot(a)), exact(r.dot(rot(a)))
        if self.shape == "rod":
            return zero(eta) and nonneg(self.dims["length"] / 2 - sp.Abs(xi))
        if self.shape == "box":
            W, H = self.dims["width"] / 2, self.dims["height"] / 2
            inside = nonneg(W - sp.Abs(xi)) and nonneg(H - sp.Abs(eta))
            return inside and (zero(sp.Abs(xi) - W) or zero(sp.Abs(eta) - H))
        return True


def check(name):
    print(f"== {name}")
    doc = tomllib.loads((SCENES / f"{name}.toml").read_text())
    fx = json.loads((FIXTURES / f"{name}.json").read_text())
    bodies = {t["name"]: Rigid(t) for t in doc["body"]}
    for p in doc.get("pin", []):
        bodies[p["body"]].pin = vec(p["point"])
    (c,) = doc["contact"]
    A, B = bodies[c["bodies"][0]], bodies[c["bodies"][1]]
    x, n = vec(c["point"]), vec(c["normal"])
    t = rot(n)
    e, mu = R(c.get("e", "1")), R(c.get("mu", "0"))
    moving = [b for b in bodies.values() if not b.fixed]

    # 7. geometry
    expect(A.on_outline(x, -n), f"{name}: contact point on {A.name}")
    expect(B.on_outline(x, n), f"{name}: contact point on {B.name}")

    # An impulse-space model from scratch: P = l n + s t with symbols l, s.
    l, s = sp.symbols("l s", real=True)
    P = l * n + s * t
    vA, wA = A.response(x, P)
    vB, wB = B.response(x, -P)
    u = A.vel_at(x, vA, wA) - B.vel_at(x, vB, wB)
    un, ut = sp.expand(u.dot(n)), sp.expand(u.dot(t))
    un0, ut0 = un.subs({l: 0, s: 0}), ut.subs({l: 0, s: 0})
    Wnn, Wnt, Wtt = un.coeff(l), un.coeff(s), ut.coeff(s)
    expect(zero(ut.coeff(l) - Wnt), f"{name}: W symmetric")
    expect(zero(Wnn - X(fx["contact"]["W"]["nn"])) and zero(Wnt - X(fx["contact"]["W"]["nt"]))
           and zero(Wtt - X(fx["contact"]["W"]["tt"])), f"{name}: W as in the fixture")
    E0 = sum(b.energy(b.v, b.w) for b in moving)

    # The path in lam, rebuilt from the fixture's phase list; tau(lam) piecewise linear.
    path = fx["path"]
    expect(X(path[0]["from"]) == 0, f"{name}: path starts at 0")
    lam = sp.symbols("lam", real=True)
    pieces = []            # (lo, hi or None, tau(lam) expression)
    tau_at = sp.Integer(0)
    for i, ph in enumerate(path):
        lo = X(ph["from"])
        hi = None if ph["to"] is None else X(ph["to"])
        if i:
            expect(zero(lo - X(path[i - 1]["to"])), f"{name}: phases are contiguous")
        ut_lo = ut.subs({l: lo, s: tau_at})
        if zero(ut_lo):   # the slip is 0 here: the mode is forced (Routh)
            can_stick = nonneg(mu * Wtt - sp.Abs(Wnt))
            forced = "stick" if can_stick else ("slide+" if exact(Wnt) > 0 else "slide-")
            expect(ph["mode"] == forced, f"{name}: at u_t = 0 the mode must be {forced}")
        else:
            expect(i == 0, f"{name}: a new phase starts only where u_t = 0")
        if ph["mode"] == "stick":
            expect(zero(ut_lo), f"{name}: stick starts with u_t = 0")
            rate = -Wnt / Wtt if Wtt != 0 else sp.Integer(0)
            expect(nonneg(mu - sp.Abs(rate)), f"{name}: stick rate inside the cone")
        else:
            sg = 1 if ph["mode"] == "slide+" else -1
            rate = -sg * mu
            expect(nonneg(sg * ut_lo) , f"{name}: {ph['mode']} starts with the slip's sign")
            if hi is not None:
                expect(zero(ut.subs({l: hi, s: tau_at + rate * (hi - lo)})),
                       f"{name}: {ph['mode']} ends where u_t = 0")
            else:  # open-ended slide: the slip does not shrink
                slope = sp.diff(ut.subs(s, tau_at + rate * (lam - lo)).subs(l, lam), lam)
                expect(nonneg(sg * slope), f"{name}: an open slide does not stop")
        tau_expr = tau_at + rate * (lam - lo)
        pieces.append((lo, hi, tau_expr))
        if hi is not None:
            tau_at = tau_expr.subs(lam, hi)

    def tau_of(val):
        for lo, hi, te in pieces:
            if hi is None or sp.simplify(val - hi) <= 0:
                return te.subs(lam, val)

    def ut_work(a, b):
        """integral of u_t dtau over [a, b] (dtau = rate dlam on each piece)."""
        total = sp.Integer(0)
        for lo, hi, te in pieces:
            lo2 = sp.Max(lo, a)
            hi2 = b if hi is None else sp.Min(hi, b)
            if sp.simplify(hi2 - lo2) > 0:
                total += sp.integrate(ut.subs({l: lam, s: te}) * sp.diff(te, lam),
                                      (lam, lo2, hi2))
        return exact(total)

    def un_pieces(a, b):
        """integral of u_n(lam) over [a, b], phase by phase, with sympy.integrate."""
        total = sp.Integer(0)
        for lo, hi, te in pieces:
            lo2 = sp.Max(lo, a)
            hi2 = b if hi is None else sp.Min(hi, b)
            if sp.simplify(hi2 - lo2) > 0:
                total += sp.integrate(un.subs({l: lam, s: te}), (lam, lo2, hi2))
        return exact(total)

    lam_c = X(fx["lam_c"])
    expect(zero(un.subs({l: lam_c, s: tau_of(lam_c)})), f"{name}: u_n(lam_c) = 0")
    # u_n < 0 before lam_c: it is linear on each piece, so check the piece ends before lam_c
    for lo, hi, te in pieces:
        if lo < lam_c:
            expect(sp.simplify(un.subs({l: lo, s: te.subs(lam, lo)})) < 0,
                   f"{name}: u_n < 0 before lam_c")
    Wc = un_pieces(0, lam_c)
    expect(sp.simplify(Wc) < 0, f"{name}: compression work < 0")

    for L in fx["laws"]:
        law = L["law"]
        lf, tf = X(L["impulse_coefficients"]["lam"]), X(L["impulse_coefficients"]["tau"])
        expect(zero(lf - X(L["lam_f"])) and zero(X(L["lam_c"]) - lam_c), f"{name}/{law}: lam")
        Pw = sp.Matrix([X(L["impulse"][0]), X(L["impulse"][1])])
        expect(zero((Pw - (lf * n + tf * t)).norm()), f"{name}/{law}: P = lam n + tau t")
        expect(zero(tf - tau_of(lf)), f"{name}/{law}: tau on the path")
        # 4. Coulomb
        expect(nonneg(mu * lf - sp.Abs(tf)), f"{name}/{law}: Coulomb |tau| <= mu lam")
        # 1. momentum, body by body
        after = {}
        for b in moving:
            got = L["bodies"][b.name]
            v1 = sp.Matrix([X(got["velocity"][0]), X(got["velocity"][1])])
            w1 = X(got["omega"])
            after[b.name] = (v1, w1)
            Pb = Pw if b is A else (-Pw if b is B else sp.zeros(2, 1))
            rest = b.m * (v1 - b.v) - Pb                # the pin's impulse (zero if free)
            dL = b.L_about(x, v1, w1) - b.L_about(x, b.v, b.w)
            if b.pin is None:
                expect(zero(rest.norm()), f"{name}/{law}: linear momentum of {b.name}")
                expect(zero(dL), f"{name}/{law}: angular momentum of {b.name} about the contact")
            else:
                pin = sp.Matrix([X(c_) for c_ in L["pin_impulse"][b.name]])
                expect(zero((rest - pin).norm()), f"{name}/{law}: pin impulse of {b.name}")
                expect(zero(dL - cr(b.pin - x, rest)),
                       f"{name}/{law}: angular momentum of {b.name} about the contact")
                expect(zero(b.vel_at(b.pin, v1, w1).norm()), f"{name}/{law}: pin at rest")
        # the fixture's state is the model's state at (lf, tf)
        for b in (A, B):
            if not b.fixed:
                vm, wm = b.response(x, P if b is A else -P)
                sub = {l: lf, s: tf}
                expect(zero((vm.subs(sub) - after[b.name][0]).norm())
                       and zero(wm.subs(sub) - after[b.name][1]), f"{name}/{law}: {b.name} state")
        unf = un.subs({l: lf, s: tf})
        utf = ut.subs({l: lf, s: tf})
        cv = L["contact_velocity"]
        expect(zero(un0 - X(cv["before"]["n"])) and zero(ut0 - X(cv["before"]["t"]))
               and zero(unf - X(cv["after"]["n"])) and zero(utf - X(cv["after"]["t"])),
               f"{name}/{law}: contact velocities")
        uw = u.subs({l: lf, s: tf})
        expect(zero((u.subs({l: 0, s: 0}) - sp.Matrix([X(c_) for c_ in cv["before"]["world"]])).norm())
               and zero((uw - sp.Matrix([X(c_) for c_ in cv["after"]["world"]])).norm()),
               f"{name}/{law}: contact velocities in the world frame")
        # the law's phases: the path cut at lam_f
        want = []
        for ph in path:
            lo = X(ph["from"])
            if want and sp.simplify(lo - lf) >= 0:
                break
            hi = lf if ph["to"] is None or sp.simplify(X(ph["to"]) - lf) > 0 else X(ph["to"])
            want.append((ph["mode"], lo, hi))
        got = [(ph["mode"], X(ph["from"]), X(ph["to"])) for ph in L["phases"]]
        expect(len(got) == len(want) and all(g[0] == w[0] and zero(g[1] - w[1]) and zero(g[2] - w[2])
                                             for g, w in zip(got, want)),
               f"{name}/{law}: phases = the path cut at lam_f")
        # the works: normal in compression and restitution, friction
        wk = L["work"]
        expect(zero(X(wk["normal_compression"]) - Wc)
               and zero(X(wk["normal_restitution"]) - un_pieces(lam_c, lf))
               and zero(X(wk["friction"]) - ut_work(0, lf)), f"{name}/{law}: works")
        expect(nonneg(-X(wk["friction"])), f"{name}/{law}: friction does no positive work")
        # 2. the law
        if law == "newton":
            expect(zero(unf + e * un0), f"{name}/newton: u_n after = -e u_n before")
            for lo, hi, te in pieces:    # and it is the first lam >= lam_c where that holds
                if lam_c < lo < lf:
                    expect(exact(un.subs({l: lo, s: te.subs(lam, lo)}) + e * un0) < 0,
                           f"{name}/newton: lam_f is the first such lam")
        elif law == "poisson":
            expect(zero(lf - (1 + e) * lam_c), f"{name}/poisson: lam_f = (1 + e) lam_c")
        else:
            Wr = un_pieces(lam_c, lf)
            expect(zero(Wr + e**2 * Wc), f"{name}/energetic: restitution work = -e^2 compression")
            expect(zero(X(L["work"]["normal_restitution"]) - Wr)
                   and zero(X(L["work"]["normal_compression"]) - Wc),
                   f"{name}/energetic: works as in the fixture")
        # 5. energy
        E1 = sum(b.energy(*after[b.name]) for b in moving)
        en = L["energy"]
        expect(zero(E0 - X(en["before"])) and zero(E1 - X(en["after"]))
               and zero(E1 - E0 - X(en["change"])), f"{name}/{law}: energies")
        gain = exact(E1 - E0) > 0
        expect(bool(gain) == L["energy_gain"], f"{name}/{law}: energy_gain flag")
        # the path-free energy formula u0 . P + P.K.P/2 (K symmetric)
        quad = sp.expand(un0 * lf + ut0 * tf + (Wnn * lf**2 + 2 * Wnt * lf * tf + Wtt * tf**2) / 2)
        expect(zero(quad - (E1 - E0)), f"{name}/{law}: energy = u0.P + P.K.P/2")
        # 9. a float stepping in lam that projects onto the cone (no modes named) agrees
        got = stepping(Wnn, Wnt, Wtt, un0, ut0, mu, e, law)
        scale_ = float(abs(un0) / Wnn) + 1e-300
        ok = got is not None and abs(got[0] - float(lf)) < 1e-3 * scale_ and \
            abs(got[1] - float(tf)) < 1e-3 * scale_ + 1e-9
        expect(ok, f"{name}/{law}: float stepping agrees ({got} vs {float(lf)}, {float(tf)})")
        # 6. closed forms
        if mu == 0:
            J = (1 + e) * (-un0) / Wnn
            expect(zero(lf - J) and zero(tf), f"{name}/{law}: frictionless J = (1+e)(-u_n)/W_nn")
        if law == "newton" and L["phases"][-1]["mode"] == "stick":
            # u after = -e u_n0 n/|n|^2 in the world: solve W (lam, tau) = (du_n, du_t)
            sol = sp.solve([sp.Eq(un, -e * un0), sp.Eq(ut, 0)], [l, s], dict=True)[0]
            expect(zero(sol[l] - lf) and zero(sol[s] - tf), f"{name}/newton: stick closed form")
        closed = HAND.get(name)
        if closed:
            for bname, (vx, vy, w) in closed(law).items():
                v1, w1 = after[bname]
                expect(zero(v1[0] - vx) and zero(v1[1] - vy) and zero(w1 - w),
                       f"{name}/{law}: hand-worked answer for {bname}")


def stepping(Wnn, Wnt, Wtt, un0, ut0, mu, e, law, steps=200000):
    """A different algorithm, in floats: march lam in small steps; each step's tangential
    increment is the one that brings u_t closest to 0 inside the cone |dtau| <= mu dlam (a
    projection, as time-stepping engines do), so Routh's modes are never named.  Returns
    (lam_f, tau_f, u_n, u_t) to O(step)."""
    Wnn, Wnt, Wtt, un, ut, mu, e = map(float, (Wnn, Wnt, Wtt, un0, ut0, mu, e))
    un0f = un
    # a step size from the frictionless impulse scale
    h = 4 * abs(un0f) / Wnn / steps
    lam = tau = wc = wr = 0.0
    lam_c = None
    while True:
        dtau = 0.0
        if Wtt > 0:
            want = -(ut + Wnt * h) / Wtt                 # the increment that zeroes u_t
            dtau = max(-mu * h, min(mu * h, want))
        un_new = un + Wnn * h + Wnt * dtau
        work = (un + un_new) / 2 * h
        if lam_c is None:
            # compression ends inside this step (the tolerance matters only for a rank-one W,
            # where u_n and u_t vanish together and rounding can leave u_n at -1e-17 for ever)
            if un_new >= -1e-12 * abs(un0f):
                f = min(1.0, -un / (un_new - un)) if un_new > un else 1.0
                lam_c = lam + f * h
                wc += un * f * h / 2
                wr += un_new * (1 - f) * h / 2
            else:
                wc += work
        else:
            wr += work
        lam, tau, un, ut = lam + h, tau + dtau, un_new, ut + Wnt * h + Wtt * dtau
        if lam_c is not None:
            if law == "newton" and un >= -e * un0f - 1e-12 * abs(un0f):
                return lam, tau, un, ut
            if law == "poisson" and lam >= (1 + e) * lam_c:
                return lam, tau, un, ut
            if law == "energetic" and wr >= -e * e * wc:
                return lam, tau, un, ut
        if lam > 100 * h * steps:
            return None


Q = sp.Rational


def paper(law):
    # m = M = 1, l = 1, a = 1/2, I = 1/3, e = 1: J = 2/(1 + 1 + (1/4)/(1/3)) = 8/11
    J = 2 / (1 + 1 + Q(1, 4) / Q(1, 3))
    return {"projectile": (1 - J, 0, 0), "rod": (J, 0, -J * Q(1, 2) / Q(1, 3))}


def paper_pivot(law):
    # pin at p = -1: I_p = 1/3 + 1, d = 3/2, J = 2/(1 + d^2/I_p) = 32/43, omega_paper = J d/I_p
    Ip, d = Q(1, 3) + 1, Q(3, 2)
    J = 2 / (1 + d**2 / Ip)
    om = J * d / Ip
    return {"projectile": (1 - J, 0, 0), "rod": (om, 0, -om)}   # V = -omega_paper * p = omega


def ball(law):
    # disc r = 1, m = 1, I = 1/2, v = (1, -1), omega = 3, mu = 1, e = 1/2. W diagonal:
    # lam_f = (1+e) * 1 = 3/2; slip 4 stops at tau = 4/3 < mu lam_f (W_tt = 3), then rolls.
    tau = Q(4, 3)
    vx = 1 - tau
    return {"ball": (vx, -1 + Q(3, 2), 3 - 2 * tau)}


def witness(law):
    # Newton and stick: Delta u = (1, -1) -> (0, 1) at the rod's end.  Only checked for newton.
    return {"rod": (Q(6, 5), Q(1, 10), Q(-3, 2))} if law == "newton" else {}


HAND = {"paper-as-bodies": paper, "paper-pivot-as-bodies": paper_pivot,
        "ball-spin-rough-floor": ball, "newton-gains-energy": witness}


def main(argv):
    names = sorted(p.stem for p in SCENES.glob("*.toml"))
    for name in names:
        if not (FIXTURES / f"{name}.json").exists():
            failures.append(f"{name}: no fixture")
            continue
        check(name)
        if "--regenerate-check" in argv:
            out = subprocess.run([sys.executable, str(ROOT / "tests/oracles/planar_impact.py"),
                                  str(SCENES / f"{name}.toml")], capture_output=True, text=True)
            expect(out.stdout == (FIXTURES / f"{name}.json").read_text(),
                   f"{name}: the oracle reproduces the fixture")
    # the witness's gain is exactly 1/10 under Newton and negative under the other laws
    fx = json.loads((FIXTURES / "newton-gains-energy.json").read_text())
    ch = {L["law"]: X(L["energy"]["change"]) for L in fx["laws"]}
    expect(ch["newton"] == Q(1, 10) and ch["poisson"] < 0 and sp.N(ch["energetic"]) < 0,
           "witness: Newton +1/10, the others lose")
    print(f"{len(names)} scenes, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
