//! Several frictionless contacts under each model: the simultaneous laws as exact linear
//! complementarity problems (every active set up to [`MAX_ENUMERATED`] contacts, Lemke's
//! method beyond), sequential impacts in an order, and projected Gauss-Seidel.

use super::common::{Contacts, finish_staged, negative_part, nonnegative, velocities};
use super::lemke::lemke;
use super::{MAX_ENUMERATED, MAX_SEQUENTIAL_IMPACTS, Model, ModelAnswer, ModelOutcome};
use crate::field::Field;
use crate::field::linear::solve_linear;
use crate::impact::law::Law;
use crate::model::System;
use std::cmp::Ordering;

/// The solutions of the LCP `lam >= 0, q + W lam >= 0, lam . (q + W lam) = 0` that differ in
/// their velocities (for a positive semidefinite W, one or none): by active sets up to
/// [`MAX_ENUMERATED`] contacts, by Lemke's method beyond.
pub(super) fn lcp<F: Field>(w: &[Vec<F>], q: &[F]) -> Vec<Vec<F>> {
    if q.len() > MAX_ENUMERATED {
        return lemke(w, q).into_iter().collect();
    }
    every_active_set(w, q)
}

/// Every solution of the LCP by active sets; solutions that differ only where W leaves them
/// open are one (the first found).
fn every_active_set<F: Field>(w: &[Vec<F>], q: &[F]) -> Vec<Vec<F>> {
    let n = q.len();
    let mut found: Vec<Vec<F>> = Vec::new();
    for mask in 0u32..(1 << n) {
        let active: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
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
        // The same velocities as a solution already found (W singular): one answer.
        let same = found.iter().any(|other| {
            velocities(
                &vec![F::zero(); n],
                w,
                &(0..n)
                    .map(|i| other[i].clone() - &lam[i])
                    .collect::<Vec<_>>(),
            )
            .iter()
            .all(F::is_zero)
        });
        if !same {
            found.push(lam);
        }
    }
    found
}

/// The frictionless contacts of `system` under `model` ([`super::solve_several`] sends
/// frictional ones to `friction.rs`).
pub(super) fn frictionless<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &[Vec<F>],
    u0: &[F],
    model: &Model,
) -> ModelOutcome<F> {
    let n = contacts.len();
    let zero = || vec![F::zero(); n];
    let staged = |stages: Vec<Vec<F>>, impacts: Vec<(usize, F)>| {
        let total: Vec<F> = (0..n)
            .map(|i| stages.iter().fold(F::zero(), |acc, stage| acc + &stage[i]))
            .collect();
        finish_staged(
            system,
            contacts,
            model.clone(),
            (total, zero(), false),
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
    let newton = || -> Vec<Vec<F>> {
        let q: Vec<F> = (0..n)
            .map(|i| u0[i].clone() - &Law::newton_leaving(&contacts.e[i], &negative_part(&u0[i])))
            .collect();
        lcp(w, &q)
    };
    match model {
        Model::SimultaneousNewton => answered(
            newton()
                .into_iter()
                .map(|lam| staged(vec![lam], Vec::new()))
                .collect(),
        ),
        Model::SimultaneousPoisson => {
            let mut answers = Vec::new();
            for compression in lcp(w, u0) {
                let u_c = velocities(u0, w, &compression);
                let pushed: Vec<F> = (0..n)
                    .map(|i| Law::poisson_restitution(&contacts.e[i], &compression[i]))
                    .collect();
                let q = velocities(&u_c, w, &pushed);
                for extra in lcp(w, &q) {
                    let expansion: Vec<F> = (0..n).map(|i| pushed[i].clone() + &extra[i]).collect();
                    answers.push(staged(vec![compression.clone(), expansion], Vec::new()));
                }
            }
            answered(answers)
        }
        // Without friction the first stage is the compression, and the second's LCP in the total
        // impulse, u1 - W lam1 + e u0^- + W lam = u0 + e u0^- + W lam, the simultaneous Newton
        // law's: split is that law reached in two stages.
        Model::Split => {
            let mut answers = Vec::new();
            for first in lcp(w, u0) {
                for total in newton() {
                    let second: Vec<F> = (0..n).map(|i| total[i].clone() - &first[i]).collect();
                    answers.push(staged(vec![first.clone(), second], Vec::new()));
                }
            }
            answered(answers)
        }
        Model::Sequential(order) => {
            let mut lam = vec![F::zero(); n];
            let mut impacts = Vec::new();
            loop {
                let mut fired = false;
                for &i in order {
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
                        return ModelOutcome::DoesNotStop;
                    }
                }
                if !fired {
                    return ModelOutcome::Answered(vec![staged(vec![lam], impacts)]);
                }
            }
        }
        Model::Pgs(_) | Model::Engine(_) => unreachable!("the iterative models are solved apart"),
    }
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
            let by_sets = every_active_set(&w, &q0);
            let by_lemke = lemke(&w, &q0);
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
