//! What an oblique, frictional scene adds to the paper's: the projectile's velocity along the
//! rod, Coulomb friction, a disc projectile with its spin, the rod's motion before the impact;
//! and the refusals that belong to them.

use super::params::{Disc, ObliqueParams, RodMotion};
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q};

/// What an oblique, frictional scene adds to the paper's (docs/conventions.md, "Oblique and
/// frictional impacts"): the projectile's velocity along the rod, Coulomb friction at the
/// contact, a disc projectile with its spin, and the rod's motion before the impact.
///
/// A scene has one only when some part of it differs from the paper's scene; a plain scene
/// reports exactly what it always did.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Oblique {
    /// The projectile's velocity along the rod (+y) before the impact.
    pub v0t: Q,
    /// Coulomb friction coefficient at the contact (>= 0).
    pub mu: Q,
    /// The disc projectile, or `None` for a point projectile.
    pub disc: Option<Disc>,
    /// The rod's motion before the impact (zero: at rest).
    pub rod_before: RodMotion<Q>,
}

impl Oblique {
    /// Lifts the oblique part into the field `F`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Oblique;
    /// use rodimpact::field::q;
    /// let o = Oblique { mu: q(1, 2), ..Default::default() };
    /// assert_eq!(o.params::<f64>().mu, 0.5);
    /// ```
    pub fn params<F: Field>(&self) -> ObliqueParams<F> {
        let lift = F::from_rational;
        ObliqueParams {
            v0t: lift(&self.v0t),
            mu: lift(&self.mu),
            disc: self.disc.as_ref().map(|d| Disc {
                radius: lift(&d.radius),
                spin: lift(&d.spin),
            }),
            rod_before: RodMotion {
                v: lift(&self.rod_before.v),
                vt: lift(&self.rod_before.vt),
                omega: lift(&self.rod_before.omega),
            },
        }
    }
}

/// The refusal of `--spin` without `--radius`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::scene::spin_without_disc().to_string(),
///            "spin: a point projectile has no spin: give the disc's --radius too");
/// ```
pub fn spin_without_disc() -> Error {
    Error::new(
        "spin",
        ErrorKind::Conflict("a point projectile has no spin: give the disc's --radius too".into()),
    )
}

/// The refusal of a scene whose projectile does not approach the struck point; `is` says what
/// the approach speed is (`is -1, not > 0`).
///
/// # Examples
/// ```
/// use rodimpact::scene::no_approach;
/// assert!(no_approach("is 0, not > 0").to_string().starts_with("v0: no approach at the contact point"));
/// ```
pub fn no_approach(is: &str) -> Error {
    Error::out_of_range(
        "v0",
        format!(
            "no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), {is}"
        ),
    )
}
