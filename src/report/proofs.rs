//! Claims as people read them: one Markdown certificate per claim, the index of `proofs/`, the
//! verification report of the paper (text and `report.md`), the directory `paper --out` writes,
//! and the `prove` listing (text and JSON).
//!
//! Everything here is deterministic: no timings enter the Markdown, so `proofs/` can be
//! golden-tested.
//!
//! Two marks qualify a verdict, each explained wherever it appears:
//!
//! - `†`: besides its certificates, the verdict rests on a step argued by hand, not
//!   machine-checked (the claim's formalisation says so with the words `not machine-checked`);
//! - `REFUTED (as the paper argues)`: the statement is an intuition the paper states in order to
//!   refute it (the claim's statement starts with `Intuition:`), so the refutation agrees with
//!   the paper.

use super::certificate::certificate_markdown;
use super::markup;
use super::table::{Format, render_document};
use crate::claims::{self, Certificate, Claim, Decided, Decision, Group, Verdict};
use crate::tables::Table;
use serde_json::{Map, Value, json};
use std::fmt::Write as _;

/// The mark of a verdict that rests on a step argued by hand.
const HAND: &str = "†";

/// The words by which a claim's formalisation marks a step argued by hand.
const HAND_WORDS: &str = "not machine-checked";

/// Whether the verdict on `claim` also rests on a step argued by hand, not machine-checked.
fn rests_on_hand_step(claim: &Claim) -> bool {
    claim.formal.contains(HAND_WORDS)
}

/// Whether `d` refutes an intuition that the paper itself states in order to refute it.
pub(super) fn refutes_intuition_as_paper(d: &Decided) -> bool {
    d.verdict == Ok(Verdict::Refuted) && d.claim.statement.starts_with("Intuition:")
}

/// The verdict as printed: `PROVED`, `REFUTED`, `QUALIFIED`, or `FAILED` when a certificate did
/// not check (the plain value of `prove --json`'s `"verdict"`).
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// use rodimpact::report::verdict_label;
/// assert_eq!(verdict_label(&decide("C15", &Paper::as_printed()).unwrap()), "PROVED");
/// ```
pub fn verdict_label(d: &Decided) -> &'static str {
    match &d.verdict {
        Ok(v) => v.as_str(),
        Err(_) => "FAILED",
    }
}

/// The verdict with its marks, as reports print it: `PROVED`, `PROVED †` (a step argued by
/// hand), `REFUTED (as the paper argues)` (an intuition the paper refutes).
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// use rodimpact::report::verdict_mark;
/// let paper = Paper::as_printed();
/// assert_eq!(verdict_mark(&decide("C15", &paper).unwrap()), "PROVED");
/// assert_eq!(verdict_mark(&decide("X19", &paper).unwrap()), "PROVED †");
/// assert_eq!(verdict_mark(&decide("C3", &paper).unwrap()), "REFUTED (as the paper argues)");
/// ```
pub fn verdict_mark(d: &Decided) -> String {
    let label = verdict_label(d);
    if refutes_intuition_as_paper(d) {
        format!("{label} (as the paper argues)")
    } else if d.verdict.is_ok() && rests_on_hand_step(&d.claim) {
        format!("{label} {HAND}")
    } else {
        label.to_string()
    }
}

