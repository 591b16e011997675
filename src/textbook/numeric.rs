//! Deciding a numeric claim against the exact value: a printed number by its own significant
//! figures (with exact rational bounds on pi for rpm), an exact number or a constant formula
//! exactly.

use super::answer::{AnswerAgreement, CheckedAnswer, RelError};
use super::claim::{ClaimedAnswer, ClaimedValue};
use super::exact::Exact;
use super::quantity::Quantity;
use super::sigfig::{Precision, Printed, Tie, round_at, round_sig};
use super::units::{Measured, Scale, pi_bounds};
use crate::field::decimal::pow10;
use crate::field::{Q, QSqrt};
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Decides a numeric claim (a printed number, or a formula without symbols) against the exact
/// value. `sig` overrides the printed significant figures.
///
/// # Examples
/// ```
/// use rodimpact::textbook::{numeric::decide, AnswerAgreement, ClaimedAnswer, Exact};
/// use rodimpact::field::q;
/// let d = decide(&ClaimedAnswer::parse("omega=1.90").unwrap(), &Exact::Rational(q(36, 19)), None);
/// assert_eq!(d.agreement, AnswerAgreement::LastDigit);
/// ```
pub fn decide(claim: &ClaimedAnswer, exact: &Exact, sig: Option<u32>) -> CheckedAnswer {
    let omega = claim.quantity == Quantity::Omega;
    decide_value(
        claim.quantity.name(),
        &claim.text,
        &claim.value,
        exact,
        omega,
        sig,
    )
}

/// Decides the claim `text` (read as `value`) named `name` against the exact value: a printed
/// number by its own significant figures (`sig` overrides them), an exact number or a constant
/// formula exactly. `by_magnitude` compares magnitudes and notes an opposite sign (textbooks'
/// rotation conventions differ); otherwise the sign counts.
///
/// # Examples
/// A published claim about any quantity, here a body's spin written as printed:
/// ```
/// use rodimpact::textbook::{numeric::decide_value, read_claimed, AnswerAgreement, Exact};
/// use rodimpact::{field::q, units::Dimension};
/// let value = read_claimed("bar.omega", "-16.714", Dimension::AngularSpeed)?;
/// let d = decide_value("bar.omega", "-16.714", &value, &Exact::Rational(q(-117, 7)), false, None);
/// assert_eq!(d.agreement, AnswerAgreement::Agrees);
/// let wrong = decide_value("bar.omega", "16.714", &read_claimed("bar.omega", "16.714", Dimension::AngularSpeed)?,
///                          &Exact::Rational(q(-117, 7)), false, None);
/// assert_eq!(wrong.agreement, AnswerAgreement::Disagrees);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn decide_value(
    name: &str,
    text: &str,
    value: &ClaimedValue,
    exact: &Exact,
    by_magnitude: bool,
    sig: Option<u32>,
) -> CheckedAnswer {
    let mut d = CheckedAnswer::new(name, text, exact.to_string(), Some(exact.clone()));
    let omega = by_magnitude;
    match value {
        ClaimedValue::Printed(m) => printed(&mut d, m, exact, omega, sig),
        ClaimedValue::Formula(r) => match r.constant() {
            Some((c, rad)) if !rad.is_negative() => {
                let (equal, same_sign) = radical_matches(&c, &rad, exact);
                d.agreement = if equal && (same_sign || omega) {
                    if !same_sign {
                        d.notes.push(opposite_sign_note());
                    }
                    AnswerAgreement::Agrees
                } else {
                    if equal {
                        d.notes.push(sign_only_note(name, c.is_positive()));
                    }
                    AnswerAgreement::Disagrees
                };
                let claim_mid = midpoint(&Exact::Surd(QSqrt::new(Q::zero(), c, rad)), 40);
                d.rel_error = rel_error(&claim_mid, &midpoint(exact, 40), omega);
            }
            _ => d.notes.push("the formula is not a real number".into()),
        },
    }
    d
}

