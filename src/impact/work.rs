//! The work budget of the general solver's iterated exact work. Exact rationals grow as they
//! are iterated (a sweep of projected Gauss-Seidel multiplies denominators), so the cost of an
//! iteration is its row operations times the cost of one on its numbers (about b^2/64 for
//! rationals of b bits: the steps of the gcd that reduces them). Each kind of iterated work
//! ([`Work`]) charges that cost as it goes and stops at its limit, a fixed number of units (no
//! clock is read, so the same input stops at the same place on every machine), and asks the
//! host between units whether to stop ([`crate::interrupt`]). The limits are in `docs/limits.md`; each is a few seconds of
//! CPU at most.
//!
//! # Examples
//! ```
//! use rodimpact::impact::{Stopped, Work};
//! assert!(Work::Sweeps.limit() > 0);
//! let stopped = Stopped::OverBudget(Work::Sweeps);
//! assert!(stopped.to_string().contains("projected Gauss-Seidel sweeps"));
//! ```

use crate::field::Field;
use std::fmt;

/// A kind of iterated exact work, each with its limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// Sweeps of projected Gauss-Seidel (`pgs:K`) and an engine's iterations.
    Sweeps,
    /// Pivots of Lemke's method.
    Pivots,
    /// The contact modes (active sets, stick or slide) tried by enumeration.
    Modes,
    /// Sequential impacts, one contact at a time.
    Impacts,
    /// An engine's steps replayed (at most [`crate::impact::MAX_ENGINE_STEPS`] steps of its
    /// iterations).
    EngineSteps,
}

/// The budget of every kind, in units of exact work (an operation on rationals of b bits costs
/// b^2/64 units, the steps of its gcd): at most about 2 s of CPU on the machine of
/// `docs/limits.md`.
pub const WORK_LIMIT: u64 = 1_000_000_000;

impl Work {
    /// The limit of this kind of work, in units of exact work (an operation on rationals of b
    /// bits costs b^2/64).
    pub fn limit(self) -> u64 {
        match self {
            // Bounded in steps already; the numbers of a step that does not stop grow.
            Work::EngineSteps => 4 * WORK_LIMIT,
            Work::Sweeps | Work::Pivots | Work::Modes | Work::Impacts => WORK_LIMIT,
        }
    }

    /// What the work is, in words.
    pub fn name(self) -> &'static str {
        match self {
            Work::Sweeps => "projected Gauss-Seidel sweeps",
            Work::Pivots => "Lemke pivots",
            Work::Modes => "contact modes tried",
            Work::Impacts => "sequential impacts",
            Work::EngineSteps => "engine steps",
        }
    }
}

/// Why iterated work stopped before its answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stopped {
    /// The work passed its limit.
    OverBudget(Work),
    /// The host asked to stop ([`crate::interrupt`]).
    Interrupted,
}

impl fmt::Display for Stopped {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stopped::OverBudget(work) => write!(
                f,
                "the exact {} pass the work limit ({} units; docs/limits.md)",
                work.name(),
                crate::field::count::grouped(work.limit())
            ),
            Stopped::Interrupted => f.write_str("interrupted"),
        }
    }
}

/// The work spent so far on one kind.
#[derive(Debug)]
pub(crate) struct Meter {
    work: Work,
    spent: u64,
    limit: u64,
}

impl Meter {
    /// A meter with the whole limit of `work`.
    pub(crate) fn new(work: Work) -> Meter {
        Meter::shared(work, 1)
    }

    /// A meter with a `share`-th of the limit of `work`: for one of `share` runs answered
    /// together (every sequential order of a scene), so that together they stay within one
    /// limit.
    pub(crate) fn shared(work: Work, share: u64) -> Meter {
        Meter {
            work,
            spent: 0,
            limit: work.limit() / share.max(1),
        }
    }

    /// Charges `operations` row operations on numbers of the size of `numbers` (the largest),
    /// and asks the host whether to stop.
    pub(crate) fn charge<'a, F: Field + 'a>(
        &mut self,
        operations: usize,
        numbers: impl IntoIterator<Item = &'a F>,
    ) -> Result<(), Stopped> {
        // An operation on b-bit rationals costs its gcd, about b^2/64 machine-word steps.
        let bits = numbers
            .into_iter()
            .map(Field::size_bits)
            .max()
            .unwrap_or(0)
            .max(64);
        let cost = bits.saturating_mul(bits) / 64;
        self.spent = self
            .spent
            .saturating_add((operations as u64).saturating_mul(cost));
        if crate::interrupt::requested() {
            return Err(Stopped::Interrupted);
        }
        if self.spent > self.limit {
            return Err(Stopped::OverBudget(self.work));
        }
        Ok(())
    }
}
