//! The compliant-contact simulation against the exact impulsive result: convergence in k with
//! the predicted slopes, the frozen model as an integrator test, event-driven RK4's order, and
//! the explicit integrators' stability limits.

use rodimpact::contact::{Contact, Geometry, Integrator, fit_slope, simulate, sweep_k};
use rodimpact::field::{Q, q};
use rodimpact::scene::Scene;
use rodimpact::solve::solve;

fn scene(rod_mass: Q, a: Q, e: Q) -> Scene {
    Scene::builder(q(1, 1), rod_mass).a(a).e(e).build().unwrap()
}

/// The paper's scene hit halfway: v = 3/11, V = 8/11, omega = 12/11 (e = 1).
fn textbook() -> Scene {
    scene(q(1, 1), q(1, 2), q(1, 1))
}

/// Step sizes h Omega used below; none is a "magic" Verlet step 2 sin(pi / 2N), at which the
/// discrete orbit mirrors and elastic Verlet is exact by coincidence. Checked for N < 100: below
/// h Omega = 0.03 the magic steps are so dense that the coincidence no longer matters.
fn not_magic(h_omega: f64) -> f64 {
    for n in 1..100 {
        let magic = 2.0 * (std::f64::consts::PI / (2.0 * n as f64)).sin();
        assert!(
            (h_omega - magic).abs() > 1e-3 * magic,
            "magic step {h_omega}"
        );
    }
    h_omega
}

#[test]
fn exact_geometry_converges_as_one_over_k_and_lateral_as_root_k() {
    let ks: Vec<f64> = (2..=8).map(|p| 10f64.powi(p)).collect();
    for s in [textbook(), scene(q(1, 1), q(19, 20), q(1, 2))] {
        let rows = sweep_k(&s, &ks, Geometry::Exact, Integrator::EventRk4, 400).unwrap();
        for i in 0..3 {
            let errors: Vec<f64> = rows.iter().map(|r| r.errors[i]).collect();
            let slope = fit_slope(&ks, &errors).unwrap();
            assert!((-1.1..=-0.9).contains(&slope), "output {i}: slope {slope}");
        }
        let lateral: Vec<f64> = rows.iter().map(|r| r.errors[3]).collect();
        let slope = fit_slope(&ks, &lateral).unwrap();
        assert!((-0.6..=-0.4).contains(&slope), "lateral slope {slope}");
    }
    // docs/stability.md (stiff contact) at k = 1e6 (M = m, a = l/2): 1.4e-7, 2.7e-7, 7.2e-7
    // for omega, V, v.
    let row = &sweep_k(
        &textbook(),
        &[1e6],
        Geometry::Exact,
        Integrator::EventRk4,
        400,
    )
    .unwrap()[0];
    for (err, want) in row.errors.iter().zip([7.2e-7, 2.7e-7, 1.4e-7, 1.9e-4]) {
        assert!((err / want - 1.0).abs() < 0.05, "{err} against {want}");
    }
}

#[test]
fn frozen_geometry_reproduces_the_impulse_for_every_k() {
    for rod_mass in [q(1, 1000), q(1, 1), q(1000, 1)] {
        for e in [q(1, 1), q(1, 2)] {
            let s = scene(rod_mass.clone(), q(1, 2), e);
            for k in [1e2, 1e6, 1e10] {
                let c = Contact::new(&s, k, Geometry::Frozen).unwrap();
                let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 200.0);
                assert!(
                    run.errors.iter().all(|e| *e < 1e-8),
                    "{k}: {:?}",
                    run.errors
                );
                assert_eq!(run.lateral, 0.0);
            }
        }
    }
    // Fixed-step RK4 with h Omega = 0.01 through approach, contact and departure.
    let c = Contact::new(&textbook(), 1e6, Geometry::Frozen).unwrap();
    let run = simulate(&c, Integrator::Rk4, not_magic(0.01) / c.frequency());
    assert!(run.errors.iter().all(|e| *e < 1e-5), "{:?}", run.errors);
}

#[test]
fn reference_is_the_exact_solution() {
    let c = Contact::new(&textbook(), 1e6, Geometry::Exact).unwrap();
    let exact = solve(&textbook().params::<Q>()).unwrap().after;
    assert_eq!(exact.omega, q(12, 11));
    assert_eq!(c.reference(), [3.0 / 11.0, 8.0 / 11.0, 12.0 / 11.0]);
}

/// Event-driven RK4 error at steps T_c / n, n = 10, 20, 40, 80, and the fitted order.
fn event_order(s: &Scene) -> f64 {
    let c = Contact::new(s, 1e6, Geometry::Frozen).unwrap();
    let ns = [10.0, 20.0, 40.0, 80.0];
    let errors: Vec<f64> = ns
        .iter()
        .map(|n| simulate(&c, Integrator::EventRk4, c.contact_time() / n).errors[2])
        .collect();
    -fit_slope(&ns, &errors).unwrap()
}

#[test]
fn event_driven_rk4_is_fourth_order() {
    let damped = event_order(&scene(q(1, 1), q(1, 2), q(1, 2)));
    assert!((3.5..=4.5).contains(&damped), "order {damped}");
    // Elastic: at least fourth order (the symmetric half-period cancels one more term).
    let elastic = event_order(&textbook());
    assert!(elastic >= 3.5, "order {elastic}");
}

#[test]
fn explicit_integrators_gain_energy_beyond_their_stability_limits() {
    let c = Contact::new(&textbook(), 1e6, Geometry::Frozen).unwrap();
    let energy = |method, h_omega: f64| simulate(&c, method, h_omega / c.frequency()).energy_change;
    for h_omega in [0.1, 0.3] {
        assert!(energy(Integrator::Verlet, not_magic(h_omega)).abs() < 1e-3);
        assert!(energy(Integrator::Rk4, h_omega).abs() < 1e-3);
    }
    // The caveat behind `not_magic`: h Omega = 1 = 2 sin(pi/6) makes elastic Verlet exact.
    let magic = simulate(&c, Integrator::Verlet, 1.0 / c.frequency());
    assert!(
        magic.errors.iter().all(|e| *e < 1e-14),
        "{:?}",
        magic.errors
    );
    for h_omega in [2.5, 4.0, 10.0] {
        let gain = energy(Integrator::Verlet, not_magic(h_omega));
        assert!(gain > 1.0, "verlet at {h_omega}: {gain}");
    }
    for h_omega in [4.0, 10.0] {
        let gain = energy(Integrator::Rk4, h_omega);
        assert!(gain > 1.0, "rk4 at {h_omega}: {gain}");
    }
}

#[test]
fn implicit_integrators_stay_bounded_and_backward_euler_turns_plastic() {
    let c = Contact::new(&textbook(), 1e6, Geometry::Frozen).unwrap();
    for h_omega in [2.5, 10.0] {
        let run = simulate(&c, Integrator::Midpoint, h_omega / c.frequency());
        assert!(run.energy_change < 3.0, "midpoint {}", run.energy_change);
    }
    // A plastic hit (e = 0) gives half the elastic omega: (1 + 0) / (1 + 1).
    let run = simulate(&c, Integrator::BackwardEuler, 10.0 / c.frequency());
    let ratio = run.velocities[2] / c.reference()[2];
    assert!((ratio - 0.5).abs() < 0.05, "omega ratio {ratio}");
    assert!(run.energy_change < -0.3);
    // Small steps: first order, close to elastic.
    let run = simulate(&c, Integrator::BackwardEuler, 0.01 / c.frequency());
    assert!(run.errors[2] < 2e-2);
}