/// The note for a claim whose magnitude agrees and whose sign does not: what the exact sign
/// means for the quantity `name` (the projectile's or the rod's velocity across the rod).
fn sign_only_note(name: &str, exact_negative: bool) -> String {
    let meaning = match (name.rsplit('.').next().unwrap_or(name), exact_negative) {
        ("v", true) => ": v < 0, the projectile rebounds (it moves back after the impact)",
        ("v", false) => ": v > 0, the projectile carries on forward",
        ("V", true) => ": V < 0, the rod's centre moves back, towards the projectile",
        ("V", false) => ": V > 0, the rod's centre moves forward, away from the projectile",
        _ => "",
    };
    format!("the magnitude agrees, only the sign differs{meaning}")
}

/// The note for an omega claim of the opposite sign.
fn opposite_sign_note() -> String {
    "opposite sign: compared by magnitude (textbooks' rotation conventions differ)".into()
}

/// Compares `c * sqrt(r)` with an exact value: (equal magnitudes, same sign).
///
/// # Examples
/// ```
/// use rodimpact::textbook::{numeric::radical_matches, Exact};
/// use rodimpact::field::{q, QSqrt};
/// let a = Exact::Surd(QSqrt::sqrt_of(&q(2, 3)));
/// assert_eq!(radical_matches(&q(1, 3), &q(6, 1), &a), (true, true));
/// assert_eq!(radical_matches(&q(-1, 1), &q(1, 1), &Exact::Rational(q(1, 1))), (true, false));
/// ```
pub fn radical_matches(c: &Q, r: &Q, exact: &Exact) -> (bool, bool) {
    let claim_sq = c * c * r;
    let (exact_sq, exact_sign) = match exact {
        Exact::Rational(x) => (Some(x * x), x.signum()),
        Exact::Surd(s) if s.x().is_zero() || s.y().is_zero() => {
            let d = s.d().cloned().unwrap_or_else(Q::zero);
            let sq = s.x() * s.x() + s.y() * s.y() * d;
            let sign = if s.x().is_zero() {
                s.y().signum()
            } else {
                s.x().signum()
            };
            (Some(sq), sign)
        }
        // x + y sqrt(d) with x, y != 0 has an irrational square; c^2 r is rational.
        Exact::Surd(s) => (
            None,
            ordering_sign(s.cmp_exact(&QSqrt::rational(Q::zero()))),
        ),
    };
    let equal = exact_sq.is_some_and(|sq| sq == claim_sq);
    let claim_sign = if r.is_zero() { Q::zero() } else { c.signum() };
    (equal, claim_sign == exact_sign || exact_sign.is_zero())
}

/// -1, 0 or 1 for an ordering against zero.
fn ordering_sign(o: Ordering) -> Q {
    Q::from_integer((o as i8).into())
}

fn printed(d: &mut CheckedAnswer, m: &Measured, exact: &Exact, omega: bool, sig: Option<u32>) {
    let mut p: Printed = m.printed.clone();
    if let Some(n) = sig {
        p = p.clone().with_sig(n).unwrap_or(p);
    }
    if let Precision::Figures {
        figures,
        ambiguous: Some((lo, hi)),
    } = p.precision
    {
        d.notes.push(format!(
            "'{}' is ambiguous ({lo} to {hi} significant figures): read with {figures}, the most lenient; --sig decides",
            d.claim
        ));
    }
    let scale = m.scale();
    if let (Scale::Pi(factor), Some(unit)) = (&scale, &m.unit) {
        let size = if factor.is_integer() {
            format!("{factor} pi")
        } else {
            format!("pi/{}", factor.recip())
        };
        d.notes.push(format!(
            "{} = {size} rad/s: decided with exact rational bounds on pi",
            unit.name
        ));
    }
    let claim_value = if omega {
        p.value.abs()
    } else {
        p.value.clone()
    };
    for digits in [40, 100, 400, 1100] {
        let (lo, hi) = enclose(exact, &scale, digits);
        let (lo, hi, negative) = if !omega || !lo.is_negative() {
            (lo, hi, false)
        } else if !hi.is_positive() {
            (-hi, -lo, true)
        } else {
            continue;
        };
        let Some(agreement) = judge(&claim_value, &p, &lo, &hi) else {
            continue;
        };
        d.agreement = agreement;
        let mid = (&lo + &hi) / Q::from_integer(2.into());
        d.rel_error = RelError::new(claim_value.clone(), mid.clone());
        if omega && !p.value.is_zero() && !mid.is_zero() && p.value.is_negative() != negative {
            d.notes.push(opposite_sign_note());
        }
        if agreement == AnswerAgreement::Disagrees
            && judge(&-claim_value.clone(), &p, &lo, &hi) == Some(AnswerAgreement::Agrees)
        {
            d.notes.push(sign_only_note(&d.name, mid.is_negative()));
        }
        if p.precision == Precision::Exact && lo != hi {
            d.notes
                .push("an exact fraction cannot equal this irrational value".into());
        }
        return;
    }
    d.notes
        .push("not decided: the exact value's bounds (and pi's, to 100 decimals) are too wide for these figures".into());
}

