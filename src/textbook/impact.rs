//! Published answers to planar impact problems, checked: the `[[claim]]` tables of a scene file
//! of `rodimpact impact`, each a printed value of one quantity under the law the source used,
//! decided against the exact answer the way `check` decides (a printed number by its own
//! significant figures, a fraction or a constant formula exactly; signs count).
//!
//! ```toml
//! [[claim]]
//! law = "newton"            # newton, poisson or energetic: the law the source used
//! quantity = "bar.omega"    # <body>.omega | <body>.velocity.x | <body>.velocity.y |
//!                           # impulse.x | impulse.y | impulse.normal | impulse.tangential |
//!                           # energy.before | energy.after | energy.change
//! value = "-16.714"         # as printed, in the scene's signs (counterclockwise, x, y)
//! ```

use super::SceneCheck;
use super::answer::CheckedAnswer;
use super::claim::{ClaimedValue, read_claimed};
use super::exact::Exact;
use super::numeric::decide_value;
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::field::{QSqrt, TrySqrt};
use crate::impact::{
    ContactMatrix, Law, LawAnswer, Model, ModelAnswer, ModelOutcome, solve_several,
};
use crate::model::System;
use crate::units::Dimension;
use num_traits::Zero;
use serde_json::Value;

/// The most claims a scene file may hold.
pub const MAX_IMPACT_CLAIMS: usize = 100;

/// One published value of a quantity of an impact.
#[derive(Debug, Clone)]
pub struct ImpactClaim {
    /// The law the source used.
    pub law: Law,
    /// With several contacts: how they act together, as the source took it.
    pub model: Option<Model>,
    /// What is claimed, as written (`bar.omega`).
    pub quantity: String,
    /// The value as printed.
    pub text: String,
    value: ClaimedValue,
    what: What,
}

#[derive(Debug, Clone, PartialEq)]
enum What {
    Omega(usize),
    Velocity(usize, bool),
    Impulse(Component),
    Energy(usize),
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Component {
    X,
    Y,
    Normal,
    Tangential,
}

/// The `claim` tables of a scene (its JSON form), read against `system`'s body names.
///
/// # Errors
/// A bad table, naming it: `claim[2].quantity: ...`.
///
/// # Examples
/// ```
/// use rodimpact::{model::from_value, field::q, scene::Scene};
/// use rodimpact::textbook::impact::read_impact_claims;
/// let system = Scene::builder(q(1, 1), q(1, 1)).build()?.system();
/// let claims = serde_json::json!({"claim": [{"law": "newton", "quantity": "rod.omega", "value": "-1.2"}]});
/// assert_eq!(read_impact_claims(&claims, &system)?.len(), 1);
/// let bad = serde_json::json!({"claim": [{"law": "newton", "quantity": "wheel.omega", "value": "1"}]});
/// assert_eq!(read_impact_claims(&bad, &system).unwrap_err().to_string(),
///            "claim[1].quantity: no body is named 'wheel'");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn read_impact_claims(scene: &Value, system: &System) -> Result<Vec<ImpactClaim>, Error> {
    let Some(list) = scene.get("claim") else {
        return Ok(Vec::new());
    };
    let Value::Array(list) = list else {
        return Err(invalid("claim", "expected [[claim]] tables"));
    };
    if list.len() > MAX_IMPACT_CLAIMS {
        return Err(Error::out_of_range(
            "claim",
            format!("more than {MAX_IMPACT_CLAIMS} claims (limit)"),
        ));
    }
    list.iter()
        .enumerate()
        .map(|(k, c)| {
            let field = format!("claim[{}]", k + 1);
            let text = |key: &str| -> Result<String, Error> {
                match c.get(key) {
                    Some(Value::String(s)) => Ok(s.clone()),
                    Some(_) => Err(invalid(&format!("{field}.{key}"), "expected a string")),
                    None => Err(Error::new(format!("{field}.{key}"), ErrorKind::Missing)),
                }
            };
            if let Value::Object(map) = c
                && let Some(unknown) = map
                    .keys()
                    .find(|k| !["law", "model", "quantity", "value"].contains(&k.as_str()))
            {
                return Err(invalid(
                    &format!("{field}.{}", crate::echo::echo(unknown)),
                    "unknown key (expected law, model, quantity, value)",
                ));
            }
            let model = match (c.get("model"), system.contacts.len()) {
                (Some(_), 1) => {
                    return Err(invalid(
                        &format!("{field}.model"),
                        "a model names how several contacts act together: this scene has one contact",
                    ));
                }
                (None, 1) => None,
                (None, _) => {
                    return Err(Error::new(format!("{field}.model"), ErrorKind::Missing));
                }
                (Some(Value::String(m)), n) => Some(
                    Model::parse(m, n).map_err(|why| invalid(&format!("{field}.model"), &why))?,
                ),
                (Some(_), _) => return Err(invalid(&format!("{field}.model"), "expected a string")),
            };
            let law = match text("law")?.as_str() {
                "newton" => Law::Newton,
                "poisson" => Law::Poisson,
                "energetic" => Law::Energetic,
                other => {
                    return Err(invalid(
                        &format!("{field}.law"),
                        &format!(
                            "expected newton, poisson or energetic, got '{}'",
                            crate::echo::echo(other)
                        ),
                    ));
                }
            };
            let quantity = text("quantity")?;
            let what = what(&quantity, system)
                .map_err(|why| invalid(&format!("{field}.quantity"), &why))?;
            let dimension = match what {
                What::Omega(_) => Dimension::AngularSpeed,
                What::Velocity(..) => Dimension::Speed,
                What::Impulse(_) => Dimension::Impulse,
                What::Energy(_) => Dimension::Energy,
            };
            let written = text("value")?;
            let value = read_claimed(&format!("{field}.value"), &written, dimension)?;
            Ok(ImpactClaim {
                law,
                model,
                quantity,
                text: written,
                value,
                what,
            })
        })
        .collect()
}

