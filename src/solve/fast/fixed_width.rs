//! The paper's scene on machine words: a free uniform rod whose inputs are fractions of
//! 64-bit parts, solved fraction-free in a fixed-width ring sized in advance from the inputs'
//! bit lengths, its laws checked as integer identities, its three outputs reduced on words. No
//! `BigRational`, no big integer.
//!
//! It is a route of its own (`batch`'s word rows), and a shortcut, never a second opinion:
//! inputs it does not take (a part above 18 digits, values that could leave the ring) are
//! refused with `None`, and what it gives is the fraction-free route's answer bit for bit
//! (`tests/lib/batch_words.rs` holds the batch to that, byte for byte).
//!
//! The formulas are those of [`super::fraction_free`] for a free rod (I = M l^2/3, so
//! g = l^2/3 = gn/gd with gn = ln^2, gd = 3 ld^2), on the unreduced parts as written.
//!
//! A fast case of the core: where it answers, it must equal `impact::solve_contact(&scene.
//! system(), Law::Newton)` in Q, which `tests/lib/fast_routes.rs` checks on random scenes.

use crate::field::int::{Ring, U256, gcd_u64};

/// A number as written in a cell: sign, numerator and denominator (not reduced).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Part {
    pub(crate) negative: bool,
    pub(crate) n: u64,
    pub(crate) d: u64,
}

impl Part {
    const ONE: Part = Part {
        negative: false,
        n: 1,
        d: 1,
    };

    /// `[+-]digits[/digits]` with at most 18 digits a part (below 2^60) and a nonzero
    /// denominator, or a decimal `[+-]digits.digits[e[+-]digits]` (also `.5`, `5.`, `2e3`,
    /// `E` for `e`) whose value is such a fraction over a power of ten (`0.05` is 5/100),
    /// surrounding ASCII blanks ignored; `None` for anything else (the general parser's
    /// forms and errors).
    pub(crate) fn parse(cell: &[u8]) -> Option<Part> {
        let cell = cell.trim_ascii();
        let (negative, rest) = match cell.first()? {
            b'-' => (true, &cell[1..]),
            b'+' => (false, &cell[1..]),
            _ => (false, cell),
        };
        let (n, used) = digits(rest).unwrap_or((0, 0));
        let d = match rest.get(used) {
            None if used > 0 => 1,
            Some(b'/') if used > 0 => match digits(&rest[used + 1..])? {
                (d, k) if k == rest.len() - used - 1 => d,
                _ => return None,
            },
            Some(b'.' | b'e' | b'E') => return Part::decimal(negative, rest),
            _ => return None,
        };
        (d != 0).then_some(Part { negative, n, d })
    }

    /// `digits[.digits][(e|E)[+-]digits]` as the shared parser reads it on words
    /// ([`WordRatio::decimal`](crate::number::WordRatio)), `n/10^k` or `n 10^k/1`, taken when
    /// each part is below 10^18.
    fn decimal(negative: bool, text: &[u8]) -> Option<Part> {
        let (n, d) = crate::number::WordRatio::decimal(text)?;
        let below = |x: U256| (x.hi == 0 && x.lo < 10u128.pow(18)).then_some(x.lo as u64);
        Some(Part {
            negative,
            n: below(n)?,
            d: below(d)?,
        })
    }

    /// Strictly positive.
    fn positive(self) -> bool {
        !self.negative && self.n != 0
    }
}

/// The number at the start of `bytes` (1 to 18 digits) and how many bytes it took.
fn digits(bytes: &[u8]) -> Option<(u64, usize)> {
    let mut n = 0u64;
    let mut used = 0;
    while used < bytes.len() && used < 19 {
        let digit = bytes[used].wrapping_sub(b'0');
        if digit > 9 {
            break;
        }
        n = n * 10 + u64::from(digit);
        used += 1;
    }
    (1..=18).contains(&used).then_some((n, used))
}

/// Bit length of a word (0 for 0).
fn bits(x: u64) -> u32 {
    64 - x.leading_zeros()
}

/// The inputs of one row, checked: m, M, l, a, v0, e.
pub(crate) struct Inputs {
    pub(crate) m: Part,
    pub(crate) big_m: Part,
    pub(crate) l: Part,
    pub(crate) a: Part,
    pub(crate) v0: Part,
    pub(crate) e: Part,
}

