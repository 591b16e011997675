//! `paper --format html`: the verification report as one self-contained web page. The verdicts
//! grouped as the paper runs, each certificate folded under its claim, the paper's results as
//! MathML formulas, every table, the figures as inline SVG; no request leaves the page (no
//! font, script or image from the network). It prints as it is shown (folded certificates stay
//! folded, unless the reader ticks the box that unfolds them all for print); the summary
//! edition (`paper --format html --summary`) leaves the certificates out, a handout to print.

use super::formula::{key_latex, meaning, poly_latex, radical_latex, ratfn_latex};
use super::mathml::{self, escape};
use super::page::{Page, document, inline_svg};
use super::proofs::{
    METHOD, TITLE, groups, refutes_intuition_as_paper, summary_line, verdict_label, verdict_mark,
};
use super::{PaperFigure, claim_markdown, hand_step_note, markup};
use crate::claims::Decided;
use crate::tables::Table;
use crate::textbook::formula::{AnswerFormula, Condition, Formulas};
use pulldown_cmark::{Event, HeadingLevel, Parser, Tag, TagEnd};
use std::fmt::Write as _;

/// The page's style: readable on screen and on a phone (wide tables scroll in their own box),
/// no controls in print.
const STYLE: &str = include_str!("paper_html.css");

/// The full page's only script: open the claim a link points to, the two buttons that unfold or
/// fold every certificate, and, when its box is ticked, every certificate unfolded for print
/// (and folded back after).
const SCRIPT: &str = include_str!("paper_html.js");

/// Which report the page is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PaperEdition {
    /// Every claim with its certificate folded under it (printed as shown, or every certificate
    /// unfolded when the reader asks).
    Full,
    /// A handout: the verdicts one line each, the formulas, tables and figures; no certificate
    /// and no script.
    Summary,
}

