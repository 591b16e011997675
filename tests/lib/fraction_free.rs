//! The fast exact path against the reference path: bit-identical v, V, omega on every row of
//! both reference batches and on random scenes, in each arithmetic (i128, 512 bits, big integers:
//! dashu's, or malachite's with the feature, from small inputs to thousands of bits).

use crate::common;

use common::{any_scene, reference_rows};
use proptest::prelude::*;
use rodimpact::field::Q;
use rodimpact::samples::sized_scene;
use rodimpact::scene::{RodInertia, Scene};
use rodimpact::solve::fast::fraction_free;
use rodimpact::solve::fast::linear::solve;
use rodimpact::stability::SplitMix64;

/// Fast and fraction-free-big results equal the generic solver's; the laws hold.
fn assert_same_as_reference(s: &Scene, context: &str) -> fraction_free::FractionFree {
    let reference = solve(&s.params::<Q>()).expect("nonsingular");
    let quick = fraction_free::solve(s);
    let big = fraction_free::solve_big(s);
    assert_eq!(quick.after, reference.after, "fast path, {context}");
    assert_eq!(big.after, reference.after, "big-integer path, {context}");
    assert!(quick.laws_hold && big.laws_hold, "laws, {context}");
    quick
}

fn check_batch(file: &str) -> [usize; 3] {
    let mut paths = [0; 3];
    for (line, s, f) in reference_rows(file, usize::MAX) {
        let out = assert_same_as_reference(&s, &line);
        assert_eq!(
            (&out.after.v, &out.after.rod_v, &out.after.omega),
            (&f[0], &f[1], &f[2]),
            "the file's exact values, row {line}"
        );
        paths[out.width as usize] += 1;
    }
    paths
}

#[test]
fn the_10e6_batch_is_reproduced_bit_for_bit() {
    // Every 10^6-sized scene overflows i128 and fits 512 bits.
    assert_eq!(check_batch("bench-1e6.csv"), [0, 10_000, 0]);
}

#[test]
fn the_textbook_batch_is_reproduced_bit_for_bit() {
    // Every textbook scene (inputs <= 100) fits the fixed width, energy identity included.
    assert_eq!(check_batch("bench-textbook.csv"), [10_000, 0, 0]);
}

