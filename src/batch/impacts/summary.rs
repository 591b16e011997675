//! What the lines of `impact --batch` said, together ([`crate::report::impact_batch_text`] and
//! [`crate::report::impact_batch_json`] render it).

use super::ImpactAudit;
use crate::batch::KnownFindings;
use std::collections::BTreeMap;

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
    /// For each finding, the ids of the scenes it was found in, in order.
    pub findings: BTreeMap<String, Vec<String>>,
    /// With known findings: the findings no entry allows, with their scenes' ids.
    pub unexpected: BTreeMap<String, Vec<String>>,
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
                .push(audit.id.clone());
        }
        if let Some(expected) = expected {
            let (used, unexpected) = expected.check(&audit.id, &audit.findings, false);
            self.used.extend(used);
            self.used.sort_unstable();
            self.used.dedup();
            for f in unexpected {
                self.unexpected
                    .entry(f.into())
                    .or_default()
                    .push(audit.id.clone());
            }
        }
    }

    /// Whether the batch passes (the exit status 0): no finding, or with known findings none
    /// that they do not allow.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::ImpactBatchSummary;
    /// assert!(ImpactBatchSummary::default().passed(false));
    /// ```
    pub fn passed(&self, with_expected: bool) -> bool {
        if with_expected {
            self.unexpected.is_empty()
        } else {
            self.findings.is_empty()
        }
    }
}
