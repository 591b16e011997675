#!/usr/bin/env python3
"""Exact oracle for planar rigid-body impacts with several simultaneous contacts.

Independent of rodimpact (no code shared with the Rust solver): Python's ``fractions.Fraction``
throughout, standard library only (``tomllib``, Python >= 3.11).  Reads a scene in the TOML of
DESIGN section 6 and prints JSON in which every number is an exact string ``"p/q"`` (``"p"``
for an integer).

    python3 tests/oracles/multi_contact.py examples/impacts/cradle-3.toml [--model M]
    python3 tests/oracles/multi_contact.py --write-fixtures      # every examples/impacts/*.toml
                                                                 # with several contacts
                                                                 # -> tests/data/impacts/*.json

Mechanics (derivation)
----------------------
Body b: mass m_b, inertia I_b about its centre c_b, velocity v_b, spin w_b (counterclockwise).
A fixed body has infinite mass and inertia (inverse mass and inverse inertia 0).  A body of
inertia 0 (shape "point") cannot be spun: its inverse inertia is taken as 0 and a contact on it
must act through its centre (checked).

Contact i joins A_i and B_i at the point p_i with the normal n_i (from B into A, any positive
length) and the tangent t_i = (-n_y, n_x).  The velocity of b's material point at p is
v_b + w_b k x (p - c_b) = v_b + w_b (-(p-c)_y, (p-c)_x).  With r = p - c and the planar cross
product r x n = r_x n_y - r_y n_x, the dot product of that velocity with n is
n . v_b + w_b (r x n).  So the normal relative velocity (A minus B) is the row

    u_i = J_i q,   J_i = [ +n_i, +(r_Ai x n_i) on A ;  -n_i, -(r_Bi x n_i) on B ],

q the stacked (v_x, v_y, w) of all bodies.  (It is scaled by |n_i|; everything below is
homogeneous in that scale, so the velocities after do not depend on it, while the reported
impulses lambda_i carry 1/|n_i| and the reported normal velocities |n_i|.)

An impulse lambda_i n_i on A and -lambda_i n_i on B is the generalised impulse J_i^T lambda_i:
dv_b = J_i^T lambda_i / m_b (linear part), dw_b = (r x n) lambda_i / I_b.  Hence after impulses
lambda the contact velocities are u = u0 + W lambda with the Delassus matrix
W = J M^-1 J^T,

    W_ij = sum over bodies b in both contacts of  s_ib s_jb ( n_i . n_j / m_b
                                                            + (r_bi x n_i)(r_bj x n_j) / I_b ),

s = +1 for A, -1 for B.  W is symmetric positive semidefinite.

Kinetic energy: T(q + M^-1 J^T lambda) - T(q) = lambda . u0 + lambda . W lambda / 2
= lambda . (u0 + u+) / 2.  So in every model dT = sum_i lambda_i (u0_i + u+_i) / 2, which is
how the ledger can be checked by hand.  (Momentum and angular momentum about the origin are
reported directly from the bodies: P = sum m v, L_O = sum (I w + m c x v), free bodies only.)

The models (frictionless; section "friction" below for mu > 0)
--------------------------------------------------------------
Write u0_i^- = min(u0_i, 0).  Approaching: u0_i < 0; touching: u0_i = 0; separating: u0_i > 0.

simultaneous-newton (generalised Newton law, Pfeiffer and Glocker's kinematic form):
    find lambda >= 0 with w = u0 + W lambda + e .* u0^- >= 0 and lambda . w = 0.
    For an approaching contact: u+_i >= -e_i u0_i, with equality if lambda_i > 0.  For a touching
    or separating one: u+_i >= 0, with equality if lambda_i > 0 (e has no effect on it).
    Identity: lambda_i > 0 implies u+_i = -e_i u0_i^- , so dT = sum lambda_i (1 - e_i) u0_i^- / 2
    <= 0 for 0 <= e <= 1: this law never creates energy without friction, and conserves it at e = 1.

simultaneous-poisson (Glocker and Pfeiffer's two-phase law, Poisson's hypothesis per contact):
    compression: lambda_C >= 0, u_C = u0 + W lambda_C >= 0, lambda_C . u_C = 0;
    expansion:   lambda_E = e .* lambda_C + x, x >= 0, u+ = u_C + W lambda_E >= 0, x . u+ = 0.
    Total impulse lambda = lambda_C + lambda_E.  Every contact of the file takes part in both
    phases (a contact that opened in compression may be closed again by x in expansion).
    For W positive semidefinite u_C is unique; if lambda_C is not, each choice is reported.

sequential (one single-contact Newton impact at a time):
    for an order (a permutation of the contacts), passes are made over the contacts in that
    order; a contact whose current normal velocity u_i is negative (approaching) takes the
    single-contact Newton impulse lambda = -(1 + e_i) u_i / W_ii (so u_i becomes -e_i u_i); a
    contact with u_i >= 0 is skipped; passes repeat until a whole pass fires nothing.  Every
    order is run; orders with identical final velocities are grouped.  If the firing pattern
    does not end (infinitely many impacts), the exact limit is computed from the linear
    pass map A (see ``sequential_limit``).

sequential-priority (the other reading of the brief's "sequential", reported alongside):
    after every impact the next one is the first contact in the order that approaches; stop
    when none approaches.  Same as the pass reading while at most one contact approaches at a
    time; on the ball-on-column scene it is not (8 outcomes over the 24 orders against 1).

pgs:K (projected Gauss-Seidel as Box2D and Rapier run it):
    accumulated impulses start at 0; a sweep visits the contacts in file order and sets
    lambda_i <- max(0, lambda_i - (u_i + e_i u0_i^-) / W_ii), applying the change at once
    (u_i is the current normal velocity, u0_i the one before the impact).  Its fixed points are
    exactly the solutions of the simultaneous-newton LCP, and for W positive definite the
    iteration converges to it (projected SOR with relaxation 1, Cryer 1971); ``pgs:limit`` is
    that answer.  Once the active set is fixed the sweep is Gauss-Seidel on W_SS: the error is
    multiplied by G = -(D + L)^-1 U each sweep; the oracle gives G's characteristic polynomial,
    its spectral radius (the asymptotic rate) and, when the errors of successive sweeps are
    exactly proportional, the exact ratio.

LCPs are solved by enumerating every active set S (lambda_j = 0 off S, w_i = 0 on S): solve
W_SS lambda_S = -q_S exactly and keep the candidates that satisfy every inequality.  All
solutions are reported (status "unique", "several", or "none").

Friction (mu > 0): see ``phase_solve``.  The frictional models are simultaneous-newton (one
phase, the normal law above, Coulomb's law on the final tangential velocity) and
simultaneous-poisson (the two phases above, Coulomb's law in each phase on that phase's impulses
and the tangential velocity at its end: Glocker's inequality impact law with tangential
restitution 0).  Each contact's mode (normal open/closed; stick, slide +, slide -) is
enumerated, so every solution is found exactly.
"""

from __future__ import annotations

import itertools
import json
import math
import sys
import tomllib
from fractions import Fraction as Q
from pathlib import Path

ZERO = Q(0)
ONE = Q(1)


# ----------------------------------------------------------------------------------------------
# Numbers and scenes
# ----------------------------------------------------------------------------------------------

