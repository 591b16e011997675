//! `rodimpact check`: published answers against the exact ones.

use super::{Failure, SceneFlags, print_out};
use clap::Args;
use rodimpact::textbook::problems::{
    MAX_CLAIMS, MAX_FILE_BYTES, check_problems, parse_problems, problems_json, problems_text,
};
use rodimpact::textbook::{Claim, check_scene};
use rodimpact::{Error, ErrorKind};
use std::io::Read;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct CheckArgs {
    /// A problem collection (TOML) to check instead of one scene.
    #[arg(value_name = "PROBLEMS.toml")]
    pub(crate) file: Option<PathBuf>,
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// A claimed answer NAME=VALUE: NAME one of v, V, V_cm, omega, a_star, omega_max,
    /// energy_before, energy_after, energy_lost, pivot_impulse, impulse; VALUE a number as
    /// printed (with an optional unit), a fraction, or a formula in m M l L a d v0 e p.
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
    let s = args.scene.input();
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
    ]
    .iter()
    .any(|f| f.is_some());
    if !args.claim.is_empty() || scene_given {
        return Err(Error::new(
            "check",
            ErrorKind::Conflict("give either a problem file or scene flags with --claim".into()),
        ));
    }
    let text = read_bounded(&label, path)?;
    let problems = parse_problems(&label, &text)?;
    let reports = check_problems(&label, &problems, args.sig)?;
    if args.json {
        print_out(&format!("{}\n", pretty(&problems_json(&reports))));
    } else {
        print_out(&problems_text(&reports));
    }
    Ok(reports.iter().all(|r| r.report.all_agree()))
}

/// The file's text, read no further than the size limit (a huge or endless file is refused
/// without being read into memory); bytes that are not UTF-8 are named by line.
fn read_bounded(label: &str, path: &std::path::Path) -> Result<String, Error> {
    let io = |e: std::io::Error| Error::new(label, ErrorKind::Io(format!("cannot read: {e}")));
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(io)?;
    if bytes.len() > MAX_FILE_BYTES {
        return Err(Error::out_of_range(
            label,
            format!("file larger than {MAX_FILE_BYTES} bytes (limit)"),
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
        Error::new(
            label,
            ErrorKind::Invalid(format!("line {line}: not valid UTF-8")),
        )
    })
}

fn check_flags(args: &CheckArgs) -> Result<bool, Error> {
    if args.claim.is_empty() {
        return Err(Error::new("claim", ErrorKind::Missing));
    }
    if args.claim.len() > MAX_CLAIMS {
        return Err(Error::out_of_range(
            "claim",
            format!("more than {MAX_CLAIMS} claims (limit)"),
        ));
    }
    let claims = args
        .claim
        .iter()
        .map(|c| Claim::parse(c))
        .collect::<Result<Vec<_>, _>>()?;
    let report = check_scene(&args.scene.input(), &claims, args.sig)?;
    if args.json {
        print_out(&format!("{}\n", pretty(&report.to_json())));
    } else {
        print_out(&format!("{}{}\n", report.to_text(), report.summary()));
    }
    Ok(report.all_agree())
}

fn pretty(v: &serde_json::Value) -> String {
    serde_json::to_string_pretty(v).expect("JSON of strings and numbers")
}
