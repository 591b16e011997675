//! `rodimpact explore`: the interactive page, optionally opening on a scene.

use super::{Failure, SceneFlags, print_out};
use clap::{Args, ValueEnum};
use rodimpact::io::write_atomic;
use rodimpact::report::explore::{Frame, Preset, explore_html};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ExploreArgs {
    /// Write the page to FILE.html, whole or not at all (without it the page goes to standard
    /// output). It opens from disk in a browser and needs no network.
    #[arg(long, value_name = "FILE.html")]
    pub(crate) out: Option<PathBuf>,
    // The scene the page opens on, with solve's flags (their help is solve's: the subcommand's
    // after_help says how the page reads them).
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// Open with "predict first" on: the answer hidden until the student guesses (the default).
    #[arg(long, overrides_with = "no_predict")]
    pub(crate) predict: bool,
    /// Open with "predict first" off: the answer shown at once.
    #[arg(long, overrides_with = "predict")]
    pub(crate) no_predict: bool,
    /// How the animation is seen: moving with the centre of mass of puck and rod [the page's
    /// default], or from the table (a rod on a pivot is always seen from the table).
    #[arg(long, value_enum, value_name = "VIEW")]
    pub(crate) frame: Option<FrameArg>,
}

/// The views of `--frame`.
#[derive(ValueEnum, Debug, Clone, Copy)]
pub(crate) enum FrameArg {
    /// Moving with the centre of mass.
    CentreOfMass,
    /// From the table (the lab frame).
    Lab,
}

pub(crate) fn run_explore(args: &ExploreArgs) -> Result<(), Failure> {
    let predict = match (args.predict, args.no_predict) {
        (true, _) => Some(true),
        (_, true) => Some(false),
        _ => None,
    };
    let frame = args.frame.map(|f| match f {
        FrameArg::CentreOfMass => Frame::CentreOfMass,
        FrameArg::Lab => Frame::Lab,
    });
    let preset = Preset::of_scene(&args.scene.input(), predict, frame)?;
    let page = explore_html(&preset)?;
    match &args.out {
        Some(file) => write_atomic("out", file, &page)?,
        None => print_out(&page),
    }
    Ok(())
}
