//! Problem collections: TOML files of published problems and their printed answers.
//!
//! ```toml
//! [[problem]]
//! id = "disc-and-stick"
//! source = "book, edition, chapter, problem number, or the page address"
//! sig = 3                      # optional: overrides the printed significant figures
//! [problem.given]
//! m = "2.0 kg"                 # numbers are strings, so "2.0" keeps its figures
//! M = "1.0 kg"
//! length = "4.0 m"             # or l (half-length)
//! from_end = "0 m"             # or a (from the centre)
//! v0 = "3.0 m/s"
//! rod = "uniform"              # dumbbell, rg=..., I=...
//! collision = "elastic"        # inelastic / sticking, or e = "0.5"
//! pivot = "-2.0 m"             # optional, signed from the centre
//! v0t = "1.0 m/s"              # optional oblique scene: velocity along the rod, friction mu,
//! mu = "0.3"                   #   a disc projectile (radius, spin) and the rod's motion
//!                              #   before the impact (rod_v, rod_vt, rod_omega)
//! [problem.claims]
//! v = "2.3 m/s"
//! ```
//! Unknown keys are errors naming the key.

use super::expr::Budget;
use super::{ClaimedAnswer, Quantity, SceneCheck, check_scene_within};
use crate::error::{Error, ErrorKind};
use crate::scene::SceneInput;
use serde::Deserialize;

