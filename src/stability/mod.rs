//! Numerical stability of the float backends, measured exactly: condition numbers
//! ([`condition`]), the accuracy of one float output against its exact value ([`Accuracy`]),
//! the backends compared ([`Backend`]), the stiff/extreme scene suite and a seeded random sweep,
//! and the comparison behind `rodimpact stability` ([`compare_backends`]: error in units of
//! cond u against run time; rendered by `crate::report`).

mod backend;
mod comparison;
mod condition;
mod judged;
mod measure;
mod suite;
mod timing;

pub use backend::{Backend, Reference};
pub use comparison::{BackendStats, compare_backends};
pub use condition::condition;
pub use judged::{ERROR_BOUND, Enclosure, Judged, JudgedFloat, judge};
pub use measure::{Accuracy, Class};
pub use suite::{Case, SplitMix64, in_range, suite, sweep};
pub use timing::median_nanos;
