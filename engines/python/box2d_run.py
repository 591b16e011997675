#!/usr/bin/env python3
"""Run the engine suite in Box2D 2.3 (pip `box2d` 2.3.10, float32 inside) and write
OUTDIR/box2d-2.3.10-f32.csv (default OUTDIR: tests/data/engines).

Set-up (the same as engines/rapier2d): zero gravity, sleeping off; the rod a box of half extents
(0.01 l, l) with explicit mass data (M, I about its centre); the ball a circle of radius 0.05 l,
mass m; friction 0 and restitution e on both fixtures (Box2D mixes restitution by max, so the
pair's restitution is e); a pivot is a b2RevoluteJoint to a static body (collideConnected off).
Default iterations: 8 velocity, 3 position. J sums the normal impulses of PostSolve.
Box2D 2.3's compile-time b2_velocityThreshold (1 m/s) makes contacts slower than that
inelastic; it is left as shipped: that is what a user of the package gets.

Usage: python box2d_run.py [OUTDIR]
"""

import os
import sys

import Box2D
from Box2D import (b2CircleShape, b2ContactListener, b2FixtureDef, b2MassData, b2PolygonShape,
                   b2World)

import common

VELOCITY_ITERATIONS, POSITION_ITERATIONS = 8, 3


class ImpulseSum(b2ContactListener):
    def __init__(self):
        super().__init__()
        self.total = 0.0

    def PostSolve(self, contact, impulse):
        self.total += sum(impulse.normalImpulses[: contact.manifold.pointCount])


def kinetic(body):
    v = body.linearVelocity
    # inertia about the centre of mass (Box2D's body.inertia is about the body origin)
    i_cm = body.inertia - body.mass * body.localCenter.lengthSquared
    return 0.5 * body.mass * (v.x * v.x + v.y * v.y) + 0.5 * i_cm * body.angularVelocity ** 2


def run(scene, dt):
    listener = ImpulseSum()
    world = b2World(gravity=(0, 0), doSleep=False, contactListener=listener)
    rod = world.CreateDynamicBody(position=(0, 0), angle=0)
    rod.CreateFixture(b2FixtureDef(shape=b2PolygonShape(box=(scene.h, scene.l)), density=1,
                                   friction=0, restitution=scene.e))
    rod.massData = b2MassData(mass=scene.M, center=(0, 0), I=scene.I)
    rod.sleepingAllowed = False
    if scene.pivot is not None:
        ground = world.CreateStaticBody(position=(0, 0))
        world.CreateRevoluteJoint(bodyA=ground, bodyB=rod, anchor=(0, scene.pivot),
                                  collideConnected=False)
    ball = world.CreateDynamicBody(position=(scene.start_x(dt), scene.a))
    ball.CreateFixture(b2FixtureDef(shape=b2CircleShape(radius=scene.r), density=1, friction=0,
                                    restitution=scene.e))
    ball.massData = b2MassData(mass=scene.m, center=(0, 0), I=0.5 * scene.m * scene.r ** 2)
    ball.sleepingAllowed = False
    ball.linearVelocity = (scene.v0, 0)
    before = kinetic(ball) + kinetic(rod)
    for _ in range(common.steps(dt)):
        world.Step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS)
    vc = rod.GetLinearVelocityFromLocalPoint((0, 0))
    V = common.centre_velocity(scene, rod.angle, vc.x, vc.y)
    return (ball.linearVelocity.x, V, -rod.angularVelocity, listener.total, before,
            kinetic(ball) + kinetic(rod))


def main():
    version = Box2D.__version__
    rows = []
    for scene in common.load_suite():
        for dt_text, dt in common.DTS:
            rows.append(common.row(scene, "box2d", version, "f32", dt_text, VELOCITY_ITERATIONS,
                                   run(scene, dt), single=True))
    path = os.path.join(common.out_dir(sys.argv), f"box2d-{version}-f32.csv")
    common.write(path, rows)
    print(f"box2d {version}: {len(rows)} runs -> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
