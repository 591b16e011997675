//! Coulomb's law of friction at a contact, stated once: what friction does during a phase of
//! the impact ([`Mode`]) and whether a tangential impulse lies in the cone `|tau| <= mu lam`.
//! The one-contact path, the several-contact friction solver, the paper's oblique completion
//! and the checks of an answer use these.

use crate::field::Field;
use std::cmp::Ordering;

/// What friction does during a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// No friction at the contact (mu = 0).
    Frictionless,
    /// The contact points slide, the slip u_t positive (`forward`) or negative.
    Slide {
        /// u_t > 0.
        forward: bool,
    },
    /// The slip is zero and stays zero.
    Stick,
}

impl Mode {
    /// `frictionless`, `slide+`, `slide-` or `stick`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Mode;
    /// assert_eq!(Mode::Slide { forward: false }.name(), "slide-");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Mode::Frictionless => "frictionless",
            Mode::Slide { forward: true } => "slide+",
            Mode::Slide { forward: false } => "slide-",
            Mode::Stick => "stick",
        }
    }

    /// `stick` or `slide` (either way), as the paper's oblique impact reports its contact;
    /// `frictionless` without friction.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Mode;
    /// assert_eq!(Mode::Slide { forward: true }.kind(), "slide");
    /// ```
    pub fn kind(self) -> &'static str {
        match self {
            Mode::Frictionless => "frictionless",
            Mode::Slide { .. } => "slide",
            Mode::Stick => "stick",
        }
    }
}

/// Whether `|x| <= bound`: a tangential impulse (or the impulse a stick would need) inside
/// Coulomb's cone of bound `mu lam`; `None` when a sign cannot be decided in the field.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, impact::within_cone};
/// assert_eq!(within_cone(&q(-1, 2), &q(1, 2)), Some(true));
/// assert_eq!(within_cone(&q(3, 4), &q(1, 2)), Some(false));
/// ```
pub fn within_cone<F: Field>(x: &F, bound: &F) -> Option<bool> {
    let magnitude = if x.sign()? == Ordering::Less {
        -x.clone()
    } else {
        x.clone()
    };
    Some((bound.clone() - &magnitude).sign()? != Ordering::Less)
}

/// How far the tangential impulse `tau` lies outside Coulomb's cone `|tau| <= mu lam`: zero
/// inside it (or where a sign cannot be decided), `|tau| - mu lam` outside.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, impact::cone_excess};
/// assert_eq!(cone_excess(&q(1, 2), &q(2, 1), &q(-1, 1)), q(0, 1));
/// assert_eq!(cone_excess(&q(1, 2), &q(2, 1), &q(-3, 2)), q(1, 2));
/// ```
pub fn cone_excess<F: Field>(mu: &F, lam: &F, tau: &F) -> F {
    let bound = mu.clone() * lam;
    if (bound.clone() - tau).sign() == Some(Ordering::Less) {
        tau.clone() - &bound
    } else if (bound.clone() + tau).sign() == Some(Ordering::Less) {
        -(tau.clone() + &bound)
    } else {
        F::zero()
    }
}
