//! The solver on arbitrary valid scenes: masses, half-length and speed any positive rationals,
//! a and the pivot anywhere on the rod, e in [0, 1], every kind of rod. Inside the target: the
//! generic exact solve has exactly zero residuals (momentum, angular momentum, energy when
//! e = 1), and the fast exact path gives the same motion with its laws holding.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::solve::fast::fraction_free;
use rodimpact::field::Q;
use rodimpact::scene::{RodInertia, Scene};
use rodimpact::solve::fast::linear::solve;

/// Reads rationals out of the fuzzer's bytes (zero when they run out).
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn int(&mut self, width: usize) -> i128 {
        let (head, rest) = self.0.split_at(width.min(self.0.len()));
        self.0 = rest;
        head.iter().fold(0i128, |acc, &b| acc << 8 | i128::from(b))
    }
    /// A positive rational.
    fn positive(&mut self) -> Q {
        let (n, d) = (self.int(8) + 1, self.int(8) + 1);
        Q::new(n.into(), d.into())
    }
    /// A rational in [-1, 1] (or [0, 1] when `signed` is false).
    fn unit(&mut self, signed: bool) -> Q {
        let d = self.int(4) + 1;
        let n = self.int(4) % (d + 1);
        let negative = signed && self.int(1) % 2 == 1;
        Q::new((if negative { -n } else { n }).into(), d.into())
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let (m, big_m, l, v0) = (b.positive(), b.positive(), b.positive(), b.positive());
    let a = b.unit(true) * &l;
    let e = b.unit(false);
    let rod = match b.int(1) % 4 {
        0 => RodInertia::Uniform,
        1 => RodInertia::Dumbbell,
        2 => RodInertia::Gyration(b.unit(false) * &l),
        _ => RodInertia::Moment(b.unit(false) * &big_m * &l * &l),
    };
    let pivot = (b.int(1) % 2 == 1).then(|| b.unit(true) * &l);
    let mut builder = Scene::builder(m, big_m)
        .half_length(l)
        .a(a)
        .v0(v0)
        .e(e)
        .rod(rod);
    if let Some(p) = pivot {
        builder = builder.pivot(p);
    }
    // r_G = 0 or I = 0 is refused by the builder; everything else here is valid.
    let Ok(scene) = builder.build() else { return };
    let out = solve(&scene.params::<Q>()).expect("a valid scene is nonsingular");
    assert!(out.residuals.all_zero(), "{scene:?}: {:?}", out.residuals);
    let fast = fraction_free::solve(&scene);
    assert_eq!(fast.after, out.after, "{scene:?}");
    assert!(fast.laws_hold, "{scene:?}");
});
