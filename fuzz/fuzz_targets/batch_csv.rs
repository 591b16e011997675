//! Batch CSV: the first line is the header, every further line a row; exact and f64 backends.
//! Never a panic; an exact row's conservation laws hold whenever it is solved; the streaming
//! `run` (chunks solved in parallel, reading and writing overlapped) writes exactly the rows
//! `Batch::row` gives, in order, or stops at the first bad one.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::batch::{Arithmetic, Batch, run};
use std::sync::OnceLock;

/// One worker: `run`'s logic without waking threads on every input (tens of ms under the
/// sanitizer with the other core busy); `crates/rodimpact-cli/tests/cli/batch.rs` runs it on two.
fn pool() -> &'static rayon::ThreadPool {
    static POOL: OnceLock<rayon::ThreadPool> = OnceLock::new();
    POOL.get_or_init(|| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .expect("a one-thread pool")
    })
}

fuzz_target!(|text: &str| {
    let mut lines = text.lines();
    let Some(header) = lines.next() else { return };
    for arithmetic in [Arithmetic::Exact, Arithmetic::F64] {
        let Ok(batch) = Batch::new(header, arithmetic) else {
            return;
        };
        let mut expected = String::new();
        let mut first_error = None;
        for (i, line) in text.lines().skip(1).take(16).enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            match batch.row(i + 1, line) {
                Ok(row) => {
                    if arithmetic == Arithmetic::Exact {
                        assert_ne!(row.laws_held, Some(false), "{header}\n{line}");
                    }
                    if first_error.is_none() {
                        expected.push_str(&row.line);
                    }
                }
                Err(e) => {
                    first_error.get_or_insert(e);
                }
            }
        }
        if text.lines().count() > 17 || text.contains('\r') {
            continue; // `run` reads more rows, or splits lines differently
        }
        let body: String = text.lines().skip(1).map(|l| format!("{l}\n")).collect();
        let mut out = Vec::new();
        let result = pool().install(|| run(body.as_bytes(), &mut out, &batch, |_| {}));
        match first_error {
            None => {
                let summary = result.expect("every row was solved one by one");
                assert_eq!(String::from_utf8(out).unwrap(), expected);
                assert_eq!(summary.laws_failed, 0);
            }
            Some(e) => assert_eq!(result.unwrap_err(), e),
        }
    }
});
