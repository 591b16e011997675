#!/usr/bin/env python3
"""Exact oracle of the impact laws that physics engines compute, and exact replays of one
engine step (pymunk 7 / Chipmunk, Box2D 2.3, Bullet 3 / pybullet), for one or several contacts.

Independent of rodimpact (no code shared with the Rust solver, none of its sources read):
Python 3.11 standard library only, every number a ``fractions.Fraction``.  It reuses the exact
linear algebra of ``multi_contact.py`` (same directory): ``solve_linear``, ``affine_solutions``,
``polytope_vertices``, ``solve_lcp``, ``num``, ``qs``.

    python3 tests/oracles/engine_laws.py SCENE.toml [--law NAME ...]
    python3 tests/oracles/engine_laws.py engines/impacts.jsonl [--law NAME ...]   # one JSON per line
    python3 tests/oracles/engine_laws.py --write-fixtures     # -> tests/data/impacts-engines/

Laws (NAME): lcp-newton, lcp-poisson, split, pgs:K (K sweeps, with friction), pymunk-7,
box2d-2.3 (options box2d-2.3:scale=S or :threshold=T), bullet-3 (option :threshold=T).
The definitions, how each is solved and the citations are in ``engine-laws.md``.

Conventions (docs/impacts.md): contact i joins A_i and B_i at p_i with normal n_i from B into A
(any positive length) and tangent t_i = n_i turned a quarter turn counterclockwise; the impulse
on A is P_i = lam_i n_i + tau_i t_i, on B -P_i.  uN_i = (v_A(p) - v_B(p)) . n_i, uT_i likewise
with t_i (both scaled by |n_i|).  After impulses (lam, tau): (uN, uT) = (uN0, uT0) + W (lam, tau)
with the Delassus blocks Wnn, Wnt, Wtn, Wtt (W = J M^-1 J^T).  u0n^- = min(uN0, 0).
"""

from __future__ import annotations

import itertools
import json
import sys
import tomllib
from fractions import Fraction as Q
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import multi_contact as mc  # noqa: E402  (exact linear algebra and LCP enumeration)

ZERO, ONE = Q(0), Q(1)
sys.set_int_max_str_digits(0)
num, qs = mc.num, mc.qs
ROOT = Path(__file__).resolve().parents[2]

DEFAULT_LAWS = ("lcp-newton", "lcp-poisson", "split", "pgs:1", "pgs:10",
                "pymunk-7", "box2d-2.3", "box2d-2.3:scale=16", "bullet-3")

# pybullet's m_leastSquaresResidualThreshold = 1e-7 (PhysicsServerCommandProcessor.cpp:2815): the
# double nearest 1e-7, taken exactly.
BULLET_RESIDUAL = Q(1e-7)
DBL_EPSILON = Q(2.220446049250313e-16)   # SIMD_EPSILON in double precision (btScalar.h:536)


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def perp(a):
    return (-a[1], a[0])


# ----------------------------------------------------------------------------------------------
# Scene: free, fixed and pinned bodies (a pinned body turns about its pin only)
# ----------------------------------------------------------------------------------------------

class Body:
    def __init__(self, t):
        self.name = t["name"]
        self.fixed = bool(t.get("fixed", False))
        self.shape = t.get("shape")
        self.position = tuple(num(v) for v in t.get("position", ["0", "0"]))
        self.velocity = tuple(num(v) for v in t.get("velocity", ["0", "0"]))
        self.omega = num(t.get("omega", "0"))
        self.pin = None
        if self.fixed:
            self.mass = self.inertia = None
            return
        self.mass = num(t["mass"])
        if self.mass <= 0:
            raise ValueError(f"body {self.name}: mass must be > 0")
        d = {k: num(t[k]) for k in ("length", "radius", "width", "height") if k in t}
        if "inertia" in t:
            self.inertia = num(t["inertia"])
        elif self.shape == "rod":
            self.inertia = self.mass * d["length"] ** 2 / 12
        elif self.shape == "disc":
            self.inertia = self.mass * d["radius"] ** 2 / 2
        elif self.shape == "box":
            self.inertia = self.mass * (d["width"] ** 2 + d["height"] ** 2) / 12
        elif self.shape == "point":
            self.inertia = ZERO
        else:
            raise ValueError(f"body {self.name}: give inertia or a shape (rod, disc, box, point)")
        if self.inertia < 0:
            raise ValueError(f"body {self.name}: negative inertia")

    @property
    def inv_mass(self):
        return ZERO if self.fixed or self.pin is not None else 1 / self.mass

    @property
    def inv_inertia(self):
        if self.fixed:
            return ZERO
        if self.pin is not None:
            r = sub(self.position, self.pin)
            return 1 / (self.inertia + self.mass * dot(r, r))
        return ZERO if self.inertia == 0 else 1 / self.inertia

    def pymunk_kind(self):
        """The shape the repository's pymunk harness gives the body (engines/python/
        impacts_common.py): rod -> segment, box -> poly, disc/point -> circle; a fixed body
        without shape (floor, wall) -> static segment, a fixed point (peg) -> static circle."""
        return {"rod": "segment", "box": "poly", "disc": "circle", "point": "circle",
                None: "segment"}.get(self.shape, "poly")


