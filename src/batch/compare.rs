//! A claimed value against the computed one, under the batch's agreement rule: exactly (on
//! machine words when the claim fits them), within a relative tolerance, or within a number of
//! ulps of the correctly rounded float of the exact value. A claimed NaN or infinity is a wrong
//! claim, never an error.

use super::plan::{Arithmetic, CLAIMS, OutputCheck};
use super::rel_error::RelError;
use super::ulps::{FloatFormat, ulp_distance};
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::field::int::U256;
use crate::number::WordRatio;
use crate::units::{Dimension, parse_si};
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// The relative error up to which a claim agrees with a value computed in f64 (the default
/// rule of `--backend f64`).
pub const FLOAT_TOLERANCE: f64 = 1e-9;

/// The largest `--ulps` accepted: 2^53 (every f64 of one binade is within it).
pub const MAX_ULPS: u64 = 1 << 53;

/// When a claim agrees with the computed value.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Agreement, FloatFormat};
/// use rodimpact::field::q;
/// assert_eq!(Agreement::parse_rtol("1e-6").unwrap(), Agreement::Relative(q(1, 1_000_000)));
/// assert_eq!(Agreement::parse_ulps("4", FloatFormat::F32).unwrap(), Agreement::Ulps(4, FloatFormat::F32));
/// assert_eq!(Agreement::parse_rtol("-1").unwrap_err().to_string(),
///            "rtol: must be a number from 0 to 1, got -1");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Agreement {
    /// Equal exactly (the default of the exact backend).
    Exact,
    /// |claim - value| <= R |value| (a zero value agrees only with a zero claim).
    Relative(Q),
    /// At most N floats of the format between the claim and the correctly rounded exact value
    /// (both rounded to the format).
    Ulps(u64, FloatFormat),
}

/// `r` exactly, as briefly as possible: the f64's own text where it is exactly `r` (`0.000001`),
/// else [`compact`](crate::field::decimal::compact) (`1/3`, `1e-10000`) where that is exact, else
/// the fraction in full (an input has at most 10,000 digits).
fn exact_text(r: &Q) -> String {
    let float = crate::field::Field::nearest_f64(r);
    let text = float.to_string();
    if float.is_finite() && crate::number::parse(&text).is_ok_and(|back| &back == r) {
        return text;
    }
    let compact = crate::field::decimal::compact(r);
    if compact.starts_with('≈') {
        r.to_string()
    } else {
        compact
    }
}

/// A tolerance flag's value (`--rtol`, `--atol`): an exact number from 0 to 1.
pub(crate) fn unit_fraction(field: &str, text: &str) -> Result<Q, Error> {
    let bad = || {
        Error::out_of_range(
            field,
            format!(
                "must be a number from 0 to 1, got {}",
                crate::echo::echo(text)
            ),
        )
    };
    let x = crate::number::parse(text).map_err(|kind| match kind {
        ErrorKind::Invalid(_) => bad(),
        other => Error::new(field, other),
    })?;
    if x.is_negative() || x > Q::from_integer(1.into()) {
        return Err(bad());
    }
    Ok(x)
}

impl Agreement {
    /// `--rtol R`: an exact number from 0 to 1.
    ///
    /// # Errors
    /// `rtol: ...` when R is not a number or not in [0, 1].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{batch::Agreement, field::q};
    /// assert_eq!(Agreement::parse_rtol("1/1000").unwrap(), Agreement::Relative(q(1, 1000)));
    /// assert!(Agreement::parse_rtol("2").is_err());
    /// ```
    pub fn parse_rtol(text: &str) -> Result<Agreement, Error> {
        unit_fraction("rtol", text).map(Agreement::Relative)
    }

    /// The rule in words, for the summary.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Agreement, FloatFormat};
    /// use rodimpact::field::q;
    /// assert_eq!(Agreement::Ulps(16, FloatFormat::F32).describe(), "within 16 f32 ulps of the exact value");
    /// assert_eq!(Agreement::Relative(q(1, 1_000_000)).describe(), "within a relative 0.000001");
    /// // Exact, beyond the range of f64 too (it used to underflow to 0).
    /// let tiny = Agreement::parse_rtol("1e-10000").unwrap();
    /// assert_eq!(tiny.describe(), "within a relative 1e-10000");
    /// assert_eq!(Agreement::Relative(q(1, 3)).describe(), "within a relative 1/3");
    /// assert_eq!(Agreement::Exact.describe(), "exactly");
    /// ```
    pub fn describe(&self) -> String {
        match self {
            Agreement::Exact => "exactly".to_string(),
            Agreement::Relative(r) => format!("within a relative {}", exact_text(r)),
            Agreement::Ulps(n, format) => {
                format!("within {n} {} ulps of the exact value", format.name())
            }
        }
    }

