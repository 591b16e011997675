//! Verdicts: a printed number against the exact value (by significant figures), an exact number
//! against it (exactly), and the report that lists them.

use super::sigfig::{Precision, Printed, Tie, round_at, round_sig};
use super::units::{Measured, Scale, pi_bounds};
use super::{Claim, ClaimValue, Exact, Quantity};
use crate::field::decimal;
use crate::field::decimal::{magnitude, pow10};
use crate::field::{Field, Q, QSqrt};
use num_traits::{Signed, Zero};
use serde_json::{Value, json};
use std::cmp::Ordering;
use std::fmt::Write as _;

/// The outcome of one claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// The claim is right (to its own significant figures, exactly, or as an identity).
    Agrees,
    /// The claim is wrong.
    Disagrees,
    /// Wrong by exactly one unit in the last printed digit.
    LastDigit,
    /// Could not be decided (no valid scene found to test, or a value on a rounding tie
    /// beyond the available precision of pi).
    Undecided,
}

impl Verdict {
    /// Label in the text report.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Verdict;
    /// assert_eq!(Verdict::LastDigit.label(), "DISAGREES (last digit off by one)");
    /// ```
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Disagrees => "DISAGREES",
            Verdict::LastDigit => "DISAGREES (last digit off by one)",
            Verdict::Undecided => "UNDECIDED",
        }
    }

    /// Key in JSON output.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Verdict;
    /// assert_eq!(Verdict::LastDigit.key(), "last_digit_off_by_one");
    /// ```
    pub fn key(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Disagrees => "disagrees",
            Verdict::LastDigit => "last_digit_off_by_one",
            Verdict::Undecided => "undecided",
        }
    }
}

/// How far a claimed number is from the exact one: both values, to show the error as a
/// percentage or, for a claim twice the exact value or more, as a factor.
#[derive(Debug, Clone, PartialEq)]
pub struct RelError {
    /// The claimed value (a magnitude for omega), in SI.
    pub claimed: Q,
    /// The exact value (a magnitude for omega), nonzero.
    pub exact: Q,
    /// Whether the values are those of a counterexample scene (a refuted formula).
    pub at_counterexample: bool,
}

impl RelError {
    /// `(claimed - exact)/|exact|`, `None` when the exact value is 0.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::verdict::RelError;
    /// use rodimpact::field::q;
    /// let e = RelError::new(q(1, 2), q(1, 1)).unwrap();
    /// assert_eq!(e.value(), q(-1, 2));
    /// assert!(RelError::new(q(1, 1), q(0, 1)).is_none());
    /// ```
    pub fn new(claimed: Q, exact: Q) -> Option<RelError> {
        (!exact.is_zero()).then_some(RelError {
            claimed,
            exact,
            at_counterexample: false,
        })
    }

    /// The relative error `(claimed - exact)/|exact|` (-0.5 is -50 %).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::verdict::RelError;
    /// use rodimpact::field::q;
    /// assert_eq!(RelError::new(q(3, 1), q(-1, 1)).unwrap().value(), q(4, 1));
    /// ```
    pub fn value(&self) -> Q {
        (&self.claimed - &self.exact) / self.exact.abs()
    }

    /// As the report prints it: `×3.96` for a claim at least twice the exact value (same
    /// sign), otherwise a signed percentage to two significant figures (`-49 %`, `+0.036 %`,
    /// `-200 %`), never in scientific notation.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::verdict::RelError;
    /// use rodimpact::field::q;
    /// let text = |c, e| RelError::new(c, e).unwrap().to_text();
    /// assert_eq!(text(q(546, 100), q(2625, 1906)), "×3.96");
    /// assert_eq!(text(q(1, 10), q(480, 2437)), "-49 %");
    /// assert_eq!(text(q(189, 100), q(36, 19)), "-0.25 %");
    /// assert_eq!(text(q(-1, 1), q(1, 1)), "-200 %");
    /// assert_eq!(text(q(1, 1), q(1, 1)), "0 %");
    /// ```
    pub fn to_text(&self) -> String {
        let ratio = &self.claimed / &self.exact;
        let two = Q::from_integer(2.into());
        let text = if ratio >= two {
            format!("×{}", plain(&ratio, 3))
        } else {
            let percent = self.value() * Q::from_integer(100.into());
            let sign = if percent.is_positive() { "+" } else { "" };
            format!("{sign}{} %", plain(&percent, 2))
        };
        if self.at_counterexample {
            format!("{text} (at the counterexample)")
        } else {
            text
        }
    }
}

