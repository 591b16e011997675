//! `rodimpact formula`: the exact answer as formulas in the scene's free symbols.

use super::{Failure, ObliqueFlags, SceneFlags, format_choice, print_out};
use clap::Args;
use rodimpact::report::{formula_json, formula_latex, formula_markdown, formula_text};
use rodimpact::textbook::formula::formulas;

#[derive(Args, Debug)]
pub(crate) struct FormulaArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    #[command(flatten)]
    pub(crate) oblique: ObliqueFlags,
    /// Output format: text, latex, markdown or json (also md, tex, txt).
    #[arg(long, value_name = "FORMAT", default_value = "text")]
    pub(crate) format: String,
}

pub(crate) fn run_formula(args: &FormulaArgs) -> Result<(), Failure> {
    let format = format_choice(
        "format",
        &args.format,
        &["text", "latex", "markdown", "json"],
    )?;
    let f = formulas(&args.oblique.input(&args.scene))?;
    let text = match format {
        "latex" => formula_latex(&f),
        "markdown" => formula_markdown(&f),
        "json" => format!(
            "{}\n",
            serde_json::to_string_pretty(&formula_json(&f)).expect("JSON of strings")
        ),
        _ => formula_text(&f),
    };
    print_out(&text);
    Ok(())
}
