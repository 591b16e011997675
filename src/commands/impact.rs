//! `rodimpact impact`: any planar impact with one contact, under the three restitution laws.

use super::{Failure, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::field::QSqrt;
use rodimpact::model::{MAX_SCENE_BYTES, parse_toml};
use rodimpact::report::{impact_json, impact_text};
use rodimpact::solve::impact::{Law, solve_contact};
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
    let system = parse_toml(&label, &text)?;
    let laws: &[Law] = match args.law {
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
    match args.format {
        ImpactFormat::Json => {
            let digits = parse_digits(args.digits.as_deref(), 30)?;
            let json = impact_json(&system, &answers, digits);
            print_out(&format!(
                "{}\n",
                serde_json::to_string_pretty(&json).expect("JSON of strings and bools")
            ));
        }
        ImpactFormat::Text => {
            let digits = parse_digits(args.digits.as_deref(), 6)?;
            print_out(&impact_text(&system, &answers, digits));
        }
    }
    Ok(())
}
