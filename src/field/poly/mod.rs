//! Sparse multivariate polynomials over [`Q`] in named symbols: the numerators and denominators
//! of [`RatFn`](super::RatFn).
//!
//! * [`Sym`] is an interned symbol name. Symbols compare **by name** (plain byte order, so
//!   `"I" < "M" < "a" < "m" < "v0"`), never by interning order: output is deterministic.
//! * [`Monomial`] is a product of symbols with positive exponents, sorted by symbol.
//! * [`Poly`] maps monomials to nonzero rational coefficients.
//!
//! **Monomial order: graded lexicographic.** A monomial of higher total degree is larger; at equal
//! degree, the one with the larger exponent of the first symbol (in name order) where they differ
//! is larger. `Display` prints terms from the largest down, e.g. `2*M*m*v0 - 3*a^2*m + 1/2`, so
//! the leading term (the one [`Poly::content`] makes positive) comes first.
//!
//! [`Poly::gcd`] is a genuine multivariate GCD over Q: trivial cases (constants, monomials, one
//! argument dividing the other, symbols present in only one argument) are answered directly,
//! otherwise a primitive pseudo-remainder sequence runs in one main symbol with contents
//! computed recursively in the others.

mod gcd;
mod monomial;
mod sym;
mod work;

pub use monomial::Monomial;
pub use sym::Sym;
pub use work::{WorkExhausted, metered};

use super::{Field, Q};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

///
/// The representation is canonical (no zero coefficients), so `==` is equality of polynomials.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, Poly, Sym};
/// let (m, big_m) = (Poly::var(Sym::new("m")), Poly::var(Sym::new("M")));
/// let p = (m.clone() + &big_m) * &(m.clone() - &big_m);
/// assert_eq!(p.to_string(), "-M^2 + m^2");
/// assert_eq!((Poly::constant(q(1, 2)) * &m).to_string(), "1/2*m");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    terms: BTreeMap<Monomial, Q>,
}

/// Adds `c * m` to `terms`, dropping the entry if it cancels.
fn add_term(terms: &mut BTreeMap<Monomial, Q>, m: Monomial, c: Q) {
    if c.is_zero() {
        return;
    }
    match terms.entry(m) {
        std::collections::btree_map::Entry::Vacant(v) => {
            v.insert(c);
        }
        std::collections::btree_map::Entry::Occupied(mut o) => {
            *o.get_mut() += c;
            if o.get().is_zero() {
                o.remove();
            }
        }
    }
}

impl Poly {
    /// Whether the representation holds its invariant: no zero coefficient, every monomial
    /// valid ([`Monomial::is_valid`]). Every operation keeps it; the property tests assert it.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let (m, big_m) = (Poly::var(Sym::new("m")), Poly::var(Sym::new("M")));
    /// assert!(((m.clone() + &big_m) * &(m - &big_m)).is_valid());
    /// ```
    pub fn is_valid(&self) -> bool {
        self.terms.iter().all(|(m, c)| !c.is_zero() && m.is_valid())
    }

    /// The constant polynomial `c` (the zero polynomial when `c == 0`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly};
    /// assert_eq!(Poly::constant(q(-3, 4)).to_string(), "-3/4");
    /// assert!(Poly::constant(q(0, 1)).is_zero());
    /// ```
    pub fn constant(c: Q) -> Poly {
        Poly::monomial(c, Monomial::one())
    }

    /// The polynomial `sym`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// assert_eq!(Poly::var(Sym::new("v0")).to_string(), "v0");
    /// ```
    pub fn var(sym: Sym) -> Poly {
        Poly::monomial(Q::one(), Monomial::var(sym, 1))
    }

    /// The single term `c * m`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, q, Poly, Sym};
    /// let t = Poly::monomial(q(2, 1), Monomial::var(Sym::new("a"), 2));
    /// assert_eq!(t.to_string(), "2*a^2");
    /// ```
    pub fn monomial(c: Q, m: Monomial) -> Poly {
        let mut terms = BTreeMap::new();
        add_term(&mut terms, m, c);
        Poly { terms }
    }