class Contact:
    def __init__(self, t, names, index):
        self.index = index
        a, b = t["bodies"]
        if a not in names or b not in names:
            raise ValueError(f"contact {index}: unknown body")
        self.a, self.b = names[a], names[b]
        if self.a == self.b:
            raise ValueError(f"contact {index}: a body against itself")
        self.names = (a, b)
        self.point = tuple(num(v) for v in t["point"])
        self.normal = tuple(num(v) for v in t["normal"])
        if self.normal == (0, 0):
            raise ValueError(f"contact {index}: zero normal")
        self.tangent = perp(self.normal)
        self.e = num(t.get("e", "1"))          # docs/impacts.md: default 1
        self.mu = num(t.get("mu", "0"))
        if not (0 <= self.e <= 1) or self.mu < 0:
            raise ValueError(f"contact {index}: e outside [0, 1] or mu < 0")
        self.n2 = dot(self.normal, self.normal)   # |n|^2 (rational)


class Scene(mc.Scene):
    """Bodies (pinned ones too), contacts, Jacobian rows, Delassus blocks: multi_contact.Scene
    with pins, sharing its couplings (coupling, delassus, un, ut)."""

    def __init__(self, data, source=""):
        self.source = source
        self.id = data.get("id", Path(source).stem if source else "")
        self.title = data.get("title", "")
        self.bodies = [Body(t) for t in data["body"]]
        names = {b.name: i for i, b in enumerate(self.bodies)}
        if len(names) != len(self.bodies):
            raise ValueError("two bodies share a name")
        for p in data.get("pin", []):
            b = self.bodies[names[p["body"]]]
            if b.fixed or b.pin is not None:
                raise ValueError(f"pin: body {b.name} fixed or pinned twice")
            b.pin = tuple(num(v) for v in p["point"])
            vq = (b.velocity[0] - b.omega * (b.pin[1] - b.position[1]),
                  b.velocity[1] + b.omega * (b.pin[0] - b.position[0]))
            if vq != (0, 0):
                raise ValueError(f"pin: the pinned point of {b.name} moves before the impact")
        self.contacts = [Contact(t, names, k + 1) for k, t in enumerate(data["contact"])]
        self.n = len(self.contacts)
        for c in self.contacts:
            for bi in (c.a, c.b):
                b = self.bodies[bi]
                if not b.fixed and b.pin is None and b.inertia == 0 and c.point != b.position:
                    raise ValueError(f"contact {c.index}: off the centre of the point body {b.name}")
            if self.bodies[c.a].fixed and self.bodies[c.b].fixed:
                raise ValueError(f"contact {c.index}: both bodies fixed")
        self.rows_n = [self._row(c, c.normal) for c in self.contacts]
        self.rows_t = [self._row(c, c.tangent) for c in self.contacts]
        self.Wnn = self.delassus(self.rows_n, self.rows_n)
        self.Wnt = self.delassus(self.rows_n, self.rows_t)
        self.Wtn = self.delassus(self.rows_t, self.rows_n)
        self.Wtt = self.delassus(self.rows_t, self.rows_t)
        s0 = self.initial_state()
        self.uN0 = self.un(s0)
        self.uT0 = self.ut(s0)
        self.friction = any(c.mu > 0 for c in self.contacts)

    def _row(self, c, d):
        row = {}
        for bi, s in ((c.a, 1), (c.b, -1)):
            b = self.bodies[bi]
            if b.pin is not None:
                row[bi] = (ZERO, ZERO, s * cross(sub(c.point, b.pin), d))
            else:
                row[bi] = (s * d[0], s * d[1], s * cross(sub(c.point, b.position), d))
        return row

    def initial_state(self):
        return [[b.velocity[0], b.velocity[1], b.omega] for b in self.bodies]

    @staticmethod
    def rowvel(row, state):
        return sum((jx * state[b][0] + jy * state[b][1] + jw * state[b][2]
                    for b, (jx, jy, jw) in row.items()), ZERO)

    def apply(self, state, row, lam):
        if lam == 0:
            return
        for bi, (jx, jy, jw) in row.items():
            b = self.bodies[bi]
            if b.fixed:
                continue
            state[bi][2] += b.inv_inertia * jw * lam
            if b.pin is not None:
                r = sub(b.position, b.pin)
                state[bi][0], state[bi][1] = -state[bi][2] * r[1], state[bi][2] * r[0]
            else:
                state[bi][0] += b.inv_mass * jx * lam
                state[bi][1] += b.inv_mass * jy * lam

    def after(self, LN, LT):
        s = self.initial_state()
        for i in range(self.n):
            self.apply(s, self.rows_n[i], LN[i])
            self.apply(s, self.rows_t[i], LT[i])
        return s

    def energy(self, s):
        return sum((b.mass * (s[i][0] ** 2 + s[i][1] ** 2) / 2 + b.inertia * s[i][2] ** 2 / 2
                    for i, b in enumerate(self.bodies) if not b.fixed), ZERO)

    def moving(self):
        return [i for i, b in enumerate(self.bodies) if not b.fixed]


def ends(sc, uN, uT, LN, LT):
    """Contact velocities after impulses (LN, LT) from (uN, uT)."""
    n = sc.n
    uN1 = [uN[i] + sum((sc.Wnn[i][j] * LN[j] + sc.Wnt[i][j] * LT[j] for j in range(n)), ZERO)
           for i in range(n)]
    uT1 = [uT[i] + sum((sc.Wtn[i][j] * LN[j] + sc.Wtt[i][j] * LT[j] for j in range(n)), ZERO)
           for i in range(n)]
    return uN1, uT1


# ----------------------------------------------------------------------------------------------
# One impact phase with Coulomb friction, every mode enumerated (exact)
# ----------------------------------------------------------------------------------------------

