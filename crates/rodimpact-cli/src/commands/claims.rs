//! `rodimpact prove` and `rodimpact paper`: the claims, their certificates and the report.

use super::{Failure, parse_ratios, print_out};
use clap::Args;
use rodimpact::claims::export::{ExportFormat, export_all};
use rodimpact::claims::{self, Decided, Paper};
use rodimpact::io::{write_atomic, write_directory};
use rodimpact::report::{self, Format};
use rodimpact::scene::{RodInertia, SceneInput};
use rodimpact::tables::{self, TableOptions};
use rodimpact::textbook::formula::formulas;
use rodimpact::{Error, ErrorKind};
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
pub(crate) struct ProveArgs {
    // Help: the claim ids, both ranges from the registry [default: all].
    #[arg(value_name = "ID", help = ids_help())]
    pub(crate) ids: Vec<String>,
    /// Write one Markdown certificate per claim into DIR (and the index README.md when all
    /// claims are decided). All or nothing: every file is staged in DIR, then all are renamed
    /// in; DIR's other files, mode and owner are kept.
    #[arg(long, value_name = "DIR")]
    pub(crate) write: Option<PathBuf>,
    /// Also export the claims for independent checkers into DIR: FORMAT `smt2` (one SMT-LIB 2
    /// file per claim, for z3) or `sympy` (one Python script per claim), and README.md listing
    /// the claims not exported and why. All or nothing, like --write.
    #[arg(long, num_args = 2, value_names = ["FORMAT", "DIR"])]
    pub(crate) export: Option<Vec<String>>,
    /// Print a JSON list instead of one line per claim.
    #[arg(long)]
    pub(crate) json: bool,
}

#[derive(Args, Debug)]
pub(crate) struct PaperArgs {
    // Help: what `--out` writes, one certificate per claim named from the registry.
    #[arg(long, value_name = "DIR|FILE.html", help = out_help())]
    pub(crate) out: Option<PathBuf>,
    /// `text`: the report on the terminal (and the directory of --out DIR); `html`: one
    /// self-contained web page (verdicts, foldable certificates, MathML formulas, tables, inline
    /// SVG figures; no network), written to --out FILE.html, or to standard output without --out.
    #[arg(long, value_enum, default_value_t = PaperFormat::Text)]
    pub(crate) format: PaperFormat,
    /// With --format html: the summary, to print or hand out (about a dozen A4 pages): each claim's
    /// verdict on one line, the formulas, tables and figures, without the certificates.
    #[arg(long)]
    pub(crate) summary: bool,
}

/// The forms of the paper's report.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PaperFormat {
    /// The terminal report; `--out DIR` writes the directory of files.
    Text,
    /// One self-contained web page.
    Html,
}

/// The ids `prove` takes, both ranges, from the registry (e.g. `C1-C46 and X1-X31`).
fn id_ranges(separator: &str) -> String {
    format!("{}{separator}{}", claims::paper_ids(), claims::beyond_ids())
}

/// `prove`'s summary in `rodimpact --help`.
pub(crate) fn prove_about() -> String {
    format!(
        "Decide claims of the paper ({}) and beyond ({}) by exact computation",
        claims::paper_ids(),
        claims::beyond_ids()
    )
}

fn ids_help() -> String {
    format!("Claim ids ({}) [default: all]", id_ranges(", "))
}

fn out_help() -> String {
    let (paper, beyond) = (claims::paper_ids(), claims::beyond_ids());
    format!(
        "With --format text, also write into DIR: README.md (what each file holds), report.md \
         (the report with the tables and figures), one certificate per claim ({}.md ... {}.md, \
         {}.md ... {}.md), tables.md, tables.tex, T1.csv ... T5.csv, omega.svg, optimum.svg and \
         figure1.svg. All or nothing: every file is staged in DIR, then all are renamed in; \
         DIR's other files, mode and owner are kept. With --format html, the page FILE.html, written whole or not at all",
        paper.first, paper.last, beyond.first, beyond.last
    )
}

/// The registered entries for the requested ids (all of them when none is given), each once,
/// in the order first given. At most as many ids as the registry holds are accepted.
fn select_claims(ids: &[String]) -> Result<Vec<&'static claims::Entry>, Error> {
    let registry = claims::registry();
    if ids.is_empty() {
        return Ok(registry.iter().collect());
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
    let mut selected: Vec<&'static claims::Entry> = Vec::new();
    for id in ids {
        let entry = claims::find(id).ok_or_else(|| {
            Error::new(
                "id",
                ErrorKind::Invalid(format!(
                    "unknown claim '{}'; the ids are {}",
                    rodimpact::echo::echo(id),
                    id_ranges(" and ")
                )),
            )
        })?;
        if !selected.iter().any(|e| e.id == entry.id) {
            selected.push(entry);
        }
    }
    Ok(selected)
}