    /// `true` for the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let m = Poly::var(Sym::new("m"));
    /// assert!((m.clone() - &m).is_zero());
    /// ```
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value when the polynomial is a constant (including 0), else `None`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// assert_eq!(Poly::constant(q(5, 2)).as_constant(), Some(q(5, 2)));
    /// assert_eq!(Poly::var(Sym::new("m")).as_constant(), None);
    /// ```
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.len() {
            0 => Some(Q::zero()),
            1 => self.terms.get(&Monomial::one()).cloned(),
            _ => None,
        }
    }

    /// The terms `(monomial, coefficient)` in increasing monomial order.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let p = Poly::var(Sym::new("m")) + &Poly::var(Sym::new("M"));
    /// let shown: Vec<String> = p.terms().map(|(m, c)| format!("{c}*{m}")).collect();
    /// assert_eq!(shown, ["1*m", "1*M"]);
    /// ```
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &Q)> {
        self.terms.iter()
    }

    /// The polynomial's size in 64-bit words: for every coefficient, the words of its numerator
    /// and denominator, two at least (the measure of [`metered`] work and of the textbook
    /// parser's budget).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// assert_eq!(Poly::var(Sym::new("m")).words(), 2);
    /// assert_eq!(Poly::constant(q(i64::MAX, 1) * q(4, 1)).words(), 3); // 65 bits over 1
    /// ```
    pub fn words(&self) -> u64 {
        self.terms
            .values()
            .map(|c| c.numer().bits() / 64 + c.denom().bits() / 64 + 2)
            .sum()
    }

    /// The largest term in the monomial order, `None` for the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, q, Poly, Sym};
    /// let a = Sym::new("a");
    /// let p = Poly::var(a).pow(2) * &Poly::constant(q(3, 1)) + &Poly::var(Sym::new("m"));
    /// assert_eq!(p.leading_term(), Some((&Monomial::var(a, 2), &q(3, 1))));
    /// ```
    pub fn leading_term(&self) -> Option<(&Monomial, &Q)> {
        self.terms.last_key_value()
    }

    /// The total degree (0 for constants and for the zero polynomial).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let p = Poly::var(Sym::new("a")).pow(2) * &Poly::var(Sym::new("m"));
    /// assert_eq!(p.total_degree(), 3);
    /// ```
    pub fn total_degree(&self) -> u32 {
        self.terms.keys().map(Monomial::degree).max().unwrap_or(0)
    }

    /// The degree in `sym` (0 when `sym` does not occur, including for the zero polynomial).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let (a, m) = (Sym::new("a"), Sym::new("m"));
    /// let p = Poly::var(a).pow(2) * &Poly::var(m) + &Poly::var(m).pow(3);
    /// assert_eq!((p.degree_in(a), p.degree_in(m), p.degree_in(Sym::new("M"))), (2, 3, 0));
    /// ```
    pub fn degree_in(&self, sym: Sym) -> u32 {
        self.terms
            .keys()
            .map(|m| m.exponent(sym))
            .max()
            .unwrap_or(0)
    }

    /// The lowest power of `sym` present (0 for the zero polynomial).
    pub(crate) fn low_degree_in(&self, sym: Sym) -> u32 {
        self.terms
            .keys()
            .map(|m| m.exponent(sym))
            .min()
            .unwrap_or(0)
    }

    /// The coefficient of `sym^k`, as a polynomial in the other symbols.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let (a, m) = (Sym::new("a"), Sym::new("m"));
    /// let p = Poly::var(a).pow(2) * &Poly::var(m) + &Poly::var(a).pow(2) + &Poly::var(m);
    /// assert_eq!(p.coeff_in(a, 2).to_string(), "m + 1");
    /// assert_eq!(p.coeff_in(a, 0).to_string(), "m");
    /// assert!(p.coeff_in(a, 1).is_zero());
    /// ```
    pub fn coeff_in(&self, sym: Sym, k: u32) -> Poly {
        let mut terms = BTreeMap::new();
        for (m, c) in &self.terms {
            let (rest, e) = m.split(sym);
            if e == k {
                terms.insert(rest, c.clone());
            }
        }
        Poly { terms }
    }

    /// The coefficients of `1, sym, sym^2, ...` up to the degree in `sym` (empty for zero).
    fn to_univariate(&self, sym: Sym) -> Vec<Poly> {
        let mut out = Vec::new();
        if self.is_zero() {
            return out;
        }
        out.resize(self.degree_in(sym) as usize + 1, Poly::zero());
        for (m, c) in &self.terms {
            let (rest, e) = m.split(sym);
            out[e as usize].terms.insert(rest, c.clone());
        }
        out
    }

    /// `sum_k coeffs[k] * sym^k`.
    fn from_univariate(sym: Sym, coeffs: &[Poly]) -> Poly {
        let mut terms = BTreeMap::new();
        for (k, c) in coeffs.iter().enumerate() {
            let x = Monomial::var(sym, k as u32);
            for (m, v) in &c.terms {
                terms.insert(m.mul(&x), v.clone());
            }
        }
        Poly { terms }
    }

    /// The set of symbols that occur.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let p = Poly::var(Sym::new("m")) * &Poly::var(Sym::new("M"));
    /// let names: Vec<&str> = p.symbols().into_iter().map(Sym::name).collect();
    /// assert_eq!(names, ["M", "m"]);
    /// ```
    pub fn symbols(&self) -> BTreeSet<Sym> {
        self.terms
            .keys()
            .flat_map(|m| m.0.iter().map(|&(s, _)| s))
            .collect()
    }

    /// `self * c` for a rational `c`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// assert_eq!(Poly::var(Sym::new("m")).scale(&q(-2, 3)).to_string(), "-2/3*m");
    /// ```
    pub fn scale(&self, c: &Q) -> Poly {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, v)| (m.clone(), v * c)).collect(),
        }
    }

    /// `self^n` (with `p^0 = 1`, also for the zero polynomial).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let p = Poly::var(Sym::new("a")) + &Poly::var(Sym::new("b"));
    /// assert_eq!(p.pow(2).to_string(), "a^2 + 2*a*b + b^2");
    /// ```
    pub fn pow(&self, n: u32) -> Poly {
        let mut result = Poly::one();
        let mut base = self.clone();
        let mut n = n;
        while n > 0 {
            if n & 1 == 1 {
                result = result * &base;
            }
            n >>= 1;
            if n > 0 {
                base = base.clone() * &base;
            }
        }
        result
    }

    /// The partial derivative with respect to `sym`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let (a, m) = (Sym::new("a"), Sym::new("m"));
    /// let p = Poly::var(a).pow(3) * &Poly::var(m) + &Poly::var(m);
    /// assert_eq!(p.derivative(a).to_string(), "3*a^2*m");
    /// ```
    pub fn derivative(&self, sym: Sym) -> Poly {
        let mut terms = BTreeMap::new();
        for (m, c) in &self.terms {
            let (rest, e) = m.split(sym);
            if e > 0 {
                let m = rest.mul(&Monomial::var(sym, e - 1));
                add_term(&mut terms, m, c * Q::from_integer(BigInt::from(e)));
            }
        }
        Poly { terms }
    }

    /// Substitutes the polynomial `value` for `sym`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// let (a, b) = (Sym::new("a"), Sym::new("b"));
    /// let p = Poly::var(a).pow(2) + &Poly::var(b);
    /// let shifted = p.subs(a, &(Poly::var(b) + &Poly::constant(q(1, 1))));
    /// assert_eq!(shifted.to_string(), "b^2 + 3*b + 1");
    /// ```
    pub fn subs(&self, sym: Sym, value: &Poly) -> Poly {
        let coeffs = self.to_univariate(sym);
        // Horner in `sym`.
        let mut acc = Poly::zero();
        for c in coeffs.iter().rev() {
            acc = acc * value + c;
        }
        acc
    }

    /// Simultaneous homogenised substitution: for each `(sym, p, q, d)`, `sym := p/q`, the whole
    /// polynomial multiplied by `q^d` (`d` at least the degree in `sym`), so the result stays a
    /// polynomial.
    pub(crate) fn subs_homogeneous(&self, subs: &[(Sym, &Poly, &Poly, u32)]) -> Poly {
        // Powers of every p and q up to d.
        let powers: Vec<(Vec<Poly>, Vec<Poly>)> = subs
            .iter()
            .map(|&(_, p, q, d)| {
                let mut ps = vec![Poly::one()];
                let mut qs = vec![Poly::one()];
                for k in 1..=d as usize {
                    ps.push(ps[k - 1].clone() * p);
                    qs.push(qs[k - 1].clone() * q);
                }
                (ps, qs)
            })
            .collect();
        let mut acc = Poly::zero();
        for (m, c) in &self.terms {
            let mut rest = m.clone();
            let mut term = Poly::one();
            for (i, &(sym, _, _, d)) in subs.iter().enumerate() {
                let (r, e) = rest.split(sym);
                rest = r;
                let (ps, qs) = &powers[i];
                term = term * &ps[e as usize] * &qs[(d - e) as usize];
            }
            acc = acc + &(term * &Poly::monomial(c.clone(), rest));
        }
        acc
    }

    /// Evaluates in any [`Field`], with `value_of` giving each symbol's value; `None` when a
    /// symbol has no value.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Field, Poly, Q, Sym};
    /// let (a, m) = (Sym::new("a"), Sym::new("m"));
    /// let p = Poly::var(a).pow(2) * &Poly::var(m) + &Poly::constant(q(1, 2));
    /// let exact = p.eval(&|s: Sym| (s == a).then(|| q(1, 3)).or(Some(q(3, 1))));
    /// assert_eq!(exact, Some(q(5, 6)));
    /// assert_eq!(p.eval(&|_: Sym| Some(2.0f64)), Some(8.5));
    /// assert_eq!(p.eval(&|s: Sym| (s == a).then_some(Q::from_i64(1))), None);
    /// ```
    pub fn eval<F: Field>(&self, value_of: &impl Fn(Sym) -> Option<F>) -> Option<F> {
        let mut values = BTreeMap::new();
        for s in self.symbols() {
            values.insert(s, value_of(s)?);
        }
        let mut acc = F::zero();
        for (m, c) in &self.terms {
            let mut t = F::from_rational(c);
            for &(s, e) in &m.0 {
                let v = &values[&s];
                for _ in 0..e {
                    t = t * v;
                }
            }
            acc = acc + &t;
        }
        Some(acc)
    }

    /// The rational content: the rational `c` with the sign of the leading coefficient such that
    /// `self / c` has coprime integer coefficients; 0 for the zero polynomial.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// let m = Poly::var(Sym::new("m"));
    /// let p = m.scale(&q(-2, 3)) + &Poly::constant(q(4, 9));
    /// assert_eq!(p.content(), q(-2, 9));
    /// assert_eq!(p.primitive().to_string(), "3*m - 2");
    /// ```
    pub fn content(&self) -> Q {
        let Some((_, lc)) = self.leading_term() else {
            return Q::zero();
        };
        let mut num = BigInt::zero();
        let mut den = BigInt::one();
        for c in self.terms.values() {
            num = num.gcd(c.numer());
            den = den.lcm(c.denom());
        }
        let c = Q::new(num, den);
        if lc.is_negative() { -c } else { c }
    }

    /// `self / content()`: coprime integer coefficients with a positive leading coefficient (the
    /// zero polynomial stays zero).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// let p = Poly::var(Sym::new("m")).scale(&q(-1, 2)) + &Poly::constant(q(3, 4));
    /// assert_eq!(p.primitive().to_string(), "2*m - 3");
    /// ```
    pub fn primitive(&self) -> Poly {
        let c = self.content();
        if c.is_zero() || c.is_one() {
            self.clone()
        } else {
            self.scale(&c.recip())
        }
    }

    /// Exact division: `Some(q)` with `q * divisor == self`, or `None` when `divisor` does not
    /// divide `self` in Q\[symbols\].
    ///
    /// # Panics
    /// When `divisor` is the zero polynomial (a programming error).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{Poly, Sym};
    /// let (x, y) = (Poly::var(Sym::new("x")), Poly::var(Sym::new("y")));
    /// let p = x.pow(2) - &y.pow(2);
    /// assert_eq!(p.div_exact(&(x.clone() - &y)).unwrap().to_string(), "x + y");
    /// assert_eq!(p.div_exact(&(x.clone() + &x.pow(2))), None);
    /// ```
    pub fn div_exact(&self, divisor: &Poly) -> Option<Poly> {
        let Some((lm, lc)) = divisor.leading_term() else {
            panic!("division by the zero polynomial");
        };
        if self.is_zero() {
            return Some(Poly::zero());
        }
        if let Some(c) = divisor.as_constant() {
            return Some(self.scale(&c.recip()));
        }
        if self.total_degree() < divisor.total_degree() {
            return None;
        }
        for &(s, e) in &lm.0 {
            if self.degree_in(s) < e {
                return None;
            }
        }
        let mut rem = self.clone();
        let mut quot = BTreeMap::new();
        while let Some((rm, rc)) = rem.terms.last_key_value() {
            let m = rm.div(lm)?;
            let c = rc / lc;
            for (dm, dc) in &divisor.terms {
                add_term(&mut rem.terms, dm.mul(&m), -(dc * &c));
            }
            quot.insert(m, c);
        }
        Some(Poly { terms: quot })
    }
}