impl Inputs {
    /// The scene's constraints (m, M, l, v0 > 0; |a| <= l; 0 <= e <= 1) on the parts read (in
    /// the order m, M, l, a, v0, e; `None`: the default); `None` when one fails (the general row then
    /// names it).
    pub(crate) fn check(parts: [Option<Part>; 6]) -> Option<Inputs> {
        let [m, big_m, l, a, v0, e] = parts;
        let (m, big_m) = (m?, big_m?);
        let l = l.unwrap_or(Part::ONE);
        let a = a.unwrap_or(l);
        let v0 = v0.unwrap_or(Part::ONE);
        let e = e.unwrap_or(Part::ONE);
        let on_rod = u128::from(a.n) * u128::from(l.d) <= u128::from(l.n) * u128::from(a.d);
        let restitution = (!e.negative || e.n == 0) && e.n <= e.d;
        let valid = [m, big_m, l, v0].iter().all(|x| x.positive()) && on_rod && restitution;
        valid.then_some(Inputs {
            m,
            big_m,
            l,
            a,
            v0,
            e,
        })
    }

    /// Elastic: e = 1.
    fn elastic(&self) -> bool {
        self.e.n == self.e.d
    }
}

/// The inputs in a ring of N limbs, with g = gn/gd = l^2/3.
struct Words<const N: usize> {
    mn: Ring<N>,
    md: Ring<N>,
    big_n: Ring<N>,
    big_d: Ring<N>,
    an: Ring<N>,
    ad: Ring<N>,
    en: Ring<N>,
    ed: Ring<N>,
    gn: Ring<N>,
    gd: Ring<N>,
}

impl<const N: usize> Words<N> {
    fn of(x: &Inputs) -> Words<N> {
        let w = |negative: bool, n: u64| Ring::signed(negative, n);
        Words {
            mn: w(false, x.m.n),
            md: w(false, x.m.d),
            big_n: w(false, x.big_m.n),
            big_d: w(false, x.big_m.d),
            an: w(x.a.negative, x.a.n),
            ad: w(false, x.a.d),
            en: w(false, x.e.n),
            ed: w(false, x.e.d),
            // Below 2^122: the parts are below 2^60.
            gn: Ring::from_u128(u128::from(x.l.n) * u128::from(x.l.n)),
            gd: Ring::from_u128(3 * u128::from(x.l.d) * u128::from(x.l.d)),
        }
    }
}

/// The solution over one common denominator (before v0): `v = v0 nv/den`, ...
#[derive(Clone, Copy)]
struct Raw<const N: usize> {
    nv: Ring<N>,
    n_big_v: Ring<N>,
    nw: Ring<N>,
    den: Ring<N>,
}

impl<const N: usize> Raw<N> {
    /// The fraction-free solve of a free rod (the module documentation of
    /// [`crate::solve::fast::fraction_free`]).
    fn solve(s: &Words<N>) -> Raw<N> {
        let ad2 = s.ad.mul(s.ad);
        let mn_big_d = s.mn.mul(s.big_d);
        let a_term = mn_big_d.mul(s.gn).mul(ad2);
        let b_term = s.big_n.mul(s.md).mul(s.gn).mul(ad2);
        let c_term = mn_big_d.mul(s.an).mul(s.an).mul(s.gd);
        let a_plus_c = a_term.add(c_term);
        let ne = s.ed.add(s.en);
        Raw {
            nv: s.ed.mul(a_plus_c).sub(s.en.mul(b_term)),
            n_big_v: ne.mul(a_term),
            nw: ne.mul(mn_big_d).mul(s.an).mul(s.gd).mul(s.ad),
            den: s.ed.mul(a_plus_c.add(b_term)),
        }
    }

    fn resize<const M: usize>(&self) -> Raw<M> {
        Raw {
            nv: self.nv.resize(),
            n_big_v: self.n_big_v.resize(),
            nw: self.nw.resize(),
            den: self.den.resize(),
        }
    }
}

/// Runs `$law::<L>($args)` in the fewest limbs L whose signed range holds `$bits`-bit values
/// (b <= 64 L - 1), up to 8; `$none` beyond.
macro_rules! in_limbs {
    ($bits:expr, $none:expr, $law:ident($($args:expr),*)) => {
        match $bits {
            0..=127 => $law::<2>($($args),*),
            128..=191 => $law::<3>($($args),*),
            192..=255 => $law::<4>($($args),*),
            256..=319 => $law::<5>($($args),*),
            320..=383 => $law::<6>($($args),*),
            384..=447 => $law::<7>($($args),*),
            448..=511 => $law::<8>($($args),*),
            _ => $none,
        }
    };
}