def phase(sc, uN, uT, base, off, friction=True):
    """Every solution of one phase, grouped by the velocities it produces.

    Unknowns: the phase's normal impulses LN and, for each contact with mu > 0, its tangential
    impulse LT (LT = 0 where mu = 0 or friction is off).  Per contact i:
      normal:  LN_i >= base_i, uN'_i + off_i >= 0, (LN_i - base_i)(uN'_i + off_i) = 0
               modes "closed" (uN'_i + off_i = 0) and "open" (LN_i = base_i);
      Coulomb: |LT_i| <= mu_i LN_i; LT_i = -mu_i LN_i sign(uT'_i) if uT'_i != 0
               modes "stick" (uT'_i = 0), "slide+" (LT_i = -mu LN_i, uT'_i >= 0),
               "slide-" (LT_i = +mu LN_i, uT'_i <= 0).  An open contact with base_i = 0 has
               LT_i = 0 (one mode).
    uN' = uN + Wnn LN + Wnt LT, uT' = uT + Wtn LN + Wtt LT.  A mode vector fixes a linear system;
    a nonsingular one gives one candidate, kept when every inequality holds; a singular one
    (e.g. two sticking points on one body whose tangent rows coincide) gives an affine set cut by
    the inequalities, whose vertices are taken exactly (multi_contact.polytope_vertices).
    Candidates producing the same velocities are one solution; its reported impulses are the
    centroid of the candidates found (a solution too: with the velocities fixed every
    condition is convex), with ``indeterminate`` true when they differ.
    Returns a list of dicts {LN, LT, uN, uT, state, modes, indeterminate}.
    """
    n = sc.n
    fr = [i for i in range(n) if friction and sc.contacts[i].mu > 0]
    k = len(fr)
    col = {i: n + j for j, i in enumerate(fr)}   # column of LT_i
    m = n + k
    mu = [c.mu for c in sc.contacts]

    def rowN(i):  # coefficients of uN'_i in x, constant uN_i
        r = [sc.Wnn[i][j] for j in range(n)] + [sc.Wnt[i][j] for j in fr]
        return r

    def rowT(i):
        return [sc.Wtn[i][j] for j in range(n)] + [sc.Wtt[i][j] for j in fr]

    def unit(j, c=ONE):
        r = [ZERO] * m
        r[j] = c
        return r

    per = []
    for i in range(n):
        opts = []
        for nm in ("closed", "open"):
            if i in col and not (nm == "open" and base[i] == 0):
                for tm in ("stick", "slide+", "slide-"):
                    opts.append((nm, tm))
            else:
                opts.append((nm, "none"))
        per.append(opts)

    cands = []
    for modes in itertools.product(*per):
        A, b = [], []
        ineq = []  # (g, h): g . x >= h
        for i, (nm, tm) in enumerate(modes):
            if nm == "closed":
                A.append(rowN(i))
                b.append(-(uN[i] + off[i]))
            else:
                A.append(unit(i))
                b.append(base[i])
            ineq.append((unit(i), base[i]))
            ineq.append((rowN(i), -(uN[i] + off[i])))
            if i in col:
                c = col[i]
                if tm == "stick":
                    A.append(rowT(i))
                    b.append(-uT[i])
                elif tm == "none":
                    A.append(unit(c))
                    b.append(ZERO)
                else:
                    s = ONE if tm == "slide+" else -ONE
                    r = unit(c)
                    r[i] = s * mu[i]
                    A.append(r)
                    b.append(ZERO)
                g1 = unit(c, -ONE)
                g1[i] = mu[i]
                ineq.append((g1, ZERO))
                g2 = unit(c)
                g2[i] = mu[i]
                ineq.append((g2, ZERO))
                if tm == "slide+":
                    ineq.append((rowT(i), -uT[i]))
                if tm == "slide-":
                    ineq.append(([-v for v in rowT(i)], uT[i]))
        sol = mc.affine_solutions(A, b)
        if sol is None:
            continue
        x0, N = sol

        def ok(x):
            return all(sum((g * v for g, v in zip(gr, x)), ZERO) >= h for gr, h in ineq)

        if not N:
            if ok(x0):
                cands.append((x0, modes))
            continue
        G = [[sum((gr[j] * N[c][j] for j in range(m)), ZERO) for c in range(len(N))] for gr, _ in ineq]
        H = [h - sum((gr[j] * x0[j] for j in range(m)), ZERO) for gr, h in ineq]
        for z in mc.polytope_vertices(G, H, len(N)):
            x = [x0[j] + sum((N[c][j] * z[c] for c in range(len(N))), ZERO) for j in range(m)]
            cands.append((x, modes))
    groups = []
    for x, modes in cands:
        LN = x[:n]
        LT = [x[col[i]] if i in col else ZERO for i in range(n)]
        st = sc.initial_state()
        # velocities produced by the phase's impulses alone (relative to the phase's start)
        for i in range(n):
            sc.apply(st, sc.rows_n[i], LN[i])
            sc.apply(st, sc.rows_t[i], LT[i])
        key = [tuple(r) for r in st]
        for g in groups:
            if g["key"] == key:
                if (LN, LT) not in g["xs"]:
                    g["xs"].append((LN, LT))
                break
        else:
            groups.append({"key": key, "xs": [(LN, LT)], "modes": modes})
    out = []
    for g in groups:
        xs = g["xs"]
        LN = [sum((x[0][j] for x in xs), ZERO) / len(xs) for j in range(n)]
        LT = [sum((x[1][j] for x in xs), ZERO) / len(xs) for j in range(n)]
        uN1, uT1 = ends(sc, uN, uT, LN, LT)
        out.append({"LN": LN, "LT": LT, "uN": uN1, "uT": uT1, "indeterminate": len(xs) > 1,
                    "normal_indeterminate": any(x[0] != xs[0][0] for x in xs)})
    return out


def modes_of(d, n):
    out = []
    for i in range(n):
        if d["LN"][i] == 0 and d["LT"][i] == 0:
            out.append("no impulse")
        elif d["uT"][i] == 0:
            out.append("stick")
        else:
            out.append("slide+" if d["uT"][i] > 0 else "slide-")
    return out


