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
//! use rodimpact::{scene::Scene, solve::solve, optimum::optimum, field::{q, Q}};
//! // The paper's example: M = m, uniform rod of half-length 1, hit at the end.
//! let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 1)).build()?;
//! let out = solve(&scene.params::<Q>()).expect("nonsingular");
//! assert_eq!(out.after.omega, q(6, 5));
//! assert!(out.residuals.all_zero()); // momentum, angular momentum and energy: exactly 0
//! let best = optimum(&scene);
//! assert_eq!(best.squared, q(2, 3)); // a* = sqrt(2/3) l, inside the rod
//! assert!(best.within_rod);
//! # Ok::<(), rodimpact::Error>(())
//! ```

pub mod batch;
pub mod claims;
pub mod contact;
pub mod echo;
pub mod error;
pub mod fast;
pub mod field;
pub mod float;
pub mod io;
pub mod mechanics;
pub mod number;
pub mod optimum;
pub mod report;
pub mod samples;
pub mod scene;
pub mod solve;
pub mod stability;
pub mod suite;
pub mod textbook;
pub mod units;

pub use error::{Error, ErrorKind};

/// The README's Rust examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
