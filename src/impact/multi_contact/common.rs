//! What every several-contact model shares: the contacts in a field (their rows of the
//! Jacobian, W's blocks, e and mu), the velocities under given impulses, and the answer
//! completed from the impulses (the bodies after and the ledger).

use super::{Ledger, Model, ModelAnswer};
use crate::field::Field;
use crate::impact::jacobian::{coordinate_changes, delassus, velocities_before};
use crate::impact::ledger::EnergyLedger;
use crate::impact::planar::PlanarSystem;
use crate::mechanics::planar::{
    PlanarBody, Vec2, angular_momentum, kinetic_energy, linear_momentum,
};
use crate::model::System;
use std::cmp::Ordering;

/// The system's contacts in a field: the bodies' coordinates, the contacts' rows, e and mu.
pub(super) struct Contacts<F> {
    pub(super) planar: PlanarSystem<F>,
    pub(super) e: Vec<F>,
    pub(super) mu: Vec<F>,
}

impl<F: Field> Contacts<F> {
    pub(super) fn of(system: &System) -> Contacts<F> {
        Contacts {
            planar: PlanarSystem::of(system),
            e: system
                .contacts
                .iter()
                .map(|c| F::from_rational(&c.e))
                .collect(),
            mu: system
                .contacts
                .iter()
                .map(|c| F::from_rational(&c.mu))
                .collect(),
        }
    }

    pub(super) fn len(&self) -> usize {
        self.planar.rows.len()
    }

    /// The Delassus matrix of the normals: W_ij, the change of u_i per unit impulse lam_j.
    pub(super) fn delassus(&self) -> Vec<Vec<F>> {
        self.coupling(0, 0)
    }

    /// W's block between the contacts' rows along `along` and `by` (0 the normals, 1 the
    /// tangents): entry (i, j) is the change of contact i's velocity along `along` per unit
    /// impulse along `by` at contact j.
    pub(super) fn coupling(&self, along: usize, by: usize) -> Vec<Vec<F>> {
        delassus(&self.planar.rows, &self.planar.coordinates, along, by)
    }

    /// The relative velocity before at every contact along its normal (0) or tangent (1).
    pub(super) fn before(&self, direction: usize) -> Vec<F> {
        let before = velocities_before(&self.planar.coordinates);
        self.planar
            .rows
            .iter()
            .map(|rows| rows.row(direction).velocity(&before))
            .collect()
    }
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
pub(super) fn velocities<F: Field>(u0: &[F], w: &[Vec<F>], lam: &[F]) -> Vec<F> {
    (0..u0.len())
        .map(|i| (0..lam.len()).fold(u0[i].clone(), |acc, j| acc + &(w[i][j].clone() * &lam[j])))
        .collect()
}

/// The answer of `model` from the normal and tangential impulses at each contact: the bodies
/// after and the ledger; one stage (the whole impulses).
pub(super) fn finish<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    model: Model,
    (impulses, tangential, split_indeterminate): (Vec<F>, Vec<F>, bool),
    impacts: Vec<(usize, F)>,
) -> ModelAnswer<F> {
    let stages = vec![(impulses.clone(), tangential.clone())];
    finish_staged(
        system,
        contacts,
        model,
        (impulses, tangential, split_indeterminate),
        impacts,
        stages,
    )
}

/// [`finish`] with the model's stages.
pub(super) fn finish_staged<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    model: Model,
    (impulses, tangential, split_indeterminate): (Vec<F>, Vec<F>, bool),
    impacts: Vec<(usize, F)>,
    stages: Vec<(Vec<F>, Vec<F>)>,
) -> ModelAnswer<F> {
    let planar = &contacts.planar;
    let pairs: Vec<[F; 2]> = impulses
        .iter()
        .zip(&tangential)
        .map(|(n, t)| [n.clone(), t.clone()])
        .collect();
    let changes = coordinate_changes(&planar.coordinates, &planar.rows, &pairs);
    let after: Vec<PlanarBody<F>> = (0..planar.coordinates.len())
        .map(|slot| planar.body_after(slot, &changes[slot]))
        .collect();
    let before = &planar.before;
    let origin = Vec2::zero();
    ModelAnswer {
        model,
        bodies: planar
            .coordinates
            .iter()
            .zip(&after)
            .map(|(c, b)| (c.body, b.velocity.clone(), b.omega.clone()))
            .collect(),
        ledger: Ledger {
            momentum_before: linear_momentum(before),
            momentum_after: linear_momentum(&after),
            angular_before: angular_momentum(before, &origin),
            angular_after: angular_momentum(&after, &origin),
            energy: EnergyLedger::new(kinetic_energy(before), kinetic_energy(&after)),
            normal_after: system
                .contacts
                .iter()
                .enumerate()
                .map(|(k, c)| {
                    planar
                        .relative_velocity(k, c, &after)
                        .dot(&planar.normals[k])
                })
                .collect(),
        },
        impulses,
        tangential,
        split_indeterminate,
        impacts,
        stages,
    }
}
