//! `rodimpact handout`: one scene as a page to print, built from the other commands' renderers.
//!
//! The reference scene is m = M = l = v0 = 1, a = 1/2, e = 1, a free uniform rod (I = M l^2/3
//! = 1/3). Worked by hand from the impulse equations, not taken from the program:
//! momentum `1 = v + V`, angular momentum about the centre `1/2 = v/2 + omega/3`, restitution
//! at the contact `V + omega/2 - v = 1`. The first two give `V = 1 - v`, `omega = 3/2 (1 - v)`;
//! the third `7/4 (1 - v) - v = 1`, so v = 3/11, V = 8/11 and omega = 12/11. omega(a) =
//! 2 a/(I (M + m)/M + a^2) (with m = v0 = 1) peaks at a*^2 = I (M + m)/(m M) = 2/3, a* =
//! sqrt(6)/3 < l, with omega_max = (1 + e) v0/(2 a*) = sqrt(6)/2.

use crate::common;

use common::rodimpact;

const SCENE: [&str; 7] = ["handout", "--m", "1", "--M", "1", "--a", "1/2"];

fn page() -> String {
    let (code, stdout, stderr) = rodimpact(&SCENE);
    assert_eq!(code, 0, "{stderr}");
    stdout
}

/// The part of the page from the section `id` to its end.
fn section<'a>(page: &'a str, id: &str) -> &'a str {
    let start = page
        .find(&format!("<section id=\"{id}\">"))
        .unwrap_or_else(|| panic!("no section {id}"));
    let len = page[start..].find("</section>").expect("a closed section");
    &page[start..start + len]
}

#[test]
fn handout_holds_the_exact_answer_the_working_the_formulas_figure_and_table() {
    let page = page();
    assert!(page.starts_with("<!DOCTYPE html>"));
    // The answer, as solve states it.
    let answer = section(&page, "answer");
    for exact in [
        "<th scope=\"row\">v</th><td>projectile velocity</td><td>3/11 m/s</td>",
        "<td>8/11 m/s</td>",
        "<th scope=\"row\">omega</th><td>rod angular velocity</td><td>12/11 rad/s</td>",
        "<td>sqrt(6)/3 m</td>",
        "<td>sqrt(6)/2 rad/s</td>",
        "<td>M ≤ 2m (here M = m)</td>",
    ] {
        assert!(answer.contains(exact), "{exact}");
    }
    // The working, in MathML: the balance equations with the numbers, and the result.
    let working = section(&page, "working");
    assert!(working.contains("<h3>2. The three balance equations</h3>"));
    assert!(working.contains("<mfrac>") || working.contains("<mn>12</mn>"));
    assert!(working.contains("<mi>ω</mi><mo>=</mo>"), "{working}");
    assert!(
        !page.contains("<merror>"),
        "math the MathML reader did not know"
    );
    // The formulas in symbols, with omega_max's condition M <= 2m typeset.
    let formulas = section(&page, "formulas");
    assert!(formulas.contains("<table class=\"formulas\">"));
    assert!(formulas.contains(
        "when <math><mrow><mi>M</mi><mo>≤</mo><mn>2</mn><mi>m</mi></mrow></math> (a* on the rod)"
    ), "{formulas}");
    // The figure, inline, with a* and the end of the rod marked.
    let figure = section(&page, "figure");
    assert!(figure.contains("<svg role=\"img\""));
    assert!(figure.contains("fastest spin on the rod") && figure.contains("end of the rod"));
    // The table: the velocities along the rod, the row a* = sqrt(6)/3 among them.
    let table = section(&page, "table");
    assert!(table.contains("<table id=\"T2\">"));
    assert!(table.contains("<mfrac><msqrt><mn>6</mn></msqrt><mn>3</mn></mfrac>"));
    assert!(table.contains("<mfrac><mn>12</mn><mn>11</mn></mfrac>"));
    // Self-contained and print-ready: nothing fetched, no script, an A4 page rule.
    for needle in [" src=", "<link", "@import", "url(", "https://", "<script"] {
        assert!(!page.contains(needle), "{needle}");
    }
    assert!(page.contains("@page { size: A4;"));
}

#[test]
fn handout_of_a_rod_on_a_pivot_lists_where_it_spins_fastest() {
    let (code, page, err) = rodimpact(&[
        "handout", "--m", "1", "--M", "1", "--a", "1/2", "--pivot", "-1",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(section(&page, "answer").contains("pivot"));
    assert!(section(&page, "table").contains("<table id=\"T1\">"));
    assert!(!page.contains("<merror>"));
}

#[test]
fn handout_out_writes_the_page_whole_and_a_bad_flag_is_one_line() {
    let dir = common::scratch("handout");
    let file = dir.join("h.html");
    let mut args = SCENE.to_vec();
    args.extend(["--out", file.to_str().unwrap()]);
    let (code, stdout, err) = rodimpact(&args);
    assert_eq!((code, stdout.as_str()), (0, ""), "{err}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), page());
    // A missing directory: exit 2, one line, and nothing written anywhere.
    let missing = dir.join("none/h.html");
    let mut args = SCENE.to_vec();
    args.extend(["--out", missing.to_str().unwrap()]);
    let (code, _, err) = rodimpact(&args);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("error: out:") && err.lines().count() == 1,
        "{err}"
    );
    let mut left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    left.sort();
    assert_eq!(left, ["h.html"]);
    // A name that promises another format (a PDF) is refused before anything is written.
    let pdf = dir.join("h.pdf");
    let mut args = SCENE.to_vec();
    args.extend(["--out", pdf.to_str().unwrap()]);
    let (code, _, err) = rodimpact(&args);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("error: out: the file name must end in .html") && err.lines().count() == 1,
        "{err}"
    );
    assert!(!pdf.exists());
    // The scene flags' own errors, one line, exit 2.
    for (bad, field) in [
        (["--m", "x", "--a", "1/2"], "error: m:"),
        (["--m", "1", "--a", "5"], "error: a:"),
        (["--m", "1", "--e", "2"], "error: e:"),
    ] {
        let mut args = vec!["handout", "--M", "1"];
        args.extend(bad);
        let (code, stdout, err) = rodimpact(&args);
        assert_eq!(code, 2, "{bad:?}");
        assert!(stdout.is_empty());
        assert!(
            err.starts_with(field) && err.lines().count() == 1,
            "{bad:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
