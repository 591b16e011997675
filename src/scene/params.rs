//! A scene's numbers lifted into a field for the solver: [`Params`] (the paper's scene) and
//! [`ObliqueParams`] (what an oblique scene adds), or built directly with symbolic entries.

use super::Support;
use crate::field::{Field, Q, RatFn};

/// A solid disc projectile (I = m r^2/2) sliding on the table, its rim touching the rod.
#[derive(Debug, Clone, PartialEq)]
pub struct Disc<F = Q> {
    /// The disc's radius r (> 0).
    pub radius: F,
    /// The disc's angular velocity before the impact, counterclockwise seen from above
    /// (about z = x cross y).
    pub spin: F,
}

/// The rod's motion: the velocity of its centre across (`v`, along x) and along (`vt`, along
/// y) the rod, and its angular velocity `omega` (the sign of docs/conventions.md: the point at
/// y moves along x with `v + omega y`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RodMotion<F> {
    /// Centre velocity along x.
    pub v: F,
    /// Centre velocity along the rod (y).
    pub vt: F,
    /// Angular velocity.
    pub omega: F,
}

impl<F: Field> RodMotion<F> {
    /// This motion, as given, of a rod on `support`, as the impulse equations see it
    /// ([`ObliqueParams::rod_moving`]): as given for a free rod; on a pivot at p the centre
    /// moves with -omega p and not along the rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::{RodMotion, Support};
    /// use rodimpact::field::q;
    /// let given = RodMotion { v: q(5, 1), vt: q(1, 1), omega: q(-2, 1) };
    /// assert_eq!(given.on(&Support::Free), given);
    /// assert_eq!(given.on(&Support::Pivot(q(1, 2))), RodMotion { v: q(1, 1), vt: q(0, 1), omega: q(-2, 1) });
    /// ```
    pub fn on(&self, support: &Support<F>) -> RodMotion<F> {
        match support {
            Support::Free => self.clone(),
            Support::Pivot(pivot) => RodMotion {
                v: -(pivot.clone() * &self.omega),
                vt: F::zero(),
                omega: self.omega.clone(),
            },
        }
    }
}

impl<F> RodMotion<F> {
    /// Each velocity mapped by `f`: a change of number type.
    pub(crate) fn map<G>(self, f: &mut impl FnMut(F) -> G) -> RodMotion<G> {
        RodMotion {
            v: f(self.v),
            vt: f(self.vt),
            omega: f(self.omega),
        }
    }
}

/// The oblique part of a scene lifted into a field `F` (see [`Oblique`](super::Oblique)), or built directly
/// with symbolic entries for a proof.
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueParams<F> {
    /// The projectile's velocity along the rod before the impact.
    pub v0t: F,
    /// Coulomb friction coefficient.
    pub mu: F,
    /// The disc projectile, if any.
    pub disc: Option<Disc<F>>,
    /// The rod's motion before the impact (for a pivoted rod only `omega` may be non-zero;
    /// its centre then moves with `v = -omega p`).
    pub rod_before: RodMotion<F>,
}

impl<F: Field> ObliqueParams<F> {
    /// The rod's motion before the impact as the impulse equations see it: as given for a
    /// free rod; on a pivot at p the centre moves with -omega0 p and not along the rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::{Oblique, RodMotion, Support};
    /// use rodimpact::field::{q, Q};
    /// let o = Oblique { rod_before: RodMotion { v: q(0, 1), vt: q(0, 1), omega: q(-2, 1) }, ..Default::default() };
    /// let r = o.params::<Q>().rod_moving(&Support::Pivot(q(1, 2)));
    /// assert_eq!(r, RodMotion { v: q(1, 1), vt: q(0, 1), omega: q(-2, 1) });
    /// ```
    pub fn rod_moving(&self, support: &Support<F>) -> RodMotion<F> {
        self.rod_before.on(support)
    }

