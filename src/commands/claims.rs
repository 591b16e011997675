//! `rodimpact prove` and `rodimpact paper`: the claims, their certificates and the report.

use super::{Failure, parse_ratios, print_out};
use clap::Args;
use rodimpact::claims::{self, Decided, Paper};
use rodimpact::report::{self, Format, TableOptions};
use rodimpact::scene::{RodInertia, SceneInput};
use rodimpact::{Error, ErrorKind};
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
pub(crate) struct ProveArgs {
    /// Claim ids (C1-C46, X1-X26) [default: all].
    #[arg(value_name = "ID")]
    pub(crate) ids: Vec<String>,
    /// Write one Markdown certificate per claim into DIR (and the index README.md when all
    /// claims are decided).
    #[arg(long, value_name = "DIR")]
    pub(crate) write: Option<PathBuf>,
    /// Print a JSON list instead of one line per claim.
    #[arg(long)]
    pub(crate) json: bool,
}

#[derive(Args, Debug)]
pub(crate) struct PaperArgs {
    /// Also write the report as Markdown (report.md) with every certificate into DIR.
    #[arg(long, value_name = "DIR")]
    pub(crate) out: Option<PathBuf>,
}

/// The registered entries for the requested ids (all of them when none is given), each once,
/// in the order first given. At most as many ids as the registry holds are accepted.
fn select_claims(ids: &[String]) -> Result<Vec<claims::Entry>, Error> {
    let registry = claims::registry();
    if ids.is_empty() {
        return Ok(registry);
    }
    if ids.len() > registry.len() {
        return Err(Error::out_of_range(
            "id",
            format!(
                "more than {} ids (limit: the number of claims; a repeated id is decided once)",
                registry.len()
            ),
        ));
    }
    let mut selected: Vec<claims::Entry> = Vec::new();
    for id in ids {
        let entry = registry
            .iter()
            .find(|e| e.id.eq_ignore_ascii_case(id.trim()))
            .ok_or_else(|| {
                Error::new(
                    "id",
                    ErrorKind::Invalid(format!(
                        "unknown claim '{}'; the ids are C1-C46 and X1-X26",
                        rodimpact::echo::echo(id)
                    )),
                )
            })?;
        if !selected.iter().any(|e| e.id == entry.id) {
            selected.push(*entry);
        }
    }
    Ok(selected)
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

pub(crate) fn run_prove(args: &ProveArgs) -> Result<(), Failure> {
    let entries = select_claims(&args.ids)?;
    let paper = Paper::as_printed();
    let decided: Vec<Decided> = entries
        .iter()
        .map(|e| claims::decide_entry(e, &paper))
        .collect();
    if args.json {
        let list: Vec<_> = decided.iter().map(report::prove_json).collect();
        let json = serde_json::to_string_pretty(&list).expect("JSON of strings and numbers");
        print_out(&format!("{json}\n"));
    } else {
        for d in &decided {
            print_out(&format!("{}\n", report::prove_line(d)));
        }
        print_out(&format!("{}\n", report::summary_line(&decided)));
    }
    if let Some(dir) = &args.write {
        write_certificates("write", dir, &decided, args.ids.is_empty())?;
    }
    all_checked(&decided)
}

pub(crate) fn run_paper(args: &PaperArgs) -> Result<(), Failure> {
    let paper = Paper::as_printed();
    let decided = claims::decide_all(&paper);
    let tables = report::all_tables(&TableOptions::default())?;
    print_out(&report::paper_report(&decided, false));
    print_out("Tables (exact; m = l = v0 = 1)\n\n");
    print_out(&report::render_document(&tables[..3], Format::Markdown));
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
