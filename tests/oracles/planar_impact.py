#!/usr/bin/env python3
"""Exact oracle for one planar rigid-body impact with Coulomb friction.

Independent reference for rodimpact's `impact` command (DESIGN section 6).  Pure Python and
`fractions.Fraction`; no floating point is used anywhere in a computed answer.  The one
irrational number that can appear (the end of Stronge's energetic restitution) is carried
exactly as x + y*sqrt(d) by the small class `QSqrt` below.

Usage:
    python3 tests/oracles/planar_impact.py SCENE.toml            # JSON on stdout
    python3 tests/oracles/planar_impact.py SCENE.toml -o OUT.json

DERIVATION (the reference; every formula the code uses is here)
=================================================================

Bodies.  A free body has mass m > 0, moment of inertia I >= 0 about its centre of mass c,
velocity v of c and spin w (counterclockwise positive).  The material point at x moves with
    v(x) = v + w (x - c)^perp,     where (dx, dy)^perp = (-dy, dx)
(this is w z-hat cross (x - c)).  A fixed body never moves.  A pinned body (one pin at q) turns
about q: v(x) = w (x - q)^perp; its centre moves with v = w (c - q)^perp, and it has the moment of
inertia about the pin I_q = I + m |c - q|^2.  The pin supplies whatever impulse holds q still.

Impulse response.  An impulse P applied at the point x of a free body changes
    dv = P/m,   dw = (x - c) cross P / I,     a cross b = a_x b_y - a_y b_x,
so the velocity of the material point x changes by
    d v(x) = P/m + (x - c)^perp ((x - c)^perp . P)/I = K_body P,
    K_body = (1/m) Id + r^perp (r^perp)^T / I,     r = x - c,
because (x - c) cross P = (x - c)^perp . P.  (A point mass, I = 0, must be struck at its centre,
r = 0, and has K = Id/m.)  For a pinned body, angular momentum about the pin gives
dw = (x - q) cross P / I_q, hence K_body = s^perp (s^perp)^T / I_q with s = x - q.  A fixed body
has K = 0.  The contact impulse is +P on A and -P on B, and the relative velocity
u = v_A(x) - v_B(x) changes by (K_A + K_B) P = K P.  K is symmetric positive semidefinite.

Contact frame without square roots.  The normal n (from B into A) is not normalised; the tangent
is t = n^perp = (-n_y, n_x), so |t| = |n| and n . t = 0.  Write P = lam n + tau t and
u_n = u . n, u_t = u . t.  Then (u_n, u_t) changes by W (lam, tau) with
    W = [[n.K.n, n.K.t], [t.K.n, t.K.t]] = [[W_nn, W_nt], [W_nt, W_tt]].
The true normal impulse is lam |n| and the true normal velocity u_n/|n|, so
lam * u_n, the Coulomb cone |tau| <= mu lam and every sign are the true ones.  Power:
u . dP = u_n dlam + u_t dtau exactly, so works need no |n| either.

Routh's process in lam.  The impact is followed with the normal coefficient lam as the
"time"; (u_n, u_t) is piecewise linear in lam:
  * slide with slip sign s = sign(u_t) (s = +1 "slide+", -1 "slide-"): dtau/dlam = -s mu
    (friction on A opposes A's slip over B), so
        du_n/dlam = W_nn - s mu W_nt,   du_t/dlam = W_nt - s mu W_tt;
  * stick (u_t = 0 held): dtau/dlam = -W_nt/W_tt (the rate that keeps du_t/dlam = 0),
    admissible iff |W_nt| <= mu W_tt; then du_n/dlam = W_nn - W_nt^2/W_tt (a Schur
    complement, >= 0).
  When the slip reaches 0 (or is 0 at the start): stick if admissible; otherwise slide with
  s = sign(W_nt), which is the only sign s with sign(W_nt - s mu W_tt) = s; after a stop it is
  the reverse of the earlier slip.  Sticking, once reached, lasts (the rate is constant and
  admissible); a slip that does not shrink never stops.  So the path has at most 2 phases.
  (Degenerate W_tt = 0, possible only with pins: then W_nt = 0, tau does not move the contact
  and the stick rate is taken as 0.)
  The path does not depend on the law; each law only chooses where it ends:
  * compression ends at lam_c, the first lam with u_n = 0;
  * newton: lam_f is the first lam >= lam_c with u_n = -e u_n(0);
  * poisson: lam_f = (1 + e) lam_c;
  * energetic (Stronge): with Wn(a, b) = integral_a^b u_n dlam (the normal impulse's work),
    lam_f is the first lam >= lam_c with Wn(lam_c, lam_f) = -e^2 Wn(0, lam_c).  Inside a phase
    u_n = a + b x (x = lam - start), so b x^2/2 + a x = R and x = (-a + sqrt(a^2 + 2 b R))/b
    (b != 0; the smaller non-negative root, for either sign of b), x = R/a when b = 0.  All
    break points are rational (they solve linear equations in rational data), so only
    lam_f can be irrational and it lies in Q(sqrt d).
  If u_n stops increasing while still negative (a slope <= 0 for ever), no finite impulse ends
  the compression: the scene is refused ("jam").

State after.  P = lam_f n + tau_f t; each body takes +P (A) or -P (B) through the formulas
above.  Kinetic energy  E = sum m |v|^2/2 + I w^2/2 (a pinned body's v is w (c - q)^perp, so this
is I_q w^2/2).  Its change equals the work  integral u . dP = Wn(0, lam_f) + integral u_t dtau;
the friction part is <= 0, and Newton's law can make the normal part positive when W_nt != 0 and
the slip stops or reverses (Kane and Levinson; Stronge 1991).

Exact number strings (inputs): "-3/7", "0.25", "1.5e-3", "2", "1.5e-3/7" (a decimal over a
decimal); TOML integers and TOML floats (read from their text, never through a binary float).
Unit suffixes are refused.

Output numbers: a rational as "p/q" in lowest terms ("p" when q = 1); an element of Q(sqrt d)
with irrational part as {"x": "p/q", "y": "p/q", "d": "n"} (d square-free, d > 1).
"""

