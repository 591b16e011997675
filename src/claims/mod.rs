//! The claims: every claim of the paper and the results beyond it, each formalised, decided by
//! exact computation and carrying the certificates that prove it.
//!
//! A claim's verdict comes only from re-checking its certificates ([`Claim::check`]):
//!
//! - PROVED: every certificate checks;
//! - REFUTED: the counterexample certificates check (the statement is false there);
//! - QUALIFIED: the natural reading is refuted by the counterexample, and the qualified
//!   statement is proved by the proof certificates.
//!
//! The paper's printed formulas enter as data ([`Paper`]), independent of the solver; a test
//! replaces one of them by a wrong one and the claims that depend on it must then fail.
//!
//! The layout: one file per claim (`paper/c01.rs` ... , `beyond/x01.rs` ...), listed once in
//! the [`registry()`]; the types in `claim.rs`; the certificate kinds in [`certificate`], one per
//! file; the small language the claim files are written in in `dsl/`.

pub mod certificate;
mod claim;
mod decide;
mod dsl;
pub mod export;
mod formula;
mod printed;
mod registry;

pub use certificate::{Certificate, CertificateError, Expected, PosExpr, Relation, SignClass};
pub use claim::{CheckError, Claim, Decided, Decision, Entry, Formalised, Group, Verdict};
pub use decide::{decide, decide_all, decide_entry};
pub use formula::Formula;
pub use printed::Paper;
pub use registry::{IdRange, beyond_claims, beyond_ids, find, paper_claims, paper_ids, registry};
