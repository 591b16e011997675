//! Scenes for the exact-cost measurements, shared by `benches/exact.rs` and
//! `examples/exact_cost.rs` (included with `#[path]`): the reference batches of
//! `../shared/data/` and random scenes of a given size.

use num_bigint::{BigInt, BigUint};
use rodimpact::batch::{Backend, Batch};
use rodimpact::field::Q;
use rodimpact::scene::Scene;

/// The first `limit` scenes of a reference batch in `../shared/data/`.
pub fn reference(file: &str, limit: usize) -> Vec<Scene> {
    let path = format!("{}/../shared/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("shared/data beside the project");
    let mut lines = text.lines();
    let batch = Batch::new(lines.next().expect("a header"), Backend::Exact).expect("the header");
    lines
        .take(limit)
        .enumerate()
        .map(|(i, line)| batch.scene(i + 1, line).expect("valid reference scene").0)
        .collect()
}

/// SplitMix64, as in PERFORMANCE.md's batches.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A random integer of exactly `bits` bits.
    fn int(&mut self, bits: u64) -> BigInt {
        let words = bits.div_ceil(32) as usize;
        let digits: Vec<u32> = (0..words).map(|_| self.next() as u32).collect();
        let mut n = BigUint::new(digits) >> (words as u64 * 32 - bits);
        n.set_bit(bits - 1, true);
        n.into()
    }

    fn rational(&mut self, bits: u64) -> Q {
        Q::new(self.int(bits), self.int(bits))
    }
}

pub fn random_scene(rng: &mut Rng, bits: u64) -> Scene {
    let (mut l, mut a) = (rng.rational(bits), rng.rational(bits));
    if a > l {
        std::mem::swap(&mut l, &mut a);
    }
    if rng.next() % 2 == 1 {
        a = -a;
    }
    Scene::builder(rng.rational(bits), rng.rational(bits))
        .half_length(l)
        .a(a)
        .v0(rng.rational(bits))
        .build()
        .expect("|a| <= l by construction")
}
