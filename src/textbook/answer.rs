//! What checking a claimed answer found: its [`AnswerAgreement`] with the exact value, how far off it
//! is ([`RelError`]), a [`Counterexample`] scene for a refuted formula, and the
//! [`SceneCheck`] that gathers one [`CheckedAnswer`] per claim. `crate::report` renders them.

use super::exact::Exact;
use crate::field::Q;
use num_traits::{Signed, Zero};

/// Whether a claimed answer agrees with the exact one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AnswerAgreement {
    /// The claim is right (to its own significant figures, exactly, or as an identity).
    Agrees,
    /// The claim is wrong.
    Disagrees,
    /// Wrong by exactly one unit in the last printed digit.
    LastDigit,
    /// Could not be decided (no valid scene found to test, or a value on a rounding tie
    /// beyond the available precision of pi).
    Undecided,
}

/// How far a claimed number is from the exact one: both values, to show the error as a
/// percentage or, for a claim twice the exact value or more, as a factor.
#[derive(Debug, Clone, PartialEq)]
pub struct RelError {
    /// The claimed value (a magnitude for omega), in SI.
    pub claimed: Q,
    /// The exact value (a magnitude for omega), nonzero.
    pub exact: Q,
    /// Whether the values are those of a counterexample scene (a refuted formula).
    pub at_counterexample: bool,
}

impl RelError {
    /// `(claimed - exact)/|exact|`, `None` when the exact value is 0.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::RelError;
    /// use rodimpact::field::q;
    /// let e = RelError::new(q(1, 2), q(1, 1)).unwrap();
    /// assert_eq!(e.value(), q(-1, 2));
    /// assert!(RelError::new(q(1, 1), q(0, 1)).is_none());
    /// ```
    pub fn new(claimed: Q, exact: Q) -> Option<RelError> {
        (!exact.is_zero()).then_some(RelError {
            claimed,
            exact,
            at_counterexample: false,
        })
    }

    /// The relative error `(claimed - exact)/|exact|` (-0.5 is -50 %).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::RelError;
    /// use rodimpact::field::q;
    /// assert_eq!(RelError::new(q(3, 1), q(-1, 1)).unwrap().value(), q(4, 1));
    /// ```
    pub fn value(&self) -> Q {
        (&self.claimed - &self.exact) / self.exact.abs()
    }
}

/// A scene where a refuted formula and the exact value differ.
#[derive(Debug, Clone, PartialEq)]
pub struct Counterexample {
    /// The free symbols' values, in the scene's order.
    pub point: Vec<(String, Q)>,
    /// The exact value there.
    pub exact: Exact,
    /// The claimed formula's value there.
    pub claimed: Exact,
}

/// One claimed answer, checked: what was claimed, the exact value, and whether they agree.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckedAnswer {
    /// Claim name (`omega`).
    pub name: String,
    /// The claimed value as written.
    pub claim: String,
    /// The exact value in SI units (a fraction, a surd, or a formula).
    pub exact: String,
    /// The exact value when it is a number (its decimals are printed from it).
    pub value: Option<Exact>,
    /// How far the claim is from the exact value, when both are numbers.
    pub rel_error: Option<RelError>,
    /// A scene refuting a formula.
    pub counterexample: Option<Counterexample>,
    /// Whether the claim agrees.
    pub agreement: AnswerAgreement,
    /// Remarks: ambiguous figures, bounds on pi, opposite sign, identity, counterexample.
    pub notes: Vec<String>,
}

impl CheckedAnswer {
    /// An answer not decided yet.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::{AnswerAgreement, CheckedAnswer};
    /// let answer = CheckedAnswer::new("v", "2.3", "7/3".into(), None);
    /// assert_eq!(answer.agreement, AnswerAgreement::Undecided);
    /// ```
    pub fn new(name: &str, claim: &str, exact: String, value: Option<Exact>) -> CheckedAnswer {
        CheckedAnswer {
            name: name.to_string(),
            claim: claim.to_string(),
            exact,
            value,
            rel_error: None,
            counterexample: None,
            agreement: AnswerAgreement::Undecided,
            notes: Vec::new(),
        }
    }

    /// Whether the claim agrees.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::CheckedAnswer;
    /// assert!(!CheckedAnswer::new("v", "2.3", "7/3".into(), None).agrees());
    /// ```
    pub fn agrees(&self) -> bool {
        self.agreement == AnswerAgreement::Agrees
    }
}

/// What a symbolic scene left free and which defaults it applied.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneSummary {
    /// The free symbols, in the scene's order.
    pub free: Vec<String>,
    /// The defaults applied to quantities not given (`e = 1 (elastic)`, ...).
    pub defaults: Vec<String>,
}

/// The claimed answers about one scene, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneCheck {
    /// For a symbolic scene, its free symbols and defaults; `None` for a numeric one.
    pub symbolic: Option<SceneSummary>,
    /// One checked answer per claim, in order.
    pub answers: Vec<CheckedAnswer>,
}

impl SceneCheck {
    /// How many claims agree.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::SceneCheck;
    /// assert_eq!(SceneCheck { symbolic: None, answers: vec![] }.agreeing(), 0);
    /// ```
    pub fn agreeing(&self) -> usize {
        self.answers.iter().filter(|d| d.agrees()).count()
    }

    /// Whether every claim agrees.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::textbook::SceneCheck;
    /// assert!(SceneCheck { symbolic: None, answers: vec![] }.all_agree());
    /// ```
    pub fn all_agree(&self) -> bool {
        self.agreeing() == self.answers.len()
    }
}