/// The Markdown certificate of one claim (`proofs/<ID>.md`).
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let md = rodimpact::report::claim_markdown(&decide("C15", &Paper::as_printed()).unwrap());
/// assert!(md.starts_with("# C15"));
/// assert!(md.contains("**Verdict: PROVED**"));
/// ```
pub fn claim_markdown(d: &Decided) -> String {
    let c = &d.claim;
    let mut out = String::new();
    let _ = writeln!(out, "# {} — {}\n", c.id, c.location);
    let _ = writeln!(
        out,
        "**Verdict: {}** · method: {}\n",
        verdict_mark(d),
        c.method()
    );
    if refutes_intuition_as_paper(d) {
        let _ = writeln!(
            out,
            "The statement is the intuition the paper states in order to refute it: this verdict \
             agrees with the paper.\n"
        );
    }
    if rests_on_hand_step(c) {
        let _ = writeln!(
            out,
            "{HAND} Besides the certificates below, this verdict rests on a step argued by hand, \
             {HAND_WORDS}: the *Formalised* section says which.\n"
        );
    }
    if let Err(why) = &d.verdict {
        let _ = writeln!(out, "**The certificates do not check:** {why}\n");
    }
    let _ = writeln!(out, "## Claim\n\n> {}\n", c.statement);
    let _ = writeln!(out, "## Formalised\n\n{}\n", c.formal);
    let _ = writeln!(out, "## Why\n\n{}\n", c.reason);
    let section = |out: &mut String, title: &str, certs: &[Certificate]| {
        let _ = writeln!(out, "## {title}\n");
        for (i, cert) in certs.iter().enumerate() {
            let _ = writeln!(out, "### {}. {}\n", i + 1, cert.title());
            out.push_str(&certificate_markdown(cert));
            out.push('\n');
        }
    };
    match &c.decision {
        Decision::Proved(certs) => section(&mut out, "Certificates", certs),
        Decision::Refuted(certs) => section(&mut out, "Counterexample", certs),
        Decision::Qualified {
            qualification,
            counterexample,
            proof,
        } => {
            let _ = writeln!(out, "## Qualification\n\n{qualification}\n");
            section(
                &mut out,
                "Counterexample to the natural reading",
                counterexample,
            );
            section(&mut out, "Proof of the qualified statement", proof);
        }
    }
    let _ = writeln!(
        out,
        "## Re-check\n\n```sh\nrodimpact prove {}\n```\n\nThe certificates above are re-checked by exact computation; the verdict comes from them{}.",
        c.id,
        if rests_on_hand_step(c) {
            " and the step argued by hand"
        } else {
            " alone"
        }
    );
    out
}

/// The table of claims, linked to their certificates, that both indexes share.
fn claims_table(all: &[Decided]) -> String {
    let mut out =
        String::from("| id | where | verdict | method | claim |\n|---|---|---|---|---|\n");
    for d in all {
        let c = &d.claim;
        let _ = writeln!(
            out,
            "| [{id}]({id}.md) | {} | {} | {} | {} |",
            markup::markdown_text(c.location),
            verdict_mark(d),
            c.method(),
            markup::markdown_text(&markup::ascii_math(c.statement)),
            id = c.id
        );
    }
    out
}

/// The summary and, when a verdict carries a mark, the legend, as Markdown paragraphs.
fn summary_paragraphs(all: &[Decided]) -> String {
    let mut out = summary_line(all);
    out.push_str("\n\n");
    if let Some(note) = hand_step_note(all) {
        out.push_str(&note);
        out.push_str("\n\n");
    }
    out
}

/// `proofs/README.md` (and the index `prove --write DIR` writes): every claim with its verdict
/// and method, linked to its certificate.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let md = rodimpact::report::index_markdown(&[d]);
/// assert!(md.contains("[C15](C15.md)"));
/// ```
pub fn index_markdown(all: &[Decided]) -> String {
    let mut out = format!(
        "# Certificates\n\nOne certificate per claim of the list in `docs/claims.md`: {} are the paper's, {} go beyond it. Written by \
         `rodimpact prove --write DIR`; the repository's copy, `proofs/`, is regenerated and compared by \
         `cargo test`. A verdict comes from re-checking its certificates by exact computation.\n\n",
        claims::paper_ids(),
        claims::beyond_ids()
    );
    out.push_str(&summary_paragraphs(all));
    out.push_str(&claims_table(all));
    out
}

