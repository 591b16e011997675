//! [`RatFn`]: rational functions over Q in named symbols, the backend that proves identities for
//! all parameter values and takes exact limits.
//!
//! **Normal form.** `num / den` with `gcd(num, den) = 1` and `den` *primitive*: coprime integer
//! coefficients and a positive leading coefficient in the graded-lex order of [`poly`](super::poly)
//! (zero is `0/1`). Each rational function has exactly one such representation, so the derived
//! `==` is equality of functions. A primitive denominator (rather than a monic one) keeps the
//! output free of fractions: `m/(2*M + m)`, not `1/2*m/(M + 1/2*m)`.
//!
//! **Display.** `num/den`, each side parenthesised when it has several terms (the denominator
//! also when it is a product of several symbols); a polynomial shows without `/1`:
//! `2*m*v0/(M + m)`, `v0/(M*m)`, `M + m`.

use super::poly::{Poly, Sym};
use super::{Field, Q};
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::collections::BTreeSet;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A rational function `num/den` over Q in named symbols, always in normal form (see the
/// [module docs](self)).
///
/// # Examples
/// ```
/// use rodimpact::field::{Field, RatFn};
/// let (m, big_m, v0) = (RatFn::symbol("m"), RatFn::symbol("M"), RatFn::symbol("v0"));
/// let two = RatFn::from_i64(2);
/// let big_v = two * &m * &v0 / (big_m.clone() + &m);
/// assert_eq!(big_v.to_string(), "2*m*v0/(M + m)");
/// // An identity holds structurally: V (M + m) - 2 m v0 == 0.
/// assert!((big_v * &(big_m + &m) - RatFn::from_i64(2) * &m * &v0).is_identically_zero());
/// ```
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct RatFn {
    num: Poly,
    den: Poly,
}

/// Where a symbol goes in [`RatFn::leading_term`] and [`RatFn::limit`].
///
/// # Examples
/// ```
/// use rodimpact::field::{ratfunc::{LimitValue, Point}, RatFn, Sym};
/// let x = RatFn::symbol("x");
/// assert_eq!(x.limit(Sym::new("x"), Point::Zero), LimitValue::Finite(RatFn::from(0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Point {
    /// The symbol tends to 0 from above.
    Zero,
    /// The symbol tends to +infinity.
    Infinity,
}

/// The exact limit of a rational function as one symbol tends to a [`Point`].
///
/// # Examples
/// ```
/// use rodimpact::field::{ratfunc::{LimitValue, Point}, RatFn, Sym};
/// let (x, y) = (RatFn::symbol("x"), RatFn::symbol("y"));
/// let f = x.clone() * &x * &y / (x.clone() + &y);
/// assert_eq!(
///     f.limit(Sym::new("x"), Point::Infinity),
///     LimitValue::Infinite { coefficient: y, order: 1 }
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LimitValue {
    /// A finite limit (a rational function of the other symbols; 0 when the function vanishes).
    Finite(RatFn),
    /// Divergence like `coefficient * sym^order` (`order > 0` at infinity, `order < 0` at 0);
    /// the sign of the divergence is the sign of `coefficient`, which may depend on the other
    /// symbols.
    Infinite {
        /// The leading coefficient, a rational function of the other symbols.
        coefficient: RatFn,
        /// The exponent of the symbol in the leading term.
        order: i64,
    },
}

impl RatFn {
    /// Whether the representation is the normal form (see the [module docs](self)): both sides
    /// valid polynomials, `num` and `den` coprime, `den` primitive with a positive leading
    /// coefficient, zero as `0/1`. Every operation keeps it; the property tests assert it.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::RatFn;
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// assert!((m.clone() / &(m + &big_m)).is_valid());
    /// ```
    pub fn is_valid(&self) -> bool {
        let normal_zero = !self.num.is_zero() || self.den.is_one();
        self.num.is_valid()
            && self.den.is_valid()
            && normal_zero
            && self.den.primitive() == self.den
            && Poly::gcd(&self.num, &self.den).is_one()
    }

    /// `num / den` in normal form, or `None` when `den` is the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, RatFn, Sym};
    /// let (m, big_m) = (Poly::var(Sym::new("m")), Poly::var(Sym::new("M")));
    /// let f = RatFn::new(m.pow(2) - &big_m.pow(2), m.clone() - &big_m).unwrap();
    /// assert_eq!(f.to_string(), "M + m");
    /// assert!(RatFn::new(m, Poly::default()).is_none());
    /// ```
    pub fn new(num: Poly, den: Poly) -> Option<RatFn> {
        (!den.is_zero()).then(|| RatFn::reduce(num, den))
    }

