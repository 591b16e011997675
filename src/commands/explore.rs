//! `rodimpact explore`: the interactive page.

use super::{Failure, print_out};
use clap::Args;
use rodimpact::io::write_atomic;
use rodimpact::report::explore::explore_html;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ExploreArgs {
    /// Write the page to FILE.html, whole or not at all (without it the page goes to standard
    /// output). It opens from disk in a browser and needs no network.
    #[arg(long, value_name = "FILE.html")]
    pub(crate) out: Option<PathBuf>,
}

pub(crate) fn run_explore(args: &ExploreArgs) -> Result<(), Failure> {
    let page = explore_html()?;
    match &args.out {
        Some(file) => write_atomic("out", file, &page)?,
        None => print_out(&page),
    }
    Ok(())
}
