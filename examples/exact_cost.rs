//! The cost of exactness, measured side by side: `cargo run --release --example exact_cost`.
//!
//! 1. Per scene (solve + the conservation laws) on both reference batches of `tests/data/`:
//!    f64 closed form, the straightforward `BigRational` path (generic solver over Q) and the
//!    fast exact path, interleaved on 1000-scene chunks; medians of per-chunk times and ratios.
//! 2. Growth of the fast exact cost with the size of the inputs: random scenes whose numerators
//!    and denominators have 10 to 100,000 bits; the exponent of the fitted power law.
//!
//! Pass `--quick` to stop the growth curve at 10,000 bits; add `--features malachite` to run the
//! big-integer fallback on malachite-nz.
//!
//! `--bits B --reps R` does only this: solves the same 10 random scenes of B bits R times on the
//! fast path and prints the time per scene. Under callgrind (valgrind), the instructions of
//! `--reps 2` minus those of `--reps 1`, over 10, are the instructions per scene, start-up and
//! scene generation cancelled.

use rodimpact::field::Q;
use rodimpact::samples::{read_batch, sized_scene};
use rodimpact::scene::Scene;
use rodimpact::solve::fast::fraction_free;
use rodimpact::solve::{
    fast::{closed_form::closed_form, linear::solve},
    outcome,
};
use rodimpact::stability::SplitMix64;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let value = |flag: &str| {
        let at = args.iter().position(|a| a == flag)?;
        let text = args
            .get(at + 1)
            .unwrap_or_else(|| panic!("{flag} needs a value"));
        Some(
            text.parse::<u64>()
                .unwrap_or_else(|e| panic!("{flag}: {e}")),
        )
    };
    if let Some(bits) = value("--bits") {
        return repeat(bits, value("--reps").unwrap_or(1));
    }
    let quick = args.iter().any(|a| a == "--quick");
    println!("== per scene, side by side (medians over 1000-scene chunks) ==");
    println!(
        "batch     | f64 ns | BigRational us | fast us | BigRational/f64 | fast/f64 | BigRational/fast"
    );
    for (label, file) in [("1e6", "bench-1e6.csv"), ("textbook", "bench-textbook.csv")] {
        side_by_side(label, &reference(file));
    }
    println!();
    println!("== growth of the fast exact cost with input size ==");
    // The fast path's big-integer fallback: the cargo feature `malachite` switches it.
    let big = if cfg!(feature = "malachite") {
        "malachite-nz"
    } else {
        "dashu-int"
    };
    println!("(big-integer fallback on {big})");
    growth(if quick { 10_000 } else { 100_000 });
}

/// Every scene of the reference batch `file` of `tests/data/` (see `tests/data/README.md`).
fn reference(file: &str) -> Vec<Scene> {
    let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    read_batch(path.as_ref(), usize::MAX)
        .unwrap_or_else(|e| panic!("the reference batch {file}: {e}"))
        .into_iter()
        .map(|row| row.scene)
        .collect()
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

/// Seconds per scene of `work` over `chunk`, repeated `reps` times.
fn per_scene(reps: usize, chunk: usize, mut work: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        work();
    }
    start.elapsed().as_secs_f64() / (reps * chunk) as f64
}

fn side_by_side(label: &str, scenes: &[Scene]) {
    let (mut f, mut b, mut x) = (vec![], vec![], vec![]);
    let (mut bf, mut xf, mut bx) = (vec![], vec![], vec![]);
    for chunk in scenes.chunks(1000) {
        let floats: Vec<_> = chunk.iter().map(|s| s.params::<f64>()).collect();
        let exact: Vec<_> = chunk.iter().map(|s| s.params::<Q>()).collect();
        let tf = per_scene(200, chunk.len(), || {
            for p in &floats {
                black_box(closed_form(black_box(p)).map(|m| outcome(p, m)));
            }
        });
        let tb = per_scene(1, chunk.len(), || {
            for p in &exact {
                black_box(solve(black_box(p)));
            }
        });
        let tx = per_scene(3, chunk.len(), || {
            for s in chunk {
                black_box(fraction_free::solve(black_box(s)));
            }
        });
        bf.push(tb / tf);
        xf.push(tx / tf);
        bx.push(tb / tx);
        f.push(tf);
        b.push(tb);
        x.push(tx);
    }
    println!(
        "{label:9} | {:6.1} | {:14.2} | {:7.3} | {:15.0} | {:8.0} | {:16.1}",
        median(f) * 1e9,
        median(b) * 1e6,
        median(x) * 1e6,
        median(bf),
        median(xf),
        median(bx)
    );
}

/// `--bits B --reps R`: the fast path on 10 random scenes of `bits` bits, `reps` times.
fn repeat(bits: u64, reps: u64) {
    let mut rng = SplitMix64::new(20240611);
    let scenes: Vec<Scene> = (0..10).map(|_| sized_scene(&mut rng, bits)).collect();
    let t = per_scene(reps as usize, scenes.len(), || {
        for s in &scenes {
            black_box(fraction_free::solve(black_box(s)));
        }
    });
    println!("{bits} bits: {:.1} us per scene", t * 1e6);
}

fn growth(max_bits: u64) {
    println!("bits    | fast exact us/scene | BigRational us/scene");
    let mut rng = SplitMix64::new(20240611);
    let mut points = vec![];
    for bits in [10u64, 32, 100, 316, 1000, 3162, 10_000, 31_623, 100_000] {
        if bits > max_bits {
            break;
        }
        let count = (200_000 / bits).clamp(1, 200) as usize;
        let scenes: Vec<Scene> = (0..count).map(|_| sized_scene(&mut rng, bits)).collect();
        let t_fast = per_scene(1, count, || {
            for s in &scenes {
                black_box(fraction_free::solve(black_box(s)));
            }
        });
        let t_big = (bits <= 3162).then(|| {
            let exact: Vec<_> = scenes.iter().map(|s| s.params::<Q>()).collect();
            per_scene(1, count, || {
                for p in &exact {
                    black_box(solve(black_box(p)));
                }
            })
        });
        let big = t_big.map_or("-".to_string(), |t| format!("{:.1}", t * 1e6));
        println!("{bits:7} | {:19.1} | {big:>20}", t_fast * 1e6);
        points.push((bits as f64, t_fast));
    }
    let fit: Vec<_> = points.iter().filter(|(b, _)| *b >= 1000.0).collect();
    if fit.len() >= 2 {
        let n = fit.len() as f64;
        let (xs, ys): (Vec<f64>, Vec<f64>) = fit.iter().map(|(b, t)| (b.ln(), t.ln())).unzip();
        let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
        let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
        let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
        println!(
            "fitted exponent (inputs >= 1000 bits): cost ~ bits^{:.2}",
            sxy / sxx
        );
    }
}
