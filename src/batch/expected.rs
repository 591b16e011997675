//! `batch --expect FILE`: a baseline of the findings an engine is known to have, so that a CI
//! job fails on a new finding and not on a known one.
//!
//! The file is CSV with the header `id,finding`, one allowed finding per line; `#` starts a
//! comment line, blank lines are skipped:
//!
//! ```text
//! # pymunk 7.3.1 on the engine suite: known differences
//! id,finding
//! free-end-*,no-contact        # every run whose id starts with free-end-
//! pivot-at-impact-1/2,off
//! *,omega-sign                 # any row
//! low-speed-3,wrong            # a wrong claim on a row the audit does not explain
//! ```
//!
//! `id` is a row's `id` cell, or a pattern with `*` standing for any text (a class of scenes);
//! `finding` is a diagnosis name (`energy-gain`, ..., `off`), `wrong` (a wrong claim), or `*`
//! (anything). A row's wrong claims are expected when a `wrong` entry allows them, or when the
//! row's findings are all expected (the findings say why the claims are wrong).

use super::audit::Finding;
use crate::echo::echo;
use crate::error::{Error, ErrorKind};

/// The largest baseline file read.
pub const MAX_EXPECTED_BYTES: usize = 1 << 20;

/// One line of the baseline: an id pattern and a finding.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExpectedEntry {
    /// The row id, or a pattern with `*`.
    pub id: String,
    /// A diagnosis name, `wrong`, or `*`.
    pub finding: String,
    /// The line of the file it comes from.
    pub line: usize,
}

/// The findings a batch is allowed to have (`batch --expect FILE`).
///
/// # Examples
/// ```
/// use rodimpact::batch::KnownFindings;
/// let e = KnownFindings::parse("known.csv", "id,finding\nfree-end-*,no-contact\n*,omega-sign\n")?;
/// assert_eq!(e.allowing("free-end-3", "no-contact"), Some(0));
/// assert_eq!(e.allowing("pivot-1", "omega-sign"), Some(1));
/// assert_eq!(e.allowing("pivot-1", "no-contact"), None);
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct KnownFindings {
    /// The entries, in file order.
    pub entries: Vec<ExpectedEntry>,
}

