//! `rodimpact handout`: one scene for a class, on one page to print or hand out.

use super::plot::check_extension;
use super::{Failure, SceneFlags, print_out};
use clap::Args;
use rodimpact::io::write_atomic;
use rodimpact::report::handout_html;
use rodimpact::scene::{RodInertia, SceneInput};
use rodimpact::solve::{Answer, working::Working};
use rodimpact::textbook::formula::formulas;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct HandoutArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// Write the page to FILE.html, whole or not at all (without it the page goes to standard
    /// output). It opens from disk in a browser, needs no network, and prints on 2-5 A4 pages.
    #[arg(long, value_name = "FILE.html")]
    pub(crate) out: Option<PathBuf>,
}

pub(crate) fn run_handout(args: &HandoutArgs) -> Result<(), Failure> {
    if let Some(file) = &args.out {
        check_extension(
            "out",
            file,
            "html",
            " (handout writes HTML; a browser prints it to PDF, 2-5 A4 pages)",
        )?;
    }
    let given = args.scene.input();
    let scene = given.build()?;
    // The formulas of a scene of this kind: the rod, the law and the pivot as given, m, M, a
    // and v0 as symbols; l too, unless a number in metres (a pivot, r_G or I) needs it.
    let lengths_given = given.pivot.is_some()
        || matches!(scene.rod(), RodInertia::Gyration(_) | RodInertia::Moment(_));
    let symbols = SceneInput {
        rod: given.rod.clone(),
        e: given.e.clone(),
        pivot: given.pivot.clone(),
        l: lengths_given.then(|| scene.half_length().to_string()),
        ..SceneInput::default()
    };
    let (answer, working) = (Answer::of(&scene), Working::of(&scene));
    let page = handout_html(&answer, &working, &formulas(&symbols)?)?;
    match &args.out {
        Some(file) => write_atomic("out", file, &page)?,
        None => print_out(&page),
    }
    Ok(())
}