/// The whole page: the verdicts of `all` grouped as the paper runs, `formulas` (the paper's
/// results for its own scene), the `tables` and the `figures`; with each claim's certificate
/// folded under it ([`PaperEdition::Full`]) or without the certificates
/// ([`PaperEdition::Summary`]).
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// use rodimpact::report::{PaperEdition, paper_html};
/// use rodimpact::scene::SceneInput;
/// use rodimpact::textbook::formula::formulas;
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let f = formulas(&SceneInput::default())?;
/// let page = paper_html(&[d.clone()], &f, &[], &[], PaperEdition::Full);
/// assert!(page.starts_with("<!DOCTYPE html>"));
/// assert!(page.contains("<details id=\"C15\" class=\"claim proved\">"));
/// assert!(page.contains("<math display=\"block\">"));
/// assert!(!page.contains("http://") && !page.contains("https://"));
/// let summary = paper_html(&[d], &f, &[], &[], PaperEdition::Summary);
/// assert!(summary.contains("<li id=\"C15\" class=\"claim proved\">"));
/// assert!(!summary.contains("<details") && !summary.contains("<script"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn paper_html(
    all: &[Decided],
    formulas: &Formulas,
    tables: &[Table],
    figures: &[PaperFigure],
    edition: PaperEdition,
) -> String {
    let full = edition == PaperEdition::Full;
    let mut body = String::new();
    let _ = write!(
        body,
        "<header>\n<h1>{}{}</h1>\n<p class=\"summary\">{} {}</p>\n",
        escape(TITLE),
        if full { "" } else { ": summary" },
        escape(&summary_line(all)),
        escape(METHOD)
    );
    if let Some(note) = hand_step_note(all) {
        let _ = writeln!(body, "<p class=\"hand\">{}</p>", escape(&note));
    }
    body.push_str(if full {
        "<p class=\"controls\"><button type=\"button\" id=\"unfold\">Unfold every certificate</button> \
         <button type=\"button\" id=\"fold\">Fold them</button> <label><input type=\"checkbox\" \
         id=\"print-all\"> unfold every certificate when printing (over 150 A4 pages; folded, \
         a certificate prints as its one line)</label></p>\n</header>\n"
    } else {
        "<p class=\"edition\">The summary, to print or hand out: each claim's verdict, the \
         formulas, tables and figures. Each claim's certificate is in the full report \
         (<code>rodimpact paper --format html</code>) and is checked again by <code>rodimpact \
         prove ID</code>.</p>\n</header>\n"
    });
    body.push_str(&contents(all, tables, figures));
    body.push_str("<main>\n");
    body.push_str(&formula_section(formulas));
    for group in groups(all) {
        let _ = writeln!(
            body,
            "<section id=\"{}\">\n<h2>{}</h2>",
            group_anchor(group.title()),
            escape(group.title())
        );
        let claims = all.iter().filter(|d| d.claim.group == group);
        if full {
            claims.for_each(|d| body.push_str(&claim_details(d)));
        } else {
            body.push_str("<ul class=\"verdicts\">\n");
            for d in claims {
                let (class, line) = claim_line(d);
                let _ = writeln!(
                    body,
                    "<li id=\"{}\" class=\"claim {class}\">{line}</li>",
                    d.claim.id
                );
            }
            body.push_str("</ul>\n");
        }
        body.push_str("</section>\n");
    }
    if !tables.is_empty() {
        body.push_str(
            "<section id=\"tables\">\n<h2>Tables</h2>\n<p>Exact, with m = l = v<sub>0</sub> = 1 \
             (lengths in units of l, velocities in units of v<sub>0</sub>); each exact value beside \
             its decimal, correctly rounded.</p>\n",
        );
        for t in tables {
            body.push_str(&wide(&format!("Table {}", t.id), &t.html()));
        }
        body.push_str("</section>\n");
    }
    if !figures.is_empty() {
        body.push_str("<section id=\"figures\">\n<h2>Figures</h2>\n");
        for (i, f) in figures.iter().enumerate() {
            let _ = writeln!(
                body,
                "<figure id=\"{}\">\n{}<figcaption><b>Figure {}.</b> {}</figcaption>\n</figure>",
                f.file.trim_end_matches(".svg"),
                inline_svg(&f.svg, &markup::unicode(&f.caption)),
                i + 1,
                mathml::text(&f.caption)
            );
        }
        body.push_str("</section>\n");
    }
    body.push_str("</main>\n");
    let _ = writeln!(
        body,
        "<footer><p>Written by <code>rodimpact paper --format html</code> (rodimpact {}). Every \
         verdict is re-checked by <code>rodimpact prove ID</code>; the claims for independent \
         checkers by <code>rodimpact prove --export smt2|sympy DIR</code>.</p></footer>",
        env!("CARGO_PKG_VERSION")
    );
    document(&Page {
        title: TITLE,
        style: STYLE,
        body: &body,
        script: if full { SCRIPT } else { "" },
    })
}

/// `html` (a table) in a box of its own that scrolls sideways when the screen is narrower than
/// the table (a phone), instead of the whole page; reachable by keyboard, named `label`.
pub(super) fn wide(label: &str, html: &str) -> String {
    format!(
        "<div class=\"wide\" role=\"region\" tabindex=\"0\" aria-label=\"{}\">\n{html}</div>\n",
        escape(label)
    )
}

/// The anchor of a group's section: its title in lower case, words joined by `-`.
fn group_anchor(title: &str) -> String {
    title
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .map(str::to_ascii_lowercase)
        .collect::<Vec<_>>()
        .join("-")
}

