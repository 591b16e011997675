//! Numerical stability of the float backends, measured exactly: condition numbers
//! ([`condition`]), exact error measurement ([`Measured`]), the backends compared
//! ([`Backend`]), the stiff/extreme scene suite and a seeded random sweep, and the report of
//! `rodimpact stability` (error in units of cond u against run time).

mod backend;
mod condition;
mod measure;
mod report;
mod suite;
mod timing;

pub use backend::{Backend, Reference};
pub use condition::condition;
pub use measure::{Class, Measured};
pub use report::{Row, json, markdown, report};
pub use suite::{Case, SplitMix64, in_range, suite, sweep};
pub use timing::median_nanos;
