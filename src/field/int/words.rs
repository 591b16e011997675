//! Machine-word exact arithmetic for the fast path: binary GCDs on `u64` and `u128`, and a
//! 256-bit unsigned integer with just the operations the fraction-free form needs.

use crate::field::Q;
use num_bigint::{BigInt, BigUint, Sign};

/// Stein's binary GCD on `u128` (`gcd(0, d) = d`).
pub(crate) fn gcd(mut a: u128, mut b: u128) -> u128 {
    if let (Ok(x), Ok(y)) = (u64::try_from(a), u64::try_from(b)) {
        return gcd_u64(x, y).into();
    }
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    // a odd. Each step is branch-free (min and difference by conditional moves): the branches
    // of the textbook loop are taken at random and mispredicted about half the time.
    loop {
        b >>= b.trailing_zeros();
        let (low, high) = (a.min(b), a.max(b));
        if let Ok(small) = u64::try_from(high) {
            // Both fit one machine word now: finish there.
            return u128::from(gcd64(low as u64, small)) << shift;
        }
        a = low;
        b = high - low;
        if b == 0 {
            return a << shift;
        }
    }
}

/// Stein's binary GCD on `u64` (`gcd_u64(0, d) = d`).
pub(crate) fn gcd_u64(a: u64, b: u64) -> u64 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    let shift = (a | b).trailing_zeros();
    gcd64(a >> a.trailing_zeros(), b) << shift
}

/// Stein's binary GCD on `u64`, for odd `a` (`gcd64(a, 0) = a`), branch-free inside the loop.
fn gcd64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        b >>= b.trailing_zeros();
        let (low, high) = (a.min(b), a.max(b));
        a = low;
        b = high - low;
    }
    a
}

/// A 256-bit unsigned integer: just enough for the energy identity of the fixed-width path and
/// the GCDs of the big-integer path. The derived order compares `hi`, then `lo`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct U256 {
    pub(crate) hi: u128,
    pub(crate) lo: u128,
}

impl U256 {
    pub(crate) const ZERO: U256 = U256 { hi: 0, lo: 0 };
    pub(crate) const ONE: U256 = U256 { hi: 0, lo: 1 };

    /// A rational's sign, numerator and denominator on words; `None` when a part passes 256
    /// bits.
    pub(crate) fn parts_of(q: &Q) -> Option<(bool, U256, U256)> {
        let n = U256::from_big(q.numer().magnitude())?;
        let d = U256::from_big(q.denom().magnitude())?;
        Some((q.numer().sign() == Sign::Minus, n, d))
    }

    pub(crate) fn from_big(x: &BigUint) -> Option<U256> {
        if x.bits() > 256 {
            return None;
        }
        let mut words = x.iter_u64_digits();
        let mut next = || u128::from(words.next().unwrap_or(0));
        let lo = next() | next() << 64;
        let hi = next() | next() << 64;
        Some(U256 { hi, lo })
    }

    pub(crate) fn to_big(self) -> BigUint {
        if self.hi == 0 {
            return BigUint::from(self.lo);
        }
        let limbs = [
            self.lo as u64,
            (self.lo >> 64) as u64,
            self.hi as u64,
            (self.hi >> 64) as u64,
        ];
        BigUint::new(
            limbs
                .iter()
                .flat_map(|&x| [x as u32, (x >> 32) as u32])
                .collect(),
        )
    }

    fn trailing_zeros(self) -> u32 {
        if self.lo == 0 {
            128 + self.hi.trailing_zeros()
        } else {
            self.lo.trailing_zeros()
        }
    }

    pub(crate) fn shr(self, k: u32) -> U256 {
        match k {
            0 => self,
            1..128 => U256 {
                hi: self.hi >> k,
                lo: self.lo >> k | self.hi << (128 - k),
            },
            _ => U256 {
                hi: 0,
                lo: self.hi >> (k - 128),
            },
        }
    }

    pub(crate) fn shl(self, k: u32) -> U256 {
        match k {
            0 => self,
            1..128 => U256 {
                hi: self.hi << k | self.lo >> (128 - k),
                lo: self.lo << k,
            },
            _ => U256 {
                hi: self.lo << (k - 128),
                lo: 0,
            },
        }
    }

