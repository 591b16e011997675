//! Contacts as Jacobian rows over the moving bodies' velocity coordinates, and the system's
//! response to contact impulses: `W = J M^-1 J^T` (as rapier's contact constraints build it).
//!
//! Each moving body has velocity coordinates `qdot` and an inverse mass matrix `M^-1` in them
//! (a free planar body: `(v_x, v_y, omega)` with `diag(1/m, 1/m, 1/I)`; a pinned one: its spin
//! about the pin with `1/I_pin`; a zero entry where the mass or inertia is zero: a point mass
//! struck at its centre never turns). A contact's relative velocity along one direction (the
//! normal, a tangent) is a row of the Jacobian, `u = J qdot`, with a block for each of its
//! moving bodies. An impulse `P = sum_r lam_r J_r^T` changes the coordinates by `M^-1 J^T lam`,
//! and the rows' velocities by `W lam`.
//!
//! Nothing here knows the number of coordinates of a body or what they mean: the plane's
//! bodies and contacts are turned into coordinates and rows by [`super::planar`].

use crate::field::Field;

/// A moving body in its velocity coordinates.
#[derive(Debug, Clone)]
pub(crate) struct Coordinates<F> {
    /// The body's index in the system.
    pub(crate) body: usize,
    /// The diagonal of `M^-1` in these coordinates (zero where the mass or inertia is zero).
    pub(crate) inverse_mass: Vec<F>,
    /// The velocity coordinates before the impact.
    pub(crate) before: Vec<F>,
}

impl<F: Field> Coordinates<F> {
    /// `M^-1 x` for a covector `x` of these coordinates.
    fn apply_inverse_mass(&self, x: &[F]) -> Vec<F> {
        self.inverse_mass
            .iter()
            .zip(x)
            .map(|(m, x)| m.clone() * x)
            .collect()
    }
}

/// One row of the Jacobian: the relative velocity at a contact along one direction, as a block
/// of coefficients for each of its moving bodies (a fixed body has none).
#[derive(Debug, Clone)]
pub(crate) struct Row<F> {
    /// (the body's slot among the moving bodies, the coefficients of its coordinates).
    pub(crate) blocks: Vec<(usize, Vec<F>)>,
}

impl<F: Field> Row<F> {
    /// `J qdot` for the bodies' coordinates `velocities` (indexed by slot).
    pub(crate) fn velocity(&self, velocities: &[Vec<F>]) -> F {
        let mut u = F::zero();
        for (slot, j) in &self.blocks {
            for (a, b) in j.iter().zip(&velocities[*slot]) {
                u = u + &(a.clone() * b);
            }
        }
        u
    }

    /// `J_self M^-1 J_other^T`: the change of this row's velocity per unit impulse along
    /// `other` (an entry of W).
    pub(crate) fn coupling(&self, other: &Row<F>, bodies: &[Coordinates<F>]) -> F {
        let mut w = F::zero();
        for (slot, j) in &self.blocks {
            for (other_slot, k) in &other.blocks {
                if slot != other_slot {
                    continue;
                }
                let response = bodies[*slot].apply_inverse_mass(k);
                for (a, b) in j.iter().zip(&response) {
                    w = w + &(a.clone() * b);
                }
            }
        }
        w
    }
}

/// A contact's rows: the normal first, then its tangent (one in the plane).
#[derive(Debug, Clone)]
pub(crate) struct ContactRows<F> {
    /// Along the normal (not normalised): `u_n`.
    pub(crate) normal: Row<F>,
    /// Along the tangent: `u_t`.
    pub(crate) tangent: Row<F>,
}

impl<F: Field> ContactRows<F> {
    /// The row of `direction`: 0 the normal, 1 the tangent.
    pub(crate) fn row(&self, direction: usize) -> &Row<F> {
        if direction == 0 {
            &self.normal
        } else {
            &self.tangent
        }
    }
}

