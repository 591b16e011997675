//! An f64 as the text `format!("{x:?}")` gives it, at a third of its cost: the shortest digits
//! that read back to `x` come from the Żmij algorithm (the `zmij` crate, which serde_json
//! already brings in), in the layout of Rust's `Debug` (decimal from 1e-4 to below 1e16, with
//! at least one fractional digit; `1.5e-7` and `1e16` beyond), which Żmij's is but for the
//! decade from 1e-5 and the exponent's `+`. A batch of floats writes three of them a row.
//!
//! The two agree on the digits but for one case: when `x` lies exactly halfway between the two
//! nearest candidates of the shortest length, std rounds up (`1360664548826925.3`) and Żmij to
//! even (`.2`). Such an `x` is rare and recognised from its binary parts ([`may_tie`]); std
//! prints it.

/// Appends `x` exactly as `write!(out, "{x:?}")` would (`0.30000000000000004`, `1e16`,
/// `-1.5e-7`, `NaN`).
pub(crate) fn push_debug(out: &mut String, x: f64) {
    // Żmij writes 1e-5 <= |x| < 1e16 in decimal, std from 1e-4: std takes the decade between.
    let decimal_below_std = (1e-5..1e-4).contains(&x.abs());
    if x == 0.0 || !x.is_finite() || decimal_below_std || may_tie(x) {
        use std::fmt::Write;
        write!(out, "{x:?}").expect("writing to a String cannot fail");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(x);
    // The layouts agree but for the exponent's sign: `1e+16` is std's `1e16`.
    match text.bytes().position(|b| b == b'+') {
        Some(plus) => {
            out.push_str(&text[..plus]);
            out.push_str(&text[plus + 1..]);
        }
        None => out.push_str(text),
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
    if k >= 0 {
        return x.abs() >= 9_007_199_254_740_992.0;
    }
    // 5^27 alone passes 10^18.
    let k = k.unsigned_abs() as usize;
    k < POWERS_OF_FIVE.len()
        && u128::from(POWERS_OF_FIVE[k]) * u128::from(odd) < 1_000_000_000_000_000_000
}

/// 5^k for k = 0..=26.
const POWERS_OF_FIVE: [u64; 27] = super::int::powers(5);

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
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.30000000000000004,
            1e-4,
            9.999999999999999e-5,
            1e-5,
            1.5e-7,
            1e15,
            9999999999999998.0,
            1e16,
            1.2345e16,
            123456.0,
            100.0,
            1e21,
            5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            -f64::MAX,
            f64::EPSILON,
            f64::INFINITY,
            f64::NAN,
            -f64::INFINITY,
            0.014147800050860564,
            2.331857488811421,
            1e100,
            1.7976931348623157e308,
            f64::from_bits(4_833_301_458_736_479_413), // 1360664548826925.25: halfway
            9_007_199_254_740_994.0,
            1e23,
            4.35e17,
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
