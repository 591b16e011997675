//! The reports of `rodimpact check`: a table or JSON of one scene's checked answers, the same
//! for a problem collection, and the summary lines (`2 of 3 claims agree; 1 disagrees`).

use super::counted;
use crate::field::decimal;
use crate::field::decimal::magnitude;
use crate::field::{Field, Q};
use crate::textbook::problems::ProblemCheck;
use crate::textbook::sigfig::{Tie, round_sig};
use crate::textbook::{AnswerAgreement, CheckedAnswer, Counterexample, RelError, SceneCheck};
use num_traits::{Signed, Zero};
use serde_json::{Value, json};
use std::fmt::Write as _;

/// Significant digits of the decimals in JSON, as `solve --json` prints them.
const JSON_DIGITS: usize = 30;

/// The label of an agreement in the text report.
///
/// # Examples
/// ```
/// use rodimpact::{report::agreement_label, textbook::AnswerAgreement};
/// assert_eq!(agreement_label(AnswerAgreement::LastDigit), "DISAGREES (last digit off by one)");
/// ```
pub fn agreement_label(agreement: AnswerAgreement) -> &'static str {
    match agreement {
        AnswerAgreement::Agrees => "agrees",
        AnswerAgreement::Disagrees => "DISAGREES",
        AnswerAgreement::LastDigit => "DISAGREES (last digit off by one)",
        AnswerAgreement::Undecided => "UNDECIDED",
    }
}

/// The key of an agreement in JSON output.
///
/// # Examples
/// ```
/// use rodimpact::{report::agreement_key, textbook::AnswerAgreement};
/// assert_eq!(agreement_key(AnswerAgreement::LastDigit), "last_digit_off_by_one");
/// ```
pub fn agreement_key(agreement: AnswerAgreement) -> &'static str {
    match agreement {
        AnswerAgreement::Agrees => "agrees",
        AnswerAgreement::Disagrees => "disagrees",
        AnswerAgreement::LastDigit => "last_digit_off_by_one",
        AnswerAgreement::Undecided => "undecided",
    }
}

/// A relative error as the report prints it: `×3.96` for a claim at least twice the exact
/// value (same sign), otherwise a signed percentage to two significant figures (`-49 %`,
/// `+0.036 %`, `-200 %`), never in scientific notation.
///
/// # Examples
/// ```
/// use rodimpact::{report::rel_error_text, textbook::RelError};
/// use rodimpact::field::q;
/// let text = |c, e| rel_error_text(&RelError::new(c, e).unwrap());
/// assert_eq!(text(q(546, 100), q(2625, 1906)), "×3.96");
/// assert_eq!(text(q(1, 10), q(480, 2437)), "-49 %");
/// assert_eq!(text(q(189, 100), q(36, 19)), "-0.25 %");
/// assert_eq!(text(q(-1, 1), q(1, 1)), "-200 %");
/// assert_eq!(text(q(1, 1), q(1, 1)), "0 %");
/// ```
pub fn rel_error_text(error: &RelError) -> String {
    let ratio = &error.claimed / &error.exact;
    let two = Q::from_integer(2.into());
    let text = if ratio >= two {
        format!("×{}", plain(&ratio, 3))
    } else {
        let percent = error.value() * Q::from_integer(100.into());
        let sign = if percent.is_positive() { "+" } else { "" };
        format!("{sign}{} %", plain(&percent, 2))
    };
    if error.at_counterexample {
        format!("{text} (at the counterexample)")
    } else {
        text
    }
}

/// `x` rounded to `figures` significant figures and printed positionally (`250`, not `2.5e2`;
/// `0.036`), however large: at least `figures` digits, more when the integer part needs them.
fn plain(x: &Q, figures: u32) -> String {
    if x.is_zero() {
        return "0".into();
    }
    let rounded = round_sig(x, figures, Tie::Up);
    let digits = (magnitude(&rounded) + 1).max(i64::from(figures));
    let text = decimal::decimal(&rounded, usize::try_from(digits).unwrap_or(1));
    // Trailing zeros after the point carry no information at two figures (`-50.0` -> `-50`).
    match text.split_once('.') {
        Some((int, frac)) if frac.chars().all(|c| c == '0') => int.to_string(),
        _ => text,
    }
}

/// `{"at": {symbol: value}, "exact": "...", "claimed": "..."}`, every value exact.
fn counterexample_json(counterexample: &Counterexample) -> Value {
    let at: serde_json::Map<String, Value> = counterexample
        .point
        .iter()
        .map(|(s, v)| (s.clone(), Value::String(v.to_string())))
        .collect();
    json!({
        "at": at,
        "exact": counterexample.exact.to_string(),
        "claimed": counterexample.claimed.to_string(),
    })
}

