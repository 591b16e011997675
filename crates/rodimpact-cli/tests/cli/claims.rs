//! The expected verdict of every claim, in one table, and the headline the reports derive from
//! the verdicts.
//!
//! Most claims are PROVED without a mark; the table lists the others, each with its verdict as
//! the reports print it (`REFUTED (as the paper argues)`, `QUALIFIED`, `PROVED †` for a verdict
//! that also rests on a step argued by hand). A claim added to the registry is expected PROVED
//! unless it is listed here.

use crate::common;

use common::rodimpact;
use rodimpact::claims::{Paper, decide_all, registry};
use rodimpact::report::{hand_step_note, summary_line, verdict_mark};
use serde_json::Value;

/// Every claim whose verdict is not a plain PROVED, in registry order.
const NOT_PLAINLY_PROVED: &[(&str, &str)] = &[
    ("C3", "REFUTED (as the paper argues)"),
    ("C8", "QUALIFIED"),
    ("C18", "PROVED †"),
    ("C31", "QUALIFIED"),
    ("C32", "QUALIFIED"),
    ("C40", "PROVED †"),
    ("C42", "QUALIFIED"),
    ("C46", "PROVED †"),
    ("X12", "PROVED †"),
    ("X19", "PROVED †"),
    ("X22", "QUALIFIED"),
    ("X26", "PROVED †"),
    ("X32", "PROVED †"),
    ("X33", "PROVED †"),
    ("X34", "REFUTED"),
    ("X37", "PROVED †"),
];

/// The verdict, as printed, that the table expects for claim `id`.
fn expected(id: &str) -> &'static str {
    NOT_PLAINLY_PROVED
        .iter()
        .find(|(listed, _)| *listed == id)
        .map_or("PROVED", |(_, verdict)| verdict)
}

/// The ids of the table with this printed verdict.
fn listed(verdict: &str) -> Vec<&'static str> {
    NOT_PLAINLY_PROVED
        .iter()
        .filter(|(_, v)| *v == verdict)
        .map(|(id, _)| *id)
        .collect()
}

#[test]
fn every_claim_has_its_expected_verdict() {
    let decided = decide_all(&Paper::as_printed());
    let mut wrong = Vec::new();
    for d in &decided {
        let (id, found) = (d.claim.id, verdict_mark(d));
        if found != expected(id) {
            wrong.push(format!(
                "{id}: expected {}, found {found} ({:?})",
                expected(id),
                d.verdict
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // The table names registered claims only, in registry order.
    let order: Vec<&str> = registry().iter().map(|e| e.id).collect();
    let positions: Vec<usize> = NOT_PLAINLY_PROVED
        .iter()
        .map(|(id, _)| {
            order
                .iter()
                .position(|r| r == id)
                .unwrap_or_else(|| panic!("{id} is not registered"))
        })
        .collect();
    assert!(positions.windows(2).all(|w| w[0] < w[1]), "{positions:?}");
}

/// The headline of the reports, written out from the table: the counts of each verdict, the
/// refuted intuition counted apart, and the verdicts resting on a step argued by hand.
fn headline() -> (String, String) {
    let total = registry().len();
    let intuitions = listed("REFUTED (as the paper argues)");
    let (refuted, qualified) = (listed("REFUTED").len(), listed("QUALIFIED").len());
    let proved = total - intuitions.len() - refuted - qualified;
    let by_hand = listed("PROVED †");
    assert_eq!(intuitions, ["C3"], "the wording below is for one intuition");
    let named = listed("REFUTED").join(", ");
    let summary = format!(
        "{total} claims: {proved} PROVED, {refuted} REFUTED ({named}), {qualified} QUALIFIED, and 1 \
         intuition REFUTED as the paper argues (C3)."
    );
    let hand = format!(
        "† {} verdicts ({}) also rest on a step argued by hand, not machine-checked; each \
         certificate's formalisation states that step.",
        by_hand.len(),
        by_hand.join(", ")
    );
    (summary, hand)
}

#[test]
fn the_summary_counts_the_verdicts_of_the_table() {
    let decided = decide_all(&Paper::as_printed());
    let (summary, hand) = headline();
    assert_eq!(summary_line(&decided), summary);
    assert_eq!(hand_step_note(&decided).as_deref(), Some(hand.as_str()));
}

/// Regression (NEWCOMER #12): the headline read "66 PROVED, 1 REFUTED, 5 QUALIFIED", and a
/// teacher took the REFUTED for an error in the paper, though it is C3, the intuition the paper
/// itself refutes; and verdicts resting on a step argued by hand looked like the others.
#[test]
fn the_headline_counts_the_refuted_intuition_apart_and_marks_hand_steps() {
    let (code, stdout, _) = rodimpact(&["paper"]);
    assert_eq!(code, 0);
    let (summary, hand) = headline();
    assert!(stdout.contains(&summary), "{summary}");
    assert!(stdout.contains(&hand), "{hand}");
    for (id, verdict) in NOT_PLAINLY_PROVED {
        let line = stdout
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{id} ")))
            .unwrap();
        assert!(line.contains(verdict), "{line}");
    }

    let (_, json, _) = rodimpact(&["prove", "--json"]);
    let list: Vec<Value> = serde_json::from_str(&json).unwrap();
    let ids_where = |key: &str| -> Vec<String> {
        list.iter()
            .filter(|c| c[key] == true)
            .map(|c| c["id"].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(ids_where("hand_step"), listed("PROVED †"));
    assert_eq!(
        ids_where("intuition"),
        listed("REFUTED (as the paper argues)")
    );
}
