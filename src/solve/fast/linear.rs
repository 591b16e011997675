//! The linear route ([`Route::Linear`](crate::solve::Route::Linear)): the impulse equations of
//! docs/conventions.md as a linear system, solved by elimination over any [`Field`]:
//!
//! - free rod, unknowns (v, V, omega):
//!   `m v + M V = m v0` (linear momentum), `m a v + I omega = m a v0` (angular momentum about
//!   the rod's centre), `-v + V + a omega = e v0` (Newton's restitution at the contact);
//! - pivot at p, unknowns (v, omega), with V = -p omega and d = a - p:
//!   `m d v + I_p omega = m d v0` (angular momentum about the pivot, I_p = I + M p^2),
//!   `-v + d omega = e v0` (restitution).
//!
//! The reference route: the claims, the textbook checks, the tables and the symbolic proofs
//! run it, over rational functions as over numbers.
//!
//! A fast case of the core: over Q it must equal `impact::solve_contact(&scene.system(),
//! Law::Newton)` (v, V, omega, the pivot's impulse, the energies), which
//! `tests/lib/fast_routes.rs` checks on random scenes.

use crate::field::Field;
use crate::field::linear::solve_linear;
use crate::scene::Motion;
use crate::scene::{Params, Scene, Support};
use crate::solve::{Outcome, outcome};

/// The impulse equations of the scene as `(A, b)`: unknowns (v, V, omega) for a free rod,
/// (v, omega) for a pivoted one.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::fast::linear::impulse_equations, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let (a, b) = impulse_equations(&p);
/// assert_eq!(a[0], vec![q(1, 1), q(1, 1), q(0, 1)]); // m v + M V = m v0
/// assert_eq!(b[2], q(1, 1)); // restitution: -v + V + a omega = e v0
/// ```
pub fn impulse_equations<F: Field>(p: &Params<F>) -> (Vec<Vec<F>>, Vec<F>) {
    let e_v0 = p.e.clone() * &p.v0;
    match &p.support {
        Support::Free => {
            let ma = p.m.clone() * &p.a;
            (
                vec![
                    vec![p.m.clone(), p.rod_mass.clone(), F::zero()],
                    vec![ma.clone(), F::zero(), p.inertia.clone()],
                    vec![-F::one(), F::one(), p.a.clone()],
                ],
                vec![p.m.clone() * &p.v0, ma * &p.v0, e_v0],
            )
        }
        Support::Pivot(pivot) => {
            let d = p.a.clone() - pivot;
            let md = p.m.clone() * &d;
            (
                vec![vec![md.clone(), p.inertia_about_axis()], vec![-F::one(), d]],
                vec![md * &p.v0, e_v0],
            )
        }
    }
}

/// Solves the impact: velocities after it, the pivot impulse, energies and residuals.
///
/// Returns `None` only when the system is singular, which a valid scene over an exact field
/// never is (its determinant is `-(m I + M I + M m a^2)` for a free rod); a float backend can
/// underflow to it.
///
/// # Examples
/// The paper's case M = m, uniform rod hit at the end:
/// ```
/// use rodimpact::{scene::Scene, solve::fast::linear::solve, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let out = solve(&p).unwrap();
/// assert_eq!((out.after.v, out.after.rod_v, out.after.omega), (q(3, 5), q(2, 5), q(6, 5)));
/// assert!(out.residuals.all_zero());
/// ```
pub fn solve<F: Field>(p: &Params<F>) -> Option<Outcome<F>> {
    motion_after(p).map(|after| outcome(p, after))
}

/// The scene struck at `a` instead of its own impact point, solved in `F`: an irrational
/// point (a* in Q(sqrt d)) as well as a rational one (the samples of a figure). `None` when
/// the impulse equations are singular there.
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, QSqrt}, scene::Scene, solve::fast::linear::solve_at};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build()?;
/// // At a* = sqrt(2/3) (m = M = 1, uniform): omega = (1 + e) a*/(2 a*^2) = sqrt(6)/2.
/// let out = solve_at(&s, QSqrt::sqrt_of(&q(2, 3))).unwrap();
/// assert_eq!(out.after.omega.to_string(), "sqrt(6)/2");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_at<F: Field>(scene: &Scene, a: F) -> Option<Outcome<F>> {
    solve(&Params {
        a,
        ..scene.params::<F>()
    })
}

/// The velocities after the impact alone, without the energies and residuals [`solve`] adds:
/// for callers that need only the motion (an identity in a symbol, where each law would be
/// one more rational function to reduce).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::fast::linear::motion_after, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// assert_eq!(motion_after(&p).unwrap().omega, q(6, 5));
/// ```
pub fn motion_after<F: Field>(p: &Params<F>) -> Option<Motion<F>> {
    let (a, b) = impulse_equations(p);
    let x = solve_linear(a, b)?;
    Some(match &p.support {
        Support::Free => Motion {
            v: x[0].clone(),
            rod_v: x[1].clone(),
            omega: x[2].clone(),
        },
        Support::Pivot(pivot) => Motion {
            v: x[0].clone(),
            rod_v: -(pivot.clone() * &x[1]),
            omega: x[1].clone(),
        },
    })
}
