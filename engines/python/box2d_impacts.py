#!/usr/bin/env python3
"""Run the planar impact suite (engines/impacts.jsonl) and every example of examples/impacts/ it
does not hold in Box2D 2.3.10 (pybox2d; single precision), one impact per scene, and write OUTDIR/box2d-2.3.10.jsonl (default OUTDIR:
tests/data/engines/impacts): each line the scene plus "claimed", the velocity and spin of every
moving body right after the impact.

Units: Box2D is tuned for objects of 0.1 to 10 m and puts a skin of b2_polygonRadius = 0.01 m
around every polygon and edge, so the world is the scene scaled by SCALE = 16 in length (lengths
and velocities times 16, spins and times unchanged, masses unchanged, inertias times 256). The
velocities read are divided by 16, which is exact in binary floating point. At this scale every
contact of the suite approaches at 16 m/s or more, above Box2D's compiled-in restitution
threshold b2_velocityThreshold = 1 m/s (at scale 1 the examples that approach at 1 would be
answered as e = 0). The skin is 0.01/16 = 1/1600 in scene units.

Set-up (impacts_common.py): no gravity, no damping, sleeping off, dt = 1/1000 s, 8 velocity and
3 position iterations (Box2D's usual values), warm starting and continuous physics on (the
defaults). Rods are polygon boxes of half thickness 0.005 m (plus the skin: a rod's surface lies
0.015 m = 0.015/16 scene units from its axis), boxes polygons, discs circles, a point mass a
circle of radius 1/100 (scene) with fixed rotation; every moving body gets the scene's mass,
centre and inertia through SetMassData after its fixture. A floor or wall is a static edge whose
surface (its core plus its skin) is the scene's line moved out by the moving body's skin; a peg a
static circle of radius 1/100 (scene). A pin is a b2RevoluteJoint to a static body
(collideConnected off).

Coefficients: Box2D takes the larger restitution and the geometric mean of the frictions of the
two fixtures, so every moving fixture gets restitution 0 and friction 1 and every static one
restitution e and friction mu^2 (max(0, e) = e exactly; sqrt(1 mu^2) is mu to within rounding);
every contact's friction and restitution are then set to the scene's e and mu exactly (as f32)
in a PreSolve callback (b2Contact::SetFriction/SetRestitution), which also covers contacts
between two moving bodies. The impulse counted for the stopping rule is the sum of the normal
and tangent impulses reported to PostSolve in each step.

Usage: python box2d_impacts.py [OUTDIR]
"""

import math
import os
import sys

import Box2D as B

import impacts_common as ic

VERSION = "2.3.10"
SCALE = 16.0
ROD_HALF_THICKNESS = 0.005          # m, the polygon's core
# Diagnostics only (never for the fixtures; see impacts_common): a larger scale shrinks the skin
# in scene units, a thinner core the rod.
SCALE = float(os.environ.get("IMPACTS_BOX2D_SCALE", SCALE))
ROD_HALF_THICKNESS = float(os.environ.get("IMPACTS_BOX2D_ROD_HALF_THICKNESS", ROD_HALF_THICKNESS))
SKIN = B.b2_polygonRadius            # m
VELOCITY_ITERATIONS, POSITION_ITERATIONS = 8, 3
SKINS = {"rod": (ROD_HALF_THICKNESS + SKIN) / SCALE, "box": SKIN / SCALE}


class Listener(B.b2ContactListener):
    def __init__(self, coefficients):
        super().__init__()
        self.coefficients = coefficients
        self.impulse = 0.0
        self.unexpected = []

    def PreSolve(self, contact, old_manifold):
        key = frozenset((contact.fixtureA.userData, contact.fixtureB.userData))
        if key in self.coefficients:
            contact.restitution, contact.friction = self.coefficients[key]
        else:
            self.unexpected.append(sorted(key))

    def PostSolve(self, contact, impulse):
        self.impulse += sum(abs(x) for x in impulse.normalImpulses[:impulse.count])
        self.impulse += sum(abs(x) for x in impulse.tangentImpulses[:impulse.count])


def scaled(p):
    return (p[0] * SCALE, p[1] * SCALE)


