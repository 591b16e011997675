//! `rodimpact impact`: any planar impact, with one contact under the restitution laws or with
//! several under the models of several contacts.

use super::{Failure, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::app::impact::{answer_impact, parse_engine, read_scene_file};
use rodimpact::app::impact_batch::{ImpactBatchOptions, read_known_findings, run};
use rodimpact::batch::FloatFormat;
use rodimpact::impact::Law;
use rodimpact::report::{
    impact_audit_json, impact_batch_json, impact_batch_text, impact_run_json, impact_run_text,
};
use rodimpact::{Error, ErrorKind};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ImpactArgs {
    /// The scene: bodies, contacts and pins in TOML (docs/impacts.md; examples/impacts/).
    #[arg(
        value_name = "FILE.toml",
        required_unless_present = "batch",
        conflicts_with = "batch"
    )]
    pub(crate) file: Option<PathBuf>,
    /// Audit many scenes instead: one scene per line in JSON (a scene file's structure) with an
    /// engine's "claimed" bodies; one JSON line out per scene: the exact answers, the claim's
    /// relative errors, which law or model it matches, and a diagnosis. Exit 1 when a claim
    /// matches none.
    #[arg(long, value_name = "FILE.jsonl", conflicts_with_all = ["law", "model", "format", "digits"])]
    pub(crate) batch: Option<PathBuf>,
    /// With --batch: a claim matches an exact answer when its error in energy,
    /// sqrt(K(claim - exact)/K(before)), is at most R [default: 1e-9].
    #[arg(long, value_name = "R", requires = "batch", allow_hyphen_values = true)]
    pub(crate) rtol: Option<String>,
    /// With --batch: a claim also matches when every component (m/s, rad/s) is within X of the
    /// exact answer's (for values that vanish exactly, where an engine leaves round-off).
    #[arg(long, value_name = "X", requires = "batch", allow_hyphen_values = true)]
    pub(crate) atol: Option<String>,
    /// With --batch: a claim also matches when every component is within N floats of the exact
    /// value correctly rounded (to f64, or to --float).
    #[arg(long, value_name = "N", requires = "batch", allow_hyphen_values = true)]
    pub(crate) ulps: Option<String>,
    /// With --batch: the float format of --ulps [default: f64].
    #[arg(long, value_enum, value_name = "f32|f64", requires = "ulps")]
    pub(crate) float: Option<FloatChoice>,
    /// With --batch: known findings (CSV `id,finding`, `*` for a class of scenes): the audit
    /// fails only on findings the file does not allow.
    #[arg(long, value_name = "FILE", requires = "batch")]
    pub(crate) expect: Option<PathBuf>,
    /// With --batch: also write the summary as JSON here (all or nothing), for a CI job.
    #[arg(long, value_name = "FILE", requires = "batch")]
    pub(crate) summary_json: Option<PathBuf>,
    /// The restitution law: newton (kinematic), poisson (kinetic), energetic (Stronge; also
    /// `stronge`), or all three side by side; or a law engines converge to: lcp-newton
    /// (Newton's restitution and Coulomb's law on the final velocities, one phase), lcp-poisson
    /// (its compression-then-expansion form), split (friction without restitution, then
    /// restitution without friction). For a scene with one contact.
    #[arg(long, value_enum, default_value = "all")]
    pub(crate) law: LawChoice,
    /// Also answer as an engine's solver does: pymunk-7, box2d-2.3, bullet-3 (one step replayed
    /// exactly), box2d-3, rapier-0.36 (the law their soft substeps converge to); settings after
    /// a colon, e.g. box2d-2.3:scale=16 (a world scaled by 16: the restitution threshold in the
    /// scene's units), :threshold=T, bullet-3:plane=xy (docs/engines.md). With --batch: compare
    /// every claim with this engine's step (`all`: every replayed engine's) instead of the step
    /// of the engine the line's "claimed" names.
    #[arg(long, value_name = "NAME")]
    pub(crate) engine: Option<String>,
    /// How several contacts act together: simultaneous-newton, simultaneous-poisson,
    /// sequential (every order), sequential:2,1,3 (one order), pgs:K (K sweeps of projected
    /// Gauss-Seidel), or all (the simultaneous models, sequential in every order, pgs:1 and
    /// pgs:10). For a scene with several contacts only.
    #[arg(long, value_name = "MODEL")]
    pub(crate) model: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub(crate) format: ImpactFormat,
    /// Significant digits of the decimals (text: 6 by default; JSON: at least 30).
    #[arg(long, value_name = "N")]
    pub(crate) digits: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum LawChoice {
    Newton,
    Poisson,
    #[value(alias = "stronge")]
    Energetic,
    LcpNewton,
    LcpPoisson,
    Split,
    All,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum FloatChoice {
    F32,
    F64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ImpactFormat {
    Text,
    Json,
}

pub(crate) fn run_impact(args: &ImpactArgs) -> Result<(), Failure> {
    if let Some(batch) = &args.batch {
        return run_batch(args, batch);
    }
    // The audit's options do nothing for one scene: refused, not ignored.
    for (flag, given) in [
        ("rtol", args.rtol.is_some()),
        ("atol", args.atol.is_some()),
        ("ulps", args.ulps.is_some()),
        ("float", args.float.is_some()),
        ("expect", args.expect.is_some()),
        ("summary-json", args.summary_json.is_some()),
    ] {
        if given {
            return Err(Error::new(
                flag,
                ErrorKind::Conflict(
                    "only with --batch (it says when an engine's claim matches)".into(),
                ),
            )
            .into());
        }
    }
    let file = args.file.as_ref().expect("clap requires FILE or --batch");
    let label = rodimpact::echo::echo_path(file);
    let value = read_scene_file(&label, file)?;
    let law = match args.law {
        LawChoice::Newton => Some(Law::Newton),
        LawChoice::Poisson => Some(Law::Poisson),
        LawChoice::Energetic => Some(Law::Energetic),
        LawChoice::LcpNewton => Some(Law::LcpNewton),
        LawChoice::LcpPoisson => Some(Law::LcpPoisson),
        LawChoice::Split => Some(Law::Split),
        LawChoice::All => None,
    };
    let engine = args.engine.as_deref().map(parse_engine).transpose()?;
    let run = answer_impact(&value, &label, law, args.model.as_deref(), engine.as_ref())?;
    match args.format {
        ImpactFormat::Json => {
            let digits = parse_digits(args.digits.as_deref(), 30)?;
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&impact_run_json(&run, digits))
                    .expect("JSON of strings and bools")
            ));
        }
        ImpactFormat::Text => {
            let digits = parse_digits(args.digits.as_deref(), 6)?;
            print_out(&impact_run_text(&run, digits));
        }
    }
    if run.all_agree() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// `impact --batch FILE.jsonl`: every line audited, one JSON line out each, a summary on stderr.
