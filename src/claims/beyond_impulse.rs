//! Results beyond the paper.

use super::Entry;

/// The registered claims of this part.
pub(super) const ENTRIES: &[Entry] = &[];
