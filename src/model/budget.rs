//! The digit budget of an impact scene: exact arithmetic on a scene costs with the size of its
//! numbers (every operation reduces a fraction by a gcd, quadratic in its digits), so a scene's
//! numbers together take at most [`MAX_SCENE_DIGITS`] digits (numerators and denominators, as
//! read: `1e-300` is 301 digits). Checked before anything is computed from them (a polygon's
//! area and inertia sum products of its vertices' denominators), naming the number at which
//! the scene passes the budget.

use crate::error::Error;
use crate::field::Q;
use serde_json::Value;

/// The digits an impact scene's numbers take together (`docs/limits.md`): at most a few
/// seconds of CPU for any one contact's answer.
pub const MAX_SCENE_DIGITS: u64 = 3_000;

/// The decimal digits of `x`'s numerator and denominator (at least 1 each).
fn digits(x: &Q) -> u64 {
    // bits * log10(2), rounded up: a bound close enough for a budget.
    let of = |bits: u64| (bits * 30_103).div_ceil(100_000).max(1);
    of(x.numer().bits()) + of(x.denom().bits())
}

/// Checks the numbers of the scene's bodies, contacts and pins (not its claims) against
/// [`MAX_SCENE_DIGITS`], in the order they are read.
///
/// # Errors
/// `FIELD: the scene's numbers pass N digits here (limit ...)` at the number that passes it.
pub(super) fn check_scene_digits(top: &serde_json::Map<String, Value>) -> Result<(), Error> {
    let mut total = 0u64;
    for key in ["body", "contact", "pin"] {
        if let Some(value) = top.get(key) {
            walk(value, key, &mut total)?;
        }
    }
    Ok(())
}

fn walk(value: &Value, field: &str, total: &mut u64) -> Result<(), Error> {
    let number = match value {
        Value::Array(items) => {
            for (k, item) in items.iter().enumerate() {
                walk(item, &format!("{field}[{}]", k + 1), total)?;
            }
            return Ok(());
        }
        Value::Object(map) => {
            for (key, item) in map {
                walk(item, &format!("{field}.{key}"), total)?;
            }
            return Ok(());
        }
        // A number with a unit is read by its digits; text that is not a number is the
        // reader's to refuse.
        Value::String(text) => text.split_whitespace().next().map(crate::number::parse),
        Value::Number(n) => Some(crate::number::parse(&n.to_string())),
        _ => None,
    };
    if let Some(Ok(x)) = number {
        *total += digits(&x);
        if *total > MAX_SCENE_DIGITS {
            return Err(Error::out_of_range(
                field,
                format!(
                    "the scene's numbers pass {} digits together here (limit on an impact \
                     scene's digits, numerators and denominators; docs/limits.md)",
                    crate::field::count::grouped(MAX_SCENE_DIGITS)
                ),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn digits_count_numerators_and_denominators() {
        assert_eq!(digits(&crate::field::q(3, 7)), 2);
        assert_eq!(digits(&crate::number::parse("1e-300").unwrap()), 1 + 301);
    }

    #[test]
    fn a_scene_past_the_budget_is_refused_at_the_number_that_passes_it() {
        let big = format!("1e-{}", MAX_SCENE_DIGITS);
        let scene = json!({"body": [{"name": "a", "mass": "1"}],
            "contact": [{"mu": "1/3"}, {"mu": big}]});
        let err = check_scene_digits(scene.as_object().unwrap()).unwrap_err();
        assert_eq!(err.field, "contact[2].mu");
        let small = json!({"body": [{"name": "a", "mass": "3/7 kg", "velocity": ["1", 2]}]});
        assert!(check_scene_digits(small.as_object().unwrap()).is_ok());
    }
}
