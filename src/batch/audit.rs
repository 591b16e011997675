//! The physics audit of a claimed state after the impact (a physics engine's v, V, omega):
//! exact balances of the claimed state, and which wrong answer it is when it is one.
//!
//! Every quantity is computed exactly from the claimed numbers (each read as the exact rational
//! it denotes); a finding is reported when a balance misses by more than [`LAW_TOLERANCE`] of
//! its scale, or when the claimed state lies within [`STATE_TOLERANCE`] of a known wrong answer
//! and nearer to it than to the right one. Scales: m |v0| for linear momentum, m |v0| l for
//! angular momentum, the energy before the impact for energies, and for states the distance
//! `max(|dv|, |dV|, |d omega| l)` against |v0|.

use crate::field::big::{Relaxed, relaxed_to_q, to_relaxed};
use crate::field::int::{I256, Unreduced, UnreducedInt, Wide, within};
use crate::field::{Field, Q, abs};
use crate::scene::{Motion, angular_momentum, kinetic_energy, linear_momentum};
use crate::scene::{Params, Scene, Support};
use crate::solve::optimum::omega_max_squared_of;
use std::cmp::Ordering;

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
/// use rodimpact::{batch::{audit, Finding}, scene::{Motion, Scene}, field::q};
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

/// `n/d` (in lowest terms, `d > 0`: the tolerances) in the audit's arithmetic.
fn fraction<F: Field>((n, d): (i64, i64)) -> F {
    F::from_rational(&Q::new_raw(n.into(), d.into()))
}

/// Audits `claimed` (the state after the impact) against the scene and its exact answer.
///
/// The balances and distances are computed on unreduced fractions of 256-bit, then 512-bit
/// integers, where an engine's 17-digit cells fit, else over dashu's rationals, unreduced
/// ([`Relaxed`]: the audit's depth is bounded, and a GCD after each of its operations cost more
/// than the longer products); the result is the same.
///
/// # Examples
/// Box2D 2.3 at v0 = 1 m/s, e = 1 (the paper's rod struck at l/2): it returns the sticking
/// answer 7/11, 4/11, 6/11 instead of 3/11, 8/11, 12/11.
/// ```
/// use rodimpact::{batch::{audit, Finding}, scene::{Motion, Scene}, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build().unwrap();
/// let exact = Motion { v: q(3, 11), rod_v: q(8, 11), omega: q(12, 11) };
/// let claimed = Motion { v: q(63592, 100000), rod_v: q(36408, 100000), omega: q(54612, 100000) };
/// let a = audit(&s, &exact, &claimed);
/// assert_eq!(a.findings, [Finding::EnergyLoss, Finding::RestitutionIgnored]);
/// assert!(audit(&s, &exact, &exact).findings.is_empty());
/// ```
pub fn audit(scene: &Scene, exact: &Motion<Q>, claimed: &Motion<Q>) -> Audit {
    // Not i128 first: an engine's 17-digit spin squared against the bound times (1 + 1/1000)^2
    // passes 127 bits, and the failed attempt cost more than it saved. Nor a width the claims'
    // squares alone would fill (a claim of 1e-91 has a 303-bit denominator): a choice of cost
    // only, every width gives the same answer or none.
    let widest = [claimed, exact]
        .iter()
        .flat_map(|m| [&m.v, &m.rod_v, &m.omega])
        .map(|x| x.numer().bits().max(x.denom().bits()))
        .max()
        .unwrap_or(0);
    let words = (widest <= 64)
        .then(|| audit_on_words::<I256>(scene, exact, claimed))
        .flatten()
        .or_else(|| {
            (widest <= 128)
                .then(|| audit_on_words::<Wide>(scene, exact, claimed))
                .flatten()
        });
    let (findings, energy_change) = match words {
        Some(done) => done,
        None => {
            let lift = |m: &Motion<Q>| m.as_ref().map(to_relaxed);
            let (findings, change) =
                audit_in(&scene.params::<Relaxed>(), &lift(exact), &lift(claimed));
            (findings, relaxed_to_q(change))
        }
    };
    Audit {
        findings,
        energy_change,
    }
}

/// [`audit`] on unreduced fractions of `T`; `None` when a value leaves its width.
fn audit_on_words<T: UnreducedInt>(
    scene: &Scene,
    exact: &Motion<Q>,
    claimed: &Motion<Q>,
) -> Option<(Vec<Finding>, Q)> {
    let lift = |m: &Motion<Q>| m.as_ref().map(Unreduced::<T>::from_rational);
    within(|| {
        audit_in(
            &scene.params::<Unreduced<T>>(),
            &lift(exact),
            &lift(claimed),
        )
    })
    .map(|(findings, change)| (findings, change.to_q()))
}

