//! Error-free transforms (fma TwoProd, TwoSum) on exponent-carried double-word numbers: the
//! numerator N = m/M + m a^2/I - e of the "scomp" formula, accurate as if computed with twice
//! the precision, so v = N/(1 + q) v0 keeps its accuracy in the stop zone q -> e.

use super::{Ext, Real};

/// `(hi + lo) 2^k`, `|lo| <= ulp(hi)/2`, `0.5 <= |hi| < 1` (or zero).
#[derive(Debug, Clone, Copy)]
struct Double<T> {
    hi: T,
    lo: T,
    k: i32,
}

/// `a + b = s + t` exactly (Knuth's TwoSum).
fn two_sum<T: Real>(a: T, b: T) -> (T, T) {
    let s = a + b;
    let bb = s - a;
    let t = (a - (s - bb)) + (b - bb);
    (s, t)
}

/// `a b = p + t` exactly (fma TwoProd).
fn two_prod<T: Real>(a: T, b: T) -> (T, T) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl<T: Real> Double<T> {
    /// `hi + lo` (any magnitudes, `hi` the larger) renormalised, exponent `k`.
    fn normalised(hi: T, lo: T, k: i32) -> Double<T> {
        let (s, t) = two_sum(hi, lo);
        let (f, j) = s.frexp();
        Double {
            hi: f,
            lo: t.ldexp(-j),
            k: k + j,
        }
    }

    fn single(x: Ext<T>) -> Double<T> {
        let (hi, k) = x.parts();
        Double {
            hi,
            lo: T::zero(),
            k,
        }
    }

    /// `a b`, exactly.
    fn product(a: Ext<T>, b: Ext<T>) -> Double<T> {
        let ((fa, ka), (fb, kb)) = (a.parts(), b.parts());
        let (p, t) = two_prod(fa, fb);
        Double::normalised(p, t, ka + kb)
    }

    /// `a / b` with the quotient's rounding error carried in `lo`.
    fn quotient(a: Ext<T>, b: Ext<T>) -> Double<T> {
        Double::single(a).div(b)
    }

    fn mul(self, b: Ext<T>) -> Double<T> {
        let (fb, kb) = b.parts();
        let (p, t) = two_prod(self.hi, fb);
        Double::normalised(p, t + (self.lo * fb), self.k + kb)
    }

    fn div(self, b: Ext<T>) -> Double<T> {
        let (fb, kb) = b.parts();
        let q = self.hi / fb;
        // hi - q fb is exact (fma); the remainder over fb is the next word.
        let remainder = (-q).mul_add(fb, self.hi) + self.lo;
        Double::normalised(q, remainder / fb, self.k - kb)
    }

    fn add(self, b: Double<T>) -> Double<T> {
        if b.hi.is_zero() {
            return self;
        }
        if self.hi.is_zero() {
            return b;
        }
        let (big, small) = if self.k >= b.k { (self, b) } else { (b, self) };
        let gap = big.k - small.k;
        if gap > 2 * T::PRECISION as i32 + 4 {
            return big;
        }
        let (s, t) = two_sum(big.hi, small.hi.ldexp(-gap));
        Double::normalised(s, t + big.lo + small.lo.ldexp(-gap), big.k)
    }

    fn value(self) -> Ext<T> {
        Ext::from_parts(self.hi + self.lo, self.k)
    }
}

/// `m/M + m a^2/I - e`, with about twice the working precision before its final rounding.
pub(crate) fn numerator<T: Real>(
    m: Ext<T>,
    rod_mass: Ext<T>,
    inertia: Ext<T>,
    a: Ext<T>,
    e: Ext<T>,
) -> Ext<T> {
    let r = Double::quotient(m, rod_mass);
    let s = Double::product(m, a).mul(a).div(inertia);
    r.add(s).add(Double::single(-e)).value()
}
