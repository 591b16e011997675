//! An engine's row of an oblique header (columns among v0t, mu, radius, spin, rod-v, rod-vt,
//! rod-omega; claims of v, V, omega, vt, Vt, the disc's spin after and the tangential
//! impulse), its claims checked on machine words.
//!
//! The scene is built as the general row builds it and solved by the general row's exact work
//! ([`AfterOnWords`]: the normal problem by the fraction-free route, completed on unreduced
//! fractions of 128-bit integers first), its values reduced and written on words, once a
//! scene ([`last_scene`]): an engine's log of oblique scenes runs each at every time step and
//! iteration count it tries. Each row then only reads its claims as written (a
//! decimal is its digits over a power of ten) and compares each with the exact value by
//! cross-multiplication on words ([`write_checks`]), with no big integer and no GCD.
//!
//! A row it does not take (a unit or a non-finite claim, a scene the general row refuses, an
//! exact value past 256 bits) goes to the general row, and a row it takes gives the general
//! row's line byte for byte.

use super::super::header::put_scene_cell;
use super::super::last_scene;
use super::super::plan::{CLAIMS, Role, SolvedRow, WordPlan};
use super::super::row::{oblique_claims, write_oblique_cells};
use super::super::word_row::each_cell;
use super::{Claim, Ratio, claim, write_checks};
use crate::batch::compare::Agreement;
use crate::field::int::write_parts;
use crate::scene::{SCENE_KEYS, SceneInput};
use crate::solve::answer::AfterOnWords;

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

impl Solved {
    /// The scene of `cells`, built as the general row builds it and solved by the same work
    /// on words ([`AfterOnWords`]); `None` when the general row must take its rows (a refused
    /// scene, a value past the words).
    fn of(cells: &SceneCells) -> Option<Solved> {
        let mut input = SceneInput::default();
        for (key, cell) in SCENE_KEYS.iter().zip(cells) {
            if key.column {
                // The general row trims a cell of any white space, not ASCII's alone.
                put_scene_cell(&mut input, key, std::str::from_utf8(cell).ok()?.trim());
            }
        }
        let scene = input.build().ok()?;
        let done = AfterOnWords::of(&scene)?;
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
