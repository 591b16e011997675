#!/usr/bin/env python3
"""Exact answers for the published planar impact problems in this directory.

Independent of rodimpact: plain Python, fractions.Fraction only (SymPy is used
for one optional surd check when it is installed). Run from anywhere:

    python3 examples/impacts/published/derive.py

Conventions are those of DESIGN.md section 6: x to the right, y up, omega
counterclockwise positive; the impulse P acts on body A (the moving body, B is
fixed in every scene here), the normal n points from B into A, the tangent t is
n turned a quarter turn counterclockwise. A single contact is followed in normal
impulse the way Routh does it (slide at -mu*sign(slip), stick when the slip stops
and the stick ratio fits in the cone, or slide the other way); the end of the
impact is set by Newton's law (normal velocity after = -e * before) or Poisson's
(normal impulse = (1 + e) * compression impulse). With e = 0, or without
friction, or when the slip never changes mode, the three laws coincide, and every
single-contact scene here is one of those cases; the energetic law is therefore
not implemented separately (it equals Poisson's whenever the slip mode does not
change during restitution, and e = 0 has no restitution).
"""
from fractions import Fraction as F


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def perp(r):  # k x r
    return (-r[1], r[0])


class Body:
    def __init__(self, m, I, pos, vel, omega):
        self.m, self.I = F(m), F(I)
        self.pos = (F(pos[0]), F(pos[1]))
        self.vel = (F(vel[0]), F(vel[1]))
        self.omega = F(omega)

    def point_velocity(self, p):
        r = (p[0] - self.pos[0], p[1] - self.pos[1])
        k = perp(r)
        return (self.vel[0] + self.omega * k[0], self.vel[1] + self.omega * k[1])

    def apply(self, p, P):
        r = (p[0] - self.pos[0], p[1] - self.pos[1])
        return Body(self.m, self.I, self.pos,
                    (self.vel[0] + P[0] / self.m, self.vel[1] + P[1] / self.m),
                    self.omega + cross(r, P) / self.I)

    def energy(self):
        return (self.m * (self.vel[0] ** 2 + self.vel[1] ** 2) + self.I * self.omega ** 2) / 2


def W_matrix(body, p, n, t):
    """Contact compliance in the (n, t) frame (n, t of equal length; scaled later)."""
    r = (p[0] - body.pos[0], p[1] - body.pos[1])
    def du(P):  # change of contact velocity per impulse P
        k = perp(r)
        w = cross(r, P) / body.I
        return (P[0] / body.m + w * k[0], P[1] / body.m + w * k[1])
    cols = []
    for d in (n, t):
        v = du(d)
        cols.append((v[0] * n[0] + v[1] * n[1], v[0] * t[0] + v[1] * t[1]))
    # W[i][j]: component i of the velocity change per unit impulse along direction j
    return [[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]]


