//! The quantities a claimed answer can be about (`v`, `V`, `omega`, `a_star`, ...), their
//! names, dimensions and values after the impact.

use super::units::Dimension;
use crate::error::{Error, ErrorKind};
use crate::field::Field;
use crate::scene::Params;
use crate::solve::Outcome;
use crate::solve::fast::oblique::ObliqueOutcome;

/// A quantity a claim is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// The projectile's velocity after the impact.
    V,
    /// The velocity of the rod's centre after the impact.
    RodV,
    /// The velocity of the centre of mass of rod + projectile after the impact.
    VCm,
    /// The rod's angular velocity after the impact (compared by magnitude).
    Omega,
    /// The impact distance that maximises omega.
    AStar,
    /// The largest omega over the impact points.
    OmegaMax,
    /// Kinetic energy before the impact.
    EnergyBefore,
    /// Kinetic energy after the impact.
    EnergyAfter,
    /// Kinetic energy lost.
    EnergyLost,
    /// The impulse the pivot gives the rod.
    PivotImpulse,
    /// The impulse the projectile gives the rod.
    Impulse,
    /// The projectile's velocity along the rod after the impact (oblique scenes).
    Vt,
    /// The velocity of the rod's centre along the rod after the impact (oblique scenes).
    RodVt,
    /// The disc projectile's spin after the impact (oblique scenes with a disc).
    Spin,
    /// The tangential impulse the projectile gives the rod (oblique scenes).
    TangentialImpulse,
}

const NAMES: [(&str, Quantity); 15] = [
    ("v", Quantity::V),
    ("V", Quantity::RodV),
    ("V_cm", Quantity::VCm),
    ("omega", Quantity::Omega),
    ("a_star", Quantity::AStar),
    ("omega_max", Quantity::OmegaMax),
    ("energy_before", Quantity::EnergyBefore),
    ("energy_after", Quantity::EnergyAfter),
    ("energy_lost", Quantity::EnergyLost),
    ("pivot_impulse", Quantity::PivotImpulse),
    ("impulse", Quantity::Impulse),
    ("vt", Quantity::Vt),
    ("Vt", Quantity::RodVt),
    ("spin", Quantity::Spin),
    ("tangential_impulse", Quantity::TangentialImpulse),
];

impl Quantity {
    /// Parses a claim name (`v`, `V`, `V_cm`, `omega`, ...).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Quantity;
    /// assert_eq!(Quantity::parse("V_cm"), Some(Quantity::VCm));
    /// assert_eq!(Quantity::parse("w"), None);
    /// ```
    pub fn parse(name: &str) -> Option<Quantity> {
        NAMES.iter().find(|(n, _)| *n == name).map(|(_, q)| *q)
    }

