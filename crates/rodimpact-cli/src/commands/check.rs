//! `rodimpact check`: published answers against the exact ones.

use super::{Failure, ObliqueFlags, SceneFlags, print_out};
use clap::Args;
use rodimpact::report::{check_json, check_summary, check_table, problems_json, problems_text};
use rodimpact::textbook::check_claims;
use rodimpact::textbook::problems::{check_problems, parse_problems, read_problem_file};
use rodimpact::{Error, ErrorKind};
use std::path::PathBuf;

#[derive(Args, Debug)]
// In check a quantity not given stays a free symbol when the claims are formulas (solve's
// defaults hold for numeric claims), so --a's help says both.
#[command(mut_arg("a", |a| a.help(
    "Signed impact distance a from the rod's centre, |a| <= l, or a* (-a*) to strike exactly at the optimum [default: l, the end, for numeric claims; a free symbol a for formulas]"
)))]
pub(crate) struct CheckArgs {
    /// A problem collection (TOML) to check instead of one scene.
    #[arg(value_name = "PROBLEMS.toml")]
    pub(crate) file: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    #[command(flatten)]
    pub(crate) oblique: ObliqueFlags,
    /// A claimed answer NAME=VALUE: NAME one of v, V, V_cm, omega, a_star, omega_max,
    /// energy_before, energy_after, energy_lost, pivot_impulse, impulse, and for an oblique
    /// scene vt, Vt, spin, tangential_impulse; VALUE a number as
    /// printed (with an optional unit), a fraction, or a formula in m M l L a d v0 e p I r.
    /// With formulas, a scene quantity not given is a free symbol, except e (1, elastic) and
    /// the rod (uniform), as in solve.
    #[arg(long, value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub(crate) claim: Vec<String>,
    /// Significant figures to use for every printed claim, instead of the inferred ones.
    #[arg(long, value_name = "N")]
    pub(crate) sig: Option<u32>,
    /// Print JSON instead of the table.
    #[arg(long)]
    pub(crate) json: bool,
}

pub(crate) fn run_check(args: &CheckArgs) -> Result<(), Failure> {
    let all_agree = match &args.file {
        Some(path) => check_file(args, path)?,
        None => check_flags(args)?,
    };
    if all_agree {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

fn check_file(args: &CheckArgs, path: &std::path::Path) -> Result<bool, Error> {
    let label = rodimpact::echo::echo_path(path);
    let s = args.oblique.input(&args.scene);
    let scene_given = [
        &s.m,
        &s.rod_mass,
        &s.l,
        &s.length,
        &s.a,
        &s.from_end,
        &s.v0,
        &s.rod,
        &s.e,
        &s.pivot,
        &s.v0t,
        &s.mu,
        &s.radius,
        &s.spin,
        &s.rod_v,
        &s.rod_vt,
        &s.rod_omega,
    ]
    .iter()
    .any(|f| f.is_some());
    if !args.claim.is_empty() || scene_given {
        return Err(stray_argument(path));
    }
    let text = read_problem_file(&label, path)?;
    let problems = parse_problems(&label, &text)?;
    let checks = check_problems(&label, &problems, args.sig)?;
    if args.json {
        print_out(&format!("{}\n", pretty(&problems_json(&checks))));
    } else {
        print_out(&problems_text(&checks));
    }
    Ok(checks.iter().all(|p| p.check.all_agree()))
}

/// The error for a positional argument next to scene flags or claims: a problem file cannot be
/// combined with them, and a word that is not a file is most often a unit separated from its
/// number (`--m 10 g`).
fn stray_argument(path: &std::path::Path) -> Error {
    let word = path.display().to_string();
    let shown: String = word.chars().take(40).collect();
    if path.is_file() {
        return Error::new(
            "check",
            ErrorKind::Conflict(format!(
                "give either a problem file ('{shown}') or scene flags with --claim, not both"
            )),
        );
    }
    let unit = rodimpact::units::find_unit(word.trim()).is_some();
    let why = if unit {
        format!(
            "unexpected argument '{shown}': a unit goes with its number in one argument (--m \"10 {shown}\" or --m 10{shown})"
        )
    } else {
        format!(
            "unexpected argument '{shown}': not a problem file; with scene flags, every value follows its flag (--m 2), and a value with spaces is quoted"
        )
    };
    Error::new("check", ErrorKind::Invalid(why))
}

fn check_flags(args: &CheckArgs) -> Result<bool, Error> {
    let check = check_claims(&args.oblique.input(&args.scene), &args.claim, args.sig)?;
    if args.json {
        print_out(&format!("{}\n", pretty(&check_json(&check))));
    } else {
        print_out(&format!(
            "{}{}\n",
            check_table(&check),
            check_summary(&check)
        ));
    }
    Ok(check.all_agree())
}

fn pretty(v: &serde_json::Value) -> String {
    serde_json::to_string_pretty(v).expect("JSON of strings and numbers")
}
