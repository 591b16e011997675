//! [`Field`] for the quadratic field Q(sqrt d): exact numbers `x + y*sqrt(d)` with `x`, `y`
//! rational and `d` a positive non-square integer.
//!
//! The optimum impact parameter `a*` is the square root of a rational, so the exact values at
//! `a*` live in such a field. Elements carry their `d` (shared through an [`Arc`]); a constant
//! (`from_rational`, `zero`, `one`) carries none until it meets one. Mixing two genuinely
//! different fields (say sqrt(2) and sqrt(3)) is a programming error and panics, naming both.
//!
//! `d` is normalised on construction: `sqrt(p/q) = sqrt(p*q)/q`, and square factors of small
//! primes (below 10^4) are pulled out, so `sqrt(8)`, `2*sqrt(2)` and `4/sqrt(2)` meet in one
//! field. A square factor of a larger prime is still recognised when two elements meet: their
//! `d`s describe the same field exactly when `d1*d2` is a square, and the larger is then
//! rewritten over the smaller.
//!
//! The parts are combined in Q while they are small and in dashu's rationals
//! ([`RBig`](super::big::RBig)) once any holds more than 512 bits: num-bigint's binary GCD made
//! the tables at the number limits take seconds to minutes, dashu's takes milliseconds.

use super::big::{to_q, to_rbig};
use super::decimal;
use super::{Field, Q, TrySqrt};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::sync::{Arc, OnceLock};

/// An exact number `x + y*sqrt(d)` of a quadratic field over Q.
///
/// Invariants: `d` is `None` only when `y == 0`; a present `d` is an integer > 1 that is not a
/// square and has no square factor `p^2` for primes `p < 10^4`.
///
/// # Examples
/// ```
/// use rodimpact::field::{q, Field, QSqrt};
/// let a = QSqrt::sqrt_of(&q(2, 3)); // a* of the paper's uniform rod with m = M
/// assert_eq!(a.to_string(), "sqrt(6)/3");
/// let two = QSqrt::from_i64(2);
/// let omega = two.clone() * &a / (QSqrt::from_rational(&q(2, 3)) + &(a.clone() * &a));
/// assert_eq!(omega.to_string(), "sqrt(6)/2");
/// assert_eq!(omega.decimal(5), "1.2247");
/// ```
#[derive(Clone)]
pub struct QSqrt {
    x: Q,
    y: Q,
    d: Option<Arc<Q>>,
}

/// The primes below 10^4, for pulling square factors out of `d`.
fn small_primes() -> &'static [u32] {
    static PRIMES: OnceLock<Vec<u32>> = OnceLock::new();
    PRIMES.get_or_init(|| {
        const LIMIT: usize = 10_000;
        let mut composite = vec![false; LIMIT];
        let mut primes = Vec::new();
        for n in 2..LIMIT {
            if !composite[n] {
                primes.push(n as u32);
                for m in (n * n..LIMIT).step_by(n) {
                    composite[m] = true;
                }
            }
        }
        primes
    })
}

/// `sqrt(r) = c * sqrt(D)` for `r > 0`: returns `(c, Some(D))`, or `(c, None)` when `r` is a
/// rational square (`sqrt(r) = c`).
fn split_radicand(r: &Q) -> (Q, Option<Q>) {
    let mut big_d: BigInt = r.numer() * r.denom();
    // The square factors are counted first and multiplied out once: the integer part c of
    // sqrt(D) is built as one product and reduced against the denominator once at the end.
    // (Pulling each p^2 out with a rational multiplication reduced a ~33,000-bit fraction by
    // GCD 10,000 times for 10^10000, which took half a minute.)
    let mut factor = BigInt::one();
    for &p in small_primes() {
        let p2 = BigInt::from(p) * p;
        if big_d < p2 {
            break;
        }
        let mut count: u32 = 0;
        loop {
            let (quotient, remainder) = big_d.div_rem(&p2);
            if !remainder.is_zero() {
                break;
            }
            big_d = quotient;
            count += 1;
        }
        if count > 0 {
            factor *= BigInt::from(p).pow(count);
        }
    }
    let root = big_d.sqrt();
    let (factor, rest) = if &root * &root == big_d {
        (factor * root, None)
    } else {
        (factor, Some(Q::from_integer(big_d)))
    };
    (Q::new(factor, r.denom().clone()), rest)
}

/// Two operands written over one radicand, and that radicand.
type Aligned<'a> = (Cow<'a, QSqrt>, Cow<'a, QSqrt>, Option<Arc<Q>>);

fn sign_of(q: &Q) -> Ordering {
    q.cmp(&Q::zero())
}