# ----------------------------------------------------------------------------------------------
# The laws
# ----------------------------------------------------------------------------------------------

def neg(x):
    return min(x, ZERO)


def law_lcp_newton(sc):
    off = [c.e * neg(u) for c, u in zip(sc.contacts, sc.uN0)]
    sols = phase(sc, sc.uN0, sc.uT0, [ZERO] * sc.n, off)
    return [{"LN": s["LN"], "LT": s["LT"], "indeterminate": s["indeterminate"],
             "extra": {"modes": modes_of(s, sc.n)}} for s in sols]


def law_lcp_poisson(sc):
    n = sc.n
    res = []
    for c in phase(sc, sc.uN0, sc.uT0, [ZERO] * n, [ZERO] * n):
        base = [sc.contacts[i].e * c["LN"][i] for i in range(n)]
        for x in phase(sc, c["uN"], c["uT"], base, [ZERO] * n):
            res.append({"LN": [a + b for a, b in zip(c["LN"], x["LN"])],
                        "LT": [a + b for a, b in zip(c["LT"], x["LT"])],
                        "indeterminate": c["indeterminate"] or x["indeterminate"],
                        "extra": {"compression": phase_json(sc, c),
                                  "expansion": dict(phase_json(sc, x),
                                                    extra_normal_impulses=[qs(x["LN"][i] - base[i]) for i in range(n)])}})
    return res


def law_split(sc):
    """Phase 1: lcp-newton with every e = 0 (friction acts).  Phase 2: normals only, no
    friction: total normal impulse lam = LN1 + x >= 0, uN'' + e u0n^- >= 0, complementary with
    lam; uN'' = uN1 + Wnn x.  An LCP in lam: w = (uN1 - Wnn LN1 + e u0n^-) + Wnn lam."""
    n = sc.n
    res = []
    for p1 in phase(sc, sc.uN0, sc.uT0, [ZERO] * n, [ZERO] * n):
        q = [p1["uN"][i] - sum((sc.Wnn[i][j] * p1["LN"][j] for j in range(n)), ZERO)
             + sc.contacts[i].e * neg(sc.uN0[i]) for i in range(n)]
        sols, deg = mc.solve_lcp(sc.Wnn, q)
        for lam in group_normal(sc, sols):
            x = [lam[i] - p1["LN"][i] for i in range(n)]
            res.append({"LN": lam, "LT": list(p1["LT"]),
                        "indeterminate": p1["indeterminate"] or deg,
                        "extra": {"phase1": phase_json(sc, p1),
                                  "phase2": {"normal_impulses": [qs(v) for v in x]}}})
    return res


def group_normal(sc, sols):
    """Normal-impulse solutions grouped by the velocities they produce (one representative)."""
    out, keys = [], []
    for lam in sols:
        st = sc.initial_state()
        for i in range(sc.n):
            sc.apply(st, sc.rows_n[i], lam[i])
        if st not in keys:
            keys.append(st)
            out.append(lam)
    return out


def phase_json(sc, d):
    return {"normal_impulses": [qs(v) for v in d["LN"]],
            "tangential_impulses": [qs(v) for v in d["LT"]],
            "normal_velocity_end": [qs(v) for v in d["uN"]],
            "tangential_velocity_end": [qs(v) for v in d["uT"]],
            "modes": modes_of(d, sc.n)}


def pgs_run(sc, K, friction=True):
    """K sweeps from zero impulses; per contact in file order the normal row
    lam_i <- max(0, lam_i - (uN_i + e_i u0n_i^-)/Wnn_ii) on the current velocities, then the
    friction row tau_i <- clamp(tau_i - uT_i/Wtt_ii, -mu_i lam_i, mu_i lam_i) on the velocities
    after the normal row.  (A contact with mu = 0 or Wtt_ii = 0 keeps tau_i = 0.)"""
    n = sc.n
    st = sc.initial_state()
    LN, LT = [ZERO] * n, [ZERO] * n
    for _ in range(K):
        for i in range(n):
            c = sc.contacts[i]
            u = sc.rowvel(sc.rows_n[i], st)
            new = max(ZERO, LN[i] - (u + c.e * neg(sc.uN0[i])) / sc.Wnn[i][i])
            sc.apply(st, sc.rows_n[i], new - LN[i])
            LN[i] = new
            if friction and c.mu > 0 and sc.Wtt[i][i] != 0:
                v = sc.rowvel(sc.rows_t[i], st)
                lim = c.mu * LN[i]
                t = min(max(LT[i] - v / sc.Wtt[i][i], -lim), lim)
                sc.apply(st, sc.rows_t[i], t - LT[i])
                LT[i] = t
    return LN, LT


def law_pgs(sc, K):
    LN, LT = pgs_run(sc, K)
    return [{"LN": LN, "LT": LT, "indeterminate": False, "extra": {"sweeps": K}}]


# ----------------------------------------------------------------------------------------------
# Engine profiles (exact replays of one velocity step; see engine-laws.md section 5)
# ----------------------------------------------------------------------------------------------

def pymunk_in_step(sc, i, u):
    """Is contact i in a Chipmunk step whose start has normal velocity u?  Positions are
    integrated before collision detection (Munk2D 2.0.1 src/cpSpaceStep.c:363-481 cpSpaceStep),
    so an approaching contact overlaps and is detected; a separating one is not; an exactly
    touching one (u = 0) stays at distance 0, which circle-circle and circle-segment treat as no
    contact (strict `distsq < mindist*mindist`, src/cpCollision.c:534, 557) and every pair with
    a polygon or two segments treats as a contact (`<= 0`, :483-677)."""
    if u < 0:
        return True
    if u > 0:
        return False
    ka = sc.bodies[sc.contacts[i].a].pymunk_kind()
    kb = sc.bodies[sc.contacts[i].b].pymunk_kind()
    return not ({ka, kb} <= {"circle", "segment"} and "circle" in (ka, kb))