/// The list of contents: the formulas, each group with its claim count, tables, figures.
fn contents(all: &[Decided], tables: &[Table], figures: &[PaperFigure]) -> String {
    let mut out = String::from(
        "<nav aria-label=\"Contents\">\n<h2>Contents</h2>\n<ol>\n\
         <li><a href=\"#formulas\">The results as formulas</a></li>\n",
    );
    for group in groups(all) {
        let n = all.iter().filter(|d| d.claim.group == group).count();
        let _ = writeln!(
            out,
            "<li><a href=\"#{}\">{}</a> ({n} claim{})</li>",
            group_anchor(group.title()),
            escape(group.title()),
            if n == 1 { "" } else { "s" }
        );
    }
    if !tables.is_empty() {
        let _ = writeln!(
            out,
            "<li><a href=\"#tables\">Tables</a> ({})</li>",
            tables.iter().map(|t| t.id).collect::<Vec<_>>().join(", ")
        );
    }
    if !figures.is_empty() {
        let _ = writeln!(out, "<li><a href=\"#figures\">Figures</a></li>");
    }
    out.push_str("</ol>\n</nav>\n");
    out
}

/// The paper's results for its own scene (free uniform rod, elastic), each in MathML with
/// what it means and when it applies.
fn formula_section(f: &Formulas) -> String {
    let mut out = String::from(
        "<section id=\"formulas\">\n<h2>The results as formulas</h2>\n<p>The exact answer of \
         <code>rodimpact formula</code> for the paper's scene",
    );
    if !f.defaults.is_empty() {
        let _ = write!(
            out,
            " ({})",
            escape(&markup::ascii_math(&f.defaults.join("; ")))
        );
    }
    let _ = writeln!(out, ", in the symbols {}.</p>", escape(&f.free.join(", ")));
    out.push_str(&formula_table(f));
    out.push_str("</section>\n");
    out
}

/// The formulas of `f` as a table (in its own sideways-scrolling box): each quantity, its
/// formula in MathML, what it means and when it applies (omega_max's case split typeset as
/// the formula beside it). The paper page and the handout both show it.
pub(super) fn formula_table(f: &Formulas) -> String {
    let mut table = String::from(
        "<table class=\"formulas\">\n<thead><tr><th scope=\"col\">quantity</th>\
         <th scope=\"col\">formula</th><th scope=\"col\">meaning</th></tr></thead>\n<tbody>\n",
    );
    for x in &f.formulas {
        let _ = writeln!(
            table,
            "<tr><th scope=\"row\">{}</th><td>{}</td><td>{}{}</td></tr>",
            mathml::math(key_latex(x.key), false),
            mathml::math(&radical_latex(&x.value), true),
            escape(&markup::ascii_math(meaning(x.key))),
            condition_html(x)
        );
    }
    table.push_str("</tbody>\n</table>\n");
    wide("The results as formulas", &table)
}

/// When a formula holds (omega_max's case split), after its meaning: the inequality and the
/// value otherwise in MathML, as the formula beside it; empty for a formula that always holds.
fn condition_html(x: &AnswerFormula) -> String {
    let Some(p) = &x.piecewise else {
        return x
            .condition
            .as_deref()
            .map(|c| format!("; {}", escape(&markup::ascii_math(c))))
            .unwrap_or_default();
    };
    let when = match &p.when {
        None => "; never: a* lies beyond the end for every value of the symbols".to_string(),
        Some(Condition::Inequality(c)) => format!(
            "; when {} (a* on the rod)",
            mathml::math(
                &format!("{} \\le {}", poly_latex(&c.lhs), poly_latex(&c.rhs)),
                false
            )
        ),
        Some(Condition::Words(w)) => format!("; when {}", escape(w)),
    };
    let otherwise = match &p.otherwise {
        Some(end) => format!(
            "; otherwise {}",
            mathml::math(
                &format!("\\omega_{{\\max}} = \\omega(l) = {}", ratfn_latex(end)),
                false
            )
        ),
        None => "; otherwise ω is largest at the end of the rod".to_string(),
    };
    when + &otherwise
}

