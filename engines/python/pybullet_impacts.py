#!/usr/bin/env python3
"""Run the planar impact suite (engines/impacts.jsonl) and every example of examples/impacts/ it
does not hold in Bullet via pybullet 3.2.7 (double precision), one impact per scene, and write
OUTDIR/pybullet-3.2.7.jsonl (default OUTDIR: tests/data/engines/impacts): each line the scene
plus "claimed", the velocity and spin of every moving body right after the impact.

The plane: the scene's (x, y) is the world's (x, z), extruded along y, as the oracle's bullet-3
profile assumes (tests/oracles/engine-laws.md section 4: a frictional contact without slip gets
its friction row along btPlaneSpace1(n), the out-of-plane y axis). A scene angle theta is the
rotation -theta about y (it turns x towards z), so the scene's omega is minus the world's
angular velocity about y. Every moving body is a maximal-coordinate rigid body
(useMaximalCoordinates) with the scene's mass and the inertia diagonal (0, I, 0): Bullet takes a
zero principal moment as infinite (btRigidBody::setMassProps), so the body turns only about y and
the motion stays in the plane exactly (a point mass gets (0, 0, 0)).

Set-up (impacts_common.py): no gravity, no damping, sleeping off, dt = 1/1000 s, pybullet's
default 50 solver iterations (least-squares residual exit 1e-7), and the settings the Bullet
maintainer gave for restitution (bulletphysics/bullet3#3094; pybullet_run.py's tuned variant):
restitutionVelocityThreshold 0, warmStartingFactor 0, useSplitImpulse on, contactSlop 0, cone
friction off, contactProcessingThreshold 0 on every body (only points at distance <= 0 are
solved). Also contactERP 0: the bodies start 0.99 steps before the scene, so the contact is
solved in the step after it closes at a penetration of 1/100 of a step's travel, and Bullet
would add erp2 * depth / dt (8e-4 of the approach speed at pybullet's erp2 = 0.08) to the
contact's target velocity (a shallow penetration goes into the velocity even with split impulse,
btSequentialImpulseConstraintSolver::setupContactConstraint); with contactERP 0 the target is
Newton's -e uN0, as in the profile (position correction is not the impact law). --erp keeps
pybullet's 0.08 (a diagnostic, written to pybullet-3.2.7-erp.jsonl).

Shapes: a rod is a capsule of radius 1/200 along its axis (impacts_common's thickness, the same
as pymunk's segment); a box a box of the scene's width and height and depth 2 * DEPTH_HALF (thin,
so that the two ends of an edge are within Bullet's contact breaking threshold 0.02 and the
manifold keeps one point per scene contact); a disc a sphere; a point mass a sphere of radius
1/100 with zero inertia. A floor or wall is a static plane (GEOM_PLANE) whose surface is the
scene's line moved away from a rod by its radius, or, in a scene with a moving box, a static box
of half extents (50, 1, 1) whose face is that line (Bullet's convex-plane algorithm adds one
point a step, the support vertex, so a box landing flat on a plane meets its two corners in two
steps, one after the other: box-lands-flat came out 0.15 from the simultaneous answer and 1.5e-4
from sequential:2,1; box-box clipping gives both corners in one step); a peg a static sphere of
radius 1/100. A pin
is a JOINT_POINT2POINT constraint to a static shapeless body at the pin.

Coefficients: Bullet multiplies the two bodies' restitutions and frictions. Every moving body
gets sqrt(e) and sqrt(mu) of the scene's contacts between two moving bodies (1 if there are
none), every static body the contact's e and mu divided by the moving body's: the product of a
pair is the contact's e and mu (to rounding; the scenes never need two coefficient sets for the
moving bodies). The impulse counted for the stopping rule is (|normal force| + |lateral
frictions|) * dt of getContactPoints after each step.

Usage: python pybullet_impacts.py [--erp] [OUTDIR]
"""

import math
import os
import sys

import pybullet as pb

import impacts_common as ic