/// Parts of more than this many bits (numerator and denominator together) are combined in
/// dashu's rationals rather than Q.
const BIG_BITS: u64 = 512;

fn is_big(q: &Q) -> bool {
    q.numer().bits() + q.denom().bits() > BIG_BITS
}

/// An operation on two elements `ax + ay sqrt(d)` and `bx + by sqrt(d)`, written once for
/// any field of parts (Q, or dashu's rationals for big parts).
#[derive(Clone, Copy)]
enum PartsOp {
    Add,
    Sub,
    Mul,
    Div,
}

impl PartsOp {
    /// The parts `(x, y)` of the result; `d` is the common radicand (`None`: both rational).
    fn apply<F: Field>(self, [ax, ay, bx, by]: [&F; 4], d: Option<&F>) -> (F, F) {
        let cross = || ax.clone() * by + &(ay.clone() * bx);
        match self {
            PartsOp::Add => (ax.clone() + bx, ay.clone() + by),
            PartsOp::Sub => (ax.clone() - bx, ay.clone() - by),
            PartsOp::Mul => match d {
                Some(d) if !ay.is_zero() && !by.is_zero() => {
                    (ax.clone() * bx + &(ay.clone() * by * d), cross())
                }
                _ => (ax.clone() * bx, cross()),
            },
            PartsOp::Div => {
                let zero = F::zero();
                let d = d.unwrap_or(&zero);
                let norm = bx.square() - by.square() * d;
                (
                    (ax.clone() * bx - ay.clone() * by * d) / &norm,
                    (ay.clone() * bx - ax.clone() * by) / &norm,
                )
            }
        }
    }
}

impl QSqrt {
    /// The rational `q`, in no particular field yet.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::rational(q(3, 2)).to_string(), "3/2");
    /// ```
    pub fn rational(q: Q) -> Self {
        QSqrt {
            x: q,
            y: Q::zero(),
            d: None,
        }
    }

    /// Whether the representation holds its invariant (see [`QSqrt`]): no radicand unless the
    /// number met one, `y != 0` only with a radicand, a radicand an integer > 1 that is not a
    /// square and has no square factor of a prime below 10^4. Every operation keeps it; the
    /// property tests assert it.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert!(QSqrt::sqrt_of(&q(2, 3)).is_valid());
    /// ```
    pub fn is_valid(&self) -> bool {
        match self.d.as_deref() {
            None => self.y.is_zero(),
            Some(d) => {
                d.is_integer() && *d > Q::one() && split_radicand(d) == (Q::one(), Some(d.clone()))
            }
        }
    }

    /// `x + y*sqrt(d)`, normalised (a square `d` gives a rational; `d == 0` gives `x`).
    ///
    /// # Panics
    /// **Panics if `d < 0`** (not a real number; a programming error).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::new(q(1, 2), q(1, 1), q(8, 1)).to_string(), "1/2 + 2*sqrt(2)");
    /// assert_eq!(QSqrt::new(q(1, 2), q(1, 1), q(9, 4)).to_string(), "2");
    /// ```
    pub fn new(x: Q, y: Q, d: Q) -> Self {
        assert!(
            !d.is_negative(),
            "QSqrt::new: d = {d} < 0 has no real square root"
        );
        if d.is_zero() || y.is_zero() {
            return QSqrt::rational(x);
        }
        match split_radicand(&d) {
            (c, None) => QSqrt::rational(x + y * c),
            (c, Some(big_d)) => QSqrt {
                x,
                y: y * c,
                d: Some(Arc::new(big_d)),
            },
        }
    }