/// "N claims: P PROVED, R REFUTED, Q QUALIFIED, and 1 intuition REFUTED as the paper argues
/// (C3)." (and the failures, if any). A refuted intuition that the paper itself refutes is
/// counted apart: it is the paper's point, not a fault found in it.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let paper = Paper::as_printed();
/// let d = decide("C15", &paper).unwrap();
/// assert_eq!(rodimpact::report::summary_line(&[d]), "1 claim: 1 PROVED, 0 REFUTED, 0 QUALIFIED.");
/// let both = [decide("C3", &paper).unwrap(), decide("C15", &paper).unwrap()];
/// assert_eq!(
///     rodimpact::report::summary_line(&both),
///     "2 claims: 1 PROVED, 0 REFUTED, 0 QUALIFIED, and 1 intuition REFUTED as the paper argues (C3)."
/// );
/// ```
pub fn summary_line(all: &[Decided]) -> String {
    let intuitions: Vec<&str> = all
        .iter()
        .filter(|d| refutes_intuition_as_paper(d))
        .map(|d| d.claim.id)
        .collect();
    let count = |v: Verdict| {
        all.iter()
            .filter(|d| d.verdict == Ok(v) && !refutes_intuition_as_paper(d))
            .count()
    };
    let failed = all.iter().filter(|d| d.verdict.is_err()).count();
    // A refuted claim is named: beyond the paper it is a finding (Newton's law gaining energy),
    // not a fault of the paper.
    let refuted: Vec<&str> = all
        .iter()
        .filter(|d| d.verdict == Ok(Verdict::Refuted) && !refutes_intuition_as_paper(d))
        .map(|d| d.claim.id)
        .collect();
    let named = if refuted.is_empty() {
        String::new()
    } else {
        format!(" ({})", refuted.join(", "))
    };
    let mut line = format!(
        "{} claim{}: {} PROVED, {} REFUTED{named}, {} QUALIFIED",
        all.len(),
        if all.len() == 1 { "" } else { "s" },
        count(Verdict::Proved),
        count(Verdict::Refuted),
        count(Verdict::Qualified)
    );
    if failed > 0 {
        let _ = write!(line, ", {failed} FAILED (a certificate did not check)");
    }
    if !intuitions.is_empty() {
        let _ = write!(
            line,
            ", and {} intuition{} REFUTED as the paper argues ({})",
            intuitions.len(),
            if intuitions.len() == 1 { "" } else { "s" },
            intuitions.join(", ")
        );
    }
    line.push('.');
    line
}

/// The legend of the `†` mark, naming the claims that carry it; `None` when none does.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let paper = Paper::as_printed();
/// let d = [decide("C15", &paper).unwrap(), decide("X19", &paper).unwrap()];
/// assert!(rodimpact::report::hand_step_note(&d).unwrap().starts_with("† 1 verdict (X19) also rests"));
/// assert_eq!(rodimpact::report::hand_step_note(&d[..1]), None);
/// ```
pub fn hand_step_note(all: &[Decided]) -> Option<String> {
    let ids: Vec<&str> = all
        .iter()
        .filter(|d| d.verdict.is_ok() && rests_on_hand_step(&d.claim))
        .map(|d| d.claim.id)
        .collect();
    (!ids.is_empty()).then(|| {
        format!(
            "{HAND} {} verdict{} ({}) also rest{} on a step argued by hand, {HAND_WORDS}; each \
             certificate's formalisation states that step.",
            ids.len(),
            if ids.len() == 1 { "" } else { "s" },
            ids.join(", "),
            if ids.len() == 1 { "s" } else { "" }
        )
    })
}

pub(super) const TITLE: &str =
    "Verification of N. A. Lemos, \"Failure of intuition in elementary rigid body dynamics\"";

pub(super) const METHOD: &str = "Every verdict comes from re-checking its certificates by exact computation (rational functions, Q(√d)).";

/// One claim's reason, qualification and failure, each with its label.
fn notes(d: &Decided) -> Vec<(&'static str, String)> {
    let c = &d.claim;
    let mut notes = vec![("", c.reason.clone())];
    if let Some(q) = c.qualification() {
        notes.push(("qualified: ", q.to_string()));
    }
    if let Err(why) = &d.verdict {
        notes.push(("CHECK FAILED: ", why.to_string()));
    }
    notes
}

/// The report groups in the paper's order.
pub(super) fn groups(all: &[Decided]) -> Vec<Group> {
    let mut groups: Vec<Group> = all.iter().map(|d| d.claim.group).collect();
    groups.dedup();
    groups
}

/// The verification report of the paper for the terminal: grouped as the paper runs, then the
/// results beyond it; each claim with its verdict (and marks), statement and reason.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let text = rodimpact::report::paper_report(&[d]);
/// assert!(text.contains("C15"));
/// assert!(text.contains("The impulse equations"));
/// ```
pub fn paper_report(all: &[Decided]) -> String {
    let mut out = format!("{TITLE}\n\n{} {METHOD}\n", summary_line(all));
    if let Some(note) = hand_step_note(all) {
        let _ = writeln!(out, "{note}");
    }
    out.push('\n');
    for group in groups(all) {
        let _ = writeln!(out, "{}", group.title());
        for d in all.iter().filter(|d| d.claim.group == group) {
            let c = &d.claim;
            let _ = writeln!(
                out,
                "  {:<4} {:<11}  {}",
                c.id,
                verdict_mark(d),
                markup::ascii_math(c.statement)
            );
            for (label, text) in notes(d) {
                let _ = writeln!(
                    out,
                    "  {:<4} {:<11}  -> {label}{}",
                    "",
                    "",
                    markup::ascii_math(&text)
                );
            }
        }
        out.push('\n');
    }
    out
}