def single_contact(body, p, n, e, mu, law="newton"):
    """Impact of one moving body on a fixed body at p (n from the fixed body into the moving one)."""
    n = (F(n[0]), F(n[1]))
    # n need not be a unit vector: with t = n turned a quarter turn (same length), the
    # ratios pt/pn, the events and Newton's end condition do not depend on |n|.
    t = perp(n)
    e, mu = F(e), F(mu)
    W = W_matrix(body, p, n, t)
    v = body.point_velocity(p)
    un = v[0] * n[0] + v[1] * n[1]
    ut = v[0] * t[0] + v[1] * t[1]
    assert un < 0, "no approach"
    pn, pt = F(0), F(0)
    phases = []
    un0 = un
    pnc = None  # normal impulse at the end of compression

    def rates(mode):
        # d(pt)/d(pn) and the velocity rates per unit normal impulse
        if mode == "stick":
            k = -W[1][0] / W[1][1]
        else:
            k = -mode * mu  # mode = sign of the slip
        dun = W[0][0] + W[0][1] * k
        dut = W[1][0] + W[1][1] * k
        return k, dun, dut

    def mode_of(ut):
        if ut != 0:
            return 1 if ut > 0 else -1
        k = -W[1][0] / W[1][1]
        if abs(k) <= mu:
            return "stick"
        # slip starts against the sign of the tangential acceleration
        return -1 if W[1][0] > 0 else 1

    target_end = None
    while True:
        mode = mode_of(ut)
        k, dun, dut = rates(mode)
        # next event in pn: un hits 0 (end of compression), un hits the Newton end,
        # pn hits the Poisson end, ut hits 0 (slip stops)
        cands = []
        if pnc is None and dun > 0 and un < 0:
            cands.append(((-un) / dun, "max-compression"))
        if pnc is not None:
            if law == "newton":
                cands.append(((-e * un0 - un) / dun if dun != 0 else None, "end"))
            else:
                cands.append(((1 + e) * pnc - pn, "end"))
        if mode != "stick" and dut != 0 and (ut / dut) < 0:
            cands.append(((-ut) / dut, "slip-stops"))
        cands = [(d, w) for d, w in cands if d is not None and d >= 0]
        d, what = min(cands, key=lambda c: c[0])
        pn += d
        pt += k * d
        un += dun * d
        ut += dut * d if mode != "stick" else 0
        if mode == "stick":
            ut = F(0)
        phases.append((mode, d, what))
        if what == "max-compression":
            pnc = pn
            if (law == "newton" and e == 0) or (law != "newton" and e == 0):
                break
        elif what == "end":
            break
        elif what == "slip-stops":
            ut = F(0)
    P = (pn * n[0] + pt * t[0], pn * n[1] + pt * t[1])
    after = body.apply(p, P)
    return after, (pn, pt), phases


def stick_ratio(body, p, n):
    n = (F(n[0]), F(n[1])); t = perp(n)
    W = W_matrix(body, p, n, t)
    return -W[1][0] / W[1][1]


def show(name, before, after, extra=""):
    Eb, Ea = before.energy(), after.energy()
    print(f"  {name}: velocity = ({after.vel[0]}, {after.vel[1]}) = ({float(after.vel[0]):.7g}, {float(after.vel[1]):.7g}), "
          f"omega = {after.omega} = {float(after.omega):.7g}")
    print(f"    energy before {Eb} after {Ea} change {Ea - Eb} (fraction lost {float((Eb - Ea) / Eb):.7g}) {extra}")


def disk_on_step(h_over_R, sx):
    """Solid disk, m = 1 kg, R = 1 m, rolling right at v = 1 m/s (omega = -1),
    hits a step corner S = (sx, -(1 - h)) relative to the centre; sx is the
    7-figure rational approximation of sqrt(1 - (1-h)^2) used in the scene file.
    No rebound (e = 0), no slip (mu = 1 is above the stick ratio)."""
    sy = -(1 - h_over_R)
    disk = Body(1, F(1, 2), (0, 0), (1, 0), -1)
    S = (sx, sy)
    # normal from the corner into the disk: along centre - S, normalised...
    # ...which is a unit vector only to 7 figures; use the exact-direction version:
    # the disk's answer depends on the normal only through its direction, so scale
    # (-sx, -sy) by 1/|.| is avoided by solving the stick case directly: e = 0 and
    # stick means the contact point's velocity after is zero.
    # Solve u + Wxy P = 0 in world axes.
    r = S
    def du(P):
        k = perp(r); w = cross(r, P) / disk.I
        return (P[0] / disk.m + w * k[0], P[1] / disk.m + w * k[1])
    a = du((F(1), F(0))); b = du((F(0), F(1)))
    u = disk.point_velocity(S)
    det = a[0] * b[1] - b[0] * a[1]
    Px = (-u[0] * b[1] + b[0] * u[1]) / det
    Py = (-a[0] * u[1] + u[0] * a[1]) / det
    after = disk.apply(S, (Px, Py))
    nvec = (-sx, -sy)
    pn = (Px * nvec[0] + Py * nvec[1])
    pt = (Px * (-nvec[1]) + Py * nvec[0])
    return disk, after, pn, pt