import json
import math
import re
import sys
import tomllib
from fractions import Fraction

LAWS = ("newton", "poisson", "energetic")


class SceneError(ValueError):
    """The scene is refused (bad input, no approach, jam)."""


# --------------------------------------------------------------------------------------------
# Exact numbers
# --------------------------------------------------------------------------------------------

_DEC = r"(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_NUM_RE = re.compile(rf"^([+-]?)({_DEC})(?:/({_DEC}))?$")


def _decimal(text):
    """Exact value of an unsigned decimal like '1.5e-3' (no float is ever made)."""
    m = re.fullmatch(r"(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?", text)
    whole, frac, exp = m.group(1) or "", m.group(2) or "", int(m.group(3) or 0)
    digits = int((whole + frac) or "0")
    scale = exp - len(frac)
    return Fraction(digits * 10**scale) if scale >= 0 else Fraction(digits, 10**-scale)


def parse_number(value, what="number"):
    """Parse an input number exactly into a Fraction."""
    if isinstance(value, bool):
        raise SceneError(f"{what}: expected a number, got {value!r}")
    if isinstance(value, int):
        return Fraction(value)
    if isinstance(value, Fraction):
        return value
    if not isinstance(value, str):
        raise SceneError(f"{what}: expected a number as a string, got {value!r}")
    m = _NUM_RE.match(value.strip())
    if not m:
        raise SceneError(f"{what}: not an exact number (units are not accepted here): {value!r}")
    num = _decimal(m.group(2))
    if m.group(3) is not None:
        den = _decimal(m.group(3))
        if den == 0:
            raise SceneError(f"{what}: zero denominator in {value!r}")
        num = num / den
    return -num if m.group(1) == "-" else num


