//! The library tested directly: the exact routes against each other, the batch word rows, the
//! claims and their mutations, the golden files, the documentation, the float error and the
//! compliant-contact model. One test binary; each module was a test file of its own.

#[path = "../common/mod.rs"]
mod common;

/// The repository's root: the examples and reference data the tests read.
pub const ROOT: &str = env!("CARGO_MANIFEST_DIR");

mod architecture;
mod batch_header;
mod batch_words;
mod docs;
mod engine_laws;
mod fast_routes;
mod fraction_free;
mod golden;
mod impact_oracle;
mod impact_several;
mod msrv;
mod mutation;
mod pages;
mod simulate;
mod solve_exact;
mod stability;
mod textbook;
