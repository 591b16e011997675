#!/usr/bin/env python3
"""Run the planar impact suite (engines/impacts.jsonl) and every example of examples/impacts/ it
does not hold in Chipmunk via pymunk 7.3.1 (double precision), one impact per scene, and write OUTDIR/pymunk-7.3.1.jsonl (default OUTDIR:
tests/data/engines/impacts): each line the scene plus "claimed", the velocity and spin of every
moving body right after the impact.

Set-up (impacts_common.py): no gravity, no damping, sleeping off (pymunk's default), dt = 1/1000,
default solver iterations (10), default collision slop and bias. Rods are segments of radius
1/200 (length 2), boxes polygons of radius 0, discs circles; a point mass a circle of radius
1/100 with an infinite moment (it cannot turn); every moving body gets the scene's mass and
moment. A floor or wall is a static segment of radius 1 whose surface is the scene's line (moved
down by a rod's radius under a rod); a peg a static circle of radius 1/100. A pin is a
PivotJoint to the space's static body (collide_bodies off).

Coefficients: Chipmunk multiplies the two shapes' elasticities and frictions, so every moving
shape gets elasticity 1 and friction 1 and every static shape the contact's e and mu: the pair's
product is exactly e and mu. A contact between two moving bodies (product 1) gets its e and mu
set on the arbiter in a pre_solve callback (pymunk's documented override), which is also done for
the static pairs (the same values). The impulse counted for the stopping rule is
|total_impulse| of every arbiter after each step.

Usage: python pymunk_impacts.py [OUTDIR]
"""

import math
import os
import sys

import pymunk

import impacts_common as ic


def build(scene, dt):
    space = pymunk.Space()
    space.gravity = (0, 0)
    space.damping = 1.0
    tags = {}
    bodies = {}
    for name, (x, angle, v, w) in scene.start(dt).items():
        b = scene.by_name[name]
        body = pymunk.Body(mass=b.mass, moment=b.inertia if b.rotates else math.inf)
        body.position, body.angle = x, angle
        body.velocity, body.angular_velocity = v, (w if b.rotates else 0.0)
        shape = b.local_shape()
        if shape[0] == "segment":
            s = pymunk.Segment(body, shape[1], shape[2], shape[3])
        elif shape[0] == "poly":
            s = pymunk.Poly(body, shape[1], radius=0)
        else:
            s = pymunk.Circle(body, shape[1])
        s.elasticity, s.friction = 1.0, 1.0
        space.add(body, s)
        tags[s] = name
        bodies[name] = body
        if b.pin is not None:
            joint = pymunk.PivotJoint(space.static_body, body, b.pin)
            joint.collide_bodies = False
            space.add(joint)
    for st in scene.statics:
        if st.kind == "halfplane":
            (px, py), (nx, ny) = st.a, st.b
            r, half = 1.0, 50.0
            cx, cy = px - r * nx, py - r * ny             # the segment's axis, r under the edge
            tx, ty = -ny, nx
            s = pymunk.Segment(space.static_body, (cx - half * tx, cy - half * ty),
                               (cx + half * tx, cy + half * ty), r)
        else:
            s = pymunk.Circle(space.static_body, st.b, offset=st.a)
        e, mu = next(val for key, val in scene.coefficients.items() if st.tag in key)
        s.elasticity, s.friction = e, mu
        space.add(s)
        tags[s] = st.tag
    unexpected = []

    def pre_solve(arbiter, space_, data):
        key = frozenset(tags[s] for s in arbiter.shapes)
        if key in scene.coefficients:
            arbiter.restitution, arbiter.friction = scene.coefficients[key]
        else:
            unexpected.append(sorted(key))

    space.on_collision(pre_solve=pre_solve)
    return space, bodies, unexpected


def run(scene, dt=ic.DT):
    space, bodies, unexpected = build(scene, dt)
    assert space.iterations == 10

    def step():
        space.step(dt)
        arbiters = []
        for body in bodies.values():
            body.each_arbiter(arbiters.append)
        return sum(a.total_impulse.length for a in arbiters)

    def snapshot():
        return {name: (*ic.reading(scene.by_name[name], b.velocity.x, b.velocity.y, b.angle),
                       b.angular_velocity) for name, b in bodies.items()}

    states, steps, ended = ic.run_until_resolved(scene, step, snapshot, dt)
    return states, steps, ended, unexpected


def main():
    version = pymunk.version
    engine = f"pymunk {version}"
    lines = []
    for scene in ic.load():
        states, steps, ended, unexpected = run(scene)
        settings = dict(ic.common_settings(steps, ended), float="f64", iterations=10,
                        collision_slop="0.1", warm_start="on", rod_radius="1/200",
                        point_radius="1/100", coefficients="static shapes e and mu, moving 1; "
                        "pre_solve sets the arbiter's restitution and friction")
        lines.append(ic.claimed_line(scene, engine, states, settings))
        note = f" ({ended})"
        if unexpected:
            note += f" (contacts outside the scene: {unexpected[0]})"
        print(f"{scene.id}: {steps} steps{note}", file=sys.stderr)
    out = sys.argv[1] if len(sys.argv) > 1 else ic.OUT_DIR
    path = os.path.join(out, f"pymunk-{version}.jsonl")
    ic.write(path, lines)
    print(f"pymunk {version} (Chipmunk {pymunk.chipmunk_version}): {len(lines)} scenes -> {path}",
          file=sys.stderr)


if __name__ == "__main__":
    main()