def num(x) -> Q:
    """An exact rational from a scene value: "3/7", "0.25", "1.5e-3", "-2", "75/9.8" or an int.

    A TOML float is refused: it has already been rounded to binary.
    """
    if isinstance(x, bool):
        raise ValueError(f"not a number: {x!r}")
    if isinstance(x, int):
        return Q(x)
    if isinstance(x, float):
        raise ValueError(f"write numbers as strings (a TOML float is binary): {x!r}")
    s = str(x).strip()
    if "/" in s:
        a, b = s.split("/", 1)
        d = num(b)
        if d == 0:
            raise ValueError(f"zero denominator: {x!r}")
        return num(a) / d
    return Q(s)  # decimal with optional exponent, parsed exactly


def qs(x: Q) -> str:
    """The exact string of a rational: "p/q", or "p" for an integer."""
    return str(Q(x))


def cross(a, b) -> Q:
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b) -> Q:
    return a[0] * b[0] + a[1] * b[1]


class Body:
    def __init__(self, t: dict):
        self.name = t["name"]
        self.fixed = bool(t.get("fixed", False))
        self.shape = t.get("shape")
        self.dims = {k: num(t[k]) for k in ("length", "radius", "width", "height") if k in t}
        self.position = tuple(num(v) for v in t.get("position", ["0", "0"]))
        self.velocity = tuple(num(v) for v in t.get("velocity", ["0", "0"]))
        self.omega = num(t.get("omega", "0"))
        if self.fixed:
            self.mass = None
            self.inertia = None
            self.inv_mass = ZERO
            self.inv_inertia = ZERO
            return
        self.mass = num(t["mass"])
        if self.mass <= 0:
            raise ValueError(f"body {self.name}: mass must be positive")
        if "inertia" in t:
            self.inertia = num(t["inertia"])
        else:
            m = self.mass
            if self.shape == "rod":
                self.inertia = m * self.dims["length"] ** 2 / 12
            elif self.shape == "disc":
                self.inertia = m * self.dims["radius"] ** 2 / 2
            elif self.shape == "box":
                self.inertia = m * (self.dims["width"] ** 2 + self.dims["height"] ** 2) / 12
            elif self.shape == "point":
                self.inertia = ZERO
            else:
                raise ValueError(f"body {self.name}: give inertia or a shape")
        if self.inertia < 0:
            raise ValueError(f"body {self.name}: negative inertia")
        self.inv_mass = 1 / self.mass
        self.inv_inertia = ZERO if self.inertia == 0 else 1 / self.inertia


class Contact:
    def __init__(self, t: dict, names: dict, index: int):
        self.index = index  # 1-based, file order
        a, b = t["bodies"]
        self.a, self.b = names[a], names[b]
        self.names = (a, b)
        self.point = tuple(num(v) for v in t["point"])
        self.normal = tuple(num(v) for v in t["normal"])
        if self.normal == (0, 0):
            raise ValueError(f"contact {index}: zero normal")
        self.tangent = (-self.normal[1], self.normal[0])
        self.e = num(t.get("e", "0"))
        self.mu = num(t.get("mu", "0"))


class Scene:
    """A scene: bodies, contacts, and the Jacobian rows of the contacts."""

    def __init__(self, data: dict, source: str = ""):
        self.source = source
        self.title = data.get("title", "")
        self.bodies = [Body(t) for t in data["body"]]
        names = {b.name: i for i, b in enumerate(self.bodies)}
        if len(names) != len(self.bodies):
            raise ValueError("two bodies share a name")
        self.contacts = [Contact(t, names, k + 1) for k, t in enumerate(data["contact"])]
        self.n = len(self.contacts)
        # rows: list of {body index: (jx, jy, jw)}
        self.rows_n = [self._row(c, c.normal) for c in self.contacts]
        self.rows_t = [self._row(c, c.tangent) for c in self.contacts]
        for c in self.contacts:
            for bi in (c.a, c.b):
                b = self.bodies[bi]
                if not b.fixed and b.inertia == 0:
                    r = (c.point[0] - b.position[0], c.point[1] - b.position[1])
                    if r != (0, 0):
                        raise ValueError(f"contact {c.index}: off the centre of the point body {b.name}")
        self.friction = any(c.mu > 0 for c in self.contacts)

    def _row(self, c: Contact, d):
        row = {}
        for bi, s in ((c.a, 1), (c.b, -1)):
            b = self.bodies[bi]
            r = (c.point[0] - b.position[0], c.point[1] - b.position[1])
            jx, jy, jw = s * d[0], s * d[1], s * cross(r, d)
            if bi in row:
                raise ValueError(f"contact {c.index}: a body against itself")
            row[bi] = (jx, jy, jw)
        return row

    # state: list of [vx, vy, w] per body
    def initial_state(self):
        return [[b.velocity[0], b.velocity[1], b.omega] for b in self.bodies]

    @staticmethod
    def rowvel(row, state) -> Q:
        return sum((jx * state[b][0] + jy * state[b][1] + jw * state[b][2] for b, (jx, jy, jw) in row.items()), ZERO)

    def apply(self, state, row, lam: Q):
        if lam == 0:
            return
        for b, (jx, jy, jw) in row.items():
            body = self.bodies[b]
            state[b][0] += body.inv_mass * jx * lam
            state[b][1] += body.inv_mass * jy * lam
            state[b][2] += body.inv_inertia * jw * lam

    def coupling(self, r1, r2) -> Q:
        s = ZERO
        for b, (x1, y1, w1) in r1.items():
            if b in r2:
                x2, y2, w2 = r2[b]
                body = self.bodies[b]
                s += body.inv_mass * (x1 * x2 + y1 * y2) + body.inv_inertia * w1 * w2
        return s

    def delassus(self, rows1, rows2):
        return [[self.coupling(a, b) for b in rows2] for a in rows1]

    def un(self, state):
        return [self.rowvel(r, state) for r in self.rows_n]

    def ut(self, state):
        return [self.rowvel(r, state) for r in self.rows_t]

    def after(self, lam_n, lam_t=None):
        s = self.initial_state()
        for i, l in enumerate(lam_n):
            self.apply(s, self.rows_n[i], l)
        if lam_t is not None:
            for i, l in enumerate(lam_t):
                self.apply(s, self.rows_t[i], l)
        return s

    # conserved quantities (free bodies only)
    def ledger(self, state0, state1):
        def mom(s):
            px = sum((b.mass * s[i][0] for i, b in enumerate(self.bodies) if not b.fixed), ZERO)
            py = sum((b.mass * s[i][1] for i, b in enumerate(self.bodies) if not b.fixed), ZERO)
            return px, py

        def ang(s):
            return sum((b.inertia * s[i][2] + b.mass * (b.position[0] * s[i][1] - b.position[1] * s[i][0])
                        for i, b in enumerate(self.bodies) if not b.fixed), ZERO)

        def ke(s):
            return sum((b.mass * (s[i][0] ** 2 + s[i][1] ** 2) / 2 + b.inertia * s[i][2] ** 2 / 2
                        for i, b in enumerate(self.bodies) if not b.fixed), ZERO)

        p0, p1 = mom(state0), mom(state1)
        e0, e1 = ke(state0), ke(state1)
        un1 = self.un(state1)
        out = {
            "momentum": {"before": [qs(p0[0]), qs(p0[1])], "after": [qs(p1[0]), qs(p1[1])]},
            "angular_momentum_origin": {"before": qs(ang(state0)), "after": qs(ang(state1))},
            "energy": {"before": qs(e0), "after": qs(e1), "change": qs(e1 - e0)},
            "energy_gain": e1 > e0,
            "normal_velocity_after": [qs(u) for u in un1],
            "sinking_contacts": [i + 1 for i, u in enumerate(un1) if u < 0],
        }
        if self.friction:
            out["tangential_velocity_after"] = [qs(u) for u in self.ut(state1)]
        return out

    def bodies_json(self, state):
        return {b.name: {"velocity": [qs(state[i][0]), qs(state[i][1])], "omega": qs(state[i][2])}
                for i, b in enumerate(self.bodies) if not b.fixed}

    def result(self, lam_n, lam_t=None, extra=None):
        s0 = self.initial_state()
        s1 = self.after(lam_n, lam_t)
        out = {}
        if extra:
            out.update(extra)
        out["bodies"] = self.bodies_json(s1)
        imp = []
        for i in range(self.n):
            d = {"contact": i + 1, "normal": qs(lam_n[i])}
            if lam_t is not None:
                d["tangential"] = qs(lam_t[i])
            imp.append(d)
        out["impulses"] = imp
        out["ledger"] = self.ledger(s0, s1)
        return out

    # geometry: every contact point on both shapes
    def geometry_checks(self):
        """Check that each contact point lies on the boundary of both bodies' shapes.

        The file has no orientation field, so: a disc needs |p - c| = r and a normal along p - c;
        a box is taken axis-aligned (width along x) and p must lie on its boundary; a rod is a
        segment through c along the line through its contact points, |p - c| <= L/2, with the
        normal perpendicular to it unless p is an end; a point needs p = c; a body without shape
        (a floor, a wall) is not checked.
        """
        notes = []
        ok = True
        rod_dirs = {}
        for c in self.contacts:
            for bi in (c.a, c.b):
                b = self.bodies[bi]
                r = (c.point[0] - b.position[0], c.point[1] - b.position[1])
                if b.shape is None:
                    continue
                if b.shape == "disc":
                    good = dot(r, r) == b.dims["radius"] ** 2 and cross(r, c.normal) == 0
                elif b.shape == "point":
                    good = r == (0, 0)
                elif b.shape == "box":
                    hw, hh = b.dims["width"] / 2, b.dims["height"] / 2
                    inside = abs(r[0]) <= hw and abs(r[1]) <= hh
                    good = inside and (abs(r[0]) == hw or abs(r[1]) == hh)
                elif b.shape == "rod":
                    half = b.dims["length"] / 2
                    good = dot(r, r) <= half ** 2
                    if r != (0, 0):
                        d = rod_dirs.setdefault(bi, r)
                        good = good and cross(d, r) == 0
                        if dot(r, r) < half ** 2:
                            good = good and dot(r, c.normal) == 0
                else:
                    good = True
                if not good:
                    ok = False
                    notes.append(f"contact {c.index}: point {[qs(v) for v in c.point]} not on {b.shape} {b.name}")
        return {"all_points_on_both_shapes": ok, "problems": notes}