/// Writes one certificate per decided claim into `dir`, and the index when `complete`, all or
/// nothing.
fn write_certificates(
    field: &str,
    dir: &Path,
    decided: &[Decided],
    complete: bool,
) -> Result<(), Error> {
    let mut files: Vec<(String, String)> = decided
        .iter()
        .map(|d| (format!("{}.md", d.claim.id), report::claim_markdown(d)))
        .collect();
    if complete {
        files.push(("README.md".into(), report::index_markdown(decided)));
    }
    write_directory(field, dir, &files)
}

fn all_checked(decided: &[Decided]) -> Result<(), Failure> {
    if decided.iter().all(|d| d.verdict.is_ok()) {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// The format and directory of `--export FORMAT DIR`, the format checked.
fn export_target(values: &[String]) -> Result<(ExportFormat, PathBuf), Error> {
    let [format, dir] = values else {
        unreachable!("clap takes exactly two values for --export");
    };
    let format = ExportFormat::parse(format).ok_or_else(|| {
        Error::new(
            "export",
            ErrorKind::Invalid(format!(
                "unknown format '{}'; the formats are smt2 and sympy",
                rodimpact::echo::echo(format)
            )),
        )
    })?;
    Ok((format, PathBuf::from(dir)))
}

pub(crate) fn run_prove(args: &ProveArgs) -> Result<(), Failure> {
    let entries = select_claims(&args.ids)?;
    let export = args.export.as_deref().map(export_target).transpose()?;
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
        if let Some(note) = report::hand_step_note(&decided) {
            print_out(&format!("{note}\n"));
        }
    }
    if let Some(dir) = &args.write {
        write_certificates("write", dir, &decided, args.ids.is_empty())?;
    }
    if let Some((format, dir)) = export {
        let selected: Vec<claims::Entry> = entries.iter().map(|e| **e).collect();
        let files: Vec<(String, String)> = export_all(&selected, format)
            .into_iter()
            .map(|f| (f.name, f.text))
            .collect();
        write_directory("export", &dir, &files)?;
    }
    all_checked(&decided)
}

pub(crate) fn run_paper(args: &PaperArgs) -> Result<(), Failure> {
    let paper = Paper::as_printed();
    let decided = claims::decide_all(&paper);
    let tables = tables::all_tables(&TableOptions::default())?;
    if args.summary && args.format != PaperFormat::Html {
        return Err(Error::new(
            "summary",
            rodimpact::ErrorKind::Conflict(
                "the summary is a web page to print: add --format html".into(),
            ),
        )
        .into());
    }
    if args.format == PaperFormat::Html {
        let page = report::paper_html(
            &decided,
            &formulas(&SceneInput::default())?,
            &tables,
            &paper_figures()?,
            if args.summary {
                report::PaperEdition::Summary
            } else {
                report::PaperEdition::Full
            },
        );
        match &args.out {
            Some(file) => write_atomic("out", file, &page)?,
            None => print_out(&page),
        }
        return all_checked(&decided);
    }
    print_out(&report::paper_report(&decided));
    print_out("Tables (exact; m = l = v0 = 1)\n\n");
    print_out(&report::render_document(&tables[..3], Format::Markdown));
    if let Some(dir) = &args.out {
        let files = report::paper_files(&decided, &tables, &paper_figures()?);
        write_directory("out", dir, &files)?;
    }
    all_checked(&decided)
}

/// The figures `paper --out` writes: omega(a), a*(M/m) and Figure 1 (M = m, a = l/2).
fn paper_figures() -> Result<Vec<report::PaperFigure>, Error> {
    let ratios = parse_ratios("ratios", "1/2,1,2,3,10")?;
    let example = SceneInput {
        m: Some("1".into()),
        rod_mass: Some("1".into()),
        a: Some("1/2".into()),
        ..Default::default()
    };
    Ok(vec![
        report::PaperFigure {
            file: "omega.svg",
            caption: "The spin $\\omega l/v_0$ against the impact point $a/l$ for $M/m = 1/2, 1, 2, 3, 10$ (uniform rod, elastic), each curve's optimum $a^*$ marked; dashed beyond the end $a = l$.".into(),
            svg: report::plot_omega(&ratios, &RodInertia::Uniform)?,
        },
        report::PaperFigure {
            file: "optimum.svg",
            caption: "The optimal impact distance $a^*/l$ against $M/m$ (uniform rod): on the rod exactly when $M \\le 2m$, tending to $l/\\sqrt{3}$ for a light rod.".into(),
            svg: report::plot_optimum(&RodInertia::Uniform)?,
        },
        report::PaperFigure {
            file: "figure1.svg",
            caption: "The paper's Fig. 1, to scale: the rod of length $2l$ at rest, the projectile $m$ with speed $v_0$ aimed at $a = l/2$ ($M = m$).".into(),
            svg: report::plot_figure1(&example.build()?)?,
        },
    ])
}
