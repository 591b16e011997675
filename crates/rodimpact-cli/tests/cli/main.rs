//! The command-line tool run as its users run it: every subcommand's contract, bad input, output
//! files and signals, the engine fixtures. One test binary (the library and the tool are built once
//! for all of these); each module was a test file of its own.

#[path = "../common/mod.rs"]
mod common;

/// The repository's root (this package lives in `crates/rodimpact-cli/`): the examples, the
/// reference data and the documentation the tests read, and the binary's working directory.
pub const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

mod backend_reliability;
mod bad_input;
mod batch;
mod batch_f64;
mod check;
mod claims;
mod console;
mod engine_laws;
mod engines;
mod explain;
mod explore;
mod formula;
mod handout;
mod impact;
mod impact_limits;
mod no_half_written;
mod oblique;
mod output_dir;
mod paper_equations;
mod paper_html;
mod plot;
mod prove;
mod simulate;
mod solve;
mod stability;
mod table;
mod units;