VERSION = "3.2.7"  # pybullet has no __version__; the pinned wheel (requirements.txt)
ENGINE = dict(restitutionVelocityThreshold=0, warmStartingFactor=0, useSplitImpulse=True,
              contactSlop=0, enableConeFriction=False)
DEPTH_HALF = 0.001


def world(p):
    return (p[0], 0.0, p[1])


def y_rotation(angle):
    """The quaternion of the scene angle `angle` (a rotation by -angle about the world y)."""
    return pb.getQuaternionFromEuler((0.0, -angle, 0.0))


def scene_angle(quaternion):
    qx, qy, qz, qw = quaternion
    return -2.0 * math.atan2(qy, qw)


def coefficients(scene):
    """(moving (e, mu), {static tag: (e, mu)}) whose products are every contact's e and mu."""
    pairs = {}
    for key, value in scene.coefficients.items():
        statics = [t for t in key if t not in scene.by_name]
        pairs.setdefault("static" if statics else "moving", []).append((statics, value))
    moving = sorted(set(v for _, v in pairs.get("moving", [])))
    if len(moving) > 1:
        raise SystemExit(f"error: {scene.id}: two coefficient sets between moving bodies")
    me, mmu = (math.sqrt(moving[0][0]), math.sqrt(moving[0][1])) if moving else (1.0, 1.0)
    static = {}
    for statics, (e, mu) in pairs.get("static", []):
        if (e and not me) or (mu and not mmu):
            raise SystemExit(f"error: {scene.id}: no product of coefficients gives ({e}, {mu})")
        static[statics[0]] = (e / me if e else 0.0, mu / mmu if mu else 0.0)
    return (me, mmu), static


def build(scene, dt, erp):
    pb.resetSimulation()
    pb.setGravity(0, 0, 0)
    pb.setPhysicsEngineParameter(fixedTimeStep=dt, numSubSteps=0, **ENGINE)
    if not erp:
        pb.setPhysicsEngineParameter(contactERP=0)
    (me, mmu), static = coefficients(scene)
    bodies = {}
    for name, (x, angle, v, w) in scene.start(dt).items():
        b = scene.by_name[name]
        shape = b.local_shape()
        if shape[0] == "segment":
            length = shape[2][0] - shape[1][0]
            col = pb.createCollisionShape(pb.GEOM_CAPSULE, radius=shape[3], height=length,
                                          collisionFrameOrientation=pb.getQuaternionFromEuler(
                                              (0.0, math.pi / 2, 0.0)))
        elif shape[0] == "poly":
            (x0, y0), _, (x2, y2), _ = shape[1]
            col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=(x2, DEPTH_HALF, y2))
        else:
            col = pb.createCollisionShape(pb.GEOM_SPHERE, radius=shape[1])
        body = pb.createMultiBody(b.mass, col, -1, basePosition=world(x),
                                  baseOrientation=y_rotation(angle), useMaximalCoordinates=True)
        inertia = (0.0, b.inertia, 0.0) if b.rotates else (0.0, 0.0, 0.0)
        pb.changeDynamics(body, -1, mass=b.mass, localInertiaDiagonal=inertia, restitution=me,
                          lateralFriction=mmu, spinningFriction=0, rollingFriction=0,
                          linearDamping=0, angularDamping=0, contactProcessingThreshold=0,
                          activationState=pb.ACTIVATION_STATE_DISABLE_SLEEPING)
        pb.resetBaseVelocity(body, world(v), (0.0, -(w if b.rotates else 0.0), 0.0))
        bodies[name] = body
        if b.pin is not None:
            # the pin in the body's frame at the start pose
            dx, dz = b.pin[0] - x[0], b.pin[1] - x[1]
            c, s = math.cos(angle), math.sin(angle)
            local = (c * dx + s * dz, 0.0, -s * dx + c * dz)
            anchor = pb.createMultiBody(0, -1, -1, basePosition=world(b.pin),
                                        useMaximalCoordinates=True)
            pb.createConstraint(body, -1, anchor, -1, pb.JOINT_POINT2POINT, (0, 0, 0), local,
                                (0, 0, 0))
    statics = []
    for st in scene.statics:
        e, mu = static[st.tag]
        if st.kind == "halfplane" and any(b.shape == "box" for b in scene.moving()):
            (px, py), (nx, ny) = st.a, st.b
            col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=(50.0, 1.0, 1.0))
            centre = (px - nx, py - ny)
            body = pb.createMultiBody(0, col, -1, basePosition=world(centre),
                                      baseOrientation=y_rotation(math.atan2(ny, nx) - math.pi / 2),
                                      useMaximalCoordinates=True)
        elif st.kind == "halfplane":
            (px, py), (nx, ny) = st.a, st.b
            col = pb.createCollisionShape(pb.GEOM_PLANE, planeNormal=(nx, 0.0, ny))
            body = pb.createMultiBody(0, col, -1, basePosition=world((px, py)),
                                      useMaximalCoordinates=True)
        else:
            col = pb.createCollisionShape(pb.GEOM_SPHERE, radius=st.b)
            body = pb.createMultiBody(0, col, -1, basePosition=world(st.a),
                                      useMaximalCoordinates=True)
        pb.changeDynamics(body, -1, restitution=e, lateralFriction=mu, spinningFriction=0,
                          rollingFriction=0, contactProcessingThreshold=0)
        statics.append(body)
    return bodies, statics


