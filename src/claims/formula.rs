//! A rational function together with the expression it was built from, so that a certificate
//! can show what was compared (`(2*m*a/I)/(1 + m/M + m*a^2/I)*v0`, the paper's Eq. (omega)
//! as printed) and not only the canonical form every side reduces to.
//!
//! Arithmetic on [`Formula`]s computes the exact value ([`RatFn`], canonical) and writes the
//! expression, with the parentheses its precedence needs; a [`RatFn`] that enters the
//! arithmetic (a solver output, a symbol) is written in its canonical form.

use crate::field::{Q, RatFn};
use num_traits::{One, Zero};
use std::fmt;
use std::ops::{Add, Deref, Div, Mul, Neg, Sub};

/// How tightly an expression binds, for parenthesising it as an operand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Precedence {
    /// A sum, a difference or a leading minus: `a + b`, `-a`.
    Sum,
    /// A product or quotient: `2*a`, `a/b`.
    Product,
    /// A symbol, an integer, a power or a parenthesised group: `a`, `2`, `a^2`, `(a + b)`.
    Atom,
}

/// The precedence of an expression as written, from its top level (outside parentheses).
fn precedence_of(text: &str) -> Precedence {
    let mut depth = 0;
    let mut product = false;
    let bytes = text.as_bytes();
    if bytes.first() == Some(&b'-') {
        return Precedence::Sum;
    }
    for (i, &c) in bytes.iter().enumerate() {
        match c {
            b'(' => depth += 1,
            b')' => depth -= 1,
            b'+' | b'-' if depth == 0 && i > 0 && bytes[i - 1] == b' ' => {
                return Precedence::Sum;
            }
            b'*' | b'/' if depth == 0 => product = true,
            _ => {}
        }
    }
    if product {
        Precedence::Product
    } else {
        Precedence::Atom
    }
}

/// Whether `text` divides at its top level (outside parentheses).
fn top_level_slash(text: &str) -> bool {
    let mut depth = 0;
    for c in text.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            '/' if depth == 0 => return true,
            _ => {}
        }
    }
    false
}

/// An exact rational function and the expression it was built from.
///
/// # Examples
/// ```
/// use rodimpact::claims::Formula;
/// let (m, big_m) = (Formula::sym("m"), Formula::sym("M"));
/// let ratio = (Formula::int(2) * &m / &big_m) / (Formula::int(1) + &(m.clone() / &big_m));
/// assert_eq!(ratio.to_string(), "(2*m/M)/(1 + m/M)");
/// assert_eq!(ratio.value().to_string(), "2*m/(M + m)");
/// ```
#[derive(Clone, PartialEq)]
pub struct Formula {
    text: String,
    precedence: Precedence,
    value: RatFn,
    /// The names used in `text` for computed values (`omega` for the solver's omega), with
    /// what they stand for, in order of first use.
    names: Vec<(String, Formula)>,
}

impl Formula {
    /// The symbol `name`.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::claims::Formula::sym("v0").to_string(), "v0");
    /// ```
    pub fn sym(name: &str) -> Formula {
        Formula::from(RatFn::symbol(name))
    }

    /// A computed value under a name: the expression shows `name`, and [`Formula::names`] lists
    /// what it stands for (`omega` = the solver's omega, `v_paper` = Eq. (v) as printed).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Formula;
    /// use rodimpact::field::RatFn;
    /// let omega = Formula::named("omega", RatFn::symbol("v0") / RatFn::symbol("a"));
    /// let x = omega * &Formula::sym("a");
    /// assert_eq!(x.to_string(), "omega*a");
    /// assert_eq!(x.value().to_string(), "v0");
    /// assert_eq!(x.names()[0].0, "omega");
    /// assert_eq!(x.names()[0].1.to_string(), "v0/a");
    /// ```
    pub fn named(name: &str, value: impl Into<Formula>) -> Formula {
        let value = value.into();
        let inner = Formula {
            names: value.names.clone(),
            ..Formula::from(RatFn::zero())
        };
        let own = Formula {
            text: name.to_string(),
            precedence: Precedence::Atom,
            value: value.value.clone(),
            names: vec![(name.to_string(), value)],
        };
        // The names the value itself uses are listed after it.
        Formula {
            names: own.merged_names(&inner),
            ..own
        }
    }

    /// The names the expression uses for computed values, with what each stands for, in
    /// order of first use (a certificate lists them under `where`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Formula;
    /// let v = Formula::named("v", Formula::sym("v0") / &Formula::int(2));
    /// let x = v.clone() - &Formula::named("V", Formula::sym("v0")) + &v;
    /// let names: Vec<&str> = x.names().iter().map(|(n, _)| n.as_str()).collect();
    /// assert_eq!(names, ["v", "V"]);
    /// ```
    pub fn names(&self) -> &[(String, Formula)] {
        &self.names
    }