/// The largest accepted problem file, in bytes.
pub const MAX_FILE_BYTES: usize = 1 << 20;
/// The most problems in one file.
pub const MAX_PROBLEMS: usize = 1_000;
/// The most claims in one problem (or on one command line).
pub const MAX_CLAIMS: usize = 100;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileDoc {
    problem: Vec<ProblemDoc>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ProblemDoc {
    id: String,
    source: String,
    #[serde(default)]
    statement: Option<String>,
    #[serde(default)]
    note: Option<String>,
    #[serde(default)]
    sig: Option<u32>,
    given: GivenDoc,
    claims: toml::Table,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GivenDoc {
    m: Option<String>,
    #[serde(rename = "M")]
    rod_mass: Option<String>,
    l: Option<String>,
    length: Option<String>,
    a: Option<String>,
    from_end: Option<String>,
    v0: Option<String>,
    rod: Option<String>,
    e: Option<String>,
    collision: Option<String>,
    pivot: Option<String>,
    v0t: Option<String>,
    mu: Option<String>,
    radius: Option<String>,
    spin: Option<String>,
    rod_v: Option<String>,
    rod_vt: Option<String>,
    rod_omega: Option<String>,
}

/// One published problem: where it is from, its scene, its printed answers.
#[derive(Debug, Clone)]
pub struct Problem {
    /// Short id.
    pub id: String,
    /// Citation.
    pub source: String,
    /// The problem in a sentence, as the source states it.
    pub statement: Option<String>,
    /// Remarks kept with the problem (what the book did, why an answer is wrong).
    pub note: Option<String>,
    /// Significant figures to use instead of the printed ones.
    pub sig: Option<u32>,
    /// The scene as given.
    pub scene: SceneInput,
    /// The printed answers as written, `(name, value)`: names are checked when the file is
    /// read, values when the problem is checked (so that only one problem's formulas are in
    /// memory at a time, and their work is charged to the run's budget).
    pub claims: Vec<(String, String)>,
}

/// Parses a problem file; `label` (the path) starts every error message. Claimed values are
/// read by [`check_problems`].
///
/// # Errors
/// TOML syntax, unknown keys, wrong value types (with line and key), an unknown claim name,
/// or a limit.
///
/// # Examples
/// ```
/// use rodimpact::textbook::problems::parse_problems;
/// let text = r#"
/// [[problem]]
/// id = "p1"
/// source = "test"
/// [problem.given]
/// m = "1"
/// M = "1"
/// [problem.claims]
/// omega = "6/5"
/// "#;
/// assert_eq!(parse_problems("t.toml", text).unwrap()[0].claims.len(), 1);
/// let bad = text.replace("source", "sorce");
/// let err = parse_problems("t.toml", &bad).unwrap_err().to_string();
/// assert!(err.starts_with("t.toml: line 4: unknown field `sorce`"), "{err}");
/// ```
pub fn parse_problems(label: &str, text: &str) -> Result<Vec<Problem>, Error> {
    if text.len() > MAX_FILE_BYTES {
        return Err(Error::out_of_range(
            label,
            format!("file larger than {MAX_FILE_BYTES} bytes (limit)"),
        ));
    }
    let doc: FileDoc = toml::from_str(text).map_err(|e| {
        let line = e.span().map(|s| {
            format!(
                "line {}: ",
                text.get(..s.start).unwrap_or(text).matches('\n').count() + 1
            )
        });
        let message = e
            .message()
            .lines()
            .next()
            .unwrap_or("invalid TOML")
            .to_string();
        Error::new(
            label,
            ErrorKind::Invalid(format!("{}{message}", line.unwrap_or_default())),
        )
    })?;
    if doc.problem.len() > MAX_PROBLEMS {
        return Err(Error::out_of_range(
            label,
            format!("more than {MAX_PROBLEMS} problems (limit)"),
        ));
    }
    let mut ids = std::collections::HashSet::new();
    if let Some(twice) = doc.problem.iter().find(|p| !ids.insert(p.id.as_str())) {
        return Err(Error::new(
            format!("{label}: problem '{}'", crate::echo::echo(&twice.id)),
            ErrorKind::Conflict("the id is used by two problems".into()),
        ));
    }
    doc.problem.into_iter().map(|p| problem(label, p)).collect()
}

fn problem(label: &str, p: ProblemDoc) -> Result<Problem, Error> {
    let id = p.id;
    let at = |field: &str| format!("{label}: problem '{}': {field}", crate::echo::echo(&id));
    let wrap = |e: Error| Error::new(at(&e.field), e.kind);
    let texts = [("id", Some(&id)), ("source", Some(&p.source))];
    let notes = [
        ("statement", p.statement.as_ref()),
        ("note", p.note.as_ref()),
    ];
    for (field, text) in texts.into_iter().chain(notes) {
        if let Some(c) = text.and_then(|t| t.chars().find(|&c| c.is_control() && c != '\t')) {
            return Err(Error::new(
                at(field),
                ErrorKind::Invalid(format!(
                    "control character '{}' (it would reach the report raw; write the text on one line)",
                    c.escape_debug()
                )),
            ));
        }
    }
    if let Some(n) = p.sig {
        super::sigfig::check_sig(n).map_err(wrap)?;
    }
    let g = p.given;
    let e = match (g.e, g.collision.as_deref()) {
        (Some(_), Some(_)) => {
            return Err(Error::new(
                at("given.collision"),
                ErrorKind::Conflict("give either e or collision, not both".into()),
            ));
        }
        (e, None) => e,
        (None, Some("elastic")) => Some("1".into()),
        (None, Some("inelastic" | "sticking")) => Some("0".into()),
        (None, Some(other)) => {
            return Err(Error::new(
                at("given.collision"),
                ErrorKind::Invalid(format!(
                    "expected elastic, inelastic or sticking, got '{}'",
                    crate::echo::echo(other)
                )),
            ));
        }
    };
    let scene = SceneInput {
        m: g.m,
        rod_mass: g.rod_mass,
        l: g.l,
        length: g.length,
        a: g.a,
        from_end: g.from_end,
        v0: g.v0,
        rod: g.rod,
        e,
        pivot: g.pivot,
        v0t: g.v0t,
        mu: g.mu,
        radius: g.radius,
        spin: g.spin,
        rod_v: g.rod_v,
        rod_vt: g.rod_vt,
        rod_omega: g.rod_omega,
    };
    if p.claims.is_empty() || p.claims.len() > MAX_CLAIMS {
        return Err(Error::out_of_range(
            at("claims"),
            format!("give 1 to {MAX_CLAIMS} claims"),
        ));
    }
    let mut claims = Vec::with_capacity(p.claims.len());
    for (name, value) in &p.claims {
        let Some(text) = value.as_str() else {
            return Err(Error::new(
                at(&format!("claims.{}", crate::echo::echo(name))),
                ErrorKind::Invalid(
                    "write the value as a string (\"1.50\"), so its significant figures survive"
                        .into(),
                ),
            ));
        };
        if Quantity::parse(name).is_none() {
            return Err(Error::new(
                at(&format!("claims.{}", crate::echo::echo(name))),
                ErrorKind::Invalid(format!(
                    "unknown name '{}' (accepted: {})",
                    crate::echo::echo(name),
                    Quantity::all_names()
                )),
            ));
        }
        claims.push((name.clone(), text.to_string()));
    }
    Ok(Problem {
        id,
        source: p.source,
        statement: p.statement,
        note: p.note,
        sig: p.sig,
        scene,
        claims,
    })
}

/// One problem's claimed answers, checked.
#[derive(Debug, Clone)]
pub struct ProblemCheck {
    /// The problem's id.
    pub id: String,
    /// Its citation.
    pub source: String,
    /// Its remark, if any.
    pub note: Option<String>,
    /// Its claimed answers, checked.
    pub check: SceneCheck,
}

/// The text of the problem file at `path` (named `label` in errors), read no further than
/// [`MAX_FILE_BYTES`] (a huge or endless file is refused without being read into memory);
/// bytes that are not UTF-8 are named by line.
///
/// # Errors
/// `LABEL: cannot read: ...`, `LABEL: file larger than ... (limit)`, `LABEL: line N: not
/// valid UTF-8`.
///
/// # Examples
/// ```
/// use rodimpact::textbook::problems::read_problem_file;
/// let text = read_problem_file("textbook.toml", "examples/textbook.toml".as_ref())?;
/// assert!(text.contains("[[problem]]"));
/// let missing = read_problem_file("none.toml", "no/such/file.toml".as_ref()).unwrap_err();
/// assert!(missing.to_string().starts_with("none.toml: cannot read: "));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn read_problem_file(label: &str, path: &std::path::Path) -> Result<String, Error> {
    use std::io::Read;
    let io = |e: std::io::Error| Error::io(label, "cannot read", e);
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES as u64 + 1).read_to_end(&mut bytes))
        .map_err(io)?;
    if bytes.len() > MAX_FILE_BYTES {
        return Err(Error::out_of_range(
            label,
            format!("file larger than {MAX_FILE_BYTES} bytes (limit)"),
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
        Error::new(
            label,
            ErrorKind::Invalid(format!("line {line}: not valid UTF-8")),
        )
    })
}