    /// `self - o` for `self >= o`.
    #[inline]
    pub(crate) fn minus(self, o: U256) -> U256 {
        let (lo, borrow) = self.lo.overflowing_sub(o.lo);
        U256 {
            hi: self.hi - o.hi - u128::from(borrow),
            lo,
        }
    }

    /// `|a - b|` for two signed magnitudes (`a_negative`, `a`) and (`b_negative`, `b`): their
    /// difference when the signs agree, their sum when not (a zero's sign is then moot);
    /// `None` when the sum passes 2^256.
    pub(crate) fn signed_distance(
        a_negative: bool,
        a: U256,
        b_negative: bool,
        b: U256,
    ) -> Option<U256> {
        if a_negative == b_negative {
            Some(a.max(b).minus(a.min(b)))
        } else {
            a.checked_add(b)
        }
    }

    /// Stein's binary GCD; once both fit in 128 bits it finishes in `u128`.
    pub(crate) fn gcd(mut a: U256, mut b: U256) -> U256 {
        if a.hi == 0 && b.hi == 0 {
            return U256 {
                hi: 0,
                lo: gcd(a.lo, b.lo),
            };
        }
        if a == U256::ZERO {
            return b;
        }
        if b == U256::ZERO {
            return a;
        }
        // One Euclid step when one is much shorter (a small relative error over its
        // denominator): the binary GCD would spend a subtraction per bit of the difference.
        let (short, long) = (a.min(b), a.max(b));
        if (16..=62).contains(&(long.bits() - short.bits())) {
            (a, b) = (short, long.div_small(short).1);
            if b == U256::ZERO {
                return a;
            }
            if a.hi == 0 && b.hi == 0 {
                return U256 {
                    hi: 0,
                    lo: gcd(a.lo, b.lo),
                };
            }
        }
        let shift = a.trailing_zeros().min(b.trailing_zeros());
        a = a.shr(a.trailing_zeros());
        loop {
            b = b.shr(b.trailing_zeros());
            if a > b {
                std::mem::swap(&mut a, &mut b);
            }
            if b.hi == 0 {
                let g = gcd(a.lo, b.lo);
                return U256 { hi: 0, lo: g }.shl(shift);
            }
            b = b.minus(a);
            if b == U256::ZERO {
                return a.shl(shift);
            }
        }
    }

    /// A decimal number below 2^256 (every number of up to 77 digits; nothing but digits, at
    /// least one), or `None`.
    pub(crate) fn parse_decimal(bytes: &[u8]) -> Option<U256> {
        if bytes.is_empty() || bytes.len() > 78 {
            return None;
        }
        let scale = |chunk: &[u8]| u128::from(POWERS_OF_TEN[chunk.len()]);
        if bytes.len() <= 38 {
            // Below 10^38 < 2^127: one or two 19-digit words in u128.
            let (head, tail) = bytes.split_at(bytes.len().saturating_sub(19));
            return Some(U256 {
                hi: 0,
                lo: u128::from(digits_word(head)?) * scale(tail) + u128::from(digits_word(tail)?),
            });
        }
        let mut value = U256::ZERO;
        // Chunks of up to 19 digits: value = value * 10^k + chunk.
        for chunk in bytes.chunks(19) {
            value = value.checked_mul(scale(chunk))?.checked_add(U256 {
                hi: 0,
                lo: digits_word(chunk)?.into(),
            })?;
        }
        Some(value)
    }

    /// `-n/d` (when `negative`) or `n/d` as a reduced [`Q`], `d > 0`: one GCD on machine
    /// words. Shared by the fast path's outputs and the machine-word parser.
    pub(crate) fn ratio(negative: bool, n: U256, d: U256) -> Q {
        let (n, d) = U256::reduce(n, d);
        let sign = if negative { Sign::Minus } else { Sign::Plus };
        Q::new_raw(BigInt::from_biguint(sign, n), d.into())
    }

    /// `n/d` (`d > 0`) as a [`Q`] as it stands, not reduced: for a value only compared,
    /// rounded or printed to a few digits (all of which [`Q`] does by value), where the GCD
    /// of [`U256::ratio`] would be most of the work.
    pub(crate) fn unreduced(n: U256, d: U256) -> Q {
        Q::new_raw(
            BigInt::from_biguint(Sign::Plus, n.to_big()),
            d.to_big().into(),
        )
    }

