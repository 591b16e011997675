"""Shared by the planar-impact harnesses (pymunk_impacts.py, box2d_impacts.py, pybullet_impacts.py,
mujoco_impacts.py): reading the suite engines/impacts.jsonl and every example of examples/impacts/
it does not hold (the TOML files as the same JSON structure, id = the file's stem), the engine
geometry of a scene, the start state, the reading rule and the output line. The Rapier harness
(engines/rapier2d/src/bin/impacts.rs) does the same in Rust (on the suite only).

Geometry (scene units; every body keeps the scene's mass, inertia and centre of mass, set
explicitly, so no shape's area enters):
  * rod: a segment of the scene's length with radius ROD_RADIUS (a capsule); a box: its polygon;
    a disc: its circle; a point mass: a circle of radius POINT_RADIUS that cannot turn (infinite
    moment, fixed rotation), as a point mass struck through its centre cannot;
  * a fixed body without a shape (a floor, a wall) is a half-plane, one per distinct line; a
    fixed point (a peg) a circle of radius PEG_RADIUS;
  * thickness is added outside the scene's outline: a half-plane's edge (or a peg) is moved away
    from a rod by the rod's radius, so the contact is on the rod's surface, ROD_RADIUS from the
    scene's point (the lever arm changes by that much); at a contact between a moving disc or
    point and a rod the disc or point is moved away along the normal (its lever arm is 0, so
    nothing changes), a point mass also by its own radius.
Start: every moving body is put where its free flight puts it START_STEPS steps before the scene
(a pinned body turned back about its pin), so the approaching contacts close in the middle of
the first step and the configuration at the nominal contact is the scene's. No gravity, no
damping, sleeping off.
Reading: the world is stepped until a contact impulse has been applied and then a whole step
applies none (every contact has ended or carries no force), or less than TAIL_RATIO of the
largest step impulse (a contact the body keeps pressing after the impact: a sustained force, not
the impact; the state is then read before that step), at most MAX_SECONDS; each moving body's
centre-of-mass velocity and spin (counterclockwise, as the scene's) are read then (a pinned
body's centre velocity in its own frame, turned back to the scene's orientation), provided no
contact of the scene still approaches (else the steps go on: the engine resolves it later). With no
gravity they are the values right after the impact.
"""

import json
import math
import os
import tomllib
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "..", "impacts.jsonl")
EXAMPLES = os.path.join(HERE, "..", "..", "examples", "impacts")
# The class of an example of examples/impacts/ that the suite engines/impacts.jsonl does not hold
# (the suite holds the examples that existed when it was generated; engines/impact_suite.py).
EXAMPLE_CLASSES = {"cradle-12-two-balls": "multi-cradle"}
OUT_DIR = os.path.join(HERE, "..", "..", "tests", "data", "engines", "impacts")

DT_TEXT = "1/1000"
DT = 1 / 1000
ROD_RADIUS = 1 / 200          # rods in the suite have length 2: 1/400 of the length
POINT_RADIUS = 1 / 100
PEG_RADIUS = 1 / 100
START_STEPS = 0.99
# Diagnostics only (never for the fixtures): the environment may change the start and the
# thickness, to trace a residual to its cause (docs/engines-conformance.md); the fixture line
# then records the values in claimed.settings.
ROD_RADIUS = float(os.environ.get("IMPACTS_ROD_RADIUS", ROD_RADIUS))
START_STEPS = float(os.environ.get("IMPACTS_START_STEPS", START_STEPS))
MAX_SECONDS = 0.1
TAIL_RATIO = 1 / 100
APPROACH_TOLERANCE = 1e-6


def num(text):
    return Fraction(text)


