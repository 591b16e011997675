"""Shared by the engine scripts: reading the suite, the set-up geometry, the reading rule and
the output format. Every script writes the same columns as the Rapier harness:

    id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,v,V,omega,J,energy_before,energy_after

v, V, omega follow rodimpact's conventions: x is the ball's direction before the impact, the rod
lies along y, omega > 0 when the struck point (a > 0) moves forward, i.e. omega = -(the engine's
counterclockwise angular velocity). J is the contact impulse the engine reports, summed over
the steps (empty where the engine does not report one); energy_before and energy_after are the
kinetic energies of the engine's own state (all velocity components and spin).
"""

import csv
import math
import os
import sys
from fractions import Fraction

HEADER = ("id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,"
          "v,V,omega,J,energy_before,energy_after").split(",")
# The log of the oblique scenes (the same as the Rapier harness's): every suite column, the
# claims rodimpact's batch checks for an oblique scene (v, V, omega), then pass-through columns
# for the comparison along the rod and the engine's impulse and energies.
OBLIQUE_HEADER = ("id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,"
                  "v0t,mu,radius,spin,rod-v,rod-vt,rod-omega,v,V,omega,"
                  "claimed_vt,claimed_Vt,claimed_spin,engine_J,engine_energy_before,"
                  "engine_energy_after").split(",")
SUITE_COLUMNS = ("id,class,m,M,l,a,v0,rod,e,pivot,"
                 "v0t,mu,radius,spin,rod-v,rod-vt,rod-omega").split(",")
OBLIQUE_COLUMNS = SUITE_COLUMNS[10:]

# Geometry relative to the rod's half-length l (the same as engines/rapier2d): the rod is a box
# of half extents (0.01 l, l), the ball's radius 0.05 l, and the ball starts 3.5 steps (at v0)
# before touching the rod's face, so it touches half-way through a step and never tunnels.
HALF_THICKNESS_PER_L = 0.01
BALL_RADIUS_PER_L = 0.05
APPROACH_STEPS = 3.5
# The state is read 0.1 s after the nominal contact: by then every contact of the suite has
# ended (or, for e = 0, carries no force), joint transients are over, and no second impact has
# happened.
AFTER_CONTACT_SECONDS = 0.1

SUITE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "suite.csv")


class Scene:
    """One suite row: the cells verbatim plus the numbers as floats (an engine's input)."""

    def __init__(self, cells):
        self.cells = cells
        q = {k: Fraction(cells[k]) for k in ("m", "M", "l", "a", "v0", "e")}
        self.m, self.M, self.l = float(q["m"]), float(q["M"]), float(q["l"])
        self.a, self.v0, self.e = float(q["a"]), float(q["v0"]), float(q["e"])
        self.pivot = float(Fraction(cells["pivot"])) if cells["pivot"].strip() else None
        self.I = float(rod_inertia(cells["rod"].strip(), q["M"], q["l"]))
        self.h = HALF_THICKNESS_PER_L * self.l
        self.oblique = any(cells[c].strip() for c in OBLIQUE_COLUMNS)
        if self.oblique:
            o = {c: float(Fraction(cells[c])) for c in OBLIQUE_COLUMNS}
            if o["rod-omega"] != 0:
                raise SystemExit(f"error: {cells['id']}: a rod turning before the impact is not set up")
            self.v0t, self.mu, self.r, self.spin = o["v0t"], o["mu"], o["radius"], o["spin"]
            self.rod_v, self.rod_vt = o["rod-v"], o["rod-vt"]
        else:
            self.v0t = self.mu = self.spin = self.rod_v = self.rod_vt = 0.0
            self.r = BALL_RADIUS_PER_L * self.l

    def start_x(self, dt):
        """The ball's starting x: 3.5 steps before its surface meets the rod's face; an oblique
        ball half a step (at the approach speed v0 - rod-v), so that its slide along the rod
        before the contact moves the impact point by at most |v0t - rod-vt| dt/2."""
        steps = 0.5 if self.oblique else APPROACH_STEPS
        return -(self.h + self.r) - steps * (self.v0 - self.rod_v) * dt