/// `x` rounded to `figures` significant figures and printed positionally (`250`, not `2.5e2`;
/// `0.036`), however large: at least `figures` digits, more when the integer part needs them.
fn plain(x: &Q, figures: u32) -> String {
    if x.is_zero() {
        return "0".into();
    }
    let rounded = round_sig(x, figures, Tie::Up);
    let digits = (magnitude(&rounded) + 1).max(i64::from(figures));
    let text = decimal::decimal(&rounded, usize::try_from(digits).unwrap_or(1));
    // Trailing zeros after the point carry no information at two figures (`-50.0` -> `-50`).
    match text.split_once('.') {
        Some((int, frac)) if frac.chars().all(|c| c == '0') => int.to_string(),
        _ => text,
    }
}

/// A scene where a refuted formula and the exact value differ.
#[derive(Debug, Clone, PartialEq)]
pub struct Counterexample {
    /// The free symbols' values, in the scene's order.
    pub point: Vec<(String, Q)>,
    /// The exact value there.
    pub exact: Exact,
    /// The claimed formula's value there.
    pub claimed: Exact,
}

impl Counterexample {
    /// The note of the text report, values in compact form.
    fn note(&self, quantity: &str) -> String {
        let values: Vec<String> = self
            .point
            .iter()
            .map(|(s, v)| format!("{s}={}", decimal::compact(v)))
            .collect();
        format!(
            "not an identity; counterexample {}: exact {quantity} = {}, claimed {}",
            if values.is_empty() {
                "(no free symbols)".to_string()
            } else {
                values.join(", ")
            },
            self.exact.compact(),
            self.claimed.compact()
        )
    }

    /// `{"at": {symbol: value}, "exact": "...", "claimed": "..."}`, every value exact.
    fn to_json(&self) -> Value {
        let at: serde_json::Map<String, Value> = self
            .point
            .iter()
            .map(|(s, v)| (s.clone(), Value::String(v.to_string())))
            .collect();
        json!({
            "at": at,
            "exact": self.exact.to_string(),
            "claimed": self.claimed.to_string(),
        })
    }
}

/// One row of the report.
#[derive(Debug, Clone, PartialEq)]
pub struct Decision {
    /// Claim name (`omega`).
    pub name: String,
    /// The claimed value as written.
    pub claim: String,
    /// The exact value in SI units (a fraction, a surd, or a formula).
    pub exact: String,
    /// The exact value when it is a number (its decimals are printed from it).
    pub value: Option<Exact>,
    /// How far the claim is from the exact value, when both are numbers.
    pub rel_error: Option<RelError>,
    /// A scene refuting a formula.
    pub counterexample: Option<Counterexample>,
    /// The verdict.
    pub verdict: Verdict,
    /// Remarks: ambiguous figures, bounds on pi, opposite sign, identity.
    pub notes: Vec<String>,
}

impl Decision {
    /// A row with no verdict yet.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Decision, Verdict};
    /// let d = Decision::new("v", "2.3", "7/3".into(), None);
    /// assert_eq!(d.verdict, Verdict::Undecided);
    /// ```
    pub fn new(name: &str, claim: &str, exact: String, value: Option<Exact>) -> Decision {
        Decision {
            name: name.to_string(),
            claim: claim.to_string(),
            exact,
            value,
            rel_error: None,
            counterexample: None,
            verdict: Verdict::Undecided,
            notes: Vec::new(),
        }
    }

    /// Whether the claim agrees.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Decision;
    /// assert!(!Decision::new("v", "2.3", "7/3".into(), None).agrees());
    /// ```
    pub fn agrees(&self) -> bool {
        self.verdict == Verdict::Agrees
    }

