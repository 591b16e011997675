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

use super::{Field, Q};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BTreeSet, HashSet};
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::{Mutex, OnceLock};

/// An interned symbol name such as `m`, `M` or `v0`; cheap to copy and compare.
///
/// Symbols are ordered by name (plain string order), so sorting never depends on which symbol
/// was created first.
///
/// # Examples
/// ```
/// use rodimpact::field::Sym;
/// let (m, big_m) = (Sym::new("m"), Sym::new("M"));
/// assert_eq!(m, Sym::new("m"));
/// assert!(big_m < m); // "M" < "m" in string order
/// assert_eq!(m.name(), "m");
/// ```
#[derive(Clone, Copy, Eq)]
pub struct Sym(&'static str);

impl Sym {
    /// The symbol called `name`, interned once for the life of the program.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Sym;
    /// assert_eq!(Sym::new("v0").to_string(), "v0");
    /// ```
    pub fn new(name: &str) -> Sym {
        static NAMES: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
        let mut names = NAMES
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        if let Some(&interned) = names.get(name) {
            return Sym(interned);
        }
        let interned: &'static str = Box::leak(name.to_owned().into_boxed_str());
        names.insert(interned);
        Sym(interned)
    }

    /// The symbol's name.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::Sym;
    /// assert_eq!(Sym::new("a").name(), "a");
    /// ```
    pub fn name(self) -> &'static str {
        self.0
    }
}

impl PartialEq for Sym {
    fn eq(&self, other: &Self) -> bool {
        // Interned: equal names share one allocation.
        std::ptr::eq(self.0, other.0)
    }
}

impl Hash for Sym {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.hash(state);
    }
}

impl Ord for Sym {
    fn cmp(&self, other: &Self) -> Ordering {
        if self == other {
            Ordering::Equal
        } else {
            self.0.cmp(other.0)
        }
    }
}

impl PartialOrd for Sym {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}

/// A product of symbols with positive exponents, kept sorted by symbol; the empty product is 1.
///
/// Ordered graded-lexicographically (see the [module docs](self)).
///
/// # Examples
/// ```
/// use rodimpact::field::poly::Monomial;
/// use rodimpact::field::Sym;
/// let m2 = Monomial::var(Sym::new("m"), 2);
/// assert_eq!(m2.degree(), 2);
/// assert!(Monomial::var(Sym::new("a"), 1) < m2); // lower degree
/// assert!(Monomial::var(Sym::new("a"), 2) > m2); // same degree, "a" < "m"
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Monomial(Vec<(Sym, u32)>);

impl Monomial {
    /// The empty product, 1.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::poly::Monomial;
    /// assert_eq!(Monomial::one().degree(), 0);
    /// ```
    pub fn one() -> Monomial {
        Monomial(Vec::new())
    }

    /// `sym^exp` (the empty product when `exp == 0`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// assert_eq!(Monomial::var(Sym::new("a"), 3).to_string(), "a^3");
    /// ```
    pub fn var(sym: Sym, exp: u32) -> Monomial {
        Monomial(if exp == 0 {
            Vec::new()
        } else {
            vec![(sym, exp)]
        })
    }

