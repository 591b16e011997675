//! Float formulas for the impulse, done properly: the IEEE formats seen through their bits
//! ([`Real`]), numbers with carried binary exponents ([`Ext`]), and the naive, stable ("sq") and
//! compensated ("scomp") formulas ([`FloatFormula`]). Their error is measured exactly by
//! [`crate::stability`].
//!
//! A fast case of the core in floats: each formula must lie within its error bound of
//! `impact::solve_contact(&scene.system(), Law::Newton)` (the exact answer), which
//! `crate::stability` measures and `tests/lib/fast_routes.rs` checks on random scenes.

mod compensated;
mod ext;
mod formulas;
mod real;

pub use ext::Ext;
pub use formulas::FloatFormula;
pub use real::Real;
