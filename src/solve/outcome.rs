//! What every route ends with: the velocities after the impact completed into an [`Outcome`]
//! (pivot impulse, energies, and the residuals of the conservation laws that apply, computed
//! with the shared [`mechanics`](crate::mechanics) functions: exactly zero over exact fields).

use crate::field::Field;
use crate::impact::{Balance, Balances, EnergyLedger};
use crate::scene::{Motion, angular_momentum, kinetic_energy, linear_momentum};
use crate::scene::{Params, Support};

/// Everything the solver knows about one impact.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome<F> {
    /// Velocities right after the impact.
    pub after: Motion<F>,
    /// Impulse the pivot exerts on the rod (x-component); `None` for a free rod.
    pub pivot_impulse: Option<F>,
    /// Kinetic energy before and after.
    pub energy: EnergyLedger<F>,
    /// Residuals of the applicable conservation laws (after minus before): linear momentum
    /// (free rod only: a pivot takes an impulse), angular momentum about the rod's centre or
    /// the pivot, and kinetic energy (elastic impacts, e = 1, only).
    pub residuals: Balances<F>,
}

impl<F> Outcome<F> {
    /// Every number mapped by `f`: a change of number type.
    pub(crate) fn map<G>(self, mut f: impl FnMut(F) -> G) -> Outcome<G> {
        let f = &mut f;
        Outcome {
            after: self.after.map(&mut *f),
            pivot_impulse: self.pivot_impulse.map(&mut *f),
            energy: self.energy.map(f),
            residuals: self.residuals.map(f),
        }
    }
}

impl<F: Field> Outcome<F> {
    /// The impulse the projectile gives the rod, `J = m (v0 - v)`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::fast::linear::solve, field::{q, Q}};
    /// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
    /// assert_eq!(solve(&p).unwrap().impulse(&p), q(2, 5));
    /// ```
    pub fn impulse(&self, p: &Params<F>) -> F {
        p.m.clone() * &(p.v0.clone() - &self.after.v)
    }
}

/// Completes an [`Outcome`] from the velocities after the impact: pivot impulse, energies and
/// the residuals of the applicable laws.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, solve::{fast::closed_form::closed_form, outcome}, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let out = outcome(&p, closed_form(&p).unwrap());
/// assert!(out.residuals.all_zero());
/// ```
pub fn outcome<F: Field>(p: &Params<F>, after: Motion<F>) -> Outcome<F> {
    let before = Motion::before(p.v0.clone());
    let about = p.axis();
    let energy_after = kinetic_energy(p, &after);
    let energy_before = kinetic_energy(p, &before);
    let mut residuals = Balances::new();
    if matches!(p.support, Support::Free) {
        residuals.push(
            Balance::LinearMomentum,
            linear_momentum(p, &after) - &linear_momentum(p, &before),
        );
    }
    residuals.push(
        Balance::AngularMomentum,
        angular_momentum(p, &after, &about) - &angular_momentum(p, &before, &about),
    );
    if p.e.is_one() {
        residuals.push(Balance::Energy, energy_after.clone() - &energy_before);
    }
    completed(p, after, energy_before, energy_after, residuals)
}

/// [`outcome`] for velocities that a route has proved to satisfy every applicable law exactly:
/// the residuals are exactly zero, and after an elastic impact the energy is the energy before.
pub(super) fn proven<F: Field>(p: &Params<F>, after: Motion<F>) -> Outcome<F> {
    let energy_before = kinetic_energy(p, &Motion::before(p.v0.clone()));
    let elastic = p.e.is_one();
    let energy_after = if elastic {
        energy_before.clone()
    } else {
        kinetic_energy(p, &after)
    };
    let mut residuals = Balances::new();
    if matches!(p.support, Support::Free) {
        residuals.push(Balance::LinearMomentum, F::zero());
    }
    residuals.push(Balance::AngularMomentum, F::zero());
    if elastic {
        residuals.push(Balance::Energy, F::zero());
    }
    completed(p, after, energy_before, energy_after, residuals)
}

/// The outcome from its parts: the pivot impulse and the energy lost are derived here.
fn completed<F: Field>(
    p: &Params<F>,
    after: Motion<F>,
    energy_before: F,
    energy_after: F,
    residuals: Balances<F>,
) -> Outcome<F> {
    let pivot_impulse = match &p.support {
        Support::Free => None,
        Support::Pivot(_) => {
            let rod_momentum = p.rod_mass.clone() * &after.rod_v;
            let from_projectile = p.m.clone() * &(p.v0.clone() - &after.v);
            Some(rod_momentum - &from_projectile)
        }
    };
    Outcome {
        after,
        pivot_impulse,
        energy: EnergyLedger::new(energy_before, energy_after),
        residuals,
    }
}
