//! An f64 as the text `format!("{x:?}")` gives it, at a third of its cost: the shortest digits
//! that read back to `x` come from the Żmij algorithm (the `zmij` crate, which serde_json
//! already brings in), laid out as Rust's `Debug` lays them out (decimal from 1e-4 to below
//! 1e16 with at least one fractional digit, `1.5e-7` and `1e16` beyond). A batch of floats
//! writes three of them a row.
//!
//! The two agree on the digits but for one case: when `x` lies exactly halfway between the two
//! nearest candidates of the shortest length, std rounds up (`1360664548826925.3`) and Żmij to
//! even (`.2`). Such an `x` is rare and recognised from its binary parts ([`may_tie`]); std
//! prints it.

/// Appends `x` exactly as `write!(out, "{x:?}")` would (`0.30000000000000004`, `1e16`,
/// `-1.5e-7`, `NaN`).
pub(crate) fn push_debug(out: &mut String, x: f64) {
    if x == 0.0 || !x.is_finite() || may_tie(x) {
        use std::fmt::Write;
        write!(out, "{x:?}").expect("writing to a String cannot fail");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(x).as_bytes();
    let (negative, text) = match text {
        [b'-', rest @ ..] => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
        Some(at) => (&text[..at], exponent_of(&text[at + 1..])),
        None => (text, 0),
    };
    // The digits without the point, and where the point stands among them.
    let point_at = mantissa.iter().position(|&b| b == b'.');
    let mut digits = [0u8; 40];
    let mut count = 0;
    for &b in mantissa.iter().filter(|&&b| b != b'.') {
        digits[count] = b;
        count += 1;
    }
    let whole = point_at.unwrap_or(mantissa.len());
    let leading = digits[..count].iter().take_while(|&&b| b == b'0').count();
    let trailing = digits[leading..count]
        .iter()
        .rev()
        .take_while(|&&b| b == b'0')
        .count();
    let significant = &digits[leading..count - trailing];
    // x = 0.significant x 10^point
    let point = whole as i32 - leading as i32 + exponent;
    if negative {
        out.push('-');
    }
    let n = significant.len() as i32;
    if (-3..=16).contains(&point) {
        if point <= 0 {
            out.push_str("0.");
            (0..-point).for_each(|_| out.push('0'));
            out.push_str(ascii(significant));
        } else if point >= n {
            out.push_str(ascii(significant));
            (n..point).for_each(|_| out.push('0'));
            out.push_str(".0");
        } else {
            let (head, tail) = significant.split_at(point as usize);
            out.push_str(ascii(head));
            out.push('.');
            out.push_str(ascii(tail));
        }
    } else {
        out.push_str(ascii(&significant[..1]));
        if n > 1 {
            out.push('.');
            out.push_str(ascii(&significant[1..]));
        }
        out.push('e');
        let mut digits = itoa::Buffer::new();
        out.push_str(digits.format(point - 1));
    }
}

/// Whether `x` may lie exactly halfway between two shortest candidates. Its exact decimal
/// expansion must then be one digit, a 5, longer than the shortest (at most 17 digits):
/// `|x| = odd 2^k` with `k < 0` is `odd 5^-k / 10^-k`, whose digits are those of `odd 5^-k`
/// (no trailing zero), so it takes at most 18 of them, `odd 5^-k < 10^18`; an integer
/// (`k >= 0`) may drop digits, a 5 and zeros, once past 2^53.
fn may_tie(x: f64) -> bool {
    let Some((_, odd, k)) = super::float_parts(x) else {
        return false;
    };
    match u32::try_from(-k) {
        Err(_) => x.abs() >= 9_007_199_254_740_992.0,
        Ok(k) => 5u128
            .checked_pow(k)
            .and_then(|power| power.checked_mul(u128::from(odd)))
            .is_some_and(|exact| exact < 1_000_000_000_000_000_000),
    }
}

/// Digits as text.
fn ascii(digits: &[u8]) -> &str {
    std::str::from_utf8(digits).expect("ASCII digits")
}

/// The exponent after an `e`: an optional sign and decimal digits.
fn exponent_of(text: &[u8]) -> i32 {
    let (negative, digits) = match text {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        _ => (false, text),
    };
    let magnitude = digits
        .iter()
        .fold(0i32, |n, &b| n * 10 + i32::from(b - b'0'));
    if negative { -magnitude } else { magnitude }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn debug(x: f64) -> String {
        let mut out = String::new();
        push_debug(&mut out, x);
        out
    }

    #[test]
    fn the_layouts_at_their_edges_are_rusts() {
        let cases = [
            0.0, -0.0, 1.0, -1.0, 0.1, 0.30000000000000004, 1e-4, 9.999999999999999e-5, 1e-5,
            1.5e-7, 1e15, 9999999999999998.0, 1e16, 1.2345e16, 123456.0, 100.0, 1e21, 5e-324,
            f64::MIN_POSITIVE, f64::MAX, -f64::MAX, f64::EPSILON, f64::INFINITY, f64::NAN,
            -f64::INFINITY, 0.014147800050860564, 2.331857488811421, 1e100, 1.7976931348623157e308,
            1360664548826925.25, 9007199254740993.0, 1e23, 4.35e17,
        ];
        for x in cases {
            assert_eq!(debug(x), format!("{x:?}"), "{x:e}");
        }
    }

    proptest! {
        /// Every float, by its bits (every exponent, subnormals, both signs), and floats of few
        /// digits near the layout's switches, print as `{:?}` prints them.
        #[test]
        fn every_float_prints_as_debug_prints_it(
            bits: u64,
            digits in 1u64..100_000,
            k in -330i32..310,
            long in 1u64 << 40..1 << 53,
            halvings in 0i32..8,
        ) {
            let x = f64::from_bits(bits);
            prop_assert_eq!(debug(x), format!("{x:?}"));
            let y: f64 = format!("{digits}e{k}").parse().unwrap();
            prop_assert_eq!(debug(y), format!("{y:?}"));
            // Exact decimals of 17 and 18 digits, where halfway cases live.
            let z = long as f64 / f64::from(1 << halvings);
            prop_assert_eq!(debug(z), format!("{z:?}"));
        }
    }
}