    /// Refutes the claim with a counterexample scene.
    pub(crate) fn refute(&mut self, counterexample: Counterexample, omega: bool) {
        self.verdict = Verdict::Disagrees;
        let (claimed, exact) = (
            midpoint(&counterexample.claimed, 40),
            midpoint(&counterexample.exact, 40),
        );
        let (claimed, exact) = if omega {
            (claimed.abs(), exact.abs())
        } else {
            (claimed, exact)
        };
        self.rel_error = RelError::new(claimed, exact).map(|r| RelError {
            at_counterexample: true,
            ..r
        });
        self.notes.push(counterexample.note(&self.name));
        self.counterexample = Some(counterexample);
    }

    /// The exact value and its decimal as the text report shows them (`36/19 ≈ 1.89474`).
    fn exact_text(&self) -> String {
        match &self.value {
            Some(v) => {
                let (exact, decimal) = (v.compact(), v.decimal(6));
                if exact == decimal || exact.starts_with('≈') {
                    exact
                } else {
                    format!("{exact} ≈ {decimal}")
                }
            }
            None => self.exact.clone(),
        }
    }

    /// The row as JSON: `decimal` correctly rounded to 30 significant digits, `rel_error` a
    /// number (`-0.5` for -50 %), `counterexample` an object.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Decision, Exact};
    /// use rodimpact::field::q;
    /// let j = Decision::new("v", "2.3", "7/3".into(), Some(Exact::Rational(q(7, 3)))).to_json();
    /// assert_eq!(j["verdict"], "undecided");
    /// assert_eq!(j["decimal"], "2.33333333333333333333333333333");
    /// ```
    pub fn to_json(&self) -> Value {
        json!({
            "name": self.name,
            "claim": self.claim,
            "exact": self.exact,
            "decimal": self.value.as_ref().map(|v| v.decimal(JSON_DIGITS)),
            "rel_error": self.rel_error.as_ref().map(|r| finite_number(&r.value())),
            "rel_error_at_counterexample": self.rel_error.as_ref().map(|r| r.at_counterexample),
            "verdict": self.verdict.key(),
            "counterexample": self.counterexample.as_ref().map(Counterexample::to_json),
            "notes": self.notes,
        })
    }
}

/// Significant digits of the decimals in JSON, as `solve --json` prints them.
const JSON_DIGITS: usize = 30;

/// A rational as a JSON number (the nearest f64), or null when it is beyond the f64 range.
fn finite_number(x: &Q) -> Value {
    let f = x.nearest_f64();
    if f.is_finite() { json!(f) } else { Value::Null }
}

/// What a symbolic scene left free and which defaults it applied.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneSummary {
    /// The free symbols, in the scene's order.
    pub free: Vec<String>,
    /// The defaults applied to quantities not given (`e = 1 (elastic)`, ...).
    pub defaults: Vec<String>,
}

/// The decisions for one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// For a symbolic scene, its free symbols and defaults; `None` for a numeric one.
    pub symbolic: Option<SceneSummary>,
    /// One decision per claim, in order.
    pub decisions: Vec<Decision>,
}

impl Report {
    /// How many claims agree.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// assert_eq!(Report { symbolic: None, decisions: vec![] }.agreeing(), 0);
    /// ```
    pub fn agreeing(&self) -> usize {
        self.decisions.iter().filter(|d| d.agrees()).count()
    }

    /// Whether every claim agrees.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// assert!(Report { symbolic: None, decisions: vec![] }.all_agree());
    /// ```
    pub fn all_agree(&self) -> bool {
        self.agreeing() == self.decisions.len()
    }