/// The changes of every moving body's coordinates under the impulses `(lam, tau)` along the
/// rows of each contact: `M^-1 J^T (lam, tau)`, by slot.
pub(crate) fn coordinate_changes<F: Field>(
    bodies: &[Coordinates<F>],
    contacts: &[ContactRows<F>],
    impulses: &[[F; 2]],
) -> Vec<Vec<F>> {
    let mut push: Vec<Vec<F>> = bodies
        .iter()
        .map(|b| vec![F::zero(); b.before.len()])
        .collect();
    for (rows, impulse) in contacts.iter().zip(impulses) {
        for (row, lam) in [&rows.normal, &rows.tangent].into_iter().zip(impulse) {
            if lam.is_zero() {
                continue;
            }
            for (slot, j) in &row.blocks {
                for (p, a) in push[*slot].iter_mut().zip(j) {
                    *p = p.clone() + &(a.clone() * lam);
                }
            }
        }
    }
    bodies
        .iter()
        .zip(&push)
        .map(|(b, p)| b.apply_inverse_mass(p))
        .collect()
}

/// The coordinates before the impact, by slot.
pub(crate) fn velocities_before<F: Field>(bodies: &[Coordinates<F>]) -> Vec<Vec<F>> {
    bodies.iter().map(|b| b.before.clone()).collect()
}

/// The contact matrix of one contact: W restricted to its normal and tangent rows (symmetric).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactMatrix<F> {
    /// `J_n M^-1 J_n^T`: how an impulse along n changes u_n.
    pub nn: F,
    /// `J_n M^-1 J_t^T = J_t M^-1 J_n^T`: the coupling. Zero in every scene of the paper's
    /// family.
    pub nt: F,
    /// `J_t M^-1 J_t^T`: how an impulse along t changes u_t.
    pub tt: F,
}

impl<F: Field> ContactMatrix<F> {
    /// The contact matrix of `rows`.
    pub(crate) fn of(rows: &ContactRows<F>, bodies: &[Coordinates<F>]) -> ContactMatrix<F> {
        ContactMatrix {
            nn: rows.normal.coupling(&rows.normal, bodies),
            nt: rows.normal.coupling(&rows.tangent, bodies),
            tt: rows.tangent.coupling(&rows.tangent, bodies),
        }
    }
}

/// The blocks of W between the contacts' rows along `along` and `by` (0 normal, 1 tangent):
/// entry (i, j) is the change of contact i's velocity along `along` per unit impulse along
/// `by` at contact j (the Delassus matrix of the normals for (0, 0)).
pub(crate) fn delassus<F: Field>(
    contacts: &[ContactRows<F>],
    bodies: &[Coordinates<F>],
    along: usize,
    by: usize,
) -> Vec<Vec<F>> {
    contacts
        .iter()
        .map(|i| {
            contacts
                .iter()
                .map(|j| i.row(along).coupling(j.row(by), bodies))
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{Q, q};

    /// A free body (m = 2, I = 1/2) and a pinned one (I_pin = 3) share a row: W is
    /// J M^-1 J^T block by block, and an impulse moves each by M^-1 J^T lam.
    #[test]
    fn w_is_j_m_inverse_j_transpose() {
        let bodies = vec![
            Coordinates {
                body: 0,
                inverse_mass: vec![q(1, 2), q(1, 2), q(2, 1)],
                before: vec![q(1, 1), q(0, 1), q(0, 1)],
            },
            Coordinates {
                body: 2,
                inverse_mass: vec![q(1, 3)],
                before: vec![q(0, 1)],
            },
        ];
        let normal = Row {
            blocks: vec![(0, vec![q(1, 1), q(0, 1), q(1, 1)]), (1, vec![q(-2, 1)])],
        };
        let tangent = Row {
            blocks: vec![(0, vec![q(0, 1), q(1, 1), q(0, 1)])],
        };
        let rows = ContactRows { normal, tangent };
        let w = ContactMatrix::of(&rows, &bodies);
        // nn = 1/2 + 2 + 4/3; nt = 0; tt = 1/2.
        assert_eq!((w.nn, w.nt, w.tt), (q(23, 6), q(0, 1), q(1, 2)));
        assert_eq!(rows.normal.velocity(&velocities_before(&bodies)), q(1, 1));
        let dv = coordinate_changes::<Q>(&bodies, &[rows], &[[q(1, 1), q(2, 1)]]);
        assert_eq!(dv[0], [q(1, 2), q(1, 1), q(2, 1)]);
        assert_eq!(dv[1], [q(-2, 3)]);
    }
}
