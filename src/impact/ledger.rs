//! What an impact conserves and what it changes, in one vocabulary for every route: the
//! kinetic energy before and after ([`EnergyLedger`]) and the balance laws checked
//! ([`Balances`]: each law's residual, exactly zero when it holds). The paper's routes, the
//! oblique completion and the general solver all report through these two types.

use crate::field::Field;
use std::cmp::Ordering;

/// Kinetic energy before and after an impact, and its change.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, impact::EnergyLedger};
/// let e = EnergyLedger::new(q(1, 2), q(1, 8));
/// assert_eq!((e.change.clone(), e.lost()), (q(-3, 8), q(3, 8)));
/// assert!(!e.gain());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyLedger<F> {
    /// Before the impact.
    pub before: F,
    /// After the impact.
    pub after: F,
    /// `after - before`: positive when the impact creates energy.
    pub change: F,
}

impl<F: Field> EnergyLedger<F> {
    /// The ledger of `before` and `after`.
    pub fn new(before: F, after: F) -> EnergyLedger<F> {
        EnergyLedger {
            change: after.clone() - &before,
            before,
            after,
        }
    }

    /// `before - after`: the energy the impact dissipates (negative when it creates energy).
    pub fn lost(&self) -> F {
        -self.change.clone()
    }

    /// Whether the impact creates kinetic energy (decided exactly over an exact field).
    pub fn gain(&self) -> bool {
        self.change.sign() == Some(Ordering::Greater)
    }
}

impl<F> EnergyLedger<F> {
    /// Each energy mapped by `f`: a change of number type.
    pub(crate) fn map<G>(self, f: &mut impl FnMut(F) -> G) -> EnergyLedger<G> {
        EnergyLedger {
            before: f(self.before),
            after: f(self.after),
            change: f(self.change),
        }
    }
}

/// A balance law an answer is checked against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Balance {
    /// Total linear momentum along x (the paper's free rod; the oblique impact's normal).
    LinearMomentum,
    /// Total linear momentum along the rod (the oblique impact, free rod).
    TangentialMomentum,
    /// Each free body's momentum changed by the impulse on it (one entry per component).
    Momentum,
    /// Angular momentum: of the paper's bodies about the rod's centre or pivot; of each body
    /// of a system about its centre or pin (a pin also holds its point at rest).
    AngularMomentum,
    /// The total angular momentum about the contact point (a system without fixed or pinned
    /// bodies).
    TotalAngularMomentum,
    /// Kinetic energy kept (elastic impacts of the paper's family).
    Energy,
    /// The energy lost minus its closed-form split (restitution plus friction).
    EnergyLoss,
    /// The restitution law at the end of the impact.
    Restitution,
    /// Coulomb's law at the end: `|tau| <= mu lam` (the residual is the excess).
    Coulomb,
    /// The energy change equals the work of the contact impulse along the path.
    EnergyEqualsWork,
}

impl Balance {
    /// The name in JSON: `linear_momentum`, `angular_momentum`, `energy_equals_work`, ...
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Balance;
    /// assert_eq!(Balance::TotalAngularMomentum.name(), "total_angular_momentum");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Balance::LinearMomentum => "linear_momentum",
            Balance::TangentialMomentum => "tangential_momentum",
            Balance::Momentum => "momentum",
            Balance::AngularMomentum => "angular_momentum",
            Balance::TotalAngularMomentum => "total_angular_momentum",
            Balance::Energy => "energy",
            Balance::EnergyLoss => "energy_loss",
            Balance::Restitution => "restitution",
            Balance::Coulomb => "coulomb",
            Balance::EnergyEqualsWork => "energy_equals_work",
        }
    }
}

/// The balance laws that apply to an answer, each with its residual (after minus before, or
/// what the law leaves over): exactly zero over an exact field when the law holds.
///
/// # Examples
/// ```
/// use rodimpact::impact::{Balance, Balances};
/// let mut b = Balances::new();
/// b.push(Balance::LinearMomentum, 0.0);
/// b.push(Balance::Energy, 0.5);
/// assert_eq!(b.get(Balance::Energy), Some(&0.5));
/// assert_eq!((b.checked(Balance::LinearMomentum), b.checked(Balance::Coulomb)), (Some(true), None));
/// assert!(!b.all_zero());
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Balances<F> {
    entries: Vec<(Balance, F)>,
}

impl<F> Default for Balances<F> {
    fn default() -> Self {
        Balances {
            entries: Vec::new(),
        }
    }
}

impl<F> Balances<F> {
    /// No law checked yet.
    pub fn new() -> Balances<F> {
        Balances::default()
    }

    /// Adds law `law`'s residual `residual`.
    pub fn push(&mut self, law: Balance, residual: F) {
        self.entries.push((law, residual));
    }

    /// Each residual mapped by `f`: a change of number type.
    pub(crate) fn map<G>(self, f: &mut impl FnMut(F) -> G) -> Balances<G> {
        Balances {
            entries: self.entries.into_iter().map(|(l, r)| (l, f(r))).collect(),
        }
    }

    /// The first residual of `law`, when it applies.
    pub fn get(&self, law: Balance) -> Option<&F> {
        self.entries.iter().find(|(l, _)| *l == law).map(|(_, r)| r)
    }
}

impl<F: Field> Balances<F> {
    /// Every residual with its law's name, in the order they were checked.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, &F)> {
        self.entries.iter().map(|(l, r)| (l.name(), r))
    }

    /// Whether every residual of `law` is zero (`true` when none applies).
    pub fn holds(&self, law: Balance) -> bool {
        self.checked(law).unwrap_or(true)
    }

    /// Whether every residual of `law` is zero; `None` when the law does not apply.
    pub fn checked(&self, law: Balance) -> Option<bool> {
        let mut of_law = self.entries.iter().filter(|(l, _)| *l == law).peekable();
        of_law.peek()?;
        Some(of_law.all(|(_, r)| r.is_zero()))
    }

    /// `true` when every residual is exactly zero (decided for exact fields, estimated for
    /// floats).
    pub fn all_zero(&self) -> bool {
        self.entries.iter().all(|(_, r)| r.is_zero())
    }

    /// The laws with a nonzero residual, each named once.
    pub fn failing(&self) -> Vec<&'static str> {
        let mut names: Vec<&'static str> = Vec::new();
        for (law, r) in &self.entries {
            if !r.is_zero() && !names.contains(&law.name()) {
                names.push(law.name());
            }
        }
        names
    }
}
