//! Checking published answers: `rodimpact check`.
//!
//! A claim (`omega=1.89 rad/s`, `omega=36/19`, `omega=12*m*v0/((M+4*m)*L)`) is compared with
//! the exact answer of its scene. Printed numbers are judged by their own significant figures
//! ([`sigfig`]), with units converted exactly ([`units`]); formulas ([`expr`]) are decided as
//! identities over the scene's domain ([`symbolic`]), with a counterexample scene when false.
//! [`verdict`] holds the decisions and [`problems`] reads problem collections (TOML).
//!
//! # Examples
//! ```
//! use rodimpact::textbook::{check_scene, Claim};
//! use rodimpact::scene::SceneInput;
//! let scene = SceneInput {
//!     m: Some("0.100 kg".into()), rod_mass: Some("1.50 kg".into()), length: Some("2.00 m".into()),
//!     from_end: Some("0".into()), v0: Some("12.0 m/s".into()), e: Some("0".into()),
//!     ..Default::default()
//! };
//! let claims = [Claim::parse("omega=1.89").unwrap(), Claim::parse("omega=0.947").unwrap()];
//! let report = check_scene(&scene, &claims, None).unwrap();
//! assert!(report.decisions[0].agrees() && !report.decisions[1].agrees());
//! assert_eq!(report.decisions[1].exact, "36/19");
//! ```

pub mod expr;
pub mod problems;
pub mod sigfig;
pub mod symbolic;
pub mod units;
pub mod verdict;

use crate::error::{Error, ErrorKind};
use crate::field::{Field, QSqrt};
use crate::optimum::optimum;
use crate::scene::{Params, SceneInput};
use crate::solve::Outcome;
use crate::solve::linear::solve;
use expr::{Budget, Radical};
use units::{Dimension, Measured};
pub use verdict::{Decision, Report, Verdict};

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
}

const NAMES: [(&str, Quantity); 11] = [
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
            Quantity::V | Quantity::RodV | Quantity::VCm => Dimension::Speed,
            Quantity::Omega | Quantity::OmegaMax => Dimension::AngularSpeed,
            Quantity::AStar => Dimension::Length,
            Quantity::EnergyBefore | Quantity::EnergyAfter | Quantity::EnergyLost => {
                Dimension::Energy
            }
            Quantity::PivotImpulse | Quantity::Impulse => Dimension::Impulse,
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
    /// use rodimpact::{scene::Scene, solve::linear::solve, field::{q, Q}};
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
            Quantity::EnergyLost => out.energy.lost.clone(),
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
        }))
    }
}

/// What a claim says: a printed number (with its unit) or a formula.
#[derive(Debug, Clone, PartialEq)]
pub enum ClaimValue {
    /// A number as printed, judged by its significant figures.
    Printed(Measured),
    /// An exact formula, possibly in the scene's symbols.
    Formula(Radical),
}

/// One claimed answer.
///
/// # Examples
/// ```
/// use rodimpact::textbook::{Claim, ClaimValue, Quantity};
/// let c = Claim::parse("omega = 1.89 rad/s").unwrap();
/// assert_eq!(c.quantity, Quantity::Omega);
/// assert!(matches!(c.value, ClaimValue::Printed(_)));
/// assert!(Claim::parse("omega=2*m").unwrap().is_symbolic());
/// assert!(Claim::parse("omegaa=2").is_err());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    /// What is claimed.
    pub quantity: Quantity,
    /// The value as written.
    pub text: String,
    /// The parsed value.
    pub value: ClaimValue,
}

impl Claim {
    /// Parses `NAME=VALUE`.
    ///
    /// # Errors
    /// `claim: ...` for a missing `=` or an unknown name, or the value's own error.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Claim;
    /// assert_eq!(Claim::parse("v=2.3 m/s").unwrap().text, "2.3 m/s");
    /// assert_eq!(Claim::parse("v").unwrap_err().to_string(), "claim: expected NAME=VALUE, got 'v'");
    /// ```
    pub fn parse(spec: &str) -> Result<Claim, Error> {
        Claim::parse_within(spec, &mut Budget::new(expr::MAX_WORK))
    }

