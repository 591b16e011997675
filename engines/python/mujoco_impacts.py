#!/usr/bin/env python3
"""Run the planar impact suite (engines/impacts.jsonl) and every example of examples/impacts/ it
does not hold in MuJoCo 4.0.0 (double precision), one impact per scene, and write
OUTDIR/mujoco-4.0.0.jsonl (default OUTDIR: tests/data/engines/impacts): each line the scene plus
"claimed", the velocity and spin of every moving body right after the impact.

MuJoCo has no coefficient of restitution: every scene contact is an explicit <pair> with the
direct form solref = (-K, -B) and a constant impedance solimp = (0.99, 0.99, 0.001, 0.5, 2), so
the contact follows r'' = -K r - B r' while it pushes; K = w0^2 makes the undamped contact last
CONTACT_STEPS = 50 steps (w0 = pi / (50 dt)), and B = 2 zeta w0 with zeta calibrated on a drop
test so that the rebound is the contact's e (mujoco_restitution.py, zeta_for(); e = 0 is the
smallest rebound a stable damping reaches, 1.4e-3, since no finite damping stops a unilateral
contact dead). Friction: condim 3
with the scene's mu (condim 1 when mu = 0), MuJoCo's default pyramidal cone, the friction rows
with the same solref (MuJoCo's default, no solreffriction). That is the "natural" mapping of
ENGINES.md, whose pyramidal cone with an elastic contact creates energy; mujoco_restitution.py
measures that against the elliptic cone.

Set-up (impacts_common.py, except the time step): the scene in the world's x-y plane; no
gravity; dt = 1e-5 s (a compliant contact must be resolved in time: 50 steps of contact; at the
suite's 1/1000 it would last 50 ms, during which the bodies move and turn), RK4; every moving
body on slide x, slide y and hinge z joints (a point mass without the hinge; a pinned body on one
hinge at its pin: exact reduced coordinates), its geom turned to the scene's angle inside the
body, explicit mass and inertia; rods capsules of radius 1/200, boxes boxes (depth 0.01), discs
spheres, a point mass a sphere of radius 1/100; a floor or wall a plane whose surface is the
scene's line (moved away from a rod by its radius), a peg a sphere of radius 1/100; collisions
only through the pairs (contype = conaffinity = 0 everywhere). The start (0.99 steps before the
scene) and the reading rule are impacts_common's; the impulse of a step is sum |efc_force| * dt.

Usage: python mujoco_impacts.py [OUTDIR]
"""

import math
import os
import sys

import mujoco

import impacts_common as ic
import mujoco_restitution as mr

DT = mr.DT
DT_TEXT = "1/100000"
BOX_DEPTH_HALF = 0.005


def geom_xml(name, b):
    shape = b.local_shape()
    c, s = math.cos(b.angle), math.sin(b.angle)
    if shape[0] == "segment":
        (x1, _), (x2, _) = shape[1], shape[2]
        return (f'<geom name="{name}" type="capsule" size="{shape[3]!r}" '
                f'fromto="{c * x1!r} {s * x1!r} 0 {c * x2!r} {s * x2!r} 0"/>')
    if shape[0] == "poly":
        _, _, (w, h), _ = shape[1]
        return (f'<geom name="{name}" type="box" size="{w!r} {h!r} {BOX_DEPTH_HALF!r}" '
                f'euler="0 0 {b.angle!r}"/>')
    return f'<geom name="{name}" type="sphere" size="{shape[1]!r}"/>'


def model_xml(scene, dt, cone, solreffriction, contact_steps, d):
    K, w0 = mr.stiffness(dt, contact_steps)
    bodies = []
    for name, (x, angle, v, w) in scene.start(dt).items():
        b = scene.by_name[name]
        if b.pin is not None:
            # the body starts at the scene's angle turned back; its geom is placed at the scene's
            # angle, so the start angle is the hinge's initial qpos (set in run)
            joints = (f'<joint name="{name}-h" type="hinge" axis="0 0 1" '
                      f'pos="{b.pin[0] - b.position[0] - b.shift[0]!r} '
                      f'{b.pin[1] - b.position[1] - b.shift[1]!r} 0"/>')
            pos = (b.position[0] + b.shift[0], b.position[1] + b.shift[1])
        else:
            joints = (f'<joint name="{name}-x" type="slide" axis="1 0 0"/>'
                      f'<joint name="{name}-y" type="slide" axis="0 1 0"/>')
            if b.rotates:
                joints += f'<joint name="{name}-h" type="hinge" axis="0 0 1"/>'
            pos = (b.position[0] + b.shift[0], b.position[1] + b.shift[1])
        i = b.inertia if b.rotates else 1.0
        bodies.append(f'<body name="{name}" pos="{pos[0]!r} {pos[1]!r} 0">{joints}'
                      f'<inertial pos="0 0 0" mass="{b.mass!r}" diaginertia="{i!r} {i!r} {i!r}"/>'
                      f'{geom_xml(name, b)}</body>')
    statics = []
    for st in scene.statics:
        if st.kind == "halfplane":
            (px, py), (nx, ny) = st.a, st.b
            statics.append(f'<geom name="{st.tag}" type="plane" size="100 100 1" '
                           f'pos="{px!r} {py!r} 0" zaxis="{nx!r} {ny!r} 0"/>')
        else:
            statics.append(f'<geom name="{st.tag}" type="sphere" size="{st.b!r}" '
                           f'pos="{st.a[0]!r} {st.a[1]!r} 0"/>')
    pairs = []
    for c in scene.contacts:
        A, B = c["A"], c["B"]
        names = []
        for body, other in ((A, B), (B, A)):
            if body.fixed:
                names.append(c["static"])
            else:
                names.append(body.name)
        zeta = mr.zeta_for(c["e"], dt, contact_steps, d)
        mu = c["mu"]
        condim = 3 if mu > 0 else 1
        extra = f' solreffriction="{2 * dt!r} 1"' if solreffriction == "critical" else ""
        pairs.append(f'<pair geom1="{names[0]}" geom2="{names[1]}" condim="{condim}" '
                     f'friction="{mu!r} {mu!r} 0.005 0.0001 0.0001" '
                     f'solref="{-K!r} {-2 * zeta * w0!r}" solimp="{mr.solimp(d)}"{extra}/>')
    return f"""
<mujoco>
  <compiler angle="radian"/>
  <option timestep="{dt!r}" gravity="0 0 0" integrator="RK4" cone="{cone}"/>
  <default><geom contype="0" conaffinity="0"/></default>
  <worldbody>
    {''.join(statics)}
    {''.join(bodies)}
  </worldbody>
  <contact>{''.join(pairs)}</contact>
</mujoco>"""


