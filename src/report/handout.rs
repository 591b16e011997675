//! `rodimpact handout`: one scene for a class on one self-contained page that prints on a few
//! A4 pages. Nothing here is new physics or a new rendering: the page puts together what the
//! other commands already print, each from its own renderer: the scene and its exact answer
//! (`solve`), the working (`solve --explain`), the formulas with their conditions (`formula`,
//! in MathML as on the paper page), the curve omega(a) with a* and the end (`plot omega`) and
//! the velocities along the rod (`table --only T2`, or T1 for a rod on a pivot).

use super::mathml::escape;
use super::page::{Page, document, inline_svg};
use super::paper_html::{formula_table, wide};
use super::{ExplainFormat, explain, markup, omega_figure, solution_html};
use crate::error::Error;
use crate::scene::{RodInertia, Scene, Support};
use crate::solve::Answer;
use crate::solve::working::Working;
use crate::tables::{Table, TableOptions, t1, t2};
use crate::textbook::formula::Formulas;
use std::fmt::Write as _;

/// The handout's style: the paper page's type, and the print rules of a handout (A4, no break
/// inside a figure, a table or a step's equations).
const STYLE: &str = include_str!("handout.css");

/// The significant digits of the decimals beside the exact answer (a handout's precision).
const DIGITS: usize = 6;

/// The handout for `answer`'s scene: its exact answer, the `working`, `formulas` (the scene's kind in
/// symbols, as `rodimpact formula` gives them), omega against the impact point, and the
/// velocities along the rod (T2; T1, a* against M/m, for a rod on a pivot).
///
/// # Errors
/// A scene the figure or the table cannot draw (an oblique scene: the working is written for
/// the paper's scene).
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::{Scene, SceneInput}, textbook::formula::formulas};
/// use rodimpact::solve::{Answer, working::Working};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let (answer, working) = (Answer::of(&s), Working::of(&s));
/// let page = rodimpact::report::handout_html(&answer, &working, &formulas(&SceneInput::default())?)?;
/// assert!(page.starts_with("<!DOCTYPE html>") && !page.contains("<script"));
/// assert!(page.contains("<td>12/11 rad/s</td>") && page.contains("<svg role=\"img\""));
/// assert!(page.contains("<table id=\"T2\">") && !page.contains("https://"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn handout_html(
    answer: &Answer,
    working: &Working,
    formulas: &Formulas,
) -> Result<String, Error> {
    let scene = &answer.scene;
    if scene.oblique().is_some() {
        return Err(Error::new(
            "scene",
            crate::error::ErrorKind::Conflict(
                "the handout is written for the paper's scene: not with oblique flags".into(),
            ),
        ));
    }
    let figure = omega_figure(std::slice::from_ref(scene))?;
    let table = table(scene)?;
    let mut body = String::from(
        "<header>\n<h1>A rod struck by a projectile: where should it be hit?</h1>\n\
         <p class=\"lead\">A projectile of mass <i>m</i> and speed <i>v</i><sub>0</sub> strikes \
         a rod of mass <i>M</i> and length 2<i>l</i> at the distance <i>a</i> from its centre. \
         How fast does the rod spin after the impact, and where should it be hit to spin it \
         fastest? Hitting the end is not always best: for a free uniform rod with \
         <i>M</i> &lt; 2<i>m</i> the fastest spin comes from an interior point \
         <i>a</i><sup>*</sup>.</p>\n</header>\n<main>\n",
    );
    let _ = write!(
        body,
        "<section id=\"answer\">\n<h2>The scene and its exact answer</h2>\n\
         {}</section>\n",
        solution_html(answer, DIGITS)
    );
    let _ = write!(
        body,
        "<section id=\"working\">\n<h2>The working</h2>\n<div class=\"working\">\n{}</div>\n\
         </section>\n",
        explain(working, ExplainFormat::Html)
    );
    body.push_str(&formula_section(formulas));
    let caption = "The rod’s angular velocity ω after the impact against the impact point a, \
                   for this scene; a* and the end of the rod marked.";
    let _ = write!(
        body,
        "<section id=\"figure\">\n<h2>The spin along the rod</h2>\n<figure>\n{}\
         <figcaption><b>Figure.</b> {}</figcaption>\n</figure>\n</section>\n",
        inline_svg(&figure.svg, caption),
        escape(caption)
    );
    let _ = write!(
        body,
        "<section id=\"table\">\n<h2>The table</h2>\n{}</section>\n</main>\n",
        wide(&format!("Table {}", table.id), &table.html())
    );
    let _ = writeln!(
        body,
        "<footer><p>Written by <code>rodimpact handout</code> (rodimpact {}), exactly: the \
         answer is <code>rodimpact solve</code>’s, the working <code>solve --explain</code>’s, \
         the formulas <code>rodimpact formula</code>’s, the figure <code>plot omega</code>’s and \
         the table <code>rodimpact table --only {}</code>’s.</p></footer>",
        env!("CARGO_PKG_VERSION"),
        table.id
    );
    Ok(document(&Page {
        title: "Handout: a rod struck by a projectile",
        style: STYLE,
        body: &body,
        script: "",
    }))
}

/// The formulas in the scene's free symbols, with the defaults they rest on.
fn formula_section(f: &Formulas) -> String {
    let mut out = String::from(
        "<section id=\"formulas\">\n<h2>The formulas</h2>\n<p>The answer for any scene of \
         this kind, as <code>rodimpact formula</code> gives it",
    );
    if !f.defaults.is_empty() {
        let _ = write!(
            out,
            " ({})",
            escape(&markup::ascii_math(&f.defaults.join("; ")))
        );
    }
    let _ = writeln!(
        out,
        ", in the symbols {}; the scene’s numbers put into them give the answer above.</p>",
        escape(&f.free.join(", "))
    );
    out.push_str(&formula_table(f));
    out.push_str("</section>\n");
    out
}

/// The table of the scene in the tables' units (m = l = v0 = 1): the velocities along the rod
/// at the scene's mass ratio (T2), or for a rod on a pivot where it spins fastest against the
/// mass ratio, the scene's included (T1).
fn table(scene: &Scene) -> Result<Table, Error> {
    let l = scene.half_length();
    let ratio = scene.rod_mass() / scene.m();
    let rod = match scene.rod() {
        RodInertia::Gyration(r) => RodInertia::Gyration(r / l),
        RodInertia::Moment(i) => RodInertia::Moment(i / (scene.rod_mass() * l * l)),
        other => other.clone(),
    };
    let mut opts = TableOptions {
        ratio: ratio.clone(),
        rod,
        e: scene.e().clone(),
        ..TableOptions::default()
    };
    match scene.support() {
        Support::Free => t2(&opts),
        Support::Pivot(p) => {
            opts.pivot = Some(p / l);
            if let Err(at) = opts.ratios.binary_search(&ratio) {
                opts.ratios.insert(at, ratio);
            }
            t1(&opts)
        }
    }
}
