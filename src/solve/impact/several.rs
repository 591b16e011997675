//! Several frictionless contacts at once, under each named model, exactly.
//!
//! With `u = u0 + W lam` the normal relative velocities after normal impulses `lam` (W, the
//! Delassus matrix, symmetric and positive semidefinite; `u0^- = min(u0, 0)`):
//!
//! - **simultaneous-newton**: `lam >= 0`, `w = u0 + W lam + e u0^- >= 0`, `lam . w = 0` (an
//!   approaching contact that pushes leaves at `-e u0`; a touching one at 0 or more);
//! - **simultaneous-poisson** (Pfeiffer and Glocker): compression `lam_c >= 0`,
//!   `u_c = u0 + W lam_c >= 0`, `lam_c . u_c = 0`; expansion `lam_e = e lam_c + x`, `x >= 0`,
//!   `u = u_c + W lam_e >= 0`, `x . u = 0`; `lam = lam_c + lam_e`;
//! - **sequential** in an order: passes over the contacts in that order, each approaching
//!   contact (`u_i < 0`) taking the single-contact Newton impulse `-(1 + e_i) u_i / W_ii`, until a
//!   pass fires nothing; every order, or one given;
//! - **pgs:K**: K sweeps of projected Gauss-Seidel from zero impulses, in the contacts' order,
//!   `lam_i <- max(0, lam_i - (u_i + e_i u0_i^-)/W_ii)`, as engines run it.
//!
//! The linear complementarity problems are solved exactly: up to [`MAX_ENUMERATED`] contacts by
//! enumerating the active sets (every subset of the contacts; solutions with the same
//! velocities are one), beyond by Lemke's method with lexicographic pivoting (`lemke.rs`), up
//! to [`MAX_CONTACTS`](crate::model::MAX_CONTACTS) contacts. W is positive semidefinite, so the velocities after are
//! the same for every solution: a model has one answer or none (the impulses may be split
//! otherwise where W is singular).

use super::lemke::lemke;
use super::matrix::Response;
use crate::field::Field;
use crate::mechanics::planar::{
    PlanarBody, Vec2, angular_momentum, kinetic_energy, linear_momentum,
};
use crate::model::System;
use crate::solve::linear::solve_linear;
use std::cmp::Ordering;
use std::fmt;

/// The most contacts whose active sets the simultaneous models enumerate (2^n of them);
/// beyond, Lemke's method solves them.
pub const MAX_ENUMERATED: usize = 8;
/// The most impacts a sequential model runs before it is reported as not stopping.
pub const MAX_SEQUENTIAL_IMPACTS: usize = 1_000;
/// The most sweeps `pgs:K` runs.
pub const MAX_SWEEPS: u32 = 10_000;
/// The most contacts whose every order the sequential model runs (n! orders).
pub const MAX_ORDERED: usize = 6;

/// How several simultaneous contacts act together.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Model {
    /// The simultaneous Newton law (a linear complementarity problem).
    SimultaneousNewton,
    /// The simultaneous Poisson law (compression, then expansion).
    SimultaneousPoisson,
    /// Single-contact impacts one at a time, in this order of the contacts (0-based), in passes
    /// until one fires nothing.
    Sequential(Vec<usize>),
    /// K sweeps of projected Gauss-Seidel from zero impulses.
    Pgs(u32),
}