    /// The slip before the impact, u_t: the velocity along the rod of the projectile's
    /// contact point (a disc's rim adds spin times radius) minus the struck point's.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::{Disc, Oblique, RodMotion, Support};
    /// use rodimpact::field::{q, Q};
    /// let o = Oblique {
    ///     v0t: q(1, 1),
    ///     disc: Some(Disc { radius: q(1, 10), spin: q(3, 1) }),
    ///     rod_before: RodMotion { v: q(0, 1), vt: q(1, 2), omega: q(0, 1) },
    ///     ..Default::default()
    /// };
    /// assert_eq!(o.params::<Q>().slip(&Support::Free), q(4, 5)); // 1 + 3/10 - 1/2
    /// ```
    pub fn slip(&self, support: &Support<F>) -> F {
        let rim = |d: &Disc<F>| d.spin.clone() * &d.radius;
        self.v0t.clone() + &self.disc.as_ref().map_or_else(F::zero, rim)
            - &self.rod_moving(support).vt
    }
}
/// The numbers the solver needs, lifted into a field `F`.
///
/// Built from a validated [`Scene`](super::Scene) by [`Scene::params`](super::Scene::params), or directly (for example with symbolic
/// entries over [`crate::field::RatFn`]) when a proof needs all parameter values at once.
#[derive(Debug, Clone, PartialEq)]
pub struct Params<F> {
    /// Projectile mass m.
    pub m: F,
    /// Rod mass M.
    pub rod_mass: F,
    /// Rod half-length l.
    pub half_length: F,
    /// Moment of inertia I about the rod's centre.
    pub inertia: F,
    /// Signed impact distance a from the rod's centre.
    pub a: F,
    /// Projectile speed before the impact.
    pub v0: F,
    /// Coefficient of restitution e.
    pub e: F,
    /// Free rod or pivot position.
    pub support: Support<F>,
}

impl Params<RatFn> {
    /// The general free-rod scene in symbols: `m`, `M`, `l`, `a`, `v0` and the given moment of
    /// inertia and restitution (themselves symbols or expressions), the one symbolic scene the
    /// claims are decided in.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::{Field, RatFn}, scene::{Params, RodInertia}, solve::fast::linear::solve};
    /// let (big_m, l) = (RatFn::symbol("M"), RatFn::symbol("l"));
    /// let p = Params::symbolic(RodInertia::Uniform.moment(&big_m, &l), RatFn::from_i64(1));
    /// let omega = solve(&p).unwrap().after.omega;
    /// assert_eq!(omega.to_string(), "6*a*m*v0/(M*l^2 + 3*a^2*m + l^2*m)");
    /// ```
    pub fn symbolic(inertia: RatFn, e: RatFn) -> Params<RatFn> {
        Params {
            m: RatFn::symbol("m"),
            rod_mass: RatFn::symbol("M"),
            half_length: RatFn::symbol("l"),
            inertia,
            a: RatFn::symbol("a"),
            v0: RatFn::symbol("v0"),
            e,
            support: Support::Free,
        }
    }
}

impl<F: Field> Params<F> {
    /// The moment of inertia about the point the angular-momentum balance is taken about: the
    /// centre (I) for a free rod, the pivot (I + M p^2) for a pivoted one.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::{q, Q};
    /// let s = Scene::builder(q(1, 1), q(3, 1)).pivot(q(-1, 1)).build().unwrap();
    /// assert_eq!(s.params::<Q>().inertia_about_axis(), q(4, 1)); // 1 + 3*1^2
    /// ```
    pub fn inertia_about_axis(&self) -> F {
        match &self.support {
            Support::Free => self.inertia.clone(),
            Support::Pivot(p) => self.inertia.clone() + &(self.rod_mass.clone() * p * p),
        }
    }

    /// The reference point of the angular-momentum balance: 0 (the centre) or the pivot p.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::{q, Q};
    /// let s = Scene::builder(q(1, 1), q(3, 1)).pivot(q(-1, 2)).build().unwrap();
    /// assert_eq!(s.params::<Q>().axis(), q(-1, 2));
    /// ```
    pub fn axis(&self) -> F {
        match &self.support {
            Support::Free => F::zero(),
            Support::Pivot(p) => p.clone(),
        }
    }
}
