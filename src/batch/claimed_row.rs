//! An engine's row on machine words: the paper's scene with any rod (`uniform`, `dumbbell`,
//! `rg=Q`, `I=Q`), free or pivoted, any e, claims among v, V, omega, J and the energies, and
//! the audit of the claimed state, with no big integer and no GCD but the outputs' own.
//!
//! The cells are read as written (a decimal is its digits over a power of ten), the scene is
//! solved by the fraction-free formulas ([`crate::solve::fast::fraction_free::raw_of`]) in `i128` or
//! 512 bits, every exact output is reduced once on words, and the audit's balances, distances
//! and bound are decided as exact integer comparisons over common denominators (the `audit`
//! submodule), in 256 bits, else 512, 1024 or 2560 (an engine's claim of 5e-107 or 5e-324
//! for a zero, squared).
//!
//! A scene is solved once, not once a row: an engine's log runs each scene at every time step
//! and iteration count it tries, row after row, and each thread keeps the scene it solved
//! last and a table of recent ones ([`last_scene`]), with their exact outputs' text and the
//! audit's part of it ([`Solved`]).
//!
//! An oblique header's rows have a row of their own (the `oblique` submodule): its scene read
//! on words as here and solved by the same formulas at the approach speed, completed along the
//! rod on unreduced fractions, once a scene, and its claims checked here on words.
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

use super::compare::Agreement;
use super::fixed_width_row::each_cell;
use super::last_scene;
use super::plan::{
    Arithmetic, Diagnosis, OutputCheck, Role, STATE, SolvedRow, WORD_CLAIMS, WordPlan,
};
use super::rel_error::RelError;
use crate::field::int::{FixedInt, U256, Wide, reduced_words};
use crate::number::ScaledRatio;
use crate::solve::fast::fixed_width::Part;
use crate::solve::fast::fraction_free::{Parts, Raw, raw_of};

mod audit;
mod oblique;
use audit::{AuditScenes, diagnose};
pub(super) use oblique::oblique_row;

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
        let (negative, n, d) = reduced_words(n, d)?;
        Some(Ratio { negative, n, d })
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

/// A row's scene cells as written, trimmed: m, M, l, a, v0, e, pivot (the slots of
/// [`Role::Scene`]), then the rod; empty where the header has no such column.
type SceneCells<'a> = [&'a [u8]; SCENE_CELLS];

/// The number of scene cells: the seven numbers and the rod.
const SCENE_CELLS: usize = 8;

/// Where the rod's cell sits among the scene cells.
const ROD: usize = 7;

/// A scene solved on words (kept for its rows by [`super::last_scene`]).
struct Solved {
    scene: Scene,
    exact: Exact,
    /// The exact outputs' cells as the row writes them (`,v,V,omega...`).
    cells: String,
    /// The scene's part of the audit, in each width a row needs.
    audits: AuditScenes,
}