    /// The exact square root of a rational `d >= 0`: rational when `d` is a square.
    ///
    /// # Panics
    /// **Panics if `d < 0`.**
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::sqrt_of(&q(2, 3)).to_string(), "sqrt(6)/3");
    /// assert_eq!(QSqrt::sqrt_of(&q(4, 9)).to_string(), "2/3");
    /// assert_eq!(QSqrt::sqrt_of(&q(8, 1)), QSqrt::new(q(0, 1), q(2, 1), q(2, 1)));
    /// ```
    pub fn sqrt_of(d: &Q) -> Self {
        QSqrt::new(Q::zero(), Q::one(), d.clone())
    }

    /// The rational part `x`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::new(q(1, 2), q(3, 1), q(2, 1)).x(), &q(1, 2));
    /// ```
    pub fn x(&self) -> &Q {
        &self.x
    }

    /// The coefficient `y` of `sqrt(d)` (after normalisation).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::sqrt_of(&q(8, 1)).y(), &q(2, 1));
    /// ```
    pub fn y(&self) -> &Q {
        &self.y
    }

    /// The normalised radicand `d` (an integer), or `None` for a constant that has met no field.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::sqrt_of(&q(8, 1)).d(), Some(&q(2, 1)));
    /// assert_eq!(QSqrt::rational(q(8, 1)).d(), None);
    /// ```
    pub fn d(&self) -> Option<&Q> {
        self.d.as_deref()
    }

    /// The field element's radicand when it is irrational (`y != 0`).
    fn radicand(&self) -> Option<&Arc<Q>> {
        self.d.as_ref().filter(|_| !self.y.is_zero())
    }

    /// `self` rewritten over the radicand `target`, when `self.d * target` is a square.
    fn rewritten_over(&self, target: &Arc<Q>) -> Option<QSqrt> {
        let own = self.radicand()?;
        // sqrt(own) = sqrt(own / target) * sqrt(target), and own / target is a rational square.
        let ratio = own.as_ref() / target.as_ref();
        ratio.try_sqrt().map(|r| QSqrt {
            x: self.x.clone(),
            y: &self.y * r,
            d: Some(target.clone()),
        })
    }

    /// Both operands over one common radicand, or `None` when they lie in different fields.
    fn align<'a>(a: &'a QSqrt, b: &'a QSqrt) -> Option<Aligned<'a>> {
        let borrowed = |d: Option<&Arc<Q>>| Some((Cow::Borrowed(a), Cow::Borrowed(b), d.cloned()));
        match (a.radicand(), b.radicand()) {
            (None, None) => borrowed(a.d.as_ref().or(b.d.as_ref())),
            (Some(d), None) | (None, Some(d)) => borrowed(Some(d)),
            (Some(da), Some(db)) if Arc::ptr_eq(da, db) || da == db => borrowed(Some(da)),
            (Some(da), Some(db)) => {
                if da < db {
                    let b2 = b.rewritten_over(da)?;
                    Some((Cow::Borrowed(a), Cow::Owned(b2), Some(da.clone())))
                } else {
                    let a2 = a.rewritten_over(db)?;
                    Some((Cow::Owned(a2), Cow::Borrowed(b), Some(db.clone())))
                }
            }
        }
    }

    /// [`QSqrt::align`], panicking (a programming error) on two different fields.
    fn align_or_panic<'a>(a: &'a QSqrt, b: &'a QSqrt) -> Aligned<'a> {
        match QSqrt::align(a, b) {
            Some(aligned) => aligned,
            None => panic!(
                "QSqrt: cannot mix elements of different fields: {a} is in Q(sqrt({})) and {b} in Q(sqrt({}))",
                a.d.as_deref().map_or("?".to_string(), Q::to_string),
                b.d.as_deref().map_or("?".to_string(), Q::to_string),
            ),
        }
    }

    fn add_ref(a: &QSqrt, b: &QSqrt) -> QSqrt {
        QSqrt::combine(PartsOp::Add, a, b)
    }

    fn sub_ref(a: &QSqrt, b: &QSqrt) -> QSqrt {
        QSqrt::combine(PartsOp::Sub, a, b)
    }

    fn mul_ref(a: &QSqrt, b: &QSqrt) -> QSqrt {
        QSqrt::combine(PartsOp::Mul, a, b)
    }

    /// `a / b = a * conj(b) / (x_b^2 - y_b^2 d)`.
    fn div_ref(a: &QSqrt, b: &QSqrt) -> QSqrt {
        assert!(!b.is_zero(), "QSqrt: division by zero");
        QSqrt::combine(PartsOp::Div, a, b)
    }

    /// `op` on two elements written over one radicand.
    fn combine(op: PartsOp, a: &QSqrt, b: &QSqrt) -> QSqrt {
        let (a, b, d) = QSqrt::align_or_panic(a, b);
        let parts = [&a.x, &a.y, &b.x, &b.y];
        let (x, y) = if parts.iter().any(|q| is_big(q)) || d.as_deref().is_some_and(is_big) {
            let [ax, ay, bx, by] = parts.map(to_rbig);
            let dv = d.as_deref().map(to_rbig);
            let (x, y) = op.apply([&ax, &ay, &bx, &by], dv.as_ref());
            (to_q(&x), to_q(&y))
        } else {
            op.apply(parts, d.as_deref())
        };
        QSqrt { x, y, d }
    }

    /// The exact sign of `x + y*sqrt(d)`: from the signs of `x` and `y`, comparing `x^2` with
    /// `y^2 d` only when they differ.
    fn sign_exact(&self) -> Ordering {
        let (sx, sy) = (sign_of(&self.x), sign_of(&self.y));
        match (sx, sy, self.d.as_deref()) {
            (_, Ordering::Equal, _) | (_, _, None) => sx,
            (Ordering::Equal, _, _) => sy,
            _ if sx == sy => sx,
            (_, _, Some(d)) => {
                // Never equal: d is not a square.
                let x_wins = if is_big(&self.x) || is_big(&self.y) || is_big(d) {
                    let (x, y, d) = (to_rbig(&self.x), to_rbig(&self.y), to_rbig(d));
                    x.square() > y.square() * &d
                } else {
                    &self.x * &self.x > &self.y * &self.y * d
                };
                if x_wins { sx } else { sy }
            }
        }
    }

    /// The exact comparison of two elements: the sign of `self - other`.
    ///
    /// # Panics
    /// When the two lie in different fields.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// use std::cmp::Ordering;
    /// let root2 = QSqrt::sqrt_of(&q(2, 1));
    /// assert_eq!(root2.cmp_exact(&QSqrt::rational(q(99, 70))), Ordering::Less);
    /// assert_eq!(root2.cmp_exact(&QSqrt::rational(q(1393, 985))), Ordering::Greater);
    /// ```
    pub fn cmp_exact(&self, other: &Self) -> Ordering {
        QSqrt::sub_ref(self, other).sign_exact()
    }

    /// Rational bounds `lo <= self <= hi` with `hi - lo <= 10^-digits * |self|`;
    /// `lo == hi == self` when `self` is rational.
    ///
    /// Built from [`decimal::sqrt_bounds`] of `d`, with guard digits doubled until the
    /// cancellation in `x + y*sqrt(d)` is covered.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// let (lo, hi) = QSqrt::sqrt_of(&q(2, 1)).bounds(3);
    /// assert!(&lo * &lo < q(2, 1) && q(2, 1) < &hi * &hi);
    /// ```
    pub fn bounds(&self, digits: usize) -> (Q, Q) {
        let Some(d) = self.radicand() else {
            return (self.x.clone(), self.x.clone());
        };
        let mut guard = 4;
        loop {
            let (s_lo, s_hi) = decimal::sqrt_bounds(d, digits + guard);
            let (y_lo, y_hi) = if self.y.is_positive() {
                (&self.y * s_lo, &self.y * s_hi)
            } else {
                (&self.y * s_hi, &self.y * s_lo)
            };
            let (lo, hi) = (&self.x + y_lo, &self.x + y_hi);
            // The value is irrational, hence nonzero: the bounds eventually share its sign.
            if lo.signum() == hi.signum() && !lo.is_zero() {
                let smallest = if lo.is_positive() { &lo } else { &hi }.abs();
                let tolerance =
                    smallest / Q::from_integer(num_traits::pow(BigInt::from(10u8), digits));
                if &hi - &lo <= tolerance {
                    return (lo, hi);
                }
            }
            guard *= 2;
        }
    }

    /// |x|, exactly (the sign decided exactly, as [`QSqrt::cmp_exact`] decides it).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// let x = QSqrt::rational(q(1, 1)) - &QSqrt::sqrt_of(&q(2, 1)); // 1 - sqrt(2) < 0
    /// assert_eq!(x.abs().to_string(), "-1 + sqrt(2)");
    /// ```
    pub fn abs(&self) -> QSqrt {
        if self.sign_exact() == Ordering::Less {
            -self.clone()
        } else {
            self.clone()
        }
    }

    /// The value correctly rounded to `digits` significant digits, formatted as
    /// [`decimal::decimal`] does (bounds refined until both round alike).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::field::{q, QSqrt};
    /// assert_eq!(QSqrt::sqrt_of(&q(3, 2)).decimal(10), "1.224744871");
    /// assert_eq!(QSqrt::rational(q(-1, 5)).decimal(3), "-0.200");
    /// ```
    pub fn decimal(&self, digits: usize) -> String {
        if self.radicand().is_none() {
            return decimal::decimal(&self.x, digits);
        }
        let mut guard = 4;
        loop {
            let (lo, hi) = self.bounds(digits + guard);
            let (a, b) = (decimal::decimal(&lo, digits), decimal::decimal(&hi, digits));
            if a == b {
                return a;
            }
            // An irrational value is never a rounding tie, so this ends.
            guard *= 2;
        }
    }
}

