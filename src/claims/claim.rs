//! What a claim is: its place in the paper, its verdict, the decision with its certificates, and
//! why a check can fail. The claims themselves are in `paper/` and `beyond/`, listed in
//! [`registry`](super::registry()).

use super::export::Export;
use super::{Certificate, CertificateError, Paper};

/// The location of every result beyond the paper.
pub(crate) const BEYOND: &str = "beyond the paper";

/// Where in the paper a claim stands, for grouping the report as the paper runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Group {
    /// Abstract and introduction.
    Introduction,
    /// Eqs. (linear) to (omega).
    Equations,
    /// The limiting cases (i)-(iii).
    LimitingCases,
    /// Where omega is largest.
    Optimum,
    /// The totally inelastic collision.
    Inelastic,
    /// Why intuition fails: fixed axes and impulses.
    Intuition,
    /// The inhomogeneous rod.
    Inhomogeneous,
    /// Results beyond the paper.
    Beyond,
}

impl Group {
    /// The heading used in reports.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Group;
    /// assert_eq!(Group::Optimum.title(), "The optimum impact point");
    /// ```
    pub fn title(self) -> &'static str {
        match self {
            Group::Introduction => "Abstract and introduction",
            Group::Equations => "The impulse equations",
            Group::LimitingCases => "Limiting cases",
            Group::Optimum => "The optimum impact point",
            Group::Inelastic => "The totally inelastic collision",
            Group::Intuition => "Why intuition fails",
            Group::Inhomogeneous => "The inhomogeneous rod",
            Group::Beyond => "Beyond the paper",
        }
    }
}

/// The verdict on a claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// True under the standing assumptions.
    Proved,
    /// False: a counterexample is given.
    Refuted,
    /// The natural reading is false; a stated qualification makes it true, and that is proved.
    Qualified,
}

impl Verdict {
    /// `PROVED`, `REFUTED` or `QUALIFIED`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Verdict;
    /// assert_eq!(Verdict::Qualified.as_str(), "QUALIFIED");
    /// ```
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Proved => "PROVED",
            Verdict::Refuted => "REFUTED",
            Verdict::Qualified => "QUALIFIED",
        }
    }
}

/// What the computation decided, with the evidence.
#[derive(Debug, Clone, PartialEq)]
pub enum Decision {
    /// The statement holds: every certificate must check.
    Proved(Vec<Certificate>),
    /// The statement is false: the certificates exhibit the counterexample.
    Refuted(Vec<Certificate>),
    /// The natural reading is false (counterexample), the qualified statement holds (proof).
    Qualified {
        /// The qualification under which the statement is true.
        qualification: String,
        /// Certificates refuting the natural reading.
        counterexample: Vec<Certificate>,
        /// Certificates proving the qualified statement.
        proof: Vec<Certificate>,
    },
}

/// Why a claim's certificates do not support its verdict.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckError {
    /// The decision carries no certificate (a list is empty).
    #[error("no certificate")]
    NoCertificate,
    /// A certificate does not check.
    #[error("{title}: {failure}")]
    Failed {
        /// The certificate's title.
        title: String,
        /// What the exact computation found.
        failure: CertificateError,
    },
}

/// One claim, formalised and decided.
#[derive(Debug, Clone, PartialEq)]
pub struct Claim {
    /// The id in `docs/claims.md` (`C15`, `X4`).
    pub id: &'static str,
    /// Where it stands in the paper (`Eq. (omega)`), or `beyond the paper`.
    pub location: &'static str,
    /// The report group.
    pub group: Group,
    /// The claim in words, as `docs/claims.md` lists it.
    pub statement: &'static str,
    /// The claim as formalised here, every assumption explicit.
    pub formal: String,
    /// One line: why the verdict is what it is.
    pub reason: String,
    /// The decision and its certificates.
    pub decision: Decision,
}

