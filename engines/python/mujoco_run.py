#!/usr/bin/env python3
"""Run the engine suite in MuJoCo 4.0.0 (double precision) and write
OUTDIR/mujoco-4.0.0-f64.csv (default OUTDIR: tests/data/engines).

MuJoCo has no coefficient of restitution: a contact is a soft constraint whose reference
acceleration is aref = -b v - k r (r the penetration, v its rate, both in the contact's normal
direction, so k and b are per unit effective mass). This script uses the documented direct form
solref = "-K -B" with a constant impedance (solimp = "0.99 0.99 ...": MuJoCo divides K by
dmax^2 and B by dmax and multiplies back with the impedance, so the contact follows
r'' = -K r - B r' exactly), i.e. a linear spring-damper of stiffness K = 1e5 s^-2 (contact time
pi/sqrt(K) = 9.9 ms) and damping B = 2 zeta sqrt(K). zeta is chosen so that the UNCLAMPED linear
oscillator rebounds with the scene's e: e = exp(-pi zeta / sqrt(1 - zeta^2)), i.e.
zeta = -ln(e) / sqrt(pi^2 + ln(e)^2); e = 1 gives B = 0, e = 0 gives critical damping
(zeta = 1). MuJoCo's contact force cannot pull, so for 0 < e < 1 the realised restitution is
not exactly e: that difference is part of what is measured.

Set-up (the same geometry as engines/rapier2d, in the plane z = 0): zero gravity; RK4; the rod
a box of half sizes (0.01 l, l, 0.01 l) on slide x, slide y and hinge z joints (free rod) or on
one hinge z joint at (0, p, 0) (pivot: an exact reduced-coordinate joint), explicit inertial
(M, I about z); the ball a sphere of radius 0.05 l on slide x and slide y joints, mass m;
condim 1 (frictionless). Time steps 1/1000, 1/10000, 1/100000 (a soft contact needs the contact
time resolved; at 1/60 it is 0.6 steps long). J is left empty (RK4's stages make a per-step
impulse sum ambiguous). Energies are MuJoCo's own kinetic energy (mjENBL_ENERGY).

Usage: python mujoco_run.py [OUTDIR]
"""

import math
import os
import sys

import mujoco
import numpy as np

import common

STIFFNESS = 1e5
DTS = (("1/1000", 1e-3), ("1/10000", 1e-4), ("1/100000", 1e-5))
IMPEDANCE = 0.99


def damping_ratio(e):
    if e >= 1:
        return 0.0
    if e <= 0:
        return 1.0
    return -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)


def model_xml(scene, dt):
    b = 2 * damping_ratio(scene.e) * math.sqrt(STIFFNESS)
    if scene.pivot is None:
        rod_joints = ('<joint name="rx" type="slide" axis="1 0 0"/>'
                      '<joint name="ry" type="slide" axis="0 1 0"/>'
                      '<joint name="rz" type="hinge" axis="0 0 1"/>')
    else:
        rod_joints = f'<joint name="rz" type="hinge" axis="0 0 1" pos="0 {scene.pivot!r} 0"/>'
    i_ball = 0.4 * scene.m * scene.r ** 2
    return f"""
<mujoco>
  <option timestep="{dt!r}" gravity="0 0 0" integrator="RK4">
    <flag energy="enable"/>
  </option>
  <default>
    <geom condim="1" friction="0 0 0" solref="{-STIFFNESS!r} {-b!r}"
          solimp="{IMPEDANCE} {IMPEDANCE} 0.001 0.5 2"/>
  </default>
  <worldbody>
    <body name="rod" pos="0 0 0">
      {rod_joints}
      <inertial pos="0 0 0" mass="{scene.M!r}" diaginertia="{scene.I!r} {scene.I!r} {scene.I!r}"/>
      <geom type="box" size="{scene.h!r} {scene.l!r} {scene.h!r}"/>
    </body>
    <body name="ball" pos="{scene.start_x(dt)!r} {scene.a!r} 0">
      <joint name="bx" type="slide" axis="1 0 0"/>
      <joint name="by" type="slide" axis="0 1 0"/>
      <inertial pos="0 0 0" mass="{scene.m!r}" diaginertia="{i_ball!r} {i_ball!r} {i_ball!r}"/>
      <geom type="sphere" size="{scene.r!r}"/>
    </body>
  </worldbody>
</mujoco>"""


def run(scene, dt):
    model = mujoco.MjModel.from_xml_string(model_xml(scene, dt))
    data = mujoco.MjData(model)
    data.qvel[model.jnt_dofadr[model.joint("bx").id]] = scene.v0
    mujoco.mj_forward(model, data)
    before = data.energy[1]
    for _ in range(common.steps(dt)):
        mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    velocity = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, model.body("ball").id,
                             velocity, 0)
    v = velocity[3]
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, model.body("rod").id,
                             velocity, 0)
    rot = data.xmat[model.body("rod").id]
    angle = math.atan2(rot[3], rot[0])
    V = common.centre_velocity(scene, angle, velocity[3], velocity[4])
    return (v, V, -velocity[2], None, before, data.energy[1])


def main():
    version = mujoco.__version__
    rows = []
    for scene in common.load_suite():
        for dt_text, dt in DTS:
            iters = mujoco.MjModel.from_xml_string(model_xml(scene, dt)).opt.iterations
            rows.append(common.row(scene, "mujoco", version, "f64", dt_text, iters,
                                   run(scene, dt)))
    path = os.path.join(common.out_dir(sys.argv), f"mujoco-{version}-f64.csv")
    common.write(path, rows)
    print(f"mujoco {version}: {len(rows)} runs -> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
