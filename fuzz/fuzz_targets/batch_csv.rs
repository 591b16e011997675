//! Batch CSV: the first line is the header, every further line a row; exact and f64 backends.
//! Never a panic; an exact row's conservation laws hold whenever it is solved.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::batch::{Backend, Batch};

fuzz_target!(|text: &str| {
    let mut lines = text.lines();
    let Some(header) = lines.next() else { return };
    for backend in [Backend::Exact, Backend::F64] {
        let Ok(batch) = Batch::new(header, backend) else {
            return;
        };
        for (i, line) in text.lines().skip(1).take(16).enumerate() {
            if let Ok(row) = batch.row(i + 1, line)
                && backend == Backend::Exact
            {
                assert_ne!(row.laws_held, Some(false), "{header}\n{line}");
            }
        }
    }
});
