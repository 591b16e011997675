//! The paper's two bodies in motion over any field: their velocities ([`Motion`]), the
//! paper's dimensionless groups ([`Groups`]), and the balance laws of the scene (momentum,
//! angular momentum, energy) evaluated through the planar laws of
//! [`crate::mechanics::planar`], so a law is stated once.
//!
//! Conventions (docs/conventions.md): x is the projectile's direction before the impact; the
//! rod lies along y with its centre at the origin; a rod point at y moves with `V + omega*y`.
//! Angular momentum about a point (0, y_ref) of the rod's line is `sum (y - y_ref) * p_x`, the
//! sign for which the paper's Eq. (angular) reads `m v0 a = m v a + I omega`.

use super::Params;
use crate::field::Field;
use crate::mechanics::planar::{self, PlanarBody, Vec2};
use num_traits::One;
use std::ops::{Add, Div, Mul};

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
    /// use rodimpact::scene::Motion;
    /// assert_eq!(Motion::<f64>::NAMES, ["v", "V", "omega"]);
    /// ```
    pub const NAMES: [&'static str; 3] = ["v", "V", "omega"];

    /// The three velocities by reference, in the order v, V, omega.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Motion;
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
    /// use rodimpact::scene::Motion;
    /// assert_eq!(Motion { v: 1, rod_v: 2, omega: 3 }.into_array(), [1, 2, 3]);
    /// ```
    pub fn into_array(self) -> [F; 3] {
        [self.v, self.rod_v, self.omega]
    }

    /// `f` applied to each velocity.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Motion;
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
    /// use rodimpact::scene::Motion;
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
    /// use rodimpact::scene::Motion;
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
    /// use rodimpact::scene::Motion;
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
    /// use rodimpact::scene::Motion;
    /// let m = Motion { v: 0.0f64, rod_v: 1.0, omega: 2.0 };
    /// assert_eq!(m.rod_point_velocity(&-0.5), 0.0);
    /// ```
    pub fn rod_point_velocity(&self, y: &F) -> F {
        self.rod_v.clone() + &(self.omega.clone() * y)
    }
}

/// The paper's dimensionless groups of a free rod: `r = m/M`, `s = m a^2/I`, `q = r + s` and
/// the denominator `D = 1 + q` of its Eqs. (v), (V), (omega), with `m a/I` on the way.
///
/// The one definition of D: the closed form, the float formulas and the condition numbers
/// compute them here. They need only by-value arithmetic, so the exponent-carried floats of
/// the stable formulas use them too, and the order of operations is fixed (`s` as
/// `(m a/I) a`), so every float route rounds alike.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Groups};
/// // The paper's uniform rod with M = m, hit at the end: I = 1/3, a = 1.
/// let g = Groups::of(&q(1, 1), &q(1, 1), &q(1, 3), &q(1, 1));
/// assert_eq!((g.r, g.s, g.q, g.d), (q(1, 1), q(3, 1), q(4, 1), q(5, 1)));
/// assert_eq!(g.ma_over_i, q(3, 1));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Groups<F> {
    /// `r = m/M`, the mass ratio.
    pub r: F,
    /// `m a/I`: omega's factor, `omega = (1 + e) (m a/I)/D v0`.
    pub ma_over_i: F,
    /// `s = m a^2/I = (m a/I) a`.
    pub s: F,
    /// `q = r + s`.
    pub q: F,
    /// `D = 1 + q`.
    pub d: F,
}

impl<F> Groups<F>
where
    F: Clone + One + for<'a> Add<&'a F, Output = F>,
    F: for<'a> Mul<&'a F, Output = F> + for<'a> Div<&'a F, Output = F>,
{
    /// The groups of projectile mass `m`, rod mass `rod_mass`, inertia `inertia` about the centre
    /// and impact distance `a` (divisions unchecked: `rod_mass` and `inertia` nonzero).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Groups;
    /// let g = Groups::of(&1.0f64, &2.0, &0.5, &0.5);
    /// assert_eq!((g.r, g.s, g.d), (0.5, 0.5, 2.0));
    /// ```
    pub fn of(m: &F, rod_mass: &F, inertia: &F, a: &F) -> Groups<F> {
        let r = m.clone() / rod_mass;
        let ma_over_i = m.clone() * a / inertia;
        let s = ma_over_i.clone() * a;
        let q = r.clone() + &s;
        let d = F::one() + &q;
        Groups {
            r,
            ma_over_i,
            s,
            q,
            d,
        }
    }
}

