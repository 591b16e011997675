//! Several contacts with Coulomb friction under the simultaneous models, the oracle's
//! formulation (`tests/oracles/several-contacts.md`, section 6): in each phase, every contact
//! open or closed, sticking or sliding, every combination tried; Coulomb's cone bounds each
//! phase's tangential impulse by mu times that phase's normal impulse, the friction opposing the
//! slip at the phase's end. Each phase tries 6^n modes, so a system with friction holds at most
//! [`MAX_FRICTIONAL_CONTACTS`](crate::model::MAX_FRICTIONAL_CONTACTS) contacts.

use super::common::{Contacts, finish, finish_staged, negative_part, nonnegative};
use super::frictionless::lcp;
use super::{Model, ModelAnswer, ModelOutcome};
use crate::field::Field;
use crate::impact::coulomb::cone_excess;
use crate::impact::law::Law;
use crate::impact::work::{Meter, Stopped, Work};
use crate::model::System;

/// What friction does at a contact during a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Grip {
    Stick,
    /// Sliding with the slip at the phase's end positive (friction -mu lam).
    Forward,
    /// Sliding with the slip negative (friction +mu lam).
    Backward,
}

/// The couplings of normal and tangential impulses: (nn, nt, tn, tt).
type Blocks<F> = [Vec<Vec<F>>; 4];

/// One solution of a phase: the normal impulses, the tangential ones, and whether only their
/// combined effect is determined (the split among the contacts is open).
type PhaseSolution<F> = (Vec<F>, Vec<F>, bool);

/// One phase with Coulomb friction (the oracle's formulation, `tests/oracles/several-contacts.md`
/// section 6): from the velocities `(un, ut)`, the normal impulses `ln >= base` with
/// `un' + off >= 0` complementary to `ln - base`, and `|lt| <= mu ln` with
/// `lt = -mu ln sign(ut')` where the slip at the phase's end is not zero. Every normal and
/// tangential mode of every contact is tried: each solution (ln, lt, split indeterminate).
fn friction_phase<F: Field>(
    blocks: &Blocks<F>,
    (un, ut): (&[F], &[F]),
    mu: &[F],
    (base, off): (&[F], &[F]),
) -> Result<Vec<PhaseSolution<F>>, Stopped> {
    let n = un.len();
    let [nn, nt, tn, tt] = blocks;
    let grips = [Grip::Stick, Grip::Forward, Grip::Backward];
    let mut found: Vec<PhaseSolution<F>> = Vec::new();
    let mut meter = Meter::new(Work::Modes);
    for code in 0..6usize.pow(n as u32) {
        // Elimination on 2n rows of 2n unknowns, then the velocities at the phase's end.
        meter.charge(8 * n * n * n + 4 * n * n, un.iter().chain(ut).chain(base))?;
        let modes: Vec<(bool, Grip)> = (0..n)
            .map(|i| {
                let digit = code / 6usize.pow(i as u32) % 6;
                (digit >= 3, grips[digit % 3])
            })
            .collect();
        // Rows over the unknowns [ln_1..ln_n, lt_1..lt_n], right-hand sides.
        let mut a = Vec::with_capacity(2 * n);
        let mut b = Vec::with_capacity(2 * n);
        for (i, (closed, grip)) in modes.iter().enumerate() {
            let mut row = vec![F::zero(); 2 * n];
            if *closed {
                row[..n].clone_from_slice(&nn[i]);
                row[n..].clone_from_slice(&nt[i]);
                b.push(-(un[i].clone() + &off[i]));
            } else {
                row[i] = F::one();
                b.push(base[i].clone());
            }
            a.push(row);
            let mut row = vec![F::zero(); 2 * n];
            match grip {
                Grip::Stick => {
                    row[..n].clone_from_slice(&tn[i]);
                    row[n..].clone_from_slice(&tt[i]);
                    b.push(-ut[i].clone());
                }
                Grip::Forward | Grip::Backward => {
                    row[n + i] = F::one();
                    row[i] = if *grip == Grip::Forward {
                        mu[i].clone()
                    } else {
                        -mu[i].clone()
                    };
                    b.push(F::zero());
                }
            }
            a.push(row);
        }
        let Some((x, free)) = solve_consistent(a, b) else {
            continue;
        };
        let (ln, lt) = (x[..n].to_vec(), x[n..].to_vec());
        let end = |block_n: &[Vec<F>], block_t: &[Vec<F>], start: &[F]| -> Vec<F> {
            (0..n)
                .map(|i| {
                    (0..n).fold(start[i].clone(), |acc, j| {
                        acc + &(block_n[i][j].clone() * &ln[j]) + &(block_t[i][j].clone() * &lt[j])
                    })
                })
                .collect()
        };
        let (un_end, ut_end) = (end(nn, nt, un), end(tn, tt, ut));
        let holds = modes.iter().enumerate().all(|(i, (closed, grip))| {
            let normal = if *closed {
                nonnegative(&(ln[i].clone() - &base[i]))
            } else {
                nonnegative(&(un_end[i].clone() + &off[i]))
            };
            let tangential = match grip {
                Grip::Stick => cone_excess(&mu[i], &ln[i], &lt[i]).is_zero(),
                Grip::Forward => nonnegative(&ut_end[i]),
                Grip::Backward => nonnegative(&-ut_end[i].clone()),
            };
            normal && tangential && nonnegative(&ln[i])
        });
        let same = |other: &(Vec<F>, Vec<F>, bool)| {
            (0..n).all(|i| (other.0[i].clone() - &ln[i]).is_zero())
                && (free || other.2 || (0..n).all(|i| (other.1[i].clone() - &lt[i]).is_zero()))
        };
        if holds && !found.iter().any(same) {
            found.push((ln, lt, free));
        }
    }
    Ok(found)
}