def profile_pymunk(sc, iterations=10, max_steps=200):
    """pymunk 7 (Chipmunk 7.0.3 = Munk2D 2.0.1): repeated steps until no contact approaches.

    One step: the contacts in the step (pymunk_in_step), each with bounce_i = e_i uN_i(step
    start) (cpArbiterPreStep, src/cpArbiter.c:383, no threshold) and accumulators 0 (fresh
    contact, no warm start); 10 iterations (src/cpSpace.c:97); per iteration, per contact in file
    order (cpArbiterApplyImpulse, src/cpArbiter.c:422-442): vrn, vrt from the current velocity;
    jn <- max(jn - (bounce + vrn)/Wnn_ii, 0); jt <- clamp(jt - vrt/Wtt_ii, +-mu jn_new); apply
    both increments together.  Lever arms stay those of the scene (no pose change modelled) and
    no warm start between steps (accumulators restart at 0 each step)."""
    n = sc.n
    st = sc.initial_state()
    TN, TT = [ZERO] * n, [ZERO] * n
    steps = []
    for step in range(max_steps):
        u0 = sc.un(st)
        if not any(u < 0 for u in u0):
            return {"LN": TN, "LT": TT, "steps": steps, "stopped": True}
        act = [i for i in range(n) if pymunk_in_step(sc, i, u0[i])]
        LN, LT = [ZERO] * n, [ZERO] * n
        for _ in range(iterations):
            for i in act:
                c = sc.contacts[i]
                vrn = sc.rowvel(sc.rows_n[i], st)
                vrt = sc.rowvel(sc.rows_t[i], st)
                jn = max(LN[i] - (c.e * u0[i] + vrn) / sc.Wnn[i][i], ZERO)
                jt = LT[i]
                if c.mu > 0 and sc.Wtt[i][i] != 0:
                    lim = c.mu * jn
                    jt = min(max(LT[i] - vrt / sc.Wtt[i][i], -lim), lim)
                sc.apply(st, sc.rows_n[i], jn - LN[i])
                sc.apply(st, sc.rows_t[i], jt - LT[i])
                LN[i], LT[i] = jn, jt
        for i in range(n):
            TN[i] += LN[i]
            TT[i] += LT[i]
        steps.append({"step": step + 1, "contacts": [i + 1 for i in act],
                      "normal_impulses": [qs(LN[i]) for i in range(n)],
                      "tangential_impulses": [qs(LT[i]) for i in range(n)]})
    return {"LN": TN, "LT": TT, "steps": steps, "stopped": False}


PYMUNK_MAX_STEPS = 60


def law_pymunk(sc):
    r = profile_pymunk(sc, max_steps=PYMUNK_MAX_STEPS)
    extra = {"steps": r["steps"][:5], "number_of_steps": len(r["steps"]),
             "contacts_per_step": [s["contacts"] for s in r["steps"]],
             "iterations_per_step": 10}
    if not r["stopped"]:
        st = sc.after(r["LN"], r["LT"])
        return {"status": "does-not-stop", "extra": extra,
                "note": (f"a contact still approaches after {PYMUNK_MAX_STEPS} steps (the frozen-pose, "
                         "no-warm-start model gives infinitely many steps); the state after them is "
                         "given in decimals only (its exact numbers are too long)"),
                "decimal": {
                    "bodies": {sc.bodies[i].name: {"velocity": [f"{float(st[i][0]):.15g}", f"{float(st[i][1]):.15g}"],
                                                   "omega": f"{float(st[i][2]):.15g}"} for i in sc.moving()},
                    "normal_velocity": [f"{float(u):.15g}" for u in sc.un(st)],
                    "energy_change": f"{float(sc.energy(st) - sc.energy(sc.initial_state())):.15g}"}}
    return [{"LN": r["LN"], "LT": r["LT"], "indeterminate": False, "extra": extra}]


def manifolds(sc):
    """Contacts grouped as Box2D manifolds: same body pair and parallel normals, at most two
    points, in file order (first contact of each manifold); points in file order."""
    groups = []
    for i, c in enumerate(sc.contacts):
        pair = frozenset((c.a, c.b))
        for g in groups:
            j = g[0]
            cj = sc.contacts[j]
            if frozenset((cj.a, cj.b)) == pair and len(g) < 2:
                # same normal direction seen from the same A
                nj = cj.normal if cj.a == c.a else (-cj.normal[0], -cj.normal[1])
                if cross(nj, c.normal) == 0 and dot(nj, c.normal) > 0:
                    g.append(i)
                    break
        else:
            groups.append([i])
    return groups


def approach_exceeds(u, n2, thr):
    """uN / |n| < -thr, decided exactly (u scaled by |n|, n2 = |n|^2)."""
    return u < 0 and u * u > thr * thr * n2 if thr > 0 else u < 0


