#!/usr/bin/env python3
"""Run the engine suite in Chipmunk via pymunk 7.3.1 (double precision) and write
OUTDIR/pymunk-7.3.1-f64.csv (default OUTDIR: tests/data/engines).

Set-up (the same as engines/rapier2d): zero gravity, sleeping off (pymunk's default); the rod a
box polygon of half extents (0.01 l, l), body mass M and moment I about its centre; the ball a
circle of radius 0.05 l, mass m; friction 0. Chipmunk multiplies the two shapes' elasticities,
so the rod gets elasticity e and the ball 1 (the pair's restitution is e). A pivot is a
PivotJoint to the space's static body (collide_bodies off). Default solver iterations (10).
J sums |total_impulse| of the rod's arbiters after every step.

The oblique scenes (issue 20) go to OUTDIR/pymunk-7.3.1-f64-oblique.csv: the ball gets (v0, v0t)
and its spin, the rod (rod-v, rod-vt); Chipmunk multiplies the shapes' frictions, so the rod gets
friction mu and the ball 1; the ball starts half a step from the rod's face (common.Scene.start_x).

Usage: python pymunk_run.py [OUTDIR]
"""

import os
import sys

import pymunk

import common


def kinetic(body):
    v = body.velocity
    return 0.5 * body.mass * v.dot(v) + 0.5 * body.moment * body.angular_velocity ** 2


def run(scene, dt):
    space = pymunk.Space()
    space.gravity = (0, 0)
    rod = pymunk.Body(mass=scene.M, moment=scene.I)
    rod_shape = pymunk.Poly.create_box(rod, size=(2 * scene.h, 2 * scene.l))
    rod_shape.friction, rod_shape.elasticity = scene.mu, scene.e
    rod.velocity = (scene.rod_v, scene.rod_vt)
    space.add(rod, rod_shape)
    if scene.pivot is not None:
        joint = pymunk.PivotJoint(space.static_body, rod, (0, scene.pivot))
        joint.collide_bodies = False
        space.add(joint)
    ball = pymunk.Body(mass=scene.m, moment=0.5 * scene.m * scene.r ** 2)
    ball.position = (scene.start_x(dt), scene.a)
    ball.velocity = (scene.v0, scene.v0t)
    ball.angular_velocity = scene.spin
    ball_shape = pymunk.Circle(ball, scene.r)
    ball_shape.friction, ball_shape.elasticity = 1, 1
    space.add(ball, ball_shape)
    before = kinetic(ball) + kinetic(rod)
    impulse = 0.0
    arbiters = []
    for _ in range(common.steps(dt)):
        space.step(dt)
        arbiters.clear()
        rod.each_arbiter(arbiters.append)
        impulse += sum(arb.total_impulse.length for arb in arbiters)
    vc = rod.velocity_at_local_point((0, 0))
    V = common.centre_velocity(scene, rod.angle, vc.x, vc.y)
    after = kinetic(ball) + kinetic(rod)
    if scene.oblique:
        Vt = common.along_rod(scene, rod.angle, vc.x, vc.y)
        return (ball.velocity.x, V, -rod.angular_velocity, ball.velocity.y, Vt,
                ball.angular_velocity, impulse, before, after)
    return (ball.velocity.x, V, -rod.angular_velocity, impulse, before, after)


def main():
    version = pymunk.version
    iters = pymunk.Space().iterations
    for oblique, make_row, header, suffix in (
            (False, common.row, common.HEADER, ""),
            (True, common.oblique_row, common.OBLIQUE_HEADER, "-oblique")):
        rows = []
        for scene in common.load_suite(oblique=oblique):
            for dt_text, dt in common.DTS:
                rows.append(make_row(scene, "pymunk", version, "f64", dt_text, iters,
                                     run(scene, dt)))
        path = os.path.join(common.out_dir(sys.argv), f"pymunk-{version}-f64{suffix}.csv")
        common.write(path, rows, header)
        print(f"pymunk {version} (Chipmunk {pymunk.chipmunk_version}): {len(rows)} runs -> "
              f"{path}", file=sys.stderr)


if __name__ == "__main__":
    main()