impl<F: Field> Groups<F> {
    /// The groups of a free-rod scene `p` (its support is not looked at); `None` when `M` or `I`
    /// is zero (a float that underflowed).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::{q, Q}, scene::{Groups, Scene}};
    /// let p = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?.params::<Q>();
    /// assert_eq!(Groups::of_params(&p).unwrap().d, q(11, 4)); // 1 + 1 + 3/4
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of_params(p: &Params<F>) -> Option<Groups<F>> {
        if p.rod_mass.is_zero() || p.inertia.is_zero() {
            return None;
        }
        Some(Groups::of(&p.m, &p.rod_mass, &p.inertia, &p.a))
    }
}

/// Total linear momentum (x-component) of projectile and rod.
///
/// `m v + M V`.
///
/// # Examples
/// ```
/// use rodimpact::scene::{linear_momentum, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(1, 1), q(3, 1)).build().unwrap().params::<Q>();
/// let after = Motion { v: q(1, 2), rod_v: q(1, 6), omega: q(0, 1) };
/// assert_eq!(linear_momentum(&p, &after), q(1, 1));
/// ```
pub fn linear_momentum<F: Field>(p: &Params<F>, s: &Motion<F>) -> F {
    planar::linear_momentum(&paper_bodies(p, s)).x
}

/// Total angular momentum about the point `about` of the rod's line (at the impact instant).
///
/// Projectile: `m v (a - y_ref)`; rod: `I omega - M V y_ref` (its centre is at y = 0).
///
/// # Examples
/// ```
/// use rodimpact::scene::{angular_momentum, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>(); // a = 1, I = 1/3
/// assert_eq!(angular_momentum(&p, &Motion::before(q(1, 1)), &q(0, 1)), q(1, 1));
/// ```
pub fn angular_momentum<F: Field>(p: &Params<F>, s: &Motion<F>, about: &F) -> F {
    let about = Vec2::new(F::zero(), about.clone());
    -planar::angular_momentum(&paper_bodies(p, s), &about)
}

/// Total kinetic energy: `m v^2/2 + M V^2/2 + I omega^2/2`.
///
/// # Examples
/// ```
/// use rodimpact::scene::{kinetic_energy, Motion};
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// let p = Scene::builder(q(2, 1), q(1, 1)).build().unwrap().params::<Q>();
/// assert_eq!(kinetic_energy(&p, &Motion::before(q(3, 1))), q(9, 1));
/// ```
pub fn kinetic_energy<F: Field>(p: &Params<F>, s: &Motion<F>) -> F {
    planar::kinetic_energy(&paper_bodies(p, s))
}

/// The paper's two bodies as planar bodies: the point projectile at (0, a) moving along x,
/// the rod's centre at the origin, its counterclockwise spin `-omega` (docs/conventions.md).
fn paper_bodies<F: Field>(p: &Params<F>, s: &Motion<F>) -> [PlanarBody<F>; 2] {
    [
        PlanarBody {
            mass: p.m.clone(),
            inertia: F::zero(),
            centre: Vec2::new(F::zero(), p.a.clone()),
            velocity: Vec2::new(s.v.clone(), F::zero()),
            omega: F::zero(),
        },
        PlanarBody {
            mass: p.rod_mass.clone(),
            inertia: p.inertia.clone(),
            centre: Vec2::zero(),
            velocity: Vec2::new(s.rod_v.clone(), F::zero()),
            omega: -s.omega.clone(),
        },
    ]
}
