//! The one list of claims, in the order of `docs/claims.md`: the paper's claims as it makes them,
//! then the results beyond it. Every count, id range and help text is derived from it.
//!
//! Each line names a claim's file and its module; the file defines the claim's `ENTRY` (its id,
//! place, group and statement, written once) and the function that formalises and decides it.
//! Adding a claim is one new file and one line here.

use super::{Entry, Group};
use std::fmt;

/// Declares each claim's module from its file (relative to `src/claims/`) and lists the
/// modules' entries in the order given.
macro_rules! registry {
    ($($file:literal => $module:ident,)*) => {
        $(
            #[path = $file]
            mod $module;
        )*

        /// Every claim, in order.
        const REGISTRY: &[Entry] = &[$($module::ENTRY),*];

        /// Each claim's file and module name, in registry order (for the consistency tests).
        #[cfg(test)]
        const FILES: &[(&str, &str)] = &[$(($file, stringify!($module))),*];
    };
}

registry! {
    "paper/c01.rs" => c01,
    "paper/c02.rs" => c02,
    "paper/c03.rs" => c03,
    "paper/c04.rs" => c04,
    "paper/c05.rs" => c05,
    "paper/c06.rs" => c06,
    "paper/c07.rs" => c07,
    "paper/c08.rs" => c08,
    "paper/c09.rs" => c09,
    "paper/c10.rs" => c10,
    "paper/c11.rs" => c11,
    "paper/c12.rs" => c12,
    "paper/c13.rs" => c13,
    "paper/c14.rs" => c14,
    "paper/c15.rs" => c15,
    "paper/c16.rs" => c16,
    "paper/c17.rs" => c17,
    "paper/c18.rs" => c18,
    "paper/c19.rs" => c19,
    "paper/c20.rs" => c20,
    "paper/c21.rs" => c21,
    "paper/c22.rs" => c22,
    "paper/c23.rs" => c23,
    "paper/c24.rs" => c24,
    "paper/c25.rs" => c25,
    "paper/c26.rs" => c26,
    "paper/c27.rs" => c27,
    "paper/c28.rs" => c28,
    "paper/c29.rs" => c29,
    "paper/c30.rs" => c30,
    "paper/c31.rs" => c31,
    "paper/c32.rs" => c32,
    "paper/c33.rs" => c33,
    "paper/c34.rs" => c34,
    "paper/c35.rs" => c35,
    "paper/c36.rs" => c36,
    "paper/c37.rs" => c37,
    "paper/c38.rs" => c38,
    "paper/c39.rs" => c39,
    "paper/c40.rs" => c40,
    "paper/c41.rs" => c41,
    "paper/c42.rs" => c42,
    "paper/c43.rs" => c43,
    "paper/c44.rs" => c44,
    "paper/c45.rs" => c45,
    "paper/c46.rs" => c46,
    "beyond/x01.rs" => x01,
    "beyond/x02.rs" => x02,
    "beyond/x03.rs" => x03,
    "beyond/x04.rs" => x04,
    "beyond/x05.rs" => x05,
    "beyond/x06.rs" => x06,
    "beyond/x07.rs" => x07,
    "beyond/x08.rs" => x08,
    "beyond/x09.rs" => x09,
    "beyond/x10.rs" => x10,
    "beyond/x11.rs" => x11,
    "beyond/x12.rs" => x12,
    "beyond/x13.rs" => x13,
    "beyond/x14.rs" => x14,
    "beyond/x15.rs" => x15,
    "beyond/x16.rs" => x16,
    "beyond/x17.rs" => x17,
    "beyond/x18.rs" => x18,
    "beyond/x19.rs" => x19,
    "beyond/x20.rs" => x20,
    "beyond/x21.rs" => x21,
    "beyond/x22.rs" => x22,
    "beyond/x23.rs" => x23,
    "beyond/x24.rs" => x24,
    "beyond/x25.rs" => x25,
    "beyond/x26.rs" => x26,
    "beyond/x27.rs" => x27,
    "beyond/x28.rs" => x28,
    "beyond/x29.rs" => x29,
    "beyond/x30.rs" => x30,
    "beyond/x31.rs" => x31,
    "beyond/x32.rs" => x32,
    "beyond/x33.rs" => x33,
    "beyond/x34.rs" => x34,
    "beyond/x35.rs" => x35,
    "beyond/x36.rs" => x36,
    "beyond/x37.rs" => x37,
    "beyond/x38.rs" => x38,
    "beyond/x39.rs" => x39,
}

/// Every claim, in the order of `docs/claims.md`: the paper's, then the results beyond it.
///
/// # Examples
/// ```
/// use rodimpact::claims::{beyond_claims, paper_claims, registry};
/// assert_eq!(registry().len(), paper_claims().len() + beyond_claims().len());
/// assert_eq!(registry()[0].id, "C1");
/// ```
pub fn registry() -> &'static [Entry] {
    REGISTRY
}

