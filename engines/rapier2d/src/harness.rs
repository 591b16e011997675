// One Rapier run of one scene. This file is compiled twice, by `include!` in `main.rs`: once
// against `rapier2d` (Real = f32) and once against `rapier2d-f64` (Real = f64), so both
// precisions run exactly the same set-up.

use crate::suite::{Ratio, Rod, Scene};
use crate::{Geometry, Outcome, PivotModel, Settings};

fn real(r: Ratio) -> Real {
    r.num as Real / r.den as Real
}

/// The rod's moment of inertia about its centre, in the engine's float.
fn rod_inertia(scene: &Scene) -> Real {
    let big_m = real(scene.big_m);
    let l = real(scene.l);
    match scene.rod {
        Rod::Uniform => big_m * l * l / 3.0,
        Rod::Dumbbell => big_m * l * l,
        Rod::RadiusOfGyration(r) => big_m * real(r) * real(r),
        Rod::Inertia(i) => real(i),
    }
}

/// Kinetic energy of a body from the engine's own state (both velocity components and spin).
fn kinetic_energy(body: &RigidBody) -> Real {
    let v = body.linvel();
    let inertia = body.mass_properties().local_mprops.principal_inertia();
    0.5 * body.mass() * v.dot(v) + 0.5 * inertia * body.angvel() * body.angvel()
}