    /// `n/d` in lowest terms (`d > 0`), on words: one binary GCD and two exact divisions.
    pub(crate) fn reduced(n: U256, d: U256) -> (U256, U256) {
        let g = U256::gcd(n, d);
        if g == U256::ONE {
            return (n, d);
        }
        match u64::try_from(g.lo) {
            Ok(small) if g.hi == 0 => (n.div_rem_word(small).0, d.div_rem_word(small).0),
            _ => {
                let g = g.to_big();
                let word = |x: BigUint| U256::from_big(&x).expect("a quotient is not larger");
                (word(n.to_big() / &g), word(d.to_big() / g))
            }
        }
    }

    /// `self mod w` for a nonzero word `w`, from the highest nonzero limb.
    pub(crate) fn rem_word(self, w: u64) -> u64 {
        let w = u128::from(w);
        let limbs = [
            (self.hi >> 64) as u64,
            self.hi as u64,
            (self.lo >> 64) as u64,
            self.lo as u64,
        ];
        let rem = |acc: u128, limb: &u64| (acc << 64 | u128::from(*limb)) % w;
        limbs.iter().skip_while(|x| **x == 0).fold(0, rem) as u64
    }

    /// `(self / g, self mod g)` for a nonzero word `g`: long division limb by limb, from the
    /// highest nonzero limb.
    pub(crate) fn div_rem_word(self, g: u64) -> (U256, u64) {
        let mut limbs = [
            (self.hi >> 64) as u64,
            self.hi as u64,
            (self.lo >> 64) as u64,
            self.lo as u64,
        ];
        let g = u128::from(g);
        let mut rem = 0u128;
        for limb in limbs.iter_mut().skip_while(|x| **x == 0) {
            let cur = rem << 64 | u128::from(*limb);
            *limb = (cur / g) as u64;
            rem = cur % g;
        }
        let quotient = U256 {
            hi: u128::from(limbs[0]) << 64 | u128::from(limbs[1]),
            lo: u128::from(limbs[2]) << 64 | u128::from(limbs[3]),
        };
        (quotient, rem as u64)
    }

    /// `n/d` in lowest terms (`d > 0`).
    fn reduce(n: U256, d: U256) -> (BigUint, BigUint) {
        let g = U256::gcd(n, d);
        if g == U256::ONE {
            return (n.to_big(), d.to_big());
        }
        if n.hi == 0 && d.hi == 0 {
            if let (Ok(n), Ok(d), Ok(g)) = (
                u64::try_from(n.lo),
                u64::try_from(d.lo),
                u64::try_from(g.lo),
            ) {
                return ((n / g).into(), (d / g).into());
            }
            return ((n.lo / g.lo).into(), (d.lo / g.lo).into());
        }
        let g = g.to_big();
        (n.to_big() / &g, d.to_big() / g)
    }

    /// `a/b == c/d` for nonzero `b`, `d`: `a d == c b`, on 512 bits.
    pub(crate) fn cross_equal(a: U256, d: U256, c: U256, b: U256) -> bool {
        a.full_product(d) == c.full_product(b)
    }

    /// The exact 512-bit product, as eight 64-bit limbs, least significant first.
    fn full_product(self, o: U256) -> [u64; 8] {
        let limbs = |x: U256| {
            [
                x.lo as u64,
                (x.lo >> 64) as u64,
                x.hi as u64,
                (x.hi >> 64) as u64,
            ]
        };
        let (a, b) = (limbs(self), limbs(o));
        let mut out = [0u64; 8];
        for i in 0..4 {
            let mut carry = 0u128;
            for j in 0..4 {
                let t = u128::from(a[i]) * u128::from(b[j]) + u128::from(out[i + j]) + carry;
                out[i + j] = t as u64;
                carry = t >> 64;
            }
            out[i + 4] = carry as u64;
        }
        out
    }

    /// Appends the decimal digits: itoa's digit-pair printer on the value below 2^64 (most
    /// of a row's numbers; itoa's u128 printer divides in 128 bits), 2^128, or on its
    /// base-10^19 digits above.
    pub(crate) fn write_decimal(self, out: &mut String) {
        const CHUNK: u64 = 10_000_000_000_000_000_000; // 10^19
        let mut buffer = itoa::Buffer::new();
        if self.hi == 0 {
            match u64::try_from(self.lo) {
                Ok(small) => out.push_str(buffer.format(small)),
                Err(_) => out.push_str(buffer.format(self.lo)),
            }
            return;
        }
        // Low base-10^19 digits until the rest fits 128 bits (at most three: 2^256 < 10^78).
        let (mut head, mut chunks, mut count) = (self, [0u64; 3], 0);
        while head.hi != 0 {
            let (quotient, rem) = head.div_rem_word(CHUNK);
            chunks[count] = rem;
            count += 1;
            head = quotient;
        }
        out.push_str(buffer.format(head.lo));
        for &chunk in chunks[..count].iter().rev() {
            let digits = buffer.format(chunk);
            out.extend(std::iter::repeat_n('0', 19 - digits.len()));
            out.push_str(digits);
        }
    }

