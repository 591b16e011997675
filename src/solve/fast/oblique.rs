//! Oblique and frictional impacts over any [`Field`]: the projectile also moves along the rod,
//! Coulomb friction acts at the contact, the projectile may be a spinning solid disc, and the
//! rod may move before the impact (docs/conventions.md, "Oblique and frictional impacts").
//!
//! The struck rod is thin and the contact is on its axis, so the two impulse problems separate:
//!
//! - **normal** (x): the paper's problem with the approach speed
//!   `u_n = v0 - (V0 + omega0 a)` in place of v0, solved by any route; the normal impulse is
//!   `J = (1 + e) u_n / k_n`, `k_n = 1/m + 1/M + a^2/I` (pivot: `1/m + (a - p)^2/I_p`);
//! - **tangential** (y): the slip `u_t = (v0t + spin r) - Vt0` of the projectile's contact
//!   point over the rod's, with the mobility `k_t = 1/m + r^2/I_disc + 1/M` (`r^2/I_disc = 2/m`
//!   for a disc, 0 for a point; no `1/M` on a pivot, which holds the rod along its length). The
//!   impulse that stops the slip, `u_t/k_t`, is used if `|u_t| <= mu J k_t` (**stick**);
//!   otherwise the contact **slides** with `Jt = mu J sign(u_t)`.
//!
//! `J` and `Jt` are the impulses of the projectile on the rod (along +x and +y). The tangential
//! impulse acts along the rod's axis, through its centre: it never changes omega.
//!
//! A fast case of the core: it must equal `impact::solve_contact(&scene.system(),
//! Law::Newton)` (both impulses, the contact mode, every body's motion; Poisson's and
//! Stronge's laws give the same answer here, W being diagonal), which
//! `tests/lib/fast_routes.rs` checks on random oblique, frictional, disc and moving-rod
//! scenes in Q.

use super::linear;
use crate::field::Field;
use crate::field::Q;
use crate::impact::{Balance, Balances, EnergyLedger, Mode, within_cone};
use crate::mechanics::planar::{
    PlanarBody, Vec2, angular_momentum, disc_inertia, kinetic_energy, linear_momentum,
};
use crate::scene::Motion;
use crate::scene::{ObliqueParams, Params, RodMotion, Support};
use num_traits::Signed;
use std::cmp::Ordering;

/// Why an oblique scene has no answer in a number type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum Refusal {
    /// The impulse equations are singular in this number type.
    #[error("the impulse equations are singular in this number type")]
    Singular,
    /// Stick or slide cannot be decided in this number type (a symbolic slip or friction
    /// coefficient) and no decision was given.
    #[error("stick or slide cannot be decided here: give the contact")]
    Undecided,
}

/// The motion of both bodies, across and along the rod, with the disc's spin.
#[derive(Debug, Clone, PartialEq)]
pub struct State<F> {
    /// The projectile's velocity along x.
    pub v: F,
    /// The projectile's velocity along the rod (y).
    pub vt: F,
    /// The disc's angular velocity (counterclockwise seen from above), `None` for a point.
    pub spin: Option<F>,
    /// The rod's centre velocity and angular velocity.
    pub rod: RodMotion<F>,
}

impl<F> State<F> {
    /// Each velocity mapped by `f`: a change of number type.
    fn map<G>(self, f: &mut impl FnMut(F) -> G) -> State<G> {
        State {
            v: f(self.v),
            vt: f(self.vt),
            spin: self.spin.map(&mut *f),
            rod: self.rod.map(f),
        }
    }
}

