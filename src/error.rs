//! The one error type of the library: which input field was wrong, and why.
//!
//! Every user-facing failure (a number that does not parse, a mass that is not positive, an impact
//! point off the rod) is an [`Error`] carrying the name of the offending field and an [`ErrorKind`].
//! Its `Display` is the one-line message the command-line tool prints before exiting with code 2.

use std::sync::Arc;
use thiserror::Error as ThisError;

/// Why an input was refused.
///
/// Two kinds are equal when they are the same variant with the same message (an I/O error's
/// source is compared by its message).
#[derive(Debug, Clone, ThisError)]
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
    /// A file could not be read or written: what was being done (`cannot read FILE`; may be
    /// empty), and the I/O error that stopped it.
    #[error("{}", io_message(context, source))]
    Io {
        /// What was being done, naming the file.
        context: String,
        /// The error the operating system reported (shared, so the kind stays `Clone`).
        #[source]
        source: Arc<std::io::Error>,
    },
    /// Two inputs contradict each other (for example `--a` together with `--from-end`).
    #[error("{0}")]
    Conflict(String),
    /// The host asked the work to stop ([`crate::interrupt`]): Python's Ctrl-C.
    #[error("interrupted")]
    Interrupted,
}

/// `context: source`, or only the source when there is no context.
fn io_message(context: &str, source: &std::io::Error) -> String {
    if context.is_empty() {
        source.to_string()
    } else {
        format!("{context}: {source}")
    }
}

impl PartialEq for ErrorKind {
    fn eq(&self, other: &Self) -> bool {
        std::mem::discriminant(self) == std::mem::discriminant(other)
            && self.to_string() == other.to_string()
    }
}

impl Eq for ErrorKind {}

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

impl std::error::Error for Error {
    /// The operating system's error of an [`ErrorKind::Io`]; none for the other kinds, whose
    /// message is the whole story.
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ErrorKind::Io { source, .. } => Some(source.as_ref()),
            _ => None,
        }
    }
}

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

    /// An I/O error about `field`: `context` says what was being done (`cannot read FILE`),
    /// `source` is the operating system's error, kept as the error's
    /// [`source`](std::error::Error::source).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::Error;
    /// use std::error::Error as _;
    /// let why = std::io::Error::new(std::io::ErrorKind::NotFound, "No such file or directory");
    /// let err = Error::io("FILE", "cannot read data.csv", why);
    /// assert_eq!(err.to_string(), "FILE: cannot read data.csv: No such file or directory");
    /// let source = err.source().unwrap().downcast_ref::<std::io::Error>().unwrap();
    /// assert_eq!(source.kind(), std::io::ErrorKind::NotFound);
    /// ```
    pub fn io(
        field: impl Into<String>,
        context: impl Into<String>,
        source: std::io::Error,
    ) -> Self {
        // An operating-system error is told as the system tells it: a wrapper's own context
        // (tempfile names its random temporary, "at path .../.x.csv.UWHvpdus.tmp") is dropped,
        // since `context` already names the file the user gave.
        let wrapped = source.get_ref().map(|inner| inner.to_string());
        let source = match (source.raw_os_error(), wrapped) {
            (Some(code), _) => std::io::Error::from_raw_os_error(code),
            // tempfile's own wrapper of the system's error, "... at path \"<temporary>\"".
            (None, Some(text)) if text.contains(" at path \"") => {
                let told = text
                    .split(" at path \"")
                    .next()
                    .unwrap_or_default()
                    .to_owned();
                std::io::Error::new(source.kind(), told)
            }
            (None, _) => source,
        };
        Error::new(
            field,
            ErrorKind::Io {
                context: context.into(),
                source: Arc::new(source),
            },
        )
    }
}