    /// `--ulps N`: a whole number from 0 to [`MAX_ULPS`].
    ///
    /// # Errors
    /// `ulps: ...` when N is not such a number.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Agreement, FloatFormat};
    /// assert_eq!(Agreement::parse_ulps("0", FloatFormat::F64).unwrap(), Agreement::Ulps(0, FloatFormat::F64));
    /// assert_eq!(Agreement::parse_ulps("-1", FloatFormat::F64).unwrap_err().to_string(),
    ///            "ulps: must be a whole number from 0 to 9007199254740992, got '-1'");
    /// ```
    pub fn parse_ulps(text: &str, format: FloatFormat) -> Result<Agreement, Error> {
        match text.trim().parse::<u64>() {
            Ok(n) if n <= MAX_ULPS => Ok(Agreement::Ulps(n, format)),
            _ => Err(Error::out_of_range(
                "ulps",
                format!(
                    "must be a whole number from 0 to {MAX_ULPS}, got '{}'",
                    crate::echo::echo(text)
                ),
            )),
        }
    }
}

/// A claimed value as read: on machine words (compared without reducing), exact, or not a
/// finite number (NaN, inf, -inf, infinity: a wrong claim).
#[derive(Debug, Clone)]
pub(super) enum Claimed {
    Word(WordRatio),
    Exact(Q),
    NotFinite,
}

impl Claimed {
    pub(super) fn parse(claim: usize, cell: &str) -> Result<Claimed, Error> {
        let unsigned = cell.trim_start_matches(['+', '-']).to_ascii_lowercase();
        if ["nan", "inf", "infinity"].contains(&unsigned.as_str()) {
            return Ok(Claimed::NotFinite);
        }
        match WordRatio::parse(cell) {
            Some(word) => Ok(Claimed::Word(word)),
            None => {
                let dimension = match claim {
                    0 | 1 | 6 | 7 => Dimension::Speed,
                    2 | 8 => Dimension::AngularSpeed,
                    3 | 9 => Dimension::Impulse,
                    _ => Dimension::Energy,
                };
                parse_si(CLAIMS[claim], cell, dimension).map(Claimed::Exact)
            }
        }
    }

    /// The exact value; `None` for a claim that is not a finite number.
    pub(super) fn value(&self) -> Option<Q> {
        match self {
            Claimed::Word(word) => Some(word.value()),
            Claimed::Exact(q) => Some(q.clone()),
            Claimed::NotFinite => None,
        }
    }
}

/// The relative error `|c - x| / |x|` of a claim `c` read on machine words against a finite
/// f64 `x`, as [`compare`] gives it for `x`'s exact value (reduced; `Some(None)`: infinite, a
/// nonzero claim of a zero value), on machine words. With `|x| = odd 2^k`, over one
/// denominator: `|cn 2^-k - s odd cd| / (odd cd)` for k < 0, `|cn - s odd 2^k cd| / (odd 2^k cd)`
/// for k >= 0 (s the sign that makes it a difference of the signed values). `None` when a
/// value passes 2^256, or `x` is not finite: the general comparison then decides.
pub(super) fn float_rel_error(claim: &WordRatio, x: f64) -> Option<Option<RelError>> {
    let (claim_negative, cn, cd) = claim.parts();
    if !x.is_finite() {
        return None;
    }
    let Some((negative, odd, exponent)) = crate::field::float_parts(x) else {
        // x = 0: only a zero claim agrees.
        return Some((cn == U256::ZERO).then_some(RelError::ZERO));
    };
    let shifted = |v: U256, k: i64| match u32::try_from(k) {
        _ if v == U256::ZERO => Some(v),
        Ok(k) if v.bits() + k <= 256 => Some(v.shl(k)),
        _ => None,
    };
    let odd = U256 {
        hi: 0,
        lo: odd.into(),
    };
    // Both sides times cd (and 2^-k for k < 0); the second is also the denominator.
    let (claimed, value) = if exponent < 0 {
        (shifted(cn, -exponent)?, odd.checked_mul_wide(cd)?)
    } else {
        (cn, shifted(odd, exponent)?.checked_mul_wide(cd)?)
    };
    let difference = U256::signed_distance(claim_negative, claimed, negative, value)?;
    Some(Some(RelError::Words(difference, value)))
}

