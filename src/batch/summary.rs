//! The totals of a batch: rows, laws, and per claimed output the count wrong, the largest and
//! the median relative error (from a bounded histogram, so memory stays flat in the rows).

use super::audit::Finding;
use super::expected::{ExpectedEntry, KnownFindings};
use super::plan::{CLAIMS, Diagnosis, SolvedRow};
use super::rel_error::RelError;
use crate::field::Q;
use std::borrow::Cow;
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// Counts, the largest relative error and a bounded histogram for the median, per claimed
/// output.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Arithmetic, Summary};
/// let b = Batch::new("m,M", Arithmetic::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&b.row(1, "1,1").unwrap());
/// assert_eq!((s.rows, s.laws_failed, s.wrong()), (1, 0, 0));
/// ```
#[derive(Debug, Clone, Default)]
pub struct Summary {
    /// Data rows processed.
    pub rows: usize,
    /// Rows whose laws did not hold exactly (exact arithmetic).
    pub laws_failed: usize,
    /// Rows whose laws were not checked (f64 arithmetic).
    pub laws_unchecked: usize,
    outputs: [OutputStats; CLAIMS.len()],
    /// Audited rows per finding (in [`Finding::ALL`] order), rows found `ok`, rows not audited.
    findings: [usize; Finding::ALL.len()],
    audited_ok: usize,
    not_audited: usize,
    findings_rows: usize,
    /// Per finding, the first [`FINDING_EXAMPLES`] distinct row labels, and whether more rows
    /// had it.
    examples: [(Vec<String>, bool); Finding::ALL.len()],
    baseline: Option<Baseline>,
}

/// The batch against its baseline (`--expect`): rows whose findings it allows, rows with new
/// ones, and the entries used.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Baseline {
    /// Rows with findings (or wrong claims), every one allowed.
    pub rows_expected: usize,
    /// Rows with a finding (or a wrong claim) no entry allows.
    pub rows_unexpected: usize,
    /// The first [`WRONG_ROWS_SHOWN`] rows with new findings: label and the findings.
    pub unexpected: Vec<(String, Vec<&'static str>)>,
    /// The entries (0-based, in file order) that allowed some row's finding.
    pub used: std::collections::BTreeSet<usize>,
}

impl Baseline {
    /// The baseline's entries that allowed no row's finding (known differences that are gone),
    /// in file order.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Baseline, KnownFindings};
    /// let known = KnownFindings::parse("known.csv", "id,finding\nend,off\nold,off\n")?;
    /// let tally = Baseline { used: [0].into(), ..Baseline::default() };
    /// let lines: Vec<usize> = tally.unmatched(&known).map(|e| e.line).collect();
    /// assert_eq!(lines, [3]);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn unmatched<'a>(
        &self,
        expected: &'a KnownFindings,
    ) -> impl Iterator<Item = &'a ExpectedEntry> {
        expected
            .entries
            .iter()
            .enumerate()
            .filter(|(k, _)| !self.used.contains(k))
            .map(|(_, entry)| entry)
    }
}

/// How many rows (by `id`, or number) the summary names per finding.
pub const FINDING_EXAMPLES: usize = 5;

/// The claims of one output (v, V or omega) over the batch: counts, the largest relative
/// error, and a histogram of relative errors rounded to two significant digits for the median.
#[derive(Debug, Clone, Default)]
pub struct OutputStats {
    compared: usize,
    wrong: usize,
    not_finite: usize,
    /// `None` before the first claim; `Some(None)` once an infinite error was seen; else the
    /// largest error as its row computed it (for ties) and reduced (printed).
    max: Option<Option<(RelError, Q)>>,
    /// The nearest f64 to the largest finite error (0 before one is seen): rounding to
    /// nearest is monotone, so a claim whose error rounds below it is not larger, one that
    /// rounds above it is, and only a tie takes the exact comparison.
    max_nearest: f64,
    /// Relative errors rounded to 2 significant digits (f64 bits, ordered as the values).
    histogram: BTreeMap<u64, usize>,
    /// The first [`WRONG_ROWS_SHOWN`] distinct rows (by label) with a wrong claim, and how
    /// many wrong claims each label had.
    wrong_rows: Vec<(String, usize)>,
    /// The last label found absent from a full `wrong_rows` (which stays absent: the list
    /// never changes once full). A label's rows come together in an engine's log, and each
    /// of them would look through the whole list again.
    absent: String,
    /// The last nonzero error's nearest f64 (its bits) and that rounded to two digits: an
    /// engine repeats a wrong value row after row (a J of 0, an error of exactly 1).
    last_rounded: Option<(u64, f64)>,
}

