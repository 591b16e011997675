//! Several frictionless contacts under each model: the simultaneous laws as exact linear
//! complementarity problems (every active set up to [`MAX_ENUMERATED`] contacts, Lemke's
//! method beyond), sequential impacts in an order, and projected Gauss-Seidel.

use super::common::{Contacts, finish_staged, negative_part, nonnegative, velocities};
use super::lemke::lemke;
use super::{MAX_ENUMERATED, MAX_SEQUENTIAL_IMPACTS, Model, ModelAnswer, ModelOutcome};
use crate::field::Field;
use crate::field::linear::solve_linear;
use crate::impact::law::Law;
use crate::impact::work::{Meter, Stopped, Work};
use crate::model::System;
use std::cmp::Ordering;

/// A solution of an LCP: its impulses, and whether they are the only ones that give its
/// velocities (where W is singular other impulses may give the same velocities: the split
/// among the contacts is then not determined).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Solution<F> {
    /// The impulses.
    pub lam: Vec<F>,
    /// Whether no other impulses give the same velocities.
    pub determined: bool,
}

/// The solutions of the LCP `lam >= 0, q + W lam >= 0, lam . (q + W lam) = 0`, one for each
/// distinct velocity outcome (for a positive semidefinite W, one or none): by active sets up to
/// [`MAX_ENUMERATED`] contacts, by Lemke's method beyond.
///
/// # Errors
/// [`Stopped`] when the work passes its limit or the host interrupts.
pub(super) fn lcp<F: Field>(w: &[Vec<F>], q: &[F]) -> Result<Vec<Solution<F>>, Stopped> {
    let basic = basic_solutions(w, q)?;
    let n = q.len();
    let same_velocities = |a: &[F], b: &[F]| {
        let difference: Vec<F> = (0..n).map(|i| a[i].clone() - &b[i]).collect();
        velocities(&vec![F::zero(); n], w, &difference)
            .iter()
            .all(F::is_zero)
    };
    let mut found: Vec<Solution<F>> = Vec::new();
    for lam in basic.vertices {
        match found.iter_mut().find(|s| same_velocities(&s.lam, &lam)) {
            Some(solution) => solution.determined = false,
            None => found.push(Solution {
                determined: basic.complete || active_block_regular(w, &lam),
                lam,
            }),
        }
    }
    Ok(found)
}

/// The basic solutions of an LCP (the vertices of its solution set): every one, by active
/// sets, up to [`MAX_ENUMERATED`] contacts (`complete`); Lemke's one beyond.
pub(super) struct Basic<F> {
    /// The distinct basic solutions found.
    pub vertices: Vec<Vec<F>>,
    /// Whether these are all of them.
    pub complete: bool,
}

/// The basic solutions of the LCP `lam >= 0, q + W lam >= 0, complementary`.
///
/// # Errors
/// [`Stopped`] when the work passes its limit or the host interrupts.
pub(super) fn basic_solutions<F: Field>(w: &[Vec<F>], q: &[F]) -> Result<Basic<F>, Stopped> {
    if q.len() > MAX_ENUMERATED {
        return Ok(Basic {
            vertices: lemke(w, q)?.into_iter().collect(),
            complete: false,
        });
    }
    Ok(Basic {
        vertices: every_active_set(w, q)?,
        complete: true,
    })
}

/// Whether W restricted to the contacts that push in `lam` is regular: then no other impulses
/// on those contacts give the same velocities (Lemke's solution, where the others are not
/// enumerated).
fn active_block_regular<F: Field>(w: &[Vec<F>], lam: &[F]) -> bool {
    let active: Vec<usize> = (0..lam.len()).filter(|&i| !lam[i].is_zero()).collect();
    let a: Vec<Vec<F>> = active
        .iter()
        .map(|&i| active.iter().map(|&j| w[i][j].clone()).collect())
        .collect();
    active.is_empty() || solve_linear(a, vec![F::zero(); active.len()]).is_some()
}