    /// Cancels the gcd and normalises the content; `den` must be nonzero.
    fn reduce(num: Poly, den: Poly) -> RatFn {
        if num.is_zero() {
            return RatFn::zero();
        }
        if den.as_constant().is_some() {
            return RatFn::fix_content(num, den);
        }
        let g = Poly::gcd(&num, &den);
        if g.as_constant().is_some() {
            return RatFn::fix_content(num, den);
        }
        RatFn::fix_content(exact(&num, &g), exact(&den, &g))
    }

    /// Scales so that `den` is primitive with a positive leading coefficient (`num/den` coprime).
    fn fix_content(num: Poly, den: Poly) -> RatFn {
        let c = den.content();
        if c.is_one() {
            RatFn { num, den }
        } else {
            let inv = c.recip();
            RatFn {
                num: num.scale(&inv),
                den: den.scale(&inv),
            }
        }
    }

    /// The rational function that is the symbol called `name`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::RatFn;
    /// assert_eq!(RatFn::symbol("v0").to_string(), "v0");
    /// ```
    pub fn symbol(name: &str) -> RatFn {
        RatFn::from(Poly::var(Sym::new(name)))
    }

    /// The constant `c`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, RatFn};
    /// assert_eq!(RatFn::constant(q(-2, 6)).to_string(), "-1/3");
    /// ```
    pub fn constant(c: Q) -> RatFn {
        RatFn::from(Poly::constant(c))
    }

    /// The numerator (normal form: coprime to the denominator).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, RatFn};
    /// let f = RatFn::symbol("m") / RatFn::from_i64(2);
    /// assert_eq!(f.num().to_string(), "1/2*m");
    /// ```
    pub fn num(&self) -> &Poly {
        &self.num
    }

    /// The denominator (normal form: coprime integer coefficients, positive leading coefficient).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, RatFn};
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// let f = m.clone() / (RatFn::from_i64(-4) * &big_m - RatFn::from_i64(2) * &m);
    /// assert_eq!(f.den().to_string(), "2*M + m");
    /// assert_eq!(f.to_string(), "-1/2*m/(2*M + m)");
    /// ```
    pub fn den(&self) -> &Poly {
        &self.den
    }

    /// `true` when the function is the zero function (its numerator expands to 0): the test
    /// that proves an identity `lhs == rhs` for all parameter values, applied to `lhs - rhs`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::RatFn;
    /// let x = RatFn::symbol("x");
    /// assert!((x.clone() * &x - x.clone() * &x).is_identically_zero());
    /// assert!(!x.is_identically_zero());
    /// ```
    pub fn is_identically_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// The value when the function is a constant, else `None`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, RatFn};
    /// let x = RatFn::symbol("x");
    /// assert_eq!((x.clone() / &(x.clone() + &x)).as_constant(), Some(q(1, 2)));
    /// assert_eq!(x.as_constant(), None);
    /// ```
    pub fn as_constant(&self) -> Option<Q> {
        self.den.as_constant().and(self.num.as_constant())
    }

    /// Substitutes `value` for `sym`; `None` when the denominator becomes identically zero.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, RatFn, Sym};
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// let f = RatFn::from_i64(2) * &m / (big_m.clone() + &m);
    /// assert_eq!(f.subs(Sym::new("M"), &m).unwrap().to_string(), "1");
    /// let g = RatFn::from_i64(1) / (big_m - &m);
    /// assert!(g.subs(Sym::new("M"), &RatFn::symbol("m")).is_none());
    /// ```
    pub fn subs(&self, sym: Sym, value: &RatFn) -> Option<RatFn> {
        self.subs_all(&[(sym, value.clone())])
    }