/// A figure of the report: its file name, a caption ([`markup`](super::markup)) and the SVG.
///
/// # Examples
/// ```
/// use rodimpact::report::PaperFigure;
/// let f = PaperFigure { file: "omega.svg", caption: "$\\omega(a)$".into(), svg: "<svg/>".into() };
/// assert_eq!(rodimpact::report::markup::unicode(&f.caption), "ω(a)");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PaperFigure {
    /// The file name (`omega.svg`).
    pub file: &'static str,
    /// What it shows.
    pub caption: String,
    /// The SVG document.
    pub svg: String,
}

/// `report.md` of `paper --out`: the verdicts grouped as the paper runs, then all tables and
/// the figures (embedded as images), with math as GitHub renders it.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// use rodimpact::report::{paper_markdown, PaperFigure};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let fig = PaperFigure { file: "omega.svg", caption: "$\\omega(a)$".into(), svg: "<svg/>".into() };
/// let md = paper_markdown(&[d], &[], &[fig]);
/// assert!(md.contains("| [C15](C15.md) |"));
/// assert!(md.contains("![ω(a)](omega.svg)"));
/// ```
pub fn paper_markdown(all: &[Decided], tables: &[Table], figures: &[PaperFigure]) -> String {
    let mut out = format!(
        "# {}\n\n{} {METHOD}\n\n",
        markup::markdown_text(TITLE),
        summary_line(all)
    );
    if let Some(note) = hand_step_note(all) {
        let _ = writeln!(out, "{note}\n");
    }
    out.push_str(
        "Each id links to its certificate. Contents: the claims by section of the paper, then the results \
         beyond it, the tables T1-T5 and the figures.\n\n",
    );
    for group in groups(all) {
        let _ = writeln!(
            out,
            "## {}\n\n| id | where | verdict | claim | reason |\n|---|---|---|---|---|",
            group.title()
        );
        for d in all.iter().filter(|d| d.claim.group == group) {
            let c = &d.claim;
            let reason: Vec<String> = notes(d)
                .iter()
                .map(|(label, text)| {
                    let text = markup::markdown_text(&markup::ascii_math(text));
                    match *label {
                        "qualified: " => format!("*Qualified:* {text}"),
                        _ => format!("{label}{text}"),
                    }
                })
                .collect();
            let _ = writeln!(
                out,
                "| [{id}]({id}.md) | {} | **{}** | {} | {} |",
                markup::markdown_text(c.location),
                verdict_mark(d),
                markup::markdown_text(&markup::ascii_math(c.statement)),
                reason.join(". "),
                id = c.id
            );
        }
        out.push('\n');
    }
    if !tables.is_empty() {
        out.push_str(
            "## Tables\n\nExact, with m = l = v0 = 1 (so lengths are in units of l, velocities in units of v0); \
             also as [tables.md](tables.md), [tables.tex](tables.tex) and one CSV file per table.\n\n",
        );
        for t in tables {
            out.push_str(&t.github_markdown());
            out.push('\n');
        }
    }
    if !figures.is_empty() {
        out.push_str("## Figures\n\n");
        for (i, f) in figures.iter().enumerate() {
            let _ = writeln!(
                out,
                "![{}]({})\n\n*Figure {}.* {}\n",
                markup::markdown_text(&markup::unicode(&f.caption)),
                f.file,
                i + 1,
                markup::github(&f.caption)
            );
        }
    }
    out
}