def main():
    print("1. jee-disk-hurdle: solid disk rolling at v hits a hurdle of height 3R/20, no rebound, no slip")
    sx = F("0.5267827")  # sqrt(111)/20 = 0.52678269...
    before, after, pn, pt = disk_on_step(F(3, 20), sx)
    show("disk", before, after, f"|Pt/Pn| = {float(abs(pt / pn)):.7g} (stick needs mu at least this)")
    speed2 = after.vel[0] ** 2 + after.vel[1] ** 2
    print(f"    speed^2 of the centre = {float(speed2):.10g}; exact with S on the rim: omega' = -(1 - 2h/3R) = -9/10, speed 9/10 v")
    print("    printed: option D, 0.9v  -> agrees")

    print("2. assignmentexpert-39724-disc-step: disc rolling at V0 hits a step R/4, rough corner")
    sx = F("0.6614378")  # sqrt(7)/4 = 0.66143783...
    before, after, pn, pt = disk_on_step(F(1, 4), sx)
    show("disc", before, after, f"|Pt/Pn| = {float(abs(pt / pn)):.7g}")
    print("    exact with S on the rim: omega' = -(1 - 2h/3R) = -5/6, speed 5/6 V0 = 0.8333 V0")
    print("    printed: V1 = 5/4 V0  -> WRONG (final angular momentum taken as M V1 R, without I_cm)")

    print("3. tutorbin-bar-wall: 2 lb, 4 ft bar translating left at 30 ft/s, upper end hits a smooth wall, e = 0.3")
    bar = Body(2, F(2) * 16 / 12, (0, 0), (-30, 0), 0)
    p = (F("-1.7320508"), F(1))  # end of the bar at 30 deg to the floor: (-2 cos 30, 2 sin 30)
    after, (pn, pt), ph = single_contact(bar, p, (1, 0), F(3, 10), 0)
    show("bar", bar, after, f"normal impulse {pn} lb ft/s = {float(pn):.7g}; phases {ph}")
    print(f"    omega = {after.omega} = {float(after.omega):.6f} (negative: clockwise), vx = {after.vel[0]} = {float(after.vel[0]):.6f}")
    print("    printed: 16.714 rad/s clockwise, 7.714 ft/s to the left -> agree (117/7, 54/7)")

    print("4. zigyan-rod-two-blocks: horizontal rod falls onto two blocks, e1, e2, simultaneous Newton")
    e1, e2 = F(3, 5), F(1, 5)
    m, L = F(1), F(2)
    I = m * L ** 2 / 12
    d = L / 2  # blocks under the ends
    v0 = F(-1)
    # unknowns P1 (at -d), P2 (at +d); after: vy = v0 + (P1+P2)/m, w = d (P2 - P1)/I
    # Newton at each contact: vy - w d = -e1 v0, vy + w d = -e2 v0
    vy = -(e1 + e2) * v0 / 2
    w = -(e2 - e1) * v0 / (2 * d)
    S = m * (vy - v0)
    D = I * w / d
    P1, P2 = (S - D) / 2, (S + D) / 2
    print(f"  vy = {vy}, omega = {w}, P1 = {P1}, P2 = {P2} (both >= 0: the simultaneous Newton answer exists)")
    print(f"  printed H = (e1+e2)^2 h / 4 <=> vy = (e1+e2)/2 sqrt(2gh) = {(e1 + e2) / 2} for sqrt(2gh) = 1 m/s -> agrees")
    # sequential, contact 1 first then 2, repeated until no approach
    rod = Body(m, I, (0, 0), (0, v0), 0)
    pts = [((-d, F(0)), e1), ((d, F(0)), e2)]
    for order in ((0, 1), (1, 0)):
        b = rod
        for _ in range(50):
            moved = False
            for i in order:
                p, e = pts[i]
                u = b.point_velocity(p)
                if u[1] < 0:
                    b, _, _ = single_contact(b, p, (0, 1), e, 0)
                    moved = True
            if not moved:
                break
        print(f"  sequential, contact {order[0] + 1} first: vy = {b.vel[1]} = {float(b.vel[1]):.7g}, omega = {b.omega} = {float(b.omega):.7g}")

    print("5. solveeit/askfilo Beer-Johnston crate: square crate turning about A hits the floor with corner B, plastic, rough")
    crate = Body(1, F(1, 6), (F(1, 2), F(1, 2)), (F(1, 2), F(-1, 2)), -1)
    B = (F(1), F(0))
    print(f"  stick ratio |Pt/Pn| = {abs(stick_ratio(crate, B, (0, 1)))}")
    after, (pn, pt), ph = single_contact(crate, B, (0, 1), 0, 1)
    show("crate", crate, after, f"impulse (n, t) = ({pn}, {pt}); phases {ph}")
    print("    printed: K = 4 (omega0/4), alpha + beta = 31 (fraction lost 15/16) -> agree")

    print("6. fenggao-sliding-cube: cube of side 2a (a = 1 m) sliding at v = 1 m/s, leading edge stopped by an obstacle")
    cube = Body(1, F(2, 3), (0, 0), (1, 0), 0)
    E = (F(1), F(-1))
    print(f"  stick ratio |Pt/Pn| = {abs(stick_ratio(cube, E, (-1, 0)))}")
    after, (pn, pt), ph = single_contact(cube, E, (-1, 0), 0, 1)
    show("cube", cube, after, f"impulse (n, t) = ({pn}, {pt}); phases {ph}")
    print("    printed: omega = 3v/(5a) = 0.6 rad/s -> WRONG (I about the edge taken as 5/3 M a^2; it is 8/3 M a^2: omega = 3v/(8a))")

    print("7. byjus-rod-37deg-floor: rod at 37 deg (cos 4/5) falls at v0 = 1 m/s onto one end, smooth floor, e = 1/2")
    rod = Body(1, F(1, 3), (0, 0), (0, -1), 0)
    after, (pn, pt), ph = single_contact(rod, (F(-4, 5), F(-3, 5)), (0, 1), F(1, 2), 0)
    show("rod", rod, after, f"normal impulse {pn} = {float(pn):.7g}")
    print("    page's own equations give J = 75/146 M v0, V = 71/146 v0 down, omega = 180/73 v0/L;")
    print("    printed (as read from garbled text): J = 50/121 M v0, speed 111/121 v0 -> disagree")

    try:
        import sympy as sp
        h = sp.Rational(3, 20)
        sxe = sp.sqrt(1 - (1 - h) ** 2)
        # angular momentum about S: I w + m (G - S) x v, rolling right: v = (1, 0), w = -1
        L0 = sp.Rational(1, 2) * (-1) + ((0 - sxe) * 0 - (0 - (-(1 - h))) * 1)
        w1 = sp.simplify(L0 / (sp.Rational(1, 2) + 1))
        print(f"sympy, exact surd geometry: jee disk omega' = {w1}")
        h = sp.Rational(1, 4)
        L0 = sp.Rational(1, 2) * (-1) - (1 - h) * 1
        print(f"sympy, exact surd geometry: R/4 step omega' = {sp.simplify(L0 / sp.Rational(3, 2))}")
    except ImportError:
        pass