/// Every basic solution of the LCP, by active sets: each set whose block of W is regular
/// gives at most one; the distinct ones, in the order found.
fn every_active_set<F: Field>(w: &[Vec<F>], q: &[F]) -> Result<Vec<Vec<F>>, Stopped> {
    let n = q.len();
    let mut meter = Meter::new(Work::Modes);
    let mut found: Vec<Vec<F>> = Vec::new();
    for mask in 0u32..(1 << n) {
        let active: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
        // Elimination on the block, then the velocities at every contact.
        meter.charge(active.len().pow(3) + n * n, w.iter().flatten().chain(q))?;
        let a: Vec<Vec<F>> = active
            .iter()
            .map(|&i| active.iter().map(|&j| w[i][j].clone()).collect())
            .collect();
        let b: Vec<F> = active.iter().map(|&i| -q[i].clone()).collect();
        let Some(x) = solve_linear(a, b) else {
            continue;
        };
        let mut lam = vec![F::zero(); n];
        for (k, &i) in active.iter().enumerate() {
            lam[i] = x[k].clone();
        }
        if !lam.iter().all(nonnegative) {
            continue;
        }
        let w_lam = velocities(q, w, &lam);
        if !w_lam.iter().all(nonnegative) {
            continue;
        }
        if !found.contains(&lam) {
            found.push(lam);
        }
    }
    Ok(found)
}

/// The frictionless contacts of `system` under `model` ([`super::solve_several`] sends
/// frictional ones to `friction.rs`).
pub(super) fn frictionless<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &[Vec<F>],
    u0: &[F],
    model: &Model,
    share: u64,
) -> Result<ModelOutcome<F>, Stopped> {
    let n = contacts.len();
    let zero = || vec![F::zero(); n];
    let staged = |stages: Vec<Vec<F>>, impacts: Vec<(usize, F)>, determined: bool| {
        let total: Vec<F> = (0..n)
            .map(|i| stages.iter().fold(F::zero(), |acc, stage| acc + &stage[i]))
            .collect();
        finish_staged(
            system,
            contacts,
            model.clone(),
            (total, zero(), !determined),
            impacts,
            stages.into_iter().map(|stage| (stage, zero())).collect(),
        )
    };
    let answered = |answers: Vec<ModelAnswer<F>>| {
        if answers.is_empty() {
            ModelOutcome::NoSolution
        } else {
            ModelOutcome::Answered(answers)
        }
    };
    // The simultaneous Newton law's LCP: u0 + W lam >= -e u0^-, complementary.
    let newton = || -> Result<Vec<Solution<F>>, Stopped> {
        let q: Vec<F> = (0..n)
            .map(|i| u0[i].clone() - &Law::newton_leaving(&contacts.e[i], &negative_part(&u0[i])))
            .collect();
        lcp(w, &q)
    };
    Ok(match model {
        Model::SimultaneousNewton => answered(
            newton()?
                .into_iter()
                .map(|s| staged(vec![s.lam], Vec::new(), s.determined))
                .collect(),
        ),
        Model::SimultaneousPoisson => answered(poisson(w, u0, &contacts.e, &staged)?),
        // Without friction the first stage is the compression, and the second's LCP in the total
        // impulse, u1 - W lam1 + e u0^- + W lam = u0 + e u0^- + W lam, the simultaneous Newton
        // law's: split is that law reached in two stages.
        Model::Split => {
            let mut answers = Vec::new();
            for first in lcp(w, u0)? {
                for total in newton()? {
                    let second: Vec<F> = (0..n)
                        .map(|i| total.lam[i].clone() - &first.lam[i])
                        .collect();
                    let determined = first.determined && total.determined;
                    answers.push(staged(
                        vec![first.lam.clone(), second],
                        Vec::new(),
                        determined,
                    ));
                }
            }
            answered(answers)
        }
        Model::Sequential(order) => {
            let mut meter = Meter::shared(Work::Impacts, share);
            let mut lam = vec![F::zero(); n];
            let mut impacts = Vec::new();
            loop {
                let mut fired = false;
                for &i in order {
                    // The velocities at every contact, for the next one in the order.
                    meter.charge(n * n, lam.iter().chain(u0))?;
                    let u = velocities(u0, w, &lam);
                    if u[i].sign() != Some(Ordering::Less) || w[i][i].is_zero() {
                        continue;
                    }
                    // Newton's single-contact impulse: u_i leaves at -e u_i.
                    let impulse = (Law::newton_leaving(&contacts.e[i], &u[i]) - &u[i]) / &w[i][i];
                    lam[i] = lam[i].clone() + &impulse;
                    impacts.push((i, impulse));
                    fired = true;
                    if impacts.len() >= MAX_SEQUENTIAL_IMPACTS {
                        return Ok(ModelOutcome::DoesNotStop);
                    }
                }
                if !fired {
                    return Ok(ModelOutcome::Answered(vec![staged(
                        vec![lam],
                        impacts,
                        true,
                    )]));
                }
            }
        }
        Model::Pgs(_) | Model::Engine(_) => unreachable!("the iterative models are solved apart"),
    })
}