    /// Simultaneous substitution (values may mention the substituted symbols: `[(x, y), (y, x)]`
    /// swaps them); a symbol listed twice takes its first value. `None` when the denominator
    /// becomes identically zero.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, RatFn, Sym};
    /// let (x, y) = (RatFn::symbol("x"), RatFn::symbol("y"));
    /// let f = x.clone() / (y.clone() + RatFn::from_i64(1));
    /// let swapped = f.subs_all(&[(Sym::new("x"), y.clone()), (Sym::new("y"), x.clone())]);
    /// assert_eq!(swapped.unwrap().to_string(), "y/(x + 1)");
    /// ```
    pub fn subs_all(&self, subs: &[(Sym, RatFn)]) -> Option<RatFn> {
        let mut seen = BTreeSet::new();
        let list: Vec<(Sym, &Poly, &Poly, u32)> = subs
            .iter()
            .filter(|(s, _)| seen.insert(*s))
            .map(|(s, v)| {
                let d = self.num.degree_in(*s).max(self.den.degree_in(*s));
                (*s, &v.num, &v.den, d)
            })
            .collect();
        // Homogenising both sides by the same prod q_i^d_i keeps them polynomials.
        let num = self.num.subs_homogeneous(&list);
        let den = self.den.subs_homogeneous(&list);
        RatFn::new(num, den)
    }

    /// The partial derivative with respect to `sym`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Field, RatFn, Sym};
    /// let x = RatFn::symbol("x");
    /// let f = RatFn::from_i64(1) / (x.clone() + RatFn::from_i64(1));
    /// assert_eq!(f.derivative(Sym::new("x")).to_string(), "-1/(x^2 + 2*x + 1)");
    /// ```
    pub fn derivative(&self, sym: Sym) -> RatFn {
        let dn = self.num.derivative(sym);
        let dd = self.den.derivative(sym);
        if dd.is_zero() {
            return RatFn::reduce(dn, self.den.clone());
        }
        RatFn::reduce(&dn * &self.den - &(&self.num * &dd), self.den.pow(2))
    }

    /// Evaluates in any [`Field`] (Q, `f64`, a quadratic field, ...); `None` when a symbol has
    /// no value or the denominator evaluates to 0.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Field, RatFn, Sym};
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// let f = m.clone() / (big_m - &m);
    /// let at = |s: Sym| Some(if s.name() == "m" { q(1, 1) } else { q(3, 1) });
    /// assert_eq!(f.eval(&at), Some(q(1, 2)));
    /// assert_eq!(f.eval(&|_: Sym| Some(2.0f64)), None); // M = m
    /// ```
    pub fn eval<F: Field>(&self, value_of: &impl Fn(Sym) -> Option<F>) -> Option<F> {
        let n = self.num.eval(value_of)?;
        let d = self.den.eval(value_of)?;
        n.checked_div(&d)
    }

    /// The symbols that occur.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{RatFn, Sym};
    /// let f = RatFn::symbol("m") / RatFn::symbol("M");
    /// assert_eq!(f.symbols().into_iter().map(Sym::name).collect::<Vec<_>>(), ["M", "m"]);
    /// ```
    pub fn symbols(&self) -> BTreeSet<Sym> {
        let mut s = self.num.symbols();
        s.extend(self.den.symbols());
        s
    }

    /// The leading behaviour `self ~ c * sym^k` as `sym` tends to `at`, with `c` a rational
    /// function of the other symbols: at 0 the lowest powers of `sym` in numerator and
    /// denominator, at infinity the highest (equivalently `sym = 1/t`, `t -> 0+`; `k` is still
    /// the exponent of `sym`). `None` for the zero function.
    ///
    /// The coefficient is exact as a rational function; for particular values of the other
    /// symbols where it vanishes the behaviour is of course different.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{ratfunc::Point, Field, RatFn, Sym};
    /// let (m, big_m, v0) = (RatFn::symbol("m"), RatFn::symbol("M"), RatFn::symbol("v0"));
    /// let big_v = RatFn::from_i64(2) * &m * &v0 / (big_m + &m);
    /// let (c, k) = big_v.leading_term(Sym::new("M"), Point::Infinity).unwrap();
    /// assert_eq!((c.to_string(), k), ("2*m*v0".to_string(), -1));
    /// let (c, k) = big_v.leading_term(Sym::new("M"), Point::Zero).unwrap();
    /// assert_eq!((c.to_string(), k), ("2*v0".to_string(), 0));
    /// ```
    pub fn leading_term(&self, sym: Sym, at: Point) -> Option<(RatFn, i64)> {
        if self.num.is_zero() {
            return None;
        }
        let power = |p: &Poly| match at {
            Point::Zero => p.low_degree_in(sym),
            Point::Infinity => p.degree_in(sym),
        };
        let (kn, kd) = (power(&self.num), power(&self.den));
        let c = RatFn::reduce(self.num.coeff_in(sym, kn), self.den.coeff_in(sym, kd));
        Some((c, i64::from(kn) - i64::from(kd)))
    }