def run(scene, dt=ic.DT, erp=False):
    bodies, statics = build(scene, dt, erp)
    ids = set(bodies.values())
    # a pinned body's velocity belongs to the pose before the step's integration (Bullet solves
    # at the step's starting pose)
    solved_at = {}

    def angle_of(body):
        return scene_angle(pb.getBasePositionAndOrientation(body)[1])

    def step():
        solved_at.update((name, angle_of(b)) for name, b in bodies.items())
        pb.stepSimulation()
        total = 0.0
        for c in pb.getContactPoints():
            if c[1] in ids or c[2] in ids:
                total += abs(c[9]) + abs(c[10]) + abs(c[12])
        return total * dt

    def snapshot():
        out = {}
        for name, b in bodies.items():
            (vx, vy, vz), (wx, wy, wz) = pb.getBaseVelocity(b)
            if abs(vy) > 1e-9 or abs(wx) > 1e-9 or abs(wz) > 1e-9:
                raise SystemExit(f"error: {scene.id}: {name} left the plane ({vy}, {wx}, {wz})")
            angle = solved_at.get(name, angle_of(b))
            out[name] = (*ic.reading(scene.by_name[name], vx, vz, angle), -wy)
        return out

    states, steps, ended = ic.run_until_resolved(scene, step, snapshot, dt)
    return states, steps, ended


def main():
    args = sys.argv[1:]
    erp = "--erp" in args
    args = [a for a in args if a != "--erp"]
    pb.connect(pb.DIRECT)
    params = pb.getPhysicsEngineParameters()
    iterations = params["numSolverIterations"]
    engine = f"pybullet {VERSION}"
    lines = []
    for scene in ic.load():
        states, steps, ended = run(scene, erp=erp)
        settings = dict(ic.common_settings(steps, ended), float="f64", iterations=iterations,
                        plane="xz", bodies="maximal coordinates, inertia (0, I, 0)",
                        contactERP=("pybullet's" if erp else "0"), rod_radius="1/200",
                        box_depth=repr(2 * DEPTH_HALF),
                        coefficients="products: moving bodies sqrt of the moving pairs', "
                        "statics the rest",
                        **{k: (v if not isinstance(v, bool) else ("on" if v else "off"))
                           for k, v in ENGINE.items()}, contactProcessingThreshold=0)
        lines.append(ic.claimed_line(scene, engine, states, settings))
        print(f"{scene.id}: {steps} steps ({ended})", file=sys.stderr)
    out = args[0] if args else ic.OUT_DIR
    path = os.path.join(out, f"pybullet-{VERSION}{'-erp' if erp else ''}.jsonl")
    ic.write(path, lines)
    print(f"pybullet {VERSION} (f64, {iterations} iterations): {len(lines)} scenes -> {path}",
          file=sys.stderr)


if __name__ == "__main__":
    main()