/// Simultaneous Poisson without friction: every compression that stops the approach (each basic
/// solution of its LCP: where W is singular the compression's split among the contacts is
/// open, and with unequal e each split pushes differently in the expansion), then `e` times
/// it plus what keeps every contact from sinking. The distinct answers, by their velocities:
/// with several, the answers are the end points of a set of answers.
fn poisson<F: Field>(
    w: &[Vec<F>],
    u0: &[F],
    e: &[F],
    staged: &impl Fn(Vec<Vec<F>>, Vec<(usize, F)>, bool) -> ModelAnswer<F>,
) -> Result<Vec<ModelAnswer<F>>, Stopped> {
    let n = u0.len();
    let compressions = basic_solutions(w, u0)?;
    let mut answers: Vec<ModelAnswer<F>> = Vec::new();
    for compression in compressions.vertices {
        let u_c = velocities(u0, w, &compression);
        let pushed: Vec<F> = (0..n)
            .map(|i| Law::poisson_restitution(&e[i], &compression[i]))
            .collect();
        let q = velocities(&u_c, w, &pushed);
        for extra in lcp(w, &q)? {
            let expansion: Vec<F> = (0..n).map(|i| pushed[i].clone() + &extra.lam[i]).collect();
            let answer = staged(
                vec![compression.clone(), expansion],
                Vec::new(),
                extra.determined,
            );
            match answers.iter_mut().find(|a| a.bodies == answer.bodies) {
                // The same velocities from another compression: the split is open.
                Some(same) => same.split_indeterminate = true,
                None => answers.push(answer),
            }
        }
    }
    if !compressions.complete {
        // Lemke's one compression: the others are not enumerated.
        for answer in &mut answers {
            answer.split_indeterminate |= !active_block_regular(w, &answer.stages[0].0);
        }
    }
    Ok(answers)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, q};
    use proptest::prelude::*;

    /// `W = J J^T` (positive semidefinite, singular when J has fewer columns than rows, as
    /// for several contacts on few bodies) and `q`, from small integers.
    fn problem() -> impl Strategy<Value = (Vec<Vec<Q>>, Vec<Q>)> {
        (1usize..=6, 1usize..=6).prop_flat_map(|(n, k)| {
            (
                proptest::collection::vec(proptest::collection::vec(-3i64..=3, k), n),
                proptest::collection::vec(-4i64..=4, n),
            )
                .prop_map(move |(j, q_int)| {
                    let w = (0..n)
                        .map(|a| {
                            (0..n)
                                .map(|b| q((0..k).map(|c| j[a][c] * j[b][c]).sum(), 1))
                                .collect()
                        })
                        .collect();
                    (w, q_int.into_iter().map(|x| q(x, 1)).collect())
                })
        })
    }

    proptest! {
        /// Lemke's method and the enumeration of active sets agree: both find no solution, or
        /// both find velocities `q + W z`, the same, and Lemke's z is complementary.
        #[test]
        fn lemke_agrees_with_every_active_set((w, q0) in problem()) {
            let by_sets = every_active_set(&w, &q0).unwrap();
            let by_lemke = lemke(&w, &q0).unwrap();
            prop_assert_eq!(by_sets.is_empty(), by_lemke.is_none());
            if let (Some(z), Some(other)) = (by_lemke, by_sets.first()) {
                let after = velocities(&q0, &w, &z);
                prop_assert_eq!(&after, &velocities(&q0, &w, other));
                for (zi, ui) in z.iter().zip(&after) {
                    prop_assert!(nonnegative(zi) && nonnegative(ui));
                    prop_assert_eq!(zi.clone() * ui, q(0, 1));
                }
            }
        }
    }
}
