//! The application layer: one place per use that takes a user's input, calls the solvers and
//! hands complete results to [`crate::report`] (as rapier's `pipeline/` orchestrates its
//! solver). The command line (`crates/rodimpact-cli`), the Python package (`python/`) and the
//! pages' WebAssembly module (`wasm/`) call these.
//!
//! | file | the use |
//! |---|---|
//! | `pages/` | the web pages: what their WebAssembly module answers ([`pages::call_json`]), and the pages written with what they carry |
//! | `batch.rs` | the options of a batch audit, read once for `rodimpact batch` and Python's `audit()` |
//! | `impact_batch.rs` | `impact --batch` and Python's `audit_impacts()`: an engine's claimed impacts audited line by line, the summary |
//! | `impact.rs` | `rodimpact impact` and Python's `impact()`: a scene file answered under the laws or models asked for, its published answers checked |

pub mod batch;
pub mod impact;
pub mod impact_batch;
pub mod pages;
