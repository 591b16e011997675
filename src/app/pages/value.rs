//! An exact number as the pages receive it: its spellings and a float for drawing.

use crate::field::notation::{Notation, surd};
use crate::field::{Field, QSqrt};
use serde_json::{Value, json};

/// `x` for a page: `text` (rodimpact's ASCII, as `solve --json` writes it), `pretty` (Unicode,
/// with a true minus sign), `decimal` (6 significant digits) and `approx` (4), and `f64`, the
/// nearest float, for drawing only.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, QSqrt};
/// let x = rodimpact::app::pages::exact(&(QSqrt::sqrt_of(&q(2, 3)) * &QSqrt::rational(q(-1, 1))));
/// assert_eq!(x["text"], "-sqrt(6)/3");
/// assert_eq!(x["pretty"], "−√6/3");
/// assert_eq!((x["decimal"].as_str(), x["approx"].as_str()), (Some("−0.816497"), Some("−0.8165")));
/// assert_eq!(x["f64"], -0.816496580927726);
/// ```
pub fn exact(x: &QSqrt) -> Value {
    let minus = |s: String| s.replace('-', "−");
    json!({
        "text": surd(x, Notation::Ascii),
        "pretty": minus(surd(x, Notation::Unicode)),
        "decimal": minus(x.decimal(6)),
        "approx": minus(x.decimal(4)),
        "f64": x.nearest_f64(),
    })
}
