#![warn(missing_docs)]
#![forbid(unsafe_code)]
//! # rodimpact
//!
//! An exact-arithmetic verifier for rigid-body impact: a projectile of mass m and speed v0
//! strikes a rod (mass M, length 2l, moment of inertia I) lying at rest on a frictionless table,
//! perpendicularly, at distance a from its centre, as in N. A. Lemos, "Failure of intuition in
//! elementary rigid body dynamics". The rod may be free or on a fixed pivot; the impact may be
//! elastic, totally inelastic (sticking) or obey any coefficient of restitution.
//!
//! The solver is written once, generically over a [`field::Field`], and run on exact rationals
//! ([`field::Q`]), floats, the quadratic field Q(sqrt d) ([`field::QSqrt`]) and rational functions
//! in named symbols ([`field::RatFn`]).
//!
//! ```
//! use rodimpact::prelude::*;
//! // The paper's example: M = m, uniform rod of half-length 1, hit at the end.
//! let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 1)).build()?;
//! let answer = Answer::of(&scene); // the front door: any scene, answered completely
//! assert_eq!(answer.impact.outcome.after.omega, q(6, 5));
//! assert!(answer.laws_hold()); // momentum, angular momentum and energy: exactly
//! let best = answer.optimum.expect("the rod is at rest before the impact");
//! assert_eq!(best.squared, q(2, 3)); // a* = sqrt(2/3) l, inside the rod
//! assert!(best.within_rod);
//! # Ok::<(), rodimpact::Error>(())
//! ```

//! ## Layers
//!
//! Each module uses only the layers above it in this table (documentation links aside); no
//! two modules import each other.
//!
//! | layer | modules | what it holds |
//! |---|---|---|
//! | 0 numbers | [`field`] (its [`field::decimal`] exact printing, [`field::int`] word-sized integers, [`field::linear`] elimination), [`echo`], [`error`], [`interrupt`] | the [`field::Field`] trait and its number types; how numbers print; the error type; the host's interrupt hook |
//! | 1 input | [`number`], [`units`] | exact parsing of `0.25`, `3/7`, `1.5e-3`; SI units |
//! | 2 model | [`mechanics`], [`model`] | momentum, angular momentum and energy of rigid bodies; bodies, shapes, contacts and pins as data ([`model::System`]) |
//! | 3 core | [`impact`] | the general solver: contacts as Jacobian rows, `W = J M^-1 J^T`; one contact under the three laws with Coulomb friction; several contacts under each model |
//! | 4 paper | [`scene`] | the paper's scene, a view of the model ([`scene::Scene::system`]): its inputs, motion (v, V, omega) and balances |
//! | 5 solve | [`solve`] | the whole answer to any scene of the paper ([`solve::Answer`]) by its fast routes, each equal to the core; a* and omega_max ([`solve::optimum`]) |
//! | 6 decide | [`claims`], [`textbook`], [`stability`], [`compliant`], [`batch`], [`suite`], [`samples`], [`tables`], [`sampling`] | the paper's claims and their certificates; published answers checked; float error; the stiff-contact cross-check; many scenes; the designed suites of scenes (engines); the exact tables T1-T6 as data; the exact values the figures draw |
//! | 7 output | [`report`], [`io`] | every rendering (text, JSON, Markdown, LaTeX, CSV, SVG); atomic files and directories written all or nothing |
//! | 8 application | [`app`] | one place per use (an impact file answered, the pages' requests, a batch's options): input in, solvers called, complete results rendered |
//!
//! The command-line tool (the package `crates/rodimpact-cli`: `main.rs` and `commands/`, one
//! file per subcommand, and the build of the pages' WebAssembly module) sits on top
//! and only parses flags, calls one library function ([`app`] where a use needs several) and
//! prints what [`report`] renders.
//!
//! [`prelude`] gathers the names most programs need:
//!
//! ```
//! use rodimpact::prelude::*;
//! let scene = Scene::builder(q(1, 1), q(3, 1)).a(q(1, 2)).build()?;
//! let solved = solve::with::<Q>(&scene, Route::FractionFree).expect("every scene in Q");
//! // omega = 2 m a v0 / (I (1 + m/M) + m a^2) = 1/(1 + 1/3 + 1/4) = 12/19 (I = M l^2/3 = 1).
//! assert_eq!(solved.after.omega, q(12, 19));
//! # Ok::<(), rodimpact::Error>(())
//! ```

// Layer 0: numbers.
pub mod echo;
pub mod error;
pub mod field;
pub mod interrupt;
// Layer 1: input.
pub mod number;
pub mod units;
// Layer 2: model.
pub mod mechanics;
pub mod model;
// Layer 3: the core.
pub mod impact;
// Layer 4: the paper's scene.
pub mod scene;
// Layer 5: the paper's routes.
pub mod solve;
// Layer 6: decide.
pub mod batch;
pub mod claims;
pub mod compliant;
pub mod samples;
pub mod sampling;
pub mod stability;
pub mod suite;
pub mod tables;
pub mod textbook;
// Layer 7: output.
pub mod io;
pub mod report;
// Layer 8: application.
pub mod app;

/// The names most programs need, in one `use rodimpact::prelude::*;`.
///
/// # Examples
/// ```
/// use rodimpact::prelude::*;
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 1)).build()?;
/// let out = solve::fast::linear::solve(&scene.params::<Q>()).expect("nonsingular");
/// assert_eq!(out.after, Motion { v: q(3, 5), rod_v: q(2, 5), omega: q(6, 5) });
/// assert_eq!(optimum(&scene).map(|o| o.squared), Some(q(2, 3)));
/// assert_eq!(Answer::of(&scene).impulse, q(2, 5)); // J = 2/(1/m + 1/M + a^2/I) = 2/5
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub mod prelude {
    pub use crate::error::{Error, ErrorKind};
    pub use crate::field::{Field, Q, QSqrt, RatFn, Sym, q};
    pub use crate::scene::Motion;
    pub use crate::scene::{Params, RodInertia, Scene, SceneInput, Support};
    pub use crate::solve::optimum::{Optimum, optimum};
    pub use crate::solve::{self, Answer, Impact, Outcome, Route, Solved};
}

pub use error::{Error, ErrorKind};

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