macro_rules! forward_binop {
    ($Trait:ident, $method:ident, $core:ident) => {
        impl $Trait<&QSqrt> for &QSqrt {
            type Output = QSqrt;
            fn $method(self, rhs: &QSqrt) -> QSqrt {
                QSqrt::$core(self, rhs)
            }
        }
        impl $Trait<&QSqrt> for QSqrt {
            type Output = QSqrt;
            fn $method(self, rhs: &QSqrt) -> QSqrt {
                QSqrt::$core(&self, rhs)
            }
        }
        impl $Trait<QSqrt> for QSqrt {
            type Output = QSqrt;
            fn $method(self, rhs: QSqrt) -> QSqrt {
                QSqrt::$core(&self, &rhs)
            }
        }
        impl $Trait<QSqrt> for &QSqrt {
            type Output = QSqrt;
            fn $method(self, rhs: QSqrt) -> QSqrt {
                QSqrt::$core(self, &rhs)
            }
        }
    };
}

forward_binop!(Add, add, add_ref);
forward_binop!(Sub, sub, sub_ref);
forward_binop!(Mul, mul, mul_ref);
forward_binop!(Div, div, div_ref);

impl Neg for QSqrt {
    type Output = QSqrt;
    fn neg(self) -> QSqrt {
        QSqrt {
            x: -self.x,
            y: -self.y,
            d: self.d,
        }
    }
}