class Body:
    def __init__(self, t):
        self.name = t["name"]
        self.fixed = bool(t.get("fixed", False))
        self.shape = t.get("shape")
        self.dims = {k: float(num(t[k])) for k in ("length", "radius", "width", "height") if k in t}
        self.position = tuple(float(num(v)) for v in t.get("position", ["0", "0"]))
        self.velocity = tuple(float(num(v)) for v in t.get("velocity", ["0", "0"]))
        self.omega = float(num(t.get("omega", "0")))
        ax = [num(v) for v in t.get("axis", ["1", "0"])]
        self.angle = math.atan2(ax[1], ax[0])
        self.pin = None
        self.shift = (0.0, 0.0)
        if self.fixed:
            self.mass = self.inertia = None
            return
        m = num(t["mass"])
        if "inertia" in t:
            inertia = num(t["inertia"])
        else:
            d = {k: num(t[k]) for k in ("length", "radius", "width", "height") if k in t}
            inertia = {"rod": lambda: m * d.get("length", 0) ** 2 / 12,
                       "disc": lambda: m * d.get("radius", 0) ** 2 / 2,
                       "box": lambda: m * (d.get("width", 0) ** 2 + d.get("height", 0) ** 2) / 12,
                       "point": lambda: Fraction(0)}[self.shape]()
        self.mass, self.inertia = float(m), float(inertia)

    @property
    def rotates(self):
        """False for a point mass: the engine body gets an infinite moment / fixed rotation."""
        return self.inertia > 0

    def skin(self):
        """How far the engine's surface lies outside the scene's outline (the scene's `skins`:
        by default a rod's radius, nothing for the other shapes)."""
        return self.skins.get(self.shape, 0.0)

    def local_shape(self):
        """('segment', a, b, radius) | ('poly', [vertices]) | ('circle', radius), in the body's
        frame (x along the scene's axis, origin at the centre of mass)."""
        if self.shape == "rod":
            h = self.dims["length"] / 2
            return ("segment", (-h, 0.0), (h, 0.0), ROD_RADIUS)
        if self.shape == "box":
            w, h = self.dims["width"] / 2, self.dims["height"] / 2
            return ("poly", [(-w, -h), (w, -h), (w, h), (-w, h)])
        if self.shape == "disc":
            return ("circle", self.dims["radius"])
        if self.shape == "point":
            return ("circle", POINT_RADIUS)
        raise SystemExit(f"error: body {self.name}: no engine shape for {self.shape!r}")


class Static:
    """A static shape: ('halfplane', point on the edge, outward unit normal) or ('circle', centre,
    radius); `tag` names it for the coefficient table."""

    def __init__(self, kind, a, b, tag):
        self.kind, self.a, self.b, self.tag = kind, a, b, tag


