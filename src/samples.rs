//! Sample scenes for tests, benchmarks and examples: the rows of a batch file, read as
//! `rodimpact batch` reads them (the reference batches of the repository's `tests/data/` are
//! such files), and random scenes whose numbers have a given size.
//!
//! The test, benchmark and example targets each name the file; what they do with it is here,
//! once.

use crate::batch::{Arithmetic, Batch};
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::scene::Scene;
use crate::stability::SplitMix64;
use num_bigint::{BigInt, BigUint};
use std::path::Path;

/// One data row of a batch file: its text, its scene and the claimed v, V, omega it carries.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The row as written (without the line break).
    pub line: String,
    /// The scene of the row.
    pub scene: Scene,
    /// The claimed (v, V, omega), where the file has those columns.
    pub claimed: [Option<Q>; 3],
}

/// The first `limit` data rows of a batch file's text (its header line first).
///
/// # Errors
/// An empty text, a bad header or a bad row, as `rodimpact batch` reports them.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, samples::batch_samples};
/// let rows = batch_samples("m,M,a,omega\n1,1,1,6/5\n1,3,0,0\n", 10)?;
/// assert_eq!(rows.len(), 2);
/// assert_eq!(rows[0].line, "1,1,1,6/5");
/// assert_eq!(rows[0].claimed, [None, None, Some(q(6, 5))]);
/// assert_eq!(rows[1].scene.a(), &q(0, 1));
/// assert_eq!(batch_samples("m,M\n1,1\n2,1\n", 1)?.len(), 1);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn batch_samples(text: &str, limit: usize) -> Result<Vec<Sample>, Error> {
    let mut lines = text.lines();
    let header = lines
        .next()
        .ok_or_else(|| Error::new("header", ErrorKind::Invalid("the file is empty".into())))?;
    let batch = Batch::new(header, Arithmetic::Exact)?;
    lines
        .take(limit)
        .enumerate()
        .map(|(i, line)| {
            let (scene, claimed) = batch.scene(i + 1, line)?;
            Ok(Sample {
                line: line.to_string(),
                scene,
                claimed,
            })
        })
        .collect()
}

/// [`batch_samples`] of the file at `path`.
///
/// # Errors
/// The file cannot be read, or [`batch_samples`] refuses its text.
///
/// # Examples
/// ```
/// let path = std::env::temp_dir().join(format!("rodimpact-samples-{}.csv", std::process::id()));
/// std::fs::write(&path, "m,M,v\n1,1,0\n").unwrap();
/// let rows = rodimpact::samples::read_batch(&path, usize::MAX)?;
/// assert_eq!(rows[0].claimed[0], Some(rodimpact::field::q(0, 1)));
/// std::fs::remove_file(&path).unwrap();
/// assert!(rodimpact::samples::read_batch(&path, 1).is_err());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn read_batch(path: &Path, limit: usize) -> Result<Vec<Sample>, Error> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Error::io("FILE", format!("cannot read {}", path.display()), e))?;
    batch_samples(&text, limit)
}

/// A random free, elastic, uniform-rod scene whose m, M, l, a and v0 are each a fraction of two
/// integers of exactly `bits` bits (`bits >= 1`), with |a| <= l and a random sign of a. The
/// same generator state gives the same scene.
///
/// # Examples
/// ```
/// use rodimpact::{samples::sized_scene, stability::SplitMix64};
/// let s = sized_scene(&mut SplitMix64::new(20240611), 100);
/// assert_eq!(s, sized_scene(&mut SplitMix64::new(20240611), 100));
/// // A fraction of two 100-bit integers, reduced: at most 100 bits above and below.
/// assert!(s.v0().numer().bits() <= 100 && s.v0().denom().bits() <= 100);
/// assert!(s.v0().numer().bits() > 90);
/// assert!(s.a().abs() <= *s.half_length());
/// # use num_traits::Signed;
/// ```
pub fn sized_scene(rng: &mut SplitMix64, bits: u64) -> Scene {
    let (mut l, mut a) = (fraction(rng, bits), fraction(rng, bits));
    if a > l {
        std::mem::swap(&mut l, &mut a);
    }
    if rng.next_u64() % 2 == 1 {
        a = -a;
    }
    Scene::builder(fraction(rng, bits), fraction(rng, bits))
        .half_length(l)
        .a(a)
        .v0(fraction(rng, bits))
        .build()
        .expect("|a| <= l by construction")
}

/// A random integer of exactly `bits` bits (the top bit set).
fn integer(rng: &mut SplitMix64, bits: u64) -> BigInt {
    let words = bits.div_ceil(32) as usize;
    let digits: Vec<u32> = (0..words).map(|_| rng.next_u64() as u32).collect();
    let mut n = BigUint::new(digits) >> (words as u64 * 32 - bits);
    n.set_bit(bits - 1, true);
    n.into()
}

/// The fraction of two random `bits`-bit integers.
fn fraction(rng: &mut SplitMix64, bits: u64) -> Q {
    Q::new(integer(rng, bits), integer(rng, bits))
}