def _squarefree(n):
    """Return (s, d) with n = s^2 d, d square-free (n > 0 an integer).

    Trial division by every k up to the cube root of what is left; the cofactor then has at most
    two prime factors, so it is either a square or square-free.  Complete for any n."""
    s, d, k = 1, 1, 2
    while k * k * k <= n:
        if n % k == 0:
            e = 0
            while n % k == 0:
                n //= k
                e += 1
            s *= k ** (e // 2)
            if e % 2:
                d *= k
        k += 1 if k == 2 else 2
    r = math.isqrt(n)
    if r * r == n:
        s *= r
    else:
        d *= n
    return s, d


class QSqrt:
    """x + y*sqrt(d), x and y rational, d > 1 an integer that is not a perfect square.

    All numbers meeting in one computation share the same d (here: one discriminant), so
    + - * / stay in the field.  d need not be square-free during arithmetic; `canonical`
    rewrites it square-free for output.  Results with y == 0 collapse to Fraction."""

    __slots__ = ("x", "y", "d")

    def __init__(self, x, y, d):
        self.x, self.y, self.d = Fraction(x), Fraction(y), int(d)

    @staticmethod
    def make(x, y, d):
        return Fraction(x) if y == 0 else QSqrt(x, y, d)

    @staticmethod
    def sqrt(q):
        """Exact square root of a rational q >= 0: a Fraction if q is a square, else a QSqrt."""
        q = Fraction(q)
        if q < 0:
            raise ValueError("square root of a negative number")
        # sqrt(p/r) = sqrt(p r)/r
        pr = q.numerator * q.denominator
        r = math.isqrt(pr)
        if r * r == pr:
            return Fraction(r, q.denominator)
        return QSqrt(0, Fraction(1, q.denominator), pr)   # made square-free only for output

    def _coerce(self, o):
        if isinstance(o, QSqrt):
            if o.d != self.d:
                raise ValueError("QSqrt with different d")
            return o.x, o.y
        return Fraction(o), Fraction(0)

    def __add__(self, o):
        a, b = self._coerce(o)
        return QSqrt.make(self.x + a, self.y + b, self.d)

    __radd__ = __add__

    def __neg__(self):
        return QSqrt(-self.x, -self.y, self.d)

    def __sub__(self, o):
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    def __mul__(self, o):
        a, b = self._coerce(o)
        return QSqrt.make(self.x * a + self.y * b * self.d, self.x * b + self.y * a, self.d)

    __rmul__ = __mul__

    def __truediv__(self, o):
        a, b = self._coerce(o)
        den = a * a - b * b * self.d          # (a + b r)(a - b r), nonzero as d is no square
        return self * QSqrt.make(a / den, -b / den, self.d)

    def __rtruediv__(self, o):
        den = self.x * self.x - self.y * self.y * self.d
        return QSqrt.make(self.x / den, -self.y / den, self.d) * o

    def sign(self):
        """Exact sign of x + y sqrt(d)."""
        sx = (self.x > 0) - (self.x < 0)
        sy = (self.y > 0) - (self.y < 0)
        if sx == sy or sy == 0:
            return sx
        if sx == 0:
            return sy
        # opposite signs: compare x^2 with y^2 d
        c = self.x * self.x - self.y * self.y * self.d
        return sx if c > 0 else (sy if c < 0 else 0)

    def __lt__(self, o):
        return sign(self - o) < 0

    def __le__(self, o):
        return sign(self - o) <= 0

    def __gt__(self, o):
        return sign(self - o) > 0

    def __ge__(self, o):
        return sign(self - o) >= 0

    def __eq__(self, o):
        return sign(self - o) == 0

    def __hash__(self):
        return hash((self.x, self.y, self.d))

    def canonical(self):
        s, d = _squarefree(self.d)
        return QSqrt.make(self.x, self.y * s, d)

    def __float__(self):
        return float(self.x) + float(self.y) * math.sqrt(self.d)

    def __repr__(self):
        return f"({self.x} + {self.y}*sqrt({self.d}))"


def sign(v):
    if isinstance(v, QSqrt):
        return v.sign()
    return (v > 0) - (v < 0)


def qstr(v):
    """JSON form of an exact number."""
    if isinstance(v, QSqrt):
        v = v.canonical()
    if isinstance(v, QSqrt):
        return {"x": qstr(v.x), "y": qstr(v.y), "d": str(v.d)}
    v = Fraction(v)
    return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"


# --------------------------------------------------------------------------------------------
# Planar vectors (tuples of exact numbers)
# --------------------------------------------------------------------------------------------

def add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def scale(k, a):
    return (k * a[0], k * a[1])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def perp(a):
    """A quarter turn counterclockwise: (x, y) -> (-y, x)."""
    return (-a[1], a[0])


# --------------------------------------------------------------------------------------------
# Scene
# --------------------------------------------------------------------------------------------

class Body:
    def __init__(self, table):
        self.name = table.get("name")
        if not isinstance(self.name, str) or not self.name:
            raise SceneError("every [[body]] needs a name")
        self.fixed = bool(table.get("fixed", False))
        self.shape = table.get("shape")
        self.pin = None
        self.position = self._vec(table, "position", ("0", "0"))
        self.axis = self._vec(table, "axis", ("1", "0"))   # a rod's length / box's width side
        if self.axis == (0, 0):
            raise SceneError(f"body {self.name}: axis must not be zero")
        if self.fixed:
            self.mass = self.inertia = None
            self.velocity, self.omega = (Fraction(0), Fraction(0)), Fraction(0)
            for key in ("velocity", "omega", "mass", "inertia"):
                if key in table:
                    raise SceneError(f"body {self.name}: a fixed body takes no {key}")
            self._shape_inertia(table)        # reads the outline's dimensions only
            return
        if "mass" not in table:
            raise SceneError(f"body {self.name}: mass must be given")
        self.mass = parse_number(table["mass"], f"body {self.name}: mass")
        if self.mass <= 0:
            raise SceneError(f"body {self.name}: mass must be given and > 0")
        self.velocity = self._vec(table, "velocity", ("0", "0"))
        self.omega = parse_number(table.get("omega", "0"), f"body {self.name}: omega")
        shape_I = self._shape_inertia(table)
        if "inertia" in table:
            self.inertia = parse_number(table["inertia"], f"body {self.name}: inertia")
            if shape_I is not None and shape_I != self.inertia:
                raise SceneError(f"body {self.name}: inertia {self.inertia} disagrees with the "
                                 f"shape's {shape_I}")
        elif shape_I is not None:
            self.inertia = shape_I
        else:
            raise SceneError(f"body {self.name}: give inertia or a shape")
        if self.inertia < 0:
            raise SceneError(f"body {self.name}: inertia must be >= 0")

    def _vec(self, table, key, default):
        raw = table.get(key, default)
        if not isinstance(raw, list) and not isinstance(raw, tuple) or len(raw) != 2:
            raise SceneError(f"body {self.name}: {key} must be [x, y]")
        return tuple(parse_number(c, f"body {self.name}: {key}") for c in raw)

    def _shape_inertia(self, table):
        """I about the centre from the shape: rod m L^2/12, disc m r^2/2, box m(w^2+h^2)/12,
        point 0."""
        m, kind = (self.mass if self.mass is not None else Fraction(0)), self.shape
        if kind is None:
            return None
        g = lambda k: parse_number(table[k], f"body {self.name}: {k}") if k in table else None
        if kind == "rod":
            self.length = g("length")
            if self.length is None or self.length <= 0:
                raise SceneError(f"body {self.name}: a rod needs length > 0")
            return m * self.length**2 / 12
        if kind == "disc":
            self.radius = g("radius")
            if self.radius is None or self.radius <= 0:
                raise SceneError(f"body {self.name}: a disc needs radius > 0")
            return m * self.radius**2 / 2
        if kind == "box":
            self.width, self.height = g("width"), g("height")
            if not self.width or not self.height or self.width <= 0 or self.height <= 0:
                raise SceneError(f"body {self.name}: a box needs width and height > 0")
            return m * (self.width**2 + self.height**2) / 12
        if kind == "point":
            return Fraction(0)
        raise SceneError(f"body {self.name}: unknown shape {kind!r}")

    # --- kinematics -------------------------------------------------------------------------
    def point_velocity(self, x):
        if self.fixed:
            return (Fraction(0), Fraction(0))
        return add(self.velocity, scale(self.omega, perp(sub(x, self.position))))

    def compliance(self, x):
        """K_body (2x2, as ((a, b), (c, d))) with d v(x) = K_body P for an impulse P at x."""
        z = Fraction(0)
        if self.fixed:
            return ((z, z), (z, z))
        if self.pin is not None:
            s = perp(sub(x, self.pin))
            Iq = self.inertia + self.mass * dot(sub(self.position, self.pin),
                                                sub(self.position, self.pin))
            if Iq == 0:
                return ((z, z), (z, z))
            return ((s[0] * s[0] / Iq, s[0] * s[1] / Iq), (s[1] * s[0] / Iq, s[1] * s[1] / Iq))
        r = perp(sub(x, self.position))
        k = 1 / self.mass
        if self.inertia == 0:
            if r != (0, 0):
                raise SceneError(f"body {self.name}: a body without inertia must be struck at "
                                 f"its centre of mass")
            return ((k, z), (z, k))
        I = self.inertia
        return ((k + r[0] * r[0] / I, r[0] * r[1] / I), (r[1] * r[0] / I, k + r[1] * r[1] / I))

    def apply(self, P, x):
        """(velocity, omega) after the impulse P at x (pin reaction included)."""
        if self.fixed:
            return self.velocity, self.omega
        if self.pin is not None:
            Iq = self.inertia + self.mass * dot(sub(self.position, self.pin),
                                                sub(self.position, self.pin))
            if Iq == 0:
                return self.velocity, self.omega
            w = self.omega + cross(sub(x, self.pin), P) / Iq
            return scale(w, perp(sub(self.position, self.pin))), w
        v = add(self.velocity, scale(1 / self.mass, P))
        if self.inertia == 0:
            return v, self.omega
        return v, self.omega + cross(sub(x, self.position), P) / self.inertia

    def energy(self, v, w):
        if self.fixed:
            return Fraction(0)
        return self.mass * dot(v, v) / 2 + self.inertia * w * w / 2


def on_shape(body, x, n_out):
    """Check that x lies on the body's outline.  n_out: normal pointing away from this body
    (used only for a fixed body without shape: a half-plane whose edge passes through its
    position, perpendicular to n_out)."""
    r = sub(x, body.position)
    kind = body.shape
    if body.fixed and kind is None:
        return dot(r, n_out) == 0
    if kind is None:
        return True  # no outline given: nothing to check
    a = body.axis
    aa = dot(a, a)
    if kind == "point":
        return r == (0, 0)
    if kind == "disc":
        return dot(r, r) == body.radius**2
    if kind == "rod":  # the segment c + s a/|a|, |s| <= L/2
        return cross(a, r) == 0 and 4 * dot(r, a) ** 2 <= body.length**2 * aa
    if kind == "box":  # local coordinates xi = r.a/|a|, eta = r.a^perp/|a|; compare squares
        xi2, eta2 = dot(r, a) ** 2, dot(r, perp(a)) ** 2
        W2, H2 = body.width**2 * aa / 4, body.height**2 * aa / 4
        return (xi2 <= W2 and eta2 <= H2) and (xi2 == W2 or eta2 == H2)
    return False


def check_no_overlap_with_wall(body, wall, n_out):
    """The moving body must not cross the wall's edge line: for every point y of the body,
    (y - wall.position) . n_out >= 0 (n_out points from the wall towards the body).  Done with
    squares so that a non-Pythagorean axis needs no square root."""
    h = dot(sub(body.position, wall.position), n_out)   # centre's (scaled) height over the wall
    if body.shape in (None, "point"):
        return h >= 0
    if body.shape == "disc":      # h >= r |n|
        return h >= 0 and h * h >= body.radius**2 * dot(n_out, n_out)
    a, aa = body.axis, dot(body.axis, body.axis)
    if body.shape == "rod":       # h >= (L/2)|a.n|/|a|
        return h >= 0 and 4 * h * h * aa >= body.length**2 * dot(a, n_out) ** 2
    if body.shape == "box":       # h >= (w/2)|a.n|/|a| + (h/2)|a^perp.n|/|a|
        p = body.width * abs(dot(a, n_out)) / 2
        q = body.height * abs(dot(perp(a), n_out)) / 2
        return h >= 0 and h * h * aa >= (p + q) ** 2
    return True


class Scene:
    def __init__(self, doc):
        self.title = doc.get("title")
        bodies = doc.get("body", [])
        self.bodies = [Body(t) for t in bodies]
        names = [b.name for b in self.bodies]
        if len(set(names)) != len(names):
            raise SceneError("body names must be distinct")
        self.by_name = {b.name: b for b in self.bodies}
        for pin in doc.get("pin", []):
            b = self.by_name.get(pin.get("body"))
            if b is None or b.fixed:
                raise SceneError(f"pin: unknown or fixed body {pin.get('body')!r}")
            if b.pin is not None:
                raise SceneError(f"body {b.name}: at most one pin (two pins fix it)")
            q = tuple(parse_number(c, "pin point") for c in pin["point"])
            b.pin = q
            if b.point_velocity(q) != (0, 0):
                raise SceneError(f"body {b.name}: the pinned point must be at rest before the "
                                 f"impact (v + omega (q - c)^perp = 0)")
            if b.shape is not None and not on_shape_or_inside(b, q):
                raise SceneError(f"body {b.name}: the pin is not on the body")
        contacts = doc.get("contact", [])
        if len(contacts) != 1:
            raise SceneError("this oracle takes exactly one [[contact]]")
        c = contacts[0]
        if len(c.get("bodies", [])) != 2:
            raise SceneError("contact: bodies = [A, B]")
        try:
            self.A, self.B = (self.by_name[n] for n in c["bodies"])
        except KeyError as exc:
            raise SceneError(f"contact: unknown body {exc}") from None
        if self.A is self.B:
            raise SceneError("contact: A and B must differ")
        if self.A.fixed and self.B.fixed:
            raise SceneError("contact: both bodies are fixed")
        self.point = tuple(parse_number(v, "contact point") for v in c["point"])
        self.n = tuple(parse_number(v, "contact normal") for v in c["normal"])
        if self.n == (0, 0):
            raise SceneError("contact: normal must not be zero")
        self.t = perp(self.n)
        self.e = parse_number(c.get("e", "1"), "contact e")
        self.mu = parse_number(c.get("mu", "0"), "contact mu")
        if not 0 <= self.e <= 1:
            raise SceneError("contact: 0 <= e <= 1")
        if self.mu < 0:
            raise SceneError("contact: mu >= 0")
        # geometry: the point on both outlines; a moving body does not cross a fixed wall
        neg = scale(-1, self.n)
        if not on_shape(self.A, self.point, self.n if self.A.fixed else neg):
            raise SceneError(f"contact point is not on body {self.A.name}'s outline")
        if not on_shape(self.B, self.point, self.n):
            raise SceneError(f"contact point is not on body {self.B.name}'s outline")
        if self.B.fixed and self.B.shape is None and not check_no_overlap_with_wall(
                self.A, self.B, self.n):
            raise SceneError(f"body {self.A.name} crosses the fixed body {self.B.name}")
        if self.A.fixed and self.A.shape is None and not check_no_overlap_with_wall(
                self.B, self.A, neg):
            raise SceneError(f"body {self.B.name} crosses the fixed body {self.A.name}")

    def moving(self):
        return [b for b in self.bodies if not b.fixed]


def on_shape_or_inside(body, q):
    r = sub(q, body.position)
    if body.shape == "point":
        return r == (0, 0)
    if body.shape == "disc":
        return dot(r, r) <= body.radius**2
    a, aa = body.axis, dot(body.axis, body.axis)
    if body.shape == "rod":
        return cross(a, r) == 0 and 4 * dot(r, a) ** 2 <= body.length**2 * aa
    if body.shape == "box":
        return 4 * dot(r, a) ** 2 <= body.width**2 * aa and \
            4 * dot(r, perp(a)) ** 2 <= body.height**2 * aa
    return True


# --------------------------------------------------------------------------------------------
# Routh's process
# --------------------------------------------------------------------------------------------

class Phase:
    """One linear piece of the path: for lam in [start, end] (end None = for ever),
    u_n = un0 + bn (lam - start), u_t = ut0 + bt (lam - start), tau = tau0 + rt (lam - start)."""

    def __init__(self, mode, start, un0, ut0, tau0, bn, bt, rt):
        self.mode, self.start, self.end = mode, start, None
        self.un0, self.ut0, self.tau0 = un0, ut0, tau0
        self.bn, self.bt, self.rt = bn, bt, rt

    def at(self, lam):
        x = lam - self.start
        return self.un0 + self.bn * x, self.ut0 + self.bt * x, self.tau0 + self.rt * x

    def work_n(self, a, b):
        """integral of u_n dlam over [a, b] inside this phase (exact: trapezoid of a line)."""
        ua, _, _ = self.at(a)
        ub, _, _ = self.at(b)
        return (ua + ub) * (b - a) / 2

    def work_t(self, a, b):
        """integral of u_t dtau = rt * integral of u_t dlam over [a, b]."""
        _, ua, _ = self.at(a)
        _, ub, _ = self.at(b)
        return self.rt * (ua + ub) * (b - a) / 2


def routh_path(Wnn, Wnt, Wtt, un0, ut0, mu):
    """The whole path in lam (at most 2 phases; the last one open-ended)."""
    def slide(s, start, un, ut, tau):
        return Phase("slide+" if s > 0 else "slide-", start, un, ut, tau,
                     Wnn - s * mu * Wnt, Wnt - s * mu * Wtt, -s * mu)

    def from_rest(start, un, tau):
        """u_t = 0: stick if the cone admits the holding rate, else slide with sign(W_nt)."""
        if abs(Wnt) <= mu * Wtt or Wtt == 0:
            rate = -Wnt / Wtt if Wtt != 0 else Fraction(0)
            bn = Wnn - Wnt * Wnt / Wtt if Wtt != 0 else Wnn
            return Phase("stick", start, un, Fraction(0), tau, bn, Fraction(0), rate)
        return slide(sign(Wnt), start, un, Fraction(0), tau)

    zero = Fraction(0)
    if ut0 == 0:
        return [from_rest(zero, un0, zero)]
    s = sign(ut0)
    first = slide(s, zero, un0, ut0, zero)
    if sign(first.bt) != -s:           # the slip does not shrink: it never stops
        return [first]
    stop = -ut0 / first.bt             # lam where u_t = 0
    first.end = stop
    un, _, tau = first.at(stop)
    return [first, from_rest(stop, un, tau)]


def first_crossing(path, lo, target):
    """First lam >= lo with u_n(lam) = target (u_n is continuous), or None."""
    for ph in path:
        a = max(ph.start, lo)
        if ph.end is not None and a > ph.end:
            continue
        ua, _, _ = ph.at(a)
        if ua == target:
            return a
        if ph.bn != 0:
            x = ph.start + (target - ph.un0) / ph.bn
            if x >= a and (ph.end is None or x <= ph.end):
                return x
    return None


def energetic_end(path, lam_c, R):
    """First lam >= lam_c with integral_{lam_c}^{lam} u_n = R (R >= 0)."""
    if R == 0:
        return lam_c
    for ph in path:
        a = max(ph.start, lam_c)
        if ph.end is not None and a > ph.end:
            continue
        ua, _, _ = ph.at(a)
        b = ph.bn
        # solve b x^2/2 + ua x = R for the smallest x >= 0
        if b == 0:
            x = R / ua if ua > 0 else None
        else:
            D = ua * ua + 2 * b * R
            x = None if D < 0 else (QSqrt.sqrt(D) - ua) / b
            if x is not None and sign(x) < 0:
                x = None
        if x is not None and (ph.end is None or x <= ph.end - a):
            return a + x
        if ph.end is None:
            return None
        R = R - ph.work_n(a, ph.end)
    return None


def phase_at(path, lam):
    for ph in path:
        if ph.end is None or lam <= ph.end:
            return ph
    return path[-1]


# --------------------------------------------------------------------------------------------
# Solve
# --------------------------------------------------------------------------------------------

def solve(scene, fmt=None):
    """The three laws' answers as a JSON-ready dict.  fmt formats each exact number (default
    qstr; pass `lambda v: v` to keep Fractions and QSqrts, as the sweep does)."""
    fmt = fmt or qstr
    A, B, x, n, t, mu, e = scene.A, scene.B, scene.point, scene.n, scene.t, scene.mu, scene.e
    u = sub(A.point_velocity(x), B.point_velocity(x))
    un0, ut0 = dot(u, n), dot(u, t)
    if un0 >= 0:
        raise SceneError(f"no approach: u.n = {un0} >= 0")
    KA, KB = A.compliance(x), B.compliance(x)
    K = tuple(tuple(KA[i][j] + KB[i][j] for j in range(2)) for i in range(2))
    Kv = lambda v: (K[0][0] * v[0] + K[0][1] * v[1], K[1][0] * v[0] + K[1][1] * v[1])
    Wnn, Wnt, Wtt = dot(n, Kv(n)), dot(n, Kv(t)), dot(t, Kv(t))
    assert Wnt == dot(t, Kv(n))
    path = routh_path(Wnn, Wnt, Wtt, un0, ut0, mu)

    lam_c = first_crossing(path, Fraction(0), Fraction(0))
    if lam_c is None:
        raise SceneError("jam: u_n never reaches 0 (no finite impulse ends the compression)")
    Wc = sum((ph.work_n(ph.start, min(ph.end, lam_c) if ph.end is not None else lam_c)
              for ph in path if ph.start < lam_c), Fraction(0))

    E0 = sum((b.energy(b.velocity, b.omega) for b in scene.moving()), Fraction(0))
    out = {
        "oracle": "tests/oracles/planar_impact.py",
        "title": scene.title,
        "contact": {
            "bodies": [A.name, B.name], "point": [fmt(c) for c in x],
            "normal": [fmt(c) for c in n], "tangent": [fmt(c) for c in t],
            "e": fmt(e), "mu": fmt(mu),
            "W": {"nn": fmt(Wnn), "nt": fmt(Wnt), "tt": fmt(Wtt)},
            "stick_admissible": bool(abs(Wnt) <= mu * Wtt),
        },
        "path": [{"mode": p.mode, "from": fmt(p.start),
                  "to": None if p.end is None else fmt(p.end)} for p in path],
        "lam_c": fmt(lam_c),
        "laws": [],
    }

    for law in LAWS:
        if law == "newton":
            lam_f = first_crossing(path, lam_c, -e * un0)
        elif law == "poisson":
            lam_f = (1 + e) * lam_c
        else:
            lam_f = energetic_end(path, lam_c, -e * e * Wc)
        if lam_f is None:
            raise SceneError(f"{law}: the restitution never ends")
        ph = phase_at(path, lam_f)
        unf, utf, tauf = ph.at(lam_f)
        P = add(scale(lam_f, n), scale(tauf, t))
        bodies, after = {}, {}
        for b in scene.moving():
            Pb = P if b is A else (scale(-1, P) if b is B else (0, 0))
            v, w = b.apply(Pb, x) if b in (A, B) else (b.velocity, b.omega)
            after[b.name] = (v, w)
            bodies[b.name] = {"velocity": [fmt(c) for c in v], "omega": fmt(w)}
        # the contact velocity after, recomputed from the bodies (consistency with the path)
        def pv(b):
            if b.fixed:
                return (0, 0)
            v, w = after[b.name]
            c = b.position
            return add(v, scale(w, perp(sub(x, c))))
        uf = sub(pv(A), pv(B))
        assert dot(uf, n) == unf and dot(uf, t) == utf, "path and bodies disagree"
        E1 = sum((b.energy(*after[b.name]) for b in scene.moving()), Fraction(0))
        # works along the path, split at lam_c
        wn_c = wn_r = wt = Fraction(0)
        for p in path:
            hi = lam_f if p.end is None else min(p.end, lam_f)
            if p.start >= lam_f:
                continue
            lo = p.start
            wt = wt + p.work_t(lo, hi)
            if lo < lam_c:
                wn_c = wn_c + p.work_n(lo, min(hi, lam_c))
            if hi > lam_c:
                wn_r = wn_r + p.work_n(max(lo, lam_c), hi)
        assert E1 - E0 == wn_c + wn_r + wt, "energy change is not the work"
        pins = {}
        for b in scene.moving():
            if b.pin is not None:
                v, _ = after[b.name]
                Pb = P if b is A else (scale(-1, P) if b is B else (0, 0))
                pins[b.name] = [fmt(c) for c in sub(scale(b.mass, sub(v, b.velocity)), Pb)]
        phases = []
        for p in path:
            if p.start > lam_f or (p.start == lam_f and phases):
                break
            hi = lam_f if p.end is None else min(p.end, lam_f)
            phases.append({"mode": p.mode, "from": fmt(p.start), "to": fmt(hi)})
        entry = {
            "law": law,
            "bodies": bodies,
            "impulse": [fmt(c) for c in P],
            "impulse_coefficients": {"lam": fmt(lam_f), "tau": fmt(tauf)},
            "lam_c": fmt(lam_c),
            "lam_f": fmt(lam_f),
            "phases": phases,
            "contact_velocity": {
                "before": {"n": fmt(un0), "t": fmt(ut0), "world": [fmt(c) for c in u]},
                "after": {"n": fmt(unf), "t": fmt(utf), "world": [fmt(c) for c in uf]},
            },
            "work": {"normal_compression": fmt(wn_c), "normal_restitution": fmt(wn_r),
                     "friction": fmt(wt)},
            "energy": {"before": fmt(E0), "after": fmt(E1), "change": fmt(E1 - E0)},
            "energy_gain": bool(sign(E1 - E0) > 0),
        }
        if pins:
            entry["pin_impulse"] = pins
        out["laws"].append(entry)
    return out


def load(path):
    with open(path, "rb") as f:
        doc = tomllib.load(f, parse_float=lambda s: parse_number(s.replace("_", "")))
    return Scene(doc)


def main(argv):
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("-o", "--output")
    args = ap.parse_args(argv)
    try:
        result = solve(load(args.scene))
    except (SceneError, KeyError, TypeError, tomllib.TOMLDecodeError) as exc:
        print(f"error: {exc if not isinstance(exc, KeyError) else f'missing key {exc}'}",
              file=sys.stderr)
        return 2
    text = json.dumps(result, indent=2) + "\n"
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
