//! `rodimpact plot`: the figures as SVG.

use super::{Failure, SceneFlags, parse_ratios};
use clap::Args;
use rodimpact::report;
use rodimpact::scene::RodInertia;
use std::path::PathBuf;

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub(crate) enum Figure {
    /// omega(a)/omega_max against a/l for several mass ratios, a* and the rod's end marked.
    Omega,
    /// a*/l against M/m (log axis), with the threshold and the light-rod asymptote.
    Optimum,
    /// The paper's missing Figure 1, drawn to scale for the scene flags (m = M = 1 by default).
    Figure1,
}

#[derive(Args, Debug)]
pub(crate) struct PlotArgs {
    /// Which figure.
    #[arg(value_enum)]
    pub(crate) figure: Figure,
    /// The SVG file to write (atomically).
    #[arg(long, value_name = "FILE.svg")]
    pub(crate) out: PathBuf,
    /// Mass ratios M/m of the curves of `omega` [default: 1/2,1,2,3,10].
    #[arg(long, value_name = "Q,Q,...")]
    pub(crate) ratios: Option<String>,
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
}

pub(crate) fn run_plot(args: &PlotArgs) -> Result<(), Failure> {
    let rod = match &args.scene.rod {
        Some(text) => RodInertia::parse(text)?,
        None => RodInertia::Uniform,
    };
    let svg = match args.figure {
        Figure::Omega => {
            let ratios = parse_ratios("ratios", args.ratios.as_deref().unwrap_or("1/2,1,2,3,10"))?;
            report::plot_omega(&ratios, &rod)?
        }
        Figure::Optimum => report::plot_optimum(&rod)?,
        Figure::Figure1 => {
            let mut input = args.scene.input();
            input.m.get_or_insert_with(|| "1".into());
            input.rod_mass.get_or_insert_with(|| "1".into());
            report::plot_figure1(&input.build()?)?
        }
    };
    report::write_atomic("out", &args.out, &svg)?;
    Ok(())
}
