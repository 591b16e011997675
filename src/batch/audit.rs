//! The physics audit of a claimed state after the impact (a physics engine's v, V, omega):
//! exact balances of the claimed state, and which wrong answer it is when it is one.
//!
//! Every quantity is computed exactly from the claimed numbers (each read as the exact rational
//! it denotes); a finding is reported when a balance misses by more than [`LAW_TOLERANCE`] of
//! its scale, or when the claimed state lies within [`STATE_TOLERANCE`] of a known wrong answer
//! and nearer to it than to the right one. Scales: m |v0| for linear momentum, m |v0| l for
//! angular momentum, the energy before the impact for energies, and for states the distance
//! `max(|dv|, |dV|, |d omega| l)` against |v0|.

use crate::field::big::{RBig, to_q, to_rbig};
use crate::field::{Field, Q};
use crate::mechanics::{Motion, angular_momentum, kinetic_energy, linear_momentum};
use crate::scene::{Params, Scene, Support};
use crate::solve::optimum::omega_max_squared;
use num_traits::Signed;

/// A balance counts as missed beyond this fraction of its scale: 1/1000.
pub const LAW_TOLERANCE: (i64, i64) = (1, 1000);
/// A claimed state is taken for another answer within this fraction of |v0|: 1/100.
pub const STATE_TOLERANCE: (i64, i64) = (1, 100);

/// What is wrong with a claimed state, in the order the `diagnosis` column lists them.
///
/// # Examples
/// ```
/// use rodimpact::batch::Finding;
/// assert_eq!(Finding::RestitutionIgnored.name(), "restitution-ignored");
/// assert_eq!(Finding::ALL.len(), 10);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Finding {
    /// The claimed kinetic energy exceeds the energy before the impact.
    EnergyGain,
    /// The claimed kinetic energy falls short of the exact energy after the impact (the loss
    /// the collision law allows).
    EnergyLoss,
    /// e > 0, and the claimed state is the e = 0 (sticking) answer.
    RestitutionIgnored,
    /// The claimed state is the state before the impact: no contact happened.
    NoContact,
    /// Linear momentum is not conserved (free rod only: a pivot takes an impulse).
    Momentum,
    /// Angular momentum about the rod's centre (free rod) or the pivot is not conserved.
    AngularMomentum,
    /// |omega| exceeds the largest |omega| any impact point on the struck side can give.
    AboveOmegaMax,
    /// The claimed state is the exact one with omega's sign flipped: a sign convention (the
    /// rod's spin counted clockwise) rather than wrong physics.
    OmegaSign,
    /// A claim is not a finite number (NaN, an infinity): the engine's state blew up.
    NonFinite,
    /// No finding above, but a claim disagrees.
    Off,
}

impl Finding {
    /// Every finding, in column order.
    pub const ALL: [Finding; 10] = [
        Finding::EnergyGain,
        Finding::EnergyLoss,
        Finding::RestitutionIgnored,
        Finding::NoContact,
        Finding::Momentum,
        Finding::AngularMomentum,
        Finding::AboveOmegaMax,
        Finding::OmegaSign,
        Finding::NonFinite,
        Finding::Off,
    ];

    /// The name written in the `diagnosis` column.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::Finding;
    /// assert_eq!(Finding::AboveOmegaMax.name(), "above-omega-max");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Finding::EnergyGain => "energy-gain",
            Finding::EnergyLoss => "energy-loss",
            Finding::RestitutionIgnored => "restitution-ignored",
            Finding::NoContact => "no-contact",
            Finding::Momentum => "momentum",
            Finding::AngularMomentum => "angular-momentum",
            Finding::AboveOmegaMax => "above-omega-max",
            Finding::OmegaSign => "omega-sign",
            Finding::NonFinite => "non-finite",
            Finding::Off => "off",
        }
    }
}

/// The audit of one claimed state: its findings (without [`Finding::Off`], which depends on
/// the agreement rule) and its energy change.
///
/// # Examples
/// A claimed state with 1 % more spin than the paper's exact answer (3/5, 2/5, 6/5):
/// ```
/// use rodimpact::{batch::{audit, Finding}, mechanics::Motion, scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// let exact = Motion { v: q(3, 5), rod_v: q(2, 5), omega: q(6, 5) };
/// let claimed = Motion { omega: q(606, 500), ..exact.clone() };
/// let a = audit(&s, &exact, &claimed);
/// assert_eq!(a.findings, [Finding::EnergyGain, Finding::AngularMomentum]);
/// // ((1.212^2 - 1.2^2)/3)/2 more energy, over the 1/2 before: +0.96 %
/// assert_eq!(a.energy_change, q(2412, 250_000));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Audit {
    /// The findings, in [`Finding::ALL`] order.
    pub findings: Vec<Finding>,
    /// (claimed kinetic energy - exact energy after) / energy before: + the claim kept or made
    /// energy the law does not allow, - it lost energy the law does not lose.
    pub energy_change: Q,
}