impl Model {
    /// One model by name, for `n` contacts: `simultaneous-newton`, `simultaneous-poisson`,
    /// `sequential:2,1,3` (an order of the contacts, 1-based) or `pgs:K`.
    ///
    /// # Errors
    /// What is wrong with the name, in words.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::solve::impact::Model;
    /// assert_eq!(Model::parse("sequential:2,1", 2), Ok(Model::Sequential(vec![1, 0])));
    /// assert_eq!(Model::parse("pgs:3", 2), Ok(Model::Pgs(3)));
    /// assert!(Model::parse("sequential:1,1", 2).is_err());
    /// ```
    pub fn parse(text: &str, n: usize) -> Result<Model, String> {
        let text = text.trim();
        match text {
            "simultaneous-newton" => return Ok(Model::SimultaneousNewton),
            "simultaneous-poisson" => return Ok(Model::SimultaneousPoisson),
            _ => {}
        }
        if let Some(order) = text.strip_prefix("sequential:") {
            let parsed: Option<Vec<usize>> = order
                .split(',')
                .map(|k| {
                    k.trim()
                        .parse::<usize>()
                        .ok()
                        .filter(|k| (1..=n).contains(k))
                        .map(|k| k - 1)
                })
                .collect();
            let order = parsed.ok_or_else(|| {
                format!(
                    "sequential:ORDER lists contacts 1 to {n}, got '{}'",
                    crate::echo::echo(order)
                )
            })?;
            let mut sorted = order.clone();
            sorted.sort_unstable();
            if sorted != (0..n).collect::<Vec<_>>() {
                return Err(format!(
                    "sequential:ORDER names each of the {n} contacts once"
                ));
            }
            return Ok(Model::Sequential(order));
        }
        if let Some(k) = text.strip_prefix("pgs:") {
            return k
                .trim()
                .parse::<u32>()
                .ok()
                .filter(|k| (1..=MAX_SWEEPS).contains(k))
                .map(Model::Pgs)
                .ok_or_else(|| format!("pgs:K takes K from 1 to {MAX_SWEEPS}"));
        }
        Err(format!(
            "expected simultaneous-newton, simultaneous-poisson, sequential:ORDER or pgs:K, got '{}'",
            crate::echo::echo(text)
        ))
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Model::SimultaneousNewton => f.write_str("simultaneous-newton"),
            Model::SimultaneousPoisson => f.write_str("simultaneous-poisson"),
            Model::Sequential(order) => {
                let order: Vec<String> = order.iter().map(|i| (i + 1).to_string()).collect();
                write!(f, "sequential:{}", order.join(","))
            }
            Model::Pgs(k) => write!(f, "pgs:{k}"),
        }
    }
}

/// What a model says of a system.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelOutcome<F> {
    /// The answers: one, or several (a simultaneous model with more than one solution).
    Answered(Vec<ModelAnswer<F>>),
    /// No impulses satisfy the model.
    NoSolution,
    /// A sequential model still firing after [`MAX_SEQUENTIAL_IMPACTS`] impacts.
    DoesNotStop,
    /// The model is frictionless here (sequential impacts, projected Gauss-Seidel), and the
    /// scene has friction.
    FrictionlessOnly,
}

/// Total momentum, angular momentum about the origin and kinetic energy of the moving bodies,
/// before and after, and the normal velocity after at every contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Ledger<F> {
    /// Linear momentum before.
    pub momentum_before: Vec2<F>,
    /// ... after.
    pub momentum_after: Vec2<F>,
    /// Angular momentum about the origin, counterclockwise, before.
    pub angular_before: F,
    /// ... after.
    pub angular_after: F,
    /// Kinetic energy before.
    pub energy_before: F,
    /// ... after.
    pub energy_after: F,
    /// after - before.
    pub energy_change: F,
    /// The model creates kinetic energy.
    pub energy_gain: bool,
    /// The normal relative velocity after at every contact (negative: the model lets the
    /// bodies sink into each other there).
    pub normal_after: Vec<F>,
}

impl<F: Field> Ledger<F> {
    /// The contacts (0-based) whose bodies sink into each other after the impact.
    pub fn sinking(&self) -> Vec<usize> {
        (0..self.normal_after.len())
            .filter(|&i| self.normal_after[i].sign() == Some(Ordering::Less))
            .collect()
    }
}