/// The exact value and its decimal as the text report shows them (`36/19 ≈ 1.89474`).
fn exact_text(answer: &CheckedAnswer) -> String {
    match &answer.value {
        Some(v) => {
            let (exact, decimal) = (v.compact(), v.decimal(6));
            if exact == decimal || exact.starts_with('≈') {
                exact
            } else {
                format!("{exact} ≈ {decimal}")
            }
        }
        None => answer.exact.clone(),
    }
}

/// One checked answer as JSON: `decimal` correctly rounded to 30 significant digits,
/// `rel_error` a number (`-0.5` for -50 %), `counterexample` an object.
///
/// # Examples
/// ```
/// use rodimpact::{report::answer_json, textbook::{CheckedAnswer, Exact}};
/// use rodimpact::field::q;
/// let j = answer_json(&CheckedAnswer::new("v", "2.3", "7/3".into(), Some(Exact::Rational(q(7, 3)))));
/// assert_eq!(j["verdict"], "undecided");
/// assert_eq!(j["decimal"], "2.33333333333333333333333333333");
/// ```
pub fn answer_json(answer: &CheckedAnswer) -> Value {
    json!({
        "name": answer.name,
        "claim": answer.claim,
        "exact": answer.exact,
        "decimal": answer.value.as_ref().map(|v| v.decimal(JSON_DIGITS)),
        "rel_error": answer.rel_error.as_ref().map(|r| finite_number(&r.value())),
        "rel_error_at_counterexample": answer.rel_error.as_ref().map(|r| r.at_counterexample),
        "verdict": agreement_key(answer.agreement),
        "counterexample": answer.counterexample.as_ref().map(counterexample_json),
        "notes": answer.notes,
    })
}

/// A rational as a JSON number (the nearest f64), or null when it is beyond the f64 range.
fn finite_number(x: &Q) -> Value {
    let f = x.nearest_f64();
    if f.is_finite() { json!(f) } else { Value::Null }
}

/// The table of one scene's checked answers: claim, exact, claimed, relative error, verdict,
/// then notes; a symbolic scene starts with its free symbols and the defaults it applied.
///
/// # Examples
/// ```
/// use rodimpact::{report::check_table, textbook::{CheckedAnswer, SceneCheck}};
/// let check = SceneCheck { symbolic: None, answers: vec![CheckedAnswer::new("v", "2.3", "7/3".into(), None)] };
/// assert!(check_table(&check).contains("UNDECIDED"));
/// ```
pub fn check_table(check: &SceneCheck) -> String {
    let mut out = String::new();
    if let Some(scene) = &check.symbolic {
        let free = if scene.free.is_empty() {
            "none".to_string()
        } else {
            scene.free.join(", ")
        };
        let _ = writeln!(out, "  free symbols: {free}");
        if !scene.defaults.is_empty() {
            let _ = writeln!(out, "  defaults: {}", scene.defaults.join("; "));
        }
    }
    let mut rows = vec![[
        "claim".to_string(),
        if check.symbolic.is_some() {
            "exact".to_string()
        } else {
            "exact (SI)".to_string()
        },
        "claimed".to_string(),
        "rel. error".to_string(),
        "verdict".to_string(),
    ]];
    for answer in &check.answers {
        rows.push([
            answer.name.clone(),
            exact_text(answer),
            answer.claim.clone(),
            answer
                .rel_error
                .as_ref()
                .map_or_else(|| "-".into(), rel_error_text),
            agreement_label(answer.agreement).to_string(),
        ]);
    }
    let widths: Vec<usize> = (0..5)
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    for (k, row) in rows.iter().enumerate() {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .map(|(c, w)| format!("{c:<w$}"))
            .collect();
        let _ = writeln!(out, "  {}", cells.join("  ").trim_end());
        if k > 0 {
            for note in &check.answers[k - 1].notes {
                let _ = writeln!(out, "      note: {note}");
            }
        }
    }
    out
}

/// The summary line of one scene's check: `2 of 3 claims agree; 1 disagrees`.
///
/// # Examples
/// ```
/// use rodimpact::{report::check_summary, textbook::SceneCheck};
/// assert_eq!(check_summary(&SceneCheck { symbolic: None, answers: vec![] }), "no claims");
/// ```
pub fn check_summary(check: &SceneCheck) -> String {
    agreement_line(check.agreeing(), check.answers.len())
}