/// The fraction-free solve in S limbs, returned in 4 (S <= 4: the caller's bound).
fn raw_in<const S: usize>(x: &Inputs) -> Option<Raw<4>> {
    (S <= 4).then(|| Raw::solve(&Words::<S>::of(x)).resize())
}

/// Linear momentum, `mn Md nv + Mn md nV = mn Md den`, in L limbs.
fn linear<const L: usize>(x: &Inputs, raw: &Raw<4>) -> bool {
    let (s, r) = (Words::<L>::of(x), raw.resize::<L>());
    let mn_big_d = s.mn.mul(s.big_d);
    mn_big_d.mul(r.nv).add(s.big_n.mul(s.md).mul(r.n_big_v)) == mn_big_d.mul(r.den)
}

/// Angular momentum about the centre, `mn Md an gd nv + Mn md gn ad nw = mn Md an gd den`, in
/// L limbs.
fn angular<const L: usize>(x: &Inputs, raw: &Raw<4>) -> bool {
    let (s, r) = (Words::<L>::of(x), raw.resize::<L>());
    let mn_an_gd = s.mn.mul(s.big_d).mul(s.an).mul(s.gd);
    let big_n_md = s.big_n.mul(s.md);
    mn_an_gd
        .mul(r.nv)
        .add(big_n_md.mul(s.gn).mul(s.ad).mul(r.nw))
        == mn_an_gd.mul(r.den)
}

/// Kinetic energy (e = 1), `w nv^2 + Mn md gd nV^2 + Mn md gn nw^2 = w den^2` with
/// `w = mn Md gd`, written `w (den - nv)(den + nv) = Mn md (gd nV^2 + gn nw^2)` (two squares
/// fewer), in L limbs.
fn energy<const L: usize>(x: &Inputs, raw: &Raw<4>) -> bool {
    let (s, r) = (Words::<L>::of(x), raw.resize::<L>());
    let weight = s.mn.mul(s.big_d).mul(s.gd);
    let kinetic =
        s.gd.mul(r.n_big_v.mul(r.n_big_v))
            .add(s.gn.mul(r.nw.mul(r.nw)));
    weight.mul(r.den.sub(r.nv)).mul(r.den.add(r.nv)) == s.big_n.mul(s.md).mul(kinetic)
}

/// Upper bounds on the bit lengths of the values of the solve (the outputs before reduction,
/// with v0) and of each law identity's terms, from the inputs' bit lengths alone.
struct Bounds {
    raw: u32,
    outputs: u32,
    linear: u32,
    angular: u32,
    energy: u32,
}

impl Bounds {
    fn of(x: &Inputs) -> Bounds {
        let (m, md) = (bits(x.m.n), bits(x.m.d));
        let (big_n, big_d) = (bits(x.big_m.n), bits(x.big_m.d));
        let (an, ad) = (bits(x.a.n), bits(x.a.d));
        let (en, ed) = (bits(x.e.n), bits(x.e.d));
        let (vn, vd) = (bits(x.v0.n), bits(x.v0.d));
        let (gn, gd) = (2 * bits(x.l.n), 2 * bits(x.l.d) + 2);
        let a_term = m + big_d + gn + 2 * ad;
        let b_term = big_n + md + gn + 2 * ad;
        let c_term = m + big_d + 2 * an + gd;
        let ne = ed.max(en) + 1;
        let den = ed + a_term.max(b_term).max(c_term) + 2;
        let nv = (ed + a_term.max(c_term) + 1).max(en + b_term) + 1;
        let n_big_v = ne + a_term;
        let nw = ne + m + big_d + an + gd + ad;
        let numerators = nv.max(n_big_v).max(nw);
        Bounds {
            raw: numerators.max(den),
            outputs: (vn + numerators).max(vd + den),
            linear: (m + big_d + nv)
                .max(big_n + md + n_big_v)
                .max(m + big_d + den)
                + 1,
            angular: (m + big_d + an + gd + nv.max(den)).max(big_n + md + gn + ad + nw) + 1,
            energy: (m + big_d + gd + 2 * nv.max(den))
                .max(big_n + md + gd + 2 * n_big_v)
                .max(big_n + md + gn + 2 * nw)
                + 2,
        }
    }
}