    /// The exact product of two `u128`.
    #[inline(always)]
    pub(crate) fn product(a: u128, b: u128) -> U256 {
        if (a | b) >> 64 == 0 {
            // Both below 2^64: one machine product.
            return U256 { hi: 0, lo: a * b };
        }
        let mask = u128::from(u64::MAX);
        let (a1, a0) = (a >> 64, a & mask);
        let (b1, b0) = (b >> 64, b & mask);
        let low = a0 * b0;
        let (mid, carry_mid) = (a1 * b0).overflowing_add(a0 * b1);
        let (lo, carry_lo) = low.overflowing_add(mid << 64);
        let hi = a1 * b1 + (mid >> 64) + (u128::from(carry_mid) << 64) + u128::from(carry_lo);
        U256 { hi, lo }
    }

    pub(crate) fn square(x: u128) -> U256 {
        U256::product(x, x)
    }

    #[inline]
    pub(crate) fn checked_mul(self, c: u128) -> Option<U256> {
        let low = U256::product(self.lo, c);
        let high = U256::product(self.hi, c);
        if high.hi != 0 {
            return None;
        }
        let hi = low.hi.checked_add(high.lo)?;
        Some(U256 { hi, lo: low.lo })
    }

    #[inline]
    pub(crate) fn checked_add(self, o: U256) -> Option<U256> {
        let (lo, carry) = self.lo.overflowing_add(o.lo);
        let hi = self.hi.checked_add(o.hi)?.checked_add(u128::from(carry))?;
        Some(U256 { hi, lo })
    }
}

/// `base^k` for `k < N`, a table built at compile time (`base^(N-1)` must fit a `u64`).
pub(crate) const fn powers<const N: usize>(base: u64) -> [u64; N] {
    let mut powers = [1u64; N];
    let mut k = 1;
    while k < N {
        powers[k] = powers[k - 1] * base;
        k += 1;
    }
    powers
}

/// 10^k for k = 0..=19, every power of ten a `u64` holds.
pub(crate) const POWERS_OF_TEN: [u64; 20] = powers(10);

/// The value of at most 19 ASCII digits (none: 0), or `None` when a byte is not a digit;
/// eight digits at a time.
fn digits_word(digits: &[u8]) -> Option<u64> {
    let mut chunks = digits.chunks_exact(8);
    let mut value = 0u64;
    for chunk in &mut chunks {
        let word = u64::from_le_bytes(chunk.try_into().expect("chunks of eight"));
        value = value * 100_000_000 + eight_digits(word)?;
    }
    for &b in chunks.remainder() {
        let digit = b.wrapping_sub(b'0');
        if digit > 9 {
            return None;
        }
        value = value * 10 + u64::from(digit);
    }
    Some(value)
}