fn run_batch(args: &ImpactArgs, path: &std::path::Path) -> Result<(), Failure> {
    use std::io::Write;
    let label = rodimpact::echo::echo_path(path);
    let float = args.float.map(|f| match f {
        FloatChoice::F32 => FloatFormat::F32,
        FloatChoice::F64 => FloatFormat::F64,
    });
    let expected = args
        .expect
        .as_deref()
        .map(read_known_findings)
        .transpose()?;
    let options = ImpactBatchOptions::parse(
        args.rtol.as_deref(),
        args.atol.as_deref(),
        args.ulps.as_deref(),
        float,
        args.engine.as_deref(),
        expected,
    )?;
    let file = std::fs::File::open(path).map_err(|e| Error::io(label.clone(), "cannot read", e))?;
    let summary_file = super::SummaryFile::open(args.summary_json.as_deref())?;
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let summary = run(std::io::BufReader::new(file), &label, &options, |audit| {
        let json = serde_json::to_string(&impact_audit_json(audit)).expect("JSON of strings");
        // A reader gone (`| head -1`) ends the run quietly; another failure with its reason.
        writeln!(out, "{json}").map_err(|why| super::stdout_failed(&why))
    })?;
    let expect_file = args.expect.as_deref().map(rodimpact::echo::echo_path);
    let text = impact_batch_text(
        &summary,
        options.expected.as_ref().zip(expect_file.as_deref()),
    );
    eprint!("{text}");
    summary_file.write(&impact_batch_json(&summary, options.expected.is_some()))?;
    if summary.passed(options.expected.is_some()) {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