    /// The table: claim, exact, claimed, relative error, verdict, then notes; a symbolic
    /// scene starts with its free symbols and the defaults it applied.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Decision, Report};
    /// let r = Report { symbolic: None, decisions: vec![Decision::new("v", "2.3", "7/3".into(), None)] };
    /// assert!(r.to_text().contains("UNDECIDED"));
    /// ```
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        if let Some(scene) = &self.symbolic {
            let free = if scene.free.is_empty() {
                "none".to_string()
            } else {
                scene.free.join(", ")
            };
            let _ = writeln!(out, "  free symbols: {free}");
            if !scene.defaults.is_empty() {
                let _ = writeln!(out, "  defaults: {}", scene.defaults.join("; "));
            }
        }
        let mut rows = vec![[
            "claim".to_string(),
            "exact (SI)".to_string(),
            "claimed".to_string(),
            "rel. error".to_string(),
            "verdict".to_string(),
        ]];
        for d in &self.decisions {
            rows.push([
                d.name.clone(),
                d.exact_text(),
                d.claim.clone(),
                d.rel_error
                    .as_ref()
                    .map_or_else(|| "-".into(), RelError::to_text),
                d.verdict.label().to_string(),
            ]);
        }
        let widths: Vec<usize> = (0..5)
            .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
            .collect();
        for (k, row) in rows.iter().enumerate() {
            let cells: Vec<String> = row
                .iter()
                .zip(&widths)
                .map(|(c, w)| format!("{c:<w$}"))
                .collect();
            let _ = writeln!(out, "  {}", cells.join("  ").trim_end());
            if k > 0 {
                for note in &self.decisions[k - 1].notes {
                    let _ = writeln!(out, "      note: {note}");
                }
            }
        }
        out
    }

    /// The summary line: `2 of 3 claims agree; 1 disagrees`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// assert_eq!(Report { symbolic: None, decisions: vec![] }.summary(), "no claims");
    /// ```
    pub fn summary(&self) -> String {
        summary_line(self.agreeing(), self.decisions.len())
    }

    /// The report as JSON: `symbolic`, `free_symbols` and `defaults` (symbolic scenes),
    /// `claims`, `summary`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// let j = Report { symbolic: None, decisions: vec![] }.to_json();
    /// assert_eq!(j["summary"]["claims"], 0);
    /// assert_eq!(j["symbolic"], false);
    /// ```
    pub fn to_json(&self) -> Value {
        let mut j = json!({
            "symbolic": self.symbolic.is_some(),
            "claims": self.decisions.iter().map(Decision::to_json).collect::<Vec<_>>(),
            "summary": summary_json(self.agreeing(), self.decisions.len()),
        });
        if let Some(scene) = &self.symbolic {
            j["free_symbols"] = json!(scene.free);
            j["defaults"] = json!(scene.defaults);
        }
        j
    }
}

/// `n thing` or `n things`.
///
/// # Examples
/// ```
/// use rodimpact::textbook::verdict::count;
/// assert_eq!(count(1, "problem"), "1 problem");
/// assert_eq!(count(0, "claim"), "0 claims");
/// ```
pub fn count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// How many claims agree, in words: `no claims`, `1 claim, it agrees`,
/// `1 of 3 claims agrees; 2 disagree`.
///
/// # Examples
/// ```
/// use rodimpact::textbook::verdict::summary_line;
/// assert_eq!(summary_line(1, 3), "1 of 3 claims agrees; 2 disagree");
/// assert_eq!(summary_line(2, 3), "2 of 3 claims agree; 1 disagrees");
/// assert_eq!(summary_line(0, 1), "1 claim, it disagrees");
/// assert_eq!(summary_line(4, 4), "4 of 4 claims agree");
/// ```
pub fn summary_line(agree: usize, total: usize) -> String {
    let wrong = total - agree;
    let verb = |n: usize, singular: &str, plural: &str| {
        format!("{n} {}", if n == 1 { singular } else { plural })
    };
    match total {
        0 => "no claims".into(),
        1 if agree == 1 => "1 claim, it agrees".into(),
        1 => "1 claim, it disagrees".into(),
        _ => {
            let head = format!(
                "{} of {total} claims {}",
                agree,
                if agree == 1 { "agrees" } else { "agree" }
            );
            if wrong == 0 {
                head
            } else {
                format!("{head}; {}", verb(wrong, "disagrees", "disagree"))
            }
        }
    }
}

/// `{"claims", "agree", "disagree"}`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::textbook::verdict::summary_json(1, 3)["disagree"], 2);
/// ```
pub fn summary_json(agree: usize, total: usize) -> Value {
    json!({ "claims": total, "agree": agree, "disagree": total - agree })
}

