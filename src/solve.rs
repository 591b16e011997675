//! The generic impulse solver, and the paper's closed forms as a second, independent path.
//!
//! [`solve`] builds the impulse equations of docs/conventions.md as a linear system and solves it
//! by elimination over any [`Field`]:
//!
//! - free rod, unknowns (v, V, omega):
//!   `m v + M V = m v0` (linear momentum), `m a v + I omega = m a v0` (angular momentum about
//!   the rod's centre), `-v + V + a omega = e v0` (Newton's restitution at the contact);
//! - pivot at p, unknowns (v, omega), with V = -p omega and d = a - p:
//!   `m d v + I_p omega = m d v0` (angular momentum about the pivot, I_p = I + M p^2),
//!   `-v + d omega = e v0` (restitution).
//!
//! The residuals of the laws that apply are then recomputed from the solution with the shared
//! [`mechanics`](crate::mechanics) functions: exactly zero over exact fields.

use crate::field::Field;
use crate::mechanics::{Motion, angular_momentum, kinetic_energy, linear_momentum};
use crate::scene::{Params, Support};
use std::cmp::Ordering;

/// Kinetic energy before and after the impact, and the loss.
#[derive(Debug, Clone, PartialEq)]
pub struct Energy<F> {
    /// Kinetic energy before the impact, `m v0^2 / 2`.
    pub before: F,
    /// Kinetic energy after the impact.
    pub after: F,
    /// `before - after` (zero for e = 1, positive otherwise).
    pub lost: F,
}

/// Residuals (after minus before) of the conservation laws that apply to the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Residuals<F> {
    /// Linear momentum: free rod only (a pivot takes an impulse).
    pub linear_momentum: Option<F>,
    /// Angular momentum about the rod's centre (free) or about the pivot (pivoted).
    pub angular_momentum: F,
    /// Kinetic energy: elastic impacts (e = 1) only.
    pub energy: Option<F>,
}

impl<F: Field> Residuals<F> {
    /// Every applicable residual, with its name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::solve, field::{q, Q}};
    /// let out = solve(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>()).unwrap();
    /// let names: Vec<_> = out.residuals.iter().map(|(n, _)| n).collect();
    /// assert_eq!(names, ["linear_momentum", "angular_momentum", "energy"]);
    /// ```
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, &F)> {
        let lin = self
            .linear_momentum
            .as_ref()
            .map(|r| ("linear_momentum", r));
        let ang = Some(("angular_momentum", &self.angular_momentum));
        let en = self.energy.as_ref().map(|r| ("energy", r));
        [lin, ang, en].into_iter().flatten()
    }

    /// `true` when every applicable residual is exactly zero (decided for exact fields,
    /// estimated for floats).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::solve, field::{q, Q}};
    /// let out = solve(&Scene::builder(q(2, 7), q(5, 3)).build().unwrap().params::<Q>()).unwrap();
    /// assert!(out.residuals.all_zero());
    /// ```
    pub fn all_zero(&self) -> bool {
        self.iter().all(|(_, r)| r.is_zero())
    }
}

/// Everything the solver knows about one impact.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome<F> {
    /// Velocities right after the impact.
    pub after: Motion<F>,
    /// Impulse the pivot exerts on the rod (x-component); `None` for a free rod.
    pub pivot_impulse: Option<F>,
    /// Kinetic energy before, after and lost.
    pub energy: Energy<F>,
    /// Residuals of the applicable conservation laws.
    pub residuals: Residuals<F>,
}

impl<F: Field> Outcome<F> {
    /// The impulse the projectile gives the rod, `J = m (v0 - v)`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::solve, field::{q, Q}};
    /// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
    /// assert_eq!(solve(&p).unwrap().impulse(&p), q(2, 5));
    /// ```
    pub fn impulse(&self, p: &Params<F>) -> F {
        p.m.clone() * &(p.v0.clone() - &self.after.v)
    }
}

/// Solves a linear system `A x = b` by Gaussian elimination over any field.
///
/// Exact fields take the first nonzero pivot (every choice is exact); float fields use partial
/// pivoting (the largest magnitude). Returns `None` when the system is singular.
///
/// # Examples
/// ```
/// use rodimpact::solve::solve_linear;
/// use rodimpact::field::{q, Q};
/// let a = vec![vec![q(0, 1), q(1, 1)], vec![q(2, 1), q(1, 1)]];
/// let x = solve_linear(a, vec![q(3, 1), q(5, 1)]).unwrap();
/// assert_eq!(x, vec![q(1, 1), q(3, 1)]);
/// ```
pub fn solve_linear<F: Field>(mut a: Vec<Vec<F>>, mut b: Vec<F>) -> Option<Vec<F>> {
    let n = b.len();
    for col in 0..n {
        let candidates = (col..n).filter(|&r| !a[r][col].is_zero());
        let pivot = if F::EXACT {
            candidates.min()?
        } else {
            candidates.max_by(|&r, &s| {
                let (x, y) = (a[r][col].nearest_f64().abs(), a[s][col].nearest_f64().abs());
                x.partial_cmp(&y).unwrap_or(Ordering::Equal)
            })?
        };
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            if a[row][col].is_zero() {
                continue;
            }
            let factor = a[row][col].clone() / &a[col][col];
            let (upper, lower) = a.split_at_mut(row);
            for (target, pivot_entry) in lower[0][col..].iter_mut().zip(&upper[col][col..]) {
                *target = target.clone() - &(factor.clone() * pivot_entry);
            }
            let delta = factor * &b[col];
            b[row] = b[row].clone() - &delta;
        }
    }
    let mut x = vec![F::zero(); n];
    for row in (0..n).rev() {
        let mut acc = b[row].clone();
        for k in row + 1..n {
            acc = acc - &(a[row][k].clone() * &x[k]);
        }
        x[row] = acc.checked_div(&a[row][row])?;
    }
    Some(x)
}

