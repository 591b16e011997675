//! One planar impact scene answered as `rodimpact impact` answers it: one contact under the
//! restitution laws asked for, several contacts under the models asked for, and the file's
//! published answers (`[[claim]]`) checked. The command line and the Python package both call
//! [`answer_impact`]; [`crate::report::impact_run_json`] and [`crate::report::impact_run_text`]
//! render the [`ImpactRun`] it returns.

use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::impact::{Law, MAX_ORDERED, Model, contact_matrix, orders, solve_exact, solve_several};
use crate::model::{MAX_SCENE_BYTES, from_value, toml_value};
use crate::textbook::SceneCheck;
use crate::textbook::impact::{
    ImpactAnswers, ImpactRun, check_impact_claims, check_model_claims, read_impact_claims,
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
/// contact under `law` (`None`: all three laws; every law when the file has claims, whose
/// sources each name theirs), with several under the models `model` names (`None`: all).
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
/// let run = answer_impact(&value, "paper.toml", Some(Law::Newton), None)?;
/// assert!(matches!(&run.answers, ImpactAnswers::Laws(a) if a.len() == 1));
/// let err = answer_impact(&value, "paper.toml", None, Some("pgs:3")).unwrap_err();
/// assert!(err.to_string().starts_with("model: one contact"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn answer_impact(
    value: &Value,
    label: &str,
    law: Option<Law>,
    model: Option<&str>,
) -> Result<ImpactRun, Error> {
    let at_file = |e: Error| Error::new(format!("{label}: {}", e.field), e.kind);
    let system = from_value(value).map_err(at_file)?;
    let claims = read_impact_claims(value, &system).map_err(at_file)?;
    if system.contacts.len() > 1 {
        if law.is_some() {
            return Err(Error::new(
                "law",
                ErrorKind::Conflict(
                    "several contacts: their models (--model) say how the contacts act together"
                        .into(),
                ),
            ));
        }
        let models = parse_models(model.unwrap_or("all"), system.contacts.len())?;
        let outcomes = models
            .into_iter()
            .map(|m| {
                let outcome = solve_several::<Q>(&system, &m);
                (m, outcome)
            })
            .collect();
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
        _ => Law::ALL.to_vec(),
    };
    let answers = laws
        .iter()
        .map(|&law| {
            solve_exact(&system, law)
                .map_err(|e| Error::new(label, ErrorKind::Invalid(e.to_string())))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let checked = SceneCheck {
        symbolic: None,
        answers: check_impact_claims(&claims, &system, &answers).map_err(at_file)?,
    };
    Ok(ImpactRun {
        contact: contact_matrix::<Q>(&system),
        system,
        answers: ImpactAnswers::Laws(answers),
        checked,
    })
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
                    "expected simultaneous-newton, simultaneous-poisson, sequential, sequential:ORDER, pgs:K or all, got '{}'",
                    crate::echo::echo(other)
                )
            })
        })?],
    })
}
