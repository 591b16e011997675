//! Checking claimed answers about one scene: the orchestration. A scene of numbers is solved
//! over Q and each claim decided numerically ([`super::numeric`]); a formula in a scene flag or
//! a claim makes the whole check symbolic: the scene is built in its free symbols
//! ([`super::symbolic`]) and each claim decided as an identity, or numerically when both sides
//! are constants.

use super::answer::CheckedAnswer;
use super::answer::{AnswerAgreement, SceneCheck, SceneSummary};
use super::claim::{ClaimedAnswer, ClaimedValue};
use super::exact::Exact;
use super::expr::{Budget, Radical};
use super::formula::{OnRod, free_symbols, on_rod};
use super::mistakes;
use super::numeric::decide;
use super::quantity::Quantity;
use super::sigfig;
use super::symbolic::{
    ContactEndings, Ending, GivenScene, SymbolicScene, contact_endings, heaviest_field, identity,
    oblique_params,
};
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt, RatFn};
use crate::scene::{ObliqueParams, Params, SceneInput, Support};
use crate::solve::Outcome;
use crate::solve::fast::linear::solve;
use crate::solve::fast::oblique::{self, normal_params};
use crate::solve::optimum::{a_star_squared, optimum};
use num_traits::{One, Signed, Zero};

/// Checks the claims `specs` (each `NAME=VALUE` as typed: `omega=1.2`, `v=3/5`,
/// `omega=6*m*v0*a/(...)`) about one scene: what `rodimpact check` does with scene flags and
/// `--claim`, the work of every formula charged to one run's budget.
///
/// # Errors
/// No claim, more than [`MAX_CLAIMS`](super::problems::MAX_CLAIMS), a claim that does not
/// parse, and those of [`check_scene_within`].
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::check_claims};
/// let s = SceneInput { m: Some("1".into()), rod_mass: Some("1".into()), ..Default::default() };
/// assert!(check_claims(&s, &["omega=6/5", "v=0.6"], None)?.all_agree());
/// assert!(!check_claims(&s, &["omega=1.3"], None)?.all_agree());
/// let none: [&str; 0] = [];
/// assert!(check_claims(&s, &none, None).unwrap_err().to_string().starts_with("claim: nothing to check"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn check_claims(
    input: &SceneInput,
    specs: &[impl AsRef<str>],
    sig: Option<u32>,
) -> Result<SceneCheck, Error> {
    use super::problems::MAX_CLAIMS;
    if specs.is_empty() {
        return Err(Error::new(
            "claim",
            ErrorKind::Invalid(
                "nothing to check: give --claim NAME=VALUE (with the scene's flags), or a problems .toml file (rodimpact check examples/textbook.toml)".into(),
            ),
        ));
    }
    if specs.len() > MAX_CLAIMS {
        return Err(Error::out_of_range(
            "claim",
            format!("more than {MAX_CLAIMS} claims (limit)"),
        ));
    }
    let mut budget = Budget::run();
    let claims = specs
        .iter()
        .map(|c| ClaimedAnswer::parse_within(c.as_ref(), &mut budget))
        .collect::<Result<Vec<_>, _>>()?;
    check_scene_within(input, &claims, sig, &mut budget)
}

/// Checks claims about one scene given as typed (numbers may carry units; any formula in a
/// scene flag or a claim makes the whole check symbolic). `sig` overrides the claims'
/// significant figures.
///
/// # Errors
/// Bad scene or claim input, naming the field.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{check_scene, ClaimedAnswer}};
/// let s = SceneInput { m: Some("1".into()), rod_mass: Some("1".into()), ..Default::default() };
/// let r = check_scene(&s, &[ClaimedAnswer::parse("omega=6/5").unwrap()], None).unwrap();
/// assert!(r.all_agree() && r.symbolic.is_none());
/// ```
pub fn check_scene(
    input: &SceneInput,
    claims: &[ClaimedAnswer],
    sig: Option<u32>,
) -> Result<SceneCheck, Error> {
    check_scene_within(input, claims, sig, &mut Budget::run())
}