impl Neg for &QSqrt {
    type Output = QSqrt;
    fn neg(self) -> QSqrt {
        -self.clone()
    }
}

impl Zero for QSqrt {
    fn zero() -> Self {
        QSqrt::rational(Q::zero())
    }
    fn is_zero(&self) -> bool {
        self.x.is_zero() && self.y.is_zero()
    }
}

impl One for QSqrt {
    fn one() -> Self {
        QSqrt::rational(Q::one())
    }
}

/// Equal values are equal: structural on `(x, y)` after both are written over one radicand;
/// the radicand of a rational element is ignored.
impl PartialEq for QSqrt {
    fn eq(&self, other: &Self) -> bool {
        match QSqrt::align(self, other) {
            Some((a, b, _)) => a.x == b.x && a.y == b.y,
            None => false,
        }
    }
}

impl Eq for QSqrt {}

/// The canonical ASCII form ([`notation::surd`](super::notation::surd)): `3/2`, `sqrt(6)`,
/// `-sqrt(2)`, `2*sqrt(6)/5`, `1/2 + sqrt(6)/3`, `1 - sqrt(2)`.
impl fmt::Display for QSqrt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&super::notation::surd(
            self,
            super::notation::Notation::Ascii,
        ))
    }
}

impl fmt::Debug for QSqrt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "QSqrt({self}")?;
        if let (Some(d), None) = (self.d.as_deref(), self.radicand()) {
            write!(f, " in Q(sqrt({d}))")?;
        }
        write!(f, ")")
    }
}

impl Field for QSqrt {
    const NAME: &'static str = "Q(sqrt d)";
    const EXACT: bool = true;

    fn size_bits(&self) -> u64 {
        self.x.size_bits() + self.y.size_bits() + self.d.as_deref().map_or(0, Field::size_bits)
    }

    fn from_rational(q: &Q) -> Self {
        QSqrt::rational(q.clone())
    }

    fn sign(&self) -> Option<Ordering> {
        Some(self.sign_exact())
    }

    /// The nearest `f64`, from rational bounds refined until both ends round to the same float.
    fn nearest_f64(&self) -> f64 {
        let to_f64 = |q: &Q| q.to_f64().unwrap_or(f64::NAN);
        if self.radicand().is_none() {
            return to_f64(&self.x);
        }
        let mut digits = 20;
        loop {
            let (lo, hi) = self.bounds(digits);
            let (a, b) = (to_f64(&lo), to_f64(&hi));
            if a == b || digits >= 2_000 {
                return a;
            }
            digits *= 2;
        }
    }
}

