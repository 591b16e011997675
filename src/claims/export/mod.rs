//! The claims exported for independent checkers: each claim's own statement
//! ([`Entry::export`]) written as an SMT-LIB 2 file for z3 and as a SymPy script, with an index
//! saying which claims are not exported and why (`rodimpact prove --export smt2|sympy DIR`).
//!
//! A statement's hypotheses are the physics of the scene (the balance equations and the contact
//! law in fresh unknowns `v`, `V`, `omega`, and the domain), never rodimpact's solution; the
//! conclusion is the claim. So a checker that confirms a file confirms the claim from the
//! physics alone.

mod expr;
mod physics;
mod smt2;
mod statement;
mod sympy;

pub use expr::{Expr, ParseError, Prop, parse};
pub use physics::{Hypothesis, hypotheses, unknowns};
pub use statement::{
    AT_A, BalanceForm, Check, Expect, Export, ExportLaw, Friction, ObliqueSetting, Rod, Setting,
    Statement, StrikePoint,
};
pub use sympy::supported as sympy_supported;

use super::Entry;

/// The export formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExportFormat {
    /// SMT-LIB 2 (QF_NRA), for z3.
    Smt2,
    /// A Python script using SymPy.
    Sympy,
}

impl ExportFormat {
    /// `smt2` or `sympy`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::export::ExportFormat;
    /// assert_eq!(ExportFormat::parse("sympy"), Some(ExportFormat::Sympy));
    /// assert_eq!(ExportFormat::Smt2.name(), "smt2");
    /// assert_eq!(ExportFormat::parse("coq"), None);
    /// ```
    pub fn parse(text: &str) -> Option<ExportFormat> {
        match text {
            "smt2" => Some(ExportFormat::Smt2),
            "sympy" => Some(ExportFormat::Sympy),
            _ => None,
        }
    }

    /// The format's name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            ExportFormat::Smt2 => "smt2",
            ExportFormat::Sympy => "sympy",
        }
    }
}

/// One exported file: its name and contents.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Exported {
    /// The file name (`C15.smt2`, `C15.py`).
    pub name: String,
    /// The contents.
    pub text: String,
}

/// The first lines of every exported file: the claim, as `docs/claims.md` lists it, and the
/// part left out, if any.
fn header(entry: &Entry, statement: &Statement, comment: &str) -> String {
    let mut out = format!(
        "{comment}rodimpact prove --export: claim {} ({})\n{comment}{}\n",
        entry.id, entry.location, entry.statement
    );
    if !statement.outside.is_empty() {
        out.push_str(&format!(
            "{comment}Not stated here: {}\n",
            statement.outside
        ));
    }
    out
}

/// Why a claim is not exported in `format`, or `None` when it is.
///
/// # Examples
/// ```
/// use rodimpact::claims::{export::{ExportFormat, not_exported}, find};
/// assert_eq!(not_exported(find("C15").unwrap(), ExportFormat::Smt2), None);
/// assert!(not_exported(find("X26").unwrap(), ExportFormat::Smt2).is_some());
/// ```
pub fn not_exported(entry: &Entry, format: ExportFormat) -> Option<&'static str> {
    match (&entry.export, format) {
        (Export::Unstated(why), _) => Some(why),
        (Export::Stated(_), ExportFormat::Smt2) => None,
        (Export::Stated(s), ExportFormat::Sympy) => (!sympy_supported(s).contains(&true)).then_some(
            "only inequalities over a domain (no identity, no check at given values): z3 decides them, see smt2/",
        ),
    }
}

/// The claim's file in `format`, or `None` when it is not exported (see [`not_exported`]).
///
/// # Examples
/// ```
/// use rodimpact::claims::{export::{ExportFormat, export}, find};
/// let file = export(find("C15").unwrap(), ExportFormat::Smt2).unwrap();
/// assert_eq!(file.name, "C15.smt2");
/// assert!(file.text.contains("(check-sat-using qfnra)") && file.text.ends_with("; expect: sat unsat\n"));
/// ```
pub fn export(entry: &Entry, format: ExportFormat) -> Option<Exported> {
    if not_exported(entry, format).is_some() {
        return None;
    }
    let Export::Stated(statement) = &entry.export else {
        return None;
    };
    Some(match format {
        ExportFormat::Smt2 => smt2::write(entry, statement),
        ExportFormat::Sympy => sympy::write(entry, statement),
    })
}

/// Every exported file of `entries` in `format`, and the index `README.md` (which lists the
/// claims not exported, with why).
///
/// # Examples
/// ```
/// use rodimpact::claims::{export::{ExportFormat, export_all}, registry};
/// let files = export_all(registry(), ExportFormat::Smt2);
/// assert!(files.iter().any(|f| f.name == "README.md"));
/// assert!(files.iter().any(|f| f.name == "C1.smt2"));
/// ```
pub fn export_all(entries: &[Entry], format: ExportFormat) -> Vec<Exported> {
    let mut files: Vec<Exported> = entries.iter().filter_map(|e| export(e, format)).collect();
    files.push(Exported {
        name: "README.md".into(),
        text: index(entries, format),
    });
    files
}

fn index(entries: &[Entry], format: ExportFormat) -> String {
    let exported = entries
        .iter()
        .filter(|e| not_exported(e, format).is_none())
        .count();
    let (checker, run, extension) = match format {
        ExportFormat::Smt2 => (
            "z3",
            "`z3 FILE` prints one answer per `(check-sat-using qfnra)` (z3's strategy for \
             nonlinear real arithmetic, ending in its complete procedure nlsat); the last line of each file, \
             `; expect: ...`, says which answers are meant (`unsat`: the claim holds; `sat`: a \
             reading meant to fail, or a witness, with its model).",
            "smt2",
        ),
        ExportFormat::Sympy => (
            "SymPy",
            "`python3 FILE` exits with status 0 when every check is confirmed.",
            "py",
        ),
    };
    let mut out = format!(
        "# The claims for {checker}\n\n\
         Written by `rodimpact prove --export {} DIR` from each claim's own statement. The \
         hypotheses are the physics (the balance equations and the contact law in fresh unknowns \
         `v`, `V`, `omega`, and the domain), never rodimpact's solution; the conclusion is the \
         claim. {run}\n\n{exported} of {} claims exported.\n\n| id | file | claim |\n|---|---|---|\n",
        format.name(),
        entries.len()
    );
    for e in entries {
        let file = match not_exported(e, format) {
            None => {
                let mut cell = format!("[{0}.{extension}]({0}.{extension})", e.id);
                if let Export::Stated(s) = &e.export {
                    let decided = sympy_supported(s);
                    let n = decided.iter().filter(|d| **d).count();
                    if format == ExportFormat::Sympy && n < decided.len() {
                        cell.push_str(&format!(
                            " ({n} of {} checks; the others, inequalities over a domain, are z3's)",
                            decided.len()
                        ));
                    }
                    if !s.outside.is_empty() {
                        cell.push_str(&format!("; not stated: {}", s.outside));
                    }
                }
                cell
            }
            Some(why) => format!("not exported: {why}"),
        };
        out.push_str(&format!(
            "| {} | {} | {} |\n",
            e.id,
            file,
            e.statement.replace('|', "\\|")
        ));
    }
    out
}