/// What `quantity` names.
fn what(quantity: &str, system: &System) -> Result<What, String> {
    let body = |name: &str| {
        system
            .bodies
            .iter()
            .position(|b| b.name == name)
            .ok_or_else(|| format!("no body is named '{}'", crate::echo::echo(name)))
    };
    Ok(match quantity.split('.').collect::<Vec<_>>().as_slice() {
        ["impulse", "x"] => What::Impulse(Component::X),
        ["impulse", "y"] => What::Impulse(Component::Y),
        ["impulse", "normal"] => What::Impulse(Component::Normal),
        ["impulse", "tangential"] => What::Impulse(Component::Tangential),
        ["energy", "before"] => What::Energy(0),
        ["energy", "after"] => What::Energy(1),
        ["energy", "change"] => What::Energy(2),
        [name, "omega"] => What::Omega(body(name)?),
        [name, "velocity", "x"] => What::Velocity(body(name)?, false),
        [name, "velocity", "y"] => What::Velocity(body(name)?, true),
        _ => {
            return Err(format!(
                "expected <body>.omega, <body>.velocity.x, <body>.velocity.y, impulse.x, impulse.y, impulse.normal, impulse.tangential or energy.before|after|change, got '{}'",
                crate::echo::echo(quantity)
            ));
        }
    })
}

/// Decides every claim against the answers (the answer of each claim's law among them).
///
/// # Errors
/// A claim about a fixed body's motion, or the impulse along a normal whose length is not
/// rational while lam is irrational.
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, QSqrt}, scene::Scene};
/// use rodimpact::impact::{solve_contact, Law};
/// use rodimpact::textbook::{AnswerAgreement, impact::{check_impact_claims, read_impact_claims}};
/// let system = Scene::builder(q(1, 1), q(1, 1)).build()?.system();
/// let answers = vec![solve_contact::<QSqrt>(&system, Law::Newton).expect("answered")];
/// let claims = read_impact_claims(&serde_json::json!({"claim": [
///     {"law": "newton", "quantity": "rod.omega", "value": "-1.2"},
///     {"law": "newton", "quantity": "projectile.velocity.x", "value": "3/5"}]}), &system)?;
/// let checked = check_impact_claims(&claims, &system, &answers)?;
/// assert!(checked.iter().all(|c| c.agreement == AnswerAgreement::Agrees));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn check_impact_claims(
    claims: &[ImpactClaim],
    system: &System,
    answers: &[LawAnswer<QSqrt>],
) -> Result<Vec<CheckedAnswer>, Error> {
    claims
        .iter()
        .map(|claim| {
            let answer = answers.iter().find(|a| a.law == claim.law).ok_or_else(|| {
                invalid(
                    &claim.quantity,
                    &format!("the claim is about {}'s law, not answered here", claim.law),
                )
            })?;
            let exact = value_of(&claim.what, system, answer)
                .map_err(|why| invalid(&claim.quantity, &why))?;
            let name = format!("{} ({})", claim.quantity, claim.law);
            Ok(decide_value(
                &name,
                &claim.text,
                &claim.value,
                &exact,
                false,
                None,
            ))
        })
        .collect()
}