impl TrySqrt for QSqrt {
    /// The root when it lies in the element's field: a rational root, `r*sqrt(d)` for a
    /// rational element, or a denested `a + b*sqrt(d)` (as `sqrt(3 + 2*sqrt(2)) = 1 + sqrt(2)`).
    /// A constant that has met no field only has rational roots here; use
    /// [`QSqrt::sqrt_of`] to adjoin one.
    fn try_sqrt(&self) -> Option<Self> {
        match self.sign_exact() {
            Ordering::Less => return None,
            Ordering::Equal => return Some(self.clone()),
            Ordering::Greater => {}
        }
        let with = |x: Q, y: Q| QSqrt {
            x,
            y,
            d: self.d.clone(),
        };
        let Some(d) = self.radicand() else {
            if let Some(r) = self.x.try_sqrt() {
                return Some(with(r, Q::zero()));
            }
            let d = self.d.as_deref()?;
            return (&self.x / d).try_sqrt().map(|r| with(Q::zero(), r));
        };
        // (a + b sqrt d)^2 = x + y sqrt d  <=>  a^2 = (x +- sqrt(x^2 - y^2 d)) / 2, b = y / 2a.
        let n = (&self.x * &self.x - &self.y * &self.y * d.as_ref()).try_sqrt()?;
        let half = Q::new(BigInt::one(), BigInt::from(2));
        for s in [(&self.x + &n) * &half, (&self.x - &n) * &half] {
            if !s.is_positive() {
                continue;
            }
            if let Some(a) = s.try_sqrt() {
                let b = &self.y / (&a * Q::from_integer(2.into()));
                let mut root = with(a, b);
                if root.sign_exact() == Ordering::Less {
                    root = -root;
                }
                if root.square() == *self {
                    return Some(root);
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{laws, q};
    use proptest::prelude::*;

    fn r(n: i64, d: i64) -> QSqrt {
        QSqrt::rational(q(n, d))
    }

    fn root(n: i64, d: i64) -> QSqrt {
        QSqrt::sqrt_of(&q(n, d))
    }

    /// Regression (F1 of the hostile-input review): each square factor p^2 was pulled out of
    /// the radicand by a rational multiplication with a full GCD reduction, 10,000 of them for
    /// 10^10000 (about 20 s). The factor is now counted, built once and reduced once.
    #[test]
    fn square_factors_at_the_digit_limit_come_out_exactly() {
        let big = |e: u32| BigInt::from(10).pow(e);
        let ten = QSqrt::sqrt_of(&Q::from_integer(big(10_000)));
        assert_eq!((ten.x(), ten.d()), (&Q::from_integer(big(5_000)), None));
        // sqrt(2 10^10000 / 3) = 10^5000/3 * sqrt(6), and sqrt(10^-10001) = sqrt(10)/10^5001.
        let third = QSqrt::sqrt_of(&Q::new(big(10_000) * 2, 3.into()));
        assert_eq!(third.y(), &Q::new(big(5_000), 3.into()));
        assert_eq!(third.d(), Some(&q(6, 1)));
        let small = QSqrt::sqrt_of(&Q::new(1.into(), big(10_001)));
        assert_eq!(small.y(), &Q::new(1.into(), big(5_001)));
        assert_eq!(small.d(), Some(&q(10, 1)));
    }

    #[test]
    fn field_laws_hold_exactly() {
        let big = num_traits::pow(BigInt::from(10u8), 300);
        let huge = QSqrt::rational(Q::from_integer(big.clone()));
        let tiny = QSqrt::rational(Q::new(BigInt::one(), big));
        let s2 = root(2, 1);
        let samples = [
            r(0, 1),
            r(1, 1),
            r(-1, 1),
            r(1, 3),
            s2.clone(),
            r(1, 1) + &(s2.clone() / &r(3, 1)),
            -s2.clone(),
            huge.clone(),
            tiny,
            huge * &s2,
        ];
        laws::check_field(&samples, |a, b| a == b);
    }

    #[test]
    fn normalisation_meets_equal_roots() {
        assert_eq!(root(8, 1), r(2, 1) * &root(2, 1));
        assert_eq!(root(1, 2), root(2, 1) / &r(2, 1));
        assert_eq!(root(12, 27), r(2, 3));
        assert_eq!(root(2, 3).d(), Some(&q(6, 1)));
        assert_eq!(root(2, 3).y(), &q(1, 3));
        assert_eq!(root(72, 1).to_string(), "6*sqrt(2)");
        assert_eq!(root(0, 1), r(0, 1));
        // A square factor of a prime above the trial-division bound: a different radicand, but
        // the same field, recognised when the elements meet.
        let p = 10_007i64;
        let big = root(2 * p * p, 1);
        assert_eq!(big.d(), Some(&q(2 * p * p, 1)));
        assert_eq!(big, r(p, 1) * &root(2, 1));
        assert_eq!((big.clone() - &(r(p, 1) * &root(2, 1))), r(0, 1));
        assert_eq!((big / &root(2, 1)), r(p, 1));
    }

    #[test]
    #[should_panic(expected = "Q(sqrt(2)) and sqrt(3) in Q(sqrt(3))")]
    fn mixing_fields_panics_naming_both() {
        let _ = root(2, 1) + root(3, 1);
    }

    #[test]
    fn constants_join_any_field() {
        let zero_in_2 = root(2, 1) - root(2, 1);
        assert_eq!(zero_in_2, r(0, 1));
        assert_eq!(zero_in_2 + root(3, 1), root(3, 1));
        assert_ne!(root(2, 1), root(3, 1));
    }

    #[test]
    fn display_is_canonical() {
        let table = [
            (r(3, 2), "3/2"),
            (r(-3, 2), "-3/2"),
            (root(6, 1), "sqrt(6)"),
            (-root(2, 1), "-sqrt(2)"),
            (root(6, 1) * &r(2, 5), "2*sqrt(6)/5"),
            (root(6, 1) * &r(-2, 5), "-2*sqrt(6)/5"),
            (r(1, 2) + &(root(6, 1) / &r(3, 1)), "1/2 + sqrt(6)/3"),
            (r(1, 1) - &root(2, 1), "1 - sqrt(2)"),
            (root(2, 1) - root(2, 1), "0"),
        ];
        for (value, want) in table {
            assert_eq!(value.to_string(), want);
        }
        assert_eq!(
            format!("{:?}", root(2, 1) - root(2, 1)),
            "QSqrt(0 in Q(sqrt(2)))"
        );
    }

    #[test]
    fn signs_of_close_cases() {
        use Ordering::*;
        // 99^2 = 9801 > 2*70^2 = 9800 and 1393^2 = 1940449 < 2*985^2 = 1940450.
        assert_eq!((root(2, 1) - r(99, 70)).sign(), Some(Less));
        assert_eq!((r(99, 70) - root(2, 1)).sign(), Some(Greater));
        assert_eq!((r(1393, 985) - root(2, 1)).sign(), Some(Less));
        assert_eq!((root(2, 1) - r(1393, 985)).sign(), Some(Greater));
        // Pell convergents p/q of sqrt(2) with p^2 - 2q^2 = +-1, about 10^-150 away.
        let (mut p, mut qq) = (BigInt::one(), BigInt::one());
        for _ in 0..200 {
            let e = &p * &p - BigInt::from(2) * &qq * &qq;
            let conv = QSqrt::rational(Q::new(p.clone(), qq.clone()));
            let want = if e.is_positive() { Greater } else { Less };
            assert_eq!(conv.cmp_exact(&root(2, 1)), want);
            (p, qq) = (&p + BigInt::from(2) * &qq, &p + &qq);
        }
        assert_eq!(r(0, 1).sign(), Some(Equal));
        assert_eq!((r(3, 1) - root(8, 1)).sign(), Some(Greater));
        assert_eq!((r(-3, 1) + root(8, 1)).sign(), Some(Less));
        assert_eq!((r(-3, 1) - root(8, 1)).sign(), Some(Less));
    }

    #[test]
    fn division_by_the_conjugate() {
        let s2 = root(2, 1);
        let one_plus = r(1, 1) + &s2;
        assert_eq!(r(1, 1) / &one_plus, s2.clone() - &r(1, 1));
        let three_plus = r(3, 1) + &(r(2, 1) * &s2);
        assert_eq!(three_plus.clone() / &one_plus, one_plus);
        assert!(one_plus.checked_div(&(s2.clone() - &s2)).is_none());
    }

    /// omega(a) = 2a / (2/3 + a^2) (uniform rod, m = M, l = 1, v0 = 1) peaks at a* = sqrt(2/3)
    /// with omega(a*) = sqrt(3/2) = sqrt(6)/2, above the end value omega(1) = 6/5.
    #[test]
    fn paper_optimum_worked_example() {
        let omega = |a: &QSqrt| r(2, 1) * a / (r(2, 3) + &a.square());
        let a_star = root(2, 3);
        let at_star = omega(&a_star);
        assert_eq!(at_star, root(3, 2));
        assert_eq!(at_star, root(6, 1) / &r(2, 1));
        assert_eq!(omega(&r(1, 1)), r(6, 5));
        assert_eq!(at_star.cmp_exact(&omega(&r(1, 1))), Ordering::Greater);
        assert_eq!(at_star.decimal(12), "1.22474487139");
        assert_eq!(at_star.nearest_f64(), 1.224744871391589);
    }

    #[test]
    fn try_sqrt_finds_roots_in_the_field() {
        let s2 = root(2, 1);
        let in2 = |v: QSqrt| v + &(s2.clone() - &s2); // a rational that has met sqrt(2)
        assert_eq!(in2(r(2, 1)).try_sqrt(), Some(s2.clone()));
        assert_eq!(in2(r(8, 1)).try_sqrt(), Some(r(2, 1) * &s2));
        assert_eq!(in2(r(1, 2)).try_sqrt(), Some(s2.clone() / &r(2, 1)));
        assert_eq!(in2(r(9, 4)).try_sqrt(), Some(r(3, 2)));
        assert_eq!(in2(r(3, 1)).try_sqrt(), None);
        assert_eq!(r(2, 1).try_sqrt(), None);
        assert_eq!(r(-4, 1).try_sqrt(), None);
        assert_eq!((-s2.clone()).try_sqrt(), None);
        assert_eq!(r(0, 1).try_sqrt(), Some(r(0, 1)));
        let one_plus = r(1, 1) + &s2;
        assert_eq!(one_plus.square().try_sqrt(), Some(one_plus.clone()));
        let one_minus = s2.clone() - &r(1, 1); // positive
        assert_eq!(one_minus.square().try_sqrt(), Some(one_minus));
        assert_eq!((r(2, 1) - &s2).try_sqrt(), None);
    }

    #[test]
    fn bounds_and_decimals() {
        let s2 = root(2, 1);
        let cases = [
            (root(6, 1) / &r(2, 1), "1.2247448713915890490986420373529"),
            (r(1, 1) - &s2, "-0.41421356237309504880168872420970"),
            (
                r(1393, 985) - &s2,
                "-0.00000036440355190159356689679853056588",
            ),
            (
                s2.clone() - &r(99, 70),
                "-0.000072151912619236912596990076016207",
            ),
            (
                r(1, 1) + &(s2.clone() / &r(3, 1)),
                "1.4714045207910316829338962414032",
            ),
            (r(-1, 5), "-0.20000000000000000000000000000000"),
        ];
        for (value, want) in &cases {
            assert_eq!(value.decimal(32), *want, "{value}");
            for digits in [0, 3, 10, 40] {
                let (lo, hi) = value.bounds(digits);
                let (lo_q, hi_q) = (QSqrt::rational(lo.clone()), QSqrt::rational(hi.clone()));
                assert!(lo_q.cmp_exact(value) != Ordering::Greater, "{value}");
                assert!(hi_q.cmp_exact(value) != Ordering::Less, "{value}");
                // hi - lo <= 10^-digits |value|
                let width = QSqrt::rational(
                    (hi - lo) * Q::from_integer(num_traits::pow(BigInt::from(10u8), digits)),
                );
                let magnitude = if value.sign() == Some(Ordering::Less) {
                    -value.clone()
                } else {
                    value.clone()
                };
                assert!(
                    width.cmp_exact(&magnitude) != Ordering::Greater,
                    "{value} {digits}"
                );
            }
        }
        assert_eq!((r(1393, 985) - &s2).nearest_f64(), -3.644035519015936e-07);
        assert_eq!(s2.nearest_f64(), std::f64::consts::SQRT_2);
        assert_eq!(
            (r(1, 1) + &(s2.clone() / &r(3, 1))).nearest_f64(),
            1.4714045207910318
        );
    }

    fn small_q() -> impl Strategy<Value = Q> {
        (-50i64..50, 1i64..20).prop_map(|(n, d)| q(n, d))
    }

    fn element() -> impl Strategy<Value = QSqrt> {
        (small_q(), small_q()).prop_map(|(x, y)| QSqrt::new(x, y, q(2, 3)))
    }

    #[test]
    fn representations_out_of_normal_form_are_caught() {
        let with = |y: Q, d: Q| QSqrt {
            x: Q::zero(),
            y,
            d: Some(Arc::new(d)),
        };
        assert!(!with(q(1, 1), q(8, 1)).is_valid()); // square factor 4
        assert!(!with(q(1, 1), q(9, 1)).is_valid()); // a square
        assert!(!with(q(1, 1), q(2, 3)).is_valid()); // not an integer
        assert!(
            !QSqrt {
                x: Q::zero(),
                y: q(1, 1),
                d: None
            }
            .is_valid()
        );
        assert!(with(q(1, 1), q(6, 1)).is_valid() && with(Q::zero(), q(6, 1)).is_valid());
    }

    proptest! {
        /// Distributivity and inverses hold exactly in Q(sqrt(6)), and `sign` agrees with the
        /// decimal enclosure.
        #[test]
        fn random_elements_obey_the_laws(a in element(), b in element(), c in element()) {
            let results = [a.clone() + &b, a.clone() - &b, a.clone() * &b, -c.clone()];
            prop_assert!(results.iter().chain([&a, &b, &c]).all(QSqrt::is_valid));
            if !b.is_zero() {
                prop_assert!((a.clone() / &b).is_valid());
            }
            prop_assert_eq!(a.clone() * &(b.clone() + &c), a.clone() * &b + &(a.clone() * &c));
            if !b.is_zero() {
                prop_assert_eq!(a.clone() / &b * &b, a.clone());
            }
            let (lo, hi) = a.bounds(5);
            match a.sign() {
                Some(Ordering::Greater) => prop_assert!(lo.is_positive()),
                Some(Ordering::Less) => prop_assert!(hi.is_negative()),
                _ => prop_assert!(lo.is_zero() && hi.is_zero()),
            }
        }
    }
}
