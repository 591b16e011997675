//! A scene of `impact` answered ([`ImpactRun`]) as `rodimpact impact` prints it: the answers
//! per law or per model, and the file's published answers checked.

use super::{
    check_json, check_summary, check_table, impact_json, impact_text, models_json, models_text,
};
use crate::textbook::impact::{ImpactAnswers, ImpactRun};
use serde_json::Value;

/// The JSON of `impact --format json`: [`impact_json`] for one contact (with `not_answered`, the
/// laws or the engine that give no answer and why, when some do), [`models_json`] for several,
/// with `claims` ([`check_json`]) when the file has published answers.
///
/// # Examples
/// ```
/// use rodimpact::report::impact_run_json;
/// use rodimpact::app::impact::{answer_impact, read_scene_file};
/// let value = read_scene_file("paper.toml", "examples/impacts/paper-as-bodies.toml".as_ref())?;
/// let json = impact_run_json(&answer_impact(&value, "paper.toml", None, None, None)?, 30);
/// assert_eq!(json["laws"].as_array().map(Vec::len), Some(3));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_run_json(run: &ImpactRun, digits: usize) -> Value {
    let mut json = match &run.answers {
        ImpactAnswers::Laws(answers, unanswered) => {
            let mut json = impact_json(&run.system, &run.contact.0, answers, digits);
            if !unanswered.is_empty() {
                json["not_answered"] = unanswered
                    .iter()
                    .map(|n| serde_json::json!({"law": n.name, "why": n.why}))
                    .collect();
            }
            json
        }
        ImpactAnswers::Models(outcomes) => {
            models_json(&run.system, &run.contact.0, outcomes, digits)
        }
    };
    if run.has_claims() {
        json["claims"] = check_json(&run.checked);
    }
    json
}

/// The text report of `impact`: [`impact_text`] or [`models_text`], and the published answers
/// checked, each under its source's law or model.
///
/// # Examples
/// ```
/// use rodimpact::report::impact_run_text;
/// use rodimpact::app::impact::{answer_impact, read_scene_file};
/// let value = read_scene_file("paper.toml", "examples/impacts/paper-as-bodies.toml".as_ref())?;
/// let text = impact_run_text(&answer_impact(&value, "paper.toml", None, None, None)?, 6);
/// assert!(text.contains("Newton (kinematic") && text.contains("omega = -12/11"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_run_text(run: &ImpactRun, digits: usize) -> String {
    let (mut text, under) = match &run.answers {
        ImpactAnswers::Laws(answers, unanswered) => {
            let mut text = impact_text(&run.system, &run.contact, answers, digits);
            for n in unanswered {
                text.push_str(&format!("\n{}: not answered: {}\n", n.name, n.why));
            }
            (text, "law")
        }
        ImpactAnswers::Models(outcomes) => (models_text(&run.system, outcomes, digits), "model"),
    };
    if run.has_claims() {
        text.push_str(&format!(
            "\nPublished answers (the file's claims, each under its source's {under})\n{}  {}\n",
            check_table(&run.checked),
            check_summary(&run.checked)
        ));
    }
    text
}
