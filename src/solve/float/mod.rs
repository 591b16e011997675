//! Float formulas for the impulse, done properly: the IEEE formats seen through their bits
//! ([`Real`]), numbers with carried binary exponents ([`Ext`]), and the naive, stable ("sq") and
//! compensated ("scomp") formulas ([`FloatFormula`]). Their error is measured exactly by
//! [`crate::stability`].

mod compensated;
mod ext;
mod formulas;
mod real;

pub use ext::Ext;
pub use formulas::FloatFormula;
pub use real::Real;
