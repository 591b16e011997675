//! Verdicts: a printed number against the exact value (by significant figures), an exact number
//! against it (exactly), and the report that lists them.

use super::sigfig::{Precision, Printed, Tie, pow10, round_at, round_sig};
use super::units::{Measured, Scale, pi_bounds};
use super::{Claim, ClaimValue, Exact, Quantity};
use crate::field::{Q, QSqrt};
use crate::number;
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

/// One row of the report.
#[derive(Debug, Clone, PartialEq)]
pub struct Decision {
    /// Claim name (`omega`).
    pub name: String,
    /// The claimed value as written.
    pub claim: String,
    /// The exact value in SI units (a fraction, a surd, or a formula).
    pub exact: String,
    /// The exact value to 6 significant figures, when it is a number.
    pub decimal: Option<String>,
    /// (claim - exact) / |exact| in percent, in the claim's unit.
    pub rel_error: Option<String>,
    /// The verdict.
    pub verdict: Verdict,
    /// Remarks: ambiguous figures, bounds on pi, opposite sign, identity, counterexample.
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
    pub fn new(name: &str, claim: &str, exact: String, decimal: Option<String>) -> Decision {
        Decision {
            name: name.to_string(),
            claim: claim.to_string(),
            exact,
            decimal,
            rel_error: None,
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

    /// The row as JSON.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Decision;
    /// let j = Decision::new("v", "2.3", "7/3".into(), None).to_json();
    /// assert_eq!(j["verdict"], "undecided");
    /// ```
    pub fn to_json(&self) -> Value {
        json!({
            "name": self.name,
            "claim": self.claim,
            "exact": self.exact,
            "decimal": self.decimal,
            "rel_error": self.rel_error,
            "verdict": self.verdict.key(),
            "notes": self.notes,
        })
    }
}

/// The decisions for one scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Whether the scene was treated symbolically.
    pub symbolic: bool,
    /// One decision per claim, in order.
    pub decisions: Vec<Decision>,
}

impl Report {
    /// How many claims agree.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// assert_eq!(Report { symbolic: false, decisions: vec![] }.agreeing(), 0);
    /// ```
    pub fn agreeing(&self) -> usize {
        self.decisions.iter().filter(|d| d.agrees()).count()
    }

    /// Whether every claim agrees.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// assert!(Report { symbolic: false, decisions: vec![] }.all_agree());
    /// ```
    pub fn all_agree(&self) -> bool {
        self.agreeing() == self.decisions.len()
    }

    /// The table: claim, exact, claimed, relative error, verdict, then notes.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Decision, Report};
    /// let r = Report { symbolic: false, decisions: vec![Decision::new("v", "2.3", "7/3".into(), None)] };
    /// assert!(r.to_text().contains("UNDECIDED"));
    /// ```
    pub fn to_text(&self) -> String {
        let mut rows = vec![[
            "claim".to_string(),
            "exact (SI)".to_string(),
            "claimed".to_string(),
            "rel. error".to_string(),
            "verdict".to_string(),
        ]];
        for d in &self.decisions {
            let exact = match &d.decimal {
                Some(dec) if *dec != d.exact => format!("{} ≈ {dec}", d.exact),
                _ => d.exact.clone(),
            };
            rows.push([
                d.name.clone(),
                exact,
                d.claim.clone(),
                d.rel_error.clone().unwrap_or_else(|| "-".into()),
                d.verdict.label().to_string(),
            ]);
        }
        let widths: Vec<usize> = (0..5)
            .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
            .collect();
        let mut out = String::new();
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
    /// assert_eq!(Report { symbolic: false, decisions: vec![] }.summary(), "0 of 0 claims agree");
    /// ```
    pub fn summary(&self) -> String {
        summary_line(self.agreeing(), self.decisions.len())
    }

    /// The report as JSON.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Report;
    /// let j = Report { symbolic: true, decisions: vec![] }.to_json();
    /// assert_eq!(j["summary"]["claims"], 0);
    /// ```
    pub fn to_json(&self) -> Value {
        json!({
            "symbolic": self.symbolic,
            "claims": self.decisions.iter().map(Decision::to_json).collect::<Vec<_>>(),
            "summary": summary_json(self.agreeing(), self.decisions.len()),
        })
    }
}

/// `k of n claims agree; j disagree(s)`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::textbook::verdict::summary_line(1, 3), "1 of 3 claims agree; 2 disagree");
/// ```
pub fn summary_line(agree: usize, total: usize) -> String {
    let wrong = total - agree;
    match wrong {
        0 => format!("{agree} of {total} claims agree"),
        1 => format!("{agree} of {total} claims agree; 1 disagrees"),
        _ => format!("{agree} of {total} claims agree; {wrong} disagree"),
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
    let (exact_text, decimal) = match exact {
        Exact::Rational(x) => (x.to_string(), number::decimal(x, 6)),
        Exact::Surd(s) => (s.to_string(), s.decimal(6)),
    };
    let mut d = Decision::new(
        claim.quantity.name(),
        &claim.text,
        exact_text,
        Some(decimal),
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
        d.rel_error = rel_error(&claim_value, &mid, false);
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
    if accepted.iter().any(|r| (claim - r).abs() == unit) {
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

fn midpoint(exact: &Exact, digits: usize) -> Q {
    let (lo, hi) = enclose(exact, &Scale::Rational(Q::from_integer(1.into())), digits);
    (lo + hi) / Q::from_integer(2.into())
}

/// `(claim - exact) / |exact|` in percent, to 2 significant figures (magnitudes for omega).
///
/// # Examples
/// ```
/// use rodimpact::textbook::verdict::rel_error;
/// use rodimpact::field::q;
/// assert_eq!(rel_error(&q(1, 2), &q(1, 1), false).unwrap(), "-50%");
/// assert_eq!(rel_error(&q(1, 1), &q(0, 1), false), None);
/// ```
pub fn rel_error(claim: &Q, exact: &Q, magnitudes: bool) -> Option<String> {
    if exact.is_zero() {
        return None;
    }
    let (claim, exact) = if magnitudes {
        (claim.abs(), exact.abs())
    } else {
        (claim.clone(), exact.clone())
    };
    let rel = (claim - &exact) / exact.abs() * Q::from_integer(100.into());
    Some(format!("{}%", number::decimal(&rel, 2)))
}
