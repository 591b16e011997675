//! One planar impact scene answered as `rodimpact impact` answers it: one contact under the
//! restitution laws asked for, several contacts under the models asked for, and the file's
//! published answers (`[[claim]]`) checked. The command line and the Python package both call
//! [`answer_impact`]; [`crate::report::impact_run_json`] and [`crate::report::impact_run_text`]
//! render the [`ImpactRun`] it returns.

use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::impact::{
    Law, MAX_ORDERED, Model, ModelOutcome, Profile, Stopped, contact_matrix, orders,
    solve_engine_exact, solve_exact, solve_several_sharing,
};
use crate::model::{MAX_SCENE_BYTES, from_value, toml_value};
use crate::textbook::SceneCheck;
use crate::textbook::impact::{
    ImpactAnswers, ImpactRun, NotAnswered, check_impact_claims, check_model_claims,
    read_impact_claims,
};
use serde_json::Value;

/// The scene file at `path` (named `label` in errors) as the JSON value of its TOML, read no
/// further than [`MAX_SCENE_BYTES`].
///
/// # Errors
/// `LABEL: cannot read: ...`, `LABEL: not UTF-8 text`, or the TOML's error with its line.
///
/// # Examples
/// ```
/// use rodimpact::app::impact::read_scene_file;
/// let value = read_scene_file("paper.toml", "examples/impacts/paper-as-bodies.toml".as_ref())?;
/// assert!(value["body"].is_array());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn read_scene_file(label: &str, path: &std::path::Path) -> Result<Value, Error> {
    use std::io::Read;
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::io(label, "cannot read", e))?;
    let text = String::from_utf8(bytes)
        .map_err(|_| Error::new(label, ErrorKind::Invalid("not UTF-8 text".into())))?;
    toml_value(label, &text)
}

/// Answers the scene `value` (a scene file's structure; `label` names it in errors): with one
/// contact under `law` (`None`: the three physical laws; every one of them, and `law`, when the
/// file has claims, whose sources each name theirs), with several under the models `model`
/// names (`None`: all); and as `engine`'s solver computes it, after the laws or models.
///
/// # Errors
/// A bad scene (`LABEL: field: why`), no approach at the contact, `model` with one contact,
/// `law` with several, a bad model name, too many contacts for the models.
///
/// # Examples
/// ```
/// use rodimpact::app::impact::{answer_impact, read_scene_file};
/// use rodimpact::textbook::impact::ImpactAnswers;
/// use rodimpact::impact::Law;
/// let value = read_scene_file("paper.toml", "examples/impacts/paper-as-bodies.toml".as_ref())?;
/// let run = answer_impact(&value, "paper.toml", Some(Law::Newton), None, None)?;
/// assert!(matches!(&run.answers, ImpactAnswers::Laws(a, _) if a.len() == 1));
/// let err = answer_impact(&value, "paper.toml", None, Some("pgs:3"), None).unwrap_err();
/// assert!(err.to_string().starts_with("model: one contact"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn answer_impact(
    value: &Value,
    label: &str,
    law: Option<Law>,
    model: Option<&str>,
    engine: Option<&Profile>,
) -> Result<ImpactRun, Error> {
    let at_file = |e: Error| Error::new(format!("{label}: {}", e.field), e.kind);
    let system = from_value(value).map_err(at_file)?;
    let claims = read_impact_claims(value, &system).map_err(at_file)?;
    if system.contacts.len() > 1 {
        // An engine's law is a law of any number of contacts; the physical laws of one
        // contact are not, the models say how the contacts act together.
        let mut models = match (law, model) {
            (None, model) => parse_models(model.unwrap_or("all"), system.contacts.len())?,
            (Some(law), None) if Model::of_law(law).is_some() => {
                vec![Model::of_law(law).expect("an engine's law")]
            }
            (Some(_), Some(_)) => {
                return Err(Error::new(
                    "law",
                    ErrorKind::Conflict(
                        "several contacts: give the law or the model (--model), not both".into(),
                    ),
                ));
            }
            (Some(_), None) => {
                return Err(Error::new(
                    "law",
                    ErrorKind::Conflict(
                        "several contacts: their models (--model) say how the contacts act \
                         together (of the laws, only the engines' lcp-newton, lcp-poisson and \
                         split apply)"
                            .into(),
                    ),
                ));
            }
        };
        models.extend(engine.cloned().map(Model::Engine));
        let outcomes: Vec<(Model, ModelOutcome<Q>)> = models
            .iter()
            .map(|m| {
                let outcome = solve_several_sharing::<Q>(&system, m, m.share_among(&models));
                (m.clone(), outcome)
            })
            .collect();
        refuse_when_nothing_answered(&outcomes)?;
        let checked = SceneCheck {
            symbolic: None,
            answers: check_model_claims(&claims, &system).map_err(at_file)?,
        };
        return Ok(ImpactRun {
            contact: contact_matrix::<Q>(&system),
            system,
            answers: ImpactAnswers::Models(outcomes),
            checked,
        });
    }
    if model.is_some() {
        return Err(Error::new(
            "model",
            ErrorKind::Conflict(
                "one contact: the models of several contacts do not apply (the laws do: --law)"
                    .into(),
            ),
        ));
    }
    // A file's published answers need their laws answered whatever `law` says.
    let laws: Vec<Law> = match law {
        Some(law) if claims.is_empty() => vec![law],
        Some(law) if !Law::ALL.contains(&law) => Law::ALL.into_iter().chain([law]).collect(),
        _ => Law::ALL.to_vec(),
    };
    // A law or the engine without an answer (the impact never ends under it, its steps do not
    // stop, its work passed the limit) is said beside the others; the first one's error when
    // nothing answered.
    let mut answers = Vec::new();
    let mut failed = Vec::new();
    let solved = laws
        .iter()
        .map(|&law| (law.to_string(), solve_exact(&system, law)))
        .chain(engine.map(|p| (p.to_string(), solve_engine_exact(&system, p))));
    for (name, solved) in solved {
        match solved {
            Ok(answer) => answers.push(answer),
            Err(error) => failed.push((name, error)),
        }
    }
    if answers.is_empty() {
        let (_, error) = failed.swap_remove(0);
        return Err(Error::new(label, ErrorKind::Invalid(error.to_string())));
    }
    let unanswered = failed
        .into_iter()
        .map(|(name, error)| NotAnswered {
            why: error.why(),
            name,
        })
        .collect();
    let checked = SceneCheck {
        symbolic: None,
        answers: check_impact_claims(&claims, &system, &answers).map_err(at_file)?,
    };
    Ok(ImpactRun {
        contact: contact_matrix::<Q>(&system),
        system,
        answers: ImpactAnswers::Laws(answers, unanswered),
        checked,
    })
}