impl Zero for Poly {
    fn zero() -> Self {
        Poly::default()
    }

    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}

impl One for Poly {
    fn one() -> Self {
        Poly::constant(Q::one())
    }

    fn is_one(&self) -> bool {
        self.terms.len() == 1 && self.terms.get(&Monomial::one()).is_some_and(Q::is_one)
    }
}

impl<'a> Add<&'a Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: &'a Poly) -> Poly {
        for (m, c) in &rhs.terms {
            add_term(&mut self.terms, m.clone(), c.clone());
        }
        self
    }
}

impl<'a> Sub<&'a Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: &'a Poly) -> Poly {
        for (m, c) in &rhs.terms {
            add_term(&mut self.terms, m.clone(), -c.clone());
        }
        self
    }
}

impl<'a> Mul<&'a Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &'a Poly) -> Poly {
        &self * rhs
    }
}

impl<'a> Mul<&'a Poly> for &Poly {
    type Output = Poly;
    fn mul(self, rhs: &'a Poly) -> Poly {
        work::charge_product(self, rhs);
        let mut terms = BTreeMap::new();
        for (m1, c1) in &self.terms {
            for (m2, c2) in &rhs.terms {
                add_term(&mut terms, m1.mul(m2), c1 * c2);
            }
        }
        Poly { terms }
    }
}