/// An oblique impact solved: both states, both impulses, the contact, energies and residuals.
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueOutcome<F> {
    /// The motion before the impact.
    pub before: State<F>,
    /// The motion after the impact.
    pub after: State<F>,
    /// The normal impulse J of the projectile on the rod (+x).
    pub impulse: F,
    /// The tangential impulse Jt of the projectile on the rod (+y).
    pub tangential_impulse: F,
    /// Stick or slide (with the slip's sign before the impact), when friction acts
    /// (mu != 0).
    pub contact: Option<Mode>,
    /// The tangential impulse that would stop the slip, u_t/k_t (used when sticking); the
    /// friction needed to stick is mu* = |stick_impulse|/J.
    pub stick_impulse: F,
    /// The pivot's impulse on the rod across and along the rod (pivot only).
    pub pivot_impulse: Option<(F, F)>,
    /// Kinetic energy before and after.
    pub energy: EnergyLedger<F>,
    /// The closed form of the loss to restitution, (1 - e^2) u_n^2/(2 k_n).
    pub lost_restitution: F,
    /// The closed form of the loss to friction: 0 without friction, u_t^2/(2 k_t) when
    /// sticking, mu J (|u_t| - mu J k_t/2) when sliding.
    pub lost_friction: F,
    /// The conservation laws' residuals: linear momentum across and along the rod (free rod
    /// only), angular momentum about the rod's centre or the pivot, and the energy lost minus
    /// `lost_restitution + lost_friction`.
    pub residuals: Balances<F>,
}

impl<F> ObliqueOutcome<F> {
    /// Every number mapped by `f`: a change of number type (the contact mode is kept).
    pub(crate) fn map<G>(self, mut f: impl FnMut(F) -> G) -> ObliqueOutcome<G> {
        let f = &mut f;
        ObliqueOutcome {
            before: self.before.map(f),
            after: self.after.map(f),
            impulse: f(self.impulse),
            tangential_impulse: f(self.tangential_impulse),
            contact: self.contact,
            stick_impulse: f(self.stick_impulse),
            pivot_impulse: self.pivot_impulse.map(|(x, y)| (f(x), f(y))),
            energy: self.energy.map(f),
            lost_restitution: f(self.lost_restitution),
            lost_friction: f(self.lost_friction),
            residuals: self.residuals.map(f),
        }
    }
}

impl ObliqueOutcome<Q> {
    /// The friction coefficient at which the contact just sticks, mu* = |Jt_stick|/J (the
    /// normal impulse J is positive).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene, solve::fast::oblique::solve};
    /// // The sliding end hit: slip 1, k_t = 2, so sticking needs 1/2 = mu* J with J = 2/5.
    /// let s = Scene::builder(q(1, 1), q(1, 1)).v0t(q(1, 1)).mu(q(1, 2)).build()?;
    /// let out = solve(&s.params(), &s.oblique().expect("oblique").params(), None).expect("solves");
    /// assert_eq!(out.mu_star(), q(5, 4));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn mu_star(&self) -> Q {
        self.stick_impulse.abs() / &self.impulse
    }
}

/// The normal problem: `p` with the approach speed `u_n = v0 - (V0 + omega0 a)` as its v0.
///
/// # Examples
/// ```
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// use rodimpact::solve::fast::oblique::normal_params;
/// let s = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).rod_before(q(1, 1), q(5, 1), q(0, 1)).build().unwrap();
/// assert_eq!(normal_params(&s.params::<Q>(), &s.oblique().unwrap().params()).v0, q(2, 1));
/// ```
pub fn normal_params<F: Field>(p: &Params<F>, o: &ObliqueParams<F>) -> Params<F> {
    let rod = o.rod_moving(&p.support);
    Params {
        v0: p.v0.clone() - &(rod.v + &(rod.omega * &p.a)),
        ..p.clone()
    }
}

/// Solves an oblique impact by the linear route for the normal problem. `given` takes the
/// contact as stick or slide whatever Coulomb's law decides (a symbolic scene's stick and
/// slide cases, a worked answer's mistaken contact); `None` lets the law decide, where the
/// field can (a field with signs always can).
///
/// # Errors
/// [`Refusal::Singular`] or [`Refusal::Undecided`].
///
/// # Examples
/// ```
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// use rodimpact::{impact::Mode, solve::fast::oblique::solve};
/// // Equal masses, centre hit, v0 = 1 and v0t = 1, mu = 1/4: the contact slides.
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).v0t(q(1, 1)).mu(q(1, 4)).build().unwrap();
/// let out = solve(&s.params::<Q>(), &s.oblique().unwrap().params(), None).unwrap();
/// assert_eq!(out.contact, Some(Mode::Slide { forward: true }));
/// assert_eq!(out.tangential_impulse, q(1, 4)); // mu J, J = 1
/// // Taken as sticking: the slip 1 stopped by k_t = 1/m + 1/M = 2, Jt = 1/2.
/// let stuck = solve(&s.params::<Q>(), &s.oblique().unwrap().params(), Some(Mode::Stick)).unwrap();
/// assert_eq!(stuck.tangential_impulse, q(1, 2));
/// ```
pub fn solve<F: Field>(
    p: &Params<F>,
    o: &ObliqueParams<F>,
    given: Option<Mode>,
) -> Result<ObliqueOutcome<F>, Refusal> {
    let response = linear::solve(&normal_params(p, o)).ok_or(Refusal::Singular)?;
    complete(p, o, response.after, given)
}

