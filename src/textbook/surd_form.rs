//! The normal form of an exact value `coeff * sqrt(radicand)` in the scene's symbols: an
//! integer free of squares under the root's constant, and the even powers of the (positive)
//! symbols outside it. Used by the expression reader's `Radical` for every value it builds.

use crate::field::{Field, Poly, Q, RatFn};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// Normal form: zero has radicand 1; the radicand's constant loses its square factors (an
/// integer under the root: `sqrt(3/2)` is `sqrt(6)/2`), and even powers of a symbol dividing
/// every term of its numerator or denominator come out of the root (the symbols are positive
/// quantities: `sqrt(3/(2 l^2))` is `(1/2/l)*sqrt(6)`). Returns `(coeff, radicand)`.
pub(super) fn normal_form(coeff: RatFn, radicand: RatFn) -> (RatFn, RatFn) {
    if coeff.is_zero() || radicand.is_one() {
        return (coeff, RatFn::one());
    }
    let (num, num_out) = even_powers_out(radicand.num());
    let (den, den_out) = even_powers_out(radicand.den());
    let (num_content, den_content) = (num.content().abs(), den.content().abs());
    let constant = &num_content / &den_content;
    if constant.is_zero() || constant.is_negative() {
        return (coeff, radicand);
    }
    let (n, d) = (constant.numer().clone(), constant.denom().clone());
    // sqrt(n/d) = sqrt(n d) / d; pull the largest square factor out of small n d.
    let nd = n * &d;
    let root = nd.sqrt();
    let (outside, inside) = if &root * &root == nd {
        (root, BigInt::one())
    } else {
        square_part(nd)
    };
    let outside = RatFn::from_rational(&Q::new(outside, d));
    let rest = RatFn::new(
        num.scale(&num_content.recip()),
        den.scale(&den_content.recip()),
    )
    .expect("a radicand's denominator is not zero");
    let coeff = coeff * &outside * &RatFn::from(num_out) / RatFn::from(den_out);
    let radicand = rest * &RatFn::from_rational(&Q::from_integer(inside));
    (coeff, radicand)
}

/// `p = out^2 * rest`, `out` the product of `sym^(k div 2)` over the symbols whose `k`-th
/// power divides every term of `p`.
fn even_powers_out(p: &Poly) -> (Poly, Poly) {
    let (mut rest, mut out) = (p.clone(), Poly::one());
    for sym in p.symbols() {
        let half = p.low_degree_in(sym) / 2;
        if half > 0 {
            let root = Poly::var(sym).pow(half);
            rest = rest
                .div_exact(&(&root * &root))
                .expect("every term holds the symbol's even power");
            out = out * &root;
        }
    }
    (rest, out)
}

/// `n = outside^2 * inside`, taking out the squares of the primes below 1000.
fn square_part(mut n: BigInt) -> (BigInt, BigInt) {
    let mut outside = BigInt::one();
    for k in 2u32..1000 {
        let k2 = BigInt::from(k * k);
        while (&n % &k2).is_zero() {
            n /= &k2;
            outside *= k;
        }
    }
    (outside, n)
}
