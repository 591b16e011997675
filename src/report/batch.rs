//! The summary `rodimpact batch` prints on standard error.

use super::counted;
use crate::batch::{Baseline, Finding, KnownFindings, OutputStats, Summary};
use crate::field::decimal;

/// The summary of a batch: rows, laws (or that they were not checked, with the f64
/// arithmetic), and per claimed output the count wrong (naming the first
/// [`WRONG_ROWS_SHOWN`](crate::batch::WRONG_ROWS_SHOWN) rows), the maximum and the median
/// relative error.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Arithmetic, Summary};
/// use rodimpact::report::batch_summary;
/// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&b.row(1, "1,1,3/5").unwrap());
/// assert_eq!(batch_summary(&s), "1 row, laws held exactly on 1\nv: 1 claim, 0 wrong, max rel error 0, median 0\n");
/// s.add(&b.row(2, "1,1,0.6").unwrap());
/// s.add(&b.row(3, "1,1,0.61").unwrap());
/// assert!(batch_summary(&s).contains("v: 3 claims, 1 wrong (row 3), max rel error 0.0167, median 0"));
///
/// let f = Batch::new("m,M", Arithmetic::F64).unwrap();
/// let mut s = Summary::default();
/// s.add(&f.row(1, "1,1").unwrap());
/// assert_eq!(batch_summary(&s), "1 row (f64: conservation laws and diagnoses not checked)\n");
///
/// let engine = Batch::new("m,M,a,v,V,omega", Arithmetic::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&engine.row(1, "1,1,1/2,3/11,8/11,12/11").unwrap());
/// s.add(&engine.row(2, "1,1,1/2,0.63592,0.36408,0.54612").unwrap());
/// assert!(batch_summary(&s).ends_with("diagnosis of 2 rows:\n  \
///     energy-loss: 1 (row 2)\n  restitution-ignored: 1 (row 2)\n  ok: 1\n"), "{}", batch_summary(&s));
/// ```
pub fn batch_summary(summary: &Summary) -> String {
    let mut out = if summary.laws_unchecked > 0 {
        format!(
            "{} (f64: conservation laws and diagnoses not checked)\n",
            counted(summary.rows, "row")
        )
    } else {
        format!(
            "{}, laws held exactly on {}\n",
            counted(summary.rows, "row"),
            summary.rows - summary.laws_failed
        )
    };
    for (name, stats) in summary.outputs() {
        if stats.compared() == 0 {
            continue;
        }
        let max = match stats.max_rel_error() {
            Some(r) => decimal::decimal(r, 3),
            None => "inf".to_string(),
        };
        let median = match stats.median() {
            Some(0.0) => "0".to_string(),
            Some(x) => format!("{x:.1e}"),
            None => "-".to_string(),
        };
        let not_finite = match stats.not_finite() {
            0 => String::new(),
            n => format!(" ({n} not a finite number)"),
        };
        out.push_str(&format!(
            "{name}: {}, {} wrong{}, max rel error {max}{not_finite}, median {median}\n",
            counted(stats.compared(), "claim"),
            stats.wrong(),
            wrong_rows_text(stats),
        ));
    }
    let diagnoses = summary.diagnoses();
    if !diagnoses.is_empty() {
        out.push_str(&format!("diagnosis of {}:\n", counted(summary.rows, "row")));
        for (name, count) in diagnoses {
            let examples = Finding::ALL
                .iter()
                .find(|f| f.name() == name)
                .map(|f| summary.examples(*f))
                .filter(|(names, _)| !names.is_empty())
                .map(|(names, more)| {
                    format!(" ({}{})", names.join(", "), if more { ", ..." } else { "" })
                })
                .unwrap_or_default();
            out.push_str(&format!("  {name}: {count}{examples}\n"));
        }
    }
    out
}

/// ` (rows 3, 17 and 5 more)` (rows without an `id`), ` (free-end-3 ×3, pivot-1)` (by `id`,
/// with how many wrong claims a repeated id had), or nothing when no claim was wrong.
fn wrong_rows_text(stats: &OutputStats) -> String {
    let listed = stats.wrong_rows();
    if listed.is_empty() {
        return String::new();
    }
    let more = stats.wrong() - listed.iter().map(|(_, n)| n).sum::<usize>();
    let numbers: Option<Vec<&str>> = listed
        .iter()
        .map(|(label, n)| label.strip_prefix("row ").filter(|_| *n == 1))
        .collect();
    let items = match numbers {
        Some(numbers) if numbers.len() == 1 && more == 0 => format!("row {}", numbers[0]),
        Some(numbers) => format!("rows {}", numbers.join(", ")),
        None => listed
            .iter()
            .map(|(label, n)| {
                if *n > 1 {
                    format!("{label} ×{n}")
                } else {
                    label.clone()
                }
            })
            .collect::<Vec<_>>()
            .join(", "),
    };
    if more == 0 {
        format!(" ({items})")
    } else {
        format!(" ({items} and {more} more)")
    }
}

