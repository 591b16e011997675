//! An engine's row of an oblique header (columns among v0t, mu, radius, spin, rod-v, rod-vt,
//! rod-omega; claims of v, V, omega, vt, Vt, the disc's spin after and the tangential
//! impulse), its claims checked on machine words.
//!
//! The scene is read on words as the plain engine row reads its scene (a decimal is its
//! digits over a power of ten) and checked as the general row checks it ([`WordScene`]); the
//! normal problem is solved by the fraction-free formulas ([`raw_of`]) at the approach speed,
//! and completed along the rod by [`oblique::complete`] on unreduced fractions of 128-bit
//! integers, else 512-bit ones; its values are reduced and written on words. A scene the
//! words do not take (a part above 18 digits, a unit) is built and solved as the general row
//! does ([`AfterOnWords::of`]). Either way once a scene ([`last_scene`]): an engine's log of
//! oblique scenes runs each at every time step and iteration count it tries. Each row then
//! only reads its claims as written and compares each with the exact value by
//! cross-multiplication on words ([`write_checks`]), with no big integer and no GCD.
//!
//! A row it does not take (a unit or a non-finite claim, a scene the general row refuses, an
//! exact value past 256 bits) goes to the general row, and a row it takes gives the general
//! row's line byte for byte.

use super::super::fixed_width_row::each_cell;
use super::super::header::put_scene_cell;
use super::super::last_scene;
use super::super::plan::{CLAIMS, Role, SolvedRow, WordPlan};
use super::super::row::{oblique_claims, write_oblique_cells};
use super::{Claim, Ratio, claim, write_checks};
use super::{Part, Rod, positive, word};
use crate::batch::compare::Agreement;
use crate::field::Field;
use crate::field::int::{FixedInt, Unreduced, Wide, within, write_parts};
use crate::scene::Motion;
use crate::scene::{
    Disc, ObliqueParams, Params, RodMotion, SCENE_KEYS, SceneInput, Support, key_index,
};
use crate::solve::answer::AfterOnWords;
use crate::solve::fast::fraction_free::{Raw, raw_of};
use crate::solve::fast::oblique::{self, normal_params};
use std::cmp::Ordering;

/// A row's scene cells as written, trimmed, by their index in [`SCENE_KEYS`]; empty where the
/// header has no such column.
type SceneCells<'a> = [&'a [u8]; SCENE_KEYS.len()];

/// An oblique scene solved exactly, with what its rows write and compare.
struct Solved {
    /// The exact outputs' cells and `laws_held`, as the row writes them.
    cells: String,
    /// The exact value of each claim that has one (the spin after only for a disc), in
    /// [`CLAIMS`] order.
    values: [Option<Ratio>; CLAIMS.len()],
    laws_hold: bool,
}

/// An oblique row's scene on words: the paper's part read and checked as the plain engine row
/// reads and checks it ([`super::Scene::check`]), and the oblique part as
/// [`crate::scene::SceneBuilder::build`] checks it (mu >= 0; a disc's radius > 0, and no spin
/// without a disc; a pivoted rod's centre given no motion of its own; the projectile
/// approaching the struck point, checked as the scene is solved).
struct WordScene {
    paper: super::Scene,
    v0t: Part,
    mu: Part,
    /// The disc's radius and spin.
    disc: Option<(Part, Part)>,
    /// The rod's v, vt and omega before the impact.
    rod_before: [Part; 3],
}

impl WordScene {
    /// The scene of `cells`, when every cell is a plain number on words (or the rod's kind)
    /// and every constraint holds; `None` otherwise (the general row's reading then decides).
    fn check(cells: &SceneCells) -> Option<WordScene> {
        // The cell of a key, found at compile time.
        let part = |key: usize| -> Option<Option<Part>> {
            match cells[key] {
                b"" => Some(None),
                cell => Part::parse(cell).map(Some),
            }
        };
        let paper = super::Scene::check(
            [
                part(const { key_index("m") })?,
                part(const { key_index("M") })?,
                part(const { key_index("l") })?,
                part(const { key_index("a") })?,
                part(const { key_index("v0") })?,
                part(const { key_index("e") })?,
                part(const { key_index("pivot") })?,
            ],
            Rod::parse(cells[const { key_index("rod") }])?,
        )?;
        let zero = Part {
            negative: false,
            n: 0,
            d: 1,
        };
        let mu = part(const { key_index("mu") })?.unwrap_or(zero);
        let radius = part(const { key_index("radius") })?;
        let disc = match (radius, part(const { key_index("spin") })?) {
            (Some(radius), spin) if positive(radius) => Some((radius, spin.unwrap_or(zero))),
            (None, None) => None,
            _ => return None,
        };
        let rod_before = [
            part(const { key_index("rod-v") })?,
            part(const { key_index("rod-vt") })?,
            part(const { key_index("rod-omega") })?,
        ]
        .map(|x| x.unwrap_or(zero));
        let moves_on_pivot = rod_before[0].n != 0 || rod_before[1].n != 0;
        if (mu.negative && mu.n != 0) || (paper.pivot.is_some() && moves_on_pivot) {
            return None;
        }
        Some(WordScene {
            paper,
            v0t: part(const { key_index("v0t") })?.unwrap_or(zero),
            mu,
            disc,
            rod_before,
        })
    }

