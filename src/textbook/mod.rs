//! Checking published answers: `rodimpact check`.
//!
//! A claimed answer (`omega=1.89 rad/s`, `omega=36/19`, `omega=12*m*v0/((M+4*m)*L)`) is
//! compared with the exact answer of its scene. Printed numbers are judged by their own
//! significant figures ([`sigfig`]), with units converted exactly ([`units`]); formulas
//! ([`expr`]) are decided as identities over the scene's domain ([`symbolic`]), with a
//! counterexample scene when false. [`problems`] reads problem collections (TOML).
//!
//! The files, bottom up: the claimed answer and what it is about (`quantity.rs`, `claim.rs`,
//! `exact.rs`), what checking it found (`answer.rs`: [`CheckedAnswer`], [`AnswerAgreement`],
//! [`SceneCheck`]), deciding a number ([`numeric`]) or a formula ([`symbolic`]), and the
//! orchestration of one scene's claims (`check.rs`: [`check_scene`]). The reports are rendered
//! by [`crate::report`] (`check_table`, `check_json`, `problems_text`, `problems_json`).
//!
//! # Examples
//! ```
//! use rodimpact::textbook::{check_scene, ClaimedAnswer};
//! use rodimpact::scene::SceneInput;
//! let scene = SceneInput {
//!     m: Some("0.100 kg".into()), rod_mass: Some("1.50 kg".into()), length: Some("2.00 m".into()),
//!     from_end: Some("0".into()), v0: Some("12.0 m/s".into()), e: Some("0".into()),
//!     ..Default::default()
//! };
//! let claims = [ClaimedAnswer::parse("omega=1.89").unwrap(), ClaimedAnswer::parse("omega=0.947").unwrap()];
//! let check = check_scene(&scene, &claims, None).unwrap();
//! assert!(check.answers[0].agrees() && !check.answers[1].agrees());
//! assert_eq!(check.answers[1].exact, "36/19");
//! ```

mod answer;
mod check;
mod claim;
mod exact;
pub mod expr;
pub mod formula;
pub mod impact;
mod mistakes;
pub mod numeric;
pub mod problems;
mod quantity;
pub mod sigfig;
mod spelling;
mod surd_form;
pub mod symbolic;
pub mod units;

pub use answer::{
    AnswerAgreement, CheckedAnswer, Counterexample, RelError, SceneCheck, SceneSummary,
};
pub use check::{check_claims, check_scene, check_scene_within};
pub use claim::{ClaimedAnswer, ClaimedValue, read_claimed};
pub use exact::Exact;
pub use quantity::Quantity;