/// Eight ASCII digits read little-endian into `word` (the first digit in the lowest byte) as
/// their value, or `None` when a byte is not a digit: the bytes become 0..9, then pairs,
/// fours and the eight are combined by three multiplications in the word.
fn eight_digits(word: u64) -> Option<u64> {
    const EACH: u64 = 0x0101_0101_0101_0101;
    let low = word.wrapping_sub(0x30 * EACH);
    // Every byte 0x30..=0x3f, and below 0x3a (adding 6 leaves its high nibble clear).
    let digits =
        word & (0xf0 * EACH) == 0x30 * EACH && low.wrapping_add(6 * EACH) & (0xf0 * EACH) == 0;
    if !digits {
        return None;
    }
    let pairs = (low.wrapping_mul(1 + (10 << 8)) >> 8) & 0x00ff_00ff_00ff_00ff;
    let fours = (pairs.wrapping_mul(1 + (100 << 16)) >> 16) & 0x0000_ffff_0000_ffff;
    Some(fours.wrapping_mul(1 + (10_000 << 32)) >> 32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;

    #[test]
    fn u256_products_match_big_integers() {
        let cases = [
            (0u128, 5u128),
            (u128::MAX, u128::MAX),
            (u128::MAX, 1),
            (1 << 64, 1 << 64),
            (
                0xdead_beef_0123_4567_89ab_cdef_7777_9999,
                0xffff_0000_ffff_0000_1234,
            ),
        ];
        for (a, b) in cases {
            let p = U256::product(a, b);
            let want = BigInt::from(a) * BigInt::from(b);
            let got = (BigInt::from(p.hi) << 128) + BigInt::from(p.lo);
            assert_eq!(got, want, "{a} * {b}");
        }
        assert_eq!(U256::square(u128::MAX).checked_mul(2), None);
        assert_eq!(
            U256::square(u128::MAX).checked_add(U256::square(u128::MAX)),
            None
        );
        assert_eq!(
            U256::square(1 << 100).checked_mul(1 << 55),
            Some(U256 {
                hi: 1 << 127,
                lo: 0
            })
        );
    }

    #[test]
    fn gcd_of_u256_matches_big_integers() {
        let big = |s: &str| s.parse::<BigUint>().unwrap();
        let cases = [
            ("0", "12"),
            ("12", "0"),
            ("340282366920938463463374607431768211457", "3"),
            (
                "115792089237316195423570985008687907853269984665640564039457584007913129639935",
                "340282366920938463463374607431768211455",
            ),
            (
                "605266953260872505155079183529643000000",
                "42781701118546417863969985673251741000000",
            ),
            ("1180591620717411303424", "3541774862152233910272"),
            // Sizes 16 to 62 bits apart: one Euclid step first (a relative error over its
            // denominator), including a remainder of zero.
            (
                "123456789012345678901000000",
                "42781701118546417863969985673251741000000",
            ),
            ("7", "42781701118546417863969985673251741000000"),
            (
                "42781701118546417863969985673251741",
                "42781701118546417863969985673251741000000000000000000",
            ),
        ];
        for (a, b) in cases {
            let (x, y) = (big(a), big(b));
            let (ux, uy) = (U256::from_big(&x).unwrap(), U256::from_big(&y).unwrap());
            assert_eq!(ux.to_big(), x);
            assert_eq!(
                U256::gcd(ux, uy).to_big(),
                num_integer::Integer::gcd(&x, &y),
                "{a} {b}"
            );
        }
        assert_eq!(U256::from_big(&(BigUint::from(1u8) << 256u32)), None);
    }

    proptest::proptest! {
        /// A run of digits of every length is read as num-bigint reads it, and one byte that is
        /// not a digit, anywhere (the bytes either side of '0'..='9' included), refuses it.
        #[test]
        fn decimal_digits_are_read_as_big_integers_read_them(
            digits in "[0-9]{1,78}",
            at in 0usize..78,
            bad in proptest::sample::select(vec![b'/', b':', b' ', b'.', b'a', 0x80, 0xb0]),
        ) {
            let want = BigUint::parse_bytes(digits.as_bytes(), 10).unwrap();
            let got = U256::parse_decimal(digits.as_bytes()).map(U256::to_big);
            let fits = want.bits() <= 256;
            proptest::prop_assert_eq!(got, fits.then_some(want));
            let mut spoiled = digits.into_bytes();
            let at = at % spoiled.len();
            spoiled[at] = bad;
            let spoiled = String::from_utf8_lossy(&spoiled).into_owned();
            proptest::prop_assert_eq!(U256::parse_decimal(spoiled.as_bytes()), None);
        }

        /// Division by a word, its remainder, and the reduction of a fraction on words, against
        /// num-bigint, across all four limbs.
        #[test]
        fn word_division_and_reduction_match_big_integers(
            limbs in proptest::array::uniform4(proptest::prelude::any::<u64>()),
            w in 1u64..,
            k in 0usize..4,
            factor in 1u64..1 << 20,
        ) {
            let mut limbs = limbs;
            limbs[..k].fill(0); // fewer limbs in use
            let x = U256 {
                hi: u128::from(limbs[0]) << 64 | u128::from(limbs[1]),
                lo: u128::from(limbs[2]) << 64 | u128::from(limbs[3]),
            };
            let big = x.to_big();
            let (q, r) = x.div_rem_word(w);
            proptest::prop_assert_eq!(q.to_big(), &big / w);
            proptest::prop_assert_eq!(BigUint::from(r), &big % w);
            proptest::prop_assert_eq!(BigUint::from(x.rem_word(w)), &big % w);
            // A fraction with a common factor, reduced, equals num-rational's.
            let n = U256 { hi: 0, lo: u128::from(w) * u128::from(factor) };
            let d = U256 { hi: 0, lo: u128::from(limbs[3] | 1) * u128::from(factor) };
            let (rn, rd) = U256::reduced(n, d);
            let want = num_rational::Ratio::new(n.to_big(), d.to_big());
            proptest::prop_assert_eq!((rn.to_big(), rd.to_big()), (want.numer().clone(), want.denom().clone()));
        }
    }

    #[test]
    fn parsing_reduction_and_cross_products_match_big_integers() {
        let big = |s: &str| s.parse::<BigUint>().unwrap();
        let max = "115792089237316195423570985008687907853269984665640564039457584007913129639935";
        assert_eq!(
            U256::parse_decimal(max.as_bytes()).unwrap().to_big(),
            big(max)
        );
        assert_eq!(
            U256::parse_decimal(
                b"115792089237316195423570985008687907853269984665640564039457584007913129639936"
            ),
            None
        );
        assert_eq!(U256::parse_decimal("9".repeat(78).as_bytes()), None);
        assert_eq!(U256::parse_decimal("0".repeat(79).as_bytes()), None);
        assert_eq!(U256::parse_decimal(b"0012"), Some(U256 { hi: 0, lo: 12 }));
        assert_eq!(U256::parse_decimal(b""), None);
        assert_eq!(U256::parse_decimal(b"1_0"), None);
        let (a, b) = (
            "605266953260872505155079183529643000000000000000000000000001",
            "3",
        );
        let (x, y) = (
            U256::parse_decimal(a.as_bytes()).unwrap(),
            U256::parse_decimal(b.as_bytes()).unwrap(),
        );
        let g = num_integer::Integer::gcd(&big(a), &big(b));
        assert_eq!(U256::reduce(x, y), (big(a) / &g, big(b) / &g));
        let (six, nine) = (U256 { hi: 0, lo: 6 }, U256 { hi: 0, lo: 9 });
        assert_eq!(
            U256::reduce(six, nine),
            (BigUint::from(2u8), BigUint::from(3u8))
        );
        let m = U256::parse_decimal(max.as_bytes()).unwrap();
        assert!(U256::cross_equal(m, m, m, m));
        assert!(!U256::cross_equal(
            m,
            m,
            m,
            U256::parse_decimal(max.replace("935", "934").as_bytes()).unwrap()
        ));
        let product = m.full_product(m);
        let want = big(max) * big(max);
        let got = product
            .iter()
            .rev()
            .fold(BigUint::from(0u8), |acc, &x| (acc << 64u32) + x);
        assert_eq!(got, want);
    }

    #[test]
    fn decimal_digits_match_big_integers() {
        let cases = [
            "0",
            "340282366920938463463374607431768211455",
            "340282366920938463463374607431768211456",
            "10000000000000000000000000000000000000000000000000000000000",
            "115792089237316195423570985008687907853269984665640564039457584007913129639935",
            "605266953260872505155079183529643000000000000000000000000001",
        ];
        for text in cases {
            let mut out = String::new();
            U256::from_big(&text.parse().unwrap())
                .unwrap()
                .write_decimal(&mut out);
            assert_eq!(out, text);
        }
    }

    #[test]
    fn gcd_of_u128() {
        assert_eq!(gcd(0, 7), 7);
        assert_eq!(gcd(12, 18), 6);
        assert_eq!(gcd(1 << 100, 3 << 90), 1 << 90);
        assert_eq!(gcd(u128::MAX, u128::MAX - 1), 1);
        assert_eq!(gcd(3 << 70, 9 << 3), 3 << 3);
        assert_eq!(gcd(1 << 64, 1), 1);
        assert_eq!(
            (gcd(0, 0), gcd(12, 0), gcd(8, 12), gcd(1 << 63, 1 << 62)),
            (0, 12, 4, 1 << 62)
        );
        assert_eq!(
            gcd(123_456_789 * 987_654_321, 987_654_321 * 1_000_003),
            987_654_321
        );
    }
}
