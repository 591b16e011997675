//! A small median-of-N timer for the report (criterion belongs to the benchmarks' own package,
//! `benches/`). Times are reported, never asserted.

use std::time::Instant;

/// Batches per measurement; the median batch is reported.
const BATCHES: usize = 9;
/// A batch runs at least this long, so the clock's resolution does not matter.
const MIN_BATCH_NANOS: u128 = 20_000;

/// Median time of one call of `f`, in nanoseconds: the batch size doubles until a batch takes
/// 20 µs, then the median of 9 batches is divided by the batch size.
///
/// # Examples
/// ```
/// let ns = rodimpact::stability::median_nanos(|| std::hint::black_box(1.0f64).sqrt());
/// assert!(ns > 0.0);
/// ```
pub fn median_nanos<R>(mut f: impl FnMut() -> R) -> f64 {
    let mut batch: u32 = 1;
    let run = |f: &mut dyn FnMut() -> R, n: u32| {
        let start = Instant::now();
        for _ in 0..n {
            std::hint::black_box(f());
        }
        start.elapsed().as_nanos()
    };
    while batch < (1 << 20) && run(&mut f, batch) < MIN_BATCH_NANOS {
        batch *= 2;
    }
    let mut times: Vec<u128> = (0..BATCHES).map(|_| run(&mut f, batch)).collect();
    times.sort_unstable();
    (times[BATCHES / 2] as f64 / f64::from(batch)).max(f64::MIN_POSITIVE)
}