/// One answer of a model.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelAnswer<F> {
    /// The model.
    pub model: Model,
    /// The normal impulse coefficient at each contact (P_i = lam_i n_i + tau_i t_i on A).
    pub impulses: Vec<F>,
    /// The tangential impulse coefficient at each contact (zero without friction).
    pub tangential: Vec<F>,
    /// Friction at contacts that stick along one line leaves only the sum of their tangential
    /// impulses determined: these are one split of it (the velocities are the same for all).
    pub split_indeterminate: bool,
    /// Every moving body after: (index, velocity, spin).
    pub bodies: Vec<(usize, Vec2<F>, F)>,
    /// What the model conserves and what it does not.
    pub ledger: Ledger<F>,
    /// The single-contact impacts a sequential model fired, in order: (contact, impulse).
    pub impacts: Vec<(usize, F)>,
}

/// The system's contacts in a field: points, normals, e, and every moving body's response.
pub(super) struct Contacts<F> {
    pub(super) points: Vec<Vec2<F>>,
    pub(super) normals: Vec<Vec2<F>>,
    pub(super) e: Vec<F>,
    /// For each contact, its two bodies (index, sign +1 for A, -1 for B), moving ones only.
    ends: Vec<Vec<(usize, F)>>,
    responses: Vec<Option<Response<F>>>,
}

impl<F: Field> Contacts<F> {
    pub(super) fn of(system: &System) -> Contacts<F> {
        let lift =
            |v: &Vec2<crate::field::Q>| Vec2::new(F::from_rational(&v.x), F::from_rational(&v.y));
        let responses: Vec<Option<Response<F>>> = system.bodies.iter().map(Response::of).collect();
        Contacts {
            points: system.contacts.iter().map(|c| lift(&c.point)).collect(),
            normals: system.contacts.iter().map(|c| lift(&c.normal)).collect(),
            e: system
                .contacts
                .iter()
                .map(|c| F::from_rational(&c.e))
                .collect(),
            ends: system
                .contacts
                .iter()
                .map(|c| {
                    [(c.a, F::one()), (c.b, -F::one())]
                        .into_iter()
                        .filter(|(b, _)| responses[*b].is_some())
                        .collect()
                })
                .collect(),
            responses,
        }
    }

    pub(super) fn len(&self) -> usize {
        self.points.len()
    }

    /// The Delassus matrix: W_ij, the change of u_i per unit impulse lam_j.
    pub(super) fn delassus(&self) -> Vec<Vec<F>> {
        self.coupling(&self.normals, &self.normals)
    }

    /// The change of the relative velocity at contact i along `along[i]` per unit impulse along
    /// `by[j]` at contact j (the Delassus matrix when both are the normals).
    pub(super) fn coupling(&self, along: &[Vec2<F>], by: &[Vec2<F>]) -> Vec<Vec<F>> {
        let n = self.len();
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let mut w = F::zero();
                        for (bi, si) in &self.ends[i] {
                            for (bj, sj) in &self.ends[j] {
                                if bi != bj {
                                    continue;
                                }
                                let r = self.responses[*bi].as_ref().expect("moving");
                                let push = by[j].scale(sj);
                                let change =
                                    r.point_change_at(&self.points[i], &self.points[j], &push);
                                w = w + &(change.dot(&along[i]) * si);
                            }
                        }
                        w
                    })
                    .collect()
            })
            .collect()
    }
}

/// The bodies before the impact, as planar bodies in the field.
fn bodies_before<F: Field>(system: &System) -> Vec<(usize, PlanarBody<F>)> {
    let lift =
        |v: &Vec2<crate::field::Q>| Vec2::new(F::from_rational(&v.x), F::from_rational(&v.y));
    system
        .bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| b.moves())
        .map(|(i, b)| {
            (
                i,
                PlanarBody {
                    mass: F::from_rational(&b.mass),
                    inertia: F::from_rational(&b.inertia),
                    centre: lift(&b.position),
                    velocity: lift(&b.velocity),
                    omega: F::from_rational(&b.omega),
                },
            )
        })
        .collect()
}

