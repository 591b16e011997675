//! What every route ends with: the velocities after the impact completed into an [`Outcome`]
//! (pivot impulse, energies, and the residuals of the conservation laws that apply, computed
//! with the shared [`mechanics`](crate::mechanics) functions: exactly zero over exact fields).

use crate::field::Field;
use crate::mechanics::{Motion, angular_momentum, kinetic_energy, linear_momentum};
use crate::scene::{Params, Support};

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

impl<F> Energy<F> {
    /// Each energy mapped by `f`: a change of number type.
    pub(crate) fn map<G>(self, f: &mut impl FnMut(F) -> G) -> Energy<G> {
        Energy {
            before: f(self.before),
            after: f(self.after),
            lost: f(self.lost),
        }
    }
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

impl<F> Residuals<F> {
    /// Each residual mapped by `f`: a change of number type.
    fn map<G>(self, f: &mut impl FnMut(F) -> G) -> Residuals<G> {
        Residuals {
            linear_momentum: self.linear_momentum.map(&mut *f),
            angular_momentum: f(self.angular_momentum),
            energy: self.energy.map(&mut *f),
        }
    }
}

impl<F: Field> Residuals<F> {
    /// Every applicable residual, with its name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, solve::linear::solve, field::{q, Q}};
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
    /// use rodimpact::{scene::Scene, solve::linear::solve, field::{q, Q}};
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
    /// use rodimpact::{scene::Scene, solve::linear::solve, field::{q, Q}};
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
/// use rodimpact::{scene::Scene, solve::{closed_form::closed_form, outcome}, field::{q, Q}};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
/// let out = outcome(&p, closed_form(&p).unwrap());
/// assert!(out.residuals.all_zero());
/// ```
pub fn outcome<F: Field>(p: &Params<F>, after: Motion<F>) -> Outcome<F> {
    let before = Motion::before(p.v0.clone());
    let about = p.axis();
    let energy_after = kinetic_energy(p, &after);
    let energy_before = kinetic_energy(p, &before);
    let residuals = Residuals {
        linear_momentum: matches!(p.support, Support::Free)
            .then(|| linear_momentum(p, &after) - &linear_momentum(p, &before)),
        angular_momentum: angular_momentum(p, &after, &about)
            - &angular_momentum(p, &before, &about),
        energy: p.e.is_one().then(|| energy_after.clone() - &energy_before),
    };
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
    let residuals = Residuals {
        linear_momentum: matches!(p.support, Support::Free).then(F::zero),
        angular_momentum: F::zero(),
        energy: elastic.then(F::zero),
    };
    completed(p, after, energy_before, energy_after, residuals)
}

/// The outcome from its parts: the pivot impulse and the energy lost are derived here.
fn completed<F: Field>(
    p: &Params<F>,
    after: Motion<F>,
    energy_before: F,
    energy_after: F,
    residuals: Residuals<F>,
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
        energy: Energy {
            lost: energy_before.clone() - &energy_after,
            before: energy_before,
            after: energy_after,
        },
        residuals,
    }
}
