//! `rodimpact stability`: every backend and formula on the stiff/extreme suite and a seeded
//! sweep, error in units of cond u against run time.

use super::{Failure, print_out};
use clap::{Args, ValueEnum};
use rodimpact::io::write_atomic;
use rodimpact::report::{plot_stability, stability_json, stability_markdown};
use rodimpact::stability::compare_backends;
use std::path::PathBuf;

/// Sweep scenes per format.
const SWEEP: usize = 150;

#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum StabilityFormat {
    /// A Markdown table.
    #[value(alias = "markdown")]
    Md,
    /// A JSON list of rows.
    Json,
}

#[derive(Args, Debug)]
pub(crate) struct StabilityArgs {
    /// Output format.
    #[arg(long, value_enum, default_value = "md")]
    pub(crate) format: StabilityFormat,
    /// Also write the error-against-time plot (SVG) to this file.
    #[arg(long, value_name = "FILE.svg")]
    pub(crate) plot: Option<PathBuf>,
}

pub(crate) fn run_stability(args: &StabilityArgs) -> Result<(), Failure> {
    if let Some(path) = &args.plot {
        super::plot::check_extension("plot", path, "svg", "")?;
    }
    let rows = compare_backends(SWEEP);
    if let Some(path) = &args.plot {
        write_atomic("plot", path, &plot_stability(&rows)?)?;
    }
    match args.format {
        StabilityFormat::Md => print_out(&stability_markdown(&rows)),
        StabilityFormat::Json => print_out(&format!(
            "{}\n",
            serde_json::to_string_pretty(&stability_json(&rows))
                .expect("JSON of numbers and strings")
        )),
    }
    Ok(())
}
