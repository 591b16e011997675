//! The `rodimpact` command line: parse, call the library, print.
//!
//! Exit codes: 0 success, 1 a check or claim failed, 2 bad input or usage (one line on stderr
//! naming the field and the reason).
#![forbid(unsafe_code)]

mod commands;

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use clap::{Parser, Subcommand};
use commands::Failure;
use std::process::ExitCode;

/// Exact verifier for the impact of a projectile on a rod (Lemos, "Failure of intuition in
/// elementary rigid body dynamics").
#[derive(Parser, Debug)]
#[command(name = "rodimpact", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Solve one scene exactly: velocities, energies, residuals and the optimal impact point.
    Solve(Box<commands::solve::SolveArgs>),
    // About: the id ranges of the paper's claims and of those beyond it, from the registry.
    #[command(about = commands::claims::prove_about())]
    Prove(commands::claims::ProveArgs),
    /// The main job: verify every claim of the paper and print the report.
    Paper(commands::claims::PaperArgs),
    /// Exact tables of the paper's results (T1-T5) and of an oblique impact with friction (T6) in Markdown, LaTeX or CSV.
    Table(commands::table::TableArgs),
    /// Figures as SVG (and their data as CSV): omega against a, a* against M/m, Figure 1,
    /// velocities before/after, quantities and energy along the rod.
    Plot(Box<commands::plot::PlotArgs>),
    /// Any planar impact, with one or several contacts (bodies, shapes and contacts in a TOML
    /// file): one contact under Newton's, Poisson's and Stronge's laws side by side, several
    /// under the simultaneous, sequential and PGS models, exactly.
    Impact(Box<commands::impact::ImpactArgs>),
    /// Check published answers (printed numbers, fractions, formulas) against the exact ones.
    Check(Box<commands::check::CheckArgs>),
    /// The exact answer as formulas in the scene's free symbols (--M 2*m, --v0t v0t).
    ///
    /// v, V, omega, J, the energy lost, a*^2 and omega_max; with the oblique flags also vt, Vt,
    /// spin, Jt and mu*, split into stick and slide when the symbols leave the contact open.
    /// Any scene flag may be a symbol or an expression.
    Formula(Box<commands::formula::FormulaArgs>),
    /// An interactive page (one self-contained HTML file) on which a student predicts where to
    /// hit the rod, then finds the exact answer, the curve and the motion; or, with --scene
    /// tilted-rod, the three restitution laws side by side on a rod landing on a rough floor.
    #[command(
        after_help = "The scene flags are solve's, read the same way; the page shows the \
        scene in units m = l = v0 = 1 (M/m, a/l, r_G/l, p/l). A flag not given keeps the page's \
        own default, not solve's: M = m, a = l/2, e = 1, a uniform rod, no pivot, predict first, \
        the centre-of-mass view. The page's link takes the same keys: explore.html#M=1/2&a=1&e=1/2\
        &rod=dumbbell&pivot=-1&predict=0&frame=lab (docs/explore.md). --scene tilted-rod writes \
        the second page (a rod landing on a rough floor under Newton's, Poisson's and Stronge's \
        laws), preset by --tilt, --slip, --mu and --e. Both pages compute with rodimpact's \
        library compiled to WebAssembly, inside the file."
    )]
    Explore(Box<commands::explore::ExploreArgs>),
    /// One scene as a handout to print: the exact answer, the working, the formulas with their
    /// conditions, omega along the rod and a table, on one self-contained HTML page (2-5 A4
    /// pages).
    Handout(Box<commands::handout::HandoutArgs>),
    /// Float error against run time for every backend and formula on the stiff/extreme suite.
    Stability(commands::stability::StabilityArgs),
    /// Many scenes from a CSV file, exactly, streamed and in parallel; claimed v, V, omega,
    /// J and energies are checked, and a claimed state (an engine's output) is diagnosed.
    Batch(commands::batch::BatchArgs),
    /// A designed suite of scenes as a batch CSV (`--suite engines`: the engine test suite).
    Scenes(commands::scenes::ScenesArgs),
    /// The compliant-contact model integrated in time against the exact impulsive result.
    Simulate(Box<commands::simulate::SimulateArgs>),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => {
            use clap::error::ErrorKind as K;
            if matches!(
                err.kind(),
                K::DisplayHelp | K::DisplayVersion | K::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                if let Err(why) = err.print() {
                    commands::stdout_failed(&why);
                }
                return ExitCode::from(
                    if err.kind() == K::DisplayHelpOnMissingArgumentOrSubcommand {
                        2
                    } else {
                        0
                    },
                );
            }
            let line = rodimpact::echo::one_line(&usage_line(&err.to_string()));
            commands::print_err(&format!("{line} (try --help)\n"));
            return ExitCode::from(2);
        }
    };
    if let Err(e) = rodimpact::io::remove_temporaries_on_signals() {
        commands::print_err(&format!("error: {e}\n"));
        return ExitCode::from(2);
    }
    let result = match &cli.command {
        Command::Solve(args) => commands::solve::run_solve(args),
        Command::Prove(args) => commands::claims::run_prove(args),
        Command::Paper(args) => commands::claims::run_paper(args),
        Command::Table(args) => commands::table::run_table(args),
        Command::Plot(args) => commands::plot::run_plot(args),
        Command::Check(args) => commands::check::run_check(args),
        Command::Impact(args) => commands::impact::run_impact(args),
        Command::Formula(args) => commands::formula::run_formula(args),
        Command::Explore(args) => commands::explore::run_explore(args),
        Command::Handout(args) => commands::handout::run_handout(args),
        Command::Stability(args) => commands::stability::run_stability(args),
        Command::Batch(args) => commands::batch::run_batch(args),
        Command::Scenes(args) => commands::scenes::run_scenes(args),
        Command::Simulate(args) => commands::simulate::run_simulate(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Check) => ExitCode::from(1),
        Err(Failure::Input(e)) => {
            commands::print_err(&format!("error: {e}\n"));
            ExitCode::from(2)
        }
    }
}

