#!/usr/bin/env python3
"""MuJoCo has no coefficient of restitution: which solref/solimp give a contact the restitution e,
and what the default pyramidal friction cone does with an elastic contact.

1. Calibration (a drop test): a ball of mass 1 and radius 1/10 on one slide joint meets a plane
   at v0 = 1 (no gravity); the contact is the direct form solref = (-K, -B) with a constant
   impedance solimp = (D, D, 0.001, 0.5, 2), so that it follows r'' = -K r - B r' while it
   pushes (MuJoCo scales K by 1/dmax^2 and B by 1/dmax and multiplies back by the impedance,
   engine_core_constraint.c), K = w0^2 with the undamped contact lasting CONTACT_STEPS steps
   (w0 = pi / (CONTACT_STEPS dt)), B = 2 zeta w0. The rebound e_measured = -v_after / v0 falls
   as zeta grows; zeta is found by bisection so that the measured rebound is e (e = 1: zeta = 0,
   measured as it comes; e = 0: the force cannot pull, so no finite damping stops the ball dead,
   and RK4 turns unstable near B dt = 1.3: the table gives the damping of the smallest rebound). dt = 1e-5, RK4, the
   contact CONTACT_STEPS = 50 steps long: the set-up of engines/python/mujoco_impacts.py, which
   imports zeta_for() from here.

2. Energy created by the pyramidal cone: tilted-rod-rough-floor (a uniform rod of length 2 and
   mass 1 along (3, 4) lands on its lower end at (1, -1), e = 1, mu = 1/3; lcp-newton gains
   +1/10 exactly, Newton's law +2.09 %, Poisson -14.41 %, Stronge -8.53 %) and
   newton-gains-energy (mu = 1) with the elastic contact (B = 0): the default pyramidal cone,
   the elliptic cone, each with the friction rows' solreffriction left to solref (MuJoCo's
   default) or set to critical damping (2 dt, 1), at two contact times, two time steps and two
   impedances; mu = 0 as a control. dE/T0 = (T_after - T_before)/T_before.

Writes OUTDIR/mujoco-<version>-restitution.json (default OUTDIR tests/data/engines/impacts;
engines/conformance.py renders it into docs/engines-conformance.md) and prints both tables.

Usage: python mujoco_restitution.py [OUTDIR]
"""

import json
import math
import os
import sys
from fractions import Fraction

import mujoco
import numpy as np

import impacts_common as ic

DT = 1e-5
CONTACT_STEPS = 50
IMPEDANCE = 0.99
TARGETS = ("0", "1/4", "1/2", "3/4", "1")


def stiffness(dt=DT, contact_steps=CONTACT_STEPS):
    w0 = math.pi / (contact_steps * dt)
    return w0 * w0, w0


def solimp(d=IMPEDANCE):
    return f"{d!r} {d!r} 0.001 0.5 2"


def drop_xml(K, B, dt=DT, d=IMPEDANCE):
    return f"""
<mujoco>
  <option timestep="{dt!r}" gravity="0 0 0" integrator="RK4"/>
  <worldbody>
    <geom name="floor" type="plane" size="10 10 0.1" contype="0" conaffinity="0"/>
    <body name="ball" pos="0 0 0.1">
      <joint name="z" type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.004 0.004 0.004"/>
      <geom name="ball" type="sphere" size="0.1" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
  <contact>
    <pair geom1="ball" geom2="floor" condim="1" solref="{-K!r} {-B!r}" solimp="{solimp(d)}"/>
  </contact>
</mujoco>"""


def rebound(zeta, dt=DT, contact_steps=CONTACT_STEPS, d=IMPEDANCE):
    """-v_after/v0 of the drop test, and the steps the contact lasted."""
    K, w0 = stiffness(dt, contact_steps)
    model = mujoco.MjModel.from_xml_string(drop_xml(K, 2 * zeta * w0, dt, d))
    data = mujoco.MjData(model)
    data.qvel[0] = -1.0
    mujoco.mj_forward(model, data)
    touched = 0
    for k in range(200 * contact_steps):
        mujoco.mj_step(model, data)
        if data.ncon and data.efc_force.size and data.efc_force.max() > 0:
            touched += 1
        elif touched and data.qvel[0] > 0:
            return float(data.qvel[0]), touched
    return float(data.qvel[0]), touched


_CACHE = {}


def zeta_for(e, dt=DT, contact_steps=CONTACT_STEPS, d=IMPEDANCE):
    """The damping ratio whose drop test rebounds with e (bisection); e = 1: 0; e = 0: the
    damping of the smallest rebound."""
    key = (float(e), dt, contact_steps, d)
    if key in _CACHE:
        return _CACHE[key]
    e = float(e)
    if e >= 1:
        _CACHE[key] = 0.0
        return 0.0
    if e <= 0:
        # no finite damping stops a unilateral contact dead, and RK4 turns unstable near
        # B dt = 1.3: the damping of the smallest rebound, on a grid then by golden section
        grid = [0.5 * k for k in range(2, 41)]
        best = min(grid, key=lambda z: abs(rebound(z, dt, contact_steps, d)[0]))
        lo, hi = best - 0.5, best + 0.5
        g = (math.sqrt(5) - 1) / 2
        for _ in range(40):
            a, b = hi - g * (hi - lo), lo + g * (hi - lo)
            if abs(rebound(a, dt, contact_steps, d)[0]) < abs(rebound(b, dt, contact_steps, d)[0]):
                hi = b
            else:
                lo = a
        _CACHE[key] = (lo + hi) / 2
        return _CACHE[key]
    target = e
    lo, hi = 0.0, 1.0
    while rebound(hi, dt, contact_steps, d)[0] > target:
        lo, hi = hi, 2 * hi
        if hi > 1e4:
            raise SystemExit(f"error: no damping gives the rebound {target}")
    for _ in range(80):
        mid = (lo + hi) / 2
        if rebound(mid, dt, contact_steps, d)[0] > target:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-12 * max(hi, 1):
            break
    _CACHE[key] = hi
    return hi


