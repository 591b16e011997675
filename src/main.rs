//! The `rodimpact` command line: parse, call the library, print.
//!
//! Exit codes: 0 success, 1 a check or claim failed, 2 bad input or usage (one line on stderr
//! naming the field and the reason).

use clap::{Args, Parser, Subcommand};
use rodimpact::claims::{self, Decided, Paper};
use rodimpact::report::{self, Format, Solution, TableOptions};
use rodimpact::scene::{RodInertia, SceneInput, parse_field};
use rodimpact::{Error, ErrorKind};
use std::path::{Path, PathBuf};
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
    Solve(Box<SolveArgs>),
    /// Decide claims of the paper (C1-C46) and beyond (X1-X26) by exact computation.
    Prove(ProveArgs),
    /// The main job: verify every claim of the paper and print the report.
    Paper(PaperArgs),
    /// Exact tables of the paper's results (T1-T5) in Markdown, LaTeX or CSV.
    Table(TableArgs),
    /// Figures as SVG: omega against a, a* against M/m, or the paper's Figure 1.
    Plot(Box<PlotArgs>),
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum Figure {
    /// omega(a)/omega_max against a/l for several mass ratios, a* and the rod's end marked.
    Omega,
    /// a*/l against M/m (log axis), with the threshold and the light-rod asymptote.
    Optimum,
    /// The paper's missing Figure 1, drawn to scale for the scene flags (m = M = 1 by default).
    Figure1,
}

#[derive(Args, Debug)]
struct PlotArgs {
    /// Which figure.
    #[arg(value_enum)]
    figure: Figure,
    /// The SVG file to write (atomically).
    #[arg(long, value_name = "FILE.svg")]
    out: PathBuf,
    /// Mass ratios M/m of the curves of `omega` [default: 1/2,1,2,3,10].
    #[arg(long, value_name = "Q,Q,...")]
    ratios: Option<String>,
    #[command(flatten)]
    scene: SceneFlags,
}

#[derive(Args, Debug)]
struct TableArgs {
    /// Mass ratios M/m for T1 and T5, comma separated [default: 1/100,1/10,1/2,1,3/2,2,3,10,100].
    #[arg(long, value_name = "Q,Q,...")]
    ratios: Option<String>,
    /// The mass ratio M/m of T2 and T3 [default: 1].
    #[arg(long, value_name = "Q")]
    ratio: Option<String>,
    /// Mass distribution, in units of l and M l^2: uniform, dumbbell, rg=R, I=X [default: uniform].
    #[arg(long, value_name = "KIND")]
    rod: Option<String>,
    /// Coefficient of restitution for T1, T2 and T5 [default: 1].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    e: Option<String>,
    /// A pivot at p (in units of l) for T1.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pivot: Option<String>,
    /// Output format: md, latex or csv [default: md].
    #[arg(long, value_name = "FORMAT", default_value = "md")]
    format: String,
    /// Only these tables (T1-T5), comma separated [default: all].
    #[arg(long, value_name = "T1,T2,...")]
    only: Option<String>,
    /// Write to FILE (atomically) instead of standard output.
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
}

#[derive(Args, Debug)]
struct ProveArgs {
    /// Claim ids (C1-C46, X1-X26) [default: all].
    #[arg(value_name = "ID")]
    ids: Vec<String>,
    /// Write one Markdown certificate per claim into DIR (and the index README.md when all
    /// claims are decided).
    #[arg(long, value_name = "DIR")]
    write: Option<PathBuf>,
    /// Print a JSON list instead of one line per claim.
    #[arg(long)]
    json: bool,
}

