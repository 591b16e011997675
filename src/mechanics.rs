//! Mechanics vocabulary over any field: the motion of the two bodies and the quantities that the
//! conservation laws balance.
//!
//! The solver's residuals and the proofs of the claims use these same functions, so a law is stated
//! once. Conventions (docs/conventions.md): x is the projectile's direction before the impact; the
//! rod lies along y with its centre at the origin; a rod point at y moves with `V + omega*y`.
//! Angular momentum about a point (0, y_ref) of the rod's line is `sum (y - y_ref) * p_x`, the sign
//! for which the paper's Eq. (angular) reads `m v0 a = m v a + I omega`.

use crate::field::Field;
use crate::scene::Params;

/// The velocities of the two bodies at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion<F> {
    /// Projectile's x-velocity.
    pub v: F,
    /// x-velocity of the rod's centre.
    pub rod_v: F,
    /// Rod's angular velocity (the rod point at y moves with `rod_v + omega*y`).
    pub omega: F,
}

impl<F> Motion<F> {
    /// The names of the three velocities, in the order of [`Motion::iter`]: `v`, `V`, `omega`
    /// (the keys of docs/conventions.md).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// assert_eq!(Motion::<f64>::NAMES, ["v", "V", "omega"]);
    /// ```
    pub const NAMES: [&'static str; 3] = ["v", "V", "omega"];

    /// The three velocities by reference, in the order v, V, omega.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let m = Motion { v: 1, rod_v: 2, omega: 3 };
    /// assert_eq!(m.iter().sum::<i32>(), 6);
    /// ```
    pub fn iter(&self) -> impl Iterator<Item = &F> {
        [&self.v, &self.rod_v, &self.omega].into_iter()
    }

    /// The three velocities as an array `[v, V, omega]`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// assert_eq!(Motion { v: 1, rod_v: 2, omega: 3 }.into_array(), [1, 2, 3]);
    /// ```
    pub fn into_array(self) -> [F; 3] {
        [self.v, self.rod_v, self.omega]
    }

    /// `f` applied to each velocity.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let m = Motion { v: 1.5f32, rod_v: -2.0, omega: 0.25 };
    /// assert_eq!(m.map(f64::from), Motion { v: 1.5f64, rod_v: -2.0, omega: 0.25 });
    /// ```
    pub fn map<G>(self, mut f: impl FnMut(F) -> G) -> Motion<G> {
        Motion {
            v: f(self.v),
            rod_v: f(self.rod_v),
            omega: f(self.omega),
        }
    }

    /// The velocities of `self` and `other` paired, component by component.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let a = Motion { v: 1, rod_v: 2, omega: 3 };
    /// let b = Motion { v: 10, rod_v: 20, omega: 30 };
    /// assert_eq!(a.zip(b).map(|(x, y)| x + y), Motion { v: 11, rod_v: 22, omega: 33 });
    /// ```
    pub fn zip<G>(self, other: Motion<G>) -> Motion<(F, G)> {
        Motion {
            v: (self.v, other.v),
            rod_v: (self.rod_v, other.rod_v),
            omega: (self.omega, other.omega),
        }
    }

    /// The velocities by reference, as a motion of references (to `map` or `zip` without
    /// moving them).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let m = Motion { v: 1, rod_v: 2, omega: 3 };
    /// assert_eq!(m.as_ref().map(|x| x * 2), Motion { v: 2, rod_v: 4, omega: 6 });
    /// ```
    pub fn as_ref(&self) -> Motion<&F> {
        Motion {
            v: &self.v,
            rod_v: &self.rod_v,
            omega: &self.omega,
        }
    }
}

impl<F: Field> Motion<F> {
    /// The motion before the impact: projectile at `v0`, rod at rest.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let m = Motion::before(2.0f64);
    /// assert_eq!((m.v, m.rod_v, m.omega), (2.0, 0.0, 0.0));
    /// ```
    pub fn before(v0: F) -> Self {
        Motion {
            v: v0,
            rod_v: F::zero(),
            omega: F::zero(),
        }
    }

    /// x-velocity of the rod's material point at position `y` along the rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::Motion;
    /// let m = Motion { v: 0.0f64, rod_v: 1.0, omega: 2.0 };
    /// assert_eq!(m.rod_point_velocity(&-0.5), 0.0);
    /// ```
    pub fn rod_point_velocity(&self, y: &F) -> F {
        self.rod_v.clone() + &(self.omega.clone() * y)
    }
}

/// Total linear momentum (x-component) of projectile and rod.
///
/// `m v + M V`.
///
/// # Examples
/// ```
/// use rodimpact::mechanics::{linear_momentum, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(1, 1), q(3, 1)).build().unwrap().params::<Q>();
/// let after = Motion { v: q(1, 2), rod_v: q(1, 6), omega: q(0, 1) };
/// assert_eq!(linear_momentum(&p, &after), q(1, 1));
/// ```
pub fn linear_momentum<F: Field>(p: &Params<F>, s: &Motion<F>) -> F {
    p.m.clone() * &s.v + &(p.rod_mass.clone() * &s.rod_v)
}

/// Total angular momentum about the point `about` of the rod's line (at the impact instant).
///
/// Projectile: `m v (a - y_ref)`; rod: `I omega - M V y_ref` (its centre is at y = 0).
///
/// # Examples
/// ```
/// use rodimpact::mechanics::{angular_momentum, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>(); // a = 1, I = 1/3
/// assert_eq!(angular_momentum(&p, &Motion::before(q(1, 1)), &q(0, 1)), q(1, 1));
/// ```
pub fn angular_momentum<F: Field>(p: &Params<F>, s: &Motion<F>, about: &F) -> F {
    let projectile = p.m.clone() * &s.v * &(p.a.clone() - about);
    let rod = p.inertia.clone() * &s.omega - &(p.rod_mass.clone() * &s.rod_v * about);
    projectile + &rod
}

/// Total kinetic energy: `m v^2/2 + M V^2/2 + I omega^2/2`.
///
/// # Examples
/// ```
/// use rodimpact::mechanics::{kinetic_energy, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(2, 1), q(1, 1)).build().unwrap().params::<Q>();
/// assert_eq!(kinetic_energy(&p, &Motion::before(q(3, 1))), q(9, 1));
/// ```
pub fn kinetic_energy<F: Field>(p: &Params<F>, s: &Motion<F>) -> F {
    let two = F::from_i64(2);
    let twice = p.m.clone() * &s.v * &s.v
        + &(p.rod_mass.clone() * &s.rod_v * &s.rod_v)
        + &(p.inertia.clone() * &s.omega * &s.omega);
    twice / &two
}