/// A row's raw solution, `v = v0 nv/den` and so on: (sign, magnitude) of `nv`, `nV`, `nw`,
/// and `den` (> 0).
type Solved = ([(bool, U256); 3], U256);

/// Word factors multiplied together into as few words as they fit (ones left out).
struct Chunks {
    words: [u64; 12],
    len: usize,
}

impl Chunks {
    fn of(factors: &[u64]) -> Chunks {
        let mut chunks = Chunks {
            words: [1; 12],
            len: 1,
        };
        for &f in factors.iter().filter(|f| **f > 1) {
            match chunks.words[chunks.len - 1].checked_mul(f) {
                Some(product) => chunks.words[chunks.len - 1] = product,
                None => {
                    chunks.words[chunks.len] = f;
                    chunks.len += 1;
                }
            }
        }
        chunks
    }
}

/// The largest divisor of `d` made of primes that divide the product of `words` (at most 12
/// words), if it fits a word: for each word-sized chunk c of the product, gcd(c, rest) is
/// divided out of the rest of `d` until it is 1.
fn smooth_part(d: U256, words: &[u64]) -> Option<u64> {
    let chunks = Chunks::of(words);
    let (mut rest, mut part) = (d, 1u64);
    for &c in &chunks.words[..chunks.len] {
        loop {
            let common = gcd_u64(c, rest.rem_word(c));
            if common == 1 {
                break;
            }
            part = part.checked_mul(common)?;
            rest = rest.div_rem_word(common).0;
        }
    }
    Some(part)
}

/// The three outputs v, V, omega of a solved scene, reduced: (sign, numerator, denominator).
///
/// Each output is `vn n/(vd den)` with gcd(n, den) = gcd(F, den) for a product F of input
/// words (`nV = ne A`, `nw = ne mn Md an 3 ld^2 ad`, and `nv = den - ne B`, so gcd(nv, den) =
/// gcd(ne B, den), B = Mn md ln^2 ad^2). Every prime of a GCD to cancel therefore divides one of
/// the words vn, vd, ne, mn, md, Mn, Md, ln, ld, an, ad, 3, so the GCD of each output with the
/// denominator is its GCD with the part of the denominator made of those primes (`smooth_part`):
/// one pass over the words for the three outputs, then a word GCD each, instead of three binary
/// GCDs of ~140-bit numbers. When that part exceeds a word, each output takes the binary GCD.
fn reduce_outputs(x: &Inputs, (numerators, den): Solved) -> [(bool, U256, U256); 3] {
    let (vn, vd) = (x.v0.n, x.v0.d);
    let d = den
        .checked_mul(u128::from(vd))
        .expect("within the solve's bound");
    let words = [
        vn,
        vd,
        x.e.n + x.e.d,
        x.m.n,
        x.m.d,
        x.big_m.n,
        x.big_m.d,
        x.l.n,
        x.l.d,
        x.a.n,
        x.a.d,
        3,
    ];
    let smooth = smooth_part(d, &words);
    numerators.map(|(negative, n)| {
        let n = n
            .checked_mul(u128::from(vn))
            .expect("within the solve's bound");
        if n == U256::ZERO {
            return (false, U256::ZERO, U256::ONE);
        }
        let (n, d) = match smooth {
            Some(1) => (n, d),
            Some(part) => match gcd_u64(part, n.rem_word(part)) {
                1 => (n, d),
                g => (n.div_rem_word(g).0, d.div_rem_word(g).0),
            },
            None => U256::reduced(n, d),
        };
        (negative, n, d)
    })
}

/// Solves the scene on words, checks its laws and reduces its outputs v, V, omega:
/// (sign, numerator, denominator) each, or `None` where the general route must decide.
pub(crate) fn solve_reduced(x: &Inputs) -> Option<[(bool, U256, U256); 3]> {
    solve(x).map(|raw| reduce_outputs(x, raw))
}

