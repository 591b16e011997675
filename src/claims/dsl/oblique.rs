//! The symbolic oblique scene of the friction claims (X27-X31): the free rod of
//! [`free_rod`](super::free_rod) struck by a projectile that also moves along the rod (`v0t`),
//! with Coulomb friction `mu_f` (the claims' mu is the reduced mass), optionally a solid disc of radius `r` spinning with `w`, and the
//! rod optionally translating before the impact (`V0`, `Vt0`), solved by the same generic
//! oblique solver as the numbers.

use super::algebra::sym;
use super::scene::free_rod;
use crate::field::RatFn;
use crate::scene::{Disc, Params};
use crate::solve::fast::oblique::solve;

pub(crate) use crate::impact::Mode;
pub(crate) use crate::scene::{ObliqueParams, RodMotion};
pub(crate) use crate::solve::fast::oblique::ObliqueOutcome;
use num_traits::Zero;

/// The three ways a frictional contact can end, each a case of every friction claim: sticking,
/// and sliding with the slip along +y or -y.
pub(crate) const CONTACTS: [Mode; 3] = [
    Mode::Stick,
    Mode::Slide { forward: true },
    Mode::Slide { forward: false },
];

/// "stick", "slide (u_t > 0)" or "slide (u_t < 0)": the case in a certificate's title.
pub(crate) fn case(contact: Mode) -> &'static str {
    match contact {
        Mode::Stick => "stick",
        Mode::Slide { forward: true } => "slide (u_t > 0)",
        Mode::Slide { forward: false } => "slide (u_t < 0)",
        Mode::Frictionless => "frictionless",
    }
}

/// The oblique part in symbols: `v0t`, `mu_f`, a disc (`r`, spin `w`) if `disc`, the rod at rest.
pub(crate) fn oblique(disc: bool) -> ObliqueParams<RatFn> {
    ObliqueParams {
        v0t: sym("v0t"),
        mu: sym("mu_f"),
        disc: disc.then(|| Disc {
            radius: sym("r"),
            spin: sym("w"),
        }),
        rod_before: RodMotion {
            v: RatFn::zero(),
            vt: RatFn::zero(),
            omega: RatFn::zero(),
        },
    }
}

/// The general free rod (symbols m, M, I, a, v0, e) for the oblique claims.
pub(crate) fn oblique_rod() -> Params<RatFn> {
    free_rod(sym("I"), sym("e"))
}

/// Solves the symbolic oblique scene in the given contact case.
pub(crate) fn oblique_solved(
    p: &Params<RatFn>,
    o: &ObliqueParams<RatFn>,
    contact: Mode,
) -> ObliqueOutcome<RatFn> {
    solve(p, o, Some(contact)).expect("the symbolic oblique system is nonsingular")
}