impl Solved {
    /// The scene of `cells` checked, solved and its outputs written; `None` when the general
    /// row must take it.
    fn of(cells: &SceneCells, wanted: &[bool; WORD_CLAIMS]) -> Option<Solved> {
        let mut parts = [None; 7];
        for (part, cell) in parts.iter_mut().zip(cells) {
            if !cell.is_empty() {
                *part = Some(Part::parse(cell)?);
            }
        }
        let scene = Scene::check(parts, Rod::parse(cells[ROD])?)?;
        let exact =
            exact_in::<i128>(&scene, wanted).or_else(|| exact_in::<Wide>(&scene, wanted))?;
        if !exact.laws_hold {
            return None;
        }
        let mut written = String::with_capacity(160);
        for value in exact.values.iter().flatten() {
            value.write_cell(&mut written);
        }
        Some(Solved {
            scene,
            exact,
            cells: written,
            audits: AuditScenes::default(),
        })
    }
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

/// A claim as written: a fraction, or a decimal as its digits over a power of ten kept apart
/// (see [`ScaledRatio`]), so a claim of 5e-107 is read on words too.
type Claim = ScaledRatio;

/// The claim of a cell on words; `None` for anything else (units, NaN, empty: the general
/// row's).
fn claim(cell: &[u8]) -> Option<Claim> {
    ScaledRatio::parse(cell.trim_ascii())
}

/// A claimed value against the exact one: its check under `agreement`, exactly as
/// [`super::compare`] decides it (the relative error kept on words, not reduced).
// Inlined into the loop over the claims: six calls a row cost the engine row about 50
// instructions.
#[inline(always)]
fn check(k: usize, claim: Claim, x: &Ratio, agreement: &Agreement) -> Option<OutputCheck> {
    let rel_error = if x.n == U256::ZERO {
        // Only a zero claim agrees with a zero value; any other is infinitely far.
        (claim.numer == U256::ZERO).then_some(RelError::ZERO)
    } else {
        let claimed = claim.numer.checked_mul_wide(x.d)?;
        let value = x.n.checked_mul_wide(claim.denominator()?)?;
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

/// Checks the claim of each claimed output against its exact value under `agreement`, in
/// order, and writes its cells (`,,` for a claim not given in this row, or an output with no
/// value: the spin after, for a point projectile); `None` when a check leaves the words.
// Inlined into each row, where the number of outputs is a constant.
#[inline(always)]
fn write_checks(
    claimed: &[bool],
    claims: &[Option<Claim>],
    values: &[Option<Ratio>],
    agreement: &Agreement,
    out: &mut String,
) -> Option<Vec<OutputCheck>> {
    let mut checks = Vec::with_capacity(claimed.len());
    for k in (0..claimed.len()).filter(|&k| claimed[k]) {
        let (Some(claim), Some(value)) = (claims[k], &values[k]) else {
            out.push_str(",,");
            continue;
        };
        let c = check(k, claim, value, agreement)?;
        c.write_cells(out, false);
        checks.push(c);
    }
    Some(checks)
}

/// The engine row of `line` (without its line ending), or `None` when the general row must
/// take it. See the module documentation.
pub(super) fn claimed_row(
    plan: &WordPlan,
    agreement: &Agreement,
    number: usize,
    line: &str,
) -> Option<SolvedRow> {
    let mut cells: SceneCells = [b""; SCENE_CELLS];
    let mut claims = [None; WORD_CLAIMS];
    each_cell(plan, line, |role, cell| {
        match role {
            Role::Scene(slot) => cells[slot] = cell.trim_ascii(),
            Role::Rod => cells[ROD] = cell.trim_ascii(),
            // An empty claim is not checked (and a state without it not audited).
            Role::Claim(_) if cell.trim_ascii().is_empty() => {}
            Role::Claim(k) => *claims.get_mut(k)? = Some(claim(cell)?),
            Role::Passed => {}
            Role::Input(_) => return None, // an oblique plan's
        }
        Some(())
    })?;
    let wanted: &[bool; WORD_CLAIMS] = plan.claimed[..WORD_CLAIMS].try_into().ok()?;
    let solved = last_scene::solved(&cells, wanted, || Solved::of(&cells, wanted));
    let solved = solved.as_ref().as_ref()?;
    let exact = &solved.exact;
    let mut out = String::with_capacity(line.len() + 400);
    out.push_str(line);
    out.push_str(&solved.cells);
    out.push_str(",true");
    let checks = write_checks(wanted, &claims, &exact.values, agreement, &mut out)?;
    let diagnosis = if plan.audits {
        out.push(',');
        let diagnosis = match [claims[0], claims[1], claims[2]] {
            [Some(v), Some(big_v), Some(omega)] => {
                diagnose(solved, [v, big_v, omega], &checks, &mut out)?
            }
            _ => {
                out.push('-');
                Diagnosis::NotAudited
            }
        };
        out.push(',');
        diagnosis.push_text(&mut out);
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
            // A float's residue for a zero V: its square needs the audit's 1024 bits.
            "pivot-centre-1,rapier2d,0.36.1,f64,1/240,1,pivot-centre,1,1,1,1,3,uniform,1,0,1.740000000087535,5.0579153677743847e-107,3.779999999737395,1.2599999999124651,4.5,3.895199999821429",
        ] {
            let fast = claimed_row(plan, &Agreement::Exact, 1, line).expect(line);
            let mut slow = general.row(1, line).unwrap();
            slow.label = None;
            slow.expectation = None;
            assert_eq!(fast, slow, "{line}");
        }
        // A centre hit at 1 m/s (exact: v = 0, V = 1) claimed as the state before the impact:
        // the same energy and momentum, named as no contact; v infinitely off, V and J by 1.
        let still = "c,x,1,f64,1/60,1,c,1,1,1,0,1,uniform,1,,1,0,0,0,1/2,1/2";
        let row = claimed_row(plan, &Agreement::Exact, 1, still).unwrap();
        let want = ",0,1,0,1,1/2,1/2,true,false,inf,false,1.00,true,0,false,1.00,true,0,true,0,0,no-contact\n";
        assert!(row.line.ends_with(want), "{}", row.line);
    }

    /// A run of rows of one scene (solved once, [`Solved`]), another scene between, the first
    /// again, and the same scene under a plan that claims fewer outputs: every line the
    /// general row's. A residue for a zero of e-107 takes the audit's 1024 bits, one of e-291
    /// its 2560; one of e-600 (past any f64) is past them, and the general row takes that row.
    #[test]
    fn a_scene_solved_once_serves_its_run_of_rows() {
        let header = "id,m,M,l,a,v0,rod,e,pivot,v,V,omega,J,energy_before,energy_after";
        let fewer = "id,m,M,l,a,v0,rod,e,pivot,v,V,omega";
        let plans = [header, fewer].map(|h| Batch::new(h, Arithmetic::Exact).unwrap());
        let lines = [
            "a,1,1,1,1/2,3,uniform,1,,0.27,0.73,1.09,2.73,4.5,1.09",
            "a,1,1,1,1/2,3,uniform,1,,0.2727,0.7272,1.0909,2.7272,4.5,1.0909",
            "b,1,1,1,1,3,uniform,1,0,1.74,5.0579153677743847e-107,3.78,1.26,4.5,3.8952",
            "d,1,1,1,1,3,uniform,1/2,0,1.9399942320547274,3.058996766720086e-291,3.1800173038358173,1.0600057679452723,4.5,3.5672071523186757",
            "c,1,1,1,1,3,uniform,1/2,0,1.9399942320547274,3.058996766720086e-600,3.1800173038358173,1.0600057679452723,4.5,3.5672071523186757",
            "a,1,1,1,1/2,3,uniform,1,,0.3,0.7,1.1,2.7,4.5,1.1",
        ];
        for batch in &plans {
            let general = batch.clone().with_atol("0").unwrap();
            let plan = batch.word_plan.as_ref().unwrap();
            for line in lines {
                let line = if plan.claimed[3] {
                    line.to_string()
                } else {
                    line.split(',').take(12).collect::<Vec<_>>().join(",")
                };
                let mut slow = general.row(1, &line).unwrap();
                slow.label = None;
                slow.expectation = None;
                let fast = claimed_row(plan, &Agreement::Exact, 1, &line);
                if line.starts_with('c') {
                    assert!(fast.is_none(), "{line}");
                } else {
                    assert_eq!(fast.expect(&line), slow, "{line}");
                }
            }
        }
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
                claimed_row(plan, &Agreement::Exact, 1, line).is_none(),
                "{line}"
            );
        }
        let ulps = Agreement::Ulps(1, super::super::FloatFormat::F64);
        assert!(words.with_agreement(ulps).unwrap().word_plan.is_none());
    }
}