/// A solution of `a x = b` when the system is consistent: the unique one, or one with the free
/// unknowns at zero (`true`: the system was singular).
fn solve_consistent<F: Field>(mut a: Vec<Vec<F>>, mut b: Vec<F>) -> Option<(Vec<F>, bool)> {
    let (rows, cols) = (a.len(), a.first().map_or(0, Vec::len));
    let mut pivots = Vec::new();
    let mut row = 0;
    for col in 0..cols {
        let Some(p) = (row..rows).find(|&r| !a[r][col].is_zero()) else {
            continue;
        };
        a.swap(row, p);
        b.swap(row, p);
        let inv = F::one() / &a[row][col];
        for x in a[row].iter_mut() {
            *x = x.clone() * &inv;
        }
        b[row] = b[row].clone() * &inv;
        let pivot_row = a[row].clone();
        for r in 0..rows {
            if r != row && !a[r][col].is_zero() {
                let factor = a[r][col].clone();
                for (x, p) in a[r].iter_mut().zip(&pivot_row) {
                    *x = x.clone() - &(p.clone() * &factor);
                }
                b[r] = b[r].clone() - &(b[row].clone() * &factor);
            }
        }
        pivots.push(col);
        row += 1;
    }
    if (row..rows).any(|r| !b[r].is_zero()) {
        return None;
    }
    let mut x = vec![F::zero(); cols];
    for (r, &col) in pivots.iter().enumerate() {
        x[col] = b[r].clone();
    }
    Some((x, pivots.len() < cols))
}