    /// The exact limit as `sym` tends to `at` (see [`RatFn::leading_term`]).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{ratfunc::{LimitValue, Point}, Field, RatFn, Sym};
    /// let (m, big_m) = (RatFn::symbol("m"), RatFn::symbol("M"));
    /// let f = (m.clone() - &big_m) / (m.clone() + &big_m);
    /// assert_eq!(f.limit(Sym::new("M"), Point::Infinity), LimitValue::Finite(RatFn::from_i64(-1)));
    /// assert_eq!(f.limit(Sym::new("M"), Point::Zero), LimitValue::Finite(RatFn::from_i64(1)));
    /// ```
    pub fn limit(&self, sym: Sym, at: Point) -> LimitValue {
        let Some((coefficient, order)) = self.leading_term(sym, at) else {
            return LimitValue::Finite(RatFn::zero());
        };
        let vanishes = match at {
            Point::Zero => order > 0,
            Point::Infinity => order < 0,
        };
        if vanishes {
            LimitValue::Finite(RatFn::zero())
        } else if order == 0 {
            LimitValue::Finite(coefficient)
        } else {
            LimitValue::Infinite { coefficient, order }
        }
    }

    /// `1/self`; the caller guarantees `self != 0`.
    fn recip(&self) -> RatFn {
        assert!(
            !self.num.is_zero(),
            "division by the zero rational function"
        );
        RatFn::fix_content(self.den.clone(), self.num.clone())
    }
}

/// `a / b` where `b` is known to divide `a` (a gcd of `a`).
fn exact(a: &Poly, b: &Poly) -> Poly {
    a.div_exact(b)
        .unwrap_or_else(|| unreachable!("a gcd divides its arguments"))
}

impl From<Poly> for RatFn {
    /// The polynomial `p` as a rational function `p/1`.
    fn from(p: Poly) -> RatFn {
        RatFn {
            num: p,
            den: Poly::one(),
        }
    }
}

impl From<i64> for RatFn {
    /// The integer `n`.
    fn from(n: i64) -> RatFn {
        RatFn::from_i64(n)
    }
}

impl Zero for RatFn {
    fn zero() -> Self {
        RatFn::from(Poly::zero())
    }

    fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
}

impl One for RatFn {
    fn one() -> Self {
        RatFn::from(Poly::one())
    }

    fn is_one(&self) -> bool {
        self.num.is_one() && self.den.is_one()
    }
}

/// Henrici's sum: only the gcd of the denominators and one gcd with it are needed.
fn add_ref(a: &RatFn, b: &RatFn) -> RatFn {
    if a.num.is_zero() {
        return b.clone();
    }
    if b.num.is_zero() {
        return a.clone();
    }
    if a.den == b.den {
        return RatFn::reduce(&a.num + &b.num, a.den.clone());
    }
    let g = Poly::gcd(&a.den, &b.den);
    if g.is_one() {
        // a/b + c/d with gcd(b, d) = 1 is already in lowest terms.
        let num = &a.num * &b.den + &(&b.num * &a.den);
        if num.is_zero() {
            return RatFn::zero();
        }
        return RatFn::fix_content(num, &a.den * &b.den);
    }
    let (ad, bd) = (exact(&a.den, &g), exact(&b.den, &g));
    let num = &a.num * &bd + &(&b.num * &ad);
    if num.is_zero() {
        return RatFn::zero();
    }
    let g2 = Poly::gcd(&num, &g);
    let (num, g) = if g2.is_one() {
        (num, g)
    } else {
        (exact(&num, &g2), exact(&g, &g2))
    };
    RatFn::fix_content(num, ad * &bd * &g)
}

/// Cross-cancelled product: `(a/b)(c/d) = ((a/g1)(c/g2)) / ((b/g2)(d/g1))`.
fn mul_ref(a: &RatFn, b: &RatFn) -> RatFn {
    if a.num.is_zero() || b.num.is_zero() {
        return RatFn::zero();
    }
    let g1 = Poly::gcd(&a.num, &b.den);
    let g2 = Poly::gcd(&b.num, &a.den);
    let cancel = |p: &Poly, g: &Poly| {
        if g.is_one() { p.clone() } else { exact(p, g) }
    };
    let num = cancel(&a.num, &g1) * &cancel(&b.num, &g2);
    let den = cancel(&a.den, &g2) * &cancel(&b.den, &g1);
    RatFn::fix_content(num, den)
}