# ----------------------------------------------------------------------------------------------
# Exact linear algebra
# ----------------------------------------------------------------------------------------------

def solve_linear(A, b):
    """Solve A x = b exactly (Gauss-Jordan). Returns x, or None if A is singular."""
    n = len(A)
    M = [list(map(Q, A[i])) + [Q(b[i])] for i in range(n)]
    for col in range(n):
        piv = next((r for r in range(col, n) if M[r][col] != 0), None)
        if piv is None:
            return None
        M[col], M[piv] = M[piv], M[col]
        p = M[col][col]
        M[col] = [v / p for v in M[col]]
        for r in range(n):
            if r != col and M[r][col] != 0:
                f = M[r][col]
                M[r] = [vr - f * vc for vr, vc in zip(M[r], M[col])]
    return [M[i][n] for i in range(n)]


def rank(A) -> int:
    M = [list(map(Q, r)) for r in A]
    rk, rows = 0, len(M)
    cols = len(M[0]) if M else 0
    for col in range(cols):
        piv = next((r for r in range(rk, rows) if M[r][col] != 0), None)
        if piv is None:
            continue
        M[rk], M[piv] = M[piv], M[rk]
        for r in range(rows):
            if r != rk and M[r][col] != 0:
                f = M[r][col] / M[rk][col]
                M[r] = [a - f * b for a, b in zip(M[r], M[rk])]
        rk += 1
    return rk


def matvec(A, x):
    return [sum((a * b for a, b in zip(row, x)), ZERO) for row in A]


def matmul(A, B):
    return [[sum((A[i][k] * B[k][j] for k in range(len(B))), ZERO) for j in range(len(B[0]))] for i in range(len(A))]


def identity(n):
    return [[ONE if i == j else ZERO for j in range(n)] for i in range(n)]


def inverse(A):
    n = len(A)
    cols = [solve_linear(A, [ONE if i == j else ZERO for i in range(n)]) for j in range(n)]
    if any(c is None for c in cols):
        return None
    return [[cols[j][i] for j in range(n)] for i in range(n)]


def charpoly(A):
    """Characteristic polynomial det(x I - A), coefficients from x^n down (Faddeev-LeVerrier)."""
    n = len(A)
    coeffs = [ONE]
    M = [[ZERO] * n for _ in range(n)]
    for k in range(1, n + 1):
        M = matmul(A, M)
        for i in range(n):
            M[i][i] += coeffs[-1]
        AM = matmul(A, M)
        c = -sum((AM[i][i] for i in range(n)), ZERO) / k
        coeffs.append(c)
    return coeffs


def poly_roots(coeffs):
    """Complex roots (floats, Durand-Kerner) of a polynomial with rational coefficients."""
    c = [float(x) for x in coeffs]
    while c and c[0] == 0:
        c.pop(0)
    n = len(c) - 1
    if n <= 0:
        return []
    c = [x / c[0] for x in c]
    roots = [complex(0.4, 0.9) ** k for k in range(n)]
    for _ in range(2000):
        new = []
        for i, r in enumerate(roots):
            val = sum(ci * r ** (n - k) for k, ci in enumerate(c))
            den = 1
            for j, s in enumerate(roots):
                if j != i:
                    den *= (r - s)
            new.append(r - val / den if den != 0 else r + 1e-9)
        roots = new
    return roots


def poly_div_root(coeffs, r):
    """Divide a polynomial (coefficients from the top degree) by (x - r), exactly (r a root)."""
    out = [coeffs[0]]
    for c in coeffs[1:-1]:
        out.append(c + out[-1] * r)
    return out


def surd(a: Q, b: Q, d: int) -> str:
    """The string of a + b sqrt(d) (d > 1 squarefree, or d = 1 folded in)."""
    if d == 1:
        return qs(a + b)
    if b == 0:
        return qs(a)
    bs = f"sqrt({d})" if b == 1 else f"-sqrt({d})" if b == -1 else f"{qs(b)}*sqrt({d})"
    if a == 0:
        return bs
    return f"{qs(a)} + {bs}" if b > 0 else f"{qs(a)} - {bs.lstrip('-')}"


