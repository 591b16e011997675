//! The report of `rodimpact stability`: error in units of cond u and run time per backend, as
//! Markdown or JSON.

use crate::stability::BackendStats;
use serde_json::{Value, json};

/// The stability report as a Markdown table, one row per backend.
///
/// # Examples
/// ```
/// use rodimpact::{report::stability_markdown, stability::compare_backends};
/// let md = stability_markdown(&compare_backends(5));
/// assert!(md.contains("| f64/sq |"));
/// ```
pub fn stability_markdown(rows: &[BackendStats]) -> String {
    let mut out = String::from(
        "Error in units of cond*u (u = 2^-53 for f64 and interval, 2^-24 for f32) over the scenes \
         in range for each format: the 27 suite scenes (items 1-22 of docs/stability.md) plus a seeded \
         sweep (f64: +-300 decades, f32: +-36). The formulas: naive is the paper's closed form \
         (its intermediate products overflow and underflow on extreme scenes); sq is the same \
         formulas with binary exponents carried as integers (exact power-of-two rescaling, \
         the library's float path); scomp is sq with q - e computed by error-free transforms, \
         so v stays accurate where the projectile nearly stops. scenes counts the scenes in \
         range for the format (every input and exact output a normal number of it): exact \
         arithmetic has no range, so it counts every scene (suite and f64 sweep), the floats \
         only those they can hold. The interval's error is its worst end (inf when an end overflows). Spurious 0 counts v in \
         the stop zone too (cond u > 1e-3), where no float formula can decide v. Times: \
         median over the suite scenes of the median time per evaluation.\n\n\
         | backend | scenes | max err/(cond u) | median err/(cond u) | NaN | inf | spurious 0 | not enclosed | median time (ns) |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {} | {:.3e} | {:.3e} | {} | {} | {} | {} | {:.1} |\n",
            r.backend.name(),
            r.scenes,
            r.max,
            r.median,
            r.nan,
            r.inf,
            r.spurious_zero,
            r.not_enclosed,
            r.nanos
        ));
    }
    out
}

/// The stability report as JSON: a list of rows, one per backend.
///
/// # Examples
/// ```
/// use rodimpact::{report::stability_json, stability::compare_backends};
/// let j = stability_json(&compare_backends(5));
/// assert_eq!(j[1]["backend"], "f64/sq");
/// ```
pub fn stability_json(rows: &[BackendStats]) -> Value {
    Value::Array(
        rows.iter()
            .map(|r| {
                json!({
                    "backend": r.backend.name(),
                    "scenes": r.scenes,
                    "max_error_cond_u": r.max,
                    "median_error_cond_u": r.median,
                    "nan": r.nan,
                    "inf": r.inf,
                    "spurious_zero": r.spurious_zero,
                    "not_enclosed": r.not_enclosed,
                    "median_nanos": r.nanos,
                })
            })
            .collect(),
    )
}