pub(super) fn compare(
    output: usize,
    claim: &Claimed,
    value: &Q,
    agreement: &Agreement,
    arithmetic: Arithmetic,
) -> OutputCheck {
    // A claim equal to the value needs no exact claimed value: a claim on machine words is
    // compared by cross-multiplying, unreduced (reducing it cost a GCD per claim).
    let equal = match claim {
        Claimed::Word(word) => word.equals(value),
        Claimed::Exact(q) => Some(q == value),
        Claimed::NotFinite => None,
    };
    let needs_value = equal != Some(true) || matches!(agreement, Agreement::Ulps(..));
    let claimed = if needs_value { claim.value() } else { None };
    if claimed.is_none() && needs_value {
        return OutputCheck {
            output,
            ok: false,
            error: None,
            nearest: f64::INFINITY,
            ulps: None,
            not_finite: true,
        };
    }
    let ulps = match (agreement, &claimed) {
        (Agreement::Ulps(_, format), Some(claimed)) => Some(ulp_distance(claimed, value, *format)),
        _ => None,
    };
    let rel_error = if equal == Some(true) {
        Some(RelError::ZERO)
    } else if value.is_zero() {
        claimed
            .as_ref()
            .is_some_and(Q::is_zero)
            .then_some(RelError::ZERO)
    } else {
        let claimed = claimed
            .as_ref()
            .expect("a claim not equal to the value is read exactly");
        // |c - v| / |v| = |cn vd - vn cd| / (|vn| cd), not reduced (its text and nearest f64
        // are taken by value), on machine words when both parts fit 256 bits.
        let difference = (claimed.numer() * value.denom() - value.numer() * claimed.denom()).abs();
        let scale = value.numer().abs() * claimed.denom();
        Some(
            match (
                U256::from_big(difference.magnitude()),
                U256::from_big(scale.magnitude()),
            ) {
                (Some(n), Some(d)) => RelError::Words(n, d),
                _ => RelError::Rational(Q::new_raw(difference, scale)),
            },
        )
    };
    OutputCheck::finite(output, rel_error, ulps, agreement, arithmetic)
}

