//! How exact numbers are written: one rule for every output, in three notations.
//!
//! A surd `x + y sqrt(d)` ([`QSqrt`]) is already canonical (its `d` a square-free integer, so
//! the square factors are out and no denominator is left under the root); this module decides
//! how it is spelled. The coefficient of the root goes in front and its denominator after:
//! `sqrt(6)/3`, `2*sqrt(6)/5`, `5*sqrt(5)`, `1/2 - sqrt(2)/4`. The same number reads
//!
//! | notation | for | `sqrt(2/3)` | `sqrt(125)` | `sqrt(24/25)` |
//! |---|---|---|---|---|
//! | [`Notation::Ascii`] | JSON, CSV, the command line (parses back with `check`) | `sqrt(6)/3` | `5*sqrt(5)` | `2*sqrt(6)/5` |
//! | [`Notation::Unicode`] | tables and text reports | `√6/3` | `5√5` | `2√6/5` |
//! | [`Notation::Latex`] | LaTeX (math mode) | `\frac{\sqrt{6}}{3}` | `5\sqrt{5}` | `\frac{2\sqrt{6}}{5}` |

use super::{Q, QSqrt};
use num_traits::{One, Signed, Zero};

/// A notation for exact numbers.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, QSqrt, notation::{surd, Notation}};
/// let x = QSqrt::sqrt_of(&q(125, 1));
/// let all: Vec<String> = [Notation::Ascii, Notation::Unicode, Notation::Latex]
///     .into_iter().map(|n| surd(&x, n)).collect();
/// assert_eq!(all, ["5*sqrt(5)", "5√5", r"5\sqrt{5}"]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Notation {
    /// Plain ASCII that the expression parser reads back: `2*sqrt(6)/5`.
    Ascii,
    /// Unicode for people: `2√6/5`.
    Unicode,
    /// LaTeX math (without the `$`): `\frac{2\sqrt{6}}{5}`.
    Latex,
    /// LaTeX math for running text, the fractions slashed: `2\sqrt{6}/5`.
    LatexInline,
}

impl Notation {
    /// `num/den`, or `\frac{num}{den}`.
    fn fraction(self, num: &str, den: &str) -> String {
        match self {
            Notation::Latex => format!("\\frac{{{num}}}{{{den}}}"),
            Notation::Ascii | Notation::Unicode | Notation::LatexInline => {
                format!("{num}/{den}")
            }
        }
    }

    /// `c` times the root of `d`, with `c` a positive integer (1 is left out).
    fn root_term(self, c: &str, d: &str) -> String {
        let c = if c == "1" { "" } else { c };
        match self {
            Notation::Ascii if c.is_empty() => format!("sqrt({d})"),
            Notation::Ascii => format!("{c}*sqrt({d})"),
            Notation::Unicode => format!("{c}√{d}"),
            Notation::Latex | Notation::LatexInline => format!("{c}\\sqrt{{{d}}}"),
        }
    }
}

/// A rational in `notation`: `-3/2`, or `-\frac{3}{2}` in LaTeX.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, notation::{rational, Notation}};
/// assert_eq!(rational(&q(-3, 2), Notation::Unicode), "-3/2");
/// assert_eq!(rational(&q(-3, 2), Notation::Latex), r"-\frac{3}{2}");
/// assert_eq!(rational(&q(4, 1), Notation::Latex), "4");
/// ```
pub fn rational(x: &Q, notation: Notation) -> String {
    let sign = if x.is_negative() { "-" } else { "" };
    format!("{sign}{}", magnitude(x, notation))
}

/// `|x|` in `notation`.
fn magnitude(x: &Q, notation: Notation) -> String {
    let numer = x.numer().abs().to_string();
    if x.denom().is_one() {
        numer
    } else {
        notation.fraction(&numer, &x.denom().to_string())
    }
}

