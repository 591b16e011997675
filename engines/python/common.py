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
        self.r = BALL_RADIUS_PER_L * self.l

    def start_x(self, dt):
        """The ball's starting x: 3.5 steps before its surface meets the rod's face."""
        return -(self.h + self.r) - APPROACH_STEPS * self.v0 * dt


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


def load_suite(path=SUITE):
    """The suite's perpendicular frictionless scenes. The oblique ones (a slide along the rod,
    friction, a spinning ball, a drifting rod: issue 20) are not set up in these engines' scripts
    yet; they are skipped, and the script says how many (Rapier runs them: engines/rapier2d)."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != SUITE_COLUMNS:
            raise SystemExit(f"error: suite header must be {','.join(SUITE_COLUMNS)}")
        rows = list(reader)
    oblique = [r for r in rows if any(r[c].strip() for c in OBLIQUE_COLUMNS)]
    if oblique:
        print(f"note: {len(oblique)} oblique scenes skipped (not set up for this engine)",
              file=sys.stderr)
    return [Scene(r) for r in rows if r not in oblique]


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


def write(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        w.writerows(rows)


def row(scene, engine, version, float_name, dt_text, iters, outcome, single=False):
    """One output row; `outcome` is (v, V, omega, J, energy_before, energy_after)."""
    c = scene.cells
    return [c["id"], engine, version, float_name, dt_text, str(iters), c["class"], c["m"], c["M"],
            c["l"], c["a"], c["v0"], c["rod"], c["e"], c["pivot"],
            *(shortest(x, single) for x in outcome)]


def out_dir(argv):
    """The output directory: the first argument, or tests/data/engines of this repository."""
    if len(argv) > 1:
        return argv[1]
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data",
                        "engines")


DTS = (("1/60", 1 / 60), ("1/240", 1 / 240), ("1/1000", 1 / 1000))
