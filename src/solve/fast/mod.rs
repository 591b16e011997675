//! The fast routes of the paper's family: each answers a [`crate::scene::Scene`] (or its
//! numbers) by its own formulas, faster than the general solver, and each must equal it. The
//! call of the core each route equals, which `tests/lib/fast_routes.rs` checks on random
//! scenes (free, pivoted, oblique, frictional, disc, moving rod; in Q and Q(sqrt d)):
//!
//! | route | what it computes | equals |
//! |---|---|---|
//! | [`linear`] | the impulse equations as a linear system, over any field | `impact::solve_contact(&scene.system(), Law::Newton)` |
//! | [`closed_form`] | the paper's closed forms, over any field | the same |
//! | [`fraction_free`] | integer identities on the scene's numerators and denominators | the same, in Q |
//! | [`fixed_width`] | the fraction-free formulas on machine words | the same, in Q |
//! | [`float`] | the float formulas (naive, sq, scomp) | the same within their error bounds |
//! | [`oblique`] | the decoupled normal and tangential problems of an oblique or frictional scene | `impact::solve_contact(&scene.system(), Law::Newton)`, phases included |
//!
//! With the paper's contact (the normal along the projectile's motion, the rod across it) W
//! is diagonal, so Newton's, Poisson's and Stronge's laws give one answer: the routes state
//! Newton's.

pub mod closed_form;
pub mod fixed_width;
pub mod float;
pub mod fraction_free;
pub mod linear;
pub mod oblique;