/// Runs `scene` with `settings`; the pivot (if any) is modelled as `model` says.
pub fn run(scene: &Scene, settings: Settings, model: PivotModel) -> Outcome {
    let dt = real(settings.dt);
    let m = real(scene.m);
    let big_m = real(scene.big_m);
    let l = real(scene.l);
    let a = real(scene.a);
    let v0 = real(scene.v0);
    let e = real(scene.e);
    let inertia = rod_inertia(scene);
    let half_thickness = l * real(Geometry::HALF_THICKNESS_PER_L);
    // The oblique scenes state the ball's radius (l/20 in the suite, the same as the others').
    let radius = match scene.oblique {
        Some(o) => real(o.radius),
        None => l * real(Geometry::BALL_RADIUS_PER_L),
    };
    // Oblique: the ball slides along the rod and spins, friction mu at the contact (both
    // colliders mu, combined by their average), the rod drifts. Zero for the other scenes.
    let zero = Ratio { num: 0, den: 1 };
    let o = scene.oblique;
    let [v0t, mu, spin, rod_v, rod_vt] = [
        o.map_or(zero, |o| o.v0t),
        o.map_or(zero, |o| o.mu),
        o.map_or(zero, |o| o.spin),
        o.map_or(zero, |o| o.rod_v),
        o.map_or(zero, |o| o.rod_vt),
    ]
    .map(real);

    let mut world = PhysicsWorld {
        gravity: Vector::ZERO,
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = dt;
    world.integration_parameters.num_solver_iterations = settings.iters;

    // The rod: a thin cuboid along y, centred at the origin, explicit mass properties (so the
    // box's thickness does not enter). A rod pivoted by locked translations carries its mass
    // properties about the pivot: the centre of mass at the pivot, inertia I_p = I + M p^2.
    let pivot = scene.pivot.map(real);
    let rod_mass_properties = match (model, pivot) {
        (PivotModel::LockedTranslations, Some(p)) => {
            MassProperties::new(Vector::new(0.0, p), big_m, inertia + big_m * p * p)
        }
        _ => MassProperties::new(Vector::ZERO, big_m, inertia),
    };
    let mut rod_body = RigidBodyBuilder::dynamic()
        .can_sleep(false)
        .linvel(Vector::new(rod_v, rod_vt));
    if let (PivotModel::LockedTranslations, Some(_)) = (model, pivot) {
        rod_body = rod_body.lock_translations();
    }
    let rod_collider = ColliderBuilder::cuboid(half_thickness, l)
        .mass_properties(rod_mass_properties)
        .friction(mu)
        .friction_combine_rule(CoefficientCombineRule::Average)
        .restitution(e)
        .restitution_combine_rule(CoefficientCombineRule::Average);
    let (rod, rod_collider) = world.insert(rod_body, rod_collider);

    if let (PivotModel::RevoluteJoint, Some(p)) = (model, pivot) {
        let ground = world.bodies.insert(RigidBodyBuilder::fixed());
        let joint = RevoluteJointBuilder::new()
            .local_anchor1(Vector::new(0.0, p))
            .local_anchor2(Vector::new(0.0, p))
            .contacts_enabled(false);
        world.impulse_joints.insert(ground, rod, joint, true);
    }

    // The ball: starts 3.5 steps (at the approach speed) before touching the rod's face, level
    // with the impact point. An oblique ball also slides along the rod while it approaches, and
    // Rapier's speculative contact may take its lever arm from any step of the approach (at
    // dt = 1/1000 from the first), so an oblique ball starts half a step from the face: the
    // impact point is then a to within half a step's slide, |v0t - Vt0| dt/2.
    let approach_steps = if scene.oblique.is_some() {
        0.5
    } else {
        real(Geometry::APPROACH_STEPS)
    };
    let gap = (v0 - rod_v) * approach_steps * dt;
    let ball_body = RigidBodyBuilder::dynamic()
        .can_sleep(false)
        .translation(Vector::new(-(half_thickness + radius) - gap, a))
        .linvel(Vector::new(v0, v0t))
        .angvel(spin);
    let ball_collider = ColliderBuilder::ball(radius)
        .mass_properties(MassProperties::new(Vector::ZERO, m, 0.5 * m * radius * radius))
        .friction(mu)
        .friction_combine_rule(CoefficientCombineRule::Average)
        .restitution(e)
        .restitution_combine_rule(CoefficientCombineRule::Average);
    let (ball, ball_collider) = world.insert(ball_body, ball_collider);

    let energy_before = kinetic_energy(&world.bodies[ball]) + kinetic_energy(&world.bodies[rod]);
    let mut impulse: Real = 0.0;
    for _ in 0..settings.steps() {
        world.step();
        if let Some(pair) = world.narrow_phase.contact_pair(ball_collider, rod_collider) {
            impulse += pair.total_impulse_magnitude();
        }
    }

    let ball_state = &world.bodies[ball];
    let rod_state = &world.bodies[rod];
    // Velocity of the rod's geometric centre (the body origin), also when the centre of mass
    // sits at a pivot. Read 0.1 s after the contact, each value is one the free motion keeps
    // constant, so it is the value right after the impact: the ball's and a free rod's world
    // velocities; for a pivoted rod the centre moves on a circle, so its velocity is taken in
    // the rod's own frame (the rod has turned by omega * 0.1 s since the impact).
    // Rapier's angvel is counterclockwise-positive (z = x cross y); the rod's point at height y
    // then moves along x with -angvel*y, so rodimpact's omega is -angvel.
    let mut centre_velocity = rod_state.velocity_at_point(rod_state.translation());
    if scene.pivot.is_some() {
        centre_velocity = rod_state.rotation().inverse().transform_vector(centre_velocity);
    }
    let energy_after = kinetic_energy(ball_state) + kinetic_energy(rod_state);
    let normal = [
        ball_state.linvel().x,
        centre_velocity.x,
        -rod_state.angvel(),
        impulse,
        energy_before,
        energy_after,
    ]
    .map(shortest);
    // Along the rod (+y), read as V is: the ball's and a free rod's centre velocity in the world
    // (both constant after the contact), a pivoted rod's centre in the rod's own frame; and the
    // ball's spin (counterclockwise, as rodimpact's `spin`).
    let tangential = match scene.oblique {
        Some(_) => [
            ball_state.linvel().y,
            centre_velocity.y,
            ball_state.angvel(),
        ]
        .map(shortest),
        None => [String::new(), String::new(), String::new()],
    };
    Outcome {
        cells: [normal.as_slice(), tangential.as_slice()].concat(),
    }
}

/// The shortest decimal that reads back to the same Real (f32 or f64); scientific notation
/// for very small or large magnitudes, so that 1e-91 is not printed as 91 zeros.
fn shortest(x: Real) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() < 1e-4 || x.abs() >= 1e16) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}