/// A clap error as one line: its first paragraph (clap lists missing arguments on the lines
/// after "the following required arguments were not provided:", and those name the field),
/// then its tips ("a similar subcommand exists: 'solve'"), joined by "; ".
fn usage_line(rendered: &str) -> String {
    let words: Vec<&str> = rendered
        .lines()
        .take_while(|line| !line.trim().is_empty())
        .map(str::trim)
        .collect();
    let mut line = if words.is_empty() {
        "error: usage error".to_string()
    } else {
        words.join(" ")
    };
    for tip in rendered
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("tip:"))
    {
        line.push_str("; ");
        line.push_str(tip);
    }
    line
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;
    use commands::parse_digits;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    /// Regression (bad-input matrix): a missing required argument printed only
    /// "error: the following required arguments were not provided:" because clap lists the
    /// arguments on the next lines and only the first line was kept; the field went unnamed.
    #[test]
    fn a_missing_argument_is_named_on_the_one_line() {
        let err = Cli::try_parse_from(["rodimpact", "plot", "omega"]).unwrap_err();
        let line = usage_line(&err.to_string());
        assert!(
            line.contains("not provided: --out <FILE.svg|FILE.png>"),
            "{line}"
        );
        assert!(!line.contains('\n'));
    }

    /// Regression (NEWCOMER #25): `rodimpact slove` printed only "unrecognized subcommand
    /// 'slove'": the one-line rewrite kept the first paragraph and dropped clap's tip naming
    /// the subcommand the user meant.
    #[test]
    fn a_typo_keeps_clap_tip_on_the_one_line() {
        let err = Cli::try_parse_from(["rodimpact", "slove"]).unwrap_err();
        let line = usage_line(&err.to_string());
        assert!(
            line.starts_with("error: unrecognized subcommand 'slove'"),
            "{line}"
        );
        assert!(
            line.contains("; tip: ") && line.contains("'solve'"),
            "{line}"
        );
        assert!(!line.contains('\n'));
        let err = Cli::try_parse_from(["rodimpact", "solve", "--mm", "1"]).unwrap_err();
        assert!(usage_line(&err.to_string()).contains("a similar argument exists: '--m'"));
    }

    #[test]
    fn digits_are_bounded() {
        assert_eq!(parse_digits(None, 30).unwrap(), 30);
        assert_eq!(parse_digits(Some("12"), 30).unwrap(), 12);
        assert!(parse_digits(Some("0"), 30).is_err());
        assert!(parse_digits(Some("100001"), 30).is_err());
        assert!(parse_digits(Some("x"), 30).is_err());
    }
}