def squarefree_split(n: int):
    """n = k^2 d with d squarefree; returns (k, d)."""
    k, d, f = 1, n, 2
    while f * f <= d:
        while d % (f * f) == 0:
            d //= f * f
            k *= f
        f += 1
    return k, d


def dominant_root_exact(coeffs):
    """The root of largest modulus as an exact string if it is rational or a real quadratic surd.

    Rational roots are divided out; a remaining quadratic x^2 + p x + q with real roots gives
    (-p +- sqrt(p^2 - 4q))/2.  Returns None if the dominant root is of higher degree.
    """
    c = list(coeffs)
    roots = []  # (float value, string)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
        roots.append((0.0, "0"))
    for r in rational_roots(c):
        if r == 0:
            continue
        while len(c) > 1 and sum((a * r ** (len(c) - 1 - k) for k, a in enumerate(c)), ZERO) == 0:
            c = poly_div_root(c, r)
            roots.append((float(r), qs(r)))
    if len(c) == 3:
        p, q = c[1] / c[0], c[2] / c[0]
        disc = p * p - 4 * q
        if disc < 0:
            return None
        num_, den = disc.numerator, disc.denominator
        k, d = squarefree_split(num_ * den)
        b = Q(k, 2 * den)
        for sgn in (1, -1):
            roots.append((float(-p / 2) + sgn * float(b) * math.sqrt(d), surd(-p / 2, sgn * b, d)))
    elif len(c) > 3:
        return None
    if not roots:
        return None
    return max(roots, key=lambda t: abs(t[0]))[1]


def rational_roots(coeffs):
    """Exact rational roots of a polynomial with rational coefficients (rational root theorem)."""
    l = math.lcm(*[x.denominator for x in coeffs])
    ints = [int(x * l) for x in coeffs]
    while ints and ints[-1] == 0:  # root 0
        ints.pop()
    found = set()
    if len(ints) < len(coeffs):
        found.add(ZERO)
    if len(ints) <= 1:
        return sorted(found)

    def divisors(k):
        k = abs(k)
        return [d for d in range(1, k + 1) if k % d == 0] if k <= 10 ** 6 else [1]

    for p in divisors(ints[-1]):
        for q in divisors(ints[0]):
            for s in (1, -1):
                r = Q(s * p, q)
                if sum((Q(a) * r ** (len(ints) - 1 - k) for k, a in enumerate(ints)), ZERO) == 0:
                    found.add(r)
    return sorted(found)


# ----------------------------------------------------------------------------------------------
# LCP by active-set enumeration
# ----------------------------------------------------------------------------------------------

def solve_lcp(W, q):
    """All solutions of lambda >= 0, w = q + W lambda >= 0, lambda . w = 0, by active sets.

    For each subset S: lambda off S is 0, w on S is 0, so W_SS lambda_S = -q_S.  Nonsingular
    W_SS: one candidate, kept if lambda_S >= 0 and w >= 0.  Singular W_SS: the subset is
    recorded as degenerate (a continuum of solutions may exist there; its vertices are found
    by the smaller subsets), and ``degenerate`` is returned true if it is consistent.
    Returns (solutions, degenerate).
    """
    n = len(q)
    sols = []
    degenerate = False
    for k in range(n + 1):
        for S in itertools.combinations(range(n), k):
            lam = [ZERO] * n
            if S:
                A = [[W[i][j] for j in S] for i in S]
                x = solve_linear(A, [-q[i] for i in S])
                if x is None:
                    aug = [A[r] + [-q[S[r]]] for r in range(len(S))]
                    if rank(A) == rank(aug):
                        degenerate = True
                    continue
                for i, v in zip(S, x):
                    lam[i] = v
            if any(v < 0 for v in lam):
                continue
            w = [q[i] + sum((W[i][j] * lam[j] for j in range(n)), ZERO) for i in range(n)]
            if any(v < 0 for v in w):
                continue
            if lam not in sols:
                sols.append(lam)
    return sols, degenerate


def status_of(sols, degenerate=False):
    """ "none", "unique" or "several".  (A degenerate active set only makes the impulses
    indeterminate: for W = J M^-1 J^T a null vector z of W_SS has J_S^T z = 0, so it moves no
    velocity; the solutions found at the vertices then carry every velocity state.)"""
    if not sols:
        return "none"
    if len(sols) > 1:
        return "several"
    return "unique"


# ----------------------------------------------------------------------------------------------
# Frictionless models
# ----------------------------------------------------------------------------------------------

def model_newton(sc: Scene, W, u0):
    q = [u0[i] + sc.contacts[i].e * min(u0[i], ZERO) for i in range(sc.n)]
    sols, deg = solve_lcp(W, q)
    return sols, deg


def model_newton_json(sc, W, u0):
    sols, deg = model_newton(sc, W, u0)
    out = {"model": "simultaneous-newton",
           "formulation": "lambda >= 0, w = u0 + W lambda + e .* min(u0, 0) >= 0, lambda . w = 0",
           "status": status_of(sols), "impulses_indeterminate": deg}
    if len(sols) == 1:
        out.update(sc.result(sols[0]))
    else:
        out["solutions"] = [sc.result(s) for s in sols]
    return out


def model_poisson(sc: Scene, W, u0):
    """Compression then expansion LCPs (Glocker/Pfeiffer).  Returns a list of
    (lambda_C, x, lambda_total) for every combination of solutions, and the degeneracy flag."""
    e = [c.e for c in sc.contacts]
    comp, deg1 = solve_lcp(W, u0)
    out = []
    deg = deg1
    for lc in comp:
        uc = [u0[i] + sum((W[i][j] * lc[j] for j in range(sc.n)), ZERO) for i in range(sc.n)]
        base = [e[i] * lc[i] for i in range(sc.n)]
        q = [uc[i] + sum((W[i][j] * base[j] for j in range(sc.n)), ZERO) for i in range(sc.n)]
        exps, deg2 = solve_lcp(W, q)
        deg = deg or deg2
        for x in exps:
            tot = [lc[i] + base[i] + x[i] for i in range(sc.n)]
            out.append((lc, uc, x, tot))
    return out, deg


def model_poisson_json(sc, W, u0):
    res, deg = model_poisson(sc, W, u0)
    out = {"model": "simultaneous-poisson",
           "formulation": ("compression: lC >= 0, uC = u0 + W lC >= 0, lC . uC = 0; "
                           "expansion: lE = e .* lC + x, x >= 0, u+ = uC + W lE >= 0, x . u+ = 0; "
                           "lambda = lC + lE"),
           "status": status_of(res), "impulses_indeterminate": deg}
    sols = []
    for lc, uc, x, tot in res:
        extra = {"compression": {"impulses": [qs(v) for v in lc], "normal_velocity_end": [qs(v) for v in uc]},
                 "expansion": {"impulses": [qs(sc.contacts[i].e * lc[i] + x[i]) for i in range(sc.n)],
                               "extra_impulses": [qs(v) for v in x]}}
        sols.append(sc.result(tot, extra=extra))
    if len(sols) == 1:
        out.update(sols[0])
    else:
        out["solutions"] = sols
    return out