/// A surd in `notation`: the canonical spelling of `x + y sqrt(d)`.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, QSqrt, notation::{surd, Notation}};
/// let a_star = QSqrt::sqrt_of(&q(2, 3));
/// assert_eq!(surd(&a_star, Notation::Ascii), "sqrt(6)/3");
/// assert_eq!(surd(&a_star, Notation::Unicode), "√6/3");
/// assert_eq!(surd(&a_star, Notation::Latex), r"\frac{\sqrt{6}}{3}");
/// assert_eq!(surd(&a_star, Notation::LatexInline), r"\sqrt{6}/3");
/// assert_eq!(surd(&QSqrt::sqrt_of(&q(125, 1)), Notation::Ascii), "5*sqrt(5)");
/// assert_eq!(surd(&QSqrt::sqrt_of(&q(11, 400)), Notation::Unicode), "√11/20");
/// let gain = a_star.clone() * &QSqrt::rational(q(5, 4)) - &QSqrt::rational(q(1, 1));
/// assert_eq!(surd(&gain, Notation::Ascii), "-1 + 5*sqrt(6)/12");
/// ```
pub fn surd(value: &QSqrt, notation: Notation) -> String {
    let (x, y) = (value.x(), value.y());
    let Some(d) = value.d().filter(|_| !y.is_zero()) else {
        return rational(x, notation);
    };
    let term = notation.root_term(&y.numer().abs().to_string(), &d.to_string());
    let y_part = if y.denom().is_one() {
        term
    } else {
        notation.fraction(&term, &y.denom().to_string())
    };
    let sign = if y.is_negative() { "-" } else { "+" };
    if x.is_zero() {
        format!("{}{y_part}", if y.is_negative() { "-" } else { "" })
    } else {
        format!("{} {sign} {y_part}", rational(x, notation))
    }
}

/// The square root of a rational `x >= 0` in `notation`, simplified like every surd:
/// `sqrt(2/3)` is written `sqrt(6)/3`, `sqrt(16/3)` is `4*sqrt(3)/3`, `sqrt(4/9)` is `2/3`.
///
/// # Panics
/// **Panics if `x < 0`** (no real root; a programming error).
///
/// # Examples
/// ```
/// use rodimpact::field::{q, notation::{root, Notation}};
/// assert_eq!(root(&q(16, 3), Notation::Ascii), "4*sqrt(3)/3");
/// assert_eq!(root(&q(25, 2), Notation::Unicode), "5√2/2");
/// assert_eq!(root(&q(4, 9), Notation::Latex), r"\frac{2}{3}");
/// ```
pub fn root(x: &Q, notation: Notation) -> String {
    surd(&QSqrt::sqrt_of(x), notation)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    /// The review's unsimplified surds, each in its canonical spelling in all three notations.
    #[test]
    fn every_root_in_one_simplified_form() {
        let table = [
            ((11, 400), "sqrt(11)/20", "√11/20", r"\frac{\sqrt{11}}{20}"),
            ((16, 3), "4*sqrt(3)/3", "4√3/3", r"\frac{4\sqrt{3}}{3}"),
            ((125, 1), "5*sqrt(5)", "5√5", r"5\sqrt{5}"),
            ((25, 2), "5*sqrt(2)/2", "5√2/2", r"\frac{5\sqrt{2}}{2}"),
            ((2, 3), "sqrt(6)/3", "√6/3", r"\frac{\sqrt{6}}{3}"),
            ((3, 2), "sqrt(6)/2", "√6/2", r"\frac{\sqrt{6}}{2}"),
            ((2, 1), "sqrt(2)", "√2", r"\sqrt{2}"),
            ((9, 4), "3/2", "3/2", r"\frac{3}{2}"),
            ((0, 1), "0", "0", "0"),
        ];
        for ((n, d), ascii, unicode, latex) in table {
            let x = q(n, d);
            assert_eq!(root(&x, Notation::Ascii), ascii, "sqrt({x})");
            assert_eq!(root(&x, Notation::Unicode), unicode, "sqrt({x})");
            assert_eq!(root(&x, Notation::Latex), latex, "sqrt({x})");
        }
    }

    #[test]
    fn sums_and_signs() {
        let r6 = QSqrt::sqrt_of(&q(6, 1));
        let half = QSqrt::rational(q(1, 2));
        let cases = [
            (-r6.clone(), "-sqrt(6)", "-√6"),
            (
                r6.clone() * &QSqrt::rational(q(-2, 5)),
                "-2*sqrt(6)/5",
                "-2√6/5",
            ),
            (
                half.clone() + &(r6.clone() / &QSqrt::rational(q(3, 1))),
                "1/2 + sqrt(6)/3",
                "1/2 + √6/3",
            ),
            (
                QSqrt::rational(q(-1, 2)) - &r6,
                "-1/2 - sqrt(6)",
                "-1/2 - √6",
            ),
            (r6.clone() - r6, "0", "0"),
        ];
        for (value, ascii, unicode) in cases {
            assert_eq!(surd(&value, Notation::Ascii), ascii);
            assert_eq!(surd(&value, Notation::Unicode), unicode);
        }
        let mixed =
            QSqrt::rational(q(-1, 2)) + &(QSqrt::sqrt_of(&q(2, 1)) * &QSqrt::rational(q(3, 4)));
        assert_eq!(
            surd(&mixed, Notation::Latex),
            r"-\frac{1}{2} + \frac{3\sqrt{2}}{4}"
        );
    }
}
