//! An engine's row on machine words: the paper's scene with any rod (`uniform`, `dumbbell`,
//! `rg=Q`, `I=Q`), free or pivoted, any e, claims among v, V, omega, J and the energies, and
//! the audit of the claimed state, with no big integer and no GCD but the outputs' own.
//!
//! The cells are read as written (a decimal is its digits over a power of ten), the scene is
//! solved by the fraction-free formulas ([`crate::solve::fraction_free::raw_of`]) in `i128` or
//! 512 bits, every exact output is reduced once on words, and the audit's balances, distances
//! and bound are decided as exact integer comparisons over common denominators written out
//! below, in 256 bits, else 512.
//!
//! It is a shortcut, never a second opinion: a row it does not take (a unit, a part above 18
//! digits, a non-finite claim, a scene the general row would refuse, a value beyond
//! the widths) goes to the general row, and a row it takes gives the general row's line byte
//! for byte. `tests/lib/batch_words.rs` and this module's proptest hold it to that.
//!
//! Notation: `m = mn/md`, `M = Mn/Md`, `l = ln/ld`, `a = an/ad`, `v0 = vn/vd`, `e = en/ed`, the
//! rod's `I = M g` with `g = gn/gd`, a pivot `p = pn/pd` (`0/1` for a free rod). The exact
//! state is `(vn nv, vn nV, vn nw)/S` with `S = vd den`; the claimed state `(Cv, CV, Cw)/q`
//! over one denominator `q`. With `wv = mn Md gd`, `wV = Mn md gd`, `ww = Mn md gn`, twice the
//! kinetic energy times `md Md gd` is `wv v^2 + wV V^2 + ww omega^2`: `Kc` for the claimed
//! state (times `q^2`), `Ke` for the exact one (before `vn^2/S^2`).

use super::audit::{Finding, LAW_TOLERANCE, STATE_TOLERANCE};
use super::compare::Agreement;
use super::plan::{
    Arithmetic, Diagnosis, OutputCheck, Role, STATE, SolvedRow, WORD_CLAIMS, WordPlan,
};
use super::rel_error::RelError;
use super::word_row::each_cell;
use crate::field::int::{FixedInt, I256, U256, Wide};
use crate::number::WordRatio;
use crate::solve::fraction_free::{Parts, Raw, raw_of};
use crate::solve::words::Part;
use std::cmp::Ordering;

/// The rod's mass distribution as its cell gives it.
#[derive(Debug, Clone, Copy)]
enum Rod {
    Uniform,
    Dumbbell,
    Gyration(Part),
    Moment(Part),
}

impl Rod {
    /// `uniform`, `dumbbell`, `rg=Q`, `I=Q` (Q a plain number; an empty cell is uniform);
    /// `None` for anything else (the general parser's units and errors).
    fn parse(cell: &[u8]) -> Option<Rod> {
        match cell.trim_ascii() {
            b"" | b"uniform" => Some(Rod::Uniform),
            b"dumbbell" => Some(Rod::Dumbbell),
            [b'r', b'g', b'=', rest @ ..] => Some(Rod::Gyration(Part::parse(rest)?)),
            [b'I', b'=', rest @ ..] => Some(Rod::Moment(Part::parse(rest)?)),
            _ => None,
        }
    }
}

/// A row's scene on words, checked as [`crate::scene::SceneBuilder::build`] checks it.
struct Scene {
    m: Part,
    big_m: Part,
    l: Part,
    a: Part,
    v0: Part,
    e: Part,
    pivot: Option<Part>,
    /// g = I/M as (gn, gd).
    g: (U256, U256),
}

/// `x > 0`.
fn positive(x: Part) -> bool {
    !x.negative && x.n != 0
}

/// `|x| <= |y|`, by cross-multiplication.
fn at_most(x: Part, y: Part) -> bool {
    u128::from(x.n) * u128::from(y.d) <= u128::from(y.n) * u128::from(x.d)
}

/// A word as a 256-bit number.
fn word(x: u64) -> U256 {
    U256 {
        hi: 0,
        lo: x.into(),
    }
}

/// The product of two words.
fn product(x: u64, y: u64) -> U256 {
    U256 {
        hi: 0,
        lo: u128::from(x) * u128::from(y),
    }
}