    /// The names of `self` and then those of `other` that are new.
    ///
    /// # Panics
    /// **Panics if one name stands for two different values** (a programming error in a claim).
    fn merged_names(&self, other: &Formula) -> Vec<(String, Formula)> {
        let mut names = self.names.clone();
        for (name, value) in &other.names {
            match names.iter().find(|(n, _)| n == name) {
                Some((_, known)) => assert!(
                    known.value == value.value,
                    "the name {name} stands for two values: {known} and {value}"
                ),
                None => names.push((name.clone(), value.clone())),
            }
        }
        names
    }

    /// The integer `n`.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::claims::Formula::int(-3).to_string(), "-3");
    /// ```
    pub fn int(n: i64) -> Formula {
        Formula::from(RatFn::from(n))
    }

    /// The exact value, canonical.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Formula;
    /// let a = Formula::sym("a");
    /// let x = a.clone() * &a - &a.pow(2);
    /// assert_eq!(x.to_string(), "a*a - a^2");
    /// assert_eq!(x.value().to_string(), "0");
    /// ```
    pub fn value(&self) -> &RatFn {
        &self.value
    }

    /// `self^n` (`n >= 2`), written as a power.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Formula;
    /// let x = Formula::sym("a") + &Formula::sym("b");
    /// assert_eq!(x.pow(2).to_string(), "(a + b)^2");
    /// assert_eq!(x.pow(2).value().to_string(), "a^2 + 2*a*b + b^2");
    /// ```
    pub fn pow(&self, n: u32) -> Formula {
        let value = (0..n).fold(RatFn::one(), |acc, _| acc * &self.value);
        Formula {
            text: format!("{}^{n}", self.operand(Precedence::Atom)),
            precedence: Precedence::Atom,
            value,
            names: self.names.clone(),
        }
    }

    /// The simultaneous substitution `pairs` into `self`, written `[expression]{a -> a - c}`.
    ///
    /// # Panics
    /// **Panics if the substitution makes a denominator vanish** (a programming error in a claim,
    /// as for the `subs` the claim files use).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::claims::Formula;
    /// use rodimpact::field::RatFn;
    /// let x = Formula::sym("a") / &Formula::sym("b");
    /// let shifted = x.subs(&[("a", RatFn::symbol("b"))]);
    /// assert_eq!(shifted.to_string(), "[a/b]{a -> b}");
    /// assert_eq!(shifted.value().to_string(), "1");
    /// ```
    pub fn subs(&self, pairs: &[(&str, RatFn)]) -> Formula {
        let pairs: Vec<(crate::field::Sym, RatFn)> = pairs
            .iter()
            .map(|(s, v)| (crate::field::Sym::new(s), v.clone()))
            .collect();
        let written: Vec<String> = pairs.iter().map(|(s, v)| format!("{s} -> {v}")).collect();
        Formula {
            text: format!("[{}]{{{}}}", self.text, written.join(", ")),
            precedence: Precedence::Atom,
            value: self
                .value
                .subs_all(&pairs)
                .expect("a claim's substitution keeps denominators nonzero"),
            names: self.names.clone(),
        }
    }

    /// The text, in parentheses when it binds less tightly than `at_least`.
    fn operand(&self, at_least: Precedence) -> String {
        if self.precedence < at_least {
            format!("({})", self.text)
        } else {
            self.text.clone()
        }
    }

    fn binary(&self, op: &str, other: &Formula, value: RatFn) -> Formula {
        let (left, right, precedence) = match op {
            "+" => (Precedence::Sum, Precedence::Sum, Precedence::Sum),
            "-" => (Precedence::Sum, Precedence::Product, Precedence::Sum),
            "*" => (
                Precedence::Product,
                Precedence::Product,
                Precedence::Product,
            ),
            _ => (Precedence::Product, Precedence::Atom, Precedence::Product),
        };
        // A quotient divided again is parenthesised for the reader: `(2*m/M)/D`.
        let left_text =
            if op == "/" && self.precedence == Precedence::Product && top_level_slash(&self.text) {
                format!("({})", self.text)
            } else {
                self.operand(left)
            };
        // A negative right operand of + or - is parenthesised: `a + (-b)`, `a - (-b)`.
        let right_text = if matches!(op, "+" | "-") && other.text.starts_with('-') {
            format!("({})", other.text)
        } else {
            other.operand(right)
        };
        let text = match op {
            "+" | "-" => format!("{left_text} {op} {right_text}"),
            _ => format!("{left_text}{op}{right_text}"),
        };
        Formula {
            text,
            precedence,
            value,
            names: self.merged_names(other),
        }
    }
}

impl From<RatFn> for Formula {
    /// A rational function written in its canonical form.
    fn from(value: RatFn) -> Formula {
        let text = value.to_string();
        Formula {
            precedence: precedence_of(&text),
            text,
            value,
            names: Vec::new(),
        }
    }
}