# ---------------------------------------------------------------------------------------------
# Second path: read every scene file here and solve it as written (catches a wrong sign or point
# in a TOML), then compare each claim the way `rodimpact check` does: a decimal claim agrees when it
# equals the exact value rounded to the claim's own significant figures; a fraction must be equal.
import glob, os, tomllib
from decimal import Decimal, ROUND_HALF_EVEN

UNITS = [" rad/s", " m/s", " kg", " m", " J", " N s"]


def num(s):
    s = str(s).strip()
    for u in UNITS:
        if s.endswith(u):
            s = s[: -len(u)].strip()
    return F(s)


def sig_agrees(claim, exact):
    s = str(claim).strip()
    for u in UNITS:
        if s.endswith(u):
            s = s[: -len(u)].strip()
    if "/" in s:
        return F(s) == exact, F(s)
    d = Decimal(s)
    digits = d.as_tuple().digits
    sig = len(str(int("".join(map(str, digits))))) if any(digits) else 1
    exp = d.adjusted() - sig + 1
    q = Decimal(exact.numerator) / Decimal(exact.denominator)
    r = q.quantize(Decimal(1).scaleb(exp), rounding=ROUND_HALF_EVEN)
    return r == d, r


def solve_scene(path):
    sc = tomllib.load(open(path, "rb"))
    movers = {b["name"]: b for b in sc["body"] if not b.get("fixed")}
    assert len(movers) == 1
    name, b = next(iter(movers.items()))
    body = Body(num(b["mass"]), num(b["inertia"]), [num(x) for x in b["position"]],
                [num(x) for x in b["velocity"]], num(b.get("omega", "0")))
    E0 = body.energy()
    cs = sc["contact"]
    if len(cs) == 1:
        c = cs[0]
        after, _, _ = single_contact(body, [num(x) for x in c["point"]], [num(x) for x in c["normal"]],
                                     num(c["e"]), num(c.get("mu", "0")))
    else:
        # simultaneous Newton, frictionless, normals along y (the only multi-contact scene here)
        pts = [[num(x) for x in c["point"]] for c in cs]
        assert all([num(x) for x in c["normal"]] == [0, 1] for c in cs)
        es = [num(c["e"]) for c in cs]
        # unknown impulses P_i along +y: u_i' = u_i + sum_j A_ij P_j = -e_i u_i
        A = [[1 / body.m + (pts[i][0] - body.pos[0]) * (pts[j][0] - body.pos[0]) / body.I for j in range(2)] for i in range(2)]
        u = [body.point_velocity(p)[1] for p in pts]
        rhs = [-(1 + es[i]) * u[i] for i in range(2)]
        det = A[0][0] * A[1][1] - A[0][1] * A[1][0]
        P = [(rhs[0] * A[1][1] - A[0][1] * rhs[1]) / det, (A[0][0] * rhs[1] - rhs[0] * A[1][0]) / det]
        assert all(x >= 0 for x in P)
        after = body
        for p, x in zip(pts, P):
            after = after.apply(p, (F(0), x))
    values = {f"{name}.omega": after.omega, f"{name}.velocity.x": after.vel[0],
              f"{name}.velocity.y": after.vel[1], "energy.change": after.energy() - E0}
    if len(cs) == 1:
        nvec = [num(x) for x in cs[0]["normal"]]
        P = (body.m * (after.vel[0] - body.vel[0]), body.m * (after.vel[1] - body.vel[1]))
        nn = nvec[0] ** 2 + nvec[1] ** 2
        if nn == 1:  # impulse components along the unit normal and tangent
            values["impulse.normal"] = P[0] * nvec[0] + P[1] * nvec[1]
            values["impulse.tangential"] = -P[0] * nvec[1] + P[1] * nvec[0]
    print(f"{os.path.basename(path)}:")
    for cl in sc.get("claim", []):
        exact = values[cl["quantity"]]
        ok, shown = sig_agrees(cl["value"], exact)
        print(f"  {cl['quantity']:<16} claim {cl['value']:<12} exact {float(exact):<.10g}  -> {'agrees' if ok else 'DISAGREES'}")


def check_scene_files():
    here = os.path.dirname(os.path.abspath(__file__))
    for path in sorted(glob.glob(os.path.join(here, "*.toml"))):
        solve_scene(path)


if __name__ == "__main__":
    main()
    print()
    print("Scene files as written:")
    check_scene_files()