    /// [`Claim::parse`], charging a formula's work to a run's `budget`.
    ///
    /// # Errors
    /// Those of [`Claim::parse`], and an exhausted budget.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Claim, expr::Budget};
    /// let mut budget = Budget::run();
    /// assert!(Claim::parse_within("v=m/(m+M)", &mut budget).unwrap().is_symbolic());
    /// assert!(budget.spent() > 0);
    /// ```
    pub fn parse_within(spec: &str, budget: &mut Budget) -> Result<Claim, Error> {
        let Some((name, value)) = spec.split_once('=') else {
            return Err(Error::new(
                "claim",
                ErrorKind::Invalid(format!(
                    "expected NAME=VALUE, got '{}'",
                    crate::echo::echo(spec)
                )),
            ));
        };
        Claim::new_within(name.trim(), value, budget)
    }

    /// A claim from its name and value text.
    ///
    /// # Errors
    /// An unknown name (listing the accepted ones) or a value that is neither a printed number
    /// nor a formula.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Claim;
    /// assert!(Claim::new("V", "1.3 m/s").is_ok());
    /// assert_eq!(Claim::new("V", "1.3 J").unwrap_err().to_string(),
    ///     "claim V: unit 'J' is an energy, expected a speed");
    /// ```
    pub fn new(name: &str, text: &str) -> Result<Claim, Error> {
        Claim::new_within(name, text, &mut Budget::new(expr::MAX_WORK))
    }

    /// [`Claim::new`], charging a formula's work to a run's `budget`.
    ///
    /// # Errors
    /// Those of [`Claim::new`], and an exhausted budget.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{Claim, expr::Budget};
    /// assert!(Claim::new_within("V", "2*m", &mut Budget::run()).is_ok());
    /// ```
    pub fn new_within(name: &str, text: &str, budget: &mut Budget) -> Result<Claim, Error> {
        let quantity = Quantity::parse(name).ok_or_else(|| {
            Error::new(
                "claim",
                ErrorKind::Invalid(format!(
                    "unknown name '{}' (accepted: {})",
                    crate::echo::echo(name),
                    Quantity::all_names()
                )),
            )
        })?;
        let field = format!("claim {name}");
        let value = read_value(&field, text, quantity.dimension(), budget)?;
        Ok(Claim {
            quantity,
            text: text.trim().to_string(),
            value,
        })
    }

    /// Whether the value mentions a symbol.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::Claim;
    /// assert!(!Claim::parse("a_star=sqrt(2/3)").unwrap().is_symbolic());
    /// assert!(Claim::parse("V=2*m*v0/(M+4*m)").unwrap().is_symbolic());
    /// ```
    pub fn is_symbolic(&self) -> bool {
        matches!(&self.value, ClaimValue::Formula(r) if r.constant().is_none())
    }
}

/// A printed number with an optional unit, or else a formula (charged to `budget`); when
/// neither reads, the error of the form the text looks like.
pub(crate) fn read_value(
    field: &str,
    text: &str,
    dimension: Dimension,
    budget: &mut Budget,
) -> Result<ClaimValue, Error> {
    match Measured::parse(field, text, dimension) {
        Ok(m) => Ok(ClaimValue::Printed(m)),
        Err(numeric) => match expr::parse_within(field, text, budget) {
            Ok(r) => Ok(ClaimValue::Formula(r)),
            Err(formula) => {
                let looks_formula = text.trim_start().starts_with(|c: char| c.is_alphabetic())
                    || text.contains(['*', '(', '^']);
                Err(if looks_formula { formula } else { numeric })
            }
        },
    }
}

/// An exact numeric answer: rational, or in Q(sqrt d) (`a_star`, `omega_max`).
#[derive(Debug, Clone, PartialEq)]
pub enum Exact {
    /// A rational.
    Rational(crate::field::Q),
    /// x + y sqrt(d).
    Surd(QSqrt),
}

impl Exact {
    /// `c * sqrt(r)` (`r >= 0`), rational when the root is.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::radical(q(2, 1), q(9, 4)), Exact::Rational(q(3, 1)));
    /// assert!(matches!(Exact::radical(q(1, 1), q(2, 1)), Exact::Surd(_)));
    /// ```
    pub fn radical(c: crate::field::Q, r: crate::field::Q) -> Exact {
        use crate::field::TrySqrt;
        match r.try_sqrt() {
            Some(root) => Exact::Rational(c * root),
            None => Exact::Surd(QSqrt::new(crate::field::Q::default(), c, r)),
        }
    }