def sequential_run(sc: Scene, W, order, max_passes=300):
    """Run one order.  Returns dict with impacts, final total impulses, termination info."""
    state = sc.initial_state()
    lam = [ZERO] * sc.n
    impacts = []
    patterns = []
    u_at_pass_start = []
    for p in range(max_passes):
        u_start = sc.un(state)
        u_at_pass_start.append(u_start)
        fired = []
        for i in order:
            u = sc.rowvel(sc.rows_n[i], state)
            if u < 0:
                l = -(1 + sc.contacts[i].e) * u / W[i][i]
                sc.apply(state, sc.rows_n[i], l)
                lam[i] += l
                fired.append(i)
                impacts.append((i, l))
        patterns.append(tuple(fired))
        if not fired:
            return {"terminated": True, "lam": lam, "impacts": impacts, "passes": p}
    # Not terminated: the firing pattern of the last passes is taken as periodic.
    return sequential_limit(sc, W, order, lam, impacts, patterns, u_at_pass_start, state)


def sequential_limit(sc, W, order, lam, impacts, patterns, u_starts, state):
    """Exact limit of an infinite sequence of single-contact impacts.

    If the same contacts fire in the same order in every pass from some pass on, each pass is
    linear in the contact velocities at its start: u_{k+1} = A u_k and the pass's impulses are
    L u_k, with A the product (in firing order) of the single-contact maps
    P_i = I - (1 + e_i) W[:, i] e_i^T / W_ii and L's rows the impulses -(1 + e_i)/W_ii times
    the current u_i.  If A's spectral radius is below 1, the impulses still to come are
    sum_k L A^k u = L (I - A)^-1 u, exactly.  The assumption that the pattern persists is
    checked in floating point for 20,000 further passes (reported).
    """
    pat = patterns[-1]
    same = 0
    for p in reversed(patterns):
        if p == pat:
            same += 1
        else:
            break
    n = sc.n
    u = sc.un(state)
    A = identity(n)
    L = []
    for i in pat:
        # impulse of this firing given u at pass start: -(1+e)/W_ii * (A u)_i
        row = [-(1 + sc.contacts[i].e) / W[i][i] * A[i][j] for j in range(n)]
        L.append((i, row))
        P = identity(n)
        for r in range(n):
            P[r][i] -= (1 + sc.contacts[i].e) * W[r][i] / W[i][i]
        A = matmul(P, A)
    cp = charpoly(A)
    rho = max((abs(r) for r in poly_roots(cp)), default=0.0)
    IA = [[(ONE if i == j else ZERO) - A[i][j] for j in range(n)] for i in range(n)]
    y = solve_linear(IA, u) if rho < 1 else None
    info = {"terminated": False, "impacts": impacts, "pattern": [i + 1 for i in pat],
            "pattern_repeats_in_exact_passes": same, "pass_map_charpoly": [qs(c) for c in cp],
            "pass_map_spectral_radius": f"{rho:.15g}"}
    if y is None:
        info["lam"] = None
        return info
    tot = list(lam)
    for i, row in L:
        tot[i] += sum((a * b for a, b in zip(row, y)), ZERO)
    info["lam"] = tot
    # float continuation to check that the pattern persists
    Wf = [[float(x) for x in r] for r in W]
    uf = [float(x) for x in u]
    persisted = True
    for k in range(20000):
        fired = []
        for i in order:
            if uf[i] < 0:
                l = -(1 + float(sc.contacts[i].e)) * uf[i] / Wf[i][i]
                uf = [uf[r] + Wf[r][i] * l for r in range(n)]
                fired.append(i)
        if tuple(fired) != pat:
            persisted = False
            break
        s = max(abs(v) for v in uf)
        if s < 1e-250:
            break
        if s < 1e-100:
            uf = [v * 1e100 for v in uf]
    info["pattern_persists_in_float_continuation"] = persisted
    return info


def model_sequential_json(sc, W, u0):
    n = sc.n
    runs = []
    groups = {}
    for perm in itertools.permutations(range(n)):
        r = sequential_run(sc, W, perm)
        name = ",".join(str(i + 1) for i in perm)
        extra = {"model": f"sequential:{name}", "order": [i + 1 for i in perm],
                 "terminated": r["terminated"]}
        imps = r["impacts"]
        extra["impacts"] = [{"contact": i + 1, "impulse": qs(l)} for i, l in imps[:60]]
        if r["terminated"]:
            extra["number_of_impacts"] = len(imps)
        else:
            extra["number_of_impacts"] = "infinite"
            extra["impacts_listed"] = min(len(imps), 60)
            for k in ("pattern", "pattern_repeats_in_exact_passes", "pass_map_charpoly",
                      "pass_map_spectral_radius", "pattern_persists_in_float_continuation"):
                if k in r:
                    extra[k] = r[k]
        if r["lam"] is None:
            extra["status"] = "no limit found"
            runs.append(extra)
            continue
        res = sc.result(r["lam"], extra=extra)
        runs.append(res)
        key = json.dumps(res["bodies"], sort_keys=True)
        groups.setdefault(key, []).append(name)
    agreement = [{"orders": v, "bodies": json.loads(k)} for k, v in groups.items()]
    return {"model": "sequential",
            "formulation": ("passes over the contacts in the given order; an approaching contact (u_i < 0) "
                            "takes lambda_i = -(1 + e_i) u_i / W_ii; repeat until a pass fires nothing"),
            "orders": runs,
            "distinct_outcomes": len(agreement),
            "all_orders_agree": len(agreement) == 1,
            "agreement": agreement}


def sequential_priority_run(sc: Scene, W, order, max_impacts=5000):
    """The other reading of "sequential": after every impact, the next one is the FIRST contact
    in the order that approaches (u_i < 0); stop when none does.  It differs from the pass reading
    once two contacts approach at the same time (e.g. the column: pass reading 1 outcome over the
    24 orders, this reading 8)."""
    state = sc.initial_state()
    lam = [ZERO] * sc.n
    impacts = []
    while len(impacts) < max_impacts:
        nxt = next((i for i in order if sc.rowvel(sc.rows_n[i], state) < 0), None)
        if nxt is None:
            return {"terminated": True, "lam": lam, "impacts": impacts}
        u = sc.rowvel(sc.rows_n[nxt], state)
        l = -(1 + sc.contacts[nxt].e) * u / W[nxt][nxt]
        sc.apply(state, sc.rows_n[nxt], l)
        lam[nxt] += l
        impacts.append((nxt, l))
    return {"terminated": False, "lam": None, "impacts": impacts}


def model_sequential_priority_json(sc, W, u0):
    runs = []
    groups = {}
    for perm in itertools.permutations(range(sc.n)):
        r = sequential_priority_run(sc, W, perm)
        name = ",".join(str(i + 1) for i in perm)
        extra = {"model": f"sequential-priority:{name}", "order": [i + 1 for i in perm],
                 "terminated": r["terminated"],
                 "impacts": [{"contact": i + 1, "impulse": qs(l)} for i, l in r["impacts"][:60]],
                 "number_of_impacts": len(r["impacts"]) if r["terminated"] else "more than 5000"}
        if r["lam"] is None:
            extra["status"] = "did not stop within 5000 impacts (no limit computed for this reading)"
            runs.append(extra)
            continue
        res = sc.result(r["lam"], extra=extra)
        runs.append(res)
        groups.setdefault(json.dumps(res["bodies"], sort_keys=True), []).append(name)
    agreement = [{"orders": v, "bodies": json.loads(k)} for k, v in groups.items()]
    return {"model": "sequential-priority",
            "formulation": ("after every impact the next is the first contact in the given order with u_i < 0, "
                            "which takes lambda_i = -(1 + e_i) u_i / W_ii; stop when no contact approaches"),
            "orders": runs,
            "distinct_outcomes": len(agreement),
            "all_orders_agree": len(agreement) == 1,
            "agreement": agreement}


