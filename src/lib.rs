#![warn(missing_docs)]
#![forbid(unsafe_code)]
//! rodimpact: exact verifier for the impact of a projectile on a rod.

pub mod error;
pub mod field;
pub mod number;

pub use error::{Error, ErrorKind};
