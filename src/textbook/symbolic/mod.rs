//! Symbolic scenes and claims: a scene quantity not given is a free symbol, except the
//! collision law (elastic, e = 1) and the rod (uniform), which take the defaults of `solve`;
//! a claimed formula is decided as an identity over the scene's domain with
//! [`RatFn`](crate::field::RatFn) arithmetic and, when it is not one, refuted by a concrete valid
//! scene found by search.
//!
//! `L` stands for `2*l`; `d`, the distance of the impact from the nearer end, for `l - a`
//! (`l - |a|` when `a` is a number); `I` for the rod's moment of inertia about its centre and
//! `r` for its radius of gyration. A formula with `sqrt` is decided by squares, exactly, and
//! its sign at a valid sample scene (the rest of the domain is assumed to keep that sign).
//!
//! A scene whose formulas leave no valid sample scene (`--a 2*l`, `--M -m`) is refused,
//! naming the field, before any claim is decided.
//!
//! The oblique flags (`formula` only) are read by [`oblique_params`] over the built scene.
//!
//! [`GivenScene`] reads the flags once (numbers and formulas), [`SymbolicScene`] builds the scene
//! in its free symbols and checks its domain (`scene.rs`), and `identity.rs` decides a formula
//! against the exact value or finds a counterexample scene.

mod given;
mod identity;
mod oblique;
mod scene;

pub use given::{GivenScene, heaviest_field};
pub(crate) use identity::identity;
pub use oblique::{ContactEndings, Ending, contact_endings, has_oblique, oblique_params};
pub use scene::SymbolicScene;