impl<'a> Add<&'a Poly> for &Poly {
    type Output = Poly;
    fn add(self, rhs: &'a Poly) -> Poly {
        self.clone() + rhs
    }
}

impl<'a> Sub<&'a Poly> for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &'a Poly) -> Poly {
        self.clone() - rhs
    }
}

impl Add for Poly {
    type Output = Poly;
    fn add(self, rhs: Poly) -> Poly {
        self + &rhs
    }
}

impl Sub for Poly {
    type Output = Poly;
    fn sub(self, rhs: Poly) -> Poly {
        self - &rhs
    }
}

impl Mul for Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        &self * &rhs
    }
}

impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for c in self.terms.values_mut() {
            *c = -c.clone();
        }
        self
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        -self.clone()
    }
}

impl fmt::Display for Poly {
    /// Terms from the largest monomial down; `-` for negative terms; coefficients as reduced
    /// fractions, omitted when 1: `2*M*m*v0 - 3*a^2*m + 1/2`. The zero polynomial is `0`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        for (i, (m, c)) in self.terms.iter().rev().enumerate() {
            let sign = if c.is_negative() { "-" } else { "+" };
            match (i, sign) {
                (0, "-") => f.write_str("-")?,
                (0, _) => {}
                _ => write!(f, " {sign} ")?,
            }
            let abs = c.abs();
            if m.0.is_empty() {
                write!(f, "{abs}")?;
            } else if abs.is_one() {
                write!(f, "{m}")?;
            } else {
                write!(f, "{abs}*{m}")?;
            }
        }
        Ok(())
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use proptest::prelude::*;

    /// The symbol `name` as a polynomial (also used by the gcd tests).
    pub(super) fn v(name: &str) -> Poly {
        Poly::var(Sym::new(name))
    }

    /// The integer constant `n` as a polynomial.
    pub(super) fn k(n: i64) -> Poly {
        Poly::constant(q(n, 1))
    }

    #[test]
    fn symbols_order_by_name_not_by_creation() {
        let z = Sym::new("zz_first_created");
        let a = Sym::new("aa_second_created");
        assert!(a < z);
        let p = v("zz_first_created") + &v("aa_second_created");
        assert_eq!(p.to_string(), "aa_second_created + zz_first_created");
    }

    #[test]
    fn display_is_graded_lex_with_reduced_fractions() {
        let p = (v("M") * &v("m") * &v("v0")).scale(&q(2, 1))
            - &(v("a").pow(2) * &v("m")).scale(&q(3, 1))
            + &Poly::constant(q(2, 4));
        assert_eq!(p.to_string(), "2*M*m*v0 - 3*a^2*m + 1/2");
        assert_eq!((-v("m")).to_string(), "-m");
        assert_eq!(Poly::zero().to_string(), "0");
        assert_eq!((v("M") + &v("m")).pow(2).to_string(), "M^2 + 2*M*m + m^2");
    }

    #[test]
    fn gcd_of_shared_power() {
        let (x, y, z) = (v("x"), v("y"), v("z"));
        let a = (x.clone() + &y).pow(3) * &(x.clone() - &z.scale(&q(2, 1)));
        let b = (x.clone() + &y).pow(2) * &(x.pow(2) + &z);
        assert_eq!(Poly::gcd(&a, &b), (x.clone() + &y).pow(2));
        // Rational content does not matter.
        assert_eq!(
            Poly::gcd(&a.scale(&q(-3, 7)), &b.scale(&q(5, 2))),
            (x + &y).pow(2)
        );
    }

    #[test]
    fn gcd_of_coprime_and_trivial_cases() {
        let (x, y, z) = (v("x"), v("y"), v("z"));
        assert!(Poly::gcd(&(x.clone() + &y), &(x.clone() - &y)).is_one());
        assert!(Poly::gcd(&(x.pow(2) + &y), &(y.clone() * &z + &k(1))).is_one());
        assert_eq!(
            Poly::gcd(&(x.pow(2) * &y), &(x.pow(3) + &(x.clone() * &z))),
            x
        );
        assert!(Poly::gcd(&k(6), &(x.clone() + &k(1))).is_one());
        assert_eq!(Poly::gcd(&Poly::zero(), &x.scale(&q(-4, 1))), x);
        assert!(Poly::gcd(&Poly::zero(), &Poly::zero()).is_zero());
        // A factor involving a symbol only one argument has.
        let a = (x.clone() + &k(1)) * &(y.clone() + &z);
        let b = (x.clone() + &k(1)) * &(x.clone() - &k(3));
        assert_eq!(Poly::gcd(&a, &b), x.clone() + &k(1));
    }

    #[test]
    fn gcd_of_physics_sized_polynomials() {
        let (m, big_m, a, r, v0) = (v("m"), v("M"), v("a"), v("r"), v("v0"));
        let d = big_m.clone() * &r.pow(2) + &(m.clone() * &r.pow(2)) + &(m.clone() * &a.pow(2));
        let f1 = m.clone() * &v0 - &(big_m.clone() * &a);
        let f2 = big_m.pow(2) + &(m.clone() * &r) + &v0;
        let g = Poly::gcd(&(d.pow(2) * &f1), &(d.clone() * &f2 * &m));
        assert_eq!(g, d);
    }

    #[test]
    fn div_exact_multivariate() {
        let (x, y, z) = (v("x"), v("y"), v("z"));
        let f = x.clone() * &y - &z + &k(2);
        let g = x.pow(2) + &(y.clone() * &z).scale(&q(1, 3));
        assert_eq!((f.clone() * &g).div_exact(&g), Some(f.clone()));
        assert_eq!((f.clone() * &g + &k(1)).div_exact(&g), None);
        assert_eq!(f.div_exact(&k(2)), Some(f.scale(&q(1, 2))));
        assert_eq!(Poly::zero().div_exact(&g), Some(Poly::zero()));
    }

    #[test]
    #[should_panic(expected = "division by the zero polynomial")]
    fn div_exact_by_zero_is_a_programming_error() {
        let _ = v("x").div_exact(&Poly::zero());
    }

    #[test]
    fn subs_derivative_and_coefficients() {
        let (x, y) = (v("x"), v("y"));
        let p = x.pow(3) * &y + &x.scale(&q(2, 1)) + &k(5);
        assert_eq!(p.derivative(Sym::new("x")).to_string(), "3*x^2*y + 2");
        assert_eq!(p.subs(Sym::new("x"), &k(2)).to_string(), "8*y + 9");
        assert_eq!(p.coeff_in(Sym::new("x"), 3), y);
        assert_eq!(p.degree_in(Sym::new("x")), 3);
        assert_eq!(p.low_degree_in(Sym::new("y")), 0);
        let h = p.subs_homogeneous(&[(Sym::new("x"), &y, &k(2), 3)]);
        // 8 * (y^3/8 * y + y + 5) = y^4 + 8y + 40
        assert_eq!(h.to_string(), "y^4 + 8*y + 40");
    }

    /// A polynomial in x, y, z from `(exponents, coefficient)` terms.
    fn from_terms(terms: &[(u32, u32, u32, i64)]) -> Poly {
        let (x, y, z) = (Sym::new("x"), Sym::new("y"), Sym::new("z"));
        let mut p = Poly::zero();
        for &(i, j, l, c) in terms {
            let m = Monomial::var(x, i)
                .mul(&Monomial::var(y, j))
                .mul(&Monomial::var(z, l));
            p = p + &Poly::monomial(q(c, 1), m);
        }
        p
    }

    fn small_poly() -> impl Strategy<Value = Poly> {
        prop::collection::vec((0u32..3, 0u32..3, 0u32..3, -4i64..=4), 1..5)
            .prop_map(|t| from_terms(&t))
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

        /// gcd(f h, g h) is a common divisor of both products and a multiple of h.
        #[test]
        fn gcd_is_a_common_divisor_containing_the_shared_factor(
            f in small_poly(), g in small_poly(), h in small_poly()
        ) {
            let (a, b) = (f.clone() * &h, g.clone() * &h);
            prop_assert!(a.is_valid() && b.is_valid() && (f.clone() + &g).is_valid());
            prop_assert!((f.clone() - &f).is_valid() && (-g.clone()).is_valid());
            let d = Poly::gcd(&a, &b);
            prop_assert!(d.is_valid());
            if a.is_zero() && b.is_zero() {
                prop_assert!(d.is_zero());
            } else {
                prop_assert!(a.div_exact(&d).is_some(), "{d} does not divide {a}");
                prop_assert!(b.div_exact(&d).is_some(), "{d} does not divide {b}");
                if !h.is_zero() {
                    prop_assert!(d.div_exact(&h).is_some(), "{h} does not divide {d}");
                }
                prop_assert_eq!(d.primitive(), d.clone());
            }
        }

        /// (f g) / g = f, and f g + 1 is not a multiple of a non-constant g.
        #[test]
        fn div_exact_inverts_multiplication(f in small_poly(), g in small_poly()) {
            if !g.is_zero() {
                prop_assert_eq!((f.clone() * &g).div_exact(&g), Some(f.clone()));
                if g.as_constant().is_none() {
                    prop_assert_eq!((f * &g + &Poly::one()).div_exact(&g), None);
                }
            }
        }
    }

    #[test]
    fn gcd_of_larger_inputs() {
        // Eight symbols, total degree up to 12: the size the claims need.
        let names = ["I", "M", "a", "e", "l", "m", "r", "v0"];
        let vs: Vec<Poly> = names.iter().map(|n| v(n)).collect();
        let d = vs[1].clone() * &vs[6].pow(2) + &(vs[5].clone() * &vs[2].pow(2)) + &vs[0];
        let f = vs[3].clone() * &vs[7] - &(vs[4].pow(2) * &vs[5]) + &k(3);
        let g = vs[2].pow(3) + &(vs[1].clone() * &vs[3] * &vs[7]) - &vs[6];
        let a = d.pow(3) * &f.pow(2);
        let b = d.pow(2) * &g * &f;
        let h = Poly::gcd(&a, &b);
        assert_eq!(h, (d.pow(2) * &f).primitive());
        // Coprime, where a remainder sequence would swell: the modular test answers it.
        let (a, b) = (d.pow(4) + &g.pow(2), f.pow(3) + &d);
        assert!(Poly::gcd(&a, &b).is_one());
    }

    #[test]
    fn invalid_representations_are_caught() {
        let zero_coefficient = Poly {
            terms: BTreeMap::from([(Monomial::var(Sym::new("m"), 1), Q::zero())]),
        };
        assert!(!zero_coefficient.is_valid());
        let unsorted = Monomial(vec![(Sym::new("m"), 1), (Sym::new("M"), 1)]);
        assert!(!unsorted.is_valid());
        assert!(!Monomial(vec![(Sym::new("m"), 0)]).is_valid());
        assert!(
            Monomial::var(Sym::new("M"), 1)
                .mul(&Monomial::var(Sym::new("m"), 1))
                .is_valid()
        );
    }

    #[test]
    fn eval_in_q_and_f64() {
        let (x, y) = (v("x"), v("y"));
        let p = x.pow(2) - &y.scale(&q(1, 3));
        let at = |s: Sym| Some(if s.name() == "x" { q(1, 2) } else { q(3, 1) });
        assert_eq!(p.eval(&at), Some(q(-3, 4)));
        assert_eq!(p.eval(&|_s: Sym| Some(3.0f64)), Some(8.0));
    }
}
