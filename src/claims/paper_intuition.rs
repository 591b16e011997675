//! Claims C32-C46: why intuition fails (fixed axes, impulses) and the inhomogeneous rod.

use super::Entry;

/// The registered claims of this part of the paper.
pub(super) const ENTRIES: &[Entry] = &[];