/// How many rows with a wrong claim the summary names, per output.
pub const WRONG_ROWS_SHOWN: usize = 10;

impl Summary {
    /// Adds one row (see the type's example).
    pub fn add(&mut self, row: &SolvedRow) {
        self.rows += 1;
        match row.laws_held {
            Some(true) => {}
            Some(false) => self.laws_failed += 1,
            None => self.laws_unchecked += 1,
        }
        match &row.diagnosis {
            None => {}
            Some(Diagnosis::NotAudited) => self.not_audited += 1,
            Some(Diagnosis::Findings(found)) if found.is_empty() => self.audited_ok += 1,
            Some(Diagnosis::Findings(found)) => {
                self.findings_rows += 1;
                let label = label_of(row);
                for f in found {
                    self.findings[*f as usize] += 1;
                    let (names, more) = &mut self.examples[*f as usize];
                    if !names.iter().any(|name| *name == label) {
                        if names.len() < FINDING_EXAMPLES {
                            names.push(label.to_string());
                        } else {
                            *more = true;
                        }
                    }
                }
            }
        }
        if let Some(expectation) = &row.expectation {
            let tally = self.baseline.get_or_insert_with(Baseline::default);
            tally.used.extend(expectation.used.iter().copied());
            if !expectation.unexpected.is_empty() {
                tally.rows_unexpected += 1;
                if tally.unexpected.len() < WRONG_ROWS_SHOWN {
                    tally
                        .unexpected
                        .push((label_of(row).into_owned(), expectation.unexpected.clone()));
                }
            } else if !expectation.used.is_empty() {
                tally.rows_expected += 1;
            }
        }
        // Named once, and copied only into the few rows the summary keeps.
        let label = row.checks.iter().any(|v| !v.ok).then(|| label_of(row));
        for v in &row.checks {
            let s = &mut self.outputs[v.output];
            s.compared += 1;
            s.wrong += usize::from(!v.ok);
            s.not_finite += usize::from(v.not_finite);
            if let (false, Some(label)) = (v.ok, &label) {
                s.count_wrong(label);
            }
            // The row's own nearest f64 orders it; the exact values only where those tie.
            let near = v.nearest;
            let bigger = match (&s.max, &v.error) {
                (None, _) | (Some(Some(_)), None) => true,
                (Some(Some((old, _))), Some(new)) => match near.total_cmp(&s.max_nearest) {
                    Ordering::Equal => new.cmp_error(old) == Ordering::Greater,
                    other => other == Ordering::Greater,
                },
                _ => false,
            };
            if bigger {
                // Reduced here, at a new maximum only: the summary's is printed.
                s.max = Some(v.error.as_ref().map(|e| (e.clone(), e.value())));
                s.max_nearest = near;
            }
            let rounded = match (&v.error, s.last_rounded) {
                (Some(r), _) if r.is_zero() => 0.0,
                (Some(_), Some((bits, rounded))) if bits == near.to_bits() => rounded,
                (Some(_), _) => {
                    let rounded = two_significant(near);
                    s.last_rounded = Some((near.to_bits(), rounded));
                    rounded
                }
                (None, _) => f64::INFINITY,
            };
            *s.histogram.entry(rounded.to_bits()).or_default() += 1;
        }
    }

    /// Claims that were wrong, over all outputs.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,3/5").unwrap());
    /// s.add(&b.row(2, "1,1,0.6000001").unwrap());
    /// assert_eq!(s.wrong(), 1);
    /// ```
    pub fn wrong(&self) -> usize {
        self.outputs.iter().map(|c| c.wrong).sum()
    }

