//! The audit of an engine row's claimed state on words: the balances, distances and bound of
//! [`crate::batch::audit`] as exact integer comparisons over common denominators in 256 bits,
//! else 512, 1024 or 2560 (an engine's claim of 5e-107 or 5e-324 for a zero, squared). What
//! depends on the scene alone ([`AuditScene`]) is computed once a scene; a row adds its claims.
//! See the parent module for the notation.

use super::{Claim, Exact, STATE, Scene, Solved, kinetic, word};
use crate::batch::audit::{Finding, LAW_TOLERANCE, STATE_TOLERANCE};
use crate::batch::plan::{Diagnosis, OutputCheck};
use crate::field::decimal::{decimal_unreduced, push_decimal_words};
use crate::field::int::{FixedInt, I256, U256, Wide, Wider, Widest};
use crate::solve::fast::fraction_free::Parts;
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The denominator of a claim in `T`, its power of ten included, if it fits.
fn denominator<T: FixedInt>(c: &Claim) -> Option<T> {
    let d = T::of_words(false, c.denom)?;
    if c.tens == 0 {
        Some(d)
    } else {
        d.mul(&ten::<T>(c.tens)?)
    }
}

/// `10^k` in `T`, if it fits.
fn ten<T: FixedInt>(k: u32) -> Option<T> {
    // 10^k > 2^(3.321 k): past the width without a product.
    if u64::from(k) * 3321 >= u64::from(T::BITS) * 1000 {
        return None;
    }
    let chunk = k.min(76);
    let head = T::of_words(false, U256::pow10(chunk)?)?;
    if k == chunk {
        Some(head)
    } else {
        head.mul(&ten::<T>(k - chunk)?)
    }
}

/// The diagnosis, as the general row's `diagnose` gives it, with the energy change cell
/// written to `out`.
pub(super) fn diagnose(
    solved: &Solved,
    state: [Claim; STATE],
    checks: &[OutputCheck],
    out: &mut String,
) -> Option<Diagnosis> {
    let off = checks.iter().any(|c| !c.ok);
    if checks[..STATE].iter().all(OutputCheck::exact) {
        out.push('0');
        let findings = if off { vec![Finding::Off] } else { Vec::new() };
        return Some(Diagnosis::Findings(findings));
    }
    let widths = &solved.audits;
    let mut findings = audit_in(&widths.words, solved, state, out)
        .or_else(|| audit_in(&widths.wide, solved, state, out))
        .or_else(|| audit_in(&widths.wider, solved, state, out))
        .or_else(|| audit_in(&widths.widest, solved, state, out))?;
    if findings.is_empty() && off {
        findings.push(Finding::Off);
    }
    Some(Diagnosis::Findings(findings))
}

/// The scene's part of the audit in each width, made when a row first needs it (`None`: the
/// scene is past the width). Boxed: the widest is 9 kB, which a scene solved anew would
/// otherwise copy on each move.
#[derive(Default)]
pub(super) struct AuditScenes {
    words: Width<I256>,
    wide: Width<Wide>,
    wider: Width<Wider>,
    widest: Width<Widest>,
}

/// The scene's part of the audit in `T`, once made.
type Width<T> = OnceCell<Option<Box<AuditScene<T>>>>;

/// [`audit`] in `T`, on the scene's part in `T` kept in `cell`.
fn audit_in<T: FixedInt>(
    cell: &Width<T>,
    solved: &Solved,
    state: [Claim; STATE],
    out: &mut String,
) -> Option<Vec<Finding>> {
    let scene = cell.get_or_init(|| AuditScene::of(&solved.scene, &solved.exact).map(Box::new));
    audit(scene.as_deref()?, state, out)
}

/// The claimed state over one denominator: `(Cv, CV, Cw)` and `q`. Decimals (digits over
/// powers of ten) take the largest power; fractions whose denominators are equal, or below
/// 2^128 with each dividing the largest, take the largest; any other take their product.
fn common<T: FixedInt>(state: [Claim; STATE]) -> Option<([T; STATE], T)> {
    let (q, factors) = if state.iter().all(|c| c.denom == U256::ONE) {
        let top = state.iter().map(|c| c.tens).max().unwrap_or(0);
        let [a, b, c] = state.map(|c| ten::<T>(top - c.tens));
        (ten::<T>(top)?, [a?, b?, c?])
    } else {
        common_of_fractions(state)?
    };
    let mut claimed = [T::small(0), T::small(0), T::small(0)];
    for (slot, (c, factor)) in claimed.iter_mut().zip(state.into_iter().zip(factors)) {
        *slot = T::of_words(c.negative, c.numer)?.mul(&factor)?;
    }
    Some((claimed, q))
}

