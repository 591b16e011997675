//! Deciding claims: build each registered claim (the computation) and re-check its certificates.

use super::{Decided, Entry, Paper, find, registry};
use std::time::Instant;

/// Builds and checks the claim `id` against `paper`; `None` for an unknown id.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper, Verdict};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// assert_eq!(d.verdict, Ok(Verdict::Proved));
/// ```
pub fn decide(id: &str, paper: &Paper) -> Option<Decided> {
    find(id).map(|e| decide_entry(e, paper))
}

/// Builds and checks one registered claim.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide_entry, find, Paper, Verdict};
/// let d = decide_entry(find("C3").unwrap(), &Paper::as_printed());
/// assert_eq!(d.verdict, Ok(Verdict::Refuted));
/// ```
pub fn decide_entry(entry: &Entry, paper: &Paper) -> Decided {
    let start = Instant::now();
    let claim = entry.claim(paper);
    let verdict = claim.check();
    Decided {
        claim,
        verdict,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// Builds and checks every claim, in registry order.
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide_all, registry, Paper};
/// let all = decide_all(&Paper::as_printed());
/// assert_eq!(all.len(), registry().len());
/// assert!(all.iter().all(|d| d.verdict.is_ok()));
/// ```
pub fn decide_all(paper: &Paper) -> Vec<Decided> {
    registry().iter().map(|e| decide_entry(e, paper)).collect()
}