/// [`audit`] in an exact ordered field `F`, on the scene's parameters (a rod at rest before a
/// normal impact): the findings (without [`Finding::NonFinite`] and [`Finding::Off`]) and the
/// energy change.
pub(crate) fn audit_in<F: Field + PartialOrd>(
    params: &Params<F>,
    exact: &Motion<F>,
    claimed: &Motion<F>,
) -> (Vec<Finding>, F) {
    let before = Motion::before(params.v0.clone());
    let law: F = fraction(LAW_TOLERANCE);
    let momentum_scale = params.m.clone() * &abs(params.v0.clone());
    let mut findings = Vec::new();

    let energy_before = kinetic_energy(params, &before);
    let energy_claimed = kinetic_energy(params, claimed);
    let energy_exact = kinetic_energy(params, exact);
    if energy_claimed > energy_before.clone() * &(F::one() + &law) {
        findings.push(Finding::EnergyGain);
    }
    if energy_claimed < energy_exact.clone() - &(law.clone() * &energy_before) {
        findings.push(Finding::EnergyLoss);
    }
    // The answer is linear in 1 + e: the e = 0 answer is before + (exact - before)/(1 + e).
    if params.e.sign() == Some(Ordering::Greater)
        && is_taken_for(params, claimed, &sticking(params, exact), exact)
    {
        findings.push(Finding::RestitutionIgnored);
    }
    if is_taken_for(params, claimed, &before, exact) {
        findings.push(Finding::NoContact);
    }
    if matches!(params.support, Support::Free) {
        let residual = linear_momentum(params, &before) - linear_momentum(params, claimed);
        if abs(residual) > law.clone() * &momentum_scale {
            findings.push(Finding::Momentum);
        }
    }
    let axis = params.axis();
    let residual =
        angular_momentum(params, &before, &axis) - angular_momentum(params, claimed, &axis);
    if abs(residual) > law.clone() * &momentum_scale * &params.half_length {
        findings.push(Finding::AngularMomentum);
    }
    // |omega| > omega_max (1 + law), squared: both sides are nonnegative.
    let bound = omega_max_squared_of(params) * &(F::one() + &law).square();
    if claimed.omega.square() > bound {
        findings.push(Finding::AboveOmegaMax);
    }
    let flipped = Motion {
        omega: -exact.omega.clone(),
        ..exact.clone()
    };
    if !exact.omega.is_zero() && is_taken_for(params, claimed, &flipped, exact) {
        findings.push(Finding::OmegaSign);
    }
    let change = (energy_claimed - energy_exact) / energy_before;
    (findings, change)
}

/// The e = 0 answer of the scene, from its exact answer.
fn sticking<F: Field>(params: &Params<F>, exact: &Motion<F>) -> Motion<F> {
    let share = F::one() / (F::one() + &params.e);
    let toward = |after: &F, before: &F| before.clone() + &((after.clone() - before) * &share);
    Motion {
        v: toward(&exact.v, &params.v0),
        rod_v: toward(&exact.rod_v, &F::zero()),
        omega: toward(&exact.omega, &F::zero()),
    }
}