/// `n/d` in the audit's arithmetic.
fn fraction((n, d): (i64, i64)) -> RBig {
    RBig::from_parts(n.into(), d.unsigned_abs().into())
}

/// Audits `claimed` (the state after the impact) against the scene and its exact answer.
///
/// The balances and distances are computed over dashu's rationals ([`RBig`]), whose GCD keeps
/// an engine log's 10,000-digit cells to a fraction of a second; only the energy change comes
/// back as a [`Q`].
///
/// # Examples
/// Box2D 2.3 at v0 = 1 m/s, e = 1 (the paper's rod struck at l/2): it returns the sticking
/// answer 7/11, 4/11, 6/11 instead of 3/11, 8/11, 12/11.
/// ```
/// use rodimpact::{batch::{audit, Finding}, mechanics::Motion, scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build().unwrap();
/// let exact = Motion { v: q(3, 11), rod_v: q(8, 11), omega: q(12, 11) };
/// let claimed = Motion { v: q(63592, 100000), rod_v: q(36408, 100000), omega: q(54612, 100000) };
/// let a = audit(&s, &exact, &claimed);
/// assert_eq!(a.findings, [Finding::EnergyLoss, Finding::RestitutionIgnored]);
/// assert!(audit(&s, &exact, &exact).findings.is_empty());
/// ```
pub fn audit(scene: &Scene, exact: &Motion<Q>, claimed: &Motion<Q>) -> Audit {
    let params = scene.params::<RBig>();
    let (exact, claimed) = (exact.as_ref().map(to_rbig), claimed.as_ref().map(to_rbig));
    let before = Motion::before(params.v0.clone());
    let law = fraction(LAW_TOLERANCE);
    let momentum_scale = params.m.clone() * &params.v0.abs();
    let mut findings = Vec::new();

    let energy_before = kinetic_energy(&params, &before);
    let energy_claimed = kinetic_energy(&params, &claimed);
    let energy_exact = kinetic_energy(&params, &exact);
    if energy_claimed > energy_before.clone() * &(RBig::ONE + &law) {
        findings.push(Finding::EnergyGain);
    }
    if energy_claimed < energy_exact.clone() - &(law.clone() * &energy_before) {
        findings.push(Finding::EnergyLoss);
    }
    // The answer is linear in 1 + e: the e = 0 answer is before + (exact - before)/(1 + e).
    if scene.e().is_positive()
        && is_taken_for(&params, &claimed, &sticking(&params, &exact), &exact)
    {
        findings.push(Finding::RestitutionIgnored);
    }
    if is_taken_for(&params, &claimed, &before, &exact) {
        findings.push(Finding::NoContact);
    }
    if matches!(scene.support(), Support::Free) {
        let residual = linear_momentum(&params, &before) - linear_momentum(&params, &claimed);
        if residual.abs() > law.clone() * &momentum_scale {
            findings.push(Finding::Momentum);
        }
    }
    let axis = params.axis();
    let residual =
        angular_momentum(&params, &before, &axis) - angular_momentum(&params, &claimed, &axis);
    if residual.abs() > law.clone() * &momentum_scale * &params.half_length {
        findings.push(Finding::AngularMomentum);
    }
    // |omega| > omega_max (1 + law), squared: both sides are nonnegative.
    let omega_max_squared: RBig =
        omega_max_squared(scene).expect("a rod at rest before the impact has an optimum");
    let bound = omega_max_squared * &(RBig::ONE + &law).square();
    if claimed.omega.square() > bound {
        findings.push(Finding::AboveOmegaMax);
    }
    let flipped = Motion {
        omega: -exact.omega.clone(),
        ..exact.clone()
    };
    if exact.omega != RBig::ZERO && is_taken_for(&params, &claimed, &flipped, &exact) {
        findings.push(Finding::OmegaSign);
    }
    Audit {
        findings,
        energy_change: to_q(&((energy_claimed - energy_exact) / energy_before)),
    }
}

/// The e = 0 answer of the scene, from its exact answer.
fn sticking(params: &Params<RBig>, exact: &Motion<RBig>) -> Motion<RBig> {
    let share = RBig::ONE / (RBig::ONE + &params.e);
    let toward =
        |after: &RBig, before: &RBig| before.clone() + &((after.clone() - before) * &share);
    Motion {
        v: toward(&exact.v, &params.v0),
        rod_v: toward(&exact.rod_v, &RBig::ZERO),
        omega: toward(&exact.omega, &RBig::ZERO),
    }
}

