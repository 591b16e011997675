//! `rodimpact paper --format html`: one self-contained page with every claim folded under its
//! verdict, the formulas and exact table values in MathML, the figures inline, and no request
//! to the network. (The page is also loaded in headless Chromium by `.ci/browser/run`, which
//! `cargo test` does not need.)

use crate::common;

use common::rodimpact;

fn page_to_stdout() -> String {
    let (code, stdout, stderr) = rodimpact(&["paper", "--format", "html"]);
    assert_eq!(code, 0, "{stderr}");
    stdout
}

#[test]
fn the_page_holds_every_claim_table_figure_and_formula() {
    let page = page_to_stdout();
    assert!(page.starts_with("<!DOCTYPE html>\n<html lang=\"en\">"));
    // NEWCOMER M5: the spin figure's caption says what its axis shows (omega l/v0, not
    // omega/omega_max), and the paper's figure keeps one numbering.
    assert!(
        page.contains("<figcaption><b>Figure 1.</b> The spin <math>"),
        "caption"
    );
    assert!(!page.contains("omega_{\\max}$ along the rod"));
    assert!(page.contains("<b>Figure 3.</b> The paper&#39;s Fig. 1, to scale"));
    assert!(!page.contains("Figure 1: a projectile"));
    assert!(page.ends_with("</html>\n"));
    // Every registered claim once, folded, with its verdict class.
    let ids: Vec<&str> = rodimpact::claims::registry().iter().map(|e| e.id).collect();
    assert_eq!(page.matches("<details id=\"").count(), ids.len());
    for id in &ids {
        assert_eq!(
            page.matches(&format!("<details id=\"{id}\" class=\"claim "))
                .count(),
            1,
            "{id}"
        );
    }
    assert!(page.contains("<details id=\"C3\" class=\"claim as-paper\">"));
    assert!(page.contains("<details id=\"C8\" class=\"claim qualified\">"));
    assert!(page.contains("<details id=\"C15\" class=\"claim proved\">"));
    assert!(!page.contains("class=\"claim failed\""));
    // The certificate under its claim: C15's identity, as `prove` writes it.
    assert!(page.contains("rhs     = (2*m*a/I)/(1 + m/M + m*a^2/I)*v0"));
    // The five tables, and T2's optimum a* = sqrt(6)/3 l in MathML beside its decimal.
    for t in ["T1", "T2", "T3", "T4", "T5"] {
        assert!(page.contains(&format!("<table id=\"{t}\">")), "{t}");
    }
    assert!(page.contains(
        "<td><math><mfrac><msqrt><mn>6</mn></msqrt><mn>3</mn></mfrac></math></td>\
         <td class=\"decimal\">0.816496580928</td>"
    ));
    // The paper's a*^2 = (M + m) l^2/(3 m) in the formula section, as a MathML fraction.
    assert!(page.contains("<msup><mi>a</mi><mrow><mo>*</mo><mn>2</mn></mrow></msup>"));
    // Three figures, inline and labelled.
    assert_eq!(page.matches("<svg role=\"img\" aria-label=").count(), 3);
    assert_eq!(page.matches("<figure id=").count(), 3);
}

/// Nothing is fetched: no external script, style sheet, image, font or frame. (The SVG
/// namespace `http://www.w3.org/2000/svg` is a name, not a request.)
#[test]
fn the_page_asks_nothing_of_the_network() {
    let page = page_to_stdout();
    for needle in [
        " src=", "<link", "@import", "url(", "<iframe", "<object", "<embed", "https://",
    ] {
        assert!(!page.contains(needle), "{needle}");
    }
    let http: Vec<&str> = page
        .match_indices("http://")
        .map(|(i, _)| &page[i..i + 34])
        .collect();
    assert!(
        http.iter()
            .all(|h| *h == "http://www.w3.org/2000/svg\" width="),
        "{http:?}"
    );
}

#[test]
fn out_writes_the_same_page_and_refuses_a_bad_path() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("paper.html");
    let (code, stdout, _) =
        rodimpact(&["paper", "--format", "html", "--out", file.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(stdout.is_empty(), "the page goes to the file only");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), page_to_stdout());
    // A directory that does not exist: exit 2, one line naming the field, nothing written.
    let missing = dir.path().join("no/such/dir/paper.html");
    let (code, _, err) = rodimpact(&[
        "paper",
        "--format",
        "html",
        "--out",
        missing.to_str().unwrap(),
    ]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: out:"), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    // An unknown format: clap's message, exit 2.
    let (code, _, err) = rodimpact(&["paper", "--format", "pdf"]);
    assert_eq!(code, 2);
    assert!(err.contains("possible values: text, html"));
}

/// NEWCOMER M9: a teacher's handout. `--summary` keeps every verdict (one line each), the
/// formulas, tables and figures, and leaves the certificates out (the full page prints as
/// shown, its certificates folded unless the reader ticks the box: the browser run counts the
/// pages); without --format html it is refused.
#[test]
fn the_summary_is_the_page_without_its_certificates() {
    let (code, summary, stderr) = rodimpact(&["paper", "--format", "html", "--summary"]);
    assert_eq!(code, 0, "{stderr}");
    let full = page_to_stdout();
    assert!(summary.len() * 3 < full.len(), "{} bytes", summary.len());
    assert!(!summary.contains("<details") && !summary.contains("<script"));
    assert!(summary.contains(": summary</h1>"));
    assert!(
        summary.contains("<li id=\"C3\" class=\"claim as-paper\"><span class=\"id\">C3</span>")
    );
    let ids = rodimpact::claims::registry().len();
    assert_eq!(summary.matches("<li id=\"").count(), ids);
    for t in ["T1", "T2", "T3", "T4", "T5"] {
        assert!(summary.contains(&format!("<table id=\"{t}\">")), "{t}");
    }
    assert_eq!(summary.matches("<figure id=").count(), 3);
    // The full page: printed as shown, with a box to unfold every certificate for print.
    assert!(full.contains(
        "<input type=\"checkbox\" id=\"print-all\"> unfold every certificate when printing"
    ));
    let (code, _, err) = rodimpact(&["paper", "--summary"]);
    assert_eq!(code, 2);
    assert_eq!(
        err.trim_end(),
        "error: summary: the summary is a web page to print: add --format html"
    );
}

/// NEWCOMER m6: on a phone the wide tables scroll in their own boxes (the browser run checks
/// that the page does not), and omega_max's case split is MathML like the formula beside it,
/// not ASCII (`6*m*v0/(M*l + 4*l*m)`).
#[test]
fn wide_tables_scroll_in_boxes_and_the_case_split_is_mathml() {
    let page = page_to_stdout();
    assert_eq!(
        page.matches("<div class=\"wide\" role=\"region\" tabindex=\"0\"")
            .count(),
        6
    );
    assert!(page.contains("aria-label=\"Table T2\">\n<table id=\"T2\">"));
    let formulas = &page[page.find("<section id=\"formulas\">").unwrap()..];
    let formulas = &formulas[..formulas.find("</section>").unwrap()];
    assert!(
        !formulas.contains("*m*") && !formulas.contains("l^2"),
        "ASCII math left"
    );
    assert!(formulas.contains("(I = M l²/3)"), "{formulas}");
    assert!(formulas.contains(
        "; when <math><mrow><mi>M</mi><mo>≤</mo><mn>2</mn><mi>m</mi></mrow></math> (a* on the rod); otherwise <math>"
    ), "{formulas}");
}
