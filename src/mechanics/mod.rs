//! The laws of mechanics over any field: momentum, angular momentum and kinetic energy of
//! rigid bodies, stated once ([`planar`]: bodies in the plane). The general solver's checks,
//! the paper's scene ([`crate::scene::Motion`] and its balances) and the proofs of the claims
//! all evaluate these same functions.

pub mod planar;
