//! Problem files (`check FILE.toml`): parsed, and when valid, checked; never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::textbook::problems::{check_problems, parse_problems};

fuzz_target!(|text: &str| {
    if let Ok(problems) = parse_problems("fuzz.toml", text) {
        let _ = check_problems("fuzz.toml", &problems, None);
    }
});
