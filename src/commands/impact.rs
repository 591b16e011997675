//! `rodimpact impact`: any planar impact with one contact, under the three restitution laws.

use super::{Failure, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::field::QSqrt;
use rodimpact::model::{MAX_SCENE_BYTES, from_value, toml_value};
use rodimpact::report::{check_json, check_summary, check_table, impact_json, impact_text};
use rodimpact::solve::impact::{Law, solve_contact};
use rodimpact::textbook::SceneCheck;
use rodimpact::textbook::impact::{check_impact_claims, read_impact_claims};
use rodimpact::{Error, ErrorKind};
use std::io::Read;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct ImpactArgs {
    /// The scene: bodies, contacts and pins in TOML (docs/impacts.md; examples/impacts/).
    #[arg(value_name = "FILE.toml")]
    pub(crate) file: PathBuf,
    /// The restitution law: newton (kinematic), poisson (kinetic), energetic (Stronge), or all
    /// three side by side.
    #[arg(long, value_enum, default_value = "all")]
    pub(crate) law: LawChoice,
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
    let label = rodimpact::echo::echo_path(&args.file);
    let mut bytes = Vec::new();
    std::fs::File::open(&args.file)
        .and_then(|f| f.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::io(label.clone(), "cannot read", e))?;
    let text = String::from_utf8(bytes)
        .map_err(|_| Error::new(label.clone(), ErrorKind::Invalid("not UTF-8 text".into())))?;
    let value = toml_value(&label, &text)?;
    let at_file = |e: Error| Error::new(format!("{label}: {}", e.field), e.kind);
    let system = from_value(&value).map_err(at_file)?;
    let claims = read_impact_claims(&value, &system).map_err(at_file)?;
    // A file's published answers need their laws answered whatever --law says.
    let laws: &[Law] = match args.law {
        _ if !claims.is_empty() => &Law::ALL,
        LawChoice::Newton => &[Law::Newton],
        LawChoice::Poisson => &[Law::Poisson],
        LawChoice::Energetic => &[Law::Energetic],
        LawChoice::All => &Law::ALL,
    };
    let answers = laws
        .iter()
        .map(|&law| {
            solve_contact::<QSqrt>(&system, law)
                .map_err(|e| Error::new(label.clone(), ErrorKind::Invalid(e.to_string())))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let checked = SceneCheck {
        symbolic: None,
        answers: check_impact_claims(&claims, &system, &answers).map_err(at_file)?,
    };
    match args.format {
        ImpactFormat::Json => {
            let digits = parse_digits(args.digits.as_deref(), 30)?;
            let mut json = impact_json(&system, &answers, digits);
            if !claims.is_empty() {
                json["claims"] = check_json(&checked);
            }
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&json).expect("JSON of strings and bools")
            ));
        }
        ImpactFormat::Text => {
            let digits = parse_digits(args.digits.as_deref(), 6)?;
            let mut text = impact_text(&system, &answers, digits);
            if !claims.is_empty() {
                text.push_str(&format!(
                    "\nPublished answers (the file's claims, each under its source's law)\n{}  {}\n",
                    check_table(&checked),
                    check_summary(&checked)
                ));
            }
            print_out(&text);
        }
    }
    if checked.all_agree() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