/// Decides a numeric claim (a printed number, or a formula without symbols) against the exact
/// value. `sig` overrides the printed significant figures.
///
/// # Examples
/// ```
/// use rodimpact::textbook::{verdict::decide, Claim, Exact, Verdict};
/// use rodimpact::field::q;
/// let d = decide(&Claim::parse("omega=1.90").unwrap(), &Exact::Rational(q(36, 19)), None);
/// assert_eq!(d.verdict, Verdict::LastDigit);
/// ```
pub fn decide(claim: &Claim, exact: &Exact, sig: Option<u32>) -> Decision {
    let mut d = Decision::new(
        claim.quantity.name(),
        &claim.text,
        exact.to_string(),
        Some(exact.clone()),
    );
    let omega = claim.quantity == Quantity::Omega;
    match &claim.value {
        ClaimValue::Printed(m) => printed(&mut d, m, exact, omega, sig),
        ClaimValue::Formula(r) => match r.constant() {
            Some((c, rad)) if !rad.is_negative() => {
                let (equal, same_sign) = radical_matches(&c, &rad, exact);
                d.verdict = if equal && (same_sign || omega) {
                    if !same_sign {
                        d.notes.push(opposite_sign_note());
                    }
                    Verdict::Agrees
                } else {
                    Verdict::Disagrees
                };
                let claim_mid = midpoint(&Exact::Surd(QSqrt::new(Q::zero(), c, rad)), 40);
                d.rel_error = rel_error(&claim_mid, &midpoint(exact, 40), omega);
            }
            _ => d.notes.push("the formula is not a real number".into()),
        },
    }
    d
}

/// The note for an omega claim of the opposite sign.
fn opposite_sign_note() -> String {
    "opposite sign: compared by magnitude (textbooks' rotation conventions differ)".into()
}

/// Compares `c * sqrt(r)` with an exact value: (equal magnitudes, same sign).
///
/// # Examples
/// ```
/// use rodimpact::textbook::{verdict::radical_matches, Exact};
/// use rodimpact::field::{q, QSqrt};
/// let a = Exact::Surd(QSqrt::sqrt_of(&q(2, 3)));
/// assert_eq!(radical_matches(&q(1, 3), &q(6, 1), &a), (true, true));
/// assert_eq!(radical_matches(&q(-1, 1), &q(1, 1), &Exact::Rational(q(1, 1))), (true, false));
/// ```
pub fn radical_matches(c: &Q, r: &Q, exact: &Exact) -> (bool, bool) {
    let claim_sq = c * c * r;
    let (exact_sq, exact_sign) = match exact {
        Exact::Rational(x) => (Some(x * x), x.signum()),
        Exact::Surd(s) if s.x().is_zero() || s.y().is_zero() => {
            let d = s.d().cloned().unwrap_or_else(Q::zero);
            let sq = s.x() * s.x() + s.y() * s.y() * d;
            let sign = if s.x().is_zero() {
                s.y().signum()
            } else {
                s.x().signum()
            };
            (Some(sq), sign)
        }
        // x + y sqrt(d) with x, y != 0 has an irrational square; c^2 r is rational.
        Exact::Surd(s) => (
            None,
            ordering_sign(s.cmp_exact(&QSqrt::rational(Q::zero()))),
        ),
    };
    let equal = exact_sq.is_some_and(|sq| sq == claim_sq);
    let claim_sign = if r.is_zero() { Q::zero() } else { c.signum() };
    (equal, claim_sign == exact_sign || exact_sign.is_zero())
}

/// -1, 0 or 1 for an ordering against zero.
fn ordering_sign(o: Ordering) -> Q {
    Q::from_integer((o as i8).into())
}

fn printed(d: &mut Decision, m: &Measured, exact: &Exact, omega: bool, sig: Option<u32>) {
    let mut p: Printed = m.printed.clone();
    if let Some(n) = sig {
        p = p.clone().with_sig(n).unwrap_or(p);
    }
    if let Precision::Figures {
        figures,
        ambiguous: Some((lo, hi)),
    } = p.precision
    {
        d.notes.push(format!(
            "'{}' is ambiguous ({lo} to {hi} significant figures): read with {figures}, the most lenient; --sig decides",
            d.claim
        ));
    }
    let scale = m.scale();
    if matches!(scale, Scale::Pi(_)) {
        d.notes
            .push("rpm = pi/30 rad/s: decided with exact rational bounds on pi".into());
    }
    let claim_value = if omega {
        p.value.abs()
    } else {
        p.value.clone()
    };
    for digits in [40, 100, 400, 1100] {
        let (lo, hi) = enclose(exact, &scale, digits);
        let (lo, hi, negative) = if !omega || !lo.is_negative() {
            (lo, hi, false)
        } else if !hi.is_positive() {
            (-hi, -lo, true)
        } else {
            continue;
        };
        let Some(verdict) = judge(&claim_value, &p, &lo, &hi) else {
            continue;
        };
        d.verdict = verdict;
        let mid = (&lo + &hi) / Q::from_integer(2.into());
        d.rel_error = RelError::new(claim_value.clone(), mid.clone());
        if omega && !p.value.is_zero() && !mid.is_zero() && p.value.is_negative() != negative {
            d.notes.push(opposite_sign_note());
        }
        if p.precision == Precision::Exact && lo != hi {
            d.notes
                .push("an exact fraction cannot equal this irrational value".into());
        }
        return;
    }
    d.notes
        .push("not decided: the exact value's bounds (and pi's, to 100 decimals) are too wide for these figures".into());
}