/// Solves the row on words and checks its laws, each in the fewest limbs its bound allows;
/// `None` when a bound exceeds the widths (the outputs must stay below 2^256, the laws' terms
/// below 2^511) or a law fails: the general row then decides.
fn solve(x: &Inputs) -> Option<Solved> {
    let bounds = Bounds::of(x);
    if bounds.outputs > 256 {
        return None;
    }
    let raw = in_limbs!(bounds.raw, None, raw_in(x))?;
    let holds = in_limbs!(bounds.linear, false, linear(x, &raw))
        && in_limbs!(bounds.angular, false, angular(x, &raw))
        && (!x.elastic() || in_limbs!(bounds.energy, false, energy(x, &raw)));
    if !holds {
        return None;
    }
    let word = |r: Ring<4>| {
        let (negative, hi, lo) = r.sign_magnitude();
        (negative, U256 { hi, lo })
    };
    Some((
        [word(raw.nv), word(raw.n_big_v), word(raw.nw)],
        word(raw.den).1,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_read_as_written_or_left_to_the_general_row() {
        let p = |s: &str| Part::parse(s.as_bytes());
        assert_eq!(
            p(" -3/6 "),
            Some(Part {
                negative: true,
                n: 3,
                d: 6
            })
        );
        assert_eq!(p("+7").map(|x| (x.n, x.d)), Some((7, 1)));
        // Decimals: the digits over a power of ten, as written (unreduced).
        let nd = |s: &str| p(s).map(|x| (x.negative, x.n, x.d));
        assert_eq!(nd("0.05"), Some((false, 5, 100)));
        assert_eq!(nd("-0.98"), Some((true, 98, 100)));
        assert_eq!(nd(" 1.5e-3 "), Some((false, 15, 10_000)));
        assert_eq!(nd("2E+2"), Some((false, 200, 1)));
        assert_eq!(nd(".5"), Some((false, 5, 10)));
        assert_eq!(nd("5."), Some((false, 5, 1)));
        assert_eq!(nd("1e3"), Some((false, 1000, 1)));
        assert_eq!(
            nd("12.345678901234567"),
            Some((false, 12345678901234567, 10u64.pow(15)))
        );
        for general in [
            "",
            "1/0",
            ".",
            "e5",
            "1.5e",
            "1.5e+",
            "1.2.3",
            "1.5/2",
            "1e1000",
            "1e18",
            "1e-18",
            "1234567890.123456789",
            "0.5 m",
            "1 kg",
            "1/2/3",
            "--1",
            "/2",
            "2/",
            "1234567890123456789",
        ] {
            assert_eq!(p(general), None, "{general}");
        }
        assert_eq!(
            p("123456789012345678").map(|x| x.n),
            Some(123456789012345678)
        );
    }

    /// The laws are checks, not formalities: one unit off in a raw value fails them (the row
    /// then goes to the general path instead of printing a wrong answer).
    #[test]
    fn a_value_one_unit_off_fails_its_laws() {
        let part = |n, d| Part {
            negative: false,
            n,
            d,
        };
        let x = Inputs {
            m: part(3, 7),
            big_m: part(5, 2),
            l: part(9, 4),
            a: Part {
                negative: true,
                ..part(4, 3)
            },
            v0: part(11, 5),
            e: Part::ONE,
        };
        let raw = raw_in::<4>(&x).unwrap();
        assert!(linear::<4>(&x, &raw) && angular::<4>(&x, &raw) && energy::<8>(&x, &raw));
        let one = Ring::<4>::signed(false, 1);
        let off_v = Raw {
            nv: raw.nv.add(one),
            ..raw
        };
        assert!(!linear::<4>(&x, &off_v) && !energy::<8>(&x, &off_v));
        let off_w = Raw {
            nw: raw.nw.sub(one),
            ..raw
        };
        assert!(!angular::<4>(&x, &off_w) && !energy::<8>(&x, &off_w));
    }

    #[test]
    fn the_bounds_hold_for_the_largest_inputs_they_admit() {
        // Every part at 2^18 - 1 bits: the bound decides the width; the ring never wraps
        // (the laws would fail and the row go to the general path, which the batch tests
        // would see as a different line).
        let big = Part {
            negative: false,
            n: (1 << 18) - 1,
            d: (1 << 18) - 3,
        };
        let x = Inputs {
            m: big,
            big_m: big,
            l: big,
            a: Part {
                negative: true,
                ..big
            },
            v0: big,
            e: Part::ONE,
        };
        let b = Bounds::of(&x);
        assert!(
            b.outputs <= 256 && b.energy <= 511,
            "{} {}",
            b.outputs,
            b.energy
        );
        assert!(solve(&x).is_some());
    }
}