impl From<&RatFn> for Formula {
    fn from(value: &RatFn) -> Formula {
        Formula::from(value.clone())
    }
}

impl From<Q> for Formula {
    fn from(value: Q) -> Formula {
        Formula::from(RatFn::constant(value))
    }
}

impl From<Formula> for RatFn {
    fn from(f: Formula) -> RatFn {
        f.value
    }
}

/// A formula reads as its value wherever a [`RatFn`] is expected (`subs(&paper.v, ...)`).
impl Deref for Formula {
    type Target = RatFn;
    fn deref(&self) -> &RatFn {
        &self.value
    }
}

impl fmt::Display for Formula {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl fmt::Debug for Formula {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} (= {})", self.text, self.value)
    }
}

impl Neg for Formula {
    type Output = Formula;
    fn neg(self) -> Formula {
        Formula {
            text: format!("-{}", self.operand(Precedence::Product)),
            precedence: Precedence::Sum,
            value: -self.value,
            names: self.names,
        }
    }
}

/// `Formula op Formula`, `Formula op RatFn` (owned or by reference): the value computed exactly,
/// the expression written.
macro_rules! formula_op {
    ($trait:ident, $method:ident, $symbol:literal) => {
        impl $trait<&Formula> for Formula {
            type Output = Formula;
            fn $method(self, other: &Formula) -> Formula {
                let value = self.value.clone().$method(&other.value);
                self.binary($symbol, other, value)
            }
        }
        impl $trait<Formula> for Formula {
            type Output = Formula;
            fn $method(self, other: Formula) -> Formula {
                self.$method(&other)
            }
        }
        impl $trait<&RatFn> for Formula {
            type Output = Formula;
            fn $method(self, other: &RatFn) -> Formula {
                self.$method(&Formula::from(other))
            }
        }
        impl $trait<RatFn> for Formula {
            type Output = Formula;
            fn $method(self, other: RatFn) -> Formula {
                self.$method(&Formula::from(other))
            }
        }
    };
}

/// `RatFn op Formula`: the rational function written in canonical form, then the operation.
macro_rules! ratfn_formula_op {
    ($trait:ident, $method:ident) => {
        impl $trait<&Formula> for RatFn {
            type Output = Formula;
            fn $method(self, other: &Formula) -> Formula {
                Formula::from(self).$method(other)
            }
        }
        impl $trait<Formula> for RatFn {
            type Output = Formula;
            fn $method(self, other: Formula) -> Formula {
                Formula::from(self).$method(&other)
            }
        }
    };
}

ratfn_formula_op!(Add, add);
ratfn_formula_op!(Sub, sub);
ratfn_formula_op!(Mul, mul);
ratfn_formula_op!(Div, div);

formula_op!(Add, add, "+");
formula_op!(Sub, sub, "-");
formula_op!(Mul, mul, "*");
formula_op!(Div, div, "/");

impl Zero for Formula {
    fn zero() -> Formula {
        Formula::int(0)
    }
    fn is_zero(&self) -> bool {
        self.value.is_identically_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(name: &str) -> Formula {
        Formula::sym(name)
    }

    #[test]
    fn parentheses_only_where_precedence_needs_them() {
        let (a, b, c) = (f("a"), f("b"), f("c"));
        let cases = [
            (a.clone() + &(b.clone() * &c), "a + b*c"),
            ((a.clone() + &b) * &c, "(a + b)*c"),
            (a.clone() - &(b.clone() + &c), "a - (b + c)"),
            (a.clone() - &(b.clone() * &c), "a - b*c"),
            (a.clone() / &(b.clone() * &c), "a/(b*c)"),
            (a.clone() * &b / &c, "a*b/c"),
            (-(a.clone() + &b), "-(a + b)"),
            (a.clone() + &(-b.clone()), "a + (-b)"),
            (
                a.clone() * &Formula::from(RatFn::symbol("b") + &RatFn::symbol("c")),
                "a*(b + c)",
            ),
            (
                a.clone() / &Formula::from(RatFn::symbol("b") / RatFn::symbol("c")),
                "a/(b/c)",
            ),
        ];
        for (formula, text) in cases {
            assert_eq!(formula.to_string(), text);
        }
    }

    #[test]
    fn the_value_is_exact_whatever_the_text() {
        let (a, b) = (f("a"), f("b"));
        let x = (a.clone() + &b).pow(2) - &(a.clone() - &b).pow(2);
        assert_eq!(x.to_string(), "(a + b)^2 - (a - b)^2");
        assert_eq!(x.value().to_string(), "4*a*b");
        assert_eq!(precedence_of("(a + b)/(c - d)"), Precedence::Product);
        assert_eq!(precedence_of("-a"), Precedence::Sum);
        assert_eq!(precedence_of("a^2"), Precedence::Atom);
    }
}