impl Scene {
    /// The scene of the cells (m, M, l, a, v0, e, pivot; `None`: the default) and rod, if every
    /// constraint holds: m, M, l, v0 > 0, 0 < r_G <= l, 0 < I <= M l^2, |a| <= l,
    /// 0 <= e <= 1, |p| <= l. `None` otherwise: the general row then names the constraint.
    fn check(parts: [Option<Part>; 7], rod: Rod) -> Option<Scene> {
        let one = Part {
            negative: false,
            n: 1,
            d: 1,
        };
        let [m, big_m, l, a, v0, e, pivot] = parts;
        let (m, big_m) = (m?, big_m?);
        let l = l.unwrap_or(one);
        let a = a.unwrap_or(l);
        let v0 = v0.unwrap_or(one);
        let e = e.unwrap_or(one);
        let valid = [m, big_m, l, v0].into_iter().all(positive)
            && at_most(a, l)
            && (!e.negative || e.n == 0)
            && e.n <= e.d
            && pivot.is_none_or(|p| at_most(p, l));
        if !valid {
            return None;
        }
        let square = |x: Part| (product(x.n, x.n), product(x.d, x.d));
        let g = match rod {
            Rod::Uniform => {
                let (n, d) = square(l);
                (n, d.checked_mul(3)?)
            }
            Rod::Dumbbell => square(l),
            Rod::Gyration(r) => {
                if !positive(r) || !at_most(r, l) {
                    return None;
                }
                square(r)
            }
            Rod::Moment(i) => {
                // 0 < I <= M l^2: in Md ld^2 <= Mn ln^2 id.
                let left = product(i.n, big_m.d).checked_mul_wide(product(l.d, l.d))?;
                let right = product(big_m.n, i.d).checked_mul_wide(product(l.n, l.n))?;
                if !positive(i) || left > right {
                    return None;
                }
                (product(i.n, big_m.d), product(i.d, big_m.n))
            }
        };
        Some(Scene {
            m,
            big_m,
            l,
            a,
            v0,
            e,
            pivot,
            g,
        })
    }

    /// The fraction-free parts in `T`.
    fn parts<T: FixedInt>(&self) -> Option<Parts<T>> {
        let w = |x: u64| T::of_words(false, word(x));
        let signed = |x: Part| T::of_words(x.negative, word(x.n));
        Some(Parts {
            mn: w(self.m.n)?,
            md: w(self.m.d)?,
            big_n: w(self.big_m.n)?,
            big_d: w(self.big_m.d)?,
            an: signed(self.a)?,
            ad: w(self.a.d)?,
            en: w(self.e.n)?,
            ed: w(self.e.d)?,
            gn: T::of_words(false, self.g.0)?,
            gd: T::of_words(false, self.g.1)?,
            pivot: match self.pivot {
                None => None,
                Some(p) => Some((signed(p)?, w(p.d)?)),
            },
        })
    }
}

/// A signed fraction on words, `d > 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ratio {
    negative: bool,
    n: U256,
    d: U256,
}

impl Ratio {
    /// `n/d` in `T` (`d > 0`), reduced on words.
    fn reduced<T: FixedInt>(n: &T, d: &T) -> Option<Ratio> {
        let ((negative, n), (_, d)) = (n.to_words()?, d.to_words()?);
        let (n, d) = U256::reduced(n, d);
        Some(Ratio {
            negative: negative && n != U256::ZERO,
            n,
            d,
        })
    }

    /// Writes `,n` or `,n/d` (with its sign), as [`crate::field::decimal::write_exact`] writes
    /// the same reduced value.
    fn write_cell(&self, out: &mut String) {
        out.push(',');
        if self.negative {
            out.push('-');
        }
        self.n.write_decimal(out);
        if self.d != U256::ONE {
            out.push('/');
            self.d.write_decimal(out);
        }
    }
}

/// The exact outputs of the row: v, V, omega, J, energy before, energy after (the last three
/// `None` where not claimed), and the raw solution on words.
struct Exact {
    values: [Option<Ratio>; WORD_CLAIMS],
    raw: [(bool, U256); 4],
    laws_hold: bool,
}

