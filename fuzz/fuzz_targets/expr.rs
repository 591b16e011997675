//! The symbolic expression grammar of `check --claim`: any text parses or is refused, within
//! the limits, never a panic or a runaway.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::textbook::{ClaimedAnswer, expr};

fuzz_target!(|text: &str| {
    let _ = expr::parse("omega", text);
    let _ = ClaimedAnswer::parse(text);
});