def calibration():
    rows = []
    K, w0 = stiffness()
    for text in TARGETS:
        e = float(Fraction(text))
        z = zeta_for(e)
        measured, steps = rebound(z)
        linear = math.exp(-math.pi * z / math.sqrt(1 - z * z)) if z < 1 else 0.0
        rows.append({"e": text, "zeta": repr(z), "solref": [repr(-K), repr(-2 * z * w0)],
                     "solimp": solimp().split(), "rebound": repr(measured),
                     "contact_steps": steps, "linear_oscillator_e": repr(linear)})
    return rows


def scene_energy(scene_id, cone, solreffriction, contact_steps=CONTACT_STEPS, dt=DT,
                 d=IMPEDANCE, mu=None):
    """dE/T0 of one suite scene in mujoco_impacts with the given friction set-up."""
    import mujoco_impacts as mi
    scene = next(s for s in ic.load() if s.id == scene_id)
    if mu is not None:
        for c in scene.contacts:
            c["mu"] = mu
        scene.coefficients = {k: (v[0], mu) for k, v in scene.coefficients.items()}
    states, steps, ended, info = mi.run(scene, cone=cone, solreffriction=solreffriction,
                                        contact_steps=contact_steps, dt=dt, d=d)
    before = sum(b.mass * (b.velocity[0] ** 2 + b.velocity[1] ** 2) / 2 +
                 b.inertia * b.omega ** 2 / 2 for b in scene.moving())
    after = sum(scene.by_name[n].mass * (v[0] ** 2 + v[1] ** 2) / 2 +
                scene.by_name[n].inertia * v[2] ** 2 / 2 for n, v in states.items())
    return (after - before) / before, states


def cone_table():
    rows = []
    for scene_id in ("tilted-rod-rough-floor", "newton-gains-energy"):
        for cone in ("pyramidal", "elliptic"):
            for srf in (None, "critical"):
                for steps, dt, d in ((CONTACT_STEPS, DT, IMPEDANCE), (200, DT, IMPEDANCE),
                                     (CONTACT_STEPS, DT / 10, IMPEDANCE),
                                     (CONTACT_STEPS, DT, 0.9)):
                    dE, states = scene_energy(scene_id, cone, srf, steps, dt, d)
                    rows.append({"scene": scene_id, "cone": cone,
                                 "solreffriction": srf or "solref (default)",
                                 "contact_steps": steps, "dt": repr(dt), "impedance": repr(d),
                                 "mu": "scene", "dE_T0": repr(dE),
                                 "bodies": {n: [repr(x) for x in v] for n, v in states.items()}})
        dE, states = scene_energy(scene_id, "pyramidal", None, mu=0.0)
        rows.append({"scene": scene_id, "cone": "pyramidal", "solreffriction": "solref (default)",
                     "contact_steps": CONTACT_STEPS, "dt": repr(DT), "impedance": repr(IMPEDANCE),
                     "mu": "0", "dE_T0": repr(dE),
                     "bodies": {n: [repr(x) for x in v] for n, v in states.items()}})
    return rows


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else ic.OUT_DIR
    cal = calibration()
    print("| e | zeta | solref (-K, -B) | solimp | measured rebound | contact steps |")
    print("|---|---:|---|---|---:|---:|")
    for r in cal:
        print(f"| {r['e']} | {float(r['zeta']):.6g} | ({float(r['solref'][0]):.6g}, "
              f"{float(r['solref'][1]):.6g}) | {' '.join(r['solimp'])} | "
              f"{float(r['rebound']):.6f} | {r['contact_steps']} |")
    cones = cone_table()
    print()
    print("| scene | cone | solreffriction | contact steps | dt | impedance | mu | dE/T0 |")
    print("|---|---|---|---:|---:|---:|---|---:|")
    for r in cones:
        print(f"| {r['scene']} | {r['cone']} | {r['solreffriction']} | {r['contact_steps']} | "
              f"{float(r['dt']):g} | {r['impedance']} | {r['mu']} | {float(r['dE_T0']):+.4f} |")
    doc = {"engine": f"mujoco {mujoco.__version__}", "dt": repr(DT), "integrator": "RK4",
           "drop_test": "ball mass 1, radius 1/10, v0 = 1, no gravity, one slide joint",
           "calibration": cal, "cone_energy": cones}
    path = os.path.join(out, f"mujoco-{mujoco.__version__}-restitution.json")
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    print(f"-> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