    /// The scene of `cells` read and solved on words, in 128 bits, else 512; `None` when the
    /// general row's reading and solve must answer.
    fn answer(cells: &SceneCells) -> Option<AfterOnWords> {
        let s = WordScene::check(cells)?;
        s.answer_in::<i128>().or_else(|| s.answer_in::<Wide>())
    }

    /// The scene solved as the general row solves it: the normal problem by the fraction-free
    /// formulas at the approach speed, completed along the rod by [`oblique::complete`] on
    /// unreduced fractions of `T`; `None` when a value leaves `T`, the projectile does not
    /// approach, or a law fails (the general row then answers).
    fn answer_in<T: FixedInt>(&self) -> Option<AfterOnWords> {
        let s = &self.paper;
        let raw: Raw<T> = raw_of(&s.parts::<T>()?, s.e.n == s.e.d)?;
        if !raw.laws_hold {
            return None;
        }
        let lift = |x: Part| {
            let (n, d) = (word(x.n), word(x.d));
            Some(Unreduced::of_parts(
                T::of_words(x.negative, n)?,
                T::of_words(false, d)?,
            ))
        };
        let whole = |x: T| Unreduced::of_parts(x, T::small(1));
        let g = Unreduced::of_parts(T::of_words(false, s.g.0)?, T::of_words(false, s.g.1)?);
        let [m, rod_mass, l, a, v0, e] = [s.m, s.big_m, s.l, s.a, s.v0, s.e].map(lift);
        let (m, rod_mass, l, a, v0, e) = (m?, rod_mass?, l?, a?, v0?, e?);
        let support = match s.pivot {
            None => Support::Free,
            Some(p) => Support::Pivot(lift(p)?),
        };
        let [v, vt, omega] = self.rod_before.map(lift);
        let disc = match self.disc {
            None => None,
            Some((radius, spin)) => Some(Disc {
                radius: lift(radius)?,
                spin: lift(spin)?,
            }),
        };
        let o = ObliqueParams {
            v0t: lift(self.v0t)?,
            mu: lift(self.mu)?,
            disc,
            rod_before: RodMotion {
                v: v?,
                vt: vt?,
                omega: omega?,
            },
        };
        let done = within(|| {
            let params = Params {
                m,
                rod_mass,
                half_length: l,
                inertia: rod_mass * g,
                a,
                v0,
                e,
                support,
            };
            // The normal problem: the paper's scene at the approach speed u, solved as
            // v = u nv/den, V = u nV/den, omega = u nw/den.
            let approach = normal_params(&params, &o).v0;
            if approach.sign() != Some(Ordering::Greater) {
                return None;
            }
            let scale = approach / whole(raw.den);
            let response = Motion {
                v: whole(raw.nv) * scale,
                rod_v: whole(raw.n_big_v) * scale,
                omega: whole(raw.nw) * scale,
            };
            oblique::complete(&params, &o, response, None).ok()
        })??;
        AfterOnWords::reduced(done, raw.laws_hold, Unreduced::reduced_words)
    }
}

impl Solved {
    /// The scene of `cells`, read and solved on words ([`WordScene`]), else built as the
    /// general row builds it and solved by the same work ([`AfterOnWords`]); `None` when the
    /// general row must take its rows (a refused scene, a value past the words).
    fn of(cells: &SceneCells) -> Option<Solved> {
        let done = match WordScene::answer(cells) {
            Some(done) => done,
            None => {
                let mut input = SceneInput::default();
                for (key, cell) in SCENE_KEYS.iter().zip(cells) {
                    if key.column {
                        // The general row trims a cell of any white space, not ASCII's alone.
                        put_scene_cell(&mut input, key, std::str::from_utf8(cell).ok()?.trim());
                    }
                }
                AfterOnWords::of(&input.build().ok()?)?
            }
        };
        let mut written = String::with_capacity(160);
        write_oblique_cells(
            &mut written,
            (&done.after, &done.tangential_impulse, done.contact),
            |out, &(negative, n, d)| write_parts(out, negative, n, d),
        );
        written.push_str(if done.laws_hold { ",true" } else { ",false" });
        let values = oblique_claims(&done.after, &done.tangential_impulse)
            .map(|x| x.map(|(negative, n, d)| Ratio { negative, n, d }));
        Some(Solved {
            cells: written,
            values,
            laws_hold: done.laws_hold,
        })
    }
}