    /// Rows per diagnosis, in column order: each finding with its count (a row with several
    /// findings counts once for each), then `ok`, then `not audited` (a state claim missing);
    /// only those that occurred. Empty when no row was audited.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("m,M,v,V,omega", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,3/5,2/5,6/5").unwrap());
    /// s.add(&b.row(2, "1,1,1,0,0").unwrap());
    /// s.add(&b.row(3, "1,1,0.6,0.4,").unwrap());
    /// assert_eq!(s.diagnoses(), [("no-contact", 1), ("ok", 1), ("not audited", 1)]);
    /// ```
    pub fn diagnoses(&self) -> Vec<(&'static str, usize)> {
        Finding::ALL
            .iter()
            .map(|f| (f.name(), self.findings[*f as usize]))
            .chain([("ok", self.audited_ok), ("not audited", self.not_audited)])
            .filter(|(_, n)| *n > 0)
            .collect()
    }

    /// The first [`FINDING_EXAMPLES`] distinct rows with `finding` (their `id`, or `row N`),
    /// and whether other rows had it too.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Finding, Summary};
    /// let b = Batch::new("id,m,M,v,V,omega", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "missed,1,1,1,0,0").unwrap());
    /// s.add(&b.row(2, "missed,1,1,1,0,0").unwrap());
    /// let (names, more) = s.examples(Finding::NoContact);
    /// assert_eq!((names, more), (&["missed".to_string()][..], false));
    /// ```
    pub fn examples(&self, finding: Finding) -> (&[String], bool) {
        let (names, more) = &self.examples[finding as usize];
        (names, *more)
    }

    /// Rows whose audit found something (each counted once).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("m,M,v,V,omega", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,1,0,0").unwrap()); // no contact
    /// s.add(&b.row(2, "1,1,3/5,2/5,6/5").unwrap());
    /// assert_eq!(s.rows_with_findings(), 1);
    /// ```
    pub fn rows_with_findings(&self) -> usize {
        self.findings_rows
    }

    /// The batch against its baseline, when it has one (`--expect`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Arithmetic, Batch, KnownFindings, Summary};
    /// let known = KnownFindings::parse("known.csv", "id,finding\nend,no-contact\n")?;
    /// let b = Batch::new("id,m,M,a,v,V,omega", Arithmetic::Exact)?.with_expected(known)?;
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "end,1,1,1,1,0,0")?); // no contact: known
    /// s.add(&b.row(2, "mid,1,1,1/2,1,0,0")?); // no contact: new
    /// s.add(&b.row(3, "fine,1,1,1/2,3/11,8/11,12/11")?);
    /// let tally = s.baseline().unwrap();
    /// assert_eq!((tally.rows_expected, tally.rows_unexpected), (1, 1));
    /// assert_eq!(tally.unexpected, [("mid".to_string(), vec!["no-contact"])]);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn baseline(&self) -> Option<&Baseline> {
        self.baseline.as_ref()
    }

    /// The statistics of each claimed output, named (`v`, `V`, `omega`, `J`, `energy_before`,
    /// `energy_after`, and an oblique scene's `vt`, `Vt`, `spin_after`, `tangential_impulse`),
    /// in that order;
    /// outputs without a claim column have nothing compared.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("m,M,omega", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,6/5").unwrap());
    /// let compared: Vec<(&str, usize)> = s.outputs().map(|(name, o)| (name, o.compared())).collect();
    /// assert_eq!(compared, [("v", 0), ("V", 0), ("omega", 1), ("J", 0), ("energy_before", 0),
    ///     ("energy_after", 0), ("vt", 0), ("Vt", 0), ("spin_after", 0), ("tangential_impulse", 0)]);
    /// ```
    pub fn outputs(&self) -> impl Iterator<Item = (&'static str, &OutputStats)> {
        CLAIMS.into_iter().zip(&self.outputs)
    }
}

impl OutputStats {
    /// Claims compared.
    pub fn compared(&self) -> usize {
        self.compared
    }

    /// Claims that were wrong.
    pub fn wrong(&self) -> usize {
        self.wrong
    }

    /// Claims that were not a finite number (NaN, an infinity): wrong, with an infinite error.
    pub fn not_finite(&self) -> usize {
        self.not_finite
    }