/// [`check_scene`], charging the work of the scene's and the claims' formulas to a run's
/// `budget` (shared by every scene of a problem file).
///
/// # Errors
/// Those of [`check_scene`], and an exhausted budget.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{check_scene_within, expr::Budget, ClaimedAnswer}};
/// let s = SceneInput { rod_mass: Some("4*m".into()), a: Some("l".into()), ..Default::default() };
/// let mut budget = Budget::run();
/// let r = check_scene_within(&s, &[ClaimedAnswer::parse("v=0").unwrap()], None, &mut budget).unwrap();
/// assert!(r.all_agree()); // M = 4m hit at the end, elastic: the projectile stops
/// ```
pub fn check_scene_within(
    input: &SceneInput,
    claims: &[ClaimedAnswer],
    sig: Option<u32>,
    budget: &mut Budget,
) -> Result<SceneCheck, Error> {
    if let Some(n) = sig {
        sigfig::check_sig(n)?;
    }
    if let Some(side) = input.a.as_deref().and_then(optimum_side) {
        return check_at_optimum(input, claims, sig, side);
    }
    let given = GivenScene::read(input, budget)?;
    if given.has_formula() || claims.iter().any(ClaimedAnswer::is_symbolic) {
        let heaviest = heaviest_field(input).unwrap_or("scene");
        budget.metered(heaviest, |budget| {
            check_symbolic(&given, input, claims, sig, budget)
        })
    } else {
        check_numeric(input, claims, sig)
    }
}

/// Checks claims about a scene of numbers: solved over Q (a* and omega_max in Q(sqrt d)), each
/// claim decided numerically.
///
/// # Errors
/// Bad scene input; a scene that is not all numbers (a missing mass); `pivot_impulse` of a
/// free rod.
fn check_numeric(
    input: &SceneInput,
    claims: &[ClaimedAnswer],
    sig: Option<u32>,
) -> Result<SceneCheck, Error> {
    let scene = input.build().map_err(|e| numeric_scene_needed(e, claims))?;
    let params = scene.params::<Q>();
    let out = solved(&params);
    let oblique = scene.oblique().map(|o| {
        oblique::solve(&params, &o.params(), None)
            .expect("Q decides stick or slide, and the equations of a valid scene are nonsingular")
    });
    let mut answers = Vec::with_capacity(claims.len());
    for claim in claims {
        let value = match &oblique {
            None => claim.quantity.motion_value(&params, &out)?,
            Some(o) => claim.quantity.oblique_value(&params, o)?,
        };
        if let Some(x) = &value {
            // A quantity of the impact: exact in Q, and a disagreement tried against the
            // usual mistakes.
            let mut answer = decide(claim, &Exact::Rational(x.clone()), sig);
            if !answer.agrees() {
                let mistake = match (&oblique, scene.oblique()) {
                    (Some(solved_oblique), Some(given)) => mistakes::oblique_mistakes(
                        input,
                        &params,
                        &given.params(),
                        solved_oblique,
                        claim,
                        x,
                        sig,
                    ),
                    _ => mistakes::motion_mistakes(input, &params, claim, x, sig, solved),
                };
                answer.notes.extend(mistake);
            }
            answers.push(answer);
            continue;
        }
        // a* and omega_max: the optimum, in Q(sqrt d).
        let Some(opt) = optimum(&scene) else {
            return Err(Error::new(
                format!("claim {}", claim.quantity.name()),
                ErrorKind::Invalid(
                    "the rod turns before the impact, so the approach speed depends on a: the paper's optimum does not apply".into(),
                ),
            ));
        };
        let exact = if claim.quantity == Quantity::AStar {
            Exact::Surd(QSqrt::sqrt_of(&opt.squared))
        } else {
            Exact::Surd(opt.omega_max.clone())
        };
        answers.push(decide(claim, &exact, sig));
    }
    Ok(SceneCheck {
        symbolic: None,
        answers,
    })
}

/// The side of `a*` a claim's `--a` names: `a*` or `+a*` (1), `-a*` (-1); `None` for
/// anything else.
fn optimum_side(a: &str) -> Option<i64> {
    match a.replace(' ', "").as_str() {
        "a*" | "+a*" => Some(1),
        "-a*" => Some(-1),
        _ => None,
    }
}

