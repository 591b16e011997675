//! The exact row on machine words: the paper's scene (a free uniform rod) read straight from
//! the line's bytes into 64-bit numerators and denominators and solved by the word route
//! ([`crate::solve::fast::fixed_width`]); its three outputs printed from words. No scene strings, no
//! `BigRational` scene, no big integer.
//!
//! It is a shortcut, never a second opinion: a row it does not take (a decimal, a unit, a part
//! above 18 digits, a bad cell, a claim not written as the exact value prints, inputs whose
//! values could leave the ring) goes to the general row, and a row it takes gives the general
//! row's line byte for byte (the outputs are reduced fractions, and a claim is taken only when
//! its cell is exactly the value's canonical text). The batch word tests hold it to that.

use super::plan::{Diagnosis, OutputCheck, Role, STATE, SolvedRow, WordPlan};
use super::rel_error::RelError;
use crate::field::int::U256;
use crate::solve::fast::fixed_width::{Inputs, Part, solve_reduced};

/// Walks the cells of `line` with their roles, giving each to `take`; `None` when the line
/// has too few or too many cells or `take` refuses one.
pub(super) fn each_cell<'a>(
    plan: &WordPlan,
    line: &'a str,
    mut take: impl FnMut(Role, &'a [u8]) -> Option<()>,
) -> Option<()> {
    let bytes = line.as_bytes();
    let (last, mut start) = (plan.roles.len() - 1, 0);
    for (k, role) in plan.roles.iter().enumerate() {
        // The memchr crate's search: a claimed fraction's cell runs to 70 bytes and more,
        // which a byte loop took four instructions each over (1,200 of a row with claims).
        let end = match memchr::memchr(b',', &bytes[start..]) {
            Some(offset) if k < last => start + offset,
            None if k == last => bytes.len(),
            _ => return None, // too few or too many cells
        };
        take(*role, &bytes[start..end])?;
        start = end + 1;
    }
    Some(())
}

/// The inputs of `line` on words, checked, and its claim cells (v, V, omega; empty where not
/// claimed); `None` when the general row must read it (or the plan is not the paper's).
pub(super) fn read_cells<'a>(
    plan: &WordPlan,
    line: &'a str,
) -> Option<(Inputs, [&'a [u8]; STATE])> {
    if !plan.paper {
        return None;
    }
    let mut parts = [None; 6];
    let mut claims: [&[u8]; STATE] = [&[]; STATE];
    each_cell(plan, line, |role, cell| {
        match role {
            Role::Scene(slot) => *parts.get_mut(slot)? = Some(Part::parse(cell)?),
            Role::Claim(claim) => *claims.get_mut(claim)? = cell,
            Role::Rod | Role::Input(_) => return None,
            Role::Passed => {}
        }
        Some(())
    })?;
    Some((Inputs::check(parts)?, claims))
}

/// The word row of `line` (without its line ending), or `None` when the general row must take
/// it. See the module documentation.
pub(super) fn fixed_width_row(plan: &WordPlan, number: usize, line: &str) -> Option<SolvedRow> {
    let (inputs, claims) = read_cells(plan, line)?;
    let outputs = solve_reduced(&inputs)?;
    // Room for the six numbers (at most 78 digits each) and the check cells: no regrowth.
    let mut out = String::with_capacity(line.len() + 560);
    out.push_str(line);
    let mut texts = [0..0, 0..0, 0..0];
    for (text, (negative, n, d)) in texts.iter_mut().zip(outputs) {
        out.push(',');
        let start = out.len();
        if negative {
            out.push('-');
        }
        n.write_decimal(&mut out);
        if d != U256::ONE {
            out.push('/');
            d.write_decimal(&mut out);
        }
        *text = start..out.len();
    }
    out.push_str(",true");
    let mut checks = Vec::with_capacity(STATE);
    for k in 0..STATE {
        if !plan.claimed[k] {
            continue;
        }
        // Taken only when the claim is the value's own text: equal, relative error 0.
        if claims[k].trim_ascii() != out[texts[k].clone()].as_bytes() {
            return None;
        }
        out.push_str(",true,0");
        checks.push(OutputCheck {
            output: k,
            ok: true,
            error: Some(RelError::ZERO),
            nearest: 0.0,
            ulps: None,
            not_finite: false,
        });
    }
    if plan.audits {
        out.push_str(",0,ok");
    }
    out.push('\n');
    let diagnosis = plan.audits.then(|| Diagnosis::Findings(Vec::new()));
    Some(SolvedRow::unlabelled(
        number,
        out,
        Some(true),
        checks,
        diagnosis,
    ))
}
