//! `rodimpact impact --batch FILE.jsonl` and Python's `audit_impacts()`: many scenes, each with
//! an engine's claimed state, audited line by line ([`crate::batch::audit_impact`]), and the
//! summary a CI job reads: the answers the claims match and are closest to, the findings by
//! scene, and, with a file of known findings (`--expect`), whether every finding is known.

use crate::batch::{
    Agreement, EngineChoice, FloatFormat, ImpactAudit, ImpactBatchSummary, ImpactTolerance,
    KnownFindings, MAX_EXPECTED_BYTES, audit_impact,
};
use crate::error::Error;
use crate::model::MAX_SCENE_BYTES;
use std::io::{BufRead, Read};
use std::path::Path;

/// How the lines are audited.
#[derive(Debug, Clone, Default)]
pub struct ImpactBatchOptions {
    /// When a claim matches an exact answer.
    pub tolerance: ImpactTolerance,
    /// Which engine steps each line is compared with.
    pub engines: EngineChoice,
    /// The known findings (`--expect`): the audit fails only on the others.
    pub expected: Option<KnownFindings>,
}

impl ImpactBatchOptions {
    /// The options as given, each number still text (the command line's flags, Python's
    /// keywords): `rtol` and `atol` numbers from 0 to 1 read exactly, `ulps` a whole number
    /// of floats in `float` (f64 by default), `engine` a profile's name or `all` (`None`: the
    /// engine each line's claim names), `expected` the known findings.
    ///
    /// # Errors
    /// The option that is wrong, by name: `rtol: must be a number from 0 to 1, got -1`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::app::impact_batch::ImpactBatchOptions;
    /// use rodimpact::batch::EngineChoice;
    /// use rodimpact::field::q;
    /// let options = ImpactBatchOptions::parse(Some("1e-2"), None, None, None, Some("all"), None)?;
    /// assert_eq!(options.tolerance.rtol, q(1, 100));
    /// assert!(matches!(options.engines, EngineChoice::Every));
    /// let bad = ImpactBatchOptions::parse(Some("-1"), None, None, None, None, None);
    /// assert_eq!(bad.unwrap_err().to_string(), "rtol: must be a number from 0 to 1, got -1");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn parse(
        rtol: Option<&str>,
        atol: Option<&str>,
        ulps: Option<&str>,
        float: Option<FloatFormat>,
        engine: Option<&str>,
        expected: Option<KnownFindings>,
    ) -> Result<ImpactBatchOptions, Error> {
        let mut tolerance = ImpactTolerance::default();
        if let Some(text) = rtol {
            tolerance.rtol = crate::batch::unit_fraction("rtol", text)?;
        }
        if let Some(text) = atol {
            tolerance.atol = Some(crate::batch::unit_fraction("atol", text)?);
        }
        if let Some(text) = ulps {
            let format = float.unwrap_or(FloatFormat::F64);
            if let Agreement::Ulps(n, format) = Agreement::parse_ulps(text, format)? {
                tolerance.ulps = Some((n, format));
            }
        }
        let engines = match engine.map(str::trim) {
            None => EngineChoice::FromClaim,
            Some("all") => EngineChoice::Every,
            Some(text) => EngineChoice::This(super::impact::parse_engine(text)?),
        };
        Ok(ImpactBatchOptions {
            tolerance,
            engines,
            expected,
        })
    }
}

/// The known findings in the CSV file at `path` (`id,finding`, `*` for a class of scenes), for
/// `batch --expect` and `impact --batch --expect`; a file larger than [`MAX_EXPECTED_BYTES`]
/// is refused.
///
/// # Errors
/// `expect: cannot read FILE: ...`, or the file's first bad line.
///
/// # Examples
/// ```
/// use rodimpact::app::impact_batch::read_known_findings;
/// let path = std::env::temp_dir().join(format!("known-{}.csv", std::process::id()));
/// std::fs::write(&path, "id,finding\nball-on-column,off\n")?;
/// let known = read_known_findings(&path)?;
/// assert_eq!(known.allowing("ball-on-column", "off"), Some(0));
/// std::fs::remove_file(&path)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn read_known_findings(path: &Path) -> Result<KnownFindings, Error> {
    let name = crate::echo::echo_path(path);
    let mut text = String::new();
    std::fs::File::open(path)
        .and_then(|f| {
            f.take(MAX_EXPECTED_BYTES as u64 + 1)
                .read_to_string(&mut text)
        })
        .map_err(|why| Error::io("expect", format!("cannot read {name}"), why))?;
    KnownFindings::parse(&name, &text)
}

/// Audits every line of `input` (named `label` in errors; blank lines skipped, a line longer
/// than [`MAX_SCENE_BYTES`] refused), handing each audit to `each` in input order, and returns
/// the summary.
///
/// # Errors
/// A line that is bad input (naming the file, the line and the field), or `each`'s error.
///
/// # Examples
/// ```
/// use rodimpact::app::impact_batch::{ImpactBatchOptions, run};
/// let line = r#"{"id": "p", "body": [{"name": "p", "mass": "1", "velocity": ["1", "0"]},
///   {"name": "wall", "fixed": true}], "contact": [{"bodies": ["p", "wall"], "point": ["0", "0"], "normal": ["-1", "0"]}],
///   "claimed": {"bodies": {"p": {"velocity": ["-1", "0"], "omega": "0"}}}}"#;
/// let one_line = line.replace('\n', " ");
/// let summary = run(one_line.as_bytes(), "lines", &ImpactBatchOptions::default(), |_| Ok(()))?;
/// assert_eq!((summary.scenes, summary.claimed), (1, 1));
/// assert!(summary.passed(false));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn run(
    input: impl BufRead,
    label: &str,
    options: &ImpactBatchOptions,
    mut each: impl FnMut(&ImpactAudit) -> Result<(), Error>,
) -> Result<ImpactBatchSummary, Error> {
    let mut reader = input;
    let mut summary = ImpactBatchSummary::default();
    let mut line = String::new();
    let mut number = 0;
    loop {
        line.clear();
        let read = (&mut reader)
            .take(MAX_SCENE_BYTES as u64 + 1)
            .read_line(&mut line)
            .map_err(|e| Error::io(label, "cannot read", e))?;
        if read == 0 {
            break;
        }
        number += 1;
        if line.len() > MAX_SCENE_BYTES {
            return Err(Error::out_of_range(
                format!("{label}: line {number}"),
                format!("longer than {MAX_SCENE_BYTES} bytes (limit)"),
            ));
        }
        if line.trim().is_empty() {
            continue;
        }
        if crate::interrupt::requested() {
            return Err(Error::new(label, crate::error::ErrorKind::Interrupted));
        }
        let audit = audit_impact(
            line.trim_end(),
            number,
            &options.tolerance,
            &options.engines,
        )
        .map_err(|e| Error::new(format!("{label}: {}", e.field), e.kind))?;
        summary.add(&audit, options.expected.as_ref());
        each(&audit)?;
    }
    Ok(summary)
}