/// One claim: a `<details>` whose summary is the id, verdict and statement, and whose body is
/// its certificate (the formalisation, the reason, the evidence, how to re-check it).
fn claim_details(d: &Decided) -> String {
    let (class, line) = claim_line(d);
    let mut out = format!(
        "<details id=\"{id}\" class=\"claim {class}\">\n<summary>{line}</summary>\n<div class=\"body\">\n",
        id = d.claim.id
    );
    out.push_str(&certificate_html(&claim_markdown(d)));
    out.push_str("</div>\n</details>\n");
    out
}

/// A claim's class (its verdict, `as-paper` for an intuition refuted as the paper argues) and
/// its line: the id, verdict, where it stands in the paper and its statement.
fn claim_line(d: &Decided) -> (String, String) {
    let c = &d.claim;
    let class = if refutes_intuition_as_paper(d) {
        "as-paper".to_string()
    } else {
        verdict_label(d).to_ascii_lowercase()
    };
    let line = format!(
        "<span class=\"id\">{}</span> <span class=\"verdict\">{}</span> \
         <span class=\"where\">{}</span> <span class=\"statement\">{}</span>",
        c.id,
        escape(&verdict_mark(d)),
        escape(c.location),
        escape(&markup::ascii_math(c.statement)),
    );
    (class, line)
}

/// A certificate's Markdown as HTML inside its claim: its title line left out (the summary
/// shows it), the headings moved two levels down.
fn certificate_html(markdown: &str) -> String {
    let mut skipping_title = false;
    let events = Parser::new(markdown).filter_map(|event| match event {
        Event::Start(Tag::Heading {
            level: HeadingLevel::H1,
            ..
        }) => {
            skipping_title = true;
            None
        }
        Event::End(TagEnd::Heading(HeadingLevel::H1)) => {
            skipping_title = false;
            None
        }
        _ if skipping_title => None,
        Event::Start(Tag::Heading {
            level,
            id,
            classes,
            attrs,
        }) => Some(Event::Start(Tag::Heading {
            level: lower(level),
            id,
            classes,
            attrs,
        })),
        Event::End(TagEnd::Heading(level)) => Some(Event::End(TagEnd::Heading(lower(level)))),
        // Raw HTML in a certificate is shown as text, never interpreted.
        Event::Html(raw) | Event::InlineHtml(raw) => Some(Event::Text(raw)),
        other => Some(other),
    });
    let mut out = String::new();
    pulldown_cmark::html::push_html(&mut out, events);
    out
}

/// A heading two levels down (`##` becomes `h4`), at most `h6`.
fn lower(level: HeadingLevel) -> HeadingLevel {
    match level {
        HeadingLevel::H1 => HeadingLevel::H3,
        HeadingLevel::H2 => HeadingLevel::H4,
        HeadingLevel::H3 => HeadingLevel::H5,
        _ => HeadingLevel::H6,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn certificate_headings_move_down_and_raw_html_is_text() {
        let html =
            certificate_html("# C1 — title\n\n## Claim\n\n> x <b>y</b>\n\n```text\na < b\n```\n");
        assert!(!html.contains("title"), "{html}");
        assert!(html.contains("<h4>Claim</h4>"), "{html}");
        assert!(html.contains("&lt;b&gt;y&lt;/b&gt;"), "{html}");
        assert!(
            html.contains("<pre><code class=\"language-text\">a &lt; b\n</code></pre>"),
            "{html}"
        );
    }

    #[test]
    fn svg_is_labelled_and_its_declaration_dropped() {
        let svg = inline_svg("<?xml version=\"1.0\"?>\n<svg width=\"1\"></svg>", "ω & a");
        assert_eq!(
            svg,
            "<svg role=\"img\" aria-label=\"ω &amp; a\" width=\"1\"></svg>"
        );
    }

    #[test]
    fn anchors_of_groups() {
        assert_eq!(
            group_anchor("The optimum impact point"),
            "the-optimum-impact-point"
        );
        assert_eq!(
            group_anchor("Abstract and introduction"),
            "abstract-and-introduction"
        );
    }
}