#[derive(Args, Debug)]
struct PaperArgs {
    /// Also write the report as Markdown (report.md) with every certificate into DIR.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

/// Scene flags shared by the commands that take one scene. Numbers are exact: "2", "0.25",
/// "3/7", "1.5e-3", "75/9.8".
#[derive(Args, Debug)]
struct SceneFlags {
    /// Projectile mass m (> 0).
    #[arg(long = "m", value_name = "Q", allow_hyphen_values = true)]
    m: Option<String>,
    /// Rod mass M (> 0).
    #[arg(long = "M", value_name = "Q", allow_hyphen_values = true)]
    rod_mass: Option<String>,
    /// Half-length l of the rod (the rod is 2l long) [default: 1].
    #[arg(long = "l", value_name = "Q", allow_hyphen_values = true)]
    l: Option<String>,
    /// Full length L = 2l of the rod, instead of --l.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    length: Option<String>,
    /// Signed impact distance a from the rod's centre, |a| <= l [default: l, the end].
    #[arg(long = "a", value_name = "Q", allow_hyphen_values = true)]
    a: Option<String>,
    /// Impact distance d from the end, instead of --a (a = l - d).
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    from_end: Option<String>,
    /// Projectile speed v0 (> 0) [default: 1].
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    v0: Option<String>,
    /// Mass distribution: uniform, dumbbell, rg=<radius of gyration> or I=<moment of inertia>
    /// [default: uniform].
    #[arg(long, value_name = "KIND")]
    rod: Option<String>,
    /// Coefficient of restitution, 0 <= e <= 1 [default: 1].
    #[arg(long, value_name = "Q", allow_hyphen_values = true, group = "law")]
    e: Option<String>,
    /// Elastic impact, e = 1 (the default).
    #[arg(long, group = "law")]
    elastic: bool,
    /// Totally inelastic impact, e = 0: the projectile sticks to the rod.
    #[arg(long, group = "law")]
    inelastic: bool,
    /// Put the rod on a fixed frictionless pivot at signed position p, |p| <= l.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pivot: Option<String>,
}

impl SceneFlags {
    fn input(&self) -> SceneInput {
        let e = if self.elastic {
            Some("1".to_string())
        } else if self.inelastic {
            Some("0".to_string())
        } else {
            self.e.clone()
        };
        SceneInput {
            m: self.m.clone(),
            rod_mass: self.rod_mass.clone(),
            l: self.l.clone(),
            length: self.length.clone(),
            a: self.a.clone(),
            from_end: self.from_end.clone(),
            v0: self.v0.clone(),
            rod: self.rod.clone(),
            e,
            pivot: self.pivot.clone(),
        }
    }
}

#[derive(Args, Debug)]
struct SolveArgs {
    #[command(flatten)]
    scene: SceneFlags,
    /// Print one JSON object (the contract of DESIGN.md §3) instead of the text report.
    #[arg(long)]
    json: bool,
    /// Significant digits of the printed decimals and of the a* bounds [default: 30 in JSON,
    /// 15 in the text report].
    #[arg(long, value_name = "N")]
    digits: Option<String>,
}

/// How a command ended, mapped to the process exit code.
enum Failure {
    /// Bad input: exit 2 with one line on stderr.
    Input(Error),
    /// A check failed: exit 1 (the report was already printed).
    Check,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Input(e)
    }
}

/// The largest `--digits` accepted: beyond it the decimals are refused, not computed for ever.
const MAX_DIGITS_OUT: usize = 10_000;

fn parse_digits(text: Option<&str>, default: usize) -> Result<usize, Error> {
    let Some(text) = text else {
        return Ok(default);
    };
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=MAX_DIGITS_OUT).contains(&n) => Ok(n),
        _ => Err(Error::out_of_range(
            "digits",
            format!(
                "must be a whole number from 1 to {MAX_DIGITS_OUT}, got '{}'",
                text.chars().take(40).collect::<String>()
            ),
        )),
    }
}

