//! The restitution laws, stated once: what ends an impact under Newton's, Poisson's and
//! Stronge's law, as the one-contact path ([`super::one_contact`]), the several-contact models
//! ([`super::multi_contact`]) and the checks of an answer all use them; and the laws that
//! velocity-level engines converge to, which impose them on the final velocities at once.
//!
//! - **newton** (kinematic): the normal relative velocity after is `-e` times before;
//! - **poisson** (kinetic): the normal impulse of restitution is `e` times that of compression;
//! - **energetic** (Stronge): the normal work of restitution is `-e^2` times that of
//!   compression;
//! - **lcp-newton**: Newton's restitution and Coulomb's law on the *final* velocities, in one
//!   phase (the Stewart-Trinkle / Anitescu-Potra velocity-level impact; what projected
//!   Gauss-Seidel converges to);
//! - **lcp-poisson**: its two-phase form: a compression with Coulomb's law, then an expansion
//!   of `e` times the compression impulse (or more), Coulomb's law again;
//! - **split**: friction and no restitution, then restitution without friction (Rapier's
//!   restitution pass, Box2D v3's).

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
    /// Newton's restitution and Coulomb's law on the final velocities, one phase.
    LcpNewton,
    /// A compression with Coulomb's law, then an expansion of e times its impulse.
    LcpPoisson,
    /// Friction without restitution, then restitution without friction.
    Split,
}

impl Law {
    /// The three physical laws, in the order they are reported.
    pub const ALL: [Law; 3] = [Law::Newton, Law::Poisson, Law::Energetic];

    /// The laws engines converge to, in the order they are reported.
    pub const ENGINES: [Law; 3] = [Law::LcpNewton, Law::LcpPoisson, Law::Split];

    /// `newton`, `poisson`, `energetic`, `lcp-newton`, `lcp-poisson` or `split`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Law;
    /// assert_eq!(Law::Energetic.name(), "energetic");
    /// assert_eq!(Law::LcpNewton.name(), "lcp-newton");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Law::Newton => "newton",
            Law::Poisson => "poisson",
            Law::Energetic => "energetic",
            Law::LcpNewton => "lcp-newton",
            Law::LcpPoisson => "lcp-poisson",
            Law::Split => "split",
        }
    }

    /// The law named `text` (its [`Law::name`], or `stronge` for the energetic law); `None`
    /// for any other text.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Law;
    /// assert_eq!(Law::parse("stronge"), Some(Law::Energetic));
    /// assert_eq!(Law::parse(" split "), Some(Law::Split));
    /// assert_eq!(Law::parse("euler"), None);
    /// ```
    pub fn parse(text: &str) -> Option<Law> {
        match text.trim() {
            "stronge" => Some(Law::Energetic),
            name => Law::ALL
                .into_iter()
                .chain(Law::ENGINES)
                .find(|law| law.name() == name),
        }
    }

    /// Whether the law follows the impact along Routh's path in the normal impulse (the three
    /// physical laws), rather than imposing itself on the final velocities (the engines').
    pub fn follows_the_path(self) -> bool {
        Law::ALL.contains(&self)
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

    /// What the law leaves over at the end of an impact (zero when it holds): newton, lcp-newton
    /// and split `u_n' - (-e u_n)`, poisson `lam - (lam_c + e lam_c)` (lcp-poisson: that, or
    /// `u_n'` where the expansion had to exceed it), energetic `W_r - (-e^2 W_c)`.
    pub(crate) fn residual<F: Field>(self, e: &F, end: &Ends<F>) -> F {
        match self {
            Law::Newton | Law::LcpNewton | Law::Split => {
                end.u_n_after.clone() - &Law::newton_leaving(e, &end.u_n_before)
            }
            Law::Poisson => end.lam.clone() - &end.lam_c - &Law::poisson_restitution(e, &end.lam_c),
            // The expansion is e times the compression's impulse, or more where the contact
            // would sink: then it ends touching.
            Law::LcpPoisson => {
                let short = end.lam.clone() - &end.lam_c - &Law::poisson_restitution(e, &end.lam_c);
                if short.is_zero() {
                    short
                } else {
                    end.u_n_after.clone()
                }
            }
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