/// Solves the scene in `T` and reduces the outputs the row prints.
fn exact_in<T: FixedInt>(s: &Scene, wanted: &[bool; WORD_CLAIMS]) -> Option<Exact> {
    let parts = s.parts::<T>()?;
    let raw: Raw<T> = raw_of(&parts, s.e.n == s.e.d)?;
    let w = |x: u64| T::of_words(false, word(x));
    let (vn, vd) = (w(s.v0.n)?, w(s.v0.d)?);
    let big_s = vd.mul(&raw.den)?;
    let state = |n: &T| Ratio::reduced(&vn.mul(n)?, &big_s);
    let mut values = [
        Some(state(&raw.nv)?),
        Some(state(&raw.n_big_v)?),
        Some(state(&raw.nw)?),
        None,
        None,
        None,
    ];
    let Parts {
        mn, md, big_d, gd, ..
    } = &parts;
    if wanted[3] {
        // J = m (v0 - v) = mn vn (den - nv) / (md S).
        let n = mn.mul(&vn)?.mul(&raw.den.sub(&raw.nv)?)?;
        values[3] = Some(Ratio::reduced(&n, &md.mul(&big_s)?)?);
    }
    let two_md_vd2 = md.mul(&vd)?.mul(&vd)?.mul(&T::small(2))?;
    if wanted[4] {
        values[4] = Some(Ratio::reduced(&mn.mul(&vn)?.mul(&vn)?, &two_md_vd2)?);
    }
    if wanted[5] {
        // (wv nv^2 + wV nV^2 + ww nw^2) vn^2 / (2 md Md gd S^2).
        let ke = kinetic(&parts.kinetic_weights()?, [&raw.nv, &raw.n_big_v, &raw.nw])?;
        let n = ke.mul(&vn)?.mul(&vn)?;
        let d = T::small(2)
            .mul(md)?
            .mul(big_d)?
            .mul(gd)?
            .mul(&big_s)?
            .mul(&big_s)?;
        values[5] = Some(Ratio::reduced(&n, &d)?);
    }
    let words = |x: &T| x.to_words();
    Some(Exact {
        values,
        raw: [
            words(&raw.nv)?,
            words(&raw.n_big_v)?,
            words(&raw.nw)?,
            words(&raw.den)?,
        ],
        laws_hold: raw.laws_hold,
    })
}

/// `wv x^2 + wV y^2 + ww z^2` for the weights of [`Parts::kinetic_weights`] (twice the kinetic
/// energy times `md Md gd`).
fn kinetic<T: FixedInt>([wv, w_big_v, ww]: &[T; 3], [x, y, z]: [&T; 3]) -> Option<T> {
    wv.mul(&x.mul(x)?)?
        .add(&w_big_v.mul(&y.mul(y)?)?)?
        .add(&ww.mul(&z.mul(z)?)?)
}

/// A claim as written: sign, numerator and denominator below 2^256 (`d > 0`, not reduced).
#[derive(Debug, Clone, Copy)]
struct Claim {
    negative: bool,
    n: U256,
    d: U256,
}

impl Claim {
    /// The claim of a cell on words (a fraction, or a decimal as its digits over a power of
    /// ten); `None` for anything else (units, NaN, empty: the general row's).
    fn parse(cell: &[u8]) -> Option<Claim> {
        let (negative, n, d) = WordRatio::parse_bytes(cell.trim_ascii())?.parts();
        Some(Claim { negative, n, d })
    }
}

/// A claimed value against the exact one: its check under `agreement`, exactly as
/// [`super::compare`] decides it (the relative error kept on words, not reduced).
fn check(k: usize, claim: Claim, x: &Ratio, agreement: &Agreement) -> Option<OutputCheck> {
    let rel_error = if x.n == U256::ZERO {
        // Only a zero claim agrees with a zero value; any other is infinitely far.
        (claim.n == U256::ZERO).then_some(RelError::ZERO)
    } else {
        let claimed = claim.n.checked_mul_wide(x.d)?;
        let value = x.n.checked_mul_wide(claim.d)?;
        let difference = U256::signed_distance(claim.negative, claimed, x.negative, value)?;
        Some(RelError::Words(difference, value))
    };
    Some(OutputCheck::finite(
        k,
        rel_error,
        None,
        agreement,
        Arithmetic::Exact,
    ))
}

