//! The stiff/extreme scene suite of docs/stability.md (items 1-22; item 22 is six f32 scenes),
//! with exact rational inputs, and a seeded random sweep over many decades.

use crate::field::Q;
use crate::scene::{Scene, SceneInput};
use crate::solve::fast::float::Real;
use num_traits::Zero;

/// One scene of the suite or the sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Id: `"1"` .. `"21"`, `"22a"` .. `"22f"`, or `"sweep-N"`.
    pub id: String,
    /// What the scene stresses.
    pub what: String,
    /// The exact scene (a free rod).
    pub scene: Scene,
}

/// (id, what, "key=value" inputs); unnamed keys take the `solve` defaults (l = 1, v0 = 1, e = 1,
/// uniform rod).
const SUITE: [(&str, &str, &str); 27] = [
    ("1", "paper scene, a = l/2", "m=1 M=1 a=1/2"),
    ("2", "a* = 1 exactly", "m=1 M=3 a=1 rod=I=3/4"),
    ("3", "v = 0, binary inputs", "m=1 M=2 a=1 rod=dumbbell"),
    ("4", "v = 0 in Q, inputs round", "m=4/7 M=1 a=1/2"),
    (
        "5",
        "stop zone, m = 4/7 + 1e-12",
        "m=4000000000007/7000000000000 M=1 a=1/2",
    ),
    (
        "6",
        "stop zone, m = 4/7 + 1e-20",
        "m=400000000000000000007/700000000000000000000 M=1 a=1/2",
    ),
    ("7", "v = 0 with e = 9/10", "m=18/35 M=1 a=1/2 e=9/10"),
    ("8", "M/m = 1e30", "m=1 M=1e30 a=1/2"),
    ("9", "M/m = 1e-30", "m=1 M=1e-30 a=1/2"),
    ("10", "a = 0 (omega = 0)", "m=1 M=3 a=0"),
    ("11", "a = 1e-300", "m=1 M=3 a=1e-300"),
    ("12", "I = 1e-300", "m=1 M=1 a=1 rod=I=1e-300"),
    ("13", "I = 1e-310 (subnormal)", "m=1 M=1 a=1 rod=I=1e-310"),
    ("14", "I = 1e300", "m=1 M=3 l=1e150 a=1 rod=I=1e300"),
    ("15", "m = M = v0 = 1e200", "m=1e200 M=1e200 v0=1e200 a=1/2"),
    (
        "16",
        "m = M = v0 = 1e-200",
        "m=1e-200 M=1e-200 v0=1e-200 a=1/2",
    ),
    ("17", "m = 1e-310, M = 3e-310", "m=1e-310 M=3e-310 a=1/2"),
    (
        "18",
        "l = 1e-160 (a^2 subnormal)",
        "m=1e20 M=3e20 l=1e-160 a=5e-161",
    ),
    (
        "19",
        "l = 1e160 (a^2 overflows)",
        "m=1e-20 M=3e-20 l=1e160 a=5e159",
    ),
    ("20", "e = 0, M/m = 1e20", "m=1 M=1e20 a=1/2 e=0"),
    ("21", "m = 1e10, v0 = 1e300", "m=1e10 M=1 v0=1e300 a=1/2"),
    ("22a", "f32: M/m = 1e30", "m=1 M=1e30 a=1/2"),
    ("22b", "f32: I = 1e-40", "m=1 M=1 a=1 rod=I=1e-40"),
    (
        "22c",
        "f32: m = M = v0 = 1e20",
        "m=1e20 M=1e20 v0=1e20 a=1/2",
    ),
    (
        "22d",
        "f32: m = M = v0 = 1e-20",
        "m=1e-20 M=1e-20 v0=1e-20 a=1/2",
    ),
    ("22e", "f32: m = M/3 = 1e-40", "m=1e-40 M=3e-40 a=1/2"),
    (
        "22f",
        "f32: m = 1e10, v0 = 1e30",
        "m=1e10 M=1 v0=1e30 a=1/2",
    ),
];

fn scene_of(text: &str) -> Scene {
    let mut s = SceneInput::default();
    for pair in text.split_whitespace() {
        let (key, value) = pair.split_once('=').expect("suite data is key=value");
        let value = Some(value.to_string());
        match key {
            "m" => s.m = value,
            "M" => s.rod_mass = value,
            "l" => s.l = value,
            "a" => s.a = value,
            "v0" => s.v0 = value,
            "rod" => s.rod = value,
            "e" => s.e = value,
            _ => unreachable!("suite keys are m, M, l, a, v0, rod, e"),
        }
    }
    s.build().expect("suite scenes are valid")
}