/// Decides every claim of a scene with several contacts against its model's answer (the model
/// is solved here; a model with no single answer cannot confirm a claim).
///
/// # Errors
/// A claim about a fixed body, about `impulse.*` (several contacts have several impulses), or
/// a model without a single answer.
///
/// # Examples
/// ```
/// use rodimpact::{model::parse_toml, textbook::{AnswerAgreement, impact::{check_model_claims, read_impact_claims}}};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
/// let system = parse_toml("cradle-3", &text)?;
/// let claims = read_impact_claims(&serde_json::json!({"claim": [
///     {"law": "newton", "model": "simultaneous-newton", "quantity": "ball1.velocity.x", "value": "-1/3"}]}), &system)?;
/// assert_eq!(check_model_claims(&claims, &system)?[0].agreement, AnswerAgreement::Agrees);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn check_model_claims(
    claims: &[ImpactClaim],
    system: &System,
) -> Result<Vec<CheckedAnswer>, Error> {
    claims
        .iter()
        .map(|claim| {
            let model = claim.model.clone().ok_or_else(|| {
                Error::new(format!("{} (model)", claim.quantity), ErrorKind::Missing)
            })?;
            let answer: ModelAnswer<Q> = match solve_several::<Q>(system, &model) {
                ModelOutcome::Answered(mut answers) if answers.len() == 1 => answers.remove(0),
                _ => {
                    return Err(invalid(
                        &claim.quantity,
                        &format!("{model} has no single answer here, so it cannot confirm a claim"),
                    ));
                }
            };
            let body = |index: usize| {
                answer
                    .bodies
                    .iter()
                    .find(|(i, _, _)| *i == index)
                    .ok_or_else(|| format!("'{}' is fixed: it does not move", system.bodies[index].name))
            };
            let value: Result<Q, String> = match &claim.what {
                What::Omega(i) => body(*i).map(|b| b.2.clone()),
                What::Velocity(i, false) => body(*i).map(|b| b.1.x.clone()),
                What::Velocity(i, true) => body(*i).map(|b| b.1.y.clone()),
                What::Energy(0) => Ok(answer.ledger.energy.before.clone()),
                What::Energy(1) => Ok(answer.ledger.energy.after.clone()),
                What::Energy(_) => Ok(answer.ledger.energy.change.clone()),
                What::Impulse(_) => Err("several contacts have several impulses: claim the bodies' motion or the energy".into()),
            };
            let exact = Exact::Rational(value.map_err(|why| invalid(&claim.quantity, &why))?);
            let name = format!("{} ({model})", claim.quantity);
            Ok(decide_value(&name, &claim.text, &claim.value, &exact, false, None))
        })
        .collect()
}

/// The exact value the claim is about.
fn value_of(what: &What, system: &System, answer: &LawAnswer<QSqrt>) -> Result<Exact, String> {
    let body = |index: usize| {
        answer
            .bodies
            .iter()
            .find(|b| b.index == index)
            .ok_or_else(|| format!("'{}' is fixed: it does not move", system.bodies[index].name))
    };
    let value = match what {
        What::Omega(i) => body(*i)?.omega.clone(),
        What::Velocity(i, false) => body(*i)?.velocity.x.clone(),
        What::Velocity(i, true) => body(*i)?.velocity.y.clone(),
        What::Impulse(Component::X) => answer.impulse.x.clone(),
        What::Impulse(Component::Y) => answer.impulse.y.clone(),
        What::Impulse(component) => {
            let n = &system.contacts[0].normal;
            let length = QSqrt::rational(n.dot(n))
                .try_sqrt()
                .or_else(|| {
                    (answer.lam.y().is_zero() && answer.tau.y().is_zero())
                        .then(|| QSqrt::sqrt_of(&n.dot(n)))
                })
                .ok_or("the normal's length is irrational and so is the impulse: claim impulse.x or impulse.y")?;
            let coefficient = if *component == Component::Normal {
                &answer.lam
            } else {
                &answer.tau
            };
            coefficient.clone() * &length
        }
        What::Energy(0) => answer.energy.before.clone(),
        What::Energy(1) => answer.energy.after.clone(),
        What::Energy(_) => answer.energy.change.clone(),
    };
    Ok(if value.y().is_zero() {
        Exact::Rational(value.x().clone())
    } else {
        Exact::Surd(value)
    })
}

fn invalid(field: &str, why: &str) -> Error {
    Error::new(field, ErrorKind::Invalid(why.into()))
}
/// The answers of one scene: per law for one contact, per model for several.
#[derive(Debug, Clone)]
pub enum ImpactAnswers {
    /// One contact: its answer under each law asked for that gives one, then the laws (or
    /// the engine) that give none, each with why.
    Laws(Vec<LawAnswer<QSqrt>>, Vec<NotAnswered>),
    /// Several contacts: the outcome of each model asked for.
    Models(Vec<(Model, ModelOutcome<Q>)>),
}

/// A law (or an engine) that gives a one-contact scene no answer, beside the laws that do: the
/// impact never ends under it, its steps do not stop, or its exact work passed its limit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotAnswered {
    /// The law's or the engine's name (`newton`, `pymunk-7`).
    pub name: String,
    /// Why, as a sentence (`a contact still approaches after 60 of pymunk-7's steps ...`).
    pub why: String,
}

/// A scene answered: the system, its answers, and the file's claims checked (none when the
/// file has no `[[claim]]`).
#[derive(Debug, Clone)]
pub struct ImpactRun {
    /// The bodies, contacts and pins.
    pub system: System,
    /// The contact matrix W of the first contact and the relative velocity (u_n, u_t) there
    /// before the impact (the scene's description prints them).
    pub contact: (ContactMatrix<Q>, [Q; 2]),
    /// The answers.
    pub answers: ImpactAnswers,
    /// The file's published answers, checked.
    pub checked: SceneCheck,
}

impl ImpactRun {
    /// Whether the file's claims all agree (true without claims): the command's exit 0.
    pub fn all_agree(&self) -> bool {
        self.checked.all_agree()
    }

    /// Whether the file holds published answers.
    pub fn has_claims(&self) -> bool {
        !self.checked.answers.is_empty()
    }
}
