//! `rodimpact solve`: one scene, exactly, and optionally in a float backend next to it.

use super::{Failure, ObliqueFlags, SceneFlags, format_choice, parse_digits, print_out};
use clap::{Args, ValueEnum};
use rodimpact::report::{
    ExplainFormat, backend_json, explain, latex_document, solution_json, solution_text,
};
use rodimpact::solve::Answer;
use rodimpact::solve::fast::float::FloatFormula;
use rodimpact::solve::working::Working;
use rodimpact::stability::Backend;
use serde_json::Value;

/// The number format `--backend` solves in.
#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum BackendArg {
    /// Exact rationals (the default).
    Exact,
    /// IEEE binary64 with the stable formula (route float/sq), measured against the exact answer.
    F64,
    /// IEEE binary32 with the stable formula (route float/sq), measured against the exact answer.
    F32,
    /// Outward-rounded f64 intervals through the closed form, checked to enclose the exact
    /// answer.
    Interval,
}

impl BackendArg {
    /// What the text report says the backend is, in words.
    fn describe(self) -> &'static str {
        match self {
            BackendArg::Exact => "exact rationals",
            BackendArg::F64 => {
                "f64: IEEE binary64 with the stable formula \"sq\" (the closed form with exact power-of-two rescaling: no intermediate overflow or underflow)"
            }
            BackendArg::F32 => {
                "f32: IEEE binary32 with the stable formula \"sq\" (the closed form with exact power-of-two rescaling: no intermediate overflow or underflow)"
            }
            BackendArg::Interval => "interval: f64 intervals rounded outward",
        }
    }

    fn backend(self) -> Backend {
        match self {
            BackendArg::Exact => Backend::Exact,
            BackendArg::F64 => Backend::F64(FloatFormula::Sq),
            BackendArg::F32 => Backend::F32(FloatFormula::Sq),
            BackendArg::Interval => Backend::Interval,
        }
    }
}

#[derive(Args, Debug)]
pub(crate) struct SolveArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    #[command(flatten)]
    pub(crate) oblique: ObliqueFlags,
    /// Print one JSON object (keys in docs/conventions.md) instead of the text report.
    #[arg(long)]
    pub(crate) json: bool,
    /// Significant digits of the printed decimals and of the a* bounds [default: 30 in JSON,
    /// 15 in the text report].
    #[arg(long, value_name = "N")]
    pub(crate) digits: Option<String>,
    /// Also solve in this backend and report its error against the exact answer.
    #[arg(long, value_enum, default_value = "exact")]
    pub(crate) backend: BackendArg,
    /// Print the working instead: the balance equations with the scene's numbers, the
    /// elimination, D, the result and the a* step, as text, markdown or latex.
    #[arg(long, value_name = "FORMAT", num_args = 0..=1, default_missing_value = "text")]
    pub(crate) explain: Option<String>,
    /// With --explain latex: a complete document that pdflatex compiles as it is.
    #[arg(long)]
    pub(crate) standalone: bool,
}

pub(crate) fn run_solve(args: &SolveArgs) -> Result<(), Failure> {
    // The working's format, aliases read once (`tex` is `latex`).
    let working = args
        .explain
        .as_deref()
        .map(|f| format_choice("explain", f, &["text", "markdown", "latex"]))
        .transpose()?;
    if args.standalone && working != Some("latex") {
        return Err(rodimpact::Error::new(
            "standalone",
            rodimpact::error::ErrorKind::Conflict(
                "a complete document is LaTeX: add --explain latex".into(),
            ),
        )
        .into());
    }
    let scene = args.oblique.input(&args.scene).build()?;
    let backend = args.backend.backend();
    if scene.oblique().is_some() && backend != Backend::Exact {
        return Err(rodimpact::Error::new(
            "backend",
            rodimpact::error::ErrorKind::Conflict(
                "the float and interval backends solve the paper's scene only; an oblique or frictional scene is solved exactly".into(),
            ),
        )
        .into());
    }
    if let Some(format) = working {
        let format = match format {
            "markdown" => ExplainFormat::Markdown,
            "latex" => ExplainFormat::Latex,
            _ => ExplainFormat::Text,
        };
        if args.json || backend != Backend::Exact {
            return Err(rodimpact::Error::new(
                "explain",
                rodimpact::error::ErrorKind::Conflict(
                    "the working is written exactly: not with --json or --backend".into(),
                ),
            )
            .into());
        }
        if scene.rod_before() != Default::default() {
            return Err(rodimpact::Error::new(
                "explain",
                rodimpact::error::ErrorKind::Conflict(
                    "the working is written for a rod at rest before the impact: not with --rod-v, --rod-vt or --rod-omega".into(),
                ),
            )
            .into());
        }
        let working = explain(&Working::of(&scene), format);
        print_out(&match (args.standalone, format) {
            (true, ExplainFormat::Latex) => latex_document(&[], &working),
            _ => working,
        });
        return Ok(());
    }
    let floats = match backend {
        Backend::Exact => None,
        _ => Some(backend_json(&rodimpact::stability::judge(&scene, backend)?)),
    };
    let answer = Answer::of(&scene);
    if args.json {
        let digits = parse_digits(args.digits.as_deref(), 30)?;
        let mut json = solution_json(&answer, digits);
        if let (Value::Object(out), Some(floats)) = (&mut json, floats) {
            out.insert("backend".into(), Value::String(backend.name()));
            out.extend(floats);
        }
        let json = serde_json::to_string_pretty(&json).expect("JSON of strings and bools");
        print_out(&format!("{json}\n"));
    } else {
        let digits = parse_digits(args.digits.as_deref(), 15)?;
        let mut text = solution_text(&answer, digits);
        if let Some(floats) = floats {
            text.push_str(&format!(
                "\nBackend {}\n  against the exact values: rel_error = |float - exact|/|exact|, cond = condition number,\n  reliable = every input and the exact value fit the format, cond * unit roundoff <= 1e-3\n  and rel_error <= 4 cond * unit roundoff\n",
                args.backend.describe()
            ));
            for (name, value) in floats {
                let fields: Vec<String> = value
                    .as_object()
                    .into_iter()
                    .flatten()
                    .filter(|(k, _)| k.as_str() != "exact")
                    .map(|(k, v)| format!("{k} {}", v.as_str().map_or(v.to_string(), String::from)))
                    .collect();
                text.push_str(&format!("  {name:<5}  {}\n", fields.join(", ")));
            }
        }
        print_out(&text);
    }
    if answer.laws_hold() {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}