    /// The total degree (sum of exponents).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// let m = Monomial::var(Sym::new("a"), 2).mul(&Monomial::var(Sym::new("m"), 1));
    /// assert_eq!(m.degree(), 3);
    /// ```
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&(_, e)| e).sum()
    }

    /// The exponent of `sym` (0 when absent).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// let a = Sym::new("a");
    /// assert_eq!(Monomial::var(a, 2).exponent(a), 2);
    /// assert_eq!(Monomial::var(a, 2).exponent(Sym::new("m")), 0);
    /// ```
    pub fn exponent(&self, sym: Sym) -> u32 {
        self.0
            .iter()
            .find(|&&(s, _)| s == sym)
            .map_or(0, |&(_, e)| e)
    }

    /// The factors `(symbol, exponent)`, sorted by symbol name, exponents positive.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// let (a, m) = (Sym::new("a"), Sym::new("m"));
    /// let mono = Monomial::var(m, 1).mul(&Monomial::var(a, 2));
    /// assert_eq!(mono.factors(), &[(a, 2), (m, 1)]);
    /// ```
    pub fn factors(&self) -> &[(Sym, u32)] {
        &self.0
    }

    /// The product of two monomials.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// let a = Sym::new("a");
    /// assert_eq!(Monomial::var(a, 1).mul(&Monomial::var(a, 2)), Monomial::var(a, 3));
    /// ```
    pub fn mul(&self, other: &Monomial) -> Monomial {
        let mut out = Vec::with_capacity(self.0.len() + other.0.len());
        let (mut i, mut j) = (0, 0);
        while i < self.0.len() && j < other.0.len() {
            let (x, y) = (self.0[i], other.0[j]);
            match x.0.cmp(&y.0) {
                Ordering::Less => {
                    out.push(x);
                    i += 1;
                }
                Ordering::Greater => {
                    out.push(y);
                    j += 1;
                }
                Ordering::Equal => {
                    out.push((x.0, x.1 + y.1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&self.0[i..]);
        out.extend_from_slice(&other.0[j..]);
        Monomial(out)
    }

    /// `self / other` when `other` divides `self`, else `None`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// let a = Sym::new("a");
    /// assert_eq!(Monomial::var(a, 3).div(&Monomial::var(a, 1)), Some(Monomial::var(a, 2)));
    /// assert_eq!(Monomial::var(a, 1).div(&Monomial::var(a, 3)), None);
    /// ```
    pub fn div(&self, other: &Monomial) -> Option<Monomial> {
        let mut out = Vec::with_capacity(self.0.len());
        let mut j = 0;
        for &(s, e) in &self.0 {
            if j < other.0.len() && other.0[j].0 < s {
                return None;
            }
            if j < other.0.len() && other.0[j].0 == s {
                let f = other.0[j].1;
                j += 1;
                match e.cmp(&f) {
                    Ordering::Less => return None,
                    Ordering::Equal => {}
                    Ordering::Greater => out.push((s, e - f)),
                }
            } else {
                out.push((s, e));
            }
        }
        (j == other.0.len()).then_some(Monomial(out))
    }

    /// The greatest common divisor (minimum exponent of each symbol).
    fn gcd(&self, other: &Monomial) -> Monomial {
        Monomial(
            self.0
                .iter()
                .filter_map(|&(s, e)| {
                    let f = other.exponent(s);
                    (f > 0).then_some((s, e.min(f)))
                })
                .collect(),
        )
    }

    /// Splits off `sym`: `(self without sym, exponent of sym)`.
    fn split(&self, sym: Sym) -> (Monomial, u32) {
        let mut exp = 0;
        let rest = self
            .0
            .iter()
            .filter(|&&(s, e)| {
                if s == sym {
                    exp = e;
                }
                s != sym
            })
            .copied()
            .collect();
        (Monomial(rest), exp)
    }
}

impl Ord for Monomial {
    fn cmp(&self, other: &Self) -> Ordering {
        self.degree().cmp(&other.degree()).then_with(|| {
            for (x, y) in self.0.iter().zip(&other.0) {
                if x.0 != y.0 {
                    // `self` has the earlier symbol with a positive exponent.
                    return if x.0 < y.0 {
                        Ordering::Greater
                    } else {
                        Ordering::Less
                    };
                }
                if x.1 != y.1 {
                    return x.1.cmp(&y.1);
                }
            }
            self.0.len().cmp(&other.0.len())
        })
    }
}

impl PartialOrd for Monomial {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for Monomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_empty() {
            return f.write_str("1");
        }
        for (i, &(s, e)) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str("*")?;
            }
            if e == 1 {
                write!(f, "{s}")?;
            } else {
                write!(f, "{s}^{e}")?;
            }
        }
        Ok(())
    }
}

impl fmt::Debug for Monomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// A polynomial over [`Q`] in named symbols: a sparse map from [`Monomial`] to nonzero coefficient.
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

    /// The greatest common divisor in Q\[symbols\], normalised by [`Poly::primitive`] (coprime
    /// integer coefficients, positive leading coefficient); `gcd(0, 0) = 0`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, Poly, Sym};
    /// let (x, y) = (Poly::var(Sym::new("x")), Poly::var(Sym::new("y")));
    /// let a = (x.clone() + &y).pow(2) * &(x.clone() - &y);
    /// let b = (x.clone() + &y).scale(&q(3, 1)) * &(x.clone() + &Poly::constant(q(1, 1)));
    /// assert_eq!(Poly::gcd(&a, &b).to_string(), "x + y");
    /// assert_eq!(Poly::gcd(&x, &y).to_string(), "1");
    /// ```
    pub fn gcd(a: &Poly, b: &Poly) -> Poly {
        if a.is_zero() {
            return b.primitive();
        }
        if b.is_zero() {
            return a.primitive();
        }
        if a.terms.len() == 1 {
            return monomial_gcd(a, b);
        }
        if b.terms.len() == 1 {
            return monomial_gcd(b, a);
        }
        let (sa, sb) = (a.symbols(), b.symbols());
        if let Some(&x) = sa.difference(&sb).next() {
            return gcd_with_coefficients(b, a, x);
        }
        if let Some(&x) = sb.difference(&sa).next() {
            return gcd_with_coefficients(a, b, x);
        }
        // Same symbols from here on. Cheap test first: does one divide the other?
        let (small, large) = if a.terms.len() <= b.terms.len() {
            (a, b)
        } else {
            (b, a)
        };
        if large.div_exact(small).is_some() {
            return small.primitive();
        }
        // Main symbol: the one of least degree (shortest remainder sequence).
        let x = sa
            .iter()
            .copied()
            .min_by_key(|&s| (a.degree_in(s).max(b.degree_in(s)), s))
            .unwrap_or_else(|| unreachable!("non-constant polynomials have symbols"));
        let (fa, fb) = (a.to_univariate(x), b.to_univariate(x));
        let (ca, cb) = (content_of(&fa), content_of(&fb));
        let c = Poly::gcd(&ca, &cb);
        if coprime_in_main_symbol(a, b, x) {
            return c;
        }
        let g = primitive_prs(divide_all(fa, &ca), divide_all(fb, &cb));
        (Poly::from_univariate(x, &g) * &c).primitive()
    }
}

