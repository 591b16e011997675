//! Deciding a claimed formula against the exact value over a symbolic scene's domain: as an
//! identity in exact rational-function arithmetic, or refuted by a sample scene where the two
//! differ.

use super::scene::{SAMPLES, SymbolicScene};
use crate::error::Error;
use crate::field::decimal;
use crate::field::{Poly, Q, RatFn, Sym};
use crate::textbook::answer::{AnswerAgreement, CheckedAnswer, Counterexample, RelError};
use crate::textbook::claim::ClaimedAnswer;
use crate::textbook::exact::Exact;
use crate::textbook::expr::{Budget, OBLIQUE_SYMBOLS, Radical, words};
use crate::textbook::numeric::{midpoint, radical_matches};
use crate::textbook::quantity::Quantity;
use num_traits::Signed;

/// Decides `claim == exact` over the domain, both `coeff * sqrt(radicand)`.
pub(crate) fn identity(
    claim: &ClaimedAnswer,
    c: &Radical,
    exact: &Radical,
    scene: &SymbolicScene,
    budget: &mut Budget,
    field: &str,
) -> Result<CheckedAnswer, Error> {
    let omega = claim.quantity == Quantity::Omega;
    // The oblique symbols either side uses (v0t, mu, ...) are free too, and sampled with the rest.
    let extra: Vec<Sym> = OBLIQUE_SYMBOLS
        .iter()
        .map(|n| Sym::new(n))
        .filter(|&s| c.mentions(s) || exact.mentions(s))
        .collect();
    let mut d = CheckedAnswer::new(claim.quantity.name(), &claim.text, exact.to_string(), None);
    let mut squares_agree = false;
    if c.is_rational() && exact.is_rational() {
        let (claimed, value) = (Fraction::of(&c.coeff), Fraction::of(&exact.coeff));
        if claimed.equals(&value, false, budget, field)? {
            d.agreement = AnswerAgreement::Agrees;
            d.notes.push(identity_note(scene, &extra));
            return Ok(d);
        }
        if omega && claimed.equals(&value, true, budget, field)? {
            d.agreement = AnswerAgreement::Agrees;
            d.notes.push(identity_note(scene, &extra));
            d.notes
                .push("opposite sign: compared by magnitude (rotation conventions differ)".into());
            return Ok(d);
        }
    } else {
        let square = |x: &Radical, budget: &mut Budget| {
            let coeff = Fraction::of(&x.coeff);
            coeff
                .times(&coeff, budget, field)?
                .times(&Fraction::of(&x.radicand), budget, field)
        };
        let (claimed, value) = (square(c, budget)?, square(exact, budget)?);
        if claimed.equals(&value, false, budget, field)? {
            squares_agree = true;
            d.notes.push(
                "the squares agree identically, and both sides have the same sign (checked at a sample scene)".into(),
            );
        }
    }
    // Search a valid scene where the values differ (or, for a root, fix the sign).
    let per_sample = eval_cost(c).saturating_add(eval_cost(exact));
    for point in scene.samples_with(&extra, SAMPLES) {
        budget.charge(field, per_sample)?;
        let at = |f: &RatFn| f.eval::<Q>(&|s| point.get(&s).cloned());
        let (Some(cc), Some(cr), Some(ec), Some(er)) = (
            at(&c.coeff),
            at(&c.radicand),
            at(&exact.coeff),
            at(&exact.radicand),
        ) else {
            continue;
        };
        if cr.is_negative() || er.is_negative() {
            continue;
        }
        let value = Exact::radical(ec, er);
        let (equal, same_sign) = radical_matches(&cc, &cr, &value);
        if equal && (same_sign || omega) && squares_agree {
            d.agreement = AnswerAgreement::Agrees;
            if !same_sign {
                d.notes.push("opposite sign: compared by magnitude".into());
            }
            return Ok(d);
        }
        if !(equal && (same_sign || omega)) {
            let counterexample = Counterexample {
                point: point
                    .iter()
                    .map(|(s, v)| (s.name().to_string(), v.clone()))
                    .collect(),
                exact: value,
                claimed: Exact::radical(cc, cr),
            };
            refute(&mut d, counterexample, omega);
            return Ok(d);
        }
    }
    d.notes
        .push("no valid sample scene separates the claim from the exact value".into());
    Ok(d)
}

