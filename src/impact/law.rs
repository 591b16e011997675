//! The restitution laws, stated once: what ends an impact under Newton's, Poisson's and
//! Stronge's law, as the one-contact path ([`super::one_contact`]), the several-contact models
//! ([`super::multi_contact`]) and the checks of an answer all use them.
//!
//! - **newton** (kinematic): the normal relative velocity after is `-e` times before;
//! - **poisson** (kinetic): the normal impulse of restitution is `e` times that of compression;
//! - **energetic** (Stronge): the normal work of restitution is `-e^2` times that of
//!   compression.

use crate::field::Field;
use std::fmt;

/// The law that ends the impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Law {
    /// Newton's kinematic law: the normal relative velocity after is -e times before.
    Newton,
    /// Poisson's kinetic law: the normal impulse of restitution is e times that of compression.
    Poisson,
    /// Stronge's energetic law: the normal work of restitution is -e^2 times that of
    /// compression.
    Energetic,
}

impl Law {
    /// All three, in the order they are reported.
    pub const ALL: [Law; 3] = [Law::Newton, Law::Poisson, Law::Energetic];

    /// `newton`, `poisson` or `energetic`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Law;
    /// assert_eq!(Law::Energetic.name(), "energetic");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Law::Newton => "newton",
            Law::Poisson => "poisson",
            Law::Energetic => "energetic",
        }
    }

    /// Newton's law: the normal relative velocity at which a contact that approached at
    /// `u_n` (< 0) leaves, `-e u_n` (for a touching or separating contact, `u_n` is taken as
    /// its approach, 0).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, impact::Law};
    /// assert_eq!(Law::newton_leaving(&q(1, 2), &q(-2, 1)), q(1, 1));
    /// ```
    pub fn newton_leaving<F: Field>(e: &F, u_n: &F) -> F {
        -(e.clone() * u_n)
    }

    /// Poisson's law: the normal impulse of restitution after a compression impulse `lam_c`,
    /// `e lam_c` (the impact ends at `lam_c + e lam_c`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, impact::Law};
    /// assert_eq!(Law::poisson_restitution(&q(1, 2), &q(3, 1)), q(3, 2));
    /// ```
    pub fn poisson_restitution<F: Field>(e: &F, lam_c: &F) -> F {
        e.clone() * lam_c
    }

    /// Stronge's law: the normal work of restitution after a compression whose normal work is
    /// `compression` (<= 0), `-e^2 compression`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, impact::Law};
    /// assert_eq!(Law::energetic_restitution(&q(1, 2), &q(-4, 1)), q(1, 1));
    /// ```
    pub fn energetic_restitution<F: Field>(e: &F, compression: &F) -> F {
        -(e.clone() * e * compression)
    }

    /// What the law leaves over at the end of an impact (zero when it holds): newton
    /// `u_n' - (-e u_n)`, poisson `lam - (lam_c + e lam_c)`, energetic `W_r - (-e^2 W_c)`.
    pub(crate) fn residual<F: Field>(self, e: &F, end: &Ends<F>) -> F {
        match self {
            Law::Newton => end.u_n_after.clone() - &Law::newton_leaving(e, &end.u_n_before),
            Law::Poisson => end.lam.clone() - &end.lam_c - &Law::poisson_restitution(e, &end.lam_c),
            Law::Energetic => {
                end.work_restitution.clone() - &Law::energetic_restitution(e, &end.work_compression)
            }
        }
    }
}

/// What the laws compare at the end of one contact's impact.
pub(crate) struct Ends<F> {
    /// u_n before and after.
    pub(crate) u_n_before: F,
    pub(crate) u_n_after: F,
    /// The normal impulse at the end of compression and at the end.
    pub(crate) lam_c: F,
    pub(crate) lam: F,
    /// The normal work in compression and in restitution.
    pub(crate) work_compression: F,
    pub(crate) work_restitution: F,
}

impl fmt::Display for Law {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