/// The row of `line` (without its line ending) under an oblique plan, or `None` when the
/// general row must take it. See the module documentation.
pub(in crate::batch) fn oblique_row(
    plan: &WordPlan,
    agreement: &Agreement,
    number: usize,
    line: &str,
) -> Option<SolvedRow> {
    let mut cells: SceneCells = [b""; SCENE_KEYS.len()];
    let mut claims: [Option<Claim>; CLAIMS.len()] = [None; CLAIMS.len()];
    each_cell(plan, line, |role, cell| {
        match role {
            Role::Input(k) => cells[k] = cell.trim_ascii(),
            // An empty claim is not checked.
            Role::Claim(_) if cell.trim_ascii().is_empty() => {}
            Role::Claim(k) => claims[k] = Some(claim(cell)?),
            Role::Passed => {}
            Role::Scene(_) | Role::Rod => return None,
        }
        Some(())
    })?;
    let solved = last_scene::solved(&cells, &plan.claimed, || Solved::of(&cells));
    let solved = solved.as_ref().as_ref()?;
    let mut out = String::with_capacity(line.len() + solved.cells.len() + 200);
    out.push_str(line);
    out.push_str(&solved.cells);
    let checks = write_checks(&plan.claimed, &claims, &solved.values, agreement, &mut out)?;
    out.push('\n');
    Some(SolvedRow::unlabelled(
        number,
        out,
        Some(solved.laws_hold),
        checks,
        None,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::{Arithmetic, Batch};

    /// Rows of the oblique engine fixtures (Rapier and pymunk: frictionless, sliding,
    /// sticking, a spinning disc, a moving rod), a run of one scene and a scene between: each
    /// taken on words with the general row's line (reached by an absolute tolerance of zero,
    /// which the word rows leave to it).
    #[test]
    fn an_oblique_engines_rows_are_taken_on_words_with_the_general_rows_lines() {
        let header = "id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega,v,V,omega,claimed_vt,claimed_Vt,claimed_spin,engine_J,engine_energy_before,engine_energy_after";
        let words = Batch::new(header, Arithmetic::Exact).unwrap();
        let general = words.clone().with_atol("0").unwrap();
        let plan = words.word_plan.as_ref().expect("an oblique header's plan");
        assert!(plan.oblique && !plan.paper && !plan.audits);
        let fixtures = [
            include_str!("../../../tests/data/engines/rapier2d-0.36.1-f64-oblique.csv"),
            include_str!("../../../tests/data/engines/pymunk-7.3.1-f64-oblique.csv"),
        ];
        let mut taken = 0;
        for line in fixtures.iter().flat_map(|f| f.lines().skip(1)) {
            let mut slow = general.row(1, line).unwrap();
            slow.label = None;
            slow.expectation = None;
            if let Some(fast) = oblique_row(plan, &Agreement::Exact, 1, line) {
                assert_eq!(fast, slow, "{line}");
                taken += 1;
            }
        }
        assert_eq!(taken, 189 + 57, "every fixture row is taken on words");
    }

    /// The scene cells of `line` under `plan`, as the row reads them.
    fn scene_cells<'a>(plan: &WordPlan, line: &'a str) -> SceneCells<'a> {
        let mut cells: SceneCells = [b""; SCENE_KEYS.len()];
        each_cell(plan, line, |role, cell| {
            if let Role::Input(k) = role {
                cells[k] = cell.trim_ascii();
            }
            Some(())
        })
        .expect("the header's cells");
        cells
    }

    /// Every scene of the oblique fixtures (frictionless, sliding, sticking, at the
    /// threshold, a spinning disc, a moving rod) is read and solved on words, with the values
    /// of the rationals' solve.
    #[test]
    fn the_fixtures_scenes_are_solved_on_words() {
        let fixtures = [
            include_str!("../../../tests/data/engines/rapier2d-0.36.1-f64-oblique.csv"),
            include_str!("../../../tests/data/engines/pymunk-7.3.1-f64-oblique.csv"),
        ];
        for fixture in fixtures {
            let mut lines = fixture.lines();
            let header = lines.next().unwrap();
            let batch = Batch::new(header, Arithmetic::Exact).unwrap();
            let plan = batch.word_plan.as_ref().unwrap();
            for line in lines {
                let cells = scene_cells(plan, line);
                let words = WordScene::answer(&cells).unwrap_or_else(|| panic!("{line}"));
                let mut input = SceneInput::default();
                for (key, cell) in SCENE_KEYS.iter().zip(&cells) {
                    if key.column {
                        put_scene_cell(&mut input, key, std::str::from_utf8(cell).unwrap());
                    }
                }
                let rationals = AfterOnWords::of(&input.build().unwrap()).unwrap();
                assert_eq!(words, rationals, "{line}");
            }
        }
    }

    /// The word scene refuses what the general row refuses (spin without a disc, a radius
    /// not above 0, negative friction, a pivoted rod's centre moving on its own, a projectile
    /// not approaching) and takes the limits it allows (friction -0, a pivoted rod turning,
    /// a projectile only just approaching); a scene beyond the words is built and solved as
    /// the general row does. The row gives the general row's line every time.
    #[test]
    fn the_word_scene_refuses_what_the_general_row_refuses() {
        let header = "m,M,l,a,v0,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega,v,vt";
        let b = Batch::new(header, Arithmetic::Exact).unwrap();
        let plan = b.word_plan.as_ref().unwrap();
        let general = b.clone().with_atol("0").unwrap();
        let cases = [
            ("1,1,1,1/2,3,,1,1/2,,2,,,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,1/2,0,2,,,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,1/2,-1/20,,,,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,-1/2,,,,,,0.6,0.8", false),
            ("1,1,1,1/2,3,-1,1,1/2,,,1,,,0.6,0.8", false),
            ("1,1,1,1/2,3,-1,1,1/2,,,,1/3,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,1/2,,,3,,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,1/2,,,2,,2,0.6,0.8", false),
            ("1,1,1,1/2,3,,1,-0,,,,,,0.6,0.8", true),
            ("1,1,1,1/2,3,-1,1,1/2,1/20,,0,0,1,0.6,0.8", true),
            ("1,1,1,1/2,3,,1,1/2,1/20,-7,2,1/3,1,0.6,0.8", true),
            ("1,1,1,1/2,3,,1,1/2,,,2999/1000,,,0.6,0.8", true),
            // Beyond the words, and taken by the general row's reading: a unit; 19 digits,
            // whose completion passes 512 bits unreduced (then solved over Q).
            ("1,1,1,1/2,3 m/s,,1,1/2,,,,,,0.6,0.8", false),
            ("1,1,1,1/2,3,,1.000000000000000001,1/2,,,,,,0.6,0.8", false),
        ];
        for (line, taken) in cases {
            let cells = scene_cells(plan, line);
            assert_eq!(WordScene::answer(&cells).is_some(), taken, "{line}");
            let slow = general.row(1, line);
            let row = oblique_row(plan, &Agreement::Exact, 1, line);
            assert_eq!(row.is_some(), slow.is_ok(), "{line}");
            match row {
                Some(fast) => {
                    let mut slow = slow.unwrap();
                    slow.label = None;
                    slow.expectation = None;
                    assert_eq!(fast, slow, "{line}");
                }
                None => assert!(!taken, "{line}"),
            }
        }
    }

    /// What the oblique row leaves to the general row: a unit in a claim, a non-finite claim,
    /// a scene the general row refuses (spin without a disc), a wrong number of cells. The
    /// claims a scene has no value for (the spin after, for a point projectile) are left
    /// empty, as the general row leaves them.
    #[test]
    fn rows_beyond_the_words_are_left_to_the_general_row() {
        let b = Batch::new("m,M,v0t,mu,radius,spin,v,vt,spin_after", Arithmetic::Exact).unwrap();
        let plan = b.word_plan.as_ref().unwrap();
        for line in [
            "1,1,1,1/2,,,0.6 m/s,0.8,",
            "1,1,1,1/2,,,NaN,0.8,",
            "1,1,1,1/2,,3,0.6,0.8,",
            "1,1,1,1/2,,,0.6,0.8",
            "1,-1,1,1/2,,,0.6,0.8,",
        ] {
            assert!(
                oblique_row(plan, &Agreement::Exact, 1, line).is_none(),
                "{line}"
            );
        }
        let point = "1,1,1,1/2,,,0.6,0.8,7";
        let row = oblique_row(plan, &Agreement::Exact, 1, point).unwrap();
        assert_eq!(
            row.line,
            "1,1,1,1/2,,,0.6,0.8,7,3/5,2/5,6/5,4/5,1/5,,1/5,slide,true,true,0,true,0,,\n"
        );
        let mut slow = b.with_atol("0").unwrap().row(1, point).unwrap();
        slow.label = None;
        assert_eq!(row, slow);
    }
}
