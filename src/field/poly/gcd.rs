//! The multivariate GCD over Q: trivial cases answered directly, a modular coprimality test in
//! the main symbol, otherwise a primitive pseudo-remainder sequence with recursive contents.

use super::{Monomial, Poly, Sym};
use crate::field::Q;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

impl Poly {
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

#[cfg(test)]
mod tests {
    use super::super::tests::{k, v};
    use super::*;

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
}