/// The suite: docs/stability.md items 1-22 (item 23, the compliant-contact models, belongs to
/// `simulate`, which is not implemented).
///
/// # Examples
/// ```
/// let suite = rodimpact::stability::suite();
/// assert_eq!(suite.len(), 27);
/// assert_eq!(suite[2].id, "3");
/// ```
pub fn suite() -> Vec<Case> {
    SUITE
        .iter()
        .map(|(id, what, text)| Case {
            id: id.to_string(),
            what: what.to_string(),
            scene: scene_of(text),
        })
        .collect()
}

/// SplitMix64: a small deterministic generator, so sweeps are reproducible from their seed.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from `seed`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::stability::SplitMix64;
    /// let mut g = SplitMix64::new(1);
    /// assert_eq!(g.next_u64(), SplitMix64::new(1).next_u64());
    /// ```
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::stability::SplitMix64;
    /// assert_ne!(SplitMix64::new(7).next_u64(), 0);
    /// ```
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo..=hi` (`lo <= hi`).
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    /// `(n/d) 10^k`, n in 1..=999, d with factors 3 and 7 (so it rounds), |k| <= decades.
    fn magnitude(&mut self, decades: i64) -> Q {
        let n = self.range(1, 999);
        let d = [1, 3, 7, 9, 21, 49][self.range(0, 5) as usize];
        let k = self.range(-decades, decades);
        let ten = num_bigint::BigInt::from(10);
        let power = ten.pow(k.unsigned_abs() as u32);
        let x = Q::new(n.into(), d.into());
        if k >= 0 {
            x * Q::from_integer(power)
        } else {
            x / Q::from_integer(power)
        }
    }
}

/// `count` random free-rod scenes from `seed`: m, M, l and v0 over 10^-decades..10^decades
/// (independently), I = M l^2 x/(1 + x) with x over the same decades, a = l j/97 with |j| <= 97, e one of 1, 0, 9/10, j/97.
///
/// # Examples
/// ```
/// let a = rodimpact::stability::sweep(5, 3, 300);
/// assert_eq!(a, rodimpact::stability::sweep(5, 3, 300)); // reproducible
/// assert_eq!(a.len(), 3);
/// ```
pub fn sweep(seed: u64, count: usize, decades: i64) -> Vec<Case> {
    let mut g = SplitMix64::new(seed);
    (0..count)
        .map(|i| {
            let [m, rod_mass, x, l, v0] = [(); 5].map(|_| g.magnitude(decades));
            let a = &l * Q::new(g.range(-97, 97).into(), 97.into());
            // I <= M l^2 (a physical rod), as far below as 10^-decades.
            let inertia = &rod_mass * &l * &l * (&x / (Q::from_integer(1.into()) + &x));
            let e = match g.range(0, 3) {
                0 => Q::from_integer(1.into()),
                1 => Q::zero(),
                2 => Q::new(9.into(), 10.into()),
                _ => Q::new(g.range(0, 97).into(), 97.into()),
            };
            let scene = Scene::builder(m, rod_mass)
                .half_length(l)
                .a(a)
                .v0(v0)
                .e(e)
                .rod(crate::scene::RodInertia::Moment(inertia))
                .build()
                .expect("sweep scenes are valid");
            Case {
                id: format!("sweep-{i}"),
                what: format!("seed {seed}, +-{decades} decades"),
                scene,
            }
        })
        .collect()
}

/// Whether a free-rod scene is in range for the format `T`: every nonzero input (m, M, I, a,
/// v0, e) and every nonzero exact output (v, V, omega) is a normal number of `T` once rounded.
///
/// # Examples
/// ```
/// use rodimpact::stability::{in_range, suite};
/// let s = suite();
/// assert!(in_range::<f64>(&s[0].scene));
/// assert!(!in_range::<f64>(&s[12].scene)); // I = 1e-310 is subnormal
/// assert!(!in_range::<f32>(&s[14].scene)); // m = 1e200 overflows f32
/// ```
pub fn in_range<T: Real>(scene: &Scene) -> bool {
    super::Reference::of(scene).is_some_and(|reference| reference.in_range::<T>())
}
