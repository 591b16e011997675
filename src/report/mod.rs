//! Output: every form in which results leave the library (JSON, text, Markdown, LaTeX, CSV and
//! SVG). The library computes values; this module turns them into text. Writing the text to
//! files, atomically, is [`crate::io`]'s job.

mod backend;
mod batch;
mod batch_json;
mod certificate;
mod check;
mod claims_doc;
mod explain;
pub mod explore;
mod formula;
mod handout;
mod impact;
mod impact_batch;
mod impact_models;
mod impact_run;
pub mod markup;
pub mod mathml;
pub mod page;
mod paper_html;
mod plot;
mod proofs;
mod simulate;
mod solution;
mod stability;
mod table;
pub mod tilted;

pub use backend::backend_json;
pub use batch::{batch_passed, batch_report, batch_summary, expected_report};
pub use batch_json::batch_summary_json;
pub use certificate::certificate_markdown;
pub use check::{
    agreement_json, agreement_key, agreement_label, agreement_line, answer_json, check_json,
    check_summary, check_table, problems_json, problems_text, rel_error_text,
};
pub use claims_doc::claims_markdown;
pub use explain::{ExplainFormat, explain};
pub use formula::{formula_json, formula_latex, formula_markdown, formula_text};
pub use handout::handout_html;
pub use impact::{impact_audit_json, impact_json, impact_text};
pub(crate) use impact::{law_heading, law_name};
pub use impact_batch::{impact_batch_json, impact_batch_text};
pub use impact_models::{models_json, models_text};
pub use impact_run::{impact_run_json, impact_run_text};
pub use paper_html::{PaperEdition, paper_html};
pub use plot::{
    Figure, PlotData, PlotValue, energy_figure, mass_ratio_family, omega_figure, optimum_figure,
    plot_figure1, plot_omega, plot_optimum, plot_stability, quantities_figure, velocity_figure,
};
#[cfg(feature = "png")]
pub use plot::{PNG_SCALE, svg_to_png};
pub use proofs::{
    PaperFigure, claim_markdown, hand_step_note, index_markdown, paper_files, paper_markdown,
    paper_report, prove_json, prove_line, summary_line, verdict_label, verdict_mark,
};
pub use simulate::{
    simulation_json, simulation_passes, simulation_text, sweep_json, sweep_passes, sweep_text,
};
pub use solution::{solution_html, solution_json, solution_text};
pub use stability::{stability_json, stability_markdown};
pub use table::{Format, render_document};

use crate::field::decimal;
use crate::field::{Q, QSqrt};
use serde_json::{Value, json};

/// A complete LaTeX document around `body`: article class, amsmath, 2 cm margins, and
/// `extra` preamble lines (packages a body needs beyond amsmath). What `table --format latex`
/// prints, and `formula` and `solve --explain latex` with `--standalone`.
///
/// # Examples
/// ```
/// let doc = rodimpact::report::latex_document(&[], "$x$");
/// assert!(doc.starts_with("\\documentclass{article}\n\\usepackage{amsmath}\n"));
/// assert!(doc.ends_with("\\begin{document}\n\n$x$\n\\end{document}\n"));
/// ```
pub fn latex_document(extra: &[&str], body: &str) -> String {
    let mut out = String::from("\\documentclass{article}\n\\usepackage{amsmath}\n");
    for line in extra {
        out.push_str(line);
        out.push('\n');
    }
    if !extra.iter().any(|l| l.contains("{geometry}")) {
        out.push_str("\\usepackage[margin=2cm]{geometry}\n");
    }
    out.push_str("\\begin{document}\n\n");
    out.push_str(body);
    if !body.ends_with('\n') {
        out.push('\n');
    }
    out.push_str("\\end{document}\n");
    out
}

/// `n thing` or `n things`: the one noun form the reports use for counts.
pub(crate) fn counted(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// The largest number of significant digits a report prints (`--digits`, and `digits=` in
/// Python): beyond it the decimals are refused, not computed for ever.
pub const MAX_DIGITS_OUT: usize = 10_000;

/// The number of significant digits `text` asks for (`default` when it is `None`): a whole
/// number from 1 to [`MAX_DIGITS_OUT`].
///
/// # Errors
/// `digits: must be a whole number from 1 to 10000, got '...'` for anything else.
///
/// # Examples
/// ```
/// use rodimpact::report::parse_digits;
/// assert_eq!(parse_digits(None, 30).unwrap(), 30);
/// assert_eq!(parse_digits(Some(" 12 "), 30).unwrap(), 12);
/// assert_eq!(
///     parse_digits(Some("0"), 30).unwrap_err().to_string(),
///     "digits: must be a whole number from 1 to 10000, got '0'"
/// );
/// ```
pub fn parse_digits(text: Option<&str>, default: usize) -> Result<usize, crate::Error> {
    let Some(text) = text else {
        return Ok(default);
    };
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=MAX_DIGITS_OUT).contains(&n) => Ok(n),
        _ => Err(crate::Error::out_of_range(
            "digits",
            format!(
                "must be a whole number from 1 to {MAX_DIGITS_OUT}, got '{}'",
                crate::echo::echo(text)
            ),
        )),
    }
}

/// The JSON value form of an exact number: `{"exact": "p/q", "decimal": "..."}`, the decimal
/// correctly rounded to `digits` significant digits.
///
/// # Examples
/// ```
/// use rodimpact::{report::value_json, field::q};
/// let v = value_json(&q(-1, 5), 3);
/// assert_eq!(v["exact"], "-1/5");
/// assert_eq!(v["decimal"], "-0.200");
/// ```
pub fn value_json(x: &Q, digits: usize) -> Value {
    json!({ "exact": x.to_string(), "decimal": decimal::decimal(x, digits) })
}

/// The JSON value form of an element of Q(sqrt d): `{"exact": "x + y*sqrt(d)" in the
/// canonical surd form, "decimal": "..."}` (a rational prints as `p/q`).
///
/// # Examples
/// ```
/// use rodimpact::{report::surd_json, field::{q, QSqrt}};
/// let v = surd_json(&QSqrt::sqrt_of(&q(2, 3)), 5);
/// assert_eq!((v["exact"].as_str(), v["decimal"].as_str()), (Some("sqrt(6)/3"), Some("0.81650")));
/// ```
pub fn surd_json(x: &QSqrt, digits: usize) -> Value {
    json!({ "exact": x.to_string(), "decimal": x.decimal(digits) })
}