/// The prime modulus of [`coprime_in_main_symbol`]: 2^31 - 1, so products fit in a `u64`.
const PRIME: u64 = 2_147_483_647;

/// A sufficient test that no common divisor of `a` and `b` involves the symbol `x`, so that
/// their gcd is the gcd of their contents in `x` and the remainder sequence can be skipped (the
/// usual case in [`RatFn`](super::RatFn) arithmetic: most gcds are 1).
///
/// The primitive (integer) forms of `a` and `b` are specialised at a fixed point for the other
/// symbols and reduced modulo a prime `p`, at a point where the leading coefficient of `a` in
/// `x` does not vanish mod `p`. By Gauss's lemma a common divisor `h` of degree `k > 0` in `x`
/// can be taken primitive with `a = h g` over Z, so its leading coefficient divides that of `a`
/// and `h` specialises to a common divisor of degree `k` mod `p`. A constant gcd mod `p`
/// therefore proves that there is no such `h`. A positive-degree gcd mod `p` proves nothing (an
/// unlucky point or a real common factor): the caller then runs the full algorithm.
fn coprime_in_main_symbol(a: &Poly, b: &Poly, x: Sym) -> bool {
    let (a, b) = (a.primitive(), b.primitive());
    let symbols: Vec<Sym> = a.symbols().union(&b.symbols()).copied().collect();
    let deg_a = a.degree_in(x) as usize;
    for attempt in 0..2u64 {
        // Fixed, spread-out residues: deterministic, and unlucky only with tiny probability.
        let point: Vec<u64> = (0..symbols.len() as u64)
            .map(|i| (i + 1 + 17 * attempt).wrapping_mul(2_654_435_761) % PRIME)
            .collect();
        let specialise = |p: &Poly| {
            let mut v = vec![0u64; p.degree_in(x) as usize + 1];
            for (m, c) in &p.terms {
                let mut t = residue(c);
                let mut k = 0;
                for &(s, e) in &m.0 {
                    if s == x {
                        k = e as usize;
                    } else {
                        let i = symbols.binary_search(&s).unwrap_or(0);
                        t = t * pow_mod(point[i], u64::from(e)) % PRIME;
                    }
                }
                v[k] = (v[k] + t) % PRIME;
            }
            v
        };
        let (ua, ub) = (specialise(&a), specialise(&b));
        if ua[deg_a] != 0 && gcd_degree_mod_p(ua, ub) == 0 {
            return true;
        }
    }
    false
}

/// An integer (the coefficients of a primitive polynomial) modulo [`PRIME`].
fn residue(c: &Q) -> u64 {
    let r = c.numer().mod_floor(&BigInt::from(PRIME));
    u64::try_from(r).unwrap_or_else(|_| unreachable!("a residue mod p fits in u64"))
}

/// `base^exp` modulo [`PRIME`].
fn pow_mod(mut base: u64, mut exp: u64) -> u64 {
    let mut acc = 1u64;
    base %= PRIME;
    while exp > 0 {
        if exp & 1 == 1 {
            acc = acc * base % PRIME;
        }
        base = base * base % PRIME;
        exp >>= 1;
    }
    acc
}

/// The degree of the gcd of two univariate polynomials over Z/p (coefficients from degree 0
/// up), by Euclid's algorithm; 0 also when both are zero.
fn gcd_degree_mod_p(mut f: Vec<u64>, mut g: Vec<u64>) -> usize {
    let trim_p = |v: &mut Vec<u64>| {
        while v.last() == Some(&0) {
            v.pop();
        }
    };
    trim_p(&mut f);
    trim_p(&mut g);
    while !g.is_empty() {
        // f := f mod g
        let dg = g.len() - 1;
        let inv = pow_mod(g[dg], PRIME - 2);
        while f.len() > dg {
            let df = f.len() - 1;
            let factor = f[df] * inv % PRIME;
            for (fi, gj) in f[df - dg..].iter_mut().zip(&g) {
                *fi = (*fi + PRIME - factor * gj % PRIME) % PRIME;
            }
            trim_p(&mut f);
        }
        std::mem::swap(&mut f, &mut g);
    }
    f.len().saturating_sub(1)
}