def build(scene, dt):
    listener = Listener(scene.coefficients)
    world = B.b2World(gravity=(0, 0), doSleep=False, contactListener=listener)
    ground = world.CreateStaticBody(position=(0, 0))
    bodies = {}
    for name, (x, angle, v, w) in scene.start(dt).items():
        b = scene.by_name[name]
        body = world.CreateDynamicBody(position=scaled(x), angle=angle, linearVelocity=scaled(v),
                                       angularVelocity=w if b.rotates else 0.0,
                                       fixedRotation=not b.rotates, allowSleep=False,
                                       linearDamping=0.0, angularDamping=0.0)
        shape = b.local_shape()
        if shape[0] == "segment":
            h = shape[2][0] * SCALE
            fixture = body.CreatePolygonFixture(box=(h, ROD_HALF_THICKNESS), density=1.0)
        elif shape[0] == "poly":
            fixture = body.CreatePolygonFixture(vertices=[scaled(p) for p in shape[1]], density=1.0)
        else:
            fixture = body.CreateCircleFixture(radius=shape[1] * SCALE, density=1.0)
        fixture.friction, fixture.restitution = 1.0, 0.0
        body.massData = B.b2MassData(mass=b.mass, center=(0, 0),
                                     I=b.inertia * SCALE * SCALE if b.rotates else 0.0)
        fixture.userData = name
        bodies[name] = body
        if b.pin is not None:
            world.CreateRevoluteJoint(bodyA=ground, bodyB=body, anchor=scaled(b.pin),
                                      collideConnected=False)
    for st in scene.statics:
        e, mu = next(val for key, val in scene.coefficients.items() if st.tag in key)
        if st.kind == "halfplane":
            (px, py), (nx, ny) = st.a, st.b
            core = (px * SCALE - SKIN * nx, py * SCALE - SKIN * ny)
            half = 50.0 * SCALE
            tx, ty = -ny, nx
            fixture = ground.CreateEdgeFixture(vertices=[(core[0] - half * tx, core[1] - half * ty),
                                                         (core[0] + half * tx, core[1] + half * ty)])
        else:
            fixture = ground.CreateCircleFixture(radius=st.b * SCALE, pos=scaled(st.a))
        fixture.friction, fixture.restitution = mu * mu, e
        fixture.userData = st.tag
    return world, bodies, listener


def run(scene, dt=ic.DT):
    world, bodies, listener = build(scene, dt)

    # Box2D solves velocities at the step's starting pose and integrates the positions after, so
    # a velocity read after a step belongs to the pose before it (for a pinned body's reading)
    solved_at = {name: b.angle for name, b in bodies.items()}

    def step():
        solved_at.update((name, b.angle) for name, b in bodies.items())
        listener.impulse = 0.0
        world.Step(dt, VELOCITY_ITERATIONS, POSITION_ITERATIONS)
        return listener.impulse

    def snapshot():
        return {name: (*ic.reading(scene.by_name[name], b.linearVelocity[0] / SCALE,
                                   b.linearVelocity[1] / SCALE, solved_at[name]),
                       b.angularVelocity)
                for name, b in bodies.items()}

    states, steps, ended = ic.run_until_resolved(scene, step, snapshot, dt)
    return states, steps, ended, listener.unexpected


def main():
    engine = f"box2d {VERSION}"
    lines = []
    for scene in ic.load(skins=SKINS):
        states, steps, ended, unexpected = run(scene)
        settings = dict(ic.common_settings(steps, ended), float="f32", scale=repr(SCALE),
                        velocity_iterations=VELOCITY_ITERATIONS,
                        position_iterations=POSITION_ITERATIONS, warm_start="on",
                        velocity_threshold="1 m/s = 1/16 scene units",
                        rod_half_thickness=f"{ROD_HALF_THICKNESS!r} m + skin {SKIN!r} m",
                        coefficients="PreSolve sets each contact's restitution and friction")
        lines.append(ic.claimed_line(scene, engine, states, settings))
        note = f" ({ended})"
        if unexpected:
            note += f" (contacts outside the scene: {unexpected[0]})"
        print(f"{scene.id}: {steps} steps{note}", file=sys.stderr)
    out = sys.argv[1] if len(sys.argv) > 1 else ic.OUT_DIR
    path = os.path.join(out, f"box2d-{VERSION}.jsonl")
    ic.write(path, lines)
    print(f"box2d {B.__version__} (f32): {len(lines)} scenes -> {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