    /// Correctly rounded to `digits` significant digits.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::Rational(q(36, 19)).decimal(6), "1.89474");
    /// ```
    pub fn decimal(&self, digits: usize) -> String {
        match self {
            Exact::Rational(x) => crate::field::decimal::decimal(x, digits),
            Exact::Surd(s) => s.decimal(digits),
        }
    }

    /// For a text report: the exact form, or a decimal when the fraction is very long
    /// ([`crate::field::decimal::compact`]).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, textbook::Exact};
    /// assert_eq!(Exact::Rational(q(36, 19)).compact(), "36/19");
    /// ```
    pub fn compact(&self) -> String {
        match self {
            Exact::Rational(x) => crate::field::decimal::compact(x),
            Exact::Surd(s) => {
                let text = s.to_string();
                if text.chars().count() <= crate::field::decimal::COMPACT_CHARS {
                    text
                } else {
                    format!("≈ {}", s.decimal(6))
                }
            }
        }
    }
}

impl std::fmt::Display for Exact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Exact::Rational(x) => write!(f, "{x}"),
            Exact::Surd(s) => write!(f, "{s}"),
        }
    }
}

/// Checks claims about one scene given as typed (numbers may carry units; any formula in a
/// scene flag or a claim makes the whole check symbolic). `sig` overrides the claims'
/// significant figures.
///
/// # Errors
/// Bad scene or claim input, naming the field.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{check_scene, Claim}};
/// let s = SceneInput { m: Some("1".into()), rod_mass: Some("1".into()), ..Default::default() };
/// let r = check_scene(&s, &[Claim::parse("omega=6/5").unwrap()], None).unwrap();
/// assert!(r.all_agree() && r.symbolic.is_none());
/// ```
pub fn check_scene(
    input: &SceneInput,
    claims: &[Claim],
    sig: Option<u32>,
) -> Result<Report, Error> {
    check_scene_within(input, claims, sig, &mut Budget::run())
}

/// [`check_scene`], charging the work of the scene's and the claims' formulas to a run's
/// `budget` (shared by every scene of a problem file).
///
/// # Errors
/// Those of [`check_scene`], and an exhausted budget.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{check_scene_within, expr::Budget, Claim}};
/// let s = SceneInput { rod_mass: Some("4*m".into()), a: Some("l".into()), ..Default::default() };
/// let mut budget = Budget::run();
/// let r = check_scene_within(&s, &[Claim::parse("v=0").unwrap()], None, &mut budget).unwrap();
/// assert!(r.all_agree()); // M = 4m hit at the end, elastic: the projectile stops
/// ```
pub fn check_scene_within(
    input: &SceneInput,
    claims: &[Claim],
    sig: Option<u32>,
    budget: &mut Budget,
) -> Result<Report, Error> {
    if let Some(n) = sig {
        sigfig::check_sig(n)?;
    }
    let given = symbolic::GivenScene::read(input, budget)?;
    if given.has_formula() || claims.iter().any(Claim::is_symbolic) {
        return symbolic::check(&given, claims, sig, budget);
    }
    let scene = input.build().map_err(|e| numeric_scene_needed(e, claims))?;
    let params = scene.params::<crate::field::Q>();
    let out = solve(&params).ok_or_else(|| {
        Error::new(
            "scene",
            ErrorKind::Invalid("singular impulse equations".into()),
        )
    })?;
    let mut decisions = Vec::with_capacity(claims.len());
    for claim in claims {
        let exact = match claim.quantity.motion_value(&params, &out)? {
            Some(x) => Exact::Rational(x),
            None => {
                let opt = optimum(&scene);
                if claim.quantity == Quantity::AStar {
                    Exact::Surd(QSqrt::sqrt_of(&opt.squared))
                } else {
                    Exact::Surd(opt.omega_max.clone())
                }
            }
        };
        decisions.push(verdict::decide(claim, &exact, sig));
    }
    Ok(Report {
        symbolic: None,
        decisions,
    })
}

/// A missing mass in a scene of numbers only: numeric claims need a numeric scene.
fn numeric_scene_needed(e: Error, claims: &[Claim]) -> Error {
    if e.kind != ErrorKind::Missing {
        return e;
    }
    let example = claims
        .first()
        .map(|c| format!(" ({}={})", c.quantity.name(), c.text))
        .unwrap_or_default();
    Error::new(
        e.field,
        ErrorKind::Invalid(format!(
            "not given; a numeric claim{example} needs a numeric scene: give m and M as numbers (--m, --M), or claim a formula in the scene's symbols"
        )),
    )
}