/// gcd when `t` is a single term: the monomial dividing `t` and every term of `other`.
fn monomial_gcd(t: &Poly, other: &Poly) -> Poly {
    let mut m = t.terms.keys().next().cloned().unwrap_or_else(Monomial::one);
    for om in other.terms.keys() {
        if m.0.is_empty() {
            break;
        }
        m = m.gcd(om);
    }
    Poly::monomial(Q::one(), m)
}

/// gcd(p, q) where `x` occurs in `q` but not in `p`: the gcd of `p` and `q`'s coefficients in `x`.
fn gcd_with_coefficients(p: &Poly, q: &Poly, x: Sym) -> Poly {
    let mut g = p.primitive();
    for c in q.to_univariate(x) {
        if g.as_constant().is_some() {
            break;
        }
        if !c.is_zero() {
            g = Poly::gcd(&g, &c);
        }
    }
    g
}

/// The gcd of a list of polynomials (the content of a univariate view).
fn content_of(coeffs: &[Poly]) -> Poly {
    let mut g = Poly::zero();
    for c in coeffs {
        if g.as_constant().is_some_and(|k| !k.is_zero()) {
            break;
        }
        g = Poly::gcd(&g, c);
    }
    g
}

/// Divides every coefficient by `c`, which divides them all (it is their gcd).
fn divide_all(coeffs: Vec<Poly>, c: &Poly) -> Vec<Poly> {
    if c.is_one() {
        return coeffs;
    }
    coeffs
        .into_iter()
        .map(|p| {
            p.div_exact(c)
                .unwrap_or_else(|| unreachable!("a gcd divides its arguments"))
        })
        .collect()
}

/// Drops trailing zero coefficients.
fn trim(v: &mut Vec<Poly>) {
    while v.last().is_some_and(Poly::is_zero) {
        v.pop();
    }
}

/// Pseudo-remainder of `f` by `g` (univariate views, `g` nonzero): `lc(g)^k f - Q g`.
fn prem(f: &[Poly], g: &[Poly]) -> Vec<Poly> {
    let mut r = f.to_vec();
    let dg = g.len() - 1;
    let lg = &g[dg];
    let lg_const = lg.as_constant();
    trim(&mut r);
    while r.len() > dg {
        let dr = r.len() - 1;
        let lr = r[dr].clone();
        let shift = dr - dg;
        match &lg_const {
            // A constant leading coefficient: divide instead of multiplying the rest.
            Some(k) => {
                let factor = lr.scale(&k.recip());
                for j in 0..=dg {
                    r[j + shift] = r[j + shift].clone() - &(factor.clone() * &g[j]);
                }
            }
            None => {
                for c in r.iter_mut().take(dr) {
                    *c = c.clone() * lg;
                }
                r[dr] = Poly::zero();
                for j in 0..dg {
                    r[j + shift] = r[j + shift].clone() - &(lr.clone() * &g[j]);
                }
            }
        }
        r[dr] = Poly::zero();
        trim(&mut r);
    }
    r
}

/// The primitive part of the gcd of two primitive univariate views (primitive PRS).
fn primitive_prs(mut f: Vec<Poly>, mut g: Vec<Poly>) -> Vec<Poly> {
    if f.len() < g.len() {
        std::mem::swap(&mut f, &mut g);
    }
    loop {
        let r = prem(&f, &g);
        match r.len() {
            0 => return g,
            1 => return vec![Poly::one()],
            _ => {
                let c = content_of(&r);
                f = std::mem::replace(&mut g, divide_all(r, &c));
            }
        }
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

    fn v(name: &str) -> Poly {
        Poly::var(Sym::new(name))
    }

    fn k(n: i64) -> Poly {
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
            let (a, b) = (f * &h, g * &h);
            let d = Poly::gcd(&a, &b);
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
    fn modular_coprimality_test_never_claims_a_shared_factor_away() {
        let (x, y, z) = (v("x"), v("y"), v("z"));
        let h = x.clone() * &y + &z.pow(2) + &k(7);
        let a = h.clone() * &(x.pow(3) - &y);
        let b = h.clone() * &(z.clone() * &x + &k(1));
        for s in ["x", "y", "z"] {
            assert!(!coprime_in_main_symbol(&a, &b, Sym::new(s)));
        }
        assert!(coprime_in_main_symbol(
            &(x.clone() + &y),
            &(x.clone() - &y),
            Sym::new("x")
        ));
        assert_eq!(gcd_degree_mod_p(vec![1, 0, 1], vec![PRIME - 1, 0, 1]), 0);
        assert_eq!(gcd_degree_mod_p(vec![PRIME - 1, 0, 1], vec![1, 1]), 1);
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