impl<'a> Add<&'a RatFn> for RatFn {
    type Output = RatFn;
    fn add(self, rhs: &'a RatFn) -> RatFn {
        add_ref(&self, rhs)
    }
}

impl<'a> Sub<&'a RatFn> for RatFn {
    type Output = RatFn;
    fn sub(self, rhs: &'a RatFn) -> RatFn {
        add_ref(&self, &-rhs)
    }
}

impl<'a> Mul<&'a RatFn> for RatFn {
    type Output = RatFn;
    fn mul(self, rhs: &'a RatFn) -> RatFn {
        mul_ref(&self, rhs)
    }
}

impl<'a> Div<&'a RatFn> for RatFn {
    type Output = RatFn;
    /// # Panics
    /// When `rhs` is zero (a programming error; use [`Field::checked_div`]).
    fn div(self, rhs: &'a RatFn) -> RatFn {
        mul_ref(&self, &rhs.recip())
    }
}

impl Add for RatFn {
    type Output = RatFn;
    fn add(self, rhs: RatFn) -> RatFn {
        self + &rhs
    }
}

impl Sub for RatFn {
    type Output = RatFn;
    fn sub(self, rhs: RatFn) -> RatFn {
        self - &rhs
    }
}

impl Mul for RatFn {
    type Output = RatFn;
    fn mul(self, rhs: RatFn) -> RatFn {
        self * &rhs
    }
}

impl Div for RatFn {
    type Output = RatFn;
    /// # Panics
    /// When `rhs` is zero (a programming error; use [`Field::checked_div`]).
    fn div(self, rhs: RatFn) -> RatFn {
        self / &rhs
    }
}

impl<'a> Add<&'a RatFn> for &RatFn {
    type Output = RatFn;
    fn add(self, rhs: &'a RatFn) -> RatFn {
        add_ref(self, rhs)
    }
}

impl<'a> Sub<&'a RatFn> for &RatFn {
    type Output = RatFn;
    fn sub(self, rhs: &'a RatFn) -> RatFn {
        add_ref(self, &-rhs)
    }
}

impl<'a> Mul<&'a RatFn> for &RatFn {
    type Output = RatFn;
    fn mul(self, rhs: &'a RatFn) -> RatFn {
        mul_ref(self, rhs)
    }
}

impl<'a> Div<&'a RatFn> for &RatFn {
    type Output = RatFn;
    /// # Panics
    /// When `rhs` is zero (a programming error; use [`Field::checked_div`]).
    fn div(self, rhs: &'a RatFn) -> RatFn {
        mul_ref(self, &rhs.recip())
    }
}

impl Neg for &RatFn {
    type Output = RatFn;
    fn neg(self) -> RatFn {
        -self.clone()
    }
}

impl Neg for RatFn {
    type Output = RatFn;
    fn neg(self) -> RatFn {
        RatFn {
            num: -self.num,
            den: self.den,
        }
    }
}

impl Field for RatFn {
    const NAME: &'static str = "Q(symbols)";
    const EXACT: bool = true;

    fn from_rational(q: &Q) -> Self {
        RatFn::constant(q.clone())
    }

    /// The sign of a constant; `None` when the function depends on its symbols.
    fn sign(&self) -> Option<Ordering> {
        self.as_constant().map(|c| {
            if c.is_zero() {
                Ordering::Equal
            } else if c.is_positive() {
                Ordering::Greater
            } else {
                Ordering::Less
            }
        })
    }

    /// The nearest `f64` of a constant; NaN otherwise.
    fn nearest_f64(&self) -> f64 {
        self.as_constant()
            .and_then(|c| c.to_f64())
            .unwrap_or(f64::NAN)
    }
}

impl fmt::Display for RatFn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den.is_one() {
            return write!(f, "{}", self.num);
        }
        let several = |p: &Poly| p.terms().nth(1).is_some();
        if several(&self.num) {
            write!(f, "({})/", self.num)?;
        } else {
            write!(f, "{}/", self.num)?;
        }
        let product = self
            .den
            .leading_term()
            .is_some_and(|(m, _)| m.factors().len() > 1);
        if several(&self.den) || product {
            write!(f, "({})", self.den)
        } else {
            write!(f, "{}", self.den)
        }
    }
}