def pgs_iterates(sc, W, u0, K):
    lam = [ZERO] * sc.n
    state = sc.initial_state()
    hist = []
    for _ in range(K):
        for i in range(sc.n):
            u = sc.rowvel(sc.rows_n[i], state)
            bias = sc.contacts[i].e * min(u0[i], ZERO)
            new = max(ZERO, lam[i] - (u + bias) / W[i][i])
            sc.apply(state, sc.rows_n[i], new - lam[i])
            lam[i] = new
        hist.append(list(lam))
    return hist


def model_pgs_json(sc, W, u0, sweeps=(1, 2, 3, 10)):
    Kmax = max(sweeps)
    hist = pgs_iterates(sc, W, u0, Kmax)
    out = []
    for K in sweeps:
        r = sc.result(hist[K - 1], extra={"model": f"pgs:{K}"})
        out.append(r)
    # limit
    sols, deg = model_newton(sc, W, u0)
    lim = {"model": "pgs:limit"}
    if len(sols) == 1 and rank(W) == sc.n:
        star = sols[0]
        lim["limit_is"] = "simultaneous-newton (W positive definite: projected Gauss-Seidel converges to the unique LCP solution)"
        S = [i for i in range(sc.n) if star[i] != 0]
        wstar = [u0[i] + sc.contacts[i].e * min(u0[i], ZERO) + sum((W[i][j] * star[j] for j in range(sc.n)), ZERO)
                 for i in range(sc.n)]
        strict = all(wstar[i] > 0 for i in range(sc.n) if i not in S)
        conv = {"active_set": [i + 1 for i in S], "strictly_complementary": strict}
        if S:
            Wss = [[W[i][j] for j in S] for i in S]
            m = len(S)
            DL = [[Wss[i][j] if j <= i else ZERO for j in range(m)] for i in range(m)]
            U = [[Wss[i][j] if j > i else ZERO for j in range(m)] for i in range(m)]
            DLi = inverse(DL)
            G = [[-x for x in row] for row in matmul(DLi, U)]
            cp = charpoly(G)
            roots = poly_roots(cp)
            rho = max((abs(r) for r in roots), default=0.0)
            conv["gauss_seidel_matrix_charpoly"] = [qs(c) for c in cp]
            conv["asymptotic_rate_per_sweep"] = f"{rho:.15g}"
            exact = dominant_root_exact(cp)
            if exact is not None:
                conv["asymptotic_rate_per_sweep_exact"] = exact
        # error ratios of successive sweeps
        errs = [[h[i] - star[i] for i in range(sc.n)] for h in hist]
        ratios = []
        for k in range(len(errs) - 1):
            a, b = errs[k], errs[k + 1]
            rs = set()
            okr = True
            if all(x == 0 for x in a) and all(y == 0 for y in b):
                ratios.append("converged")
                continue
            for x, y in zip(a, b):
                if x == 0 and y == 0:
                    continue
                if x == 0:
                    okr = False
                    break
                rs.add(y / x)
            ratios.append(qs(rs.pop()) if okr and len(rs) == 1 else None)
        conv["error_ratio_sweep_k_to_k_plus_1"] = ratios
        if ratios and ratios[0] not in (None, "converged") and all(r == ratios[0] for r in ratios):
            conv["exact_geometric_ratio"] = ratios[0]
            conv["first_sweep_error"] = [qs(v) for v in errs[0]]
        lim["convergence"] = conv
        lim.update(sc.result(star))
    else:
        lim["status"] = "not computed: the Newton LCP has no unique solution or W is singular"
    out.append(lim)
    return out


# ----------------------------------------------------------------------------------------------
# Friction: one impact phase with Coulomb's law, every mode enumerated
# ----------------------------------------------------------------------------------------------

NORMAL_MODES = ("closed", "open")
TANG_MODES = ("stick", "slide+", "slide-")


def affine_solutions(A, b):
    """The solution set of A x = b as (x0, N): x = x0 + N z, N's columns a null-space basis.

    Exact reduced row echelon form.  Returns None if the system is inconsistent.
    """
    rows, cols = len(A), len(A[0])
    M = [list(map(Q, A[i])) + [Q(b[i])] for i in range(rows)]
    pivots = []
    r = 0
    for c in range(cols):
        piv = next((k for k in range(r, rows) if M[k][c] != 0), None)
        if piv is None:
            continue
        M[r], M[piv] = M[piv], M[r]
        pv = M[r][c]
        M[r] = [v / pv for v in M[r]]
        for k in range(rows):
            if k != r and M[k][c] != 0:
                f = M[k][c]
                M[k] = [a - f * bb for a, bb in zip(M[k], M[r])]
        pivots.append(c)
        r += 1
        if r == rows:
            break
    for k in range(r, rows):
        if M[k][cols] != 0:
            return None
    free = [c for c in range(cols) if c not in pivots]
    x0 = [ZERO] * cols
    for k, c in enumerate(pivots):
        x0[c] = M[k][cols]
    N = []
    for f in free:
        v = [ZERO] * cols
        v[f] = ONE
        for k, c in enumerate(pivots):
            v[c] = -M[k][f]
        N.append(v)
    return x0, N


def polytope_vertices(G, h, k):
    """Vertices of {z in Q^k : G z >= h} by choosing k tight rows (exact; k small)."""
    verts = []
    for rows in itertools.combinations(range(len(G)), k):
        z = solve_linear([G[r] for r in rows], [h[r] for r in rows])
        if z is None:
            continue
        if all(sum((g * zz for g, zz in zip(G[r], z)), ZERO) >= h[r] for r in range(len(G))):
            if z not in verts:
                verts.append(z)
    return verts


