//! Interned symbol names, ordered by name.

use std::cmp::Ordering;
use std::collections::HashSet;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::{Mutex, OnceLock};

/// An interned symbol name such as `m`, `M` or `v0`; cheap to copy and compare.
///
/// Symbols are ordered by name (plain string order), so sorting never depends on which symbol
/// was created first.
///
/// # Examples
/// ```
/// use rodimpact::field::Sym;
/// let (m, big_m) = (Sym::new("m"), Sym::new("M"));
/// assert_eq!(m, Sym::new("m"));
/// assert!(big_m < m); // "M" < "m" in string order
/// assert_eq!(m.name(), "m");
/// ```
#[derive(Clone, Copy, Eq)]
pub struct Sym(pub(super) &'static str);

impl Sym {
    /// The symbol called `name`, interned once for the life of the program.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Sym;
    /// assert_eq!(Sym::new("v0").to_string(), "v0");
    /// ```
    pub fn new(name: &str) -> Sym {
        static NAMES: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
        let mut names = NAMES
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some(&interned) = names.get(name) {
            return Sym(interned);
        }
        let interned: &'static str = Box::leak(name.to_owned().into_boxed_str());
        names.insert(interned);
        Sym(interned)
    }

    /// The symbol's name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Sym;
    /// assert_eq!(Sym::new("a").name(), "a");
    /// ```
    pub fn name(self) -> &'static str {
        self.0
    }
}

impl PartialEq for Sym {
    fn eq(&self, other: &Self) -> bool {
        // Interned: equal names share one allocation.
        std::ptr::eq(self.0, other.0)
    }
}

impl Hash for Sym {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.hash(state);
    }
}

impl Ord for Sym {
    fn cmp(&self, other: &Self) -> Ordering {
        if self == other {
            Ordering::Equal
        } else {
            self.0.cmp(other.0)
        }
    }
}

impl PartialOrd for Sym {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}