impl OutputCheck {
    /// The check of a finite claim whose relative error is `rel_error` (`None`: infinite) and
    /// ulp distance `ulps` (under [`Agreement::Ulps`]): whether it agrees under `agreement`.
    pub(super) fn finite(
        output: usize,
        error: Option<RelError>,
        ulps: Option<u64>,
        agreement: &Agreement,
        arithmetic: Arithmetic,
    ) -> OutputCheck {
        let nearest = error.as_ref().map_or(f64::INFINITY, RelError::nearest_f64);
        let ok = match (agreement, arithmetic) {
            (Agreement::Exact, Arithmetic::Exact) => error.as_ref().is_some_and(RelError::is_zero),
            (Agreement::Exact, Arithmetic::F64) => error.is_some() && nearest <= FLOAT_TOLERANCE,
            (Agreement::Relative(tolerance), _) => error
                .as_ref()
                .is_some_and(|r| r.cmp_value(tolerance) != Ordering::Greater),
            (Agreement::Ulps(n, _), _) => ulps.is_some_and(|u| u <= *n),
        };
        OutputCheck {
            output,
            ok,
            error,
            nearest,
            ulps,
            not_finite: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::Batch;

    #[test]
    fn claims_on_machine_words_are_compared_unreduced_and_with_their_sign() {
        // M = 3m hit at the centre: v = -1/2, V = 1/2, omega = 0.
        let b = Batch::new("m,M,a,v,V,omega", Arithmetic::Exact).unwrap();
        let row = b.row(1, "1,3,0,-3/6,+2/4,-0").unwrap();
        assert!(row.checks.iter().all(|v| v.ok), "{row:?}");
        let signs = b.row(2, "1,3,0,1/2,-1/2,0/7").unwrap();
        let oks: Vec<bool> = signs.checks.iter().map(|v| v.ok).collect();
        assert_eq!(oks, [false, false, true]);
        assert_eq!(signs.checks[0].rel_error(), Some(Q::from_integer(2.into())));
        // Beyond 38 digits a claim takes the general parser, with the same check.
        let long = format!("{}/{}", "1".repeat(40), "2".repeat(40));
        let row = b.row(3, &format!("1,3,0,-1/2,{long},0")).unwrap();
        let oks: Vec<bool> = row.checks.iter().map(|v| v.ok).collect();
        assert_eq!(oks, [true, true, true]);
    }

    proptest::proptest! {
        /// A claim on words against any f64 (every exponent, subnormals, zeros, both signs):
        /// where the word comparison answers, its relative error is the general one.
        #[test]
        fn float_errors_on_words_are_the_general_ones(
            n in proptest::prelude::any::<u128>(), d in 1u128.., shift in 0u32..128,
            negative: bool, bits: u64, near: bool,
        ) {
            // Half the floats near the claim (a relative error of about 2^-53), half anywhere.
            let text = format!("{}{}/{}", if negative { "-" } else { "" }, n >> shift, d);
            let word = WordRatio::parse(&text).unwrap();
            let claimed = Claimed::Word(word);
            let x = if near {
                crate::field::Field::nearest_f64(&word.value())
            } else {
                f64::from_bits(bits)
            };
            proptest::prop_assume!(x.is_finite());
            let value = crate::field::exact_float(x).unwrap();
            let general = compare(0, &claimed, &value, &Agreement::Exact, Arithmetic::F64);
            if let Some(rel_error) = float_rel_error(&word, x) {
                proptest::prop_assert_eq!(rel_error.map(|r| r.value()), general.rel_error());
            } else {
                // Only far from the claim can a product pass 2^256.
                proptest::prop_assert!(!near);
            }
        }
    }

    #[test]
    fn the_f64_backend_agrees_within_its_tolerance() {
        let b = Batch::new("m,M,V", Arithmetic::F64).unwrap();
        let row = b.row(1, "1,1,2/5").unwrap();
        assert_eq!(row.line, "1,1,2/5,0.6,0.4,1.2,true,5.55e-17\n");
        assert!(!b.row(2, "1,1,0.41").unwrap().checks[0].ok);
    }

    /// Rapier f32 on the paper's scene: v = 0.59999996 is one f32 below 0.6f32 (the correctly
    /// rounded 3/5), omega = 1.1999999 one below 1.2f32: wrong exactly, right within 1 ulp and
    /// within a relative 1e-7.
    #[test]
    fn ulps_and_relative_tolerances_decide_f32_claims() {
        let header = "m,M,v,V,omega";
        let line = "1,1,0.59999996,0.40000004,1.1999999";
        let exact = Batch::new(header, Arithmetic::Exact).unwrap();
        assert!(exact.row(1, line).unwrap().checks.iter().all(|c| !c.ok));
        let ulps = exact
            .clone()
            .with_agreement(Agreement::Ulps(1, FloatFormat::F32))
            .unwrap();
        let row = ulps.row(1, line).unwrap();
        let distances: Vec<Option<u64>> = row.checks.iter().map(|c| c.ulps).collect();
        assert_eq!(distances, [Some(1), Some(1), Some(1)]);
        assert!(row.checks.iter().all(|c| c.ok));
        let tight = exact
            .clone()
            .with_agreement(Agreement::Ulps(0, FloatFormat::F32))
            .unwrap();
        assert!(tight.row(1, line).unwrap().checks.iter().all(|c| !c.ok));
        let relative = exact
            .with_agreement(Agreement::Relative(Q::new(1.into(), 10_000_000.into())))
            .unwrap();
        assert!(relative.row(1, line).unwrap().checks.iter().all(|c| c.ok));
    }

    #[test]
    fn a_claimed_nan_or_infinity_is_a_wrong_claim_in_its_row() {
        let b = Batch::new("m,M,v,V,omega", Arithmetic::Exact).unwrap();
        let row = b.row(1, "1,1,NaN,-inf,Infinity").unwrap();
        assert!(row.checks.iter().all(|c| !c.ok && c.not_finite));
        assert!(
            row.line
                .ends_with(",false,nan,false,nan,false,nan,nan,non-finite\n"),
            "{}",
            row.line
        );
    }
}