/// Checks every problem, one at a time (its claims read, decided and dropped before the next
/// problem's); `sig` (if given) overrides each problem's figures. The work of every formula
/// of the file is charged to one budget ([`super::expr::MAX_RUN_WORK`]).
///
/// # Errors
/// The first problem whose scene or claims are bad input, or that exhausts the budget, naming
/// the problem and field.
///
/// # Examples
/// ```
/// use rodimpact::textbook::problems::{parse_problems, check_problems};
/// let text = "[[problem]]\nid = \"p\"\nsource = \"s\"\n[problem.given]\nm = \"1\"\nM = \"1\"\n[problem.claims]\nomega = \"6/5\"\n";
/// let checks = check_problems("t.toml", &parse_problems("t.toml", text).unwrap(), None).unwrap();
/// assert!(checks[0].check.all_agree());
/// ```
pub fn check_problems(
    label: &str,
    problems: &[Problem],
    sig: Option<u32>,
) -> Result<Vec<ProblemCheck>, Error> {
    let mut budget = Budget::run();
    problems
        .iter()
        .map(|p| {
            let at =
                |field: &str| format!("{label}: problem '{}': {field}", crate::echo::echo(&p.id));
            let claims = p
                .claims
                .iter()
                .map(|(name, text)| {
                    ClaimedAnswer::new_within(name, text, &mut budget).map_err(|e| {
                        Error::new(at(&format!("claims.{}", crate::echo::echo(name))), e.kind)
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            let check = check_scene_within(&p.scene, &claims, sig.or(p.sig), &mut budget)
                .map_err(|e| Error::new(at(&e.field), e.kind))?;
            Ok(ProblemCheck {
                id: p.id.clone(),
                source: p.source.clone(),
                note: p.note.clone(),
                check,
            })
        })
        .collect()
}
