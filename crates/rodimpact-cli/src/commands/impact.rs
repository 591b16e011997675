//! `rodimpact impact`: any planar impact with one contact, under the three restitution laws.

use super::{Failure, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::app::impact::{answer_impact, read_scene_file};
use rodimpact::batch::audit_impact;
use rodimpact::field::Q;
use rodimpact::impact::Law;
use rodimpact::model::MAX_SCENE_BYTES;
use rodimpact::report::{impact_audit_json, impact_run_json, impact_run_text};
use rodimpact::{Error, ErrorKind};
use std::io::Read;
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
    #[arg(long, value_name = "FILE.jsonl")]
    pub(crate) batch: Option<PathBuf>,
    /// With --batch: a claim matches an exact answer when every component is within this
    /// relative error [default: 1e-9].
    #[arg(long, value_name = "R", requires = "batch")]
    pub(crate) rtol: Option<String>,
    /// The restitution law: newton (kinematic), poisson (kinetic), energetic (Stronge), or all
    /// three side by side.
    #[arg(long, value_enum, default_value = "all")]
    pub(crate) law: LawChoice,
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
    Energetic,
    All,
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
    let file = args.file.as_ref().expect("clap requires FILE or --batch");
    let label = rodimpact::echo::echo_path(file);
    let value = read_scene_file(&label, file)?;
    let law = match args.law {
        LawChoice::Newton => Some(Law::Newton),
        LawChoice::Poisson => Some(Law::Poisson),
        LawChoice::Energetic => Some(Law::Energetic),
        LawChoice::All => None,
    };
    let run = answer_impact(&value, &label, law, args.model.as_deref())?;
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
    use std::io::{BufRead, Write};
    let label = rodimpact::echo::echo_path(path);
    let rtol = match &args.rtol {
        None => Q::new(1.into(), 1_000_000_000.into()),
        Some(text) => {
            let r = rodimpact::number::parse(text).map_err(|kind| Error::new("rtol", kind))?;
            if r < Q::from_integer(0.into()) {
                return Err(
                    Error::out_of_range("rtol", format!("must be >= 0, got {text}")).into(),
                );
            }
            r
        }
    };
    let file = std::fs::File::open(path).map_err(|e| Error::io(label.clone(), "cannot read", e))?;
    let mut reader = std::io::BufReader::new(file);
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let (mut scenes, mut claimed) = (0usize, 0usize);
    let mut findings: std::collections::BTreeMap<String, Vec<String>> = Default::default();
    let mut matched: std::collections::BTreeMap<String, usize> = Default::default();
    let mut line = String::new();
    let mut number = 0;
    loop {
        line.clear();
        let read = (&mut reader)
            .take(MAX_SCENE_BYTES as u64 + 1)
            .read_line(&mut line)
            .map_err(|e| Error::io(label.clone(), "cannot read", e))?;
        if read == 0 {
            break;
        }
        number += 1;
        if line.len() > MAX_SCENE_BYTES {
            return Err(Error::out_of_range(
                format!("{label}: line {number}"),
                format!("longer than {MAX_SCENE_BYTES} bytes (limit)"),
            )
            .into());
        }
        if line.trim().is_empty() {
            continue;
        }
        let audit = audit_impact(line.trim_end(), number, &rtol)
            .map_err(|e| Error::new(format!("{label}: {}", e.field), e.kind))?;
        scenes += 1;
        if audit.claimed.is_some() {
            claimed += 1;
            for m in &audit.matches {
                *matched.entry(m.clone()).or_default() += 1;
            }
            for f in &audit.findings {
                findings
                    .entry((*f).into())
                    .or_default()
                    .push(audit.id.clone());
            }
        }
        let json = serde_json::to_string(&impact_audit_json(&audit)).expect("JSON of strings");
        if writeln!(out, "{json}").is_err() {
            return Err(Error::new(
                "stdout",
                ErrorKind::Invalid("cannot write standard output".into()),
            )
            .into());
        }
    }
    let mut summary = format!(
        "{scenes} scene{}, {claimed} with a claimed state\n",
        if scenes == 1 { "" } else { "s" }
    );
    if !matched.is_empty() {
        let list: Vec<String> = matched.iter().map(|(k, v)| format!("{k} {v}")).collect();
        summary.push_str(&format!(
            "claims matching each exact answer: {}\n",
            list.join(", ")
        ));
    }
    if findings.is_empty() {
        summary.push_str("every claim matches an exact answer\n");
    } else {
        summary.push_str("findings:\n");
        for (finding, ids) in &findings {
            let shown: Vec<&str> = ids.iter().take(5).map(String::as_str).collect();
            summary.push_str(&format!(
                "  {finding}: {} ({}{})\n",
                ids.len(),
                shown.join(", "),
                if ids.len() > 5 { ", ..." } else { "" }
            ));
        }
    }
    eprint!("{summary}");
    if findings.is_empty() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
