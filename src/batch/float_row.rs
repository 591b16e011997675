//! The f64 row on words (`batch --backend f64`): the cells read as the exact word row reads
//! them ([`read_cells`]), each input rounded to the nearest f64 straight from its integer parts,
//! the rod's inertia M l^2/3 rounded from its exact integer parts, and the paper's closed form
//! evaluated by the same function as the general row ([`closed_form`]). No `BigRational` scene,
//! and no exact values of the results: a claimed v, V or omega written `p/q` is compared with
//! the float on machine words ([`float_rel_error`]), its relative error kept there.
//!
//! A row it does not take (a claim in another form, a part of 2^24 or more, a product past
//! 2^256, anything the word row leaves) goes to the general row, whose line it gives byte for
//! byte: every input is the same correctly rounded f64 either way, and every relative error the
//! same value (`tests/lib/batch_words.rs`).

use super::compare::{Agreement, float_rel_error};
use super::fixed_width_row::read_cells;
use super::plan::{Arithmetic, OutputCheck, STATE, SolvedRow, WordPlan, write_float};
use crate::field::int::U256;
use crate::number::WordRatio;
use crate::scene::{Params, Support};
use crate::solve::fast::closed_form::closed_form;
use crate::solve::fast::fixed_width::{Inputs, Part};

/// The nearest f64 to `n/d` (ties to even), for `0 < d` and `n, d < 2^74` (the callers bound
/// their parts below 2^24).
fn nearest(n: u128, d: u128) -> f64 {
    let word = |x: u128| U256 { hi: 0, lo: x };
    if n == 0 {
        return 0.0;
    }
    U256::nearest_f64(word(n), word(d)).expect("operands below 2^74")
}

/// A part as the nearest f64, if it is below 2^24.
fn part(x: Part) -> Option<f64> {
    const LIMIT: u64 = 1 << 24;
    (x.n < LIMIT && x.d < LIMIT).then(|| {
        let value = nearest(x.n.into(), x.d.into());
        if x.negative { -value } else { value }
    })
}

/// The scene's f64 parameters, each the nearest f64 to the exact value, as
/// [`Scene::params`](crate::scene::Scene::params) gives them; `None` when a part is 2^24 or
/// more.
fn float_params(x: &Inputs) -> Option<Params<f64>> {
    let [m, big_m, l, a, v0, e] = [x.m, x.big_m, x.l, x.a, x.v0, x.e].map(part);
    let (m, rod_mass, half_length, a, v0, e) = (m?, big_m?, l?, a?, v0?, e?);
    // Every part below 2^24, so I = M l^2/3 = Mn ln^2/(3 Md ld^2) has parts below 2^72 and 2^74.
    let square = |w: u64| u128::from(w) * u128::from(w);
    let inertia = nearest(
        u128::from(x.big_m.n) * square(x.l.n),
        3 * u128::from(x.big_m.d) * square(x.l.d),
    );
    Some(Params {
        m,
        rod_mass,
        half_length,
        inertia,
        a,
        v0,
        e,
        support: Support::Free,
    })
}

/// The f64 row of `line` (without its line ending), or `None` when the general row must take
/// it (see the module documentation).
pub(super) fn float_word_row(
    plan: &WordPlan,
    agreement: &Agreement,
    number: usize,
    line: &str,
) -> Option<SolvedRow> {
    let (inputs, claims) = read_cells(plan, line)?;
    let after = closed_form(&float_params(&inputs)?)?;
    let values = [after.v, after.rod_v, after.omega];
    let mut out = String::with_capacity(line.len() + 140);
    out.push_str(line);
    for x in values {
        out.push(',');
        write_float(&mut out, x);
    }
    let mut checks = Vec::new();
    for k in (0..STATE).filter(|&k| plan.claimed[k]) {
        let cell = claims[k].trim_ascii();
        if cell.is_empty() {
            out.push_str(",,");
            continue;
        }
        let claim = WordRatio::parse_bytes(cell)?;
        let rel_error = float_rel_error(&claim, values[k])?;
        let check = OutputCheck::finite(k, rel_error, None, agreement, Arithmetic::F64);
        check.write_cells(&mut out, false);
        checks.push(check);
    }
    out.push('\n');
    Some(SolvedRow::unlabelled(number, out, None, checks, None))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;
    use num_traits::ToPrimitive;
    use proptest::prelude::*;

    proptest! {
        /// The nearest f64 from integer parts is num-rational's correctly rounded value, at
        /// every size the row admits and beyond (ties included: n/d = odd/2^k).
        #[test]
        fn nearest_matches_the_correctly_rounded_ratio(n in 1u128..1 << 74, d in 1u128..1 << 74, k in 0u32..60) {
            let want = Q::new(n.into(), d.into()).to_f64().unwrap();
            prop_assert_eq!(nearest(n, d), want);
            // 55 bits whose last two are 10: exactly halfway, to the even neighbour (down for
            // ...00 10, up for ...01 10).
            for tie in [(1u128 << 54) | 2, (1u128 << 54) | 6] {
                let want = Q::new(tie.into(), (1u128 << k).into()).to_f64().unwrap();
                prop_assert_eq!(nearest(tie, 1 << k), want);
            }
        }
    }
}