/// Checks claims about a scene of numbers struck exactly at its optimum `a*` on `side` (from
/// the centre, or from the pivot on a pivoted rod), solved in Q(sqrt d): there omega is
/// omega_max and, on a free rod, the projectile and the rod's centre leave together (X19).
///
/// # Errors
/// The scene's own errors; an oblique scene (its optimum is the normal problem's); `a*`
/// beyond the rod's end (then the end is the best point, and has a number).
fn check_at_optimum(
    input: &SceneInput,
    claims: &[ClaimedAnswer],
    sig: Option<u32>,
    side: i64,
) -> Result<SceneCheck, Error> {
    let at_end = SceneInput {
        a: None,
        ..input.clone()
    };
    let scene = at_end
        .build()
        .map_err(|e| numeric_scene_needed(e, claims))?;
    if let Some(field) = input.first_oblique() {
        return Err(Error::new(
            field,
            ErrorKind::Invalid(
                "--a a* strikes the paper's scene at its optimum; an oblique or frictional scene takes a number for a".into(),
            ),
        ));
    }
    let p = scene.params::<Q>();
    let opt = optimum(&scene).expect("a rod at rest before the impact has an optimum");
    let squared = opt.squared.clone();
    let pivot = match &p.support {
        Support::Free => Q::zero(),
        Support::Pivot(at) => at.clone(),
    };
    // The rod's end on that side, as a distance from the centre or the pivot.
    let room = if side > 0 {
        p.half_length.clone() - &pivot
    } else {
        p.half_length.clone() + &pivot
    };
    if !room.is_positive() || squared > room.clone() * &room {
        let end = p.half_length.clone() * Q::from_integer(side.into());
        return Err(Error::out_of_range(
            "a",
            format!(
                "a* = sqrt({squared}) from the {} lies beyond the rod's end on that side: the end is the best point there (--a {end})",
                if pivot.is_zero() { "centre" } else { "pivot" }
            ),
        ));
    }
    let arm = QSqrt::sqrt_of(&squared) * &QSqrt::rational(Q::from_integer(side.into()));
    let mut lifted = scene.params::<QSqrt>();
    lifted.a = arm + &QSqrt::rational(pivot);
    let out = solved(&lifted);
    let answers = claims
        .iter()
        .map(|claim| {
            let exact = match claim.quantity.motion_value(&lifted, &out)? {
                Some(x) => Exact::Surd(x),
                None if claim.quantity == Quantity::AStar => {
                    Exact::Surd(QSqrt::sqrt_of(&opt.squared))
                }
                None => Exact::Surd(opt.omega_max.clone()),
            };
            Ok(decide(claim, &exact, sig))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(SceneCheck {
        symbolic: None,
        answers,
    })
}

/// A missing mass in a scene of numbers only: numeric claims need a numeric scene.
fn numeric_scene_needed(e: Error, claims: &[ClaimedAnswer]) -> Error {
    if e.kind != ErrorKind::Missing {
        return e;
    }
    let example = claims
        .first()
        .map(|c| format!(" ({}={})", c.quantity.name(), c.text))
        .unwrap_or_default();
    Error::new(
        e.field,
        ErrorKind::Invalid(format!(
            "not given; a numeric claim{example} needs a numeric scene: give m and M as numbers (--m, --M), or claim a formula in the scene's symbols"
        )),
    )
}

/// The exact answer a claim is compared with, as `coeff * sqrt(radicand)`.
fn exact_value(
    quantity: Quantity,
    field: &str,
    scene: &SymbolicScene,
    out: &Outcome<RatFn>,
) -> Result<Radical, Error> {
    if let Some(x) = quantity.motion_value(&scene.params, out)? {
        return Ok(Radical::rational(x));
    }
    match quantity {
        Quantity::AStar => Ok(Radical::normalized(
            RatFn::one(),
            a_star_squared(&scene.params),
        )),
        _ => omega_max_value(field, &scene.params),
    }
}

/// omega_max of a symbolic free rod where the symbols decide which side of the end a* lies:
/// (1 + e) v0/(2 a*) = (1 + e) v0 sqrt(A)/(2 A) (A = a*^2) when a* lies on the rod for every
/// value of the symbols, omega(l) when it never does.
///
/// # Errors
/// A pivoted rod, or a* on the rod for some values of the symbols only (then two formulas).
fn omega_max_value(field: &str, p: &Params<RatFn>) -> Result<Radical, Error> {
    let refuse = |why: String| Err(Error::new(field, ErrorKind::Invalid(why)));
    if p.support != Support::Free {
        return refuse("omega_max on a pivoted rod is checked for numeric scenes only: claim omega with --a a* instead".into());
    }
    let squared = a_star_squared(p);
    match on_rod(&squared, &p.half_length) {
        OnRod::Always => {
            let coeff = (RatFn::one() + &p.e) * &p.v0 / &(RatFn::from_i64(2) * &squared);
            Ok(Radical::normalized(coeff, squared))
        }
        OnRod::Never => {
            let at_end = Params {
                a: p.half_length.clone(),
                ..p.clone()
            };
            Ok(Radical::rational(solved(&at_end).after.omega))
        }
        OnRod::When(c) => refuse(format!(
            "omega_max is omega(a*) when {c} and omega(l) otherwise, two formulas: fix the case in the scene (--M 2*m, ...) or claim a_star or omega"
        )),
    }
}

/// The domain condition of a symbolic a* on a free rod ([`on_rod`]): a* (the stationary point of
/// omega(a)) is where omega is largest on the rod only when a*^2 <= l^2. `None` for a pivoted
/// rod or when a* is on the rod for every value of the symbols and that is all there is to say.
fn a_star_on_rod(p: &Params<RatFn>) -> Option<String> {
    if p.support != Support::Free {
        return None;
    }
    Some(match on_rod(&a_star_squared(p), &p.half_length) {
        OnRod::Never => {
            "a* lies beyond the end for every value of the symbols: omega is largest at a = l"
                .into()
        }
        OnRod::Always => {
            "a* lies on the rod for every value of the symbols, and omega is largest there".into()
        }
        OnRod::When(c) => format!(
            "a* lies on the rod (omega is largest there) when {c}; otherwise omega is largest at a = l"
        ),
    })
}

/// Checks claims about a symbolic scene; every formula's work is charged to `budget`.
///
/// # Errors
/// Bad input; `omega_max` where the symbols leave a* on either side of the end (two
/// formulas), or on a pivot; rpm against a formula; an exhausted budget.
fn check_symbolic(
    given: &GivenScene,
    input: &SceneInput,
    claims: &[ClaimedAnswer],
    sig: Option<u32>,
    budget: &mut Budget,
) -> Result<SceneCheck, Error> {
    let scene = SymbolicScene::build(given)?;
    let oblique = oblique_params(&scene, input, budget)?;
    let endings = oblique.as_ref().map(|o| contact_endings(&scene, o));
    let out = solved(&scene.params);
    let mut answers = Vec::with_capacity(claims.len());
    for claim in claims {
        let field = format!("claim {}", claim.quantity.name());
        let answer = match (&oblique, &endings) {
            (Some(o), Some(endings)) => {
                check_oblique_claim(claim, o, endings, &scene, sig, budget, &field)?
            }
            _ => {
                let exact = exact_value(claim.quantity, &field, &scene, &out)?;
                check_symbolic_claim(claim, &exact, false, &scene, sig, budget, &field)?
            }
        };
        answers.push(answer);
    }
    // An oblique scene's own symbols are free too; an open slip's sign is a default taken.
    let free = match &oblique {
        Some(o) => free_symbols(&scene, o),
        None => scene.free.iter().map(|s| s.name().to_string()).collect(),
    };
    let mut defaults = scene.defaults.clone();
    defaults.extend(endings.and_then(|e| e.slip_taken));
    Ok(SceneCheck {
        symbolic: Some(SceneSummary { free, defaults }),
        answers,
    })
}

/// One claim against one exact value of a symbolic scene: a number against a number, or an
/// identity in the free symbols.
fn check_symbolic_claim(
    claim: &ClaimedAnswer,
    exact: &Radical,
    oblique: bool,
    scene: &SymbolicScene,
    sig: Option<u32>,
    budget: &mut Budget,
    field: &str,
) -> Result<CheckedAnswer, Error> {
    let claimed = match &claim.value {
        ClaimedValue::Printed(m) => {
            if let Some((c, r)) = exact.constant() {
                return Ok(decide(claim, &Exact::radical(c, r), sig));
            }
            let si = m.si().ok_or_else(|| {
                Error::new(
                    field,
                    ErrorKind::Invalid(
                        "a value in rpm cannot be compared with a formula: give it in rad/s".into(),
                    ),
                )
            })?;
            Radical::rational(RatFn::from_rational(&si))
        }
        ClaimedValue::Formula(r) => {
            // An oblique scene's claims may use its symbols (v0t, mu, ...), which stay themselves.
            let resolved = if oblique {
                scene.substitute(field, r, budget)?
            } else {
                scene.resolve(field, r, budget)?
            };
            if let (Some(_), Some((c, r))) = (resolved.constant(), exact.constant()) {
                let numeric = ClaimedAnswer {
                    value: ClaimedValue::Formula(resolved),
                    ..claim.clone()
                };
                return Ok(decide(&numeric, &Exact::radical(c, r), sig));
            }
            resolved
        }
    };
    let mut answer = identity(claim, &claimed, exact, scene, budget, field)?;
    if claim.quantity == Quantity::AStar
        && let Some(condition) = a_star_on_rod(&scene.params)
    {
        answer.notes.push(condition);
    }
    // In check, a quantity not given is a free symbol, not solve's default: an end-hit
    // formula refuted only because a is free says so.
    let a_free = scene.free.iter().any(|s| s.name() == "a");
    let uses_a =
        matches!(&claim.value, ClaimedValue::Formula(r) if r.mentions(crate::field::Sym::new("a")));
    let depends_on_a = !matches!(claim.quantity, Quantity::AStar | Quantity::OmegaMax);
    if answer.agreement == AnswerAgreement::Disagrees && a_free && !uses_a && depends_on_a {
        answer.notes.push(
            "a is a free symbol here (not the end, solve's default): add --a l for a hit at the end".into(),
        );
    }
    if matches!(claim.value, ClaimedValue::Printed(_)) {
        answer.notes.insert(
            0,
            "a number against a formula: decided as an identity in the free symbols".into(),
        );
    }
    Ok(answer)
}

/// A claim about a symbolic oblique or frictional scene (NEWCOMER M6): against the answer of
/// the way the contact ends when the symbols decide it, or against both (it sticks when
/// mu >= mu*, slides otherwise): the claim agrees when it is one of them, and says which.
fn check_oblique_claim(
    claim: &ClaimedAnswer,
    o: &ObliqueParams<RatFn>,
    endings: &ContactEndings,
    scene: &SymbolicScene,
    sig: Option<u32>,
    budget: &mut Budget,
    field: &str,
) -> Result<CheckedAnswer, Error> {
    let p = &scene.params;
    let exact_of = |ending: &Ending| -> Result<Radical, Error> {
        if let Some(x) = claim.quantity.oblique_value(p, &ending.outcome)? {
            return Ok(Radical::rational(x));
        }
        // a* and omega_max: the paper's, for the normal problem (the slide along the rod and
        // friction never change them, X27-X31).
        let normal = normal_params(p, o);
        match claim.quantity {
            Quantity::AStar => Ok(Radical::normalized(RatFn::one(), a_star_squared(&normal))),
            _ => omega_max_value(field, &normal),
        }
    };
    let friction = !o.mu.is_zero();
    let mu_star = endings
        .mu_star
        .as_ref()
        .map(|m| format!(", mu_star = {m}"))
        .unwrap_or_default();
    let exacts = endings
        .endings
        .iter()
        .map(|e| exact_of(e).map(|x| (e, x)))
        .collect::<Result<Vec<_>, _>>()?;
    // A quantity the contact's ending does not change (v, V, omega, J): one check.
    if exacts.len() > 1 && exacts.iter().all(|(_, x)| x == &exacts[0].1) {
        let mut answer =
            check_symbolic_claim(claim, &exacts[0].1, true, scene, sig, budget, field)?;
        answer.notes.push(format!(
            "the same however the contact ends (it sticks when mu >= mu_star{mu_star})"
        ));
        return Ok(answer);
    }
    let mut tried = Vec::new();
    for (ending, exact) in exacts {
        let mut answer = check_symbolic_claim(claim, &exact, true, scene, sig, budget, field)?;
        match &ending.condition {
            None if friction => answer.notes.push(format!(
                "the contact {}s for every value of the symbols{mu_star}",
                ending.contact
            )),
            None => {}
            Some(condition) => answer.notes.push(format!(
                "the answer when the contact {}s ({condition}{mu_star})",
                ending.contact
            )),
        }
        if answer.agreement == AnswerAgreement::Agrees || endings.endings.len() == 1 {
            return Ok(answer);
        }
        tried.push((ending, exact, answer));
    }
    // Neither way: the claim against the first, naming the other's formula too.
    let mut iter = tried.into_iter();
    let (_, _, mut answer) = iter.next().expect("two endings were tried");
    for (ending, exact, _) in iter {
        answer.notes.push(format!(
            "nor the answer when it {}s: {}",
            ending.contact, exact
        ));
    }
    Ok(answer)
}

/// The impulse equations of a valid scene, solved.
///
/// Their determinant (`-(m I + M I + M m a^2)` for a free rod) is nonzero wherever the scene's
/// constraints hold (m, M, I > 0, the impact and the pivot on the rod). A numeric scene was
/// validated when it was built; a symbolic one holds at a sample point of its free symbols
/// ([`SymbolicScene::build`] refuses it otherwise), so its determinant is not identically zero.
/// A singular system is therefore a bug in this crate, never bad input, and it is not reported
/// as bad input (exit 2): it stops the program as the broken invariant it is.
fn solved<F: Field>(params: &Params<F>) -> Outcome<F> {
    solve(params).expect("the impulse equations of a valid scene are nonsingular")
}
