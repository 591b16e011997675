//! `batch --summary-json FILE`: the batch's summary for a machine (a CI job), the same facts as
//! the text on standard error.

use super::batch_passed;
use crate::batch::{Finding, KnownFindings, Summary};
use crate::field::decimal;
use serde_json::{Value, json};

/// The summary as JSON: rows and laws, per claimed output the counts, the largest and median
/// relative errors (decimal strings; `"inf"` for an infinite one) and the rows with a wrong
/// claim, per diagnosis the rows and the first ids, the baseline's verdict (with `--expect`),
/// and `passed` (the exit status 0).
///
/// # Examples
/// ```
/// use rodimpact::batch::{Arithmetic, Batch, Summary};
/// use rodimpact::report::batch_summary_json;
/// let b = Batch::new("id,m,M,a,v,V,omega", Arithmetic::Exact)?;
/// let mut s = Summary::default();
/// s.add(&b.row(1, "end,1,1,1,3/5,2/5,6/5")?);
/// s.add(&b.row(2, "miss,1,1,1/2,1,0,0")?);
/// let json = batch_summary_json(&s, None);
/// assert_eq!(json["rows"], 2);
/// assert_eq!(json["claims"]["v"]["wrong"], 1);
/// assert_eq!(json["claims"]["v"]["wrong_rows"][0], serde_json::json!({"id": "miss", "claims": 1}));
/// assert_eq!(json["claims"]["v"]["max_rel_error"], "2.67");
/// assert_eq!(json["diagnosis"]["no-contact"]["rows"], 1);
/// assert_eq!(json["diagnosis"]["ok"]["rows"], 1);
/// assert_eq!(json["passed"], false);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn batch_summary_json(summary: &Summary, expected: Option<&KnownFindings>) -> Value {
    let mut claims = serde_json::Map::new();
    for (name, stats) in summary.outputs() {
        if stats.compared() == 0 {
            continue;
        }
        let listed: Vec<Value> = stats
            .wrong_rows()
            .iter()
            .map(|(id, n)| json!({"id": id, "claims": n}))
            .collect();
        let shown: usize = stats.wrong_rows().iter().map(|(_, n)| n).sum();
        claims.insert(
            name.to_string(),
            json!({
                "compared": stats.compared(),
                "wrong": stats.wrong(),
                "not_finite": stats.not_finite(),
                "max_rel_error": stats.max_rel_error().map_or("inf".to_string(), |r| decimal::decimal(r, 3)),
                "median_rel_error": stats.median().map(|m| if m.is_finite() { format!("{m:.1e}") } else { "inf".to_string() }),
                "wrong_rows": listed,
                "wrong_claims_not_listed": stats.wrong() - shown,
            }),
        );
    }
    let mut diagnosis = serde_json::Map::new();
    for (name, rows) in summary.diagnoses() {
        let mut entry = json!({ "rows": rows });
        if let Some(finding) = Finding::ALL.iter().find(|f| f.name() == name) {
            let (ids, more) = summary.examples(*finding);
            entry["ids"] = json!(ids);
            entry["more"] = json!(more);
        }
        diagnosis.insert(name.to_string(), entry);
    }
    let mut out = json!({
        "rows": summary.rows,
        "laws_checked": summary.laws_unchecked == 0,
        "laws_failed": summary.laws_failed,
        "claims": claims,
        "diagnosis": diagnosis,
    });
    if let Some(expected) = expected {
        let empty = crate::batch::Baseline::default();
        let tally = summary.baseline().unwrap_or(&empty);
        out["expected"] = json!({
            "rows_expected": tally.rows_expected,
            "rows_unexpected": tally.rows_unexpected,
            "unexpected": tally.unexpected.iter().map(|(id, names)| json!({"id": id, "findings": names})).collect::<Vec<_>>(),
            "unmatched_lines": tally.unmatched(expected)
                .map(|e| json!({"line": e.line, "id": e.id, "finding": e.finding}))
                .collect::<Vec<_>>(),
        });
    }
    out["passed"] = json!(batch_passed(summary));
    out
}
