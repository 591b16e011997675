//! The one error type of the library: which input field was wrong, and why.
//!
//! Every user-facing failure (a number that does not parse, a mass that is not positive, an impact
//! point off the rod) is an [`Error`] carrying the name of the offending field and an [`ErrorKind`].
//! Its `Display` is the one-line message the command-line tool prints before exiting with code 2.

use thiserror::Error as ThisError;

/// Why an input was refused.
#[derive(Debug, Clone, PartialEq, Eq, ThisError)]
pub enum ErrorKind {
    /// Nothing was given where a number was expected.
    #[error("empty number")]
    Empty,
    /// A required input was not given at all.
    #[error("required, but not given")]
    Missing,
    /// The text is not a number of any accepted form; the string says what was found.
    #[error("not a number: {0}")]
    Malformed(String),
    /// NaN or an infinity was given: only finite exact numbers are accepted.
    #[error("{0} is not a finite number")]
    NotFinite(String),
    /// A fraction with a zero denominator, such as `1/0`.
    #[error("division by zero")]
    DivisionByZero,
    /// The number has more digits than the resource limit allows.
    #[error("more than {limit} digits (limit on digits per number)")]
    TooManyDigits {
        /// The limit that was exceeded.
        limit: usize,
    },
    /// The decimal exponent is outside the resource limit.
    #[error("exponent beyond +-{limit} (limit on |exponent|)")]
    ExponentTooLarge {
        /// The limit that was exceeded.
        limit: u64,
    },
    /// The value breaks a physical constraint; the string states the constraint and the value.
    #[error("{0}")]
    OutOfRange(String),
    /// The value is not one of the accepted forms; the string lists them.
    #[error("{0}")]
    Invalid(String),
    /// A file could not be read or written; the string says which and why.
    #[error("{0}")]
    Io(String),
    /// Two inputs contradict each other (for example `--a` together with `--from-end`).
    #[error("{0}")]
    Conflict(String),
}

/// An input error: the field it concerns (`m`, `M`, `a`, `rod`, ...) and the reason.
///
/// Displayed as `field: reason` on one line: whatever control character the field or the
/// reason still holds (a newline, ESC, CR, NUL from the input) is escaped
/// ([`crate::echo::one_line`]), so the message is one line and inert in a terminal.
///
/// # Examples
/// ```
/// use rodimpact::{Error, ErrorKind};
/// let err = Error::new("m", ErrorKind::DivisionByZero);
/// assert_eq!(err.to_string(), "m: division by zero");
/// let raw = Error::new("id", ErrorKind::Invalid("unknown claim 'C1\nC2'".into()));
/// assert_eq!(raw.to_string(), "id: unknown claim 'C1\\nC2'");
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    /// The input field the error concerns, as the user wrote it (`m`, `M`, `l`, `a`, ...).
    pub field: String,
    /// What is wrong with it.
    pub kind: ErrorKind,
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let message = format!("{}: {}", self.field, self.kind);
        f.write_str(&crate::echo::one_line(&message))
    }
}

impl std::error::Error for Error {}

impl Error {
    /// An error about `field` of the given kind.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{Error, ErrorKind};
    /// let err = Error::new("e", ErrorKind::OutOfRange("must lie in [0, 1], got 2".into()));
    /// assert_eq!(err.to_string(), "e: must lie in [0, 1], got 2");
    /// ```
    pub fn new(field: impl Into<String>, kind: ErrorKind) -> Self {
        Error {
            field: field.into(),
            kind,
        }
    }

    /// An out-of-range error about `field` with the given explanation.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::Error;
    /// assert_eq!(Error::out_of_range("M", "must be > 0, got -1").to_string(), "M: must be > 0, got -1");
    /// ```
    pub fn out_of_range(field: impl Into<String>, why: impl Into<String>) -> Self {
        Error::new(field, ErrorKind::OutOfRange(why.into()))
    }
}