/// The impulse equations of the scene as `(A, b)`: unknowns (v, V, omega) for a free rod,
/// (v, omega) for a pivoted one.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::impulse_equations, field::{q, Q}};
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
/// use rodimpact::{scene::Scene, solve::solve, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let out = solve(&p).unwrap();
/// assert_eq!((out.after.v, out.after.rod_v, out.after.omega), (q(3, 5), q(2, 5), q(6, 5)));
/// assert!(out.residuals.all_zero());
/// ```
pub fn solve<F: Field>(p: &Params<F>) -> Option<Outcome<F>> {
    let (a, b) = impulse_equations(p);
    let x = solve_linear(a, b)?;
    let after = match &p.support {
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
    };
    Some(outcome(p, after))
}

/// Completes an [`Outcome`] from the velocities after the impact: pivot impulse, energies and
/// the residuals of the applicable laws.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::{closed_form, outcome}, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let out = outcome(&p, closed_form(&p).unwrap());
/// assert!(out.residuals.all_zero());
/// ```
pub fn outcome<F: Field>(p: &Params<F>, after: Motion<F>) -> Outcome<F> {
    let before = Motion::before(p.v0.clone());
    let about = p.axis();
    let pivot_impulse = match &p.support {
        Support::Free => None,
        Support::Pivot(_) => {
            let rod_momentum = p.rod_mass.clone() * &after.rod_v;
            let from_projectile = p.m.clone() * &(p.v0.clone() - &after.v);
            Some(rod_momentum - &from_projectile)
        }
    };
    let energy_before = kinetic_energy(p, &before);
    let energy_after = kinetic_energy(p, &after);
    let residuals = Residuals {
        linear_momentum: matches!(p.support, Support::Free)
            .then(|| linear_momentum(p, &after) - &linear_momentum(p, &before)),
        angular_momentum: angular_momentum(p, &after, &about)
            - &angular_momentum(p, &before, &about),
        energy: p.e.is_one().then(|| energy_after.clone() - &energy_before),
    };
    Outcome {
        after,
        pivot_impulse,
        energy: Energy {
            lost: energy_before.clone() - &energy_after,
            before: energy_before,
            after: energy_after,
        },
        residuals,
    }
}

/// The closed forms: the paper's Eqs. (v), (V), (omega) generalised to restitution e, and the
/// fixed-axis formula for a pivoted rod. A second path, independent of [`solve`].
///
/// Free rod, with r = m/M, s = m a^2/I, q = r + s:
/// `v = (q - e)/(1 + q) v0`, `V = (1 + e) r/(1 + q) v0`, `omega = (1 + e)(m a/I)/(1 + q) v0`
/// (for e = 1 exactly the paper's `v = -(1 - m/M - m a^2/I)/D v0` with D = 1 + q).
/// Pivot at p, d = a - p: `omega = (1 + e) m d v0/(I_p + m d^2)`, `v = d omega - e v0`,
/// `V = -p omega`. `None` if a denominator vanishes (float underflow only).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::closed_form, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(3, 1)).pivot(q(0, 1)).e(q(0, 1)).build().unwrap().params::<Q>();
/// let m = closed_form(&p).unwrap();
/// assert_eq!((m.v, m.omega), (q(1, 2), q(1, 2)));
/// ```
pub fn closed_form<F: Field>(p: &Params<F>) -> Option<Motion<F>> {
    let one = F::one();
    let one_plus_e = one.clone() + &p.e;
    match &p.support {
        Support::Free => {
            let r = p.m.checked_div(&p.rod_mass)?;
            let ma_over_i = (p.m.clone() * &p.a).checked_div(&p.inertia)?;
            let q = r.clone() + &(ma_over_i.clone() * &p.a);
            let d = one + &q;
            Some(Motion {
                v: (q - &p.e).checked_div(&d)? * &p.v0,
                rod_v: (one_plus_e.clone() * &r).checked_div(&d)? * &p.v0,
                omega: (one_plus_e * &ma_over_i).checked_div(&d)? * &p.v0,
            })
        }
        Support::Pivot(pivot) => {
            let d = p.a.clone() - pivot;
            let md = p.m.clone() * &d;
            let denominator = p.inertia_about_axis() + &(md.clone() * &d);
            let omega = (one_plus_e * &md * &p.v0).checked_div(&denominator)?;
            Some(Motion {
                v: omega.clone() * &d - &(p.e.clone() * &p.v0),
                rod_v: -(pivot.clone() * &omega),
                omega,
            })
        }
    }
}
