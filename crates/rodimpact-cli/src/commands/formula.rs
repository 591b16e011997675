//! `rodimpact formula`: the exact answer as formulas in the scene's free symbols.

use super::{Failure, ObliqueFlags, SceneFlags, format_choice, print_out};
use clap::Args;
use rodimpact::report::{
    formula_json, formula_latex, formula_markdown, formula_text, latex_document,
};
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
    /// With --format latex: a complete document that pdflatex compiles as it is.
    #[arg(long)]
    pub(crate) standalone: bool,
}

pub(crate) fn run_formula(args: &FormulaArgs) -> Result<(), Failure> {
    let format = format_choice(
        "format",
        &args.format,
        &["text", "latex", "markdown", "json"],
    )?;
    if args.standalone && format != "latex" {
        return Err(rodimpact::Error::new(
            "standalone",
            rodimpact::ErrorKind::Conflict(
                "a complete document is LaTeX: add --format latex".into(),
            ),
        )
        .into());
    }
    let f = formulas(&args.oblique.input(&args.scene))?;
    let text = match format {
        "latex" if args.standalone => latex_document(&[], &formula_latex(&f)),
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