class Scene:
    """A suite line and its engine geometry. `skins`: shape -> how far an engine puts the body's
    surface outside the scene's outline (a rod's radius; Box2D's polygon skin)."""

    def __init__(self, line, skins=None):
        self.line = line
        self.id = line["id"]
        self.bodies = [Body(t) for t in line["body"]]
        for b in self.bodies:
            b.skins = {"rod": ROD_RADIUS} if skins is None else skins
        self.by_name = {b.name: b for b in self.bodies}
        for pin in line.get("pin", []):
            self.by_name[pin["body"]].pin = tuple(float(num(v)) for v in pin["point"])
        self.contacts = []
        for c in line["contact"]:
            n = [float(num(v)) for v in c["normal"]]
            norm = math.hypot(*n)
            self.contacts.append({
                "A": self.by_name[c["bodies"][0]], "B": self.by_name[c["bodies"][1]],
                "point": tuple(float(num(v)) for v in c["point"]),
                "n": (n[0] / norm, n[1] / norm),
                "e": float(num(c.get("e", "1"))), "mu": float(num(c.get("mu", "0"))),
                "e_text": c.get("e", "1"), "mu_text": c.get("mu", "0")})
        self.statics = []
        self.coefficients = {}     # frozenset of two tags -> (e, mu)
        self._place()

    def moving(self):
        return [b for b in self.bodies if not b.fixed]

    def _set_coefficients(self, tag1, tag2, c):
        key = frozenset((tag1, tag2))
        value = (c["e"], c["mu"])
        if self.coefficients.setdefault(key, value) != value:
            raise SystemExit(f"error: {self.id}: one pair of shapes with two coefficient sets")

    def _shift(self, body, d):
        if body.shift != (0.0, 0.0) and body.shift != d:
            raise SystemExit(f"error: {self.id}: body {body.name} would be moved twice")
        body.shift = d

    def _place(self):
        lines = {}
        for c in self.contacts:
            A, B, n, p = c["A"], c["B"], c["n"], c["point"]
            if A.fixed or B.fixed:
                moving, fixed = (B, A) if A.fixed else (A, B)
                into = n if moving is A else (-n[0], -n[1])   # from the fixed body into the moving
                if moving.shape == "point":
                    self._shift(moving, (POINT_RADIUS * into[0], POINT_RADIUS * into[1]))
                s = moving.skin()
                surface = (p[0] - s * into[0], p[1] - s * into[1])
                if fixed.shape is None:
                    offset = surface[0] * into[0] + surface[1] * into[1]
                    key = (fixed.name, round(into[0], 12), round(into[1], 12), round(offset, 12))
                    if key not in lines:
                        lines[key] = Static("halfplane", surface, into, f"{fixed.name}#{len(self.statics)}")
                        self.statics.append(lines[key])
                    st = lines[key]
                elif fixed.shape == "point":
                    centre = (surface[0] - PEG_RADIUS * into[0], surface[1] - PEG_RADIUS * into[1])
                    st = Static("circle", centre, PEG_RADIUS, f"{fixed.name}#{len(self.statics)}")
                    self.statics.append(st)
                else:
                    raise SystemExit(f"error: {self.id}: fixed body {fixed.name} with shape {fixed.shape}")
                self._set_coefficients(moving.name, st.tag, c)
                c["static"] = st.tag
                continue
            # two moving bodies: move a disc or a point away from the other body's surface
            for X, Y, sign in ((A, B, 1), (B, A, -1)):
                if X.shape in ("disc", "point"):
                    d = Y.skin() + (POINT_RADIUS if X.shape == "point" else 0.0)
                    if d:
                        self._shift(X, (sign * d * n[0], sign * d * n[1]))
                    break
            else:
                raise SystemExit(f"error: {self.id}: a contact between two bodies neither a disc nor a point")
            self._set_coefficients(A.name, B.name, c)

    def start(self, dt):
        """(position, angle, velocity, omega) of each moving body at the start: START_STEPS steps
        of free flight before the scene (a pinned body turned about its pin)."""
        t0 = START_STEPS * dt
        out = {}
        for b in self.moving():
            x = (b.position[0] + b.shift[0], b.position[1] + b.shift[1])
            if b.pin is not None:
                a = -b.omega * t0
                r = (x[0] - b.pin[0], x[1] - b.pin[1])
                x = (b.pin[0] + math.cos(a) * r[0] - math.sin(a) * r[1],
                     b.pin[1] + math.sin(a) * r[0] + math.cos(a) * r[1])
            else:
                x = (x[0] - b.velocity[0] * t0, x[1] - b.velocity[1] * t0)
            out[b.name] = (x, b.angle - b.omega * t0, b.velocity, b.omega)
        return out


def reading(body, vx, vy, angle):
    """The centre-of-mass velocity as read: a free body's is constant after the impact; a pinned
    body's centre moves on a circle about the pin, so its velocity is turned back by the angle
    the body has turned since the scene's configuration (the velocity in the body's frame)."""
    if body.pin is None:
        return vx, vy
    a = -(angle - body.angle)
    return math.cos(a) * vx - math.sin(a) * vy, math.sin(a) * vx + math.cos(a) * vy