/// Everything `rodimpact batch` prints on standard error after the rows: the columns passed
/// through, the agreement rule (`claims agree ...`), the rules per class of rows
/// (`--tolerance`), the `atol` floor, then [`batch_summary`].
///
/// # Examples
/// ```
/// use rodimpact::batch::{Agreement, Arithmetic, Batch, Summary};
/// use rodimpact::report::batch_report;
/// let b = Batch::new("id,m,M,v", Arithmetic::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&b.row(1, "a,1,1,3/5").unwrap());
/// let rule = Agreement::parse_rtol("1e-9").unwrap();
/// assert_eq!(
///     batch_report(&s, &b.passed_through(), Some(&rule), &[], Some("1e-12")),
///     "passed through: id\nclaims agree within a relative 0.000000001\n\
///      claims also agree within 1e-12 of the scene's units (v0, v0/l, m v0, m v0^2/2)\n\
///      1 row, laws held exactly on 1\nv: 1 claim, 0 wrong, max rel error 0, median 0\n"
/// );
/// ```
pub fn batch_report(
    summary: &Summary,
    passed: &[&str],
    agreement: Option<&crate::batch::Agreement>,
    class_rules: &[crate::batch::ClassRule],
    atol: Option<&str>,
) -> String {
    use crate::echo::echo;
    let mut out = String::new();
    if !passed.is_empty() {
        let names: Vec<String> = passed.iter().map(|name| echo(name)).collect();
        out.push_str(&format!("passed through: {}\n", names.join(", ")));
    }
    if let Some(agreement) = agreement {
        out.push_str(&format!("claims agree {}\n", agreement.describe()));
    }
    for rule in class_rules {
        out.push_str(&format!("claims agree, on {}\n", rule.describe()));
    }
    if let Some(x) = atol {
        out.push_str(&format!(
            "claims also agree within {} of the scene's units (v0, v0/l, m v0, m v0^2/2)\n",
            echo(x.trim())
        ));
    }
    out.push_str(&batch_summary(summary));
    out
}

/// Whether a batch passed (`rodimpact batch`'s exit 0): every law held, and no wrong claim
/// and no finding, or, with a baseline (`--expect`), none the baseline does not allow.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Arithmetic, Batch, Summary};
/// use rodimpact::report::batch_passed;
/// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&b.row(1, "1,1,3/5").unwrap());
/// assert!(batch_passed(&s));
/// s.add(&b.row(2, "1,1,0.7").unwrap());
/// assert!(!batch_passed(&s));
/// ```
pub fn batch_passed(summary: &Summary) -> bool {
    match summary.baseline() {
        Some(baseline) => summary.laws_failed == 0 && baseline.rows_unexpected == 0,
        None => {
            summary.wrong() == 0 && summary.laws_failed == 0 && summary.rows_with_findings() == 0
        }
    }
}

/// The lines `batch --expect FILE` adds after the summary: how the rows with findings stand
/// against the baseline `file`, the rows with new findings, and the baseline lines that
/// matched no row (known differences that are gone).
///
/// # Examples
/// ```
/// use rodimpact::batch::{Arithmetic, Batch, KnownFindings, Summary};
/// use rodimpact::report::expected_report;
/// let known = KnownFindings::parse("known.csv", "id,finding\nend,no-contact\nold,off\n")?;
/// let b = Batch::new("id,m,M,a,v,V,omega", Arithmetic::Exact)?.with_expected(known.clone())?;
/// let mut s = Summary::default();
/// s.add(&b.row(1, "end,1,1,1,1,0,0")?);
/// s.add(&b.row(2, "mid,1,1,1/2,1,0,0")?);
/// assert_eq!(expected_report(&s, &known, std::path::Path::new("known.csv")),
///     "against known.csv: 1 row with known findings only, 1 with new ones: mid (no-contact)\n\
///      known.csv lines that matched no row: 3 (old,off)\n");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn expected_report(
    summary: &Summary,
    expected: &KnownFindings,
    file: &std::path::Path,
) -> String {
    let file = crate::echo::echo_path(file);
    let empty = Baseline::default();
    let tally = summary.baseline().unwrap_or(&empty);
    let mut out = format!(
        "against {file}: {} with known findings only, {} with new ones",
        counted(tally.rows_expected, "row"),
        tally.rows_unexpected
    );
    if !tally.unexpected.is_empty() {
        let rows: Vec<String> = tally
            .unexpected
            .iter()
            .map(|(label, names)| format!("{label} ({})", names.join(", ")))
            .collect();
        let more = tally.rows_unexpected - rows.len();
        out.push_str(&format!(": {}", rows.join(", ")));
        if more > 0 {
            out.push_str(&format!(" and {more} more"));
        }
    }
    out.push('\n');
    let unseen: Vec<String> = tally
        .unmatched(expected)
        .map(|e| format!("{} ({},{})", e.line, e.id, e.finding))
        .collect();
    if !unseen.is_empty() {
        out.push_str(&format!(
            "{file} lines that matched no row: {}\n",
            unseen.join(", ")
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{Arithmetic, Batch};

    #[test]
    fn a_zero_value_with_a_nonzero_claim_is_infinitely_wrong() {
        let b = Batch::new("m,M,a,omega", Arithmetic::Exact).unwrap();
        let row = b.row(1, "1,1,0,1/1000").unwrap();
        assert!(row.line.ends_with(",false,inf\n"), "{}", row.line);
        let mut s = Summary::default();
        s.add(&row);
        assert!(batch_summary(&s).contains("omega: 1 claim, 1 wrong (row 1), max rel error inf"));
    }

    #[test]
    fn more_wrong_rows_than_shown_are_counted() {
        let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
        let mut s = Summary::default();
        for n in 1..=13 {
            s.add(&b.row(n, "1,1,1").unwrap());
        }
        assert!(
            batch_summary(&s)
                .contains("v: 13 claims, 13 wrong (rows 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 and 3 more)"),
            "{}",
            batch_summary(&s)
        );
    }
}