def profile_box2d(sc, iterations=8, threshold=ONE):
    """Box2D 2.3.0 (pybox2d 2.3.10) b2ContactSolver: see engine-laws.md.  Returns LN, LT, info."""
    n = sc.n
    st = sc.initial_state()
    bias = [(-sc.contacts[i].e * sc.uN0[i] if approach_exceeds(sc.uN0[i], sc.contacts[i].n2, threshold)
             else ZERO) for i in range(n)]
    LN, LT = [ZERO] * n, [ZERO] * n
    mans = manifolds(sc)
    dropped = []
    solved = []
    for g in mans:
        if len(g) == 2:
            i, j = g
            k11, k22, k12 = sc.Wnn[i][i], sc.Wnn[j][j], sc.Wnn[i][j]
            det = k11 * k22 - k12 * k12
            # k11^2 < 1000 det with unit normals: k11^2 |n_j|^2 < 1000 det |n_i|^2
            if not (k11 * k11 * sc.contacts[j].n2 < 1000 * det * sc.contacts[i].n2):
                dropped.append(j + 1)
                g = [i]
        solved.append(g)
    for _ in range(iterations):
        for g in solved:
            for i in g:                                   # friction first (b2ContactSolver.cpp:314-341)
                c = sc.contacts[i]
                if c.mu > 0 and sc.Wtt[i][i] != 0:
                    vt = sc.rowvel(sc.rows_t[i], st)
                    lim = c.mu * LN[i]                    # previous sweep's normal impulse (:328)
                    t = min(max(LT[i] - vt / sc.Wtt[i][i], -lim), lim)
                    sc.apply(st, sc.rows_t[i], t - LT[i])
                    LT[i] = t
            if len(g) == 1:                               # scalar normal row (:343-366)
                i = g[0]
                vn = sc.rowvel(sc.rows_n[i], st)
                new = max(LN[i] - (vn - bias[i]) / sc.Wnn[i][i], ZERO)
                sc.apply(st, sc.rows_n[i], new - LN[i])
                LN[i] = new
            else:                                         # 2x2 block LCP (:368-590)
                i, j = g
                k11, k22, k12 = sc.Wnn[i][i], sc.Wnn[j][j], sc.Wnn[i][j]
                a = (LN[i], LN[j])
                vn1 = sc.rowvel(sc.rows_n[i], st)
                vn2 = sc.rowvel(sc.rows_n[j], st)
                bx = vn1 - bias[i] - (k11 * a[0] + k12 * a[1])
                by = vn2 - bias[j] - (k12 * a[0] + k22 * a[1])
                det = k11 * k22 - k12 * k12
                x = None
                # case 1: both active, x = -K^-1 b
                x1 = -(k22 * bx - k12 * by) / det
                x2 = -(-k12 * bx + k11 * by) / det
                if x1 >= 0 and x2 >= 0:
                    x = (x1, x2)
                if x is None:                             # case 2: point 1 only
                    x1 = -bx / k11
                    if x1 >= 0 and k12 * x1 + by >= 0:
                        x = (x1, ZERO)
                if x is None:                             # case 3: point 2 only
                    x2 = -by / k22
                    if x2 >= 0 and k12 * x2 + bx >= 0:
                        x = (ZERO, x2)
                if x is None and bx >= 0 and by >= 0:     # case 4: none
                    x = (ZERO, ZERO)
                if x is not None:
                    sc.apply(st, sc.rows_n[i], x[0] - a[0])
                    sc.apply(st, sc.rows_n[j], x[1] - a[1])
                    LN[i], LN[j] = x
    return LN, LT, {"manifolds": [[i + 1 for i in g] for g in mans], "dropped_points": dropped,
                    "restitution_bias": [qs(b) for b in bias], "velocity_iterations": iterations,
                    "threshold": qs(threshold)}


def law_box2d(sc, threshold=ONE):
    LN, LT, info = profile_box2d(sc, threshold=threshold)
    return [{"LN": LN, "LT": LT, "indeterminate": False, "extra": info}]


def profile_bullet(sc, iterations=50, threshold=ZERO, residual_exit=BULLET_RESIDUAL, plane="xz"):
    """Bullet 3 (pybullet 3.2.7) btSequentialImpulseConstraintSolver, rigid path (pybullet's
    useMaximalCoordinates=True, as the tuned harness), one step: per iteration every normal row
    (file order) then every friction row (file order); early exit when the largest squared
    row residual (delta impulse times K, unit rows) is <= 1e-7.  See engine-laws.md.

    Friction direction (convertContact, btSequentialImpulseConstraintSolver.cpp:1096-1124): one
    row along the lateral relative velocity at setup if its squared length exceeds SIMD_EPSILON
    (DBL_EPSILON: pybullet is built with BT_USE_DOUBLE_PRECISION), else btPlaneSpace1(n).  The
    lateral velocity of a planar scene lies in the plane, so the row is along +-t; btPlaneSpace1
    of an in-plane normal is the out-of-plane axis when the scene's plane is x-z (extruded along
    y, plane="xz": no in-plane friction for that contact) and the in-plane tangent when it is x-y
    (plane="xy")."""
    n = sc.n
    st = sc.initial_state()
    rest, has_t = [], []
    for i, c in enumerate(sc.contacts):
        u = sc.uN0[i]
        below = u * u < threshold * threshold * c.n2          # |rel_vel| < threshold (strict)
        rest.append(ZERO if below else max(c.e * (-u), ZERO))  # restitutionCurve, clamped >= 0
        moving = sc.uT0[i] ** 2 > DBL_EPSILON * c.n2
        has_t.append(c.mu > 0 and sc.Wtt[i][i] != 0 and (moving or plane == "xy"))
    LN, LT = [ZERO] * n, [ZERO] * n
    done = 0
    for it in range(iterations):
        res2 = ZERO
        for i in range(n):
            vn = sc.rowvel(sc.rows_n[i], st)
            new = max(LN[i] + (rest[i] - vn) / sc.Wnn[i][i], ZERO)
            d = new - LN[i]
            res2 = max(res2, d * d * sc.Wnn[i][i] ** 2 / sc.contacts[i].n2)
            sc.apply(st, sc.rows_n[i], d)
            LN[i] = new
        for i in range(n):
            c = sc.contacts[i]
            lim = c.mu * LN[i]
            if has_t[i] and LN[i] > 0:                     # row skipped while the normal impulse is 0
                vt = sc.rowvel(sc.rows_t[i], st)
                t = min(max(LT[i] - vt / sc.Wtt[i][i], -lim), lim)
                d = t - LT[i]
                res2 = max(res2, d * d * sc.Wtt[i][i] ** 2 / c.n2)
                sc.apply(st, sc.rows_t[i], d)
                LT[i] = t
        done = it + 1
        if residual_exit is not None and res2 <= residual_exit:
            break
    return LN, LT, {"iterations": done, "restitution_target": [qs(r) for r in rest],
                    "friction_rows": [i + 1 for i in range(n) if has_t[i]],
                    "threshold": qs(threshold), "plane": plane}