def _exact_strings(value):
    """A TOML value as the suite's JSON keeps it: numbers as exact strings, the rest as is."""
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, Fraction)):
        return str(value)
    if isinstance(value, float):
        raise SystemExit(f"error: a float {value!r} in an example (numbers are exact strings)")
    if isinstance(value, dict):
        return {k: _exact_strings(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_exact_strings(v) for v in value]
    return value


def example_lines(suite_lines):
    """Every scene of examples/impacts/*.toml (not published/) as a suite line, id = the file's
    stem, in file-name order. An example the suite already holds must be converted to that very
    line (it is then not repeated); the others get their class from EXAMPLE_CLASSES."""
    held = {line["id"]: line for line in suite_lines}
    out = []
    for name in sorted(os.listdir(EXAMPLES)):
        if not name.endswith(".toml"):
            continue
        stem = name[:-5]
        with open(os.path.join(EXAMPLES, name), "rb") as f:
            doc = tomllib.load(f)
        if stem in held:
            cls = held[stem]["class"]
        elif stem in EXAMPLE_CLASSES:
            cls = EXAMPLE_CLASSES[stem]
        else:
            raise SystemExit(f"error: example {stem}: no class (add it to EXAMPLE_CLASSES)")
        line = {"id": stem, "class": cls}
        for key in ("title", "body", "contact", "pin"):
            if key in doc:
                line[key] = _exact_strings(doc[key])
        if stem in held:
            if line != held[stem]:
                raise SystemExit(f"error: example {stem} differs from its line in {SUITE}")
            continue
        out.append(line)
    return out


def load(path=SUITE, skins=None, examples=True):
    """The scenes to run: every line of the suite (its order and ids), then every example of
    examples/impacts/ the suite does not hold (ids = file stems)."""
    with open(path) as f:
        lines = [json.loads(text) for text in f if text.strip()]
    if examples:
        lines += example_lines(lines)
    return [Scene(line, skins) for line in lines]


def max_steps(dt):
    return math.ceil(START_STEPS) + round(MAX_SECONDS / dt)


def approaching(scene, states):
    """The scene's contacts whose normal relative velocity, from `states` (name -> (vx, vy,
    omega)) and the scene's geometry, is below -APPROACH_TOLERANCE of the largest approach speed
    before the impact."""
    def un(c, get):
        u = [0.0, 0.0]
        for body, sign in ((c["A"], 1), (c["B"], -1)):
            if body.fixed:
                continue
            vx, vy, w = get(body)
            r = (c["point"][0] - body.position[0], c["point"][1] - body.position[1])
            u[0] += sign * (vx - w * r[1])
            u[1] += sign * (vy + w * r[0])
        return u[0] * c["n"][0] + u[1] * c["n"][1]

    before = [un(c, lambda b: (*b.velocity, b.omega)) for c in scene.contacts]
    scale = max([-u for u in before] + [1e-300])
    return [k + 1 for k, c in enumerate(scene.contacts)
            if un(c, lambda b: states[b.name]) < -APPROACH_TOLERANCE * scale]


def run_until_resolved(scene, step, snapshot, dt):
    """Steps the world until the impact is over and returns (states, steps, how it ended).
    `step()` advances one step and returns the total contact impulse magnitude applied in it;
    `snapshot()` returns name -> (vx, vy, omega). The impact is over at the first step, after one
    that applied an impulse, that applies none ("ended") or less than TAIL_RATIO of the largest
    step impulse so far ("tail": a sustained contact force, e.g. a plastic contact the body keeps
    pressing as it turns; the state is read before that step), once no contact of the scene
    approaches (a contact the engine has not resolved yet, e.g. the next ball of a cradle that
    the engine strikes a few steps later, is waited for)."""
    peak, before = 0.0, snapshot()
    for k in range(1, max_steps(dt) + 1):
        impulse = step()
        if peak > 0 and impulse <= TAIL_RATIO * peak:
            state, how = (snapshot(), "ended") if impulse == 0 else (before, "tail")
            if not approaching(scene, state):
                return state, k, how
        peak = max(peak, impulse)
        before = snapshot()
    late = approaching(scene, before)
    return before, max_steps(dt), ("still in contact at the end" if not late else
                                   f"contacts {late} still approach at the end")


def claimed_line(scene, engine, states, settings=None):
    """The fixture line: the scene's own JSON plus "claimed" (states: name -> (vx, vy, omega)),
    with the run's "settings" (engine parameters, dt, steps taken, how the reading ended)."""
    out = dict(scene.line)
    out["claimed"] = {"engine": engine, "bodies": {
        name: {"velocity": [repr(float(v[0])), repr(float(v[1]))], "omega": repr(float(v[2]))}
        for name, v in states.items()}}
    if settings is not None:
        out["claimed"]["settings"] = settings
    return out


def common_settings(steps, ended):
    """The set-up shared by every harness, as recorded in a fixture line's claimed.settings."""
    out = {"dt": DT_TEXT, "start_steps": repr(START_STEPS), "gravity": "0", "damping": "0",
           "sleeping": "off", "steps": steps, "ended": ended}
    if ROD_RADIUS != 1 / 200:
        out["rod_radius_diagnostic"] = repr(ROD_RADIUS)
    return out


def write(path, lines):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        for entry in lines:
            f.write(json.dumps(entry) + "\n")
