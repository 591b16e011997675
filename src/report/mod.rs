//! Output: the forms in which results leave the library (JSON, text, and later Markdown, LaTeX,
//! CSV and SVG).

mod backend;
mod certificate;
mod claims_doc;
mod files;
pub mod markup;
mod output_dir;
mod paper_tables;
mod plot;
mod proofs;
mod simulate;
mod solution;
mod table;

pub use backend::{ERROR_BOUND, backend_values};
pub use certificate::certificate_markdown;
pub use claims_doc::claims_markdown;
pub use files::{AtomicFile, create_output_dir, remove_temporaries_on_signals, write_atomic};
pub use output_dir::write_directory;
pub use paper_tables::{TableOptions, all_tables, t1, t2, t3, t4, t5};
pub use plot::{
    Figure, PlotData, PlotValue, energy_figure, mass_ratio_family, omega_figure, optimum_figure,
    plot_figure1, plot_omega, plot_optimum, plot_stability, quantities_figure, velocity_figure,
};
pub use proofs::{
    PaperFigure, claim_markdown, hand_step_note, index_markdown, paper_files, paper_markdown,
    paper_report, prove_json, prove_line, summary_line, verdict_label, verdict_mark,
};
pub use simulate::{
    simulation_json, simulation_passes, simulation_text, sweep_json, sweep_passes, sweep_text,
};
pub use solution::Solution;
pub use table::{Cell, Column, Format, Table, render_document};

use crate::field::Q;
use crate::number;
use serde_json::{Value, json};

/// The JSON value form of an exact number: `{"exact": "p/q", "decimal": "..."}`, the decimal
/// correctly rounded to `digits` significant digits.
///
/// # Examples
/// ```
/// use rodimpact::{report::value_json, field::q};
/// let v = value_json(&q(-1, 5), 3);
/// assert_eq!(v["exact"], "-1/5");
/// assert_eq!(v["decimal"], "-0.200");
/// ```
pub fn value_json(x: &Q, digits: usize) -> Value {
    json!({ "exact": x.to_string(), "decimal": number::decimal(x, digits) })
}
