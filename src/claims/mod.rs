//! The claims registry: every claim of the paper (C1-C46) and the results beyond it (X1-X26),
//! each formalised, decided by exact computation and carrying the certificates that prove it.
//!
//! A claim's verdict comes only from re-checking its certificates ([`Claim::check`]):
//!
//! - PROVED: every certificate checks;
//! - REFUTED: the counterexample certificates check (the statement is false there);
//! - QUALIFIED: the natural reading is refuted by the counterexample, and the qualified
//!   statement is proved by the proof certificates.
//!
//! The paper's printed formulas enter as data ([`Paper`]), independent of the solver; a test
//! replaces one of them by a wrong one and the claims that depend on it must then fail.

mod beyond_impulse;
mod beyond_motion;
mod build;
pub mod certificate;
mod formula;
pub mod model;
mod paper_equations;
mod paper_intuition;
mod paper_optimum;

pub use certificate::{Certificate, CertificateError, Expected, PosExpr, Relation, SignClass};
pub use formula::Formula;

use std::time::Instant;

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

/// The formulas as the paper prints them: the data the claims compare with independent
/// computations. [`Paper::as_printed`] is the paper; tests mutate a field to check that the
/// verifier notices. Each is a [`Formula`], so certificates show it as printed.
#[derive(Debug, Clone, PartialEq)]
pub struct Paper {
    /// Eq. (v): `v = -(1 - m/M - m a^2/I)/D v0`.
    pub v: Formula,
    /// Eq. (V): `V = (2m/M)/D v0`.
    pub big_v: Formula,
    /// Eq. (omega): `omega = (2ma/I)/D v0`.
    pub omega: Formula,
    /// Eq. (maximal-a-general), squared: `a*^2 = (M + m) I/(m M)`.
    pub a_star_squared: Formula,
    /// Eq. (inertia-homogeneous): `I = M (2l)^2/12`.
    pub uniform_inertia: Formula,
    /// Eq. (maximal-a-homogeneous), squared: `a*^2 = (M + m) l^2/(3m)`.
    pub a_star_uniform_squared: Formula,
    /// The mass ratio M/m at which a* reaches the end of a uniform rod: 2.
    pub threshold: Formula,
    /// Eq. (impulse-linear): `I_lin = 2 m v0/(1 + m/M + 3 m a^2/(M l^2))`.
    pub impulse_linear: Formula,
    /// Eq. (maximal-a-gyration), squared: `a*^2 = (M + m) r_G^2/m`.
    pub a_star_gyration_squared: Formula,
}

impl Paper {
    /// The formulas exactly as printed in the paper (`D = 1 + m/M + m a^2/I` written out).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Paper;
    /// let paper = Paper::as_printed();
    /// assert_eq!(paper.threshold.to_string(), "2");
    /// assert_eq!(paper.omega.to_string(), "(2*m*a/I)/(1 + m/M + m*a^2/I)*v0");
    /// assert_eq!(paper.omega.value().to_string(), "2*M*a*m*v0/(M*a^2*m + I*M + I*m)");
    /// ```
    pub fn as_printed() -> Paper {
        let f = Formula::sym;
        let (m, big_m, inertia, a, v0, l, r) =
            (f("m"), f("M"), f("I"), f("a"), f("v0"), f("l"), f("r_G"));
        let (one, two, three) = (Formula::int(1), Formula::int(2), Formula::int(3));
        let m_over_big_m = m.clone() / &big_m;
        let m_a2_over_i = m.clone() * &a.pow(2) / &inertia;
        let d = one.clone() + &m_over_big_m + &m_a2_over_i;
        Paper {
            v: -((one.clone() - &m_over_big_m - &m_a2_over_i) / &d * &v0),
            big_v: (two.clone() * &m / &big_m) / &d * &v0,
            omega: (two.clone() * &m * &a / &inertia) / &d * &v0,
            a_star_squared: (big_m.clone() + &m) * &inertia / &(m.clone() * &big_m),
            uniform_inertia: big_m.clone() * &(two.clone() * &l).pow(2) / &Formula::int(12),
            a_star_uniform_squared: (big_m.clone() + &m) / &(three.clone() * &m) * &l.pow(2),
            threshold: two.clone(),
            impulse_linear: two * &m * &v0
                / &(one + &m_over_big_m + &(three * &m * &a.pow(2) / &(big_m.clone() * &l.pow(2)))),
            a_star_gyration_squared: (big_m + &m) / &m * &r.pow(2),
        }
    }
}

/// A registered claim: its id and the function that formalises and decides it.
#[derive(Clone, Copy)]
pub struct Entry {
    /// The claim id.
    pub id: &'static str,
    /// Builds the claim (doing the computation) from the paper's formulas.
    pub build: fn(&Paper) -> Claim,
}

/// Every claim, in the order of `docs/claims.md`: C1-C46, then X1-X26.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::claims::registry().len(), 72);
/// ```
pub fn registry() -> Vec<Entry> {
    let mut all = Vec::new();
    all.extend_from_slice(paper_equations::ENTRIES);
    all.extend_from_slice(paper_optimum::ENTRIES);
    all.extend_from_slice(paper_intuition::ENTRIES);
    all.extend_from_slice(beyond_impulse::ENTRIES);
    all.extend_from_slice(beyond_motion::ENTRIES);
    all
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

/// Builds and checks the claim `id` against `paper`; `None` for an unknown id.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper, Verdict};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// assert_eq!(d.verdict, Ok(Verdict::Proved));
/// ```
pub fn decide(id: &str, paper: &Paper) -> Option<Decided> {
    registry()
        .into_iter()
        .find(|e| e.id.eq_ignore_ascii_case(id))
        .map(|e| decide_entry(&e, paper))
}

/// Builds and checks one registered claim.
pub fn decide_entry(entry: &Entry, paper: &Paper) -> Decided {
    let start = Instant::now();
    let claim = (entry.build)(paper);
    let verdict = claim.check();
    Decided {
        claim,
        verdict,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// Builds and checks every claim.
pub fn decide_all(paper: &Paper) -> Vec<Decided> {
    registry().iter().map(|e| decide_entry(e, paper)).collect()
}

/// Helpers shared by the claim files' tests.
#[cfg(test)]
mod test_support {
    use super::{Paper, Verdict, decide};

    /// The verdict of claim `id` against `paper`.
    pub(super) fn verdict(id: &str, paper: &Paper) -> Result<Verdict, super::CheckError> {
        decide(id, paper).expect("registered").verdict
    }
}