impl Claim {
    /// Re-checks every certificate and returns the verdict they support.
    ///
    /// # Errors
    /// [`CheckError::NoCertificate`] for an empty list, or the first certificate that does not
    /// check ([`CheckError::Failed`]: its title and why).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{decide, Paper, Verdict};
    /// let claim = decide("C31", &Paper::as_printed()).unwrap().claim;
    /// assert_eq!(claim.check(), Ok(Verdict::Qualified));
    /// ```
    pub fn check(&self) -> Result<Verdict, CheckError> {
        let all = |certs: &[Certificate]| -> Result<(), CheckError> {
            if certs.is_empty() {
                return Err(CheckError::NoCertificate);
            }
            for c in certs {
                c.check().map_err(|failure| CheckError::Failed {
                    title: c.title().to_string(),
                    failure,
                })?;
            }
            Ok(())
        };
        match &self.decision {
            Decision::Proved(c) => all(c).map(|()| Verdict::Proved),
            Decision::Refuted(c) => all(c).map(|()| Verdict::Refuted),
            Decision::Qualified {
                counterexample,
                proof,
                ..
            } => {
                all(counterexample)?;
                all(proof).map(|()| Verdict::Qualified)
            }
        }
    }

    /// Every certificate of the decision, counterexamples first.
    pub fn certificates(&self) -> Vec<&Certificate> {
        match &self.decision {
            Decision::Proved(c) | Decision::Refuted(c) => c.iter().collect(),
            Decision::Qualified {
                counterexample,
                proof,
                ..
            } => counterexample.iter().chain(proof).collect(),
        }
    }

    /// Every certificate of the decision, counterexamples first, for editing (the mutation tests
    /// use it to check that a tampered certificate fails).
    pub fn certificates_mut(&mut self) -> Vec<&mut Certificate> {
        match &mut self.decision {
            Decision::Proved(c) | Decision::Refuted(c) => c.iter_mut().collect(),
            Decision::Qualified {
                counterexample,
                proof,
                ..
            } => counterexample.iter_mut().chain(proof.iter_mut()).collect(),
        }
    }

    /// The method: the distinct certificate kinds, joined by `+` (`identity + positivity`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{decide, Paper};
    /// let c = decide("C15", &Paper::as_printed()).unwrap();
    /// assert_eq!(c.claim.method(), "identity + positivity");
    /// ```
    pub fn method(&self) -> String {
        let mut kinds: Vec<&str> = Vec::new();
        for c in self.certificates() {
            if !kinds.contains(&c.kind()) {
                kinds.push(c.kind());
            }
        }
        kinds.join(" + ")
    }

    /// The qualification, for a QUALIFIED decision.
    pub fn qualification(&self) -> Option<&str> {
        match &self.decision {
            Decision::Qualified { qualification, .. } => Some(qualification),
            _ => None,
        }
    }
}

/// A registered claim: what it says, as data, and the function that formalises and decides it.
/// Each claim file defines one (`ENTRY`); the [`registry`](super::registry()) lists them in order.
#[derive(Debug, Clone, Copy)]
pub struct Entry {
    /// The id in `docs/claims.md` (`C15`, `X4`), written once: here.
    pub id: &'static str,
    /// Where it stands in the paper (`Eq. (omega)`), or `beyond the paper`.
    pub location: &'static str,
    /// The report group.
    pub group: Group,
    /// The claim in words, as `docs/claims.md` lists it.
    pub statement: &'static str,
    /// Formalises the claim and decides it (doing the computation) from the paper's formulas.
    pub formalise: fn(&Paper) -> Formalised,
    /// The claim in real arithmetic for independent checkers (z3, SymPy), from the physics.
    pub export: Export,
}

impl Entry {
    /// The claim formalised and decided against `paper`, its certificates not yet checked.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::{Paper, find};
    /// let claim = find("C15").unwrap().claim(&Paper::as_printed());
    /// assert_eq!(claim.location, "Eq. (omega)");
    /// assert_eq!(claim.method(), "identity + positivity");
    /// ```
    pub fn claim(&self, paper: &Paper) -> Claim {
        let Formalised {
            formal,
            reason,
            decision,
        } = (self.formalise)(paper);
        Claim {
            id: self.id,
            location: self.location,
            group: self.group,
            statement: self.statement,
            formal,
            reason,
            decision,
        }
    }
}

/// What a claim's code computes: the claim formalised, why the verdict is what it is, and the
/// decision with its certificates.
#[derive(Debug, Clone, PartialEq)]
pub struct Formalised {
    /// The claim as formalised here, every assumption explicit.
    pub formal: String,
    /// One line: why the verdict is what it is.
    pub reason: String,
    /// The decision and its certificates.
    pub decision: Decision,
}

/// A claim built and checked, with the time it took.
#[derive(Debug, Clone)]
pub struct Decided {
    /// The claim.
    pub claim: Claim,
    /// The verdict the certificates support, or why they do not.
    pub verdict: Result<Verdict, CheckError>,
    /// Seconds spent building and checking.
    pub seconds: f64,
}