    /// The claim name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Quantity;
    /// assert_eq!(Quantity::EnergyLost.name(), "energy_lost");
    /// ```
    pub fn name(self) -> &'static str {
        NAMES
            .iter()
            .find(|(_, q)| *q == self)
            .map_or("?", |(n, _)| n)
    }

    /// The accepted names, for error messages.
    ///
    /// # Examples
    /// ```
    /// assert!(rodimpact::textbook::Quantity::all_names().starts_with("v, V, V_cm"));
    /// ```
    pub fn all_names() -> String {
        NAMES.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
    }

    /// What it measures.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Quantity, units::Dimension};
    /// assert_eq!(Quantity::OmegaMax.dimension(), Dimension::AngularSpeed);
    /// ```
    pub fn dimension(self) -> Dimension {
        match self {
            Quantity::V | Quantity::RodV | Quantity::VCm | Quantity::Vt | Quantity::RodVt => {
                Dimension::Speed
            }
            Quantity::Omega | Quantity::OmegaMax | Quantity::Spin => Dimension::AngularSpeed,
            Quantity::AStar => Dimension::Length,
            Quantity::EnergyBefore | Quantity::EnergyAfter | Quantity::EnergyLost => {
                Dimension::Energy
            }
            Quantity::PivotImpulse | Quantity::Impulse | Quantity::TangentialImpulse => {
                Dimension::Impulse
            }
        }
    }

    /// The value after the impact over any field; `Ok(None)` for `a_star` and `omega_max`
    /// (not motion quantities).
    ///
    /// # Errors
    /// `pivot_impulse` asked of a free rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Quantity;
    /// use rodimpact::{scene::Scene, solve::fast::linear::solve, field::{q, Q}};
    /// let p = Scene::builder(q(1, 1), q(1, 1)).build().unwrap().params::<Q>();
    /// let out = solve(&p).unwrap();
    /// assert_eq!(Quantity::VCm.motion_value(&p, &out).unwrap(), Some(q(1, 2)));
    /// assert!(Quantity::PivotImpulse.motion_value(&p, &out).is_err());
    /// ```
    pub fn motion_value<F: Field>(
        self,
        p: &Params<F>,
        out: &Outcome<F>,
    ) -> Result<Option<F>, Error> {
        let after = &out.after;
        Ok(Some(match self {
            Quantity::V => after.v.clone(),
            Quantity::RodV => after.rod_v.clone(),
            Quantity::VCm => {
                let momentum = p.m.clone() * &after.v + &(p.rod_mass.clone() * &after.rod_v);
                momentum / (p.m.clone() + &p.rod_mass)
            }
            Quantity::Omega => after.omega.clone(),
            Quantity::EnergyBefore => out.energy.before.clone(),
            Quantity::EnergyAfter => out.energy.after.clone(),
            Quantity::EnergyLost => out.energy.lost(),
            Quantity::Impulse => out.impulse(p),
            Quantity::PivotImpulse => match &out.pivot_impulse {
                Some(j) => j.clone(),
                None => {
                    return Err(Error::new(
                        "claim pivot_impulse",
                        ErrorKind::Invalid("the rod is free (no pivot)".into()),
                    ));
                }
            },
            Quantity::AStar | Quantity::OmegaMax => return Ok(None),
            Quantity::Vt | Quantity::RodVt | Quantity::Spin | Quantity::TangentialImpulse => {
                return Err(Error::new(
                    format!("claim {}", self.name()),
                    ErrorKind::Invalid(
                        "only an oblique scene has it: give --v0t, --mu, --radius or the rod's motion before the impact".into(),
                    ),
                ));
            }
        }))
    }

    /// The value after an oblique impact; `Ok(None)` for `a_star` and `omega_max`.
    ///
    /// # Errors
    /// `pivot_impulse` of a free rod, `spin` of a point projectile.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Quantity;
    /// use rodimpact::{scene::Scene, solve::fast::oblique::solve, field::{q, Q}};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).v0t(q(1, 1)).mu(q(1, 2)).build().unwrap();
    /// let p = s.params::<Q>();
    /// let out = solve(&p, &s.oblique().unwrap().params(), None).unwrap();
    /// assert_eq!(Quantity::Vt.oblique_value(&p, &out).unwrap(), Some(q(4, 5)));
    /// assert!(Quantity::Spin.oblique_value(&p, &out).is_err());
    /// ```
    pub fn oblique_value<F: Field>(
        self,
        p: &Params<F>,
        out: &ObliqueOutcome<F>,
    ) -> Result<Option<F>, Error> {
        let after = &out.after;
        let missing = |why: &str| {
            Error::new(
                format!("claim {}", self.name()),
                ErrorKind::Invalid(why.into()),
            )
        };
        Ok(Some(match self {
            Quantity::V => after.v.clone(),
            Quantity::RodV => after.rod.v.clone(),
            Quantity::VCm => {
                let momentum = p.m.clone() * &after.v + &(p.rod_mass.clone() * &after.rod.v);
                momentum / (p.m.clone() + &p.rod_mass)
            }
            Quantity::Omega => after.rod.omega.clone(),
            Quantity::Vt => after.vt.clone(),
            Quantity::RodVt => after.rod.vt.clone(),
            Quantity::Spin => after
                .spin
                .clone()
                .ok_or_else(|| missing("the projectile is a point (no --radius)"))?,
            Quantity::EnergyBefore => out.energy.before.clone(),
            Quantity::EnergyAfter => out.energy.after.clone(),
            Quantity::EnergyLost => out.energy.lost(),
            Quantity::Impulse => out.impulse.clone(),
            Quantity::TangentialImpulse => out.tangential_impulse.clone(),
            Quantity::PivotImpulse => match &out.pivot_impulse {
                Some((across, _)) => across.clone(),
                None => return Err(missing("the rod is free (no pivot)")),
            },
            Quantity::AStar | Quantity::OmegaMax => return Ok(None),
        }))
    }
}