def law_bullet(sc, threshold=ZERO, plane="xz"):
    LN, LT, info = profile_bullet(sc, threshold=threshold, plane=plane)
    return [{"LN": LN, "LT": LT, "indeterminate": False, "extra": info}]


# ----------------------------------------------------------------------------------------------
# Answers as JSON
# ----------------------------------------------------------------------------------------------

def solution_json(sc, LN, LT, extra=None, indeterminate=False):
    s0, s1 = sc.initial_state(), sc.after(LN, LT)
    uN1, uT1 = sc.un(s1), sc.ut(s1)
    E0, E1 = sc.energy(s0), sc.energy(s1)
    out = {}
    out["bodies"] = {sc.bodies[i].name: {"velocity": [qs(s1[i][0]), qs(s1[i][1])], "omega": qs(s1[i][2])}
                     for i in sc.moving()}
    out["impulses"] = [{"contact": i + 1, "normal": qs(LN[i]), "tangential": qs(LT[i])} for i in range(sc.n)]
    if sc.n == 1:
        c = sc.contacts[0]
        P = (LN[0] * c.normal[0] + LT[0] * c.tangent[0], LN[0] * c.normal[1] + LT[0] * c.tangent[1])
        out["impulse"] = [qs(P[0]), qs(P[1])]
        out["impulse_coefficients"] = {"lam": qs(LN[0]), "tau": qs(LT[0])}
    out["contact_velocity_after"] = {"normal": [qs(v) for v in uN1], "tangential": [qs(v) for v in uT1]}
    out["energy"] = {"before": qs(E0), "after": qs(E1), "change": qs(E1 - E0)}
    out["energy_gain"] = E1 > E0
    out["sinking_contacts"] = [i + 1 for i in range(sc.n) if uN1[i] < 0]
    if indeterminate:
        out["impulses_indeterminate"] = True
    if extra:
        out.update(extra)
    return out


DEFINITIONS = {
    "lcp-newton": ("one phase: lam >= 0, uN' + e uN0^- >= 0 complementary; Coulomb on the final slip: "
                   "|tau| <= mu lam, uT' = 0 inside, tau = -mu lam sign(uT') if uT' != 0"),
    "lcp-poisson": ("compression = lcp-newton with e = 0 -> (lam_c, tau_c); expansion from its velocities: "
                    "lam_e >= e lam_c, uN+ >= 0, (lam_e - e lam_c) uN+ = 0, Coulomb on (tau_e, uT+); total = sum"),
    "split": ("phase 1 = lcp-newton with e = 0 (friction acts); phase 2 normals only: total lam >= 0, "
              "uN'' + e uN0^- >= 0 complementary with the total; tangential impulses as phase 1 left them"),
    "pgs": ("K sweeps from 0, contacts in file order: lam <- max(0, lam - (uN + e uN0^-)/Wnn_ii), then "
            "tau <- clamp(tau - uT/Wtt_ii, -mu lam, mu lam) on the velocities after the normal row"),
    "pymunk-7": ("Chipmunk 7.0.3 / Munk2D 2.0.1 cpArbiterApplyImpulse, 10 iterations, normal and friction "
                 "increments from the same pre-point velocity, bound mu * new jnAcc, bounce e uN0 no threshold; "
                 "touching circle-circle / circle-segment pairs not in the step; steps repeated until no "
                 "contact approaches (lever arms frozen, no warm start)"),
    "box2d-2.3": ("Box2D 2.3.0 b2ContactSolver, 8 velocity iterations, per manifold friction rows first "
                  "(bound mu * previous normal impulse), then normal rows (2-point block LCP); bias -e uN0 "
                  "only if uN0/|n| < -threshold"),
    "bullet-3": ("Bullet 3 btSequentialImpulseConstraintSolver, 50 iterations, per iteration all normal rows "
                 "then all friction rows (bound mu * this iteration's normal impulse, skipped while 0); "
                 "restitution e * -uN0 unless |uN0|/|n| < threshold"),
}


def options(opt):
    """ "scale=16,threshold=1/5" -> {"scale": "16", "threshold": "1/5"}."""
    out = {}
    for part in filter(None, opt.split(",")):
        k, _, v = part.partition("=")
        if k not in ("scale", "threshold", "plane") or not v:
            raise ValueError(f"unknown option {part!r}")
        out[k] = v
    return out


def parse_law(name):
    base, _, opt = name.partition(":")
    return base, opt