/// The claimed state is within [`STATE_TOLERANCE`] of `other` and strictly nearer to it than
/// to the exact answer.
fn is_taken_for(
    params: &Params<RBig>,
    claimed: &Motion<RBig>,
    other: &Motion<RBig>,
    exact: &Motion<RBig>,
) -> bool {
    let distance = |x: &Motion<RBig>| {
        let spin = (claimed.omega.clone() - &x.omega).abs() * &params.half_length;
        [
            (claimed.v.clone() - &x.v).abs(),
            (claimed.rod_v.clone() - &x.rod_v).abs(),
            spin,
        ]
        .into_iter()
        .fold(RBig::ZERO, |a, b| if b > a { b } else { a })
    };
    let to_other = distance(other);
    to_other <= fraction(STATE_TOLERANCE) * &params.v0.abs() && to_other < distance(exact)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    fn motion(v: Q, rod_v: Q, omega: Q) -> Motion<Q> {
        Motion { v, rod_v, omega }
    }

    /// Pybullet's reading of the paper's scene (m = M = l = a = v0 = 1, e = 1): omega 1.245
    /// against omega_max = sqrt(6)/2 = 1.2247..., with 3 % more energy than before.
    #[test]
    fn a_spin_above_the_proven_maximum_is_found() {
        let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
        let exact = motion(q(3, 5), q(2, 5), q(6, 5));
        let claimed = motion(q(585, 1000), q(415, 1000), q(1245, 1000));
        let a = audit(&s, &exact, &claimed);
        assert_eq!(
            a.findings,
            [Finding::EnergyGain, Finding::AboveOmegaMax],
            "{a:?}"
        );
        // E = (0.585^2 + 0.415^2 + 1.245^2/3)/2 = 0.5155625 against 1/2: +3.1125 %.
        assert_eq!(a.energy_change, q(249, 8000));
        // Just inside the bound (1/1000 above sqrt(6)/2 is 1.22597...): not found.
        let inside = motion(q(3, 5), q(2, 5), q(1225, 1000));
        assert!(
            !audit(&s, &exact, &inside)
                .findings
                .contains(&Finding::AboveOmegaMax)
        );
    }

    /// Rapier's revolute joint, pivot at the centre struck at the end, e = 1: angular momentum
    /// about the pivot holds (0.54689 + 1.35932/3 = 1.0000) but 8.5 % of the energy is gone.
    /// The rod's centre does not move, so there is no linear-momentum balance to miss.
    #[test]
    fn a_joint_that_absorbs_the_bounce_loses_energy_but_keeps_angular_momentum() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .pivot(q(0, 1))
            .build()
            .unwrap();
        let exact = motion(q(1, 2), q(0, 1), q(3, 2));
        let claimed = motion(q(54689, 100_000), q(0, 1), q(135_932, 100_000));
        assert_eq!(audit(&s, &exact, &claimed).findings, [Finding::EnergyLoss]);
        let twisted = motion(q(1, 2), q(0, 1), q(14, 10));
        assert_eq!(
            audit(&s, &exact, &twisted).findings,
            [Finding::EnergyLoss, Finding::AngularMomentum]
        );
    }

    /// An engine that counts the rod's spin clockwise: the paper's exact state (3/5, 2/5, 6/5)
    /// reported with omega = -1.2. Angular momentum fails, and the sign flip is named.
    #[test]
    fn a_flipped_spin_is_named() {
        let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
        let exact = motion(q(3, 5), q(2, 5), q(6, 5));
        let flipped = motion(q(3, 5), q(2, 5), q(-6, 5));
        assert_eq!(
            audit(&s, &exact, &flipped).findings,
            [Finding::AngularMomentum, Finding::OmegaSign]
        );
        // A centre hit does not spin: nothing to flip.
        let centre = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).build().unwrap();
        let still = motion(q(0, 1), q(1, 1), q(0, 1));
        assert!(audit(&centre, &still, &still).findings.is_empty());
    }

    #[test]
    fn the_state_before_the_impact_is_no_contact_and_momentum_is_checked_on_a_free_rod() {
        let s = Scene::builder(q(1, 1), q(1, 1)).e(q(1, 2)).build().unwrap();
        let exact = crate::solve::fraction_free::solve(&s).after;
        let before = Motion::before(q(1, 1));
        assert_eq!(audit(&s, &exact, &before).findings, [Finding::NoContact]);
        let pushed = motion(
            exact.v.clone(),
            &exact.rod_v + q(1, 100),
            exact.omega.clone(),
        );
        assert_eq!(audit(&s, &exact, &pushed).findings, [Finding::Momentum]);
    }
}