/// [`common`]'s denominator and factors for claims that are not all decimals.
fn common_of_fractions<T: FixedInt>(state: [Claim; STATE]) -> Option<(T, [T; STATE])> {
    let one = T::small(1);
    let plain = state.iter().all(|c| c.tens == 0);
    if plain && state[0].denom == state[1].denom && state[1].denom == state[2].denom {
        return Some((T::of_words(false, state[0].denom)?, [one; STATE]));
    }
    if plain && state.iter().all(|c| c.denom.hi == 0) {
        let ds = state.map(|c| c.denom.lo);
        let largest = ds.iter().copied().max().unwrap_or(1);
        if ds.iter().all(|&d| largest % d == 0) {
            let factor = |d: u128| {
                T::of_words(
                    false,
                    U256 {
                        hi: 0,
                        lo: largest / d,
                    },
                )
            };
            return Some((factor(1)?, [factor(ds[0])?, factor(ds[1])?, factor(ds[2])?]));
        }
    }
    let [a, b, c] = state.map(|c| denominator::<T>(&c));
    let (a, b, c) = (a?, b?, c?);
    let ab = a.mul(&b)?;
    Some((ab.mul(&c)?, [b.mul(&c)?, a.mul(&c)?, ab]))
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

/// What the audit needs of the scene and its exact answer alone, in `T`: the products of its
/// comparisons that no claim enters, each named for the comparison it serves (see [`audit`]).
/// A scene's rows share it ([`Solved`] keeps it, [`AuditScenes`]).
struct AuditScene<T> {
    weights: [T; 3],
    /// The rod's half length `(ln, ld)`: the distances weigh the spin by it.
    lengths: (T, T),
    /// The law's tolerance's denominator.
    law_d: T,
    /// `S = vd den`.
    big_s: T,
    /// Energy gain: `Kc law_d vd^2 > law_plus wv vn^2 q^2`.
    gain: (T, T),
    /// Energy loss: `vn^2 (law_d Ke - law_n wv den^2) q^2 > Kc law_d S^2`.
    loss: (T, T),
    /// The exact state's side of a distance before `q`: `vn (nv, nV, nw)`.
    exact: [T; 3],
    /// Within reach: `state_d vd D <= state_n vn ld S q k`: `(state_d vd, state_n vn ld S)`.
    reach: (T, T),
    /// The e = 0 answer (for e > 0): `1 + e` as `ne` over `ed`, and its v side before `q`.
    sticking: Option<(T, T, T)>,
    /// The state before the impact, v side before `q`: `vn den`.
    before: T,
    /// Linear momentum (a free rod): the residual `mn Md vn q - (vd mn Md Cv + vd Mn md CV)`
    /// against `law_d |R| > law_n mn Md vn q`.
    momentum: Option<[T; 4]>,
    /// Angular momentum: the residual `A1 vn q - A1 vd Cv - A2 Cw + A3 CV` against
    /// `law_d ld |R| > law_n S0 q`: `[A1 vn, A1 vd, A2, A3, law_d ld, law_n S0]`.
    angular: [T; 6],
    /// Above omega_max: `Cw^2 Wd law_d^2 > Wn law_plus^2 q^2`.
    omega: (T, T),
    /// The energy change `(Kc vd^2 den^2 - vn^2 Ke q^2) / (q^2 den^2 wv vn^2)`.
    change: [T; 3],
}

impl<T: FixedInt> AuditScene<T> {
    /// The scene's part of the audit in `T`; `None` when a value leaves the width.
    fn of(s: &Scene, exact: &Exact) -> Option<AuditScene<T>> {
        let p = s.parts::<T>()?;
        let w = |x: u64| T::of_words(false, word(x));
        let raw = |k: usize| T::of_words(exact.raw[k].0, exact.raw[k].1);
        let (nv, n_big_v, nw, den) = (raw(0)?, raw(1)?, raw(2)?, raw(3)?);
        let (vn, vd) = (w(s.v0.n)?, w(s.v0.d)?);
        let (ln, ld) = (w(s.l.n)?, w(s.l.d)?);
        let big_s = vd.mul(&den)?;
        // S = vd den > 0 (den is ed times a sum of positive terms; were it not, the general
        // row would take the row): the distances below divide by it.
        if big_s.sign() != Ordering::Greater {
            return None;
        }
        let c = |x: i64| T::of_words(x < 0, word(x.unsigned_abs()));
        let (law_n, law_d) = (c(LAW_TOLERANCE.0)?, c(LAW_TOLERANCE.1)?);
        let (state_n, state_d) = (c(STATE_TOLERANCE.0)?, c(STATE_TOLERANCE.1)?);
        let law_plus = law_d.add(&law_n)?;
        let weights = p.kinetic_weights()?;
        let wv = weights[0];
        let ke = kinetic(&weights, [&nv, &n_big_v, &nw])?;
        let (vn2, vd2, den2) = (vn.mul(&vn)?, vd.mul(&vd)?, den.mul(&den)?);
        let allowed = law_d.mul(&ke)?.sub(&law_n.mul(&wv)?.mul(&den2)?)?;
        let (en, ed) = (w(s.e.n)?, w(s.e.d)?);
        let sticking = if en.sign() == Ordering::Greater {
            // The e = 0 answer: (vn (den ne + (nv - den) ed), vn nV ed, vn nw ed)/(S ne).
            let ne = ed.add(&en)?;
            let v = vn.mul(&den.mul(&ne)?.add(&nv.sub(&den)?.mul(&ed)?)?)?;
            Some((ne, v, ed))
        } else {
            None
        };
        let zero = T::small(0);
        let (pn, pd) = match &p.pivot {
            Some((pn, pd)) => (*pn, *pd),
            None => (zero, T::small(1)),
        };
        let (mn_big_d, big_n_md) = (p.mn.mul(&p.big_d)?, p.big_n.mul(&p.md)?);
        let momentum = match p.pivot {
            Some(_) => None,
            None => Some([
                mn_big_d.mul(&vn)?,
                vd.mul(&mn_big_d)?,
                vd.mul(&big_n_md)?,
                law_n.mul(&mn_big_d)?.mul(&vn)?,
            ]),
        };
        // Angular momentum about the axis y = p (0 for a free rod), with a - y = dn/dq:
        // m (a - y)(v0 - v) - I omega + M y V, times md dq vd q Md gd pd; its scale m |v0| l
        // times the same, over ld.
        let dn = p.an.mul(&pd)?.sub(&pn.mul(&p.ad)?)?;
        let dq = p.ad.mul(&pd)?;
        let a1 = p.mn.mul(&dn)?.mul(&p.big_d)?.mul(&p.gd)?.mul(&pd)?;
        let a2 = big_n_md.mul(&p.gn)?.mul(&dq)?.mul(&pd)?.mul(&vd)?;
        let a3 = big_n_md.mul(&pn)?.mul(&dq)?.mul(&p.gd)?.mul(&vd)?;
        let scale =
            p.mn.mul(&vn)?
                .mul(&ln)?
                .mul(&dq)?
                .mul(&p.big_d)?
                .mul(&p.gd)?
                .mul(&pd)?;
        let (wn, wd) = omega_max_squared(s, &p)?;
        Some(AuditScene {
            weights,
            lengths: (ln, ld),
            law_d,
            big_s,
            gain: (law_d.mul(&vd2)?, law_plus.mul(&wv)?.mul(&vn2)?),
            loss: (vn2.mul(&allowed)?, law_d.mul(&big_s.mul(&big_s)?)?),
            exact: [vn.mul(&nv)?, vn.mul(&n_big_v)?, vn.mul(&nw)?],
            reach: (state_d.mul(&vd)?, state_n.mul(&vn)?.mul(&ld)?.mul(&big_s)?),
            sticking,
            before: vn.mul(&den)?,
            momentum,
            angular: [
                a1.mul(&vn)?,
                a1.mul(&vd)?,
                a2,
                a3,
                law_d.mul(&ld)?,
                law_n.mul(&scale)?,
            ],
            omega: (
                wd.mul(&law_d)?.mul(&law_d)?,
                wn.mul(&law_plus)?.mul(&law_plus)?,
            ),
            change: [vd2.mul(&den2)?, vn2.mul(&ke)?, den2.mul(&wv)?.mul(&vn2)?],
        })
    }
}

/// The audit of the claimed state in `T` (see [`crate::batch::audit::audit`] for what each
/// finding means), on the scene's part `a` in `T`: the findings in [`Finding::ALL`] order,
/// without `Off`, with the energy change written to `out`; `None` (and nothing written) when a
/// value leaves the width (a wider one, or the general row, then takes the row).
fn audit<T: FixedInt>(
    a: &AuditScene<T>,
    state: [Claim; STATE],
    out: &mut String,
) -> Option<Vec<Finding>> {
    let ([cv, c_big_v, cw], q) = common::<T>(state)?;
    let mut findings = Vec::new();

    // Energies: Kc/q^2 against the exact vn^2 Ke/S^2 and the before wv vn^2/vd^2.
    let kc = kinetic(&a.weights, [&cv, &c_big_v, &cw])?;
    let q2 = q.mul(&q)?;
    if greater(&kc.mul(&a.gain.0)?, &a.gain.1.mul(&q2)?) {
        findings.push(Finding::EnergyGain);
    }
    if greater(&a.loss.0.mul(&q2)?, &kc.mul(&a.loss.1)?) {
        findings.push(Finding::EnergyLoss);
    }

    // Distances: the largest of |Cv T - q X1| ld, |CV T - q X2| ld, |Cw T - q X3| ln over
    // q T ld, for a state (X1, X2, X3)/T, from the claimed side (Cv T, CV T, Cw T) and the
    // state's (q X1, q X2, q X3): the exact state, the state before and the flipped spin share
    // T = S, and the larger of the first two gaps is found before `ld > 0` scales it.
    let (ln, ld) = (&a.lengths.0, &a.lengths.1);
    let distance = |claimed: &[T; 3], state: [&T; 3]| -> Option<T> {
        let gap = |k: usize| abs(claimed[k].sub(state[k])?);
        Some(max(max(gap(0)?, gap(1)?).mul(ld)?, gap(2)?.mul(ln)?))
    };
    let over_s = [cv.mul(&a.big_s)?, c_big_v.mul(&a.big_s)?, cw.mul(&a.big_s)?];
    let exact_side = [
        q.mul(&a.exact[0])?,
        q.mul(&a.exact[1])?,
        q.mul(&a.exact[2])?,
    ];
    let to_exact = distance(&over_s, [&exact_side[0], &exact_side[1], &exact_side[2]])?;
    // Within STATE_TOLERANCE |v0| of another state, over T = k S, and strictly nearer to it
    // than to the exact state: state_d vd D_o <= state_n vn q ld S k, and D_o S < D_e T, which
    // is D_o < D_e k.
    let reach = a.reach.1.mul(&q)?;
    let taken_for = |d: T, k: Option<&T>| -> Option<bool> {
        let (reach, nearer) = match k {
            None => (reach, to_exact),
            Some(k) => (reach.mul(k)?, to_exact.mul(k)?),
        };
        Some(!greater(&a.reach.0.mul(&d)?, &reach) && greater(&nearer, &d))
    };
    if let Some((ne, v, ed)) = &a.sticking {
        let claimed = [over_s[0].mul(ne)?, over_s[1].mul(ne)?, over_s[2].mul(ne)?];
        let state = [q.mul(v)?, exact_side[1].mul(ed)?, exact_side[2].mul(ed)?];
        let d = distance(&claimed, [&state[0], &state[1], &state[2]])?;
        if taken_for(d, Some(ne))? {
            findings.push(Finding::RestitutionIgnored);
        }
    }
    let zero = T::small(0);
    let before = q.mul(&a.before)?;
    if taken_for(distance(&over_s, [&before, &zero, &zero])?, None)? {
        findings.push(Finding::NoContact);
    }
    if let Some([m1, m2, m3, m4]) = &a.momentum {
        // m v0 - (m v + M V), times md Md q vd, against law m |v0|.
        let residual = m1.mul(&q)?.sub(&m2.mul(&cv)?.add(&m3.mul(&c_big_v)?)?)?;
        if greater(&a.law_d.mul(&abs(residual)?)?, &m4.mul(&q)?) {
            findings.push(Finding::Momentum);
        }
    }
    let [a1_vn, a1_vd, a2, a3, law_ld, law_scale] = &a.angular;
    let residual = a1_vn
        .mul(&q)?
        .sub(&a1_vd.mul(&cv)?)?
        .sub(&a2.mul(&cw)?)?
        .add(&a3.mul(&c_big_v)?)?;
    if greater(&law_ld.mul(&abs(residual)?)?, &law_scale.mul(&q)?) {
        findings.push(Finding::AngularMomentum);
    }
    if greater(&cw.mul(&cw)?.mul(&a.omega.0)?, &a.omega.1.mul(&q2)?) {
        findings.push(Finding::AboveOmegaMax);
    }
    // A flipped spin is another answer only where the exact spin (vn nw, vn > 0) is not zero.
    if a.exact[2].sign() != Ordering::Equal {
        let flipped = exact_side[2].negated()?;
        let d = distance(&over_s, [&exact_side[0], &exact_side[1], &flipped])?;
        if taken_for(d, None)? {
            findings.push(Finding::OmegaSign);
        }
    }
    let change_n = kc.mul(&a.change[0])?.sub(&a.change[1].mul(&q2)?)?;
    let change_d = q2.mul(&a.change[2])?;
    if change_n.sign() == Ordering::Greater {
        out.push('+');
    }
    match (change_n.to_words(), change_d.to_words()) {
        (Some((negative, n)), Some((_, d))) => push_decimal_words(out, negative, n, d, 3, None),
        // Past 256 bits (a claim of 5e-107 squared): the same digits from big integers.
        _ => out.push_str(&decimal_unreduced(
            &change_n.to_big(),
            &change_d.to_big(),
            3,
        )),
    }
    Some(findings)
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
