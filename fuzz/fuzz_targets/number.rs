//! Exact numbers, bare and with units: never a panic; a parsed number prints and parses back
//! to itself whenever its printed form is within the digit limit (`1e10000` is accepted, but
//! its 10,001 written-out digits are not: the limit counts digits as typed).
#![no_main]

use libfuzzer_sys::fuzz_target;
use rodimpact::number;
use rodimpact::textbook::units::{Dimension, Measured};

const DIMENSIONS: [Dimension; 6] = [
    Dimension::Mass,
    Dimension::Length,
    Dimension::Speed,
    Dimension::AngularSpeed,
    Dimension::Energy,
    Dimension::Impulse,
];

fuzz_target!(|text: &str| {
    if let Ok(q) = number::parse(text) {
        if let Ok(back) = number::parse(&q.to_string()) {
            assert_eq!(back, q, "{text}");
        }
        let _ = rodimpact::field::decimal::decimal(&q, 30);
    }
    for dimension in DIMENSIONS {
        if let Ok(measured) = Measured::parse("x", text, dimension) {
            let _ = measured.si();
        }
    }
});