/// Completes the normal problem's answer `response` (the motion after the impact of the
/// paper's scene [`normal_params`], from any route) into the oblique outcome.
///
/// # Errors
/// [`Refusal::Undecided`] when `given` is `None` and the field cannot decide stick or slide;
/// [`Refusal::Singular`] for a zero mass.
///
/// # Examples
/// ```
/// use rodimpact::scene::Scene;
/// use rodimpact::field::{q, Q};
/// use rodimpact::scene::Motion;
/// use rodimpact::solve::fast::oblique::complete;
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).v0t(q(1, 1)).build().unwrap();
/// let response = Motion { v: q(0, 1), rod_v: q(1, 1), omega: q(0, 1) };
/// let out = complete(&s.params::<Q>(), &s.oblique().unwrap().params(), response, None).unwrap();
/// assert_eq!(out.after.vt, q(1, 1)); // no friction: the slide along the rod is kept
/// ```
pub fn complete<F: Field>(
    p: &Params<F>,
    o: &ObliqueParams<F>,
    response: Motion<F>,
    given: Option<Mode>,
) -> Result<ObliqueOutcome<F>, Refusal> {
    let rod0 = o.rod_moving(&p.support);
    let normal = normal_params(p, o);
    let approach = normal.v0.clone();
    let impulse = p.m.clone() * &(approach.clone() - &response.v);
    let free = matches!(p.support, Support::Free);
    let inv = |x: &F| F::one().checked_div(x).ok_or(Refusal::Singular);
    let inv_m = inv(&p.m)?;
    // The disc's rim point moves with vt + spin r; r^2/I_disc = 2/m.
    let disc_term = if o.disc.is_some() {
        inv_m.clone() * &F::from_i64(2)
    } else {
        F::zero()
    };
    let rod_term = if free { inv(&p.rod_mass)? } else { F::zero() };
    let k_t = inv_m.clone() + &disc_term + &rod_term;
    let slip = o.slip(&p.support);
    let stick_impulse = slip.clone() / &k_t;
    let contact = if o.mu.is_zero() {
        None
    } else {
        Some(
            given
                .or_else(|| decide(&slip, &(o.mu.clone() * &impulse * &k_t)))
                .ok_or(Refusal::Undecided)?,
        )
    };
    let jt = match contact {
        None | Some(Mode::Frictionless) => F::zero(),
        Some(Mode::Stick) => stick_impulse.clone(),
        Some(Mode::Slide { forward: true }) => o.mu.clone() * &impulse,
        Some(Mode::Slide { forward: false }) => -(o.mu.clone() * &impulse),
    };
    let before = State {
        v: p.v0.clone(),
        vt: o.v0t.clone(),
        spin: o.disc.as_ref().map(|d| d.spin.clone()),
        rod: rod0.clone(),
    };
    let after = State {
        v: response.v.clone() + &(p.v0.clone() - &approach),
        vt: o.v0t.clone() - &(jt.clone() * &inv_m),
        spin: o
            .disc
            .as_ref()
            .map(|d| d.spin.clone() - &(F::from_i64(2) * &jt * &inv_m / &d.radius)),
        rod: RodMotion {
            v: rod0.v.clone() + &response.rod_v,
            vt: rod0.vt.clone() + &(jt.clone() * &rod_term),
            omega: rod0.omega.clone() + &response.omega,
        },
    };
    let pivot_impulse = (!free).then(|| {
        let across = p.rod_mass.clone() * &(after.rod.v.clone() - &before.rod.v) - &impulse;
        (across, -jt.clone())
    });
    let k_n = inv_m.clone()
        + &match &p.support {
            Support::Free => rod_term.clone() + &(p.a.clone() * &p.a / &p.inertia),
            Support::Pivot(pivot) => {
                let d = p.a.clone() - pivot;
                d.clone() * &d / &p.inertia_about_axis()
            }
        };
    let two = F::from_i64(2);
    let lost_restitution =
        (F::one() - &(p.e.clone() * &p.e)) * &approach * &approach / &(two.clone() * &k_n);
    let lost_friction = match contact {
        None | Some(Mode::Frictionless) => F::zero(),
        Some(Mode::Stick) => slip.clone() * &slip / &(two.clone() * &k_t),
        Some(Mode::Slide { forward }) => {
            let speed = if forward { slip.clone() } else { -slip.clone() };
            let mu_j = o.mu.clone() * &impulse;
            mu_j.clone() * &(speed - &(mu_j * &k_t / &two))
        }
    };
    let (bodies_before, bodies_after) = (bodies(p, o, &before), bodies(p, o, &after));
    let energy_before = kinetic_energy(&bodies_before);
    let energy_after = kinetic_energy(&bodies_after);
    let energy = EnergyLedger::new(energy_before, energy_after);
    // Angular momentum about the centre or the pivot, in the paper's sign (-L_z).
    let about = Vec2::new(F::zero(), p.axis());
    let momentum = linear_momentum(&bodies_after).sub(&linear_momentum(&bodies_before));
    let mut residuals = Balances::new();
    if free {
        residuals.push(Balance::LinearMomentum, momentum.x);
        residuals.push(Balance::TangentialMomentum, momentum.y);
    }
    residuals.push(
        Balance::AngularMomentum,
        angular_momentum(&bodies_before, &about) - &angular_momentum(&bodies_after, &about),
    );
    residuals.push(
        Balance::EnergyLoss,
        energy.lost() - &lost_restitution - &lost_friction,
    );
    Ok(ObliqueOutcome {
        before,
        after,
        impulse,
        tangential_impulse: jt,
        contact,
        stick_impulse,
        pivot_impulse,
        energy,
        lost_restitution,
        lost_friction,
        residuals,
    })
}

