//! `rodimpact solve`: one scene, exactly.

use super::{Failure, SceneFlags, parse_digits, print_out};
use clap::Args;
use rodimpact::report::Solution;

#[derive(Args, Debug)]
pub(crate) struct SolveArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// Print one JSON object (the contract of DESIGN.md §3) instead of the text report.
    #[arg(long)]
    pub(crate) json: bool,
    /// Significant digits of the printed decimals and of the a* bounds [default: 30 in JSON,
    /// 15 in the text report].
    #[arg(long, value_name = "N")]
    pub(crate) digits: Option<String>,
}

pub(crate) fn run_solve(args: &SolveArgs) -> Result<(), Failure> {
    let scene = args.scene.input().build()?;
    let solution = Solution::of(&scene);
    if args.json {
        let digits = parse_digits(args.digits.as_deref(), 30)?;
        let json = solution.to_json(digits);
        let json = serde_json::to_string_pretty(&json).expect("JSON of strings and bools");
        print_out(&format!("{json}\n"));
    } else {
        let digits = parse_digits(args.digits.as_deref(), 15)?;
        print_out(&solution.to_text(digits));
    }
    if solution.outcome.residuals.all_zero() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