    /// The first [`WRONG_ROWS_SHOWN`] distinct rows with a wrong claim, in input order: each
    /// row's label (its `id`, or `row N`) and its wrong claims of this output (an engine log
    /// may repeat an id over several runs).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("id,m,M,v", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// for (n, line) in ["end,1,1,0.7", "end,1,1,0.8", "mid,1,1,3/5"].iter().enumerate() {
    ///     s.add(&b.row(n + 1, line).unwrap());
    /// }
    /// let (_, v) = s.outputs().next().unwrap();
    /// assert_eq!(v.wrong_rows(), [("end".to_string(), 2)]);
    /// ```
    pub fn wrong_rows(&self) -> &[(String, usize)] {
        &self.wrong_rows
    }

    /// The largest relative error, exactly; `None` when some error was infinite (a zero value
    /// with a nonzero claim) or nothing was compared.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{batch::{Batch, Arithmetic, Summary}, field::q};
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,3/5").unwrap());
    /// s.add(&b.row(2, "1,1,3/4").unwrap());
    /// let (_, v) = s.outputs().next().unwrap();
    /// assert_eq!(v.max_rel_error(), Some(&q(1, 4)));
    /// ```
    pub fn max_rel_error(&self) -> Option<&Q> {
        self.max.as_ref().and_then(Option::as_ref).map(|(_, q)| q)
    }

    /// Counts a wrong claim of the row labelled `label`.
    fn count_wrong(&mut self, label: &str) {
        if self.wrong_rows.len() == WRONG_ROWS_SHOWN && self.absent == label {
            return;
        }
        if let Some(at) = self.wrong_rows.iter().position(|(l, _)| l == label) {
            self.wrong_rows[at].1 += 1;
        } else if self.wrong_rows.len() < WRONG_ROWS_SHOWN {
            self.wrong_rows.push((label.to_string(), 1));
        } else {
            self.absent.clear();
            self.absent.push_str(label);
        }
    }

    /// The median relative error, rounded to two significant digits (infinite for an infinite
    /// error); `None` when nothing was compared.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Summary};
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
    /// let mut s = Summary::default();
    /// for (n, claim) in [(1, "3/5"), (2, "0.61"), (3, "0.62")].into_iter() {
    ///     s.add(&b.row(n, &format!("1,1,{claim}")).unwrap());
    /// }
    /// let (_, v) = s.outputs().next().unwrap();
    /// assert_eq!(v.median(), Some(0.017)); // |0.61 - 3/5| / (3/5) = 0.01666...
    /// ```
    pub fn median(&self) -> Option<f64> {
        let mut seen = 0;
        for (&bits, &count) in &self.histogram {
            seen += count;
            if 2 * seen > self.compared {
                return Some(f64::from_bits(bits));
            }
        }
        None
    }
}

/// A row's name in the summary: its label (its `id`), else `row N`.
fn label_of(row: &SolvedRow) -> Cow<'_, str> {
    match &row.label {
        Some(label) => Cow::Borrowed(label),
        None => Cow::Owned(format!("row {}", row.number)),
    }
}

/// `x` rounded to two significant digits (half to even, on its exact binary value) and read
/// back as the nearest f64: what `format!("{x:.1e}").parse::<f64>()` gives (infinity where
/// that fails), on machine words for the positive floats a relative error takes (the
/// formatting cost more than the rest of a summary's row).
fn two_significant(x: f64) -> f64 {
    let formatted = || format!("{x:.1e}").parse::<f64>().unwrap_or(f64::INFINITY);
    on_words_two_significant(x).unwrap_or_else(formatted)
}

