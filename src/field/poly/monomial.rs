//! Monomials: products of symbols with positive exponents, in graded lexicographic order.

use super::Sym;
use std::cmp::Ordering;
use std::fmt;

/// A product of symbols with positive exponents, kept sorted by symbol; the empty product is 1.
///
/// Ordered graded-lexicographically (see the [module docs](super)).
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
pub struct Monomial(pub(super) Vec<(Sym, u32)>);

impl Monomial {
    /// Whether the representation holds its invariant: symbols strictly increasing by name, every
    /// exponent positive.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{poly::Monomial, Sym};
    /// assert!(Monomial::var(Sym::new("a"), 2).mul(&Monomial::var(Sym::new("m"), 1)).is_valid());
    /// ```
    pub fn is_valid(&self) -> bool {
        self.0.iter().all(|&(_, e)| e > 0) && self.0.windows(2).all(|w| w[0].0 < w[1].0)
    }

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
    pub(super) fn gcd(&self, other: &Monomial) -> Monomial {
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
    pub(super) fn split(&self, sym: Sym) -> (Monomial, u32) {
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