impl fmt::Debug for RatFn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};
    use num_bigint::BigInt;
    use proptest::prelude::*;

    fn s(name: &str) -> RatFn {
        RatFn::symbol(name)
    }

    fn k(n: i64) -> RatFn {
        RatFn::from_i64(n)
    }

    #[test]
    fn field_laws_hold_structurally() {
        let huge = RatFn::constant(Q::from_integer(BigInt::from(10u32).pow(60)));
        let samples = [
            k(0),
            k(1),
            k(-1),
            RatFn::constant(q(1, 3)),
            s("m"),
            s("M") + &s("m"),
            k(1) / (s("a") * &s("a") + &s("I")),
            huge,
        ];
        laws::check_field(&samples, |a, b| a == b);
    }

    #[test]
    fn structural_equality_agrees_with_cross_multiplication() {
        let (m, big_m, a) = (s("m"), s("M"), s("a"));
        let samples = [
            k(0),
            k(3),
            m.clone() / &big_m,
            (m.clone() + &a) / (big_m.clone() - &a),
            (m.clone() * &m - &(a.clone() * &a)) / (m.clone() - &a),
            m.clone() + &a,
            k(2) * &m / (k(4) * &big_m + &(k(6) * &a)),
            m.clone() / (k(2) * &big_m + &(k(3) * &a)),
        ];
        for x in &samples {
            for y in &samples {
                let cross = (x.num() * y.den() - &(y.num() * x.den())).is_zero();
                assert_eq!(x == y, cross, "{x} vs {y}");
            }
        }
    }

    #[test]
    fn normal_form_cancels_and_shows_plainly() {
        let (m, big_m) = (s("m"), s("M"));
        let f = (m.clone() * &m - &(big_m.clone() * &big_m)) / (m.clone() - &big_m);
        assert_eq!(f.to_string(), "M + m");
        assert_eq!(f.den().to_string(), "1");
        assert_eq!((k(0) / &m).num().to_string(), "0");
        assert_eq!((k(0) / &m).den().to_string(), "1");
        assert_eq!((s("v0") / (m.clone() * &big_m)).to_string(), "v0/(M*m)");
        assert_eq!((s("v0") / (m.clone() * &m)).to_string(), "v0/m^2");
        assert_eq!(((m.clone() + &k(1)) / &big_m).to_string(), "(m + 1)/M");
        assert_eq!((k(-3) / (k(6) * &m)).to_string(), "-1/2/m");
    }

    #[test]
    fn field_trait_surface() {
        assert_eq!(RatFn::NAME, "Q(symbols)");
        assert_eq!(RatFn::constant(q(-1, 2)).sign(), Some(Ordering::Less));
        assert_eq!(s("m").sign(), None);
        assert_eq!(RatFn::constant(q(1, 4)).nearest_f64(), 0.25);
        assert!(s("m").nearest_f64().is_nan());
        assert!(k(1).checked_div(&k(0)).is_none());
        // Every operator form agrees.
        let (a, b) = (s("m") + &k(1), s("M") / &s("m"));
        assert_eq!(&a + &b, a.clone() + b.clone());
        assert_eq!(&a - &b, a.clone() - b.clone());
        assert_eq!(&a * &b, a.clone() * b.clone());
        assert_eq!(&a / &b, a.clone() / b.clone());
        assert_eq!(-&a, -a.clone());
    }

    #[test]
    fn derivative_of_quotient() {
        // d/da [2 v0 a / (a*^2 + a^2)] = 2 v0 (a*^2 - a^2)/(a*^2 + a^2)^2, with a*^2 = c.
        let (a, c, v0) = (s("a"), s("c"), s("v0"));
        let w = k(2) * &v0 * &a / (c.clone() + &(a.clone() * &a));
        let dw = w.derivative(Sym::new("a"));
        let expected = k(2) * &v0 * &(c.clone() - &(a.clone() * &a))
            / ((c.clone() + &(a.clone() * &a)) * &(c.clone() + &(a.clone() * &a)));
        assert_eq!(dw, expected);
        assert!(w.derivative(Sym::new("M")).is_identically_zero());
    }

    #[test]
    fn substitution_and_evaluation() {
        let (m, big_m, r) = (s("m"), s("M"), s("r"));
        let i = s("I");
        let d = k(1) + &(m.clone() / &big_m) + &(m.clone() * &s("a") * &s("a") / &i);
        let with_inertia = d.subs(Sym::new("I"), &(big_m.clone() * &r * &r)).unwrap();
        let expected =
            (big_m.clone() * &r * &r + &(m.clone() * &r * &r) + &(m.clone() * &s("a") * &s("a")))
                / (big_m.clone() * &r * &r);
        assert_eq!(with_inertia, expected);
        // M = 2m, uniform rod I = M l^2 / 3 with r^2 = l^2/3 and a = l: D = 1 + 1/2 + 3/2 = 3.
        let at = |sym: Sym| {
            Some(match sym.name() {
                "m" => q(1, 1),
                "M" => q(2, 1),
                "a" => q(1, 1),
                "r" => q(1, 1) / q(3, 1),
                _ => return None,
            })
        };
        // r = 1/3 is not the uniform rod; check against a direct computation instead.
        let direct = q(1, 1) + q(1, 2) + q(1, 1) / (q(2, 1) * q(1, 9));
        assert_eq!(with_inertia.eval(&at), Some(direct.clone()));
        let approx = with_inertia
            .eval(&|sym: Sym| at(sym).map(|v| v.to_f64().unwrap_or(f64::NAN)))
            .unwrap();
        assert!((approx - direct.to_f64().unwrap_or(f64::NAN)).abs() < 1e-12);
        assert_eq!(with_inertia.eval(&|_: Sym| None::<Q>), None);
    }

    /// The paper's free rod with I = M r^2: v, V, omega over Q(m, M, a, r, v0).
    fn paper_velocities() -> (RatFn, RatFn, RatFn) {
        let (m, big_m, a, r, v0) = (s("m"), s("M"), s("a"), s("r"), s("v0"));
        let i = big_m.clone() * &r * &r;
        let d = k(1) + &(m.clone() / &big_m) + &(m.clone() * &a * &a / &i);
        let v = -(k(1) - &(m.clone() / &big_m) - &(m.clone() * &a * &a / &i)) / d.clone() * &v0;
        let big_v = k(2) * &m / &big_m / d.clone() * &v0;
        let w = k(2) * &m * &a / &i / d * &v0;
        (v, big_v, w)
    }

    #[test]
    fn limits_as_the_rod_gets_heavy() {
        let (v, big_v, w) = paper_velocities();
        let big_m = Sym::new("M");
        let (m, a, r, v0) = (s("m"), s("a"), s("r"), s("v0"));
        assert_eq!(
            v.limit(big_m, Point::Infinity),
            LimitValue::Finite(-v0.clone())
        );
        assert_eq!(
            big_v.limit(big_m, Point::Infinity),
            LimitValue::Finite(k(0))
        );
        assert_eq!(
            big_v.leading_term(big_m, Point::Infinity),
            Some((k(2) * &m * &v0, -1))
        );
        assert_eq!(
            w.leading_term(big_m, Point::Infinity),
            Some((k(2) * &a * &m * &v0 / (r.clone() * &r), -1))
        );
        assert_eq!(w.limit(big_m, Point::Infinity), LimitValue::Finite(k(0)));
        // 1/V grows like M/(2 m v0).
        assert_eq!(
            (k(1) / &big_v).limit(big_m, Point::Infinity),
            LimitValue::Infinite {
                coefficient: k(1) / (k(2) * &m * &v0),
                order: 1
            }
        );
    }

    #[test]
    fn limits_as_the_rod_gets_light() {
        let (v, big_v, w) = paper_velocities();
        let big_m = Sym::new("M");
        let (a, r, v0) = (s("a"), s("r"), s("v0"));
        let r2a2 = r.clone() * &r + &(a.clone() * &a);
        assert_eq!(v.limit(big_m, Point::Zero), LimitValue::Finite(v0.clone()));
        assert_eq!(
            big_v.limit(big_m, Point::Zero),
            LimitValue::Finite(k(2) * &r * &r * &v0 / r2a2.clone())
        );
        assert_eq!(
            w.limit(big_m, Point::Zero),
            LimitValue::Finite(k(2) * &a * &v0 / r2a2)
        );
        // 1/M diverges at 0 with order -1.
        assert_eq!(
            (k(1) / s("M")).limit(big_m, Point::Zero),
            LimitValue::Infinite {
                coefficient: k(1),
                order: -1
            }
        );
        assert_eq!(k(0).leading_term(big_m, Point::Zero), None);
        assert_eq!(k(0).limit(big_m, Point::Zero), LimitValue::Finite(k(0)));
    }

    /// A polynomial in x, y from `(exponents, coefficient)` terms.
    fn poly_from(terms: &[(u32, u32, i64)]) -> Poly {
        use crate::field::poly::Monomial;
        let (x, y) = (Sym::new("x"), Sym::new("y"));
        let mut p = Poly::zero();
        for &(i, j, c) in terms {
            let m = Monomial::var(x, i).mul(&Monomial::var(y, j));
            p = p + &Poly::monomial(q(c, 1), m);
        }
        p
    }

    fn ratfn() -> impl Strategy<Value = RatFn> {
        let poly = || {
            prop::collection::vec((0u32..3, 0u32..3, -3i64..=3), 1..4).prop_map(|t| poly_from(&t))
        };
        (poly(), poly()).prop_map(|(n, d)| RatFn::new(n, d).unwrap_or_else(RatFn::zero))
    }

    /// The normal form: coprime, primitive denominator with positive leading coefficient.
    #[test]
    fn representations_out_of_normal_form_are_caught() {
        let m = Poly::var(Sym::new("m"));
        let two = Poly::constant(crate::field::q(2, 1));
        let not_primitive = RatFn {
            num: m.clone(),
            den: two.clone(),
        };
        assert!(!not_primitive.is_valid());
        let not_coprime = RatFn {
            num: m.clone() * &m,
            den: m.clone(),
        };
        assert!(!not_coprime.is_valid());
        let zero_over_two = RatFn {
            num: Poly::zero(),
            den: two,
        };
        assert!(!zero_over_two.is_valid());
        assert!(RatFn::new(m.clone() * &m, m).unwrap().is_valid());
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

        /// Every result is in normal form, and == agrees with cross-multiplication.
        #[test]
        fn results_are_normal_and_equality_is_cross_multiplication(a in ratfn(), b in ratfn()) {
            let sum = a.clone() + &b;
            let product = a.clone() * &b;
            prop_assert!(a.is_valid() && sum.is_valid() && product.is_valid());
            prop_assert!((sum.clone() - &b).is_valid() && (-a.clone()).is_valid());
            if !b.is_zero() {
                prop_assert!((a.clone() / &b).is_valid());
            }
            let cross = (a.num() * b.den() - &(b.num() * a.den())).is_zero();
            prop_assert_eq!(a == b, cross);
            prop_assert_eq!(sum - &b, a.clone());
            if !b.is_zero() {
                prop_assert_eq!(product / &b, a);
            }
        }
    }

    #[test]
    fn symbolic_free_rod_solve_matches_closed_form_and_conserves_energy() {
        let (m, big_m, i, a, v0, e) = (s("m"), s("M"), s("I"), s("a"), s("v0"), s("e"));
        // Unknowns (v, V, w): m v + M V = m v0; m a v + I w = m a v0; V + w a - v = e v0.
        let matrix = vec![
            vec![m.clone(), big_m.clone(), k(0)],
            vec![m.clone() * &a, k(0), i.clone()],
            vec![-k(1), k(1), a.clone()],
        ];
        let rhs = vec![m.clone() * &v0, m.clone() * &a * &v0, e.clone() * &v0];
        let x = crate::field::linear::solve_linear(matrix, rhs).unwrap();
        let (v, big_v, w) = (&x[0], &x[1], &x[2]);

        let j = (k(1) + &e) * &v0
            / (k(1) / m.clone() + &(k(1) / big_m.clone()) + &(a.clone() * &a / &i));
        assert_eq!(*v, v0.clone() - &(j.clone() / &m));
        assert_eq!(*big_v, j.clone() / &big_m);
        assert_eq!(*w, j.clone() * &a / &i);
        let energy = |v: &RatFn, big_v: &RatFn, w: &RatFn| {
            m.clone() * &v.square()
                + &(big_m.clone() * &big_v.square())
                + &(i.clone() * &w.square())
        };
        let elastic = |f: &RatFn| f.subs(Sym::new("e"), &k(1)).unwrap();
        let (ve, bve, we) = (elastic(v), elastic(big_v), elastic(w));
        assert!((energy(&ve, &bve, &we) - m.clone() * &v0.square()).is_identically_zero());
    }
}