/// The engine row of `line` (without its line ending), or `None` when the general row must
/// take it. See the module documentation.
pub(super) fn engine_row(
    plan: &WordPlan,
    agreement: &Agreement,
    number: usize,
    line: &str,
) -> Option<SolvedRow> {
    let mut parts = [None; 7];
    let mut rod = Rod::Uniform;
    let mut claims = [None; WORD_CLAIMS];
    each_cell(plan, line, |role, cell| {
        match role {
            Role::Scene(slot) if !cell.trim_ascii().is_empty() => {
                parts[slot] = Some(Part::parse(cell)?);
            }
            Role::Rod => rod = Rod::parse(cell)?,
            // An empty claim is not checked (and a state without it not audited).
            Role::Claim(_) if cell.trim_ascii().is_empty() => {}
            Role::Claim(k) => claims[k] = Some(Claim::parse(cell)?),
            Role::Scene(_) | Role::Passed => {}
        }
        Some(())
    })?;
    let scene = Scene::check(parts, rod)?;
    let exact = exact_in::<i128>(&scene, &plan.claimed)
        .or_else(|| exact_in::<Wide>(&scene, &plan.claimed))?;
    if !exact.laws_hold {
        return None;
    }
    let mut out = String::with_capacity(line.len() + 400);
    out.push_str(line);
    for value in exact.values.iter().flatten() {
        value.write_cell(&mut out);
    }
    out.push_str(",true");
    let mut checks = Vec::with_capacity(WORD_CLAIMS);
    for k in (0..WORD_CLAIMS).filter(|&k| plan.claimed[k]) {
        let Some(claim) = claims[k] else {
            out.push_str(",,");
            continue;
        };
        let value = exact.values[k].as_ref()?;
        let c = check(k, claim, value, agreement)?;
        c.write_cells(&mut out, false);
        checks.push(c);
    }
    let diagnosis = if plan.audits {
        let (change, diagnosis) = match [claims[0], claims[1], claims[2]] {
            [Some(v), Some(big_v), Some(omega)] => {
                diagnose(&scene, &exact, [v, big_v, omega], &checks)?
            }
            _ => ("-".to_string(), Diagnosis::NotAudited),
        };
        out.push(',');
        out.push_str(&change);
        out.push(',');
        out.push_str(&diagnosis.text());
        Some(diagnosis)
    } else {
        None
    };
    out.push('\n');
    Some(SolvedRow::unlabelled(
        number,
        out,
        Some(true),
        checks,
        diagnosis,
    ))
}

/// The energy change cell and the diagnosis, as the general row's `diagnose` gives them.
fn diagnose(
    scene: &Scene,
    exact: &Exact,
    state: [Claim; STATE],
    checks: &[OutputCheck],
) -> Option<(String, Diagnosis)> {
    let off = checks.iter().any(|c| !c.ok);
    if checks[..STATE].iter().all(OutputCheck::exact) {
        let findings = if off { vec![Finding::Off] } else { Vec::new() };
        return Some(("0".to_string(), Diagnosis::Findings(findings)));
    }
    let (mut findings, change) =
        audit::<I256>(scene, exact, state).or_else(|| audit::<Wide>(scene, exact, state))?;
    if findings.is_empty() && off {
        findings.push(Finding::Off);
    }
    Some((change, Diagnosis::Findings(findings)))
}

/// The claimed state over one denominator: `(Cv, CV, Cw)` and `q`. The denominators as
/// written; when they are equal, or below 2^128 and each divides the largest (decimals'
/// powers of ten), `q` is the largest, else their product.
fn common<T: FixedInt>(state: [Claim; STATE]) -> Option<([T; STATE], T)> {
    let small: Option<[u128; STATE]> = state
        .iter()
        .map(|c| (c.d.hi == 0).then_some(c.d.lo))
        .collect::<Option<Vec<u128>>>()
        .and_then(|v| v.try_into().ok());
    let one = U256::ONE;
    let (q, factors) = match small {
        _ if state[0].d == state[1].d && state[1].d == state[2].d => (state[0].d, [one; STATE]),
        Some(ds)
            if ds
                .iter()
                .all(|&d| ds.iter().max().is_some_and(|m| m % d == 0)) =>
        {
            let largest = ds.into_iter().max().unwrap_or(1);
            let factor = |d: u128| U256 {
                hi: 0,
                lo: largest / d,
            };
            (factor(1), ds.map(factor))
        }
        _ => {
            let [a, b, c] = state.map(|c| c.d);
            let ab = a.checked_mul_wide(b)?;
            (
                ab.checked_mul_wide(c)?,
                [b.checked_mul_wide(c)?, a.checked_mul_wide(c)?, ab],
            )
        }
    };
    let mut claimed = [T::small(0), T::small(0), T::small(0)];
    for (slot, (c, factor)) in claimed.iter_mut().zip(state.into_iter().zip(factors)) {
        *slot = T::of_words(c.negative, c.n)?.mul(&T::of_words(false, factor)?)?;
    }
    Some((claimed, T::of_words(false, q)?))
}