/// The registered claim with this id (case-insensitive, surrounding spaces ignored).
///
/// # Examples
/// ```
/// use rodimpact::claims::find;
/// assert_eq!(find(" c15").unwrap().location, "Eq. (omega)");
/// assert!(find("C0").is_none());
/// ```
pub fn find(id: &str) -> Option<&'static Entry> {
    REGISTRY
        .iter()
        .find(|e| e.id.eq_ignore_ascii_case(id.trim()))
}

/// Where the results beyond the paper start: the paper's claims come first.
fn beyond_start() -> usize {
    REGISTRY
        .iter()
        .position(|e| e.group == Group::Beyond)
        .unwrap_or(REGISTRY.len())
}

/// The paper's claims (C1, C2, ...), in the order the paper makes them.
///
/// # Examples
/// ```
/// use rodimpact::claims::{Group, paper_claims};
/// assert!(paper_claims().iter().all(|e| e.group != Group::Beyond));
/// ```
pub fn paper_claims() -> &'static [Entry] {
    &REGISTRY[..beyond_start()]
}

/// The results beyond the paper (X1, X2, ...).
///
/// # Examples
/// ```
/// use rodimpact::claims::{Group, beyond_claims};
/// assert!(beyond_claims().iter().all(|e| e.group == Group::Beyond));
/// ```
pub fn beyond_claims() -> &'static [Entry] {
    &REGISTRY[beyond_start()..]
}

/// The ids of a part of the registry, first to last; the part holds every id between them (the
/// registry's tests check that the ids of each part are numbered 1, 2, ... without gaps).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IdRange {
    /// The first id (`C1`).
    pub first: &'static str,
    /// The last id (`C46`).
    pub last: &'static str,
}

impl IdRange {
    fn of(part: &'static [Entry]) -> IdRange {
        let (Some(first), Some(last)) = (part.first(), part.last()) else {
            unreachable!("the registry holds claims of the paper and beyond it");
        };
        IdRange {
            first: first.id,
            last: last.id,
        }
    }
}

/// `C1-C46`.
impl fmt::Display for IdRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}-{}", self.first, self.last)
    }
}

/// The ids of the paper's claims, as a range (`C1-C...`).
///
/// # Examples
/// ```
/// use rodimpact::claims::{paper_claims, paper_ids};
/// assert_eq!(paper_ids().to_string(), format!("C1-C{}", paper_claims().len()));
/// ```
pub fn paper_ids() -> IdRange {
    IdRange::of(paper_claims())
}

/// The ids of the results beyond the paper, as a range (`X1-X...`).
///
/// # Examples
/// ```
/// use rodimpact::claims::{beyond_claims, beyond_ids};
/// assert_eq!(beyond_ids().first, "X1");
/// assert_eq!(beyond_ids().last, format!("X{}", beyond_claims().len()));
/// ```
pub fn beyond_ids() -> IdRange {
    IdRange::of(beyond_claims())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ranges name every claim: each part is numbered 1, 2, ... without gaps, with its own
    /// letter, so `C1-C46` means exactly the paper's claims.
    #[test]
    fn each_part_is_numbered_from_one_without_gaps() {
        for (part, letter) in [(paper_claims(), 'C'), (beyond_claims(), 'X')] {
            let ids: Vec<&str> = part.iter().map(|e| e.id).collect();
            let expected: Vec<String> = (1..=part.len()).map(|i| format!("{letter}{i}")).collect();
            assert_eq!(ids, expected);
        }
        assert!(!paper_claims().is_empty() && !beyond_claims().is_empty());
        assert_eq!(paper_claims().len() + beyond_claims().len(), REGISTRY.len());
    }

    /// The id is written once, in the claim's file; the file's name must agree with it
    /// (`paper/c07.rs` holds C7, `beyond/x26.rs` holds X26).
    #[test]
    fn each_claim_lives_in_the_file_named_after_its_id() {
        assert_eq!(FILES.len(), REGISTRY.len());
        for ((file, module), entry) in FILES.iter().zip(REGISTRY) {
            let (letter, number) = entry.id.split_at(1);
            let number: u32 = number.parse().expect("a numbered id");
            assert_eq!(*module, format!("{}{number:02}", letter.to_lowercase()));
            let folder = if entry.group == Group::Beyond {
                "beyond"
            } else {
                "paper"
            };
            assert_eq!(*file, format!("{folder}/{module}.rs"), "{}", entry.id);
        }
    }

    #[test]
    fn the_ranges_are_written_first_to_last() {
        assert_eq!(
            paper_ids().to_string(),
            format!("C1-C{}", paper_claims().len())
        );
        assert_eq!(find("x1").map(|e| e.id), Some(beyond_ids().first));
    }
}
