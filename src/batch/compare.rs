//! A claimed v, V or omega against the computed value: exactly (on machine words when the
//! claim fits them), or within [`FLOAT_TOLERANCE`] for the f64 arithmetic.

use super::header::{Arithmetic, OUTPUTS};
use crate::error::Error;
use crate::field::Q;
use crate::number::WordRatio;
use crate::units::{Dimension, parse_si};
use num_traits::{Signed, Zero};

/// The relative error up to which a claim agrees with a value computed in f64.
pub const FLOAT_TOLERANCE: f64 = 1e-9;

/// A claimed value compared with the computed one.
///
/// # Examples
/// ```
/// use rodimpact::{batch::{Batch, Arithmetic}, field::q};
/// let row = Batch::new("m,M,V", Arithmetic::Exact).unwrap().row(1, "1,1,0.5").unwrap();
/// let check = &row.checks[0];
/// assert_eq!((check.output, check.ok), (1, false));
/// assert_eq!(check.rel_error, Some(q(1, 4))); // |1/2 - 2/5| / (2/5)
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OutputCheck {
    /// Which output: 0 v, 1 V, 2 omega.
    pub output: usize,
    /// The claim agrees (exactly, or within [`FLOAT_TOLERANCE`] in f64).
    pub ok: bool,
    /// |claim - value| / |value|, exact; `None` when the value is 0 and the claim is not.
    pub rel_error: Option<Q>,
}

/// A claimed value as read: on machine words (compared without reducing), or exact.
#[derive(Debug, Clone)]
pub(super) enum Claimed {
    Word(WordRatio),
    Exact(Q),
}

impl Claimed {
    pub(super) fn parse(output: usize, cell: &str) -> Result<Claimed, Error> {
        match WordRatio::parse(cell) {
            Some(word) => Ok(Claimed::Word(word)),
            None => {
                let dimension = if output == 2 {
                    Dimension::AngularSpeed
                } else {
                    Dimension::Speed
                };
                parse_si(OUTPUTS[output], cell, dimension).map(Claimed::Exact)
            }
        }
    }

    pub(super) fn value(&self) -> Q {
        match self {
            Claimed::Word(word) => word.value(),
            Claimed::Exact(q) => q.clone(),
        }
    }
}

pub(super) fn compare(
    output: usize,
    claim: &Claimed,
    value: &Q,
    arithmetic: Arithmetic,
) -> OutputCheck {
    let equal = match claim {
        Claimed::Word(word) => word.equals(value),
        Claimed::Exact(q) => Some(q == value),
    };
    if equal == Some(true) {
        return OutputCheck {
            output,
            ok: true,
            rel_error: Some(Q::zero()),
        };
    }
    let claim = &claim.value();
    let rel_error = if value.is_zero() {
        claim.is_zero().then(Q::zero)
    } else {
        // |c - v| / |v| = |cn vd - vn cd| / (|vn| cd), reduced once (one GCD instead of the
        // three of a subtraction and a division of rationals).
        let difference = claim.numer() * value.denom() - value.numer() * claim.denom();
        Some(Q::new(
            difference.abs(),
            value.numer().abs() * claim.denom(),
        ))
    };
    let ok = match arithmetic {
        Arithmetic::Exact => claim == value,
        Arithmetic::F64 => rel_error
            .as_ref()
            .is_some_and(|r| crate::field::Field::nearest_f64(r) <= FLOAT_TOLERANCE),
    };
    OutputCheck {
        output,
        ok,
        rel_error,
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
        assert_eq!(signs.checks[0].rel_error, Some(Q::from_integer(2.into())));
        // Beyond 38 digits a claim takes the general parser, with the same check.
        let long = format!("{}/{}", "1".repeat(40), "2".repeat(40));
        let row = b.row(3, &format!("1,3,0,-1/2,{long},0")).unwrap();
        let oks: Vec<bool> = row.checks.iter().map(|v| v.ok).collect();
        assert_eq!(oks, [true, true, true]);
    }

    #[test]
    fn the_f64_backend_agrees_within_its_tolerance() {
        let b = Batch::new("m,M,V", Arithmetic::F64).unwrap();
        let row = b.row(1, "1,1,2/5").unwrap();
        assert!(row.line.starts_with("1,1,2/5,0.6,0.4,1.2"), "{}", row.line);
        assert!(row.line.contains(",-,true,"), "{}", row.line);
        assert!(!b.row(2, "1,1,0.41").unwrap().checks[0].ok);
    }
}