/// `|x|`.
fn abs<T: FixedInt>(x: T) -> Option<T> {
    if x.sign() == Ordering::Less {
        x.negated()
    } else {
        Some(x)
    }
}

/// The larger.
fn max<T: FixedInt>(x: T, y: T) -> T {
    if y.order(&x) == Ordering::Greater {
        y
    } else {
        x
    }
}

/// `x > y`.
fn greater<T: FixedInt>(x: &T, y: &T) -> bool {
    x.order(y) == Ordering::Greater
}

/// The audit of the claimed state in `T` (see [`super::audit::audit`] for what each finding
/// means): the findings in [`Finding::ALL`] order, without `Off`, and the energy change as
/// text; `None` when a value leaves the width (the general row then takes the row).
fn audit<T: FixedInt>(
    s: &Scene,
    exact: &Exact,
    state: [Claim; STATE],
) -> Option<(Vec<Finding>, String)> {
    let p = s.parts::<T>()?;
    let w = |x: u64| T::of_words(false, word(x));
    let raw = |k: usize| T::of_words(exact.raw[k].0, exact.raw[k].1);
    let (nv, n_big_v, nw, den) = (raw(0)?, raw(1)?, raw(2)?, raw(3)?);
    let (vn, vd) = (w(s.v0.n)?, w(s.v0.d)?);
    let (ln, ld) = (w(s.l.n)?, w(s.l.d)?);
    let ([cv, c_big_v, cw], q) = common::<T>(state)?;
    let big_s = vd.mul(&den)?;
    let c = |x: i64| T::of_words(x < 0, word(x.unsigned_abs()));
    let (law_n, law_d) = (c(LAW_TOLERANCE.0)?, c(LAW_TOLERANCE.1)?);
    let (state_n, state_d) = (c(STATE_TOLERANCE.0)?, c(STATE_TOLERANCE.1)?);
    let law_plus = law_d.add(&law_n)?;
    let mut findings = Vec::new();

    // Energies: Kc/q^2 against the exact vn^2 Ke/S^2 and the before wv vn^2/vd^2.
    let weights = p.kinetic_weights()?;
    let wv = weights[0];
    let kc = kinetic(&weights, [&cv, &c_big_v, &cw])?;
    let ke = kinetic(&weights, [&nv, &n_big_v, &nw])?;
    let (vn2, q2, vd2, den2) = (vn.mul(&vn)?, q.mul(&q)?, vd.mul(&vd)?, den.mul(&den)?);
    // E_c > E_b (1 + law): law_d Kc vd^2 > (law_d + law_n) wv vn^2 q^2.
    if greater(
        &law_d.mul(&kc)?.mul(&vd2)?,
        &law_plus.mul(&wv)?.mul(&vn2)?.mul(&q2)?,
    ) {
        findings.push(Finding::EnergyGain);
    }
    // E_c < E_e - law E_b: law_d Kc S^2 < vn^2 q^2 (law_d Ke - law_n wv den^2).
    let s2 = big_s.mul(&big_s)?;
    let allowed = law_d.mul(&ke)?.sub(&law_n.mul(&wv)?.mul(&den2)?)?;
    if greater(&vn2.mul(&q2)?.mul(&allowed)?, &law_d.mul(&kc)?.mul(&s2)?) {
        findings.push(Finding::EnergyLoss);
    }

    // Distances: the largest of |Cv T - q X1| ld, |CV T - q X2| ld, |Cw T - q X3| ln over
    // q T ld, for a state (X1, X2, X3)/T, from the claimed side (Cv T, CV T, Cw T) and the
    // state's (q X1, q X2, q X3): the exact state, the state before and the flipped spin share
    // T = S, and the larger of the first two gaps is found before `ld > 0` scales it.
    let distance = |claimed: &[T; 3], state: [&T; 3]| -> Option<T> {
        let gap = |k: usize| abs(claimed[k].sub(state[k])?);
        Some(max(max(gap(0)?, gap(1)?).mul(&ld)?, gap(2)?.mul(&ln)?))
    };
    let (ev, e_big_v, ew) = (vn.mul(&nv)?, vn.mul(&n_big_v)?, vn.mul(&nw)?);
    let over_s = [cv.mul(&big_s)?, c_big_v.mul(&big_s)?, cw.mul(&big_s)?];
    let exact_side = [q.mul(&ev)?, q.mul(&e_big_v)?, q.mul(&ew)?];
    let to_exact = distance(&over_s, [&exact_side[0], &exact_side[1], &exact_side[2]])?;
    // Within STATE_TOLERANCE |v0| of another state, over T = k S, and strictly nearer to it
    // than to the exact state: state_d vd D_o <= state_n vn q ld S k, and D_o S < D_e T, which
    // is D_o < D_e k: S = vd den > 0 (den is ed times a sum of positive terms; were it not,
    // the general row would take the row).
    if big_s.sign() != Ordering::Greater {
        return None;
    }
    let scaled_d = state_d.mul(&vd)?;
    let reach = state_n.mul(&vn)?.mul(&q)?.mul(&ld)?.mul(&big_s)?;
    let taken_for = |d: T, k: Option<&T>| -> Option<bool> {
        let (reach, nearer) = match k {
            None => (reach, to_exact),
            Some(k) => (reach.mul(k)?, to_exact.mul(k)?),
        };
        Some(!greater(&scaled_d.mul(&d)?, &reach) && greater(&nearer, &d))
    };
    let (en, ed) = (w(s.e.n)?, w(s.e.d)?);
    if en.sign() == Ordering::Greater {
        // The e = 0 answer: (vn (den ne + (nv - den) ed), vn nV ed, vn nw ed)/(S ne).
        let ne = ed.add(&en)?;
        let v = vn.mul(&den.mul(&ne)?.add(&nv.sub(&den)?.mul(&ed)?)?)?;
        let claimed = [
            over_s[0].mul(&ne)?,
            over_s[1].mul(&ne)?,
            over_s[2].mul(&ne)?,
        ];
        let state = [q.mul(&v)?, exact_side[1].mul(&ed)?, exact_side[2].mul(&ed)?];
        let d = distance(&claimed, [&state[0], &state[1], &state[2]])?;
        if taken_for(d, Some(&ne))? {
            findings.push(Finding::RestitutionIgnored);
        }
    }
    let zero = T::small(0);
    let before = q.mul(&vn)?.mul(&den)?;
    if taken_for(distance(&over_s, [&before, &zero, &zero])?, None)? {
        findings.push(Finding::NoContact);
    }
    let (pn, pd) = match &p.pivot {
        Some((pn, pd)) => (*pn, *pd),
        None => (zero, T::small(1)),
    };
    let (mn_big_d, big_n_md) = (p.mn.mul(&p.big_d)?, p.big_n.mul(&p.md)?);
    if p.pivot.is_none() {
        // m v0 - (m v + M V), times md Md q vd, against law m |v0|.
        let residual = mn_big_d
            .mul(&q)?
            .mul(&vn)?
            .sub(&vd.mul(&mn_big_d.mul(&cv)?.add(&big_n_md.mul(&c_big_v)?)?)?)?;
        if greater(
            &law_d.mul(&abs(residual)?)?,
            &law_n.mul(&mn_big_d)?.mul(&q)?.mul(&vn)?,
        ) {
            findings.push(Finding::Momentum);
        }
    }
    // Angular momentum about the axis y = p (0 for a free rod), with a - y = dn/dq:
    // m (a - y)(v0 - v) - I omega + M y V, times md dq vd q Md gd pd.
    let dn = p.an.mul(&pd)?.sub(&pn.mul(&p.ad)?)?;
    let dq = p.ad.mul(&pd)?;
    let residual =
        p.mn.mul(&dn)?
            .mul(&p.big_d)?
            .mul(&p.gd)?
            .mul(&pd)?
            .mul(&vn.mul(&q)?.sub(&vd.mul(&cv)?)?)?
            .sub(
                &big_n_md
                    .mul(&p.gn)?
                    .mul(&dq)?
                    .mul(&pd)?
                    .mul(&vd)?
                    .mul(&cw)?,
            )?
            .add(
                &big_n_md
                    .mul(&pn)?
                    .mul(&dq)?
                    .mul(&p.gd)?
                    .mul(&vd)?
                    .mul(&c_big_v)?,
            )?;
    // Against law m |v0| l: law_d |R| ld > law_n mn vn ln dq q Md gd pd.
    let scale =
        p.mn.mul(&vn)?
            .mul(&ln)?
            .mul(&dq)?
            .mul(&q)?
            .mul(&p.big_d)?
            .mul(&p.gd)?
            .mul(&pd)?;
    if greater(&law_d.mul(&abs(residual)?)?.mul(&ld)?, &law_n.mul(&scale)?) {
        findings.push(Finding::AngularMomentum);
    }
    // omega^2 > omega_max^2 (1 + law)^2: Cw^2 Wd law_d^2 > Wn law_plus^2 q^2.
    let (wn, wd) = omega_max_squared(s, &p)?;
    if greater(
        &cw.mul(&cw)?.mul(&wd)?.mul(&law_d)?.mul(&law_d)?,
        &wn.mul(&law_plus)?.mul(&law_plus)?.mul(&q2)?,
    ) {
        findings.push(Finding::AboveOmegaMax);
    }
    if nw.sign() != Ordering::Equal {
        let flipped = exact_side[2].negated()?;
        let d = distance(&over_s, [&exact_side[0], &exact_side[1], &flipped])?;
        if taken_for(d, None)? {
            findings.push(Finding::OmegaSign);
        }
    }
    // (E_c - E_e)/E_b = (Kc vd^2 den^2 - vn^2 Ke q^2) / (q^2 den^2 wv vn^2).
    let change_n = kc.mul(&vd2)?.mul(&den2)?.sub(&vn2.mul(&ke)?.mul(&q2)?)?;
    let change_d = q2.mul(&den2)?.mul(&wv)?.mul(&vn2)?;
    let ((negative, n), (_, d)) = (change_n.to_words()?, change_d.to_words()?);
    let text = crate::field::decimal::decimal_words(negative, n, d, 3);
    let change = if change_n.sign() == Ordering::Greater {
        format!("+{text}")
    } else {
        text
    };
    Some((findings, change))
}