def run(scene, dt=DT, cone="pyramidal", solreffriction=None, contact_steps=mr.CONTACT_STEPS,
        d=mr.IMPEDANCE):
    model = mujoco.MjModel.from_xml_string(
        model_xml(scene, dt, cone, solreffriction, contact_steps, d))
    data = mujoco.MjData(model)
    start = scene.start(dt)
    for name, (x, angle, v, w) in start.items():
        b = scene.by_name[name]
        if b.pin is not None:
            j = model.joint(f"{name}-h")
            data.qpos[j.qposadr[0]] = angle - b.angle
            data.qvel[j.dofadr[0]] = w
            continue
        p0 = (b.position[0] + b.shift[0], b.position[1] + b.shift[1])
        for axis, k in (("x", 0), ("y", 1)):
            j = model.joint(f"{name}-{axis}")
            data.qpos[j.qposadr[0]] = x[k] - p0[k]
            data.qvel[j.dofadr[0]] = v[k]
        if b.rotates:
            j = model.joint(f"{name}-h")
            data.qpos[j.qposadr[0]] = angle - b.angle
            data.qvel[j.dofadr[0]] = w
    mujoco.mj_forward(model, data)
    solved_at = {}

    def angle_of(name):
        b = scene.by_name[name]
        if not b.rotates:
            return b.angle
        j = model.joint(f"{name}-h")
        return b.angle + data.qpos[j.qposadr[0]]

    def step():
        solved_at.update((name, angle_of(name)) for name in start)
        mujoco.mj_step(model, data)
        return float(abs(data.efc_force[:data.nefc]).sum()) * dt

    def snapshot():
        out = {}
        for name in start:
            b = scene.by_name[name]
            if b.pin is not None:
                w = data.qvel[model.joint(f"{name}-h").dofadr[0]]
                cx, cy = data.xpos[model.body(name).id][:2]
                vx, vy = -w * (cy - b.pin[1]), w * (cx - b.pin[0])
                vx, vy = ic.reading(b, float(vx), float(vy), solved_at.get(name, angle_of(name)))
                out[name] = (vx, vy, float(w))
                continue
            vx = data.qvel[model.joint(f"{name}-x").dofadr[0]]
            vy = data.qvel[model.joint(f"{name}-y").dofadr[0]]
            w = data.qvel[model.joint(f"{name}-h").dofadr[0]] if b.rotates else 0.0
            out[name] = (float(vx), float(vy), float(w))
        return out

    states, steps, ended = ic.run_until_resolved(scene, step, snapshot, dt)
    zetas = {c["e_text"]: repr(mr.zeta_for(c["e"], dt, contact_steps, d)) for c in scene.contacts}
    return states, steps, ended, zetas


def main():
    version = mujoco.__version__
    engine = f"mujoco {version}"
    lines = []
    K, w0 = mr.stiffness()
    for scene in ic.load():
        states, steps, ended, zetas = run(scene)
        settings = dict(ic.common_settings(steps, ended), dt=DT_TEXT, float="f64",
                        integrator="RK4", cone="pyramidal", solver="Newton (default)",
                        contact=f"solref (-K, -2 zeta w0), K = w0^2 = {K!r}, "
                                f"{mr.CONTACT_STEPS} steps of undamped contact",
                        solimp=mr.solimp(), zeta_by_e=zetas, solreffriction="solref (default)",
                        rod_radius="1/200")
        lines.append(ic.claimed_line(scene, engine, states, settings))
        print(f"{scene.id}: {steps} steps ({ended})", file=sys.stderr)
    out = sys.argv[1] if len(sys.argv) > 1 else ic.OUT_DIR
    path = os.path.join(out, f"mujoco-{version}.jsonl")
    ic.write(path, lines)
    print(f"mujoco {version} (f64, RK4, dt 1e-5): {len(lines)} scenes -> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