def phase_solve(sc: Scene, uN, uT, base, off):
    """All solutions of one impact phase with Coulomb friction.

    Unknowns: the phase's normal impulses LN and tangential impulses LT.  At the phase's end
    uN' = uN + Wnn LN + Wnt LT and uT' = uT + Wtn LN + Wtt LT.  Per contact i:
      normal:     LN_i - base_i >= 0,  uN'_i + off_i >= 0,  (LN_i - base_i)(uN'_i + off_i) = 0
                  ("closed": uN'_i + off_i = 0; "open": LN_i = base_i);
      tangential: |LT_i| <= mu_i LN_i and LT_i = -mu_i LN_i sign(uT'_i) when uT'_i != 0
                  ("stick": uT'_i = 0; "slide+": LT_i = -mu_i LN_i, uT'_i >= 0;
                   "slide-": LT_i = +mu_i LN_i, uT'_i <= 0).
    For a mode vector the equalities are a linear system in (LN, LT).  If it is nonsingular its
    solution is kept when every inequality holds.  If it is singular (two sticking points on one
    body whose tangent rows coincide, e.g. a box flat on a floor: the split of the tangential
    impulse between them is statically indeterminate), its solution set x0 + N z is cut by the
    inequalities and the vertices of that polytope (exact, k tight rows at a time) are taken.
    Solutions are then grouped by the velocities and normal impulses they produce: tangential
    impulses that differ only along directions with J^T dx = 0 give one physical solution,
    reported at the centroid of its vertices (a solution too: every condition is convex once
    the velocities are fixed) with ``indeterminate`` true.
    Returns a list of (LN, LT, modes, uN', uT', indeterminate).
    """
    n = sc.n
    Wnn = sc.delassus(sc.rows_n, sc.rows_n)
    Wnt = sc.delassus(sc.rows_n, sc.rows_t)
    Wtn = sc.delassus(sc.rows_t, sc.rows_n)
    Wtt = sc.delassus(sc.rows_t, sc.rows_t)
    mu = [c.mu for c in sc.contacts]

    def ends(LN, LT):
        uN1 = [uN[i] + sum((Wnn[i][j] * LN[j] + Wnt[i][j] * LT[j] for j in range(n)), ZERO) for i in range(n)]
        uT1 = [uT[i] + sum((Wtn[i][j] * LN[j] + Wtt[i][j] * LT[j] for j in range(n)), ZERO) for i in range(n)]
        return uN1, uT1

    def inequalities(tm):
        """Rows (g, h) meaning g . x >= h, x = (LN, LT), for the mode's inequalities."""
        rows = []
        for i in range(n):
            g = [ZERO] * (2 * n)
            g[i] = ONE
            rows.append((g, base[i]))                                   # LN_i >= base_i
            rows.append((Wnn[i] + Wnt[i], -(uN[i] + off[i])))           # uN'_i + off_i >= 0
            g1 = [ZERO] * (2 * n)
            g1[i], g1[n + i] = mu[i], -ONE
            rows.append((g1, ZERO))                                     # mu LN - LT >= 0
            g2 = [ZERO] * (2 * n)
            g2[i], g2[n + i] = mu[i], ONE
            rows.append((g2, ZERO))                                     # mu LN + LT >= 0
            if tm[i] == "slide+":
                rows.append((Wtn[i] + Wtt[i], -uT[i]))                  # uT'_i >= 0
            if tm[i] == "slide-":
                rows.append(([-v for v in Wtn[i] + Wtt[i]], uT[i]))     # uT'_i <= 0
        return rows

    cands = []  # (x, modes, indeterminate)
    for nm in itertools.product(NORMAL_MODES, repeat=n):
        for tm in itertools.product(TANG_MODES, repeat=n):
            A, b = [], []
            for i in range(n):
                if nm[i] == "closed":
                    A.append(Wnn[i] + Wnt[i])
                    b.append(-(uN[i] + off[i]))
                else:
                    A.append([ONE if j == i else ZERO for j in range(n)] + [ZERO] * n)
                    b.append(base[i])
            for i in range(n):
                if tm[i] == "stick":
                    A.append(Wtn[i] + Wtt[i])
                    b.append(-uT[i])
                else:
                    s = ONE if tm[i] == "slide+" else -ONE
                    row = [ZERO] * (2 * n)
                    row[n + i] = ONE
                    row[i] = s * mu[i]
                    A.append(row)
                    b.append(ZERO)
            sol = affine_solutions(A, b)
            if sol is None:
                continue
            x0, N = sol
            ineq = inequalities(tm)
            if not N:
                if all(sum((g * x for g, x in zip(gr, x0)), ZERO) >= h for gr, h in ineq):
                    cands.append((x0, tuple(zip(nm, tm)), False))
                continue
            k = len(N)
            G = [[sum((gr[j] * N[c][j] for j in range(2 * n)), ZERO) for c in range(k)] for gr, _ in ineq]
            H = [h - sum((gr[j] * x0[j] for j in range(2 * n)), ZERO) for gr, h in ineq]
            for z in polytope_vertices(G, H, k):
                x = [x0[j] + sum((N[c][j] * z[c] for c in range(k)), ZERO) for j in range(2 * n)]
                cands.append((x, tuple(zip(nm, tm)), True))
    # group by the velocities produced
    groups = []
    for x, modes, ind in cands:
        st = sc.initial_state()
        for i in range(n):
            sc.apply(st, sc.rows_n[i], x[i])
            sc.apply(st, sc.rows_t[i], x[n + i])
        key = ([tuple(r) for r in st], x[:n])  # same velocities and normal impulses
        for g in groups:
            if g["key"] == key:
                if x not in g["xs"]:
                    g["xs"].append(x)
                break
        else:
            groups.append({"key": key, "xs": [x], "modes": modes})
    out = []
    for g in groups:
        xs = g["xs"]
        x = [sum((v[j] for v in xs), ZERO) / len(xs) for j in range(2 * n)]
        LN, LT = x[:n], x[n:]
        uN1, uT1 = ends(LN, LT)
        out.append((LN, LT, g["modes"], uN1, uT1, len(xs) > 1))
    return out


def mode_names(sol, LN, uT1):
    """Describe a solution's modes from its values (a slide mode with uT' = 0 is a stick)."""
    out = []
    for i, (nm, tm) in enumerate(sol):
        if LN[i] == 0:
            out.append("no impulse")
        elif uT1[i] == 0:
            out.append("stick")
        else:
            out.append("slide +" if uT1[i] > 0 else "slide -")
    return out


def friction_newton_json(sc, u0, uT0):
    n = sc.n
    off = [sc.contacts[i].e * min(u0[i], ZERO) for i in range(n)]
    sols = phase_solve(sc, u0, uT0, [ZERO] * n, off)
    out = {"model": "simultaneous-newton",
           "formulation": ("one phase: lambda_N >= 0, uN+ + e .* min(u0, 0) >= 0 complementary; "
                           "Coulomb: |lambda_T| <= mu lambda_N, lambda_T = -mu lambda_N sign(uT+) if uT+ != 0"),
           "status": status_of(sols, False)}
    res = []
    for LN, LT, modes, uN1, uT1, ind in sols:
        res.append(sc.result(LN, LT, extra={"modes": mode_names(modes, LN, uT1),
                                            "tangential_split_indeterminate": ind}))
    if len(res) == 1:
        out.update(res[0])
    else:
        out["solutions"] = res
    return out


def friction_poisson(sc, u0, uT0):
    """Glocker's two-phase Poisson law with Coulomb friction (tangential restitution 0).

    Compression: phase_solve with base 0, offset 0 from the velocities before.  Expansion: from
    the velocities at the end of compression, base e .* LN_C (the Poisson impulse applied whatever
    happens, plus a free extra impulse wherever a contact would otherwise sink), offset 0;
    Coulomb's law in each phase bounds that phase's tangential impulse by mu times its normal
    impulse, with the slip direction at the phase's end.
    """
    n = sc.n
    e = [c.e for c in sc.contacts]
    comp = phase_solve(sc, u0, uT0, [ZERO] * n, [ZERO] * n)
    res = []
    for LNc, LTc, mc, uNc, uTc, indc in comp:
        base = [e[i] * LNc[i] for i in range(n)]
        exps = phase_solve(sc, uNc, uTc, base, [ZERO] * n)
        for LNe, LTe, me, uNe, uTe, inde in exps:
            res.append((LNc, LTc, mc, uNc, uTc, LNe, LTe, me, uNe, uTe, indc or inde))
    return res