/// One scene's check as JSON: `symbolic`, `free_symbols` and `defaults` (symbolic scenes),
/// `claims`, `summary`.
///
/// # Examples
/// ```
/// use rodimpact::{report::check_json, textbook::SceneCheck};
/// let j = check_json(&SceneCheck { symbolic: None, answers: vec![] });
/// assert_eq!(j["summary"]["claims"], 0);
/// assert_eq!(j["symbolic"], false);
/// ```
pub fn check_json(check: &SceneCheck) -> Value {
    let mut j = json!({
        "symbolic": check.symbolic.is_some(),
        "claims": check.answers.iter().map(answer_json).collect::<Vec<_>>(),
        "summary": agreement_json(check.agreeing(), check.answers.len()),
    });
    if let Some(scene) = &check.symbolic {
        j["free_symbols"] = json!(scene.free);
        j["defaults"] = json!(scene.defaults);
    }
    j
}

/// How many claimed answers agree, in words: `no claims`, `1 claim, it agrees`,
/// `1 of 3 claims agrees; 2 disagree`.
///
/// # Examples
/// ```
/// use rodimpact::report::agreement_line;
/// assert_eq!(agreement_line(1, 3), "1 of 3 claims agrees; 2 disagree");
/// assert_eq!(agreement_line(2, 3), "2 of 3 claims agree; 1 disagrees");
/// assert_eq!(agreement_line(0, 1), "1 claim, it disagrees");
/// assert_eq!(agreement_line(4, 4), "4 of 4 claims agree");
/// ```
pub fn agreement_line(agree: usize, total: usize) -> String {
    let wrong = total - agree;
    let verb = |n: usize, singular: &str, plural: &str| {
        format!("{n} {}", if n == 1 { singular } else { plural })
    };
    match total {
        0 => "no claims".into(),
        1 if agree == 1 => "1 claim, it agrees".into(),
        1 => "1 claim, it disagrees".into(),
        _ => {
            let head = format!(
                "{} of {total} claims {}",
                agree,
                if agree == 1 { "agrees" } else { "agree" }
            );
            if wrong == 0 {
                head
            } else {
                format!("{head}; {}", verb(wrong, "disagrees", "disagree"))
            }
        }
    }
}

/// How many claimed answers agree, as JSON: `{"claims", "agree", "disagree"}`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::report::agreement_json(1, 3)["disagree"], 2);
/// ```
pub fn agreement_json(agree: usize, total: usize) -> Value {
    json!({ "claims": total, "agree": agree, "disagree": total - agree })
}

/// (agreeing, total) claimed answers over every problem.
fn totals(checks: &[ProblemCheck]) -> (usize, usize) {
    checks.iter().fold((0, 0), |(a, t), p| {
        (a + p.check.agreeing(), t + p.check.answers.len())
    })
}

/// The text report of a problem collection: one section per problem, then the summary.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::report::problems_text(&[]), "0 problems; no claims\n");
/// ```
pub fn problems_text(checks: &[ProblemCheck]) -> String {
    let mut out = String::new();
    for p in checks {
        let _ = writeln!(out, "{}  ({})", p.id, p.source);
        out.push_str(&check_table(&p.check));
        if let Some(note) = &p.note {
            let _ = writeln!(out, "  about: {note}");
        }
        let _ = writeln!(out, "  {}\n", check_summary(&p.check));
    }
    let (agree, total) = totals(checks);
    let wrong: Vec<&str> = checks
        .iter()
        .filter(|p| !p.check.all_agree())
        .map(|p| p.id.as_str())
        .collect();
    let _ = write!(
        out,
        "{}; {}",
        counted(checks.len(), "problem"),
        agreement_line(agree, total)
    );
    if !wrong.is_empty() {
        let _ = write!(out, " (disagreements in: {})", wrong.join(", "));
    }
    out.push('\n');
    out
}

/// The JSON report of a problem collection: `{"problems": [...], "summary": {...}}`.
///
/// # Examples
/// ```
/// let j = rodimpact::report::problems_json(&[]);
/// assert_eq!(j["summary"]["claims"], 0);
/// ```
pub fn problems_json(checks: &[ProblemCheck]) -> Value {
    let (agree, total) = totals(checks);
    json!({
        "problems": checks.iter().map(|p| {
            let mut j = check_json(&p.check);
            j["id"] = json!(p.id);
            j["source"] = json!(p.source);
            j
        }).collect::<Vec<_>>(),
        "summary": agreement_json(agree, total),
    })
}