def answer(sc, name):
    base, opt = parse_law(name)
    out = {"law": name}
    if base == "lcp-newton":
        sols = law_lcp_newton(sc)
    elif base == "lcp-poisson":
        sols = law_lcp_poisson(sc)
    elif base == "split":
        sols = law_split(sc)
    elif base == "pgs":
        sols = law_pgs(sc, int(opt))
        base = "pgs"
    elif base == "pymunk-7":
        sols = law_pymunk(sc)
    elif base == "box2d-2.3":
        o = options(opt)
        thr = ONE
        if "scale" in o:
            thr = 1 / num(o["scale"])
        if "threshold" in o:
            thr = num(o["threshold"])
        sols = law_box2d(sc, thr)
    elif base == "bullet-3":
        o = options(opt)
        sols = law_bullet(sc, num(o.get("threshold", "0")), o.get("plane", "xz"))
    else:
        raise ValueError(f"unknown law {name!r}")
    out["definition"] = DEFINITIONS[base]
    if isinstance(sols, dict):           # does-not-stop
        out["status"] = sols["status"]
        out["note"] = sols["note"]
        out["after_limit_decimal"] = sols["decimal"]
        out.update({k: v for k, v in sols["extra"].items() if k != "steps"})
        return out
    js = [solution_json(sc, s["LN"], s["LT"], s.get("extra"), s["indeterminate"]) for s in sols]
    # distinct velocity states only
    uniq, keys = [], []
    for s, j in zip(sols, js):
        k = json.dumps(j["bodies"], sort_keys=True)
        if k not in keys:
            keys.append(k)
            uniq.append(j)
    if not uniq:
        out["status"] = "no-solution"
    elif len(uniq) == 1:
        out["status"] = "answered"
        out.update(uniq[0])
    else:
        out["status"] = "several"
        out["solutions"] = uniq
    return out


def scene_json(sc):
    bodies = []
    for b in sc.bodies:
        if b.fixed:
            bodies.append({"name": b.name, "fixed": True})
        else:
            d = {"name": b.name, "mass": qs(b.mass), "inertia": qs(b.inertia),
                 "position": [qs(v) for v in b.position], "velocity": [qs(v) for v in b.velocity],
                 "omega": qs(b.omega)}
            if b.pin is not None:
                d["pin"] = [qs(v) for v in b.pin]
            bodies.append(d)
    contacts = [{"contact": c.index, "bodies": list(c.names), "point": [qs(v) for v in c.point],
                 "normal": [qs(v) for v in c.normal], "tangent": [qs(v) for v in c.tangent],
                 "e": qs(c.e), "mu": qs(c.mu)} for c in sc.contacts]
    return {"file": sc.source, "id": sc.id, "title": sc.title, "bodies": bodies, "contacts": contacts}


def analyse(sc, laws=DEFAULT_LAWS):
    s0 = sc.initial_state()
    if not any(u < 0 for u in sc.uN0):
        raise ValueError("no contact approaches")
    out = {"oracle": "tests/oracles/engine_laws.py", "scene": scene_json(sc),
           "delassus": {"nn": [[qs(x) for x in r] for r in sc.Wnn],
                        "nt": [[qs(x) for x in r] for r in sc.Wnt],
                        "tt": [[qs(x) for x in r] for r in sc.Wtt]},
           "normal_velocity_before": [qs(u) for u in sc.uN0],
           "tangential_velocity_before": [qs(u) for u in sc.uT0],
           "energy_before": qs(sc.energy(s0)),
           "conventions": ("impulse on A = normal * n + tangential * t (t = n turned a quarter turn "
                           "counterclockwise), on B the opposite; velocities and impulses in the file's "
                           "scaling of n; fixed bodies omitted"),
           "answers": [answer(sc, l) for l in laws]}
    return out


def load_toml(path):
    p = Path(path)
    with open(p, "rb") as f:
        data = tomllib.load(f)
    try:
        src = str(p.resolve().relative_to(ROOT))
    except ValueError:
        src = str(p)
    return Scene(data, src)


def load_jsonl(path):
    out = []
    for line in Path(path).read_text().splitlines():
        if line.strip():
            d = json.loads(line)
            out.append(Scene(d, d.get("id", "")))
    return out


def fixture_scenes():
    """(scene file, fixture name): every examples/impacts/*.toml, and the witnesses of
    tests/oracles/witnesses/ (scenes made to show no-solution, several and does-not-stop)."""
    out = [(p, p.stem + ".json") for p in sorted((ROOT / "examples" / "impacts").glob("*.toml"))]
    out += [(p, "witness-" + p.stem + ".json")
            for p in sorted((ROOT / "tests" / "oracles" / "witnesses").glob("*.toml"))]
    return out


def write_fixtures(laws=DEFAULT_LAWS, only=None):
    outdir = ROOT / "tests" / "data" / "impacts-engines"
    outdir.mkdir(parents=True, exist_ok=True)
    for p, name in fixture_scenes():
        if only and p.stem not in only:
            continue
        sc = load_toml(p)
        res = analyse(sc, laws)
        (outdir / name).write_text(json.dumps(res, indent=1) + "\n")
        print(f"wrote {outdir / name}", file=sys.stderr)
    if not only or "impacts.jsonl" in only:
        src = ROOT / "engines" / "impacts.jsonl"
        lines = [json.dumps(analyse(sc, laws)) for sc in load_jsonl(src)]
        (outdir / "engines-impacts.jsonl").write_text("\n".join(lines) + "\n")
        print(f"wrote {outdir / 'engines-impacts.jsonl'}", file=sys.stderr)


def main(argv):
    args = argv[1:]
    laws = []
    while "--law" in args:
        k = args.index("--law")
        laws.append(args[k + 1])
        del args[k:k + 2]
    laws = tuple(laws) or DEFAULT_LAWS
    if args[:1] == ["--write-fixtures"]:
        write_fixtures(laws, set(args[1:]) or None)
        return 0
    if len(args) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    if args[0].endswith(".jsonl"):
        for sc in load_jsonl(args[0]):
            print(json.dumps(analyse(sc, laws)))
    else:
        print(json.dumps(analyse(load_toml(args[0]), laws), indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
