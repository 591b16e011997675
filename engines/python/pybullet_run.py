#!/usr/bin/env python3
"""Run the engine suite in Bullet via pybullet 3.2.7 (double precision) and write
OUTDIR/pybullet-3.2.7-f64.csv (default OUTDIR: tests/data/engines), with two engine variants:

  pybullet        what a user writes first: default engine parameters (restitution velocity
                  threshold, split impulse, contact slop and warm starting as shipped), bodies
                  in pybullet's default (reduced-coordinate multibody) form; only damping and
                  friction switched off.
  pybullet-tuned  the settings the Bullet maintainer gave for proper restitution in
                  bulletphysics/bullet3#3094: restitutionVelocityThreshold=0,
                  warmStartingFactor=0, useSplitImpulse=True, contactSlop=0,
                  enableConeFriction=False, useMaximalCoordinates=True and
                  contactProcessingThreshold=0 on both bodies.

Set-up (the same as engines/rapier2d, in the plane z = 0): zero gravity; sleeping disabled; the
rod a box of half extents (0.01 l, l, 0.01 l), the ball a sphere of radius 0.05 l;
changeDynamics sets mass AND localInertiaDiagonal together (localInertiaDiagonal alone resets
the mass to 0: a pybullet trap), the rod's inertia is I about every axis (only z matters, the
motion stays in the plane); lateral, spinning and rolling friction 0; linear and angular
damping 0 (pybullet's default is 0.04). Bullet multiplies restitutions, so the rod gets e and
the ball 1. A pivot is a JOINT_POINT2POINT constraint to a fixed (mass 0, shapeless) body at (0, p, 0). J sums
normalForce * dt of getContactPoints (pybullet reports the impulse divided by the step).
Default solver iterations (50).

Usage: python pybullet_run.py [OUTDIR]
"""

import math
import os
import sys

import pybullet as pb

import common

VERSION = "3.2.7"  # pybullet has no __version__; this is the pinned wheel (requirements.txt)

TUNED_ENGINE = dict(restitutionVelocityThreshold=0, warmStartingFactor=0, useSplitImpulse=True,
                    contactSlop=0, enableConeFriction=False)


def kinetic(body, mass, inertia):
    lin, ang = pb.getBaseVelocity(body)
    return 0.5 * mass * sum(x * x for x in lin) + 0.5 * inertia * ang[2] ** 2


def run(scene, dt, tuned):
    pb.resetSimulation()
    pb.setGravity(0, 0, 0)
    pb.setPhysicsEngineParameter(fixedTimeStep=dt, numSubSteps=0)
    if tuned:
        pb.setPhysicsEngineParameter(**TUNED_ENGINE)
    body_options = dict(useMaximalCoordinates=True) if tuned else {}
    rod_shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=(scene.h, scene.l, scene.h))
    rod = pb.createMultiBody(scene.M, rod_shape, -1, basePosition=(0, 0, 0), **body_options)
    ball_shape = pb.createCollisionShape(pb.GEOM_SPHERE, radius=scene.r)
    ball = pb.createMultiBody(scene.m, ball_shape, -1, basePosition=(scene.start_x(dt), scene.a, 0),
                              **body_options)
    ball_inertia = 0.4 * scene.m * scene.r ** 2
    for body, mass, inertia, restitution in ((rod, scene.M, scene.I, scene.e),
                                             (ball, scene.m, ball_inertia, 1.0)):
        options = dict(mass=mass, localInertiaDiagonal=(inertia, inertia, inertia),
                       restitution=restitution, lateralFriction=0, spinningFriction=0,
                       rollingFriction=0, linearDamping=0, angularDamping=0,
                       activationState=pb.ACTIVATION_STATE_DISABLE_SLEEPING)
        if tuned:
            options["contactProcessingThreshold"] = 0
        pb.changeDynamics(body, -1, **options)
    if scene.pivot is not None:
        anchor = pb.createMultiBody(0, -1, -1, basePosition=(0, scene.pivot, 0), **body_options)
        pb.createConstraint(rod, -1, anchor, -1, pb.JOINT_POINT2POINT, (0, 0, 0),
                            (0, scene.pivot, 0), (0, 0, 0))
    pb.resetBaseVelocity(ball, (scene.v0, 0, 0), (0, 0, 0))
    before = kinetic(ball, scene.m, ball_inertia) + kinetic(rod, scene.M, scene.I)
    impulse = 0.0
    for _ in range(common.steps(dt)):
        pb.stepSimulation()
        impulse += sum(c[9] for c in pb.getContactPoints(ball, rod)) * dt
    (vx, _, _), _ = pb.getBaseVelocity(ball)
    (cx, cy, _), (_, _, wz) = pb.getBaseVelocity(rod)
    _, orientation = pb.getBasePositionAndOrientation(rod)
    angle = pb.getEulerFromQuaternion(orientation)[2]
    V = common.centre_velocity(scene, angle, cx, cy)
    after = kinetic(ball, scene.m, ball_inertia) + kinetic(rod, scene.M, scene.I)
    return (vx, V, -wz, impulse, before, after)


def main():
    pb.connect(pb.DIRECT)
    iters = pb.getPhysicsEngineParameters()["numSolverIterations"]
    rows = []
    for engine, tuned in (("pybullet", False), ("pybullet-tuned", True)):
        for scene in common.load_suite():
            for dt_text, dt in common.DTS:
                rows.append(common.row(scene, engine, VERSION, "f64", dt_text, iters,
                                       run(scene, dt, tuned)))
    path = os.path.join(common.out_dir(sys.argv), f"pybullet-{VERSION}-f64.csv")
    common.write(path, rows)
    print(f"pybullet {VERSION}: {len(rows)} runs -> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
