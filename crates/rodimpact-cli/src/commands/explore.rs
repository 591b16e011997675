//! `rodimpact explore`: the interactive page, optionally opening on a scene.

use super::{Failure, ObliqueFlags, SceneFlags, print_out};
use clap::{Args, ValueEnum};
use rodimpact::app::pages::{self, Frame, Preset, TiltedPreset, explore_page};
use rodimpact::io::write_atomic;
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
    /// Which page: the paper's rod struck by a puck [default], or a rod tilted above a rough
    /// floor under Newton's, Poisson's and Stronge's laws (with --tilt, --slip, --mu, --e).
    #[arg(
        long = "scene",
        value_enum,
        value_name = "SCENE",
        default_value = "paper"
    )]
    pub(crate) scene_page: ScenePage,
    /// tilted-rod: the tilt theta of the rod above the floor, as tan(theta/2) in (0, 1)
    /// [default 1/2: cos = 3/5].
    #[arg(long, value_name = "T")]
    pub(crate) tilt: Option<String>,
    /// tilted-rod: the rod's sideways velocity before the impact (it falls at 1) [default 1].
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub(crate) slip: Option<String>,
    // The oblique tab (--v0t, --mu, --radius, --spin: solve's flags); --mu also the tilted rod's
    // friction at the floor [default 1/3].
    #[command(flatten)]
    pub(crate) oblique: ObliqueFlags,
}

/// The WebAssembly module (zlib-compressed, in base64) that `build.rs` built for the pages:
/// empty when this build has none (without the feature `pages`, without the wasm32 target, or
/// with `RODIMPACT_PAGES_WASM=none`).
const PAGES_MODULE: &str = include_str!(concat!(env!("OUT_DIR"), "/pages.wasm.b64"));

/// The pages of `--scene`.
#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ScenePage {
    /// The paper's scene: where to strike a rod to spin it fastest.
    Paper,
    /// A tilted rod landing on a rough floor: where Newton's law creates energy.
    TiltedRod,
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
    let page = match args.scene_page {
        ScenePage::Paper => paper_page(args)?,
        ScenePage::TiltedRod => tilted_page(args)?,
    };
    match &args.out {
        Some(file) => write_atomic("out", file, &page)?,
        None => print_out(&page),
    }
    Ok(())
}

/// The tilted-rod page: --tilt, --slip, --mu and --e; the paper's scene flags are refused.
fn tilted_page(args: &ExploreArgs) -> Result<String, Failure> {
    let input = args.oblique.input(&args.scene);
    let foreign = input
        .inputs()
        .find(|(key, value)| value.is_some() && !["e", "mu"].contains(&key.name))
        .map(|(key, _)| key.name)
        .or(args.frame.map(|_| "frame"))
        .or((args.predict || args.no_predict).then_some("predict"));
    if let Some(flag) = foreign {
        return Err(rodimpact::Error::new(
            flag,
            rodimpact::ErrorKind::Invalid(
                "not a setting of the tilted-rod page, which takes --tilt, --slip, --mu and --e"
                    .into(),
            ),
        )
        .into());
    }
    let preset = TiltedPreset::of(
        args.tilt.as_deref(),
        args.slip.as_deref(),
        input.mu.as_deref(),
        input.e.as_deref(),
    )?;
    Ok(pages::tilted_page(&preset, PAGES_MODULE)?)
}

/// The paper's page, preset by the scene flags, --predict and --frame.
fn paper_page(args: &ExploreArgs) -> Result<String, Failure> {
    if let Some(flag) = [("tilt", &args.tilt), ("slip", &args.slip)]
        .into_iter()
        .find_map(|(flag, value)| value.as_ref().map(|_| flag))
    {
        return Err(rodimpact::Error::new(
            flag,
            rodimpact::ErrorKind::Invalid(
                "a setting of the tilted-rod page (--scene tilted-rod)".into(),
            ),
        )
        .into());
    }
    let predict = match (args.predict, args.no_predict) {
        (true, _) => Some(true),
        (_, true) => Some(false),
        _ => None,
    };
    let frame = args.frame.map(|f| match f {
        FrameArg::CentreOfMass => Frame::CentreOfMass,
        FrameArg::Lab => Frame::Lab,
    });
    let preset = Preset::of_scene(&args.oblique.input(&args.scene), predict, frame)?;
    Ok(explore_page(&preset, PAGES_MODULE)?)
}