/// The simultaneous models with Coulomb friction at the contacts.
pub(super) fn with_friction<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &[Vec<F>],
    u0: &[F],
    model: &Model,
) -> Result<ModelOutcome<F>, Stopped> {
    let n = contacts.len();
    let blocks: Blocks<F> = [
        w.to_vec(),
        contacts.coupling(0, 1),
        contacts.coupling(1, 0),
        contacts.coupling(1, 1),
    ];
    let mu = &contacts.mu;
    let ut0 = contacts.before(1);
    let zero = vec![F::zero(); n];
    let finish_one = |(ln, lt, free): (Vec<F>, Vec<F>, bool)| {
        finish(system, contacts, model.clone(), (ln, lt, free), Vec::new())
    };
    let finish_staged_one = |(ln, lt, free): (Vec<F>, Vec<F>, bool), stages| {
        finish_staged(
            system,
            contacts,
            model.clone(),
            (ln, lt, free),
            Vec::new(),
            stages,
        )
    };
    // The velocities `start + W (ln, lt)` along the normals (`bn`, `bt`: blocks 0 and 1) or
    // the tangents (blocks 2 and 3).
    let after = |start: &[F], (bn, bt): (&[Vec<F>], &[Vec<F>]), ln: &[F], lt: &[F]| -> Vec<F> {
        (0..n)
            .map(|i| {
                (0..n).fold(start[i].clone(), |acc, j| {
                    acc + &(bn[i][j].clone() * &ln[j]) + &(bt[i][j].clone() * &lt[j])
                })
            })
            .collect()
    };
    let answers: Vec<ModelAnswer<F>> = match model {
        Model::SimultaneousNewton => {
            let off: Vec<F> = (0..n)
                .map(|i| -Law::newton_leaving(&contacts.e[i], &negative_part(&u0[i])))
                .collect();
            friction_phase(&blocks, (u0, &ut0), mu, (&zero, &off))?
                .into_iter()
                .map(finish_one)
                .collect()
        }
        Model::SimultaneousPoisson => {
            let mut all = Vec::new();
            for (lc, tc, free_c) in friction_phase(&blocks, (u0, &ut0), mu, (&zero, &zero))? {
                let un_c = after(u0, (&blocks[0], &blocks[1]), &lc, &tc);
                let ut_c = after(&ut0, (&blocks[2], &blocks[3]), &lc, &tc);
                let base: Vec<F> = (0..n)
                    .map(|i| Law::poisson_restitution(&contacts.e[i], &lc[i]))
                    .collect();
                for (le, te, free_e) in friction_phase(&blocks, (&un_c, &ut_c), mu, (&base, &zero))?
                {
                    let ln = (0..n).map(|i| lc[i].clone() + &le[i]).collect();
                    let lt = (0..n).map(|i| tc[i].clone() + &te[i]).collect();
                    let stages = vec![(lc.clone(), tc.clone()), (le, te)];
                    all.push(finish_staged_one((ln, lt, free_c || free_e), stages));
                }
            }
            all
        }
        // Friction without restitution (the first stage: lcp-newton with e = 0, the Poisson
        // law's compression), then the normals alone to -e u0^-: an LCP in the total normal
        // impulse, u1 - W lam1 + e u0^- + W lam >= 0 (`lcp`), the tangential impulses kept.
        Model::Split => {
            let mut all = Vec::new();
            for (l1, t1, free) in friction_phase(&blocks, (u0, &ut0), mu, (&zero, &zero))? {
                let u1 = after(u0, (&blocks[0], &blocks[1]), &l1, &t1);
                let q: Vec<F> = (0..n)
                    .map(|i| {
                        let pushed = (0..n).fold(F::zero(), |acc, j| {
                            acc + &(blocks[0][i][j].clone() * &l1[j])
                        });
                        u1[i].clone()
                            - &pushed
                            - &Law::newton_leaving(&contacts.e[i], &negative_part(&u0[i]))
                    })
                    .collect();
                for total in lcp(w, &q)? {
                    let second: Vec<F> = (0..n).map(|i| total.lam[i].clone() - &l1[i]).collect();
                    let stages = vec![(l1.clone(), t1.clone()), (second, zero.clone())];
                    let free = free || !total.determined;
                    all.push(finish_staged_one((total.lam, t1.clone(), free), stages));
                }
            }
            all
        }
        Model::Sequential(_) => return Ok(ModelOutcome::FrictionlessOnly),
        Model::Pgs(_) | Model::Engine(_) => unreachable!("the iterative models are solved apart"),
    };
    // Answers that differ only in how an indeterminate friction split is shared are one.
    let mut distinct: Vec<ModelAnswer<F>> = Vec::new();
    for a in answers {
        let same_motion = |b: &ModelAnswer<F>| {
            a.bodies.iter().zip(&b.bodies).all(|(x, y)| {
                (x.1.x.clone() - &y.1.x).is_zero()
                    && (x.1.y.clone() - &y.1.y).is_zero()
                    && (x.2.clone() - &y.2).is_zero()
            })
        };
        match distinct.iter_mut().find(|b| same_motion(b)) {
            // The same motion from other tangential impulses: only their sum is determined.
            Some(b) => {
                if (0..n).any(|i| !(b.tangential[i].clone() - &a.tangential[i]).is_zero()) {
                    b.split_indeterminate = true;
                }
            }
            None => distinct.push(a),
        }
    }
    Ok(if distinct.is_empty() {
        ModelOutcome::NoSolution
    } else {
        ModelOutcome::Answered(distinct)
    })
}
