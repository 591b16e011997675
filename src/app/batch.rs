//! The options of a batch audit (`rodimpact batch` and Python's `audit()`), read once for
//! both: the arithmetic, when a claim agrees (`rtol`, `ulps` in a float format, `atol`, the
//! per-class tolerances) and the batch they make for a file's header.

use crate::batch::{Agreement, Arithmetic, Batch, ClassRule, FloatFormat};
use crate::error::{Error, ErrorKind};

/// How the options are spelt where they were given, for the messages that name them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Spelling {
    /// The command line's flags (`--ulps N`).
    #[default]
    Flags,
    /// Python's keyword arguments (`ulps=`).
    Keywords,
}

/// A batch's options as given, each number still text (read by the batch's own parsers).
///
/// # Examples
/// ```
/// use rodimpact::app::batch::BatchOptions;
/// let options = BatchOptions { rtol: Some("1e-6".into()), ..Default::default() };
/// let checked = options.checked()?;
/// let batch = options.batch("m,M,v,V,omega", &checked)?;
/// assert!(batch.output_header().contains("v_rel_error"));
/// let both = BatchOptions { rtol: Some("1e-6".into()), ulps: Some("4".into()), ..Default::default() };
/// assert_eq!(both.checked().unwrap_err().to_string(), "rtol: give either rtol or ulps, not both");
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, Default)]
pub struct BatchOptions {
    /// Exact rationals, or the paper's closed form in f64.
    pub arithmetic: Arithmetic,
    /// The float format of an ulps count (`None`: f64).
    pub float: Option<FloatFormat>,
    /// A claim agrees within this relative error.
    pub rtol: Option<String>,
    /// A claim agrees within this many floats of the correctly rounded exact value.
    pub ulps: Option<String>,
    /// A claim also agrees within this absolute error in the scene's own units.
    pub atol: Option<String>,
    /// Per-class tolerances, `CLASS=RULE`, the first that takes a row wins.
    pub tolerance: Vec<String>,
    /// How the options were spelt.
    pub spelling: Spelling,
}

/// The options read before any row: the agreement rule and the class rules.
#[derive(Debug, Clone)]
pub struct CheckedOptions {
    /// The rule of `rtol` or `ulps`, if given.
    pub agreement: Option<Agreement>,
    /// The rules of `tolerance`, in order.
    pub rules: Vec<ClassRule>,
}

impl BatchOptions {
    /// The arithmetic named `exact` or `f64` (`backend`).
    ///
    /// # Errors
    /// `backend: expected exact or f64, got '...'`.
    pub fn arithmetic_of(text: Option<&str>) -> Result<Arithmetic, Error> {
        match text.map(str::trim) {
            None | Some("exact") => Ok(Arithmetic::Exact),
            Some("f64") => Ok(Arithmetic::F64),
            Some(other) => Err(Error::new(
                "backend",
                ErrorKind::Invalid(format!(
                    "expected exact or f64, got '{}'",
                    crate::echo::echo(other)
                )),
            )),
        }
    }

    /// The float format named `f32` or `f64` (`float`).
    ///
    /// # Errors
    /// `float: expected f32 or f64, got '...'`.
    pub fn float_of(text: Option<&str>) -> Result<Option<FloatFormat>, Error> {
        match text.map(str::trim) {
            None => Ok(None),
            Some("f64") => Ok(Some(FloatFormat::F64)),
            Some("f32") => Ok(Some(FloatFormat::F32)),
            Some(other) => Err(Error::new(
                "float",
                ErrorKind::Invalid(format!(
                    "expected f32 or f64, got '{}'",
                    crate::echo::echo(other)
                )),
            )),
        }
    }

    /// The agreement rule and the class rules, checked before the file is opened.
    ///
    /// # Errors
    /// `rtol` and `ulps` both given; a wrong `rtol`, `ulps` or tolerance rule; a float format
    /// that no ulps count reads.
    pub fn checked(&self) -> Result<CheckedOptions, Error> {
        let format = self.float.unwrap_or(FloatFormat::F64);
        let agreement = match (&self.rtol, &self.ulps) {
            (Some(_), Some(_)) => {
                return Err(Error::new(
                    "rtol",
                    ErrorKind::Conflict("give either rtol or ulps, not both".into()),
                ));
            }
            (Some(r), None) => Some(Agreement::parse_rtol(r)?),
            (None, Some(n)) => Some(Agreement::parse_ulps(n, format)?),
            (None, None) => None,
        };
        let rules: Vec<ClassRule> = self
            .tolerance
            .iter()
            .map(|text| ClassRule::parse(text, format))
            .collect::<Result<_, _>>()?;
        let ulps_rule = rules
            .iter()
            .any(|r| matches!(r.agreement, Agreement::Ulps(..)));
        if self.float.is_some() && self.ulps.is_none() && !ulps_rule {
            return Err(match self.spelling {
                Spelling::Flags => Error::new(
                    "float",
                    ErrorKind::Invalid(
                        "the float format of an ulps count: give --ulps N or a --tolerance CLASS=ulps:N"
                            .into(),
                    ),
                ),
                Spelling::Keywords => Error::new(
                    "float",
                    ErrorKind::Conflict("the float format of ulps: give ulps too".into()),
                ),
            });
        }
        Ok(CheckedOptions { agreement, rules })
    }

    /// The batch of a file whose header is `header`, with these options.
    ///
    /// # Errors
    /// The header's errors ([`Batch::new`]), an `atol` or an agreement the header cannot take.
    pub fn batch(&self, header: &str, checked: &CheckedOptions) -> Result<Batch, Error> {
        let batch = Batch::new(header, self.arithmetic)?;
        let batch = match &checked.agreement {
            Some(agreement) => batch.with_agreement(agreement.clone())?,
            None => batch,
        };
        let batch = match &self.atol {
            Some(x) => batch.with_atol(x)?,
            None => batch,
        };
        batch.with_class_rules(checked.rules.clone())
    }
}
