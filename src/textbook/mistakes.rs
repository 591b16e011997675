//! The usual mistakes of a worked answer: when a printed answer disagrees, `check` solves the
//! scene again as each usual mistake would have it and says which one reproduces the printed
//! number (to its printed precision), if any: the moment of inertia about the rod's end instead
//! of its centre, the pivot's parallel-axis term forgotten, e = 0 for e = 1 or the reverse, the
//! rod's length for its half-length or the reverse, a measured from the end, grams read as
//! kilograms, a factor 2 or 1/2, and, in an oblique impact, stick for slide or the reverse. A
//! claim printed to fewer than three significant figures is not tried: too many wrong answers
//! round to it.

use super::claim::{ClaimedAnswer, ClaimedValue};
use super::exact::Exact;
use super::numeric::decide;
use super::sigfig::Precision;
use crate::field::Q;
use crate::impact::Mode;
use crate::scene::ObliqueParams;
use crate::scene::{Params, SceneInput, Support};
use crate::solve::Outcome;
use crate::solve::fast::oblique::{self, ObliqueOutcome};
use num_traits::{One, Signed, Zero};

/// A scene as a usual mistake has it: what the mistake is, in words, and its parameters.
struct Variant {
    mistake: String,
    params: Params<Q>,
}

/// The scenes of the usual mistakes on a scene of numbers (`input` as given, `p` its exact
/// parameters): each differs from `p` in one place.
fn variants(input: &SceneInput, p: &Params<Q>) -> Vec<Variant> {
    let mut out = Vec::new();
    let mut push = |mistake: String, change: &dyn Fn(&mut Params<Q>)| {
        let mut params = p.clone();
        change(&mut params);
        if params.inertia.is_positive() && params.half_length.is_positive() {
            out.push(Variant { mistake, params });
        }
    };
    let (big_m, l) = (p.rod_mass.clone(), p.half_length.clone());
    match &p.support {
        Support::Free => push(
            "the moment of inertia about the rod's end (I + M l^2) instead of its centre".into(),
            &|q| q.inertia = &q.inertia + &big_m * &l * &l,
        ),
        Support::Pivot(pivot) if !pivot.is_zero() => {
            let shift = &big_m * pivot * pivot;
            push(
                "the moment of inertia about the centre instead of the pivot (the parallel-axis term M p^2 forgotten)".into(),
                &|q| q.inertia = &q.inertia - &shift,
            );
        }
        Support::Pivot(_) => {}
    }
    let e = p.e.clone();
    if !e.is_zero() {
        push(
            format!("e = 0 (a sticking impact) instead of e = {e}"),
            &|q| q.e = Q::zero(),
        );
    }
    if !e.is_one() {
        push(
            format!("e = 1 (an elastic impact) instead of e = {e}"),
            &|q| q.e = Q::one(),
        );
    }
    // I scales as l^2 unless the rod's inertia was given outright (`--rod I=...`).
    let inertia_given = input
        .rod
        .as_deref()
        .is_some_and(|r| r.trim_start().starts_with("I="));
    let scale = |q: &mut Params<Q>, k: Q| {
        if !inertia_given {
            q.inertia = &q.inertia * &k * &k;
        }
        q.half_length = &q.half_length * &k;
    };
    push(
        "the rod's length 2l taken as its half-length l".into(),
        &|q| scale(q, Q::from_integer(2.into())),
    );
    push(
        "the rod's half-length l taken as its length 2l".into(),
        &|q| scale(q, Q::new(1.into(), 2.into())),
    );
    if matches!(p.support, Support::Free) && !p.a.is_zero() {
        push(
            "a measured from the rod's end instead of its centre".into(),
            &|q| q.a = (&q.half_length - q.a.abs()) * q.a.signum(),
        );
    }
    let in_grams = |text: &Option<String>| {
        text.as_deref()
            .is_some_and(|t| t.trim_end().ends_with('g') && !t.trim_end().ends_with("kg"))
    };
    let thousand = Q::from_integer(1000.into());
    if in_grams(&input.m) {
        push(
            "the projectile's mass in grams read as kilograms".into(),
            &|q| q.m = &q.m * &thousand,
        );
    }
    if in_grams(&input.rod_mass) {
        push("the rod's mass in grams read as kilograms".into(), &|q| {
            q.rod_mass = &q.rod_mass * &thousand;
            if !inertia_given {
                q.inertia = &q.inertia * &thousand;
            }
        });
    }
    out
}