impl KnownFindings {
    /// Reads a baseline file's text (`label` names it in errors).
    ///
    /// # Errors
    /// `expect: ...` naming the line: a header other than `id,finding`, a line without two
    /// cells, an empty id, an unknown finding, or a file over [`MAX_EXPECTED_BYTES`].
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::KnownFindings;
    /// let err = KnownFindings::parse("known.csv", "id,finding\nend,energy-loose\n").unwrap_err();
    /// assert_eq!(err.to_string(), "expect: known.csv line 2: unknown finding 'energy-loose' \
    ///     (expected energy-gain, energy-loss, restitution-ignored, no-contact, momentum, \
    ///     angular-momentum, above-omega-max, omega-sign, non-finite, off, wrong or *)");
    /// ```
    pub fn parse(label: &str, text: &str) -> Result<KnownFindings, Error> {
        let bad = |line: usize, why: String| {
            Error::new(
                "expect",
                ErrorKind::Invalid(format!("{label} line {line}: {why}")),
            )
        };
        if text.len() > MAX_EXPECTED_BYTES {
            return Err(Error::out_of_range(
                "expect",
                format!("{label} is larger than {MAX_EXPECTED_BYTES} bytes (limit)"),
            ));
        }
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(k, l)| (k + 1, l.trim_start_matches('\u{feff}').trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        match lines.next() {
            Some((_, header)) if cells(header) == ["id", "finding"] => {}
            Some((n, header)) => {
                return Err(bad(
                    n,
                    format!("the header is '{}', expected 'id,finding'", echo(header)),
                ));
            }
            None => return Err(bad(1, "no header 'id,finding'".into())),
        }
        let mut entries = Vec::new();
        for (n, line) in lines {
            let content = line.split(" #").next().unwrap_or(line);
            let [id, finding] = cells(content)[..] else {
                return Err(bad(
                    n,
                    format!("expected two cells 'id,finding', got '{}'", echo(line)),
                ));
            };
            if id.is_empty() {
                return Err(bad(n, "the id is empty (write * for every row)".into()));
            }
            let known = Finding::ALL.iter().any(|f| f.name() == finding);
            if !known && finding != "wrong" && finding != "*" {
                let names: Vec<&str> = Finding::ALL.iter().map(|f| f.name()).collect();
                return Err(bad(
                    n,
                    format!(
                        "unknown finding '{}' (expected {}, wrong or *)",
                        echo(finding),
                        names.join(", ")
                    ),
                ));
            }
            entries.push(ExpectedEntry {
                id: id.to_string(),
                finding: finding.to_string(),
                line: n,
            });
        }
        Ok(KnownFindings { entries })
    }

    /// The first entry that allows `finding` (a diagnosis name, or `wrong`) on the row `id`.
    pub fn allowing(&self, id: &str, finding: &str) -> Option<usize> {
        self.entries
            .iter()
            .position(|e| (e.finding == "*" || e.finding == finding) && matches(&e.id, id))
    }

    /// Checks one row: its label, its findings' names and whether a claim is wrong. Returns
    /// the entries used and the findings no entry allows (`wrong` for wrong claims that no
    /// entry allows and no finding of the row explains).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::KnownFindings;
    /// let e = KnownFindings::parse("b.csv", "id,finding\nend,energy-loss\n")?;
    /// // The expected finding also explains the row's wrong claims.
    /// assert_eq!(e.check("end", &["energy-loss"], true), (vec![0], vec![]));
    /// assert_eq!(e.check("end", &["energy-loss", "momentum"], true), (vec![0], vec!["momentum"]));
    /// assert_eq!(e.check("mid", &[], true), (vec![], vec!["wrong"]));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn check<'a>(
        &self,
        id: &str,
        findings: &[&'a str],
        wrong: bool,
    ) -> (Vec<usize>, Vec<&'a str>) {
        let mut used = Vec::new();
        let mut unexpected = Vec::new();
        for &name in findings {
            match self.allowing(id, name) {
                Some(k) => used.push(k),
                None => unexpected.push(name),
            }
        }
        if wrong {
            match self.allowing(id, "wrong") {
                Some(k) => used.push(k),
                None if findings.is_empty() => unexpected.push("wrong"),
                None => {}
            }
        }
        used.sort_unstable();
        used.dedup();
        (used, unexpected)
    }
}

/// The comma-separated cells of a line, trimmed.
fn cells(line: &str) -> Vec<&str> {
    line.split(',').map(str::trim).collect()
}

/// `text` matches `pattern`, in which `*` stands for any text (also none).
pub(super) fn matches(pattern: &str, text: &str) -> bool {
    let parts: Vec<&str> = pattern.split('*').collect();
    if parts.len() == 1 {
        return pattern == text;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !text.starts_with(first) || text.len() < first.len() + last.len() || !text.ends_with(last) {
        return false;
    }
    let mut rest = &text[first.len()..text.len() - last.len()];
    for part in &parts[1..parts.len() - 1] {
        match rest.find(part) {
            Some(at) => rest = &rest[at + part.len()..],
            None => return false,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patterns_match_classes_of_ids() {
        for (pattern, text, expected) in [
            ("free-end-3", "free-end-3", true),
            ("free-end-3", "free-end-30", false),
            ("free-end-*", "free-end-30", true),
            ("free-end-*", "free-end-", true),
            ("*-1/2", "pivot-at-impact-1/2", true),
            ("*", "", true),
            ("pivot-*-1/2", "pivot-at-impact-1/2", true),
            ("pivot-*-1/2", "pivot-1/2", false),
            ("a*b*c", "abc", true),
            ("a*b*c", "acb", false),
        ] {
            assert_eq!(matches(pattern, text), expected, "{pattern} {text}");
        }
    }

    #[test]
    fn bad_files_name_the_line() {
        for (text, expected) in [
            ("", "expect: b.csv line 1: no header 'id,finding'"),
            (
                "# only a comment\n",
                "expect: b.csv line 1: no header 'id,finding'",
            ),
            (
                "id,diagnosis\n",
                "expect: b.csv line 1: the header is 'id,diagnosis', expected 'id,finding'",
            ),
            (
                "id,finding\n\nend\n",
                "expect: b.csv line 3: expected two cells 'id,finding', got 'end'",
            ),
            (
                "id,finding\n,off\n",
                "expect: b.csv line 2: the id is empty (write * for every row)",
            ),
        ] {
            assert_eq!(
                KnownFindings::parse("b.csv", text).unwrap_err().to_string(),
                expected
            );
        }
        let big = format!("id,finding\n{}", "a,off\n".repeat(200_000));
        assert!(
            KnownFindings::parse("b.csv", &big)
                .unwrap_err()
                .to_string()
                .contains("larger than 1048576 bytes (limit)")
        );
    }

    #[test]
    fn comments_after_a_line_are_dropped() {
        let e = KnownFindings::parse("b.csv", "id,finding\nend,off   # known since 2.3\n").unwrap();
        assert_eq!(e.entries[0].finding, "off");
        assert_eq!(e.entries[0].line, 2);
    }
}