/// The claimed state is within [`STATE_TOLERANCE`] of `other` and strictly nearer to it than
/// to the exact answer.
fn is_taken_for<F: Field + PartialOrd>(
    params: &Params<F>,
    claimed: &Motion<F>,
    other: &Motion<F>,
    exact: &Motion<F>,
) -> bool {
    let distance = |x: &Motion<F>| {
        let spin = abs(claimed.omega.clone() - &x.omega) * &params.half_length;
        [
            abs(claimed.v.clone() - &x.v),
            abs(claimed.rod_v.clone() - &x.rod_v),
            spin,
        ]
        .into_iter()
        .fold(F::zero(), |a, b| if b > a { b } else { a })
    };
    let to_other = distance(other);
    to_other <= fraction::<F>(STATE_TOLERANCE) * &abs(params.v0.clone())
        && to_other < distance(exact)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use crate::scene::RodInertia;
    use proptest::prelude::*;

    /// A scene of small fractions (free or pivoted, every rod, e from 0 to 1) and a claimed
    /// state written as an engine writes it: each exact value times (1 + k/10^j), rounded to
    /// 17 significant digits, or the exact value itself.
    fn claimed_row() -> impl Strategy<Value = (Scene, Motion<Q>, Motion<Q>)> {
        let part = || (1i64..40, 1i64..12).prop_map(|(n, d)| q(n, d));
        let rod = prop_oneof![
            Just(RodInertia::Uniform),
            Just(RodInertia::Dumbbell),
            (1i64..5, 2i64..9).prop_map(|(n, d)| RodInertia::Gyration(q(n, d))),
        ];
        let claim = || (-3i64..4, 2u32..18, any::<bool>());
        (
            (part(), part(), part(), -12i64..=12, part(), 0i64..=4),
            (rod, proptest::option::of(-4i64..=4)),
            (claim(), claim(), claim()),
        )
            .prop_filter_map(
                "a valid scene",
                |((m, big_m, l, a, v0, e), (rod, pivot), claims)| {
                    let mut b = Scene::builder(m, big_m)
                        .half_length(l.clone())
                        .a(l.clone() * q(a, 12))
                        .v0(v0)
                        .e(q(e, 4))
                        .rod(rod);
                    if let Some(p) = pivot {
                        b = b.pivot(l * q(p, 4));
                    }
                    let scene = b.build().ok()?;
                    let exact = crate::solve::fast::fraction_free::solve(&scene).after;
                    let engine = |x: &Q, (k, j, exact_claim): (i64, u32, bool)| {
                        if exact_claim {
                            return x.clone();
                        }
                        let off = x * (Q::from_integer(1.into()) + q(k, 10i64.pow(j.min(17))));
                        crate::number::parse(&crate::field::decimal::decimal(&off, 17))
                            .ok()
                            .unwrap_or(off)
                    };
                    let claimed = Motion {
                        v: engine(&exact.v, claims.0),
                        rod_v: engine(&exact.rod_v, claims.1),
                        omega: engine(&exact.omega, claims.2),
                    };
                    Some((scene, exact, claimed))
                },
            )
    }

    proptest! {
        /// Law: the audit on unreduced 256-bit and 512-bit fractions, and on dashu's unreduced
        /// rationals (`audit`'s last resort), finds what the audit over dashu's reduced
        /// rationals finds, with the same energy change, whenever it fits (a scene whose
        /// fractions have many distinct denominators may not fit the words).
        #[test]
        fn the_fixed_width_audit_is_the_unbounded_one((scene, exact, claimed) in claimed_row()) {
            use crate::field::big::{RBig, to_q, to_rbig};
            let lift = |m: &Motion<Q>| m.as_ref().map(to_rbig);
            let (findings, change) =
                audit_in(&scene.params::<RBig>(), &lift(&exact), &lift(&claimed));
            let unbounded = (findings, to_q(&change));
            let lift = |m: &Motion<Q>| m.as_ref().map(to_relaxed);
            let (findings, change) =
                audit_in(&scene.params::<Relaxed>(), &lift(&exact), &lift(&claimed));
            prop_assert_eq!(&(findings, relaxed_to_q(change)), &unbounded);
            for words in [
                audit_on_words::<I256>(&scene, &exact, &claimed),
                audit_on_words::<Wide>(&scene, &exact, &claimed),
            ].into_iter().flatten() {
                prop_assert_eq!(&words, &unbounded);
            }
            prop_assert_eq!(audit(&scene, &exact, &claimed), Audit {
                findings: unbounded.0,
                energy_change: unbounded.1,
            });
        }
    }

    fn motion(v: Q, rod_v: Q, omega: Q) -> Motion<Q> {
        Motion { v, rod_v, omega }
    }

    /// An engine's row (Rapier f64, the paper's rod struck at l/2, v0 = 3: exact 9/11, 24/11,
    /// 36/11) fits 256 bits, and its audit there is the unbounded one: nothing found,
    /// the spin's last digit an energy change of -9.09e-17.
    #[test]
    fn an_engine_row_is_audited_in_the_fixed_width() {
        let s = Scene::builder(q(1, 1), q(1, 1))
            .a(q(1, 2))
            .v0(q(3, 1))
            .build()
            .unwrap();
        let exact = motion(q(9, 11), q(24, 11), q(36, 11));
        let parse = |x: &str| crate::number::parse(x).unwrap();
        let claimed = motion(
            parse("0.8181818181818183"),
            parse("2.1818181818181817"),
            parse("3.2727272727272725"),
        );
        let words = audit_on_words::<I256>(&s, &exact, &claimed).expect("fits 256 bits");
        assert_eq!(words.0, []);
        assert_eq!(crate::field::decimal::decimal(&words.1, 3), "-9.09e-17");
        assert_eq!(audit(&s, &exact, &claimed).energy_change, words.1);
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
        let exact = crate::solve::fast::fraction_free::solve(&s).after;
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
