//! The summary of `impact --batch` for people (standard error) and for a CI job
//! (`--summary-json FILE`): the scenes, the answers the claims match and are closest to, the
//! findings with their scenes, and the known findings' verdict.

use crate::batch::{ImpactBatchSummary, KnownFindings, Scenes};
use serde_json::{Value, json};

/// The scenes a finding was found in, the first five named.
fn shown(scenes: &Scenes) -> String {
    let first: Vec<&str> = scenes.named.iter().take(5).map(String::as_str).collect();
    format!(
        "{} ({}{})",
        scenes.count,
        first.join(", "),
        if scenes.count > 5 { ", ..." } else { "" }
    )
}

/// The summary as text, for standard error; with `expected` (and its file's name), what the
/// known findings allow.
///
/// # Examples
/// ```
/// use rodimpact::batch::ImpactBatchSummary;
/// use rodimpact::report::impact_batch_text;
/// let mut s = ImpactBatchSummary { scenes: 2, claimed: 2, ..Default::default() };
/// s.findings.entry("energy-gain".into()).or_default().push("tilted");
/// assert!(impact_batch_text(&s, None).contains("  energy-gain: 1 (tilted)\n"));
/// ```
pub fn impact_batch_text(
    summary: &ImpactBatchSummary,
    expected: Option<(&KnownFindings, &str)>,
) -> String {
    let mut out = format!(
        "{} scene{}, {} with a claimed state\n",
        summary.scenes,
        if summary.scenes == 1 { "" } else { "s" },
        summary.claimed
    );
    let list = |counts: &std::collections::BTreeMap<String, usize>| -> String {
        counts
            .iter()
            .map(|(k, v)| format!("{k} {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !summary.matched.is_empty() {
        out.push_str(&format!(
            "claims matching each exact answer: {}\n",
            list(&summary.matched)
        ));
    }
    if !summary.closest.is_empty() {
        out.push_str(&format!(
            "closest exact answer: {}\n",
            list(&summary.closest)
        ));
    }
    if summary.claimed == 0 {
        out.push_str(
            "nothing audited: no line has a \"claimed\" state (an engine's bodies after)\n",
        );
    } else if summary.findings.is_empty() {
        out.push_str("every claim matches an exact answer\n");
    } else {
        out.push_str("findings:\n");
        for (finding, ids) in &summary.findings {
            out.push_str(&format!("  {finding}: {}\n", shown(ids)));
        }
    }
    if let Some((expected, file)) = expected {
        if summary.unexpected.is_empty() {
            out.push_str(&format!(
                "every finding is known ({file}: {} of {} entries used)\n",
                summary.used.len(),
                expected.entries.len()
            ));
        } else {
            out.push_str(&format!("findings {file} does not allow:\n"));
            for (finding, ids) in &summary.unexpected {
                out.push_str(&format!("  {finding}: {}\n", shown(ids)));
            }
        }
    }
    out
}

/// The summary as JSON, for a CI job: `scenes`, `claimed`, `matched` and `closest` (counts per
/// answer), `findings` (per finding, its count and the first 100 scenes' ids, escaped), with known findings `unexpected`
/// and `entries_used`, and `passed` (the exit status 0).
///
/// # Examples
/// ```
/// use rodimpact::batch::ImpactBatchSummary;
/// use rodimpact::report::impact_batch_json;
/// let s = ImpactBatchSummary { scenes: 1, claimed: 1, ..Default::default() };
/// assert_eq!(impact_batch_json(&s, false)["passed"], true);
/// ```
pub fn impact_batch_json(summary: &ImpactBatchSummary, with_expected: bool) -> Value {
    let by = |m: &std::collections::BTreeMap<String, Scenes>| -> Value {
        m.iter()
            .map(|(k, s)| (k.clone(), json!({"count": s.count, "scenes": s.named})))
            .collect::<serde_json::Map<String, Value>>()
            .into()
    };
    let mut out = json!({
        "scenes": summary.scenes,
        "claimed": summary.claimed,
        "matched": summary.matched,
        "closest": summary.closest,
        "findings": by(&summary.findings),
        "passed": summary.passed(with_expected),
    });
    if with_expected {
        out["unexpected"] = by(&summary.unexpected);
        out["entries_used"] = json!(summary.used);
    }
    out
}