/// Every file `paper --out DIR` writes, named and in order: `README.md` (the index of the
/// directory), `report.md`, one certificate per claim, `tables.md`, `tables.tex`, one CSV file
/// per table (`T1.csv`), and the figures.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let files = rodimpact::report::paper_files(&[d], &[], &[]);
/// let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
/// assert_eq!(names, ["README.md", "report.md", "C15.md", "tables.md", "tables.tex"]);
/// ```
pub fn paper_files(
    all: &[Decided],
    tables: &[Table],
    figures: &[PaperFigure],
) -> Vec<(String, String)> {
    let mut files = vec![
        ("README.md".to_string(), paper_index(all, tables, figures)),
        (
            "report.md".to_string(),
            paper_markdown(all, tables, figures),
        ),
    ];
    files.extend(
        all.iter()
            .map(|d| (format!("{}.md", d.claim.id), claim_markdown(d))),
    );
    for format in [Format::Markdown, Format::Latex] {
        files.push((
            format!("tables.{}", format.extension()),
            render_document(tables, format),
        ));
    }
    files.extend(
        tables
            .iter()
            .map(|t| (format!("{}.csv", t.id), t.render(Format::Csv))),
    );
    files.extend(figures.iter().map(|f| (f.file.to_string(), f.svg.clone())));
    files
}

/// The `README.md` of `paper --out DIR`: what each file of the directory holds, then the claims.
fn paper_index(all: &[Decided], tables: &[Table], figures: &[PaperFigure]) -> String {
    let mut out = format!(
        "# {}\n\nWritten by `rodimpact paper --out DIR`; a re-run replaces these files as a whole.\n\n\
         | file | what it holds |\n|---|---|\n\
         | [report.md](report.md) | the report: every claim's verdict and reason, the tables, the figures |\n\
         | `{}.md` … `{}.md` | one certificate per claim, linked below: the claim formalised, the evidence, how to re-check it |\n\
         | [tables.md](tables.md) | the tables T1-T5 in Markdown |\n\
         | [tables.tex](tables.tex) | the same tables, a LaTeX document (`pdflatex tables.tex`) |\n",
        markup::markdown_text(TITLE),
        claims::paper_ids().first,
        claims::beyond_ids().last
    );
    for t in tables {
        let _ = writeln!(
            out,
            "| [{id}.csv]({id}.csv) | {id} as CSV: exact strings and decimals, units in the column names |",
            id = t.id
        );
    }
    for f in figures {
        let _ = writeln!(
            out,
            "| [{file}]({file}) | {} |",
            markup::github(&f.caption),
            file = f.file
        );
    }
    out.push_str("\n## Claims\n\n");
    out.push_str(&summary_paragraphs(all));
    out.push_str(&claims_table(all));
    out
}

/// One `prove` line: id, verdict (with its marks), method, time.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let line = rodimpact::report::prove_line(&decide("C15", &Paper::as_printed()).unwrap());
/// assert!(line.starts_with("C15  PROVED"));
/// ```
pub fn prove_line(d: &Decided) -> String {
    let mut line = format!(
        "{:<4} {:<11}  {:<32} {:>9.3} ms",
        d.claim.id,
        verdict_mark(d),
        d.claim.method(),
        d.seconds * 1e3
    );
    if let Err(why) = &d.verdict {
        let _ = write!(line, "  ({why})");
    }
    line
}

/// The `prove --json` element: `{"id", "verdict", "statement", "formal", "qualification"
/// (QUALIFIED only), "method", "hand_step", "intuition", "seconds"}`, plus `"error"` when a
/// certificate failed to check. `"hand_step"` is true when the verdict also rests on a step
/// argued by hand (the `†` of the reports); `"intuition"` is true for a statement the paper
/// itself states in order to refute it.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let j = rodimpact::report::prove_json(&decide("C15", &Paper::as_printed()).unwrap());
/// assert_eq!(j["verdict"], "PROVED");
/// assert_eq!(j["hand_step"], false);
/// assert!(j.get("qualification").is_none());
/// ```
pub fn prove_json(d: &Decided) -> Value {
    let c = &d.claim;
    let mut out = Map::new();
    out.insert("id".into(), json!(c.id));
    out.insert("verdict".into(), json!(verdict_label(d)));
    out.insert("statement".into(), json!(c.statement));
    out.insert("formal".into(), json!(c.formal));
    if let Some(q) = c.qualification() {
        out.insert("qualification".into(), json!(q));
    }
    out.insert("method".into(), json!(c.method()));
    out.insert("hand_step".into(), json!(rests_on_hand_step(c)));
    out.insert(
        "intuition".into(),
        json!(c.statement.starts_with("Intuition:")),
    );
    out.insert("seconds".into(), json!(d.seconds));
    if let Err(why) = &d.verdict {
        out.insert("error".into(), json!(why.to_string()));
    }
    Value::Object(out)
}