/// Stick when the impulse that stops the slip lies in Coulomb's cone, `|slip| <= limit`
/// (limit = mu J k_t), slide otherwise; `None` when the field cannot tell.
fn decide<F: Field>(slip: &F, limit: &F) -> Option<Mode> {
    let forward = slip.sign()? == Ordering::Greater;
    if within_cone(slip, limit)? {
        Some(Mode::Stick)
    } else {
        Some(Mode::Slide { forward })
    }
}

/// The two bodies of an oblique impact as planar bodies: the projectile (a disc's centre at
/// (-r, a), a point's at (0, a)) and the rod (centre at the origin, counterclockwise spin
/// `-omega`: docs/conventions.md).
fn bodies<F: Field>(p: &Params<F>, o: &ObliqueParams<F>, s: &State<F>) -> [PlanarBody<F>; 2] {
    let (offset, inertia) = o.disc.as_ref().map_or_else(
        || (F::zero(), F::zero()),
        |d| (-d.radius.clone(), disc_inertia(&p.m, &d.radius)),
    );
    [
        PlanarBody {
            mass: p.m.clone(),
            inertia,
            centre: Vec2::new(offset, p.a.clone()),
            velocity: Vec2::new(s.v.clone(), s.vt.clone()),
            omega: s.spin.clone().unwrap_or_else(F::zero),
        },
        PlanarBody {
            mass: p.rod_mass.clone(),
            inertia: p.inertia.clone(),
            centre: Vec2::zero(),
            velocity: Vec2::new(s.rod.v.clone(), s.rod.vt.clone()),
            omega: -s.rod.omega.clone(),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, q};
    use crate::scene::Scene;

    fn solved(s: &Scene) -> ObliqueOutcome<Q> {
        solve(&s.params(), &s.oblique().expect("oblique").params(), None).expect("solves")
    }

    /// Free uniform rod m = M = 1, l = 1, end hit (a = 1), v0 = 1, v0t = 1, e = 1, mu = 1/2.
    /// By hand: k_n = 1 + 1 + 3 = 5, J = 2/5; k_t = 2, the stick impulse 1/2 > mu J = 1/5,
    /// so it slides with Jt = 1/5: vt = 4/5, Vt = 1/5, v = 3/5, V = 2/5, omega = 6/5.
    /// Friction loss mu J (|u_t| - mu J k_t/2) = 1/5 (1 - 1/5) = 4/25.
    #[test]
    fn sliding_end_hit_by_hand() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .v0t(q(1, 1))
            .mu(q(1, 2))
            .build()
            .unwrap();
        let out = solved(&s);
        assert_eq!(out.contact, Some(Mode::Slide { forward: true }));
        assert_eq!(
            (
                &out.after.v,
                &out.after.vt,
                &out.after.rod.v,
                &out.after.rod.vt
            ),
            (&q(3, 5), &q(4, 5), &q(2, 5), &q(1, 5))
        );
        assert_eq!(out.after.rod.omega, q(6, 5));
        assert_eq!(out.lost_friction, q(4, 25));
        assert_eq!(out.energy.lost(), q(4, 25));
        assert!(out.residuals.all_zero());
    }

    /// A disc (r = 1/2) spinning with 2 rad/s hits the centre of a free rod, v0t = 0, mu = 1,
    /// m = M = 1, e = 0. By hand: J = 1/2 (k_n = 2); slip u_t = spin r = 1, k_t = 1 + 2 + 1 = 4,
    /// stick impulse 1/4 <= mu J = 1/2: sticks. vt = -1/4, spin = 2 - 2 (1/4)/(1/2) = 1,
    /// Vt = 1/4, and the rim then moves with vt + spin r = 1/4 = Vt.
    #[test]
    fn spinning_disc_sticks_by_hand() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .a(q(0, 1))
            .e(q(0, 1))
            .mu(q(1, 1))
            .disc(q(1, 2), q(2, 1))
            .build()
            .unwrap();
        let out = solved(&s);
        assert_eq!(out.contact, Some(Mode::Stick));
        assert_eq!(out.tangential_impulse, q(1, 4));
        assert_eq!(
            (&out.after.vt, out.after.spin.as_ref(), &out.after.rod.vt),
            (&q(-1, 4), Some(&q(1, 1)), &q(1, 4))
        );
        assert_eq!(out.lost_friction, q(1, 8)); // u_t^2/(2 k_t)
        assert!(out.residuals.all_zero());
    }

    /// The same generic code in f64 decides the contact from float signs and lands within
    /// rounding of the exact sliding end hit above.
    #[test]
    fn floats_take_the_same_route() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .v0t(q(1, 1))
            .mu(q(1, 2))
            .build()
            .unwrap();
        let out = solve(&s.params::<f64>(), &s.oblique().unwrap().params(), None).unwrap();
        assert_eq!(out.contact, Some(Mode::Slide { forward: true }));
        for (float, exact) in [
            (out.after.vt, 0.8),
            (out.after.rod.vt, 0.2),
            (out.lost_friction, 0.16),
        ] {
            assert!((float - exact).abs() < 1e-15, "{float} vs {exact}");
        }
    }

    /// A pivoted rod (m = 1, M = 3, l = 1, pivot at -1, end hit, v0t = -2, mu = 1/3) takes the tangential impulse at the pivot: the rod gains no slide, the
    /// pivot pushes back with -Jt, and angular momentum about the pivot holds.
    #[test]
    fn pivot_absorbs_the_tangential_impulse() {
        let s = Scene::builder(q(1, 1), q(3, 1))
            .pivot(q(-1, 1))
            .v0t(q(-2, 1))
            .mu(q(1, 3))
            .build()
            .unwrap();
        let out = solved(&s);
        assert_eq!(out.after.rod.vt, q(0, 1));
        let (_, along) = out.pivot_impulse.clone().unwrap();
        assert_eq!(along, -out.tangential_impulse.clone());
        // d = 2, I_p = 4, J = 2/(1 + 4/4) = 1; slip -2 beyond mu J k_t = 1/3: slides back.
        assert_eq!(out.contact, Some(Mode::Slide { forward: false }));
        assert_eq!(out.tangential_impulse, q(-1, 3));
        assert!(out.residuals.all_zero());
    }
}