/// A positive rational with numerator and denominator of up to `bits` bits.
fn wide(bits: u32) -> impl Strategy<Value = Q> {
    let max = (1u64 << bits) - 1;
    (1..=max, 1..=max).prop_map(|(n, d)| Q::new(n.into(), d.into()))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Law: from the 512-bit width to far beyond it (random scenes of 32 to 2,000 bits a part,
    /// e random, sometimes pivoted), the fast path and the big-integer fallback on its own give
    /// the generic solver's exact values over num-rational.
    #[test]
    fn big_integers_equal_generic_at_thousands_of_bits(
        seed in any::<u64>(), bits in 32u64..=2000, e in 0i64..=4, pivot in any::<bool>(),
    ) {
        let s = sized_scene(&mut SplitMix64::new(seed), bits);
        let mut builder = Scene::builder(s.m().clone(), s.rod_mass().clone())
            .half_length(s.half_length().clone())
            .a(s.a().clone())
            .v0(s.v0().clone())
            .e(Q::new(e.into(), 4.into()));
        if pivot {
            builder = builder.pivot(-s.half_length() / Q::from_integer(3.into()));
        }
        let s = builder.build().unwrap();
        assert_same_as_reference(&s, &format!("{bits} bits, seed {seed}"));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Law: on any valid scene (any rod, any e, free or pivoted) the fast path gives the
    /// generic solver's exact values and the laws hold.
    #[test]
    fn fast_equals_generic_on_any_scene(s in any_scene()) {
        assert_same_as_reference(&s, &format!("{s:?}"));
    }

    /// Law: the same across the fixed-width overflow boundary (inputs of 8 to 40 bits), for
    /// every rod kind, e and support.
    #[test]
    fn fast_equals_generic_across_the_overflow_boundary(
        bits in 8u32..=40,
        kind in 0u8..4,
        e_num in 0i64..=4,
        sign in proptest::bool::ANY,
        pivot in proptest::option::of(-8i64..=8),
        seed in (wide(40), wide(40), wide(40), wide(40), (1u64..=1000, 1u64..=1000)),
    ) {
        let scale = Q::from_integer(1.into()) / Q::from_integer((1u64 << (40 - bits)).into());
        let (m, big_m, l, v0, (p, q)) = seed;
        let (m, big_m, l, v0) = (m * &scale, big_m * &scale, l * &scale, v0 * &scale);
        let frac = Q::new(p.min(q).into(), p.max(q).into());
        let a = if sign { -(&l * &frac) } else { &l * &frac };
        let rod = match kind {
            0 => RodInertia::Uniform,
            1 => RodInertia::Dumbbell,
            2 => RodInertia::Gyration(&l * &frac),
            _ => RodInertia::Moment(&big_m * &l * &l * &frac),
        };
        let mut builder = Scene::builder(m, big_m);
        if let Some(k) = pivot {
            builder = builder.pivot(&l * Q::new(k.into(), 8.into()));
        }
        let s = builder
            .half_length(l)
            .a(a)
            .v0(v0)
            .e(Q::new(e_num.into(), 4.into()))
            .rod(rod)
            .build()
            .unwrap();
        assert_same_as_reference(&s, &format!("{s:?}"));
    }
}

/// A value of the hostile review's G1 scenes: a power of ten 10^k (|k| from 300 to 2,000), an
/// integer of 300 to 2,000 digits, or a small fraction.
fn hostile(rng: &mut SplitMix64) -> Q {
    let ten = num_bigint::BigInt::from(10u8);
    match rng.next_u64() % 3 {
        0 => {
            let k = 300 + (rng.next_u64() % 1701) as u32;
            let p = ten.pow(k);
            if rng.next_u64().is_multiple_of(2) {
                Q::from_integer(p)
            } else {
                Q::new(1.into(), p)
            }
        }
        1 => {
            let digits = 300 + (rng.next_u64() % 1701) as u32;
            let x = ten.pow(digits - 1) + num_bigint::BigInt::from(rng.next_u64());
            Q::from_integer(x)
        }
        _ => Q::new(
            (1 + rng.next_u64() % 97).into(),
            (1 + rng.next_u64() % 89).into(),
        ),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// G1 (docs/upstream-dashu-gcd.md): scenes of 300- to 2,000-digit numbers and powers of
    /// ten, with pivots such as 1e-622 (a third of them panicked in dashu-int 0.4.3's gcd, exit
    /// 101), are solved, and the big-integer path gives the generic solver's exact values.
    #[test]
    fn hostile_big_scenes_never_panic_and_agree(seed in any::<u64>(), pivot in 0u32..3) {
        let mut rng = SplitMix64::new(seed);
        let (m, big_m, l) = (hostile(&mut rng), hostile(&mut rng), hostile(&mut rng));
        let a = &l * Q::new(((rng.next_u64() % 9) as i64 - 4).into(), 4.into());
        let mut builder = Scene::builder(m, big_m).half_length(l.clone()).a(a);
        builder = match pivot {
            0 => builder,
            1 => builder.pivot(&l / Q::from_integer(num_bigint::BigInt::from(10u8).pow(622))),
            _ => builder.pivot(&l / Q::from_integer((2 + rng.next_u64() % 7).into())),
        };
        let s = builder.build().unwrap();
        assert_same_as_reference(&s, &format!("seed {seed}"));
    }
}

/// G1's own scene, whole: `solve --m 1 --M 1 --pivot 1e-622` exited 101 with dashu-int 0.4.3.
#[test]
fn the_pivot_at_1e_minus_622_is_solved() {
    let p = Q::new(1.into(), num_bigint::BigInt::from(10u8).pow(622));
    let s = Scene::builder(Q::from_integer(1.into()), Q::from_integer(1.into()))
        .pivot(p)
        .build()
        .unwrap();
    assert_same_as_reference(&s, "pivot 1e-622");
}