/// The normal relative velocity before, at every contact.
pub(super) fn normal_before<F: Field>(system: &System, contacts: &Contacts<F>) -> Vec<F> {
    system
        .contacts
        .iter()
        .zip(&contacts.normals)
        .map(|(c, n)| {
            let rel = system.relative_velocity(c);
            Vec2::new(F::from_rational(&rel.x), F::from_rational(&rel.y)).dot(n)
        })
        .collect()
}

pub(super) fn negative_part<F: Field>(x: &F) -> F {
    if x.sign() == Some(Ordering::Less) {
        x.clone()
    } else {
        F::zero()
    }
}

pub(super) fn nonnegative<F: Field>(x: &F) -> bool {
    x.sign() != Some(Ordering::Less)
}

/// `u0 + W lam`.
fn velocities<F: Field>(u0: &[F], w: &[Vec<F>], lam: &[F]) -> Vec<F> {
    (0..u0.len())
        .map(|i| (0..lam.len()).fold(u0[i].clone(), |acc, j| acc + &(w[i][j].clone() * &lam[j])))
        .collect()
}

/// The solutions of the LCP `lam >= 0, q + W lam >= 0, lam . (q + W lam) = 0` that differ in
/// their velocities (for a positive semidefinite W, one or none): by active sets up to
/// [`MAX_ENUMERATED`] contacts, by Lemke's method beyond.
fn lcp<F: Field>(w: &[Vec<F>], q: &[F]) -> Vec<Vec<F>> {
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
    let answer = |impulses: Vec<F>, impacts: Vec<(usize, F)>| {
        let tangential = vec![F::zero(); impulses.len()];
        finish(
            system,
            contacts,
            w,
            u0,
            model.clone(),
            (impulses, tangential, false),
            impacts,
        )
    };
    match model {
        Model::SimultaneousNewton => {
            let q: Vec<F> = (0..n)
                .map(|i| u0[i].clone() + &(contacts.e[i].clone() * &negative_part(&u0[i])))
                .collect();
            let all = lcp(w, &q);
            if all.is_empty() {
                ModelOutcome::NoSolution
            } else {
                ModelOutcome::Answered(all.into_iter().map(|lam| answer(lam, Vec::new())).collect())
            }
        }
        Model::SimultaneousPoisson => {
            let mut answers = Vec::new();
            for compression in lcp(w, u0) {
                let u_c = velocities(u0, w, &compression);
                let pushed: Vec<F> = (0..n)
                    .map(|i| contacts.e[i].clone() * &compression[i])
                    .collect();
                let q = velocities(&u_c, w, &pushed);
                for extra in lcp(w, &q) {
                    let lam: Vec<F> = (0..n)
                        .map(|i| compression[i].clone() + &pushed[i] + &extra[i])
                        .collect();
                    answers.push(answer(lam, Vec::new()));
                }
            }
            if answers.is_empty() {
                ModelOutcome::NoSolution
            } else {
                ModelOutcome::Answered(answers)
            }
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
                    let impulse = -((F::one() + &contacts.e[i]) * &u[i]) / &w[i][i];
                    lam[i] = lam[i].clone() + &impulse;
                    impacts.push((i, impulse));
                    fired = true;
                    if impacts.len() >= MAX_SEQUENTIAL_IMPACTS {
                        return ModelOutcome::DoesNotStop;
                    }
                }
                if !fired {
                    return ModelOutcome::Answered(vec![answer(lam, impacts)]);
                }
            }
        }
        Model::Pgs(sweeps) => {
            let mut lam = vec![F::zero(); n];
            for _ in 0..*sweeps {
                for i in 0..n {
                    if w[i][i].is_zero() {
                        continue;
                    }
                    let u = velocities(u0, w, &lam);
                    let target = u[i].clone() + &(contacts.e[i].clone() * &negative_part(&u0[i]));
                    let next = lam[i].clone() - &(target / &w[i][i]);
                    lam[i] = if nonnegative(&next) { next } else { F::zero() };
                }
            }
            ModelOutcome::Answered(vec![answer(lam, Vec::new())])
        }
    }
}