/// The usual mistakes that reproduce `claim` (which disagrees with the exact answer `exact`)
/// on a scene of numbers: `value` computes the claimed quantity on a variant scene (`None`
/// when it does not apply there).
fn reproducing(
    claim: &ClaimedAnswer,
    exact: &Q,
    sig: Option<u32>,
    variants: Vec<(String, Option<Q>)>,
) -> Vec<String> {
    if !precise_enough(claim, sig) {
        return Vec::new();
    }
    let agrees = |x: &Q| decide(claim, &Exact::Rational(x.clone()), sig).agrees();
    let mut found: Vec<String> = variants
        .into_iter()
        .filter(|(_, value)| value.as_ref().is_some_and(|x| x != exact && agrees(x)))
        .map(|(mistake, _)| mistake)
        .collect();
    found.dedup();
    for (k, name) in [
        (Q::from_integer(2.into()), "2"),
        (Q::new(1.into(), 2.into()), "1/2"),
    ] {
        if !exact.is_zero() && agrees(&(exact * &k)) {
            found.push(format!("a factor {name} (the exact value times {name})"));
        }
    }
    found
}

/// The note `check` adds to a disagreeing claim on a paper's scene (no oblique flags) when a
/// usual mistake reproduces it; `None` when none does.
pub(super) fn motion_mistakes(
    input: &SceneInput,
    p: &Params<Q>,
    claim: &ClaimedAnswer,
    exact: &Q,
    sig: Option<u32>,
    solve: impl Fn(&Params<Q>) -> Outcome<Q>,
) -> Option<String> {
    let values = variants(input, p)
        .into_iter()
        .map(|v| {
            let value = claim
                .quantity
                .motion_value(&v.params, &solve(&v.params))
                .ok()
                .flatten();
            (v.mistake, value)
        })
        .collect();
    note(reproducing(claim, exact, sig, values))
}

/// As [`motion_mistakes`], for an oblique or frictional scene: also the contact taken the
/// other way (stick for slide, or slide for stick).
pub(super) fn oblique_mistakes(
    input: &SceneInput,
    p: &Params<Q>,
    o: &ObliqueParams<Q>,
    solved: &ObliqueOutcome<Q>,
    claim: &ClaimedAnswer,
    exact: &Q,
    sig: Option<u32>,
) -> Option<String> {
    let value = |p: &Params<Q>, given: Option<Mode>| {
        oblique::solve(p, o, given)
            .ok()
            .and_then(|out| claim.quantity.oblique_value(p, &out).ok().flatten())
    };
    let mut values: Vec<(String, Option<Q>)> = variants(input, p)
        .into_iter()
        .map(|v| (v.mistake, value(&v.params, None)))
        .collect();
    let others: Vec<(&str, Mode)> = match solved.contact {
        Some(Mode::Stick) => [true, false]
            .map(|forward| ("sliding taken for sticking", Mode::Slide { forward }))
            .to_vec(),
        Some(Mode::Slide { .. }) => vec![("sticking taken for sliding", Mode::Stick)],
        None | Some(Mode::Frictionless) => Vec::new(),
    };
    for (mistake, mode) in others {
        values.push((mistake.into(), value(p, Some(mode))));
    }
    note(reproducing(claim, exact, sig, values))
}

/// The fewest significant figures a printed claim needs before a mistake is named: with one
/// or two, too many wrong answers round to the same printed number to tell them apart.
const FIGURES_TO_NAME_A_MISTAKE: u32 = 3;

/// Whether `claim` is printed precisely enough (or exact) for a mistake to be named.
fn precise_enough(claim: &ClaimedAnswer, sig: Option<u32>) -> bool {
    match (&claim.value, sig) {
        (ClaimedValue::Formula(_), _) => true,
        (ClaimedValue::Printed(_), Some(figures)) => figures >= FIGURES_TO_NAME_A_MISTAKE,
        (ClaimedValue::Printed(m), None) => match m.printed.precision {
            Precision::Exact => true,
            Precision::Figures { figures, .. } => figures >= FIGURES_TO_NAME_A_MISTAKE,
            Precision::ZeroAt { .. } => false,
        },
    }
}

fn note(found: Vec<String>) -> Option<String> {
    (!found.is_empty()).then(|| {
        format!(
            "a usual mistake reproduces the claim: {}",
            found.join("; or ")
        )
    })
}