/// The verdict of a printed value against an exact value known to lie in `[lo, hi]`, or `None`
/// when the interval is still too wide to decide the rounding.
fn judge(claim: &Q, p: &Printed, lo: &Q, hi: &Q) -> Option<Verdict> {
    let round = |x: &Q, tie: Tie| match &p.precision {
        Precision::ZeroAt { place } => round_at(x, *place, tie),
        Precision::Figures { figures, .. } => round_sig(x, *figures, tie),
        Precision::Exact => x.clone(),
    };
    if p.precision == Precision::Exact {
        return Some(if lo == hi && claim == lo {
            Verdict::Agrees
        } else {
            Verdict::Disagrees
        });
    }
    let mut accepted = Vec::with_capacity(2);
    for tie in [Tie::Up, Tie::Down] {
        let r = round(lo, tie);
        if r != round(hi, tie) {
            return None;
        }
        accepted.push(r);
    }
    if accepted.contains(claim) {
        return Some(Verdict::Agrees);
    }
    let unit = pow10(p.place().unwrap_or(0));
    let one_digit_off = accepted.iter().any(|r| (claim - r).abs() == unit);
    let within_a_unit = (claim - lo).abs() <= unit && (claim - hi).abs() <= unit;
    let two_figures = matches!(p.precision, Precision::Figures { figures, .. } if figures >= 2);
    if one_digit_off && within_a_unit && two_figures {
        Some(Verdict::LastDigit)
    } else {
        Some(Verdict::Disagrees)
    }
}

/// Rational bounds on the exact value expressed in a unit of the given scale.
fn enclose(exact: &Exact, scale: &Scale, digits: usize) -> (Q, Q) {
    let (lo, hi) = match exact {
        Exact::Rational(x) => (x.clone(), x.clone()),
        Exact::Surd(s) => s.bounds(digits),
    };
    match scale {
        Scale::Rational(f) => (lo / f, hi / f),
        Scale::Pi(f) => {
            let (pl, ph) = pi_bounds(digits as u32);
            let quotients = [
                &lo / (f * &pl),
                &lo / (f * &ph),
                &hi / (f * &pl),
                &hi / (f * &ph),
            ];
            let min = quotients.iter().min().cloned().unwrap_or_else(Q::zero);
            let max = quotients.iter().max().cloned().unwrap_or_else(Q::zero);
            (min, max)
        }
    }
}

pub(crate) fn midpoint(exact: &Exact, digits: usize) -> Q {
    let (lo, hi) = enclose(exact, &Scale::Rational(Q::from_integer(1.into())), digits);
    (lo + hi) / Q::from_integer(2.into())
}

/// The relative error of `claim` against `exact` (magnitudes for omega); `None` for an exact 0.
///
/// # Examples
/// ```
/// use rodimpact::textbook::verdict::rel_error;
/// use rodimpact::field::q;
/// assert_eq!(rel_error(&q(1, 2), &q(1, 1), false).unwrap().to_text(), "-50 %");
/// assert_eq!(rel_error(&q(-1, 2), &q(1, 1), true).unwrap().to_text(), "-50 %");
/// assert_eq!(rel_error(&q(1, 1), &q(0, 1), false), None);
/// ```
pub fn rel_error(claim: &Q, exact: &Q, magnitudes: bool) -> Option<RelError> {
    if magnitudes {
        RelError::new(claim.abs(), exact.abs())
    } else {
        RelError::new(claim.clone(), exact.clone())
    }
}