/// The agreement of a printed value against an exact value known to lie in `[lo, hi]`, or `None`
/// when the interval is still too wide to decide the rounding.
fn judge(claim: &Q, p: &Printed, lo: &Q, hi: &Q) -> Option<AnswerAgreement> {
    let round = |x: &Q, tie: Tie| match &p.precision {
        Precision::ZeroAt { place } => round_at(x, *place, tie),
        Precision::Figures { figures, .. } => round_sig(x, *figures, tie),
        Precision::Exact => x.clone(),
    };
    if p.precision == Precision::Exact {
        return Some(if lo == hi && claim == lo {
            AnswerAgreement::Agrees
        } else {
            AnswerAgreement::Disagrees
        });
    }
    let mut accepted = Vec::with_capacity(2);
    for tie in [Tie::Up, Tie::Down] {
        let r = round(lo, tie);
        if r != round(hi, tie) {
            return None;
        }
        accepted.push(r);
    }
    if accepted.contains(claim) {
        return Some(AnswerAgreement::Agrees);
    }
    let unit = pow10(p.place().unwrap_or(0));
    let one_digit_off = accepted.iter().any(|r| (claim - r).abs() == unit);
    let within_a_unit = (claim - lo).abs() <= unit && (claim - hi).abs() <= unit;
    let two_figures = matches!(p.precision, Precision::Figures { figures, .. } if figures >= 2);
    if one_digit_off && within_a_unit && two_figures {
        Some(AnswerAgreement::LastDigit)
    } else {
        Some(AnswerAgreement::Disagrees)
    }
}

/// Rational bounds on the exact value expressed in a unit of the given scale.
fn enclose(exact: &Exact, scale: &Scale, digits: usize) -> (Q, Q) {
    let (lo, hi) = match exact {
        Exact::Rational(x) => (x.clone(), x.clone()),
        Exact::Surd(s) => s.bounds(digits),
    };
    match scale {
        Scale::Rational(f) => (lo / f, hi / f),
        Scale::Pi(f) => {
            let (pl, ph) = pi_bounds(digits as u32);
            let quotients = [
                &lo / (f * &pl),
                &lo / (f * &ph),
                &hi / (f * &pl),
                &hi / (f * &ph),
            ];
            let min = quotients.iter().min().cloned().unwrap_or_else(Q::zero);
            let max = quotients.iter().max().cloned().unwrap_or_else(Q::zero);
            (min, max)
        }
    }
}

/// The midpoint of rational bounds on `exact`, `digits` digits tight.
pub(crate) fn midpoint(exact: &Exact, digits: usize) -> Q {
    let (lo, hi) = enclose(exact, &Scale::Rational(Q::from_integer(1.into())), digits);
    (lo + hi) / Q::from_integer(2.into())
}

/// The relative error of `claim` against `exact` (magnitudes for omega); `None` for an exact 0.
///
/// # Examples
/// ```
/// use rodimpact::textbook::numeric::rel_error;
/// use rodimpact::field::q;
/// assert_eq!(rel_error(&q(1, 2), &q(1, 1), false).unwrap().value(), q(-1, 2));
/// assert_eq!(rel_error(&q(-1, 2), &q(1, 1), true).unwrap().value(), q(-1, 2)); // magnitudes
/// assert_eq!(rel_error(&q(1, 1), &q(0, 1), false), None);
/// ```
pub fn rel_error(claim: &Q, exact: &Q, magnitudes: bool) -> Option<RelError> {
    if magnitudes {
        RelError::new(claim.abs(), exact.abs())
    } else {
        RelError::new(claim.clone(), exact.clone())
    }
}