/// omega_max^2 as `(Wn, Wd)` ([`crate::solve::optimum::omega_max_squared_of`]): with a*^2 =
/// `sn/sd` and the struck arm `rn/rd`, `(1 + e)^2 v0^2 / (4 a*^2)` when `a* <= arm`, else
/// omega at the arm's end squared, `((1 + e) v0 arm / (a*^2 + arm^2))^2`.
fn omega_max_squared<T: FixedInt>(s: &Scene, p: &Parts<T>) -> Option<(T, T)> {
    let w = |x: u64| T::of_words(false, word(x));
    let (ln, ld) = (w(s.l.n)?, w(s.l.d)?);
    let ((sn, sd), (rn, rd)) = match &p.pivot {
        // a*^2 = I (M + m)/(m M) = gn (Mn md + mn Md) / (gd Md mn); the arm l.
        None => {
            let sn = p.gn.mul(&p.big_n.mul(&p.md)?.add(&p.mn.mul(&p.big_d)?)?)?;
            ((sn, p.gd.mul(&p.big_d)?.mul(&p.mn)?), (ln, ld))
        }
        // a*^2 = (I + M p^2)/m = Mn md (gn pd^2 + pn^2 gd) / (Md gd pd^2 mn); the arm from the
        // pivot to the struck end, l - p toward +l, l + p toward -l.
        Some((pn, pd)) => {
            let pd2 = pd.mul(pd)?;
            let inertia = p.gn.mul(&pd2)?.add(&pn.mul(pn)?.mul(&p.gd)?)?;
            let sn = p.big_n.mul(&p.md)?.mul(&inertia)?;
            let sd = p.big_d.mul(&p.gd)?.mul(&pd2)?.mul(&p.mn)?;
            let side = p.an.mul(pd)?.sub(&pn.mul(&p.ad)?)?.sign();
            let toward_plus = match side {
                Ordering::Equal => pn.sign() != Ordering::Greater,
                side => side == Ordering::Greater,
            };
            let l_pd = ln.mul(pd)?;
            let p_ld = pn.mul(&ld)?;
            let rn = if toward_plus {
                l_pd.sub(&p_ld)?
            } else {
                l_pd.add(&p_ld)?
            };
            ((sn, sd), (rn, ld.mul(pd)?))
        }
    };
    let (en, ed) = (w(s.e.n)?, w(s.e.d)?);
    let (vn, vd) = (w(s.v0.n)?, w(s.v0.d)?);
    // (1 + e) v0 = ne vn/(ed vd).
    let top = ed.add(&en)?.mul(&vn)?;
    let bottom = ed.mul(&vd)?;
    let (rn2, rd2) = (rn.mul(&rn)?, rd.mul(&rd)?);
    if !greater(&sn.mul(&rd2)?, &rn2.mul(&sd)?) {
        // top^2 sd / (4 bottom^2 sn).
        let wn = top.mul(&top)?.mul(&sd)?;
        let wd = T::small(4).mul(&bottom)?.mul(&bottom)?.mul(&sn)?;
        Some((wn, wd))
    } else {
        // (top rn sd rd)^2 / (bottom (sn rd^2 + rn^2 sd))^2.
        let n = top.mul(&rn)?.mul(&sd)?.mul(&rd)?;
        let d = bottom.mul(&sn.mul(&rd2)?.add(&rn2.mul(&sd)?)?)?;
        Some((n.mul(&n)?, d.mul(&d)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::Batch;

    /// Rows of the engine fixtures (Box2D f32 with each rod, Rapier f64 on a pivot and at the
    /// pivot itself): each taken on words, each the general row's line (reached by an absolute
    /// tolerance of zero, which the word rows leave to it).
    #[test]
    fn an_engines_rows_are_taken_on_words_with_the_general_rows_lines() {
        let header = "id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,v,V,omega,J,energy_before,energy_after";
        let words = Batch::new(header, Arithmetic::Exact).unwrap();
        let general = words.clone().with_atol("0").unwrap();
        let plan = words
            .word_plan
            .as_ref()
            .expect("an engine's header has a word plan");
        assert!(!plan.paper);
        for line in [
            "free-inside-7,box2d,2.3.10,f32,1/60,8,free-inside,1,1,1,1/2,3,I=1/5,1/2,,1.6153846,1.3846155,3.4615383,1.3846154,4.5,3.4615386",
            "free-inside-6,box2d,2.3.10,f32,1/60,8,free-inside,1,1,1,1/2,3,rg=1/2,1,,1,2,4,2,4.5,4.5",
            "free-inside-5,box2d,2.3.10,f32,1/60,8,free-inside,1,1,1,1/2,3,dumbbell,1,,0.33333325,2.6666667,1.3333334,2.6666667,4.5,4.5000005",
            "pivot-at-impact-1,rapier2d,0.36.1,f64,1/60,1,pivot-at-impact,1,1,1,1/2,3,uniform,1,1/2,-1.6287699050404494,-0.0006828934984906771,0.0013657869973352017,4.62876990504045,4.5,1.3264462458501896",
            "pivot-centre-2,rapier2d,0.36.1,f64,1/60,1,pivot-centre,1,1,1,1,3,uniform,1/2,0,1.9735933931375842,0,3.0792198205872467,1.0264066068624158,4.5,3.5278012246343877",
        ] {
            let fast = engine_row(plan, &Agreement::Exact, 1, line).expect(line);
            let mut slow = general.row(1, line).unwrap();
            slow.label = None;
            slow.expectation = None;
            assert_eq!(fast, slow, "{line}");
        }
        // A centre hit at 1 m/s (exact: v = 0, V = 1) claimed as the state before the impact:
        // the same energy and momentum, named as no contact; v infinitely off, V and J by 1.
        let still = "c,x,1,f64,1/60,1,c,1,1,1,0,1,uniform,1,,1,0,0,0,1/2,1/2";
        let row = engine_row(plan, &Agreement::Exact, 1, still).unwrap();
        let want = ",0,1,0,1,1/2,1/2,true,false,inf,false,1.00,true,0,false,1.00,true,0,true,0,0,no-contact\n";
        assert!(row.line.ends_with(want), "{}", row.line);
    }

    /// What the word rows leave to the general row: a unit, a non-finite claim, a scene the
    /// general row refuses; an ulps rule drops the word plan altogether.
    #[test]
    fn rows_beyond_the_words_are_left_to_the_general_row() {
        let words = Batch::new("m,M,rod,pivot,v,V,omega", Arithmetic::Exact).unwrap();
        let plan = words.word_plan.as_ref().unwrap();
        for line in [
            "1 kg,1,uniform,,0.6,0.4,1.2",
            "1,1,uniform,,NaN,0.4,1.2",
            "1,1,rg=2,,0.6,0.4,1.2",
            "1,1,steel,,0.6,0.4,1.2",
            "1,1,uniform,2,0.6,0.4,1.2",
            "1,-1,uniform,,0.6,0.4,1.2",
        ] {
            assert!(
                engine_row(plan, &Agreement::Exact, 1, line).is_none(),
                "{line}"
            );
        }
        let ulps = Agreement::Ulps(1, super::super::FloatFormat::F64);
        assert!(words.with_agreement(ulps).unwrap().word_plan.is_none());
    }
}