/// The work of evaluating `x` at a point: for each polynomial, its terms times its words (each
/// term is added to a sum that grows to the size of the whole).
fn eval_cost(x: &Radical) -> u64 {
    [
        x.coeff.num(),
        x.coeff.den(),
        x.radicand.num(),
        x.radicand.den(),
    ]
    .iter()
    .map(|p| (p.terms().count() as u64).saturating_mul(words(p)))
    .fold(0, u64::saturating_add)
}

/// A rational function as an unreduced quotient of polynomials: identities are decided by
/// cross-multiplying, without the GCDs that reducing would cost.
struct Fraction {
    num: Poly,
    den: Poly,
}

impl Fraction {
    fn of(f: &RatFn) -> Fraction {
        Fraction {
            num: f.num().clone(),
            den: f.den().clone(),
        }
    }

    /// The product, its work charged.
    fn times(&self, other: &Fraction, budget: &mut Budget, field: &str) -> Result<Fraction, Error> {
        let cost = words(&self.num).saturating_mul(words(&other.num))
            + words(&self.den).saturating_mul(words(&other.den));
        budget.charge(field, cost)?;
        Ok(Fraction {
            num: &self.num * &other.num,
            den: &self.den * &other.den,
        })
    }

    /// Whether `self == other` (or `self == -other` when `negated`) identically.
    fn equals(
        &self,
        other: &Fraction,
        negated: bool,
        budget: &mut Budget,
        field: &str,
    ) -> Result<bool, Error> {
        let cost = words(&self.num).saturating_mul(words(&other.den))
            + words(&other.num).saturating_mul(words(&self.den));
        budget.charge(field, cost)?;
        let (left, right) = (&self.num * &other.den, &other.num * &self.den);
        Ok(if negated {
            (left + &right).is_zero()
        } else {
            (left - &right).is_zero()
        })
    }
}

fn identity_note(scene: &SymbolicScene, extra: &[Sym]) -> String {
    let free: Vec<&str> = scene.free.iter().chain(extra).map(|s| s.name()).collect();
    if free.is_empty() {
        "exact: equal as numbers".into()
    } else {
        format!(
            "identity in {} (exact rational-function arithmetic)",
            free.join(", ")
        )
    }
}

/// Refutes the claim with a counterexample scene: the relative error there, and a note.
fn refute(answer: &mut CheckedAnswer, counterexample: Counterexample, omega: bool) {
    answer.agreement = AnswerAgreement::Disagrees;
    let (claimed, exact) = (
        midpoint(&counterexample.claimed, 40),
        midpoint(&counterexample.exact, 40),
    );
    let (claimed, exact) = if omega {
        (claimed.abs(), exact.abs())
    } else {
        (claimed, exact)
    };
    answer.rel_error = RelError::new(claimed, exact).map(|r| RelError {
        at_counterexample: true,
        ..r
    });
    answer
        .notes
        .push(counterexample_note(&counterexample, &answer.name));
    answer.counterexample = Some(counterexample);
}

/// The note of a refuted claim, values in compact form.
fn counterexample_note(counterexample: &Counterexample, quantity: &str) -> String {
    let values: Vec<String> = counterexample
        .point
        .iter()
        .map(|(s, v)| format!("{s}={}", decimal::compact(v)))
        .collect();
    format!(
        "not an identity; counterexample {}: exact {quantity} = {}, claimed {}",
        if values.is_empty() {
            "(no free symbols)".to_string()
        } else {
            values.join(", ")
        },
        counterexample.exact.compact(),
        counterexample.claimed.compact()
    )
}