fn run_solve(args: &SolveArgs) -> Result<(), Failure> {
    let scene = args.scene.input().build()?;
    let solution = Solution::of(&scene);
    if args.json {
        let digits = parse_digits(args.digits.as_deref(), 30)?;
        let json = solution.to_json(digits);
        println!(
            "{}",
            serde_json::to_string_pretty(&json).expect("JSON of strings and bools")
        );
    } else {
        let digits = parse_digits(args.digits.as_deref(), 15)?;
        print!("{}", solution.to_text(digits));
    }
    if solution.outcome.residuals.all_zero() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// The registered entries for the requested ids (all of them when none is given).
fn select_claims(ids: &[String]) -> Result<Vec<claims::Entry>, Error> {
    let registry = claims::registry();
    if ids.is_empty() {
        return Ok(registry);
    }
    ids.iter()
        .map(|id| {
            registry
                .iter()
                .find(|e| e.id.eq_ignore_ascii_case(id.trim()))
                .copied()
                .ok_or_else(|| {
                    Error::new(
                        "id",
                        ErrorKind::Invalid(format!(
                            "unknown claim '{}'; the ids are C1-C46 and X1-X26",
                            id.chars().take(40).collect::<String>()
                        )),
                    )
                })
        })
        .collect()
}

/// Writes one certificate per decided claim into `dir`, and the index when `complete`.
fn write_certificates(
    field: &str,
    dir: &Path,
    decided: &[Decided],
    complete: bool,
) -> Result<(), Error> {
    report::create_output_dir(field, dir)?;
    for d in decided {
        let path = dir.join(format!("{}.md", d.claim.id));
        report::write_atomic(field, &path, &report::claim_markdown(d))?;
    }
    if complete {
        report::write_atomic(
            field,
            &dir.join("README.md"),
            &report::index_markdown(decided),
        )?;
    }
    Ok(())
}

fn all_checked(decided: &[Decided]) -> Result<(), Failure> {
    if decided.iter().all(|d| d.verdict.is_ok()) {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

fn run_prove(args: &ProveArgs) -> Result<(), Failure> {
    let entries = select_claims(&args.ids)?;
    let paper = Paper::as_printed();
    let decided: Vec<Decided> = entries
        .iter()
        .map(|e| claims::decide_entry(e, &paper))
        .collect();
    if args.json {
        let list: Vec<_> = decided.iter().map(report::prove_json).collect();
        println!(
            "{}",
            serde_json::to_string_pretty(&list).expect("JSON of strings and numbers")
        );
    } else {
        for d in &decided {
            println!("{}", report::prove_line(d));
        }
        println!("{}", report::summary_line(&decided));
    }
    if let Some(dir) = &args.write {
        write_certificates("write", dir, &decided, args.ids.is_empty())?;
    }
    all_checked(&decided)
}

fn run_paper(args: &PaperArgs) -> Result<(), Failure> {
    let paper = Paper::as_printed();
    let decided = claims::decide_all(&paper);
    let tables = report::all_tables(&TableOptions::default())?;
    print!("{}", report::paper_report(&decided, false));
    println!("Tables (exact; m = l = v0 = 1)\n");
    print!(
        "{}",
        report::render_document(&tables[..3], Format::Markdown)
    );
    if let Some(dir) = &args.out {
        write_certificates("out", dir, &decided, true)?;
        let report_md = report::paper_report(&decided, true);
        report::write_atomic("out", &dir.join("report.md"), &report_md)?;
        for format in [Format::Markdown, Format::Latex, Format::Csv] {
            let path = dir.join(format!("tables.{}", format.extension()));
            report::write_atomic("out", &path, &report::render_document(&tables, format))?;
        }
        for (name, svg) in paper_figures()? {
            report::write_atomic("out", &dir.join(name), &svg)?;
        }
    }
    all_checked(&decided)
}

/// The figures `paper --out` writes: omega(a), a*(M/m) and Figure 1 (M = m, a = l/2).
fn paper_figures() -> Result<[(&'static str, String); 3], Error> {
    let ratios = parse_ratios("ratios", "1/2,1,2,3,10")?;
    let example = SceneInput {
        m: Some("1".into()),
        rod_mass: Some("1".into()),
        a: Some("1/2".into()),
        ..Default::default()
    };
    Ok([
        (
            "omega.svg",
            report::plot_omega(&ratios, &RodInertia::Uniform)?,
        ),
        ("optimum.svg", report::plot_optimum(&RodInertia::Uniform)?),
        ("figure1.svg", report::plot_figure1(&example.build()?)?),
    ])
}

fn table_options(args: &TableArgs) -> Result<TableOptions, Error> {
    let mut opts = TableOptions::default();
    if let Some(list) = &args.ratios {
        opts.ratios = parse_ratios("ratios", list)?;
    }
    if let Some(r) = &args.ratio {
        opts.ratio = parse_ratios("ratio", r)?.remove(0);
    }
    if let Some(rod) = &args.rod {
        opts.rod = RodInertia::parse(rod)?;
    }
    if let Some(e) = &args.e {
        opts.e = parse_field("e", e)?;
    }
    if let Some(p) = &args.pivot {
        opts.pivot = Some(parse_field("pivot", p)?);
    }
    Ok(opts)
}

fn parse_format(text: &str) -> Result<Format, Error> {
    Format::parse(text).ok_or_else(|| {
        Error::new(
            "format",
            ErrorKind::Invalid(format!(
                "expected md, latex or csv, got '{}'",
                text.chars().take(40).collect::<String>()
            )),
        )
    })
}

fn run_table(args: &TableArgs) -> Result<(), Failure> {
    let format = parse_format(&args.format)?;
    let opts = table_options(args)?;
    let mut tables = report::all_tables(&opts)?;
    if let Some(only) = &args.only {
        let wanted: Vec<String> = only
            .split(',')
            .map(|t| t.trim().to_ascii_uppercase())
            .collect();
        if let Some(bad) = wanted
            .iter()
            .find(|w| !tables.iter().any(|t| t.id == w.as_str()))
        {
            return Err(Error::new(
                "only",
                ErrorKind::Invalid(format!(
                    "unknown table '{}'; the tables are T1-T5",
                    bad.chars().take(40).collect::<String>()
                )),
            )
            .into());
        }
        tables.retain(|t| wanted.iter().any(|w| w == t.id));
    }
    let text = report::render_document(&tables, format);
    match &args.out {
        Some(path) => report::write_atomic("out", path, &text)?,
        None => print!("{text}"),
    }
    Ok(())
}

fn parse_ratios(field: &str, list: &str) -> Result<Vec<rodimpact::field::Q>, Error> {
    list.split(',')
        .map(|text| {
            let x = parse_field(field, text)?;
            if x > rodimpact::field::Q::from_integer(0.into()) {
                Ok(x)
            } else {
                Err(Error::out_of_range(
                    field,
                    format!("mass ratios must be > 0, got {x}"),
                ))
            }
        })
        .collect()
}

fn run_plot(args: &PlotArgs) -> Result<(), Failure> {
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

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(err) => {
            use clap::error::ErrorKind as K;
            if matches!(
                err.kind(),
                K::DisplayHelp | K::DisplayVersion | K::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = err.print();
                return ExitCode::from(
                    if err.kind() == K::DisplayHelpOnMissingArgumentOrSubcommand {
                        2
                    } else {
                        0
                    },
                );
            }
            let rendered = err.to_string();
            let first = rendered.lines().next().unwrap_or("usage error");
            eprintln!("{first} (try --help)");
            return ExitCode::from(2);
        }
    };
    let result = match &cli.command {
        Command::Solve(args) => run_solve(args),
        Command::Prove(args) => run_prove(args),
        Command::Paper(args) => run_paper(args),
        Command::Table(args) => run_table(args),
        Command::Plot(args) => run_plot(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Check) => ExitCode::from(1),
        Err(Failure::Input(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
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