/// The bodies after the impulses `lam` and the ledger.
pub(super) fn finish<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &[Vec<F>],
    u0: &[F],
    model: Model,
    (impulses, tangential, split_indeterminate): (Vec<F>, Vec<F>, bool),
    impacts: Vec<(usize, F)>,
) -> ModelAnswer<F> {
    let _ = (w, u0);
    let before = bodies_before::<F>(system);
    let after: Vec<(usize, PlanarBody<F>)> = before
        .iter()
        .map(|(index, body)| {
            let response = contacts.responses[*index].as_ref().expect("moving");
            let (mut dv, mut dw) = (Vec2::zero(), F::zero());
            for (k, ends) in contacts.ends.iter().enumerate() {
                for (b, sign) in ends {
                    if b != index {
                        continue;
                    }
                    let push = contacts.normals[k]
                        .scale(&impulses[k])
                        .add(&contacts.normals[k].perp().scale(&tangential[k]))
                        .scale(sign);
                    dv = dv.add(&response.centre_change(&body.centre, &contacts.points[k], &push));
                    dw = dw + &response.spin_change(&contacts.points[k], &push);
                }
            }
            (
                *index,
                PlanarBody {
                    velocity: body.velocity.add(&dv),
                    omega: body.omega.clone() + &dw,
                    ..body.clone()
                },
            )
        })
        .collect();
    let planar = |list: &[(usize, PlanarBody<F>)]| -> Vec<PlanarBody<F>> {
        list.iter().map(|(_, b)| b.clone()).collect()
    };
    let (b0, b1) = (planar(&before), planar(&after));
    let energy_before = kinetic_energy(&b0);
    let energy_after = kinetic_energy(&b1);
    let energy_change = energy_after.clone() - &energy_before;
    let origin = Vec2::zero();
    ModelAnswer {
        model,
        bodies: after
            .iter()
            .map(|(i, b)| (*i, b.velocity.clone(), b.omega.clone()))
            .collect(),
        ledger: Ledger {
            momentum_before: linear_momentum(&b0),
            momentum_after: linear_momentum(&b1),
            angular_before: angular_momentum(&b0, &origin),
            angular_after: angular_momentum(&b1, &origin),
            energy_gain: energy_change.sign() == Some(Ordering::Greater),
            energy_before,
            energy_after,
            energy_change,
            normal_after: (0..contacts.len())
                .map(|k| {
                    let velocity = |index: usize| -> Vec2<F> {
                        after
                            .iter()
                            .find(|(i, _)| *i == index)
                            .map_or_else(Vec2::zero, |(_, b)| b.point_velocity(&contacts.points[k]))
                    };
                    let c = &system.contacts[k];
                    velocity(c.a).sub(&velocity(c.b)).dot(&contacts.normals[k])
                })
                .collect(),
        },
        impulses,
        tangential,
        split_indeterminate,
        impacts,
    }
}

/// Every order of the contacts `0..n` (n! of them, n at most [`MAX_ORDERED`]), in
/// lexicographic order.
///
/// # Examples
/// ```
/// use rodimpact::solve::impact::orders;
/// assert_eq!(orders(3).len(), 6);
/// assert_eq!(orders(2), [vec![0, 1], vec![1, 0]]);
/// ```
pub fn orders(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![Vec::new()];
    }
    let mut out = Vec::new();
    for first in 0..n {
        for rest in orders(n - 1) {
            let mut order = vec![first];
            order.extend(rest.into_iter().map(|i| if i >= first { i + 1 } else { i }));
            out.push(order);
        }
    }
    out
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