/// [`two_significant`] on words: `None` outside the range it covers (a negative, zero or
/// non-finite `x`, a quotient past 2^256, a power of ten past 10^22).
fn on_words_two_significant(x: f64) -> Option<f64> {
    use crate::field::decimal::{EXACT_POWERS_OF_TEN, Rounding, round_float, round_on_words};
    use crate::field::int::U256;
    // The float alone where it decides (most relative errors), else its exact value on words.
    let on_words = || {
        let (false, odd, exponent) = crate::field::float_parts(x)? else {
            return None;
        };
        // x = odd 2^exponent as a fraction of words.
        let shift = u32::try_from(exponent.unsigned_abs())
            .ok()
            .filter(|k| *k < 200)?;
        let odd = U256 {
            hi: 0,
            lo: odd.into(),
        };
        let (n, d) = if exponent >= 0 {
            (odd.shl(shift), U256::ONE)
        } else {
            (odd, U256::ONE.shl(shift))
        };
        round_on_words(false, n, d, 2, Rounding::HalfEven, Some(x))
    };
    // Rounded to digits 10^s with two digits.
    let (digits, exp) =
        round_float(x, 2).or_else(|| on_words().map(|(digits, exp, _)| (digits, exp)))?;
    let s = exp - 1;
    let power = *EXACT_POWERS_OF_TEN.get(usize::try_from(s.unsigned_abs()).ok()?)?;
    // One correctly rounded operation on exact operands: the nearest f64, as the parser gives.
    Some(if s >= 0 {
        digits as f64 * power
    } else {
        digits as f64 / power
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// Law: the summary's rounding to two digits on words is the formatter's, for every
        /// positive float (subnormals and huge ones included) and at decimal ties and carries.
        #[test]
        fn two_significant_digits_are_the_formatters(
            bits in 1u64..0x7ff0_0000_0000_0000, tie in 0u64..1000, k in -20i32..20,
        ) {
            let formatted = |x: f64| format!("{x:.1e}").parse::<f64>().unwrap();
            let x = f64::from_bits(bits);
            proptest::prop_assert_eq!(two_significant(x).to_bits(), formatted(x).to_bits());
            let near_tie = (tie as f64 + 0.5) * 10f64.powi(k);
            proptest::prop_assert_eq!(
                two_significant(near_tie).to_bits(),
                formatted(near_tie).to_bits()
            );
            // Whole numbers of units (1, 0.25, 3e-5): the scaled float lands on an integer.
            let whole = (tie + 1) as f64 * 10f64.powi(k) / 4.0;
            proptest::prop_assert_eq!(two_significant(whole).to_bits(), formatted(whole).to_bits());
        }
    }

    /// A row's relative error may be unreduced; the summary's maximum, which is printed, is
    /// in lowest terms.
    #[test]
    fn the_largest_relative_error_is_kept_in_lowest_terms() {
        use crate::batch::{Arithmetic, Batch};
        // An engine's row (a rod column): v = 3/5 claimed as 0.6000001, 5/30000000 off.
        let b = Batch::new("m,M,rod,v", Arithmetic::Exact).unwrap();
        let row = b.row(1, "1,1,uniform,0.6000001").unwrap();
        let mut s = Summary::default();
        s.add(&row);
        let max = s.outputs[0].max_rel_error().unwrap();
        assert_eq!(max.to_string(), "1/6000000");
        let reduced = Q::new(max.numer().clone(), max.denom().clone());
        assert_eq!(max.to_string(), reduced.to_string());
        assert_eq!(row.checks[0].rel_error().as_ref(), Some(max));
        // The premise: the row's own is not in lowest terms.
        let own = row.checks[0].error.as_ref().unwrap().unreduced();
        assert_ne!(own.numer(), reduced.numer());
    }

    /// An engine repeats a wrong value row after row: the median counts each row's own error,
    /// repeated or not (1, 1, 1/2 three times, 1, 1/2: the median is 1/2).
    #[test]
    fn repeated_errors_each_count_in_the_median() {
        use crate::batch::{Arithmetic, Batch};
        let b = Batch::new("m,M,J", Arithmetic::Exact).unwrap();
        // m = M = 1 at the end: J = 2/(1 + 1 + 3) = 2/5; a claim of 0 is off by 1, of 3/5 by 1/2.
        let mut s = Summary::default();
        for (n, claim) in [
            (1, "0"),
            (2, "0"),
            (3, "0.6"),
            (4, "0.6"),
            (5, "0.6"),
            (6, "0"),
            (7, "0.6"),
        ] {
            s.add(&b.row(n, &format!("1,1,{claim}")).unwrap());
        }
        let (_, j) = s.outputs().find(|(name, _)| *name == "J").unwrap();
        assert_eq!(j.median(), Some(0.5));
        assert_eq!(j.histogram.values().sum::<usize>(), 7);
        assert_eq!(j.histogram.get(&1f64.to_bits()), Some(&3));
    }

    #[test]
    fn ties_round_to_even_and_carry_into_a_new_digit() {
        for (x, want) in [
            (0.125, 0.12),
            (0.375, 0.38),
            (2.25, 2.2),
            (9.96, 10.0),
            (1.5e-17, 1.5e-17),
        ] {
            assert_eq!(two_significant(x), want, "{x}");
        }
    }
}
