//! `rodimpact scenes --suite engines [--out FILE]`: a designed suite of scenes as a batch CSV.

use super::{Failure, print_out};
use clap::{Args, ValueEnum};
use rodimpact::io::write_atomic;
use rodimpact::suite::{engine_suite, suite_csv};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ScenesArgs {
    /// Which suite: `engines`, the scenes that discriminate physics engines (docs/engines.md).
    #[arg(long, value_enum)]
    pub(crate) suite: SuiteArg,
    /// Write to FILE (atomically) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(crate) enum SuiteArg {
    Engines,
}

pub(crate) fn run_scenes(args: &ScenesArgs) -> Result<(), Failure> {
    let text = match args.suite {
        SuiteArg::Engines => suite_csv(&engine_suite()),
    };
    match &args.out {
        Some(path) => write_atomic("out", path, &text)?,
        None => print_out(&text),
    }
    Ok(())
}