def friction_poisson_json(sc, u0, uT0):
    n = sc.n
    res = friction_poisson(sc, u0, uT0)
    out = {"model": "simultaneous-poisson",
           "formulation": ("compression: LN_C >= 0, uN_C >= 0 complementary, Coulomb on (LT_C, uT_C); "
                           "expansion: LN_E = e .* LN_C + x, x >= 0, uN+ >= 0, x . uN+ = 0, Coulomb on "
                           "(LT_E, uT+) with |LT_E| <= mu LN_E; tangential restitution 0"),
           "status": status_of(distinct_states(sc, res), False)}
    sols = []
    for LNc, LTc, mc, uNc, uTc, LNe, LTe, me, uNe, uTe, ind in res:
        s_c = sc.after(LNc, LTc)
        extra = {"compression": {"normal_impulses": [qs(v) for v in LNc], "tangential_impulses": [qs(v) for v in LTc],
                                 "normal_velocity_end": [qs(v) for v in uNc],
                                 "tangential_velocity_end": [qs(v) for v in uTc],
                                 "modes": mode_names(mc, LNc, uTc),
                                 "energy_change": qs(ke_of(sc, s_c) - ke_of(sc, sc.initial_state()))},
                 "expansion": {"normal_impulses": [qs(v) for v in LNe], "tangential_impulses": [qs(v) for v in LTe],
                               "extra_impulses": [qs(LNe[i] - sc.contacts[i].e * LNc[i]) for i in range(n)],
                               "modes": mode_names(me, LNe, uTe)},
                 "tangential_split_indeterminate": ind}
        sols.append(sc.result([a + b for a, b in zip(LNc, LNe)], [a + b for a, b in zip(LTc, LTe)], extra=extra))
    if len(sols) == 1:
        out.update(sols[0])
    else:
        out["solutions"] = sols
    return out


def distinct_states(sc, res):
    """The distinct velocity states of a list of Poisson results (for the status)."""
    keys = []
    for r in res:
        st = sc.after([a + b for a, b in zip(r[0], r[5])], [a + b for a, b in zip(r[1], r[6])])
        if st not in keys:
            keys.append(st)
    return keys


def ke_of(sc, s):
    return sum((b.mass * (s[i][0] ** 2 + s[i][1] ** 2) / 2 + b.inertia * s[i][2] ** 2 / 2
                for i, b in enumerate(sc.bodies) if not b.fixed), ZERO)


# ----------------------------------------------------------------------------------------------
# Driver
# ----------------------------------------------------------------------------------------------

def scene_json(sc: Scene):
    bodies = []
    for b in sc.bodies:
        if b.fixed:
            bodies.append({"name": b.name, "fixed": True})
        else:
            bodies.append({"name": b.name, "mass": qs(b.mass), "inertia": qs(b.inertia),
                           "position": [qs(v) for v in b.position], "velocity": [qs(v) for v in b.velocity],
                           "omega": qs(b.omega)})
    contacts = []
    for c in sc.contacts:
        contacts.append({"contact": c.index, "bodies": list(c.names), "point": [qs(v) for v in c.point],
                         "normal": [qs(v) for v in c.normal], "tangent": [qs(v) for v in c.tangent],
                         "e": qs(c.e), "mu": qs(c.mu)})
    return {"file": sc.source, "title": sc.title, "bodies": bodies, "contacts": contacts}


# The most contacts whose every order the sequential models run.
MAX_ORDERED = 6


def analyse(sc: Scene, models=("simultaneous-newton", "simultaneous-poisson", "sequential", "sequential-priority", "pgs")):
    W = sc.delassus(sc.rows_n, sc.rows_n)
    s0 = sc.initial_state()
    u0 = sc.un(s0)
    if not any(u < 0 for u in u0):
        raise ValueError("no contact approaches")
    out = {"oracle": "tests/oracles/multi_contact.py", "scene": scene_json(sc),
           "geometry": sc.geometry_checks(),
           "delassus_W": [[qs(x) for x in row] for row in W],
           "normal_velocity_before": [qs(u) for u in u0],
           "contact_state_before": ["approaching" if u < 0 else "touching" if u == 0 else "separating" for u in u0],
           "conventions": ("impulse on A = lambda n (+ lambda_t t), on B the opposite; normal velocities "
                           "and impulses in the file's scaling of n; fixed bodies omitted")}
    ms = []
    if sc.friction:
        uT0 = sc.ut(s0)
        out["tangential_velocity_before"] = [qs(u) for u in uT0]
        out["delassus_full"] = {
            "nn": [[qs(x) for x in r] for r in W],
            "nt": [[qs(x) for x in r] for r in sc.delassus(sc.rows_n, sc.rows_t)],
            "tt": [[qs(x) for x in r] for r in sc.delassus(sc.rows_t, sc.rows_t)]}
        if "simultaneous-newton" in models:
            ms.append(friction_newton_json(sc, u0, uT0))
        if "simultaneous-poisson" in models:
            ms.append(friction_poisson_json(sc, u0, uT0))
        out["not_computed"] = ("sequential and pgs: this oracle runs them frictionless only "
                               "(a scene with mu > 0 gets the frictional simultaneous laws)")
    else:
        if "simultaneous-newton" in models:
            ms.append(model_newton_json(sc, W, u0))
        if "simultaneous-poisson" in models:
            ms.append(model_poisson_json(sc, W, u0))
        # Every order is n! runs: like rodimpact (MAX_ORDERED), at most 6 contacts.
        if sc.n > MAX_ORDERED and any(m.startswith("sequential") for m in models):
            out["not_computed"] = (f"sequential in every order: {sc.n} contacts, more than "
                                   f"{MAX_ORDERED} ({sc.n}! orders)")
        else:
            if "sequential" in models:
                ms.append(model_sequential_json(sc, W, u0))
            if "sequential-priority" in models:
                ms.append(model_sequential_priority_json(sc, W, u0))
        if "pgs" in models:
            ms.extend(model_pgs_json(sc, W, u0))
    out["models"] = ms
    return out


def load(path) -> Scene:
    p = Path(path)
    with open(p, "rb") as f:
        data = tomllib.load(f)
    try:
        src = str(p.resolve().relative_to(Path(__file__).resolve().parents[2]))
    except ValueError:
        src = str(p)
    return Scene(data, src)


def main(argv):
    root = Path(__file__).resolve().parents[2]
    if argv[1:2] == ["--write-fixtures"]:
        outdir = root / "tests" / "data" / "impacts"
        outdir.mkdir(parents=True, exist_ok=True)
        for p in sorted((root / "examples" / "impacts").glob("*.toml")):
            sc = load(p)
            if sc.n < 2:
                continue  # one contact: planar_impact.py writes its fixture
            res = analyse(sc)
            (outdir / (p.stem + ".json")).write_text(json.dumps(res, indent=1) + "\n")
            print(f"wrote {outdir / (p.stem + '.json')}", file=sys.stderr)
        return 0
    if len(argv) < 2:
        print(__doc__.split("\n\n")[0], file=sys.stderr)
        print("usage: multi_contact.py SCENE.toml [--model simultaneous-newton|simultaneous-poisson|sequential|"
              "sequential-priority|pgs]"
              " | --write-fixtures", file=sys.stderr)
        return 2
    models = ("simultaneous-newton", "simultaneous-poisson", "sequential", "sequential-priority", "pgs")
    if "--model" in argv:
        models = (argv[argv.index("--model") + 1],)
    print(json.dumps(analyse(load(argv[1]), models), indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