def rod_inertia(rod, M, l):
    """I about the centre for rodimpact's `--rod uniform|dumbbell|rg=Q|I=Q`, exact."""
    if rod == "uniform":
        return M * l * l / 3
    if rod == "dumbbell":
        return M * l * l
    if rod.startswith("rg="):
        return M * Fraction(rod[3:]) ** 2
    if rod.startswith("I="):
        return Fraction(rod[2:])
    raise ValueError(f"rod '{rod}' is not uniform, dumbbell, rg=Q or I=Q")


def load_suite(path=SUITE, oblique=None):
    """The suite's perpendicular frictionless scenes (`oblique` False), or its oblique ones
    (True: a slide along the rod, friction, a spinning ball, a drifting rod; issue 20). A script
    that does not set the oblique scenes up leaves `oblique` out, and is told how many it skips."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != SUITE_COLUMNS:
            raise SystemExit(f"error: suite header must be {','.join(SUITE_COLUMNS)}")
        scenes = [Scene(row) for row in reader]
    if oblique:
        return [s for s in scenes if s.oblique]
    skipped = sum(s.oblique for s in scenes)
    if skipped and oblique is None:
        print(f"note: {skipped} oblique scenes not run by this script", file=sys.stderr)
    return [s for s in scenes if not s.oblique]


def steps(dt):
    """Steps per run: the approach (3.5 steps, rounded up) plus 0.1 s."""
    return math.ceil(APPROACH_STEPS) + round(AFTER_CONTACT_SECONDS / dt)


def shortest(x, single=False):
    """The shortest decimal that reads back to the same float (f32 when `single`)."""
    if x is None:
        return ""
    if single:
        import numpy as np

        return np.format_float_positional(np.float32(x), unique=True, trim="-") \
            if 1e-4 <= abs(x) < 1e16 or x == 0 or not math.isfinite(x) \
            else np.format_float_scientific(np.float32(x), unique=True, trim="-")
    text = repr(float(x))
    return {"nan": "NaN", "inf": "inf", "-inf": "-inf"}.get(text, text)


def rotate_into(angle, vx, vy):
    """The x-component, in a frame turned by `angle` (counterclockwise), of a world vector."""
    return math.cos(angle) * vx + math.sin(angle) * vy


def centre_velocity(scene, angle, vx, vy):
    """V as read after the contact: a free rod's centre velocity is constant in the world, so
    its x-component is V; a pivoted rod's centre moves on a circle, so its velocity is taken in
    the rod's own frame (the rod has turned by `angle` since the impact)."""
    return vx if scene.pivot is None else rotate_into(angle, vx, vy)


def write(path, rows, header=HEADER):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


def row(scene, engine, version, float_name, dt_text, iters, outcome, single=False):
    """One output row; `outcome` is (v, V, omega, J, energy_before, energy_after)."""
    c = scene.cells
    return [c["id"], engine, version, float_name, dt_text, str(iters), c["class"], c["m"], c["M"],
            c["l"], c["a"], c["v0"], c["rod"], c["e"], c["pivot"],
            *(shortest(x, single) for x in outcome)]


def oblique_row(scene, engine, version, float_name, dt_text, iters, outcome, single=False):
    """One row of an oblique log; `outcome` is (v, V, omega, vt, Vt, spin, J, energy_before,
    energy_after)."""
    c = scene.cells
    return [c["id"], engine, version, float_name, dt_text, str(iters), c["class"],
            *(c[k] for k in SUITE_COLUMNS[2:]),
            *(shortest(x, single) for x in outcome)]


def along_rod(scene, angle, vx, vy):
    """The centre's velocity along the rod, read as V is (`centre_velocity`): in the world for a
    free rod, in the rod's frame for a pivoted one."""
    if scene.pivot is None:
        return vy
    return -math.sin(angle) * vx + math.cos(angle) * vy


def out_dir(argv):
    """The output directory: the first argument, or tests/data/engines of this repository."""
    if len(argv) > 1:
        return argv[1]
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data",
                        "engines")


DTS = (("1/60", 1 / 60), ("1/240", 1 / 240), ("1/1000", 1 / 1000))