/// The law `text` names (`newton`, `poisson`, `energetic` or `stronge`, `lcp-newton`,
/// `lcp-poisson`, `split`), or `None` for `all` (the three physical laws).
///
/// # Errors
/// `law: expected ...` for any other text.
///
/// # Examples
/// ```
/// use rodimpact::{app::impact::parse_law, impact::Law};
/// assert_eq!(parse_law("stronge")?, Some(Law::Energetic));
/// assert_eq!(parse_law("all")?, None);
/// assert!(parse_law("euler").unwrap_err().to_string().starts_with("law: expected"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn parse_law(text: &str) -> Result<Option<Law>, Error> {
    if text.trim() == "all" {
        return Ok(None);
    }
    Law::parse(text).map(Some).ok_or_else(|| {
        Error::new(
            "law",
            ErrorKind::Invalid(format!(
                "expected newton, poisson, energetic (stronge), lcp-newton, lcp-poisson, split or all, got '{}'",
                crate::echo::echo(text)
            )),
        )
    })
}

/// The engine profile `text` names ([`Profile::parse`]: `pymunk-7`, `box2d-2.3:scale=16`, ...).
///
/// # Errors
/// `engine: ...` naming what is wrong.
///
/// # Examples
/// ```
/// use rodimpact::app::impact::parse_engine;
/// assert_eq!(parse_engine("bullet-3")?.to_string(), "bullet-3");
/// assert!(parse_engine("havok").unwrap_err().to_string().starts_with("engine: expected one of"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn parse_engine(text: &str) -> Result<Profile, Error> {
    Profile::parse(text).map_err(|why| Error::new("engine", ErrorKind::Invalid(why)))
}

/// Refuses a run where the host interrupted the work, or where every model asked stopped at
/// its work limit (one line naming the first and the limit); a run where some models answer
/// reports the others as not answered.
fn refuse_when_nothing_answered(outcomes: &[(Model, ModelOutcome<Q>)]) -> Result<(), Error> {
    let stopped = |o: &ModelOutcome<Q>| match o {
        ModelOutcome::Stopped(s) => Some(*s),
        _ => None,
    };
    if outcomes
        .iter()
        .any(|(_, o)| stopped(o) == Some(Stopped::Interrupted))
    {
        return Err(Error::new("impact", ErrorKind::Interrupted));
    }
    match outcomes.first() {
        Some((model, first)) if outcomes.iter().all(|(_, o)| stopped(o).is_some()) => {
            Err(Error::out_of_range(
                "model",
                format!("{model}: {}", stopped(first).expect("every model stopped")),
            ))
        }
        _ => Ok(()),
    }
}

/// The models `text` names, for `n` contacts: `all` (the simultaneous models, sequential in
/// every order when there are at most [`MAX_ORDERED`] contacts, `pgs:1` and `pgs:10`),
/// `sequential` (every order), or one model ([`Model::parse`]).
///
/// # Errors
/// `model: ...`: an unknown name, or every order of more than [`MAX_ORDERED`] contacts.
///
/// # Examples
/// ```
/// use rodimpact::app::impact::parse_models;
/// assert_eq!(parse_models("all", 2)?.len(), 6); // 2 simultaneous, 2 orders, pgs:1, pgs:10
/// assert_eq!(parse_models("sequential", 3)?.len(), 6);
/// assert!(parse_models("newton", 2).unwrap_err().to_string().starts_with("model: expected"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn parse_models(text: &str, n: usize) -> Result<Vec<Model>, Error> {
    let bad = |why: String| Error::new("model", ErrorKind::Invalid(why));
    let every_order = || -> Result<Vec<Model>, Error> {
        if n > MAX_ORDERED {
            return Err(Error::out_of_range(
                "model",
                format!(
                    "sequential in every order takes at most {MAX_ORDERED} contacts ({n}! orders); give one order, sequential:1,2,..."
                ),
            ));
        }
        Ok(orders(n).into_iter().map(Model::Sequential).collect())
    };
    Ok(match text.trim() {
        "all" => {
            let mut all = vec![Model::SimultaneousNewton, Model::SimultaneousPoisson];
            if n <= MAX_ORDERED {
                all.extend(every_order()?);
            }
            all.extend([Model::Pgs(1), Model::Pgs(10)]);
            all
        }
        "sequential" => every_order()?,
        other => vec![Model::parse(other, n).map_err(|why| {
            bad(if other.contains(':') {
                why
            } else {
                format!(
                    "expected simultaneous-newton (lcp-newton), simultaneous-poisson (lcp-poisson), split, sequential, sequential:ORDER, pgs:K, an engine (pymunk-7, box2d-2.3, box2d-3, rapier-0.36, bullet-3) or all, got '{}'",
                    crate::echo::echo(other)
                )
            })
        })?],
    })
}
