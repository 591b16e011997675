//! What the lines of `impact --batch` said, together ([`crate::report::impact_batch_text`] and
//! [`crate::report::impact_batch_json`] render it).

use super::ImpactAudit;
use crate::batch::KnownFindings;
use std::collections::BTreeMap;

/// How many scenes of each finding the summary names; the others are counted.
pub const MAX_NAMED_SCENES: usize = 100;

/// The scenes a finding was found in: how many, and the first [`MAX_NAMED_SCENES`] by their
/// ids as a message quotes them ([`crate::echo::echo`]: escaped, at most 40 characters), so
/// that the summary's memory stays bounded however long the file and its ids.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Scenes {
    /// How many scenes.
    pub count: usize,
    /// The first ones' ids.
    pub named: Vec<String>,
}

impl Scenes {
    /// Counts one more scene, naming it while there is room.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::Scenes;
    /// let mut s = Scenes::default();
    /// s.push("a\u{1b}[2J");
    /// assert_eq!((s.count, s.named[0].as_str()), (1, "a\\u{1b}[2J"));
    /// ```
    pub fn push(&mut self, id: &str) {
        self.count += 1;
        if self.named.len() < MAX_NAMED_SCENES {
            self.named.push(crate::echo::echo(id));
        }
    }
}

/// What the lines said, together.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ImpactBatchSummary {
    /// The scenes read.
    pub scenes: usize,
    /// Those with a claimed state.
    pub claimed: usize,
    /// For each answer's name, the claims that match it.
    pub matched: BTreeMap<String, usize>,
    /// For each answer's name, the claims it is closest to.
    pub closest: BTreeMap<String, usize>,
    /// For each finding, the scenes it was found in, in order.
    pub findings: BTreeMap<String, Scenes>,
    /// With known findings: the findings no entry allows, with their scenes.
    pub unexpected: BTreeMap<String, Scenes>,
    /// With known findings: the entries (0-based) some scene used.
    pub used: Vec<usize>,
}

impl ImpactBatchSummary {
    /// Adds one audited line.
    pub fn add(&mut self, audit: &ImpactAudit, expected: Option<&KnownFindings>) {
        self.scenes += 1;
        if audit.claimed.is_none() {
            return;
        }
        self.claimed += 1;
        for m in &audit.matches {
            *self.matched.entry(m.clone()).or_default() += 1;
        }
        if let Some(closest) = &audit.closest {
            *self.closest.entry(closest.clone()).or_default() += 1;
        }
        for f in &audit.findings {
            self.findings
                .entry((*f).into())
                .or_default()
                .push(&audit.id);
        }
        if let Some(expected) = expected {
            let (used, unexpected) = expected.check(&audit.id, &audit.findings, false);
            self.used.extend(used);
            self.used.sort_unstable();
            self.used.dedup();
            for f in unexpected {
                self.unexpected.entry(f.into()).or_default().push(&audit.id);
            }
        }
    }

    /// Whether the batch passes (the exit status 0): some claim audited, and no finding, or
    /// with known findings none that they do not allow. A batch without a claimed state (an
    /// empty file, `"claim"` for `"claimed"`) audited nothing and does not pass.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::ImpactBatchSummary;
    /// assert!(!ImpactBatchSummary::default().passed(false));
    /// ```
    pub fn passed(&self, with_expected: bool) -> bool {
        if self.claimed == 0 {
            false
        } else if with_expected {
            self.unexpected.is_empty()
        } else {
            self.findings.is_empty()
        }
    }
}
