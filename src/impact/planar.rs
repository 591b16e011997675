//! The plane's bodies and contacts in the core's terms: each moving body's velocity
//! coordinates (free: `(v_x, v_y, omega)`; pinned: its spin about the pin), each contact's
//! normal and tangent rows of the Jacobian, and the bodies' motion after the impact read back
//! from their coordinates; with the planar laws ([`crate::mechanics::planar`]) that check it.
//!
//! A free body of mass m and inertia I about its centre c, struck at p along a direction d
//! (sign s: +1 on body A, -1 on B), has the row block `s (d_x, d_y, (p - c) x d)` and
//! `M^-1 = diag(1/m, 1/m, 1/I)`; a body pinned at q, `s ((p - q) x d)` and
//! `M^-1 = 1/(I + m |c - q|^2)`; a fixed body has no coordinates. The tangent is the normal
//! turned a quarter turn counterclockwise, so `|t| = |n|`.

use super::jacobian::{ContactRows, Coordinates, Row};
use crate::field::{Field, Q};
use crate::mechanics::planar::{PlanarBody, Vec2};
use crate::model::{Body, Contact, Mobility, System};

/// A vector of Q lifted into a field.
pub(crate) fn lift<F: Field>(v: &Vec2<Q>) -> Vec2<F> {
    Vec2::new(F::from_rational(&v.x), F::from_rational(&v.y))
}

/// 1/x, or 0 for x = 0 (no response: a point mass struck at its centre never turns).
fn invert<F: Field>(x: &F) -> F {
    if x.is_zero() { F::zero() } else { F::one() / x }
}

/// A system of the plane in a field: its moving bodies' coordinates and states, its contacts'
/// rows, points and normals.
#[derive(Debug, Clone)]
pub(crate) struct PlanarSystem<F> {
    /// The moving bodies' coordinates, by slot (their order in the system).
    pub(crate) coordinates: Vec<Coordinates<F>>,
    /// The moving bodies before the impact, by slot.
    pub(crate) before: Vec<PlanarBody<F>>,
    /// The pin of each moving body that has one, by slot.
    pins: Vec<Option<Vec2<F>>>,
    /// Each contact's rows.
    pub(crate) rows: Vec<ContactRows<F>>,
    /// Each contact's point.
    pub(crate) points: Vec<Vec2<F>>,
    /// Each contact's normal (from B into A, not normalised).
    pub(crate) normals: Vec<Vec2<F>>,
    /// The slot of each body of the system (`None`: fixed).
    slots: Vec<Option<usize>>,
}

impl<F: Field> PlanarSystem<F> {
    /// `system` lifted into `F`.
    pub(crate) fn of(system: &System) -> PlanarSystem<F> {
        let mut slots = Vec::with_capacity(system.bodies.len());
        let (mut coordinates, mut before, mut pins) = (Vec::new(), Vec::new(), Vec::new());
        for (index, body) in system.bodies.iter().enumerate() {
            let Some((coords, pin)) = body_coordinates(index, body) else {
                slots.push(None);
                continue;
            };
            slots.push(Some(coordinates.len()));
            coordinates.push(coords);
            pins.push(pin);
            before.push(lifted_body(body));
        }
        let mut planar = PlanarSystem {
            coordinates,
            before,
            pins,
            rows: Vec::with_capacity(system.contacts.len()),
            points: system.contacts.iter().map(|c| lift(&c.point)).collect(),
            normals: system.contacts.iter().map(|c| lift(&c.normal)).collect(),
            slots,
        };
        planar.rows = system
            .contacts
            .iter()
            .enumerate()
            .map(|(k, c)| planar.contact_rows(k, c))
            .collect();
        planar
    }

    /// The rows of contact `k` (A's blocks with sign +1, B's with -1).
    fn contact_rows(&self, k: usize, c: &Contact) -> ContactRows<F> {
        let normal = self.normals[k].clone();
        let tangent = normal.perp();
        ContactRows {
            normal: self.row(c, &self.points[k], &normal),
            tangent: self.row(c, &self.points[k], &tangent),
        }
    }

    /// The row of the relative velocity at `point` along `direction` for contact `c`.
    fn row(&self, c: &Contact, point: &Vec2<F>, direction: &Vec2<F>) -> Row<F> {
        let mut blocks = Vec::with_capacity(2);
        for (index, sign) in [(c.a, F::one()), (c.b, -F::one())] {
            let Some(slot) = self.slots[index] else {
                continue;
            };
            let about = self.pins[slot]
                .as_ref()
                .unwrap_or(&self.before[slot].centre);
            let moment = point.sub(about).cross(direction) * &sign;
            let block = if self.pins[slot].is_some() {
                vec![moment]
            } else {
                vec![
                    direction.x.clone() * &sign,
                    direction.y.clone() * &sign,
                    moment,
                ]
            };
            blocks.push((slot, block));
        }
        Row { blocks }
    }

    /// The moving body in `slot` after its coordinates changed by `change`.
    pub(crate) fn body_after(&self, slot: usize, change: &[F]) -> PlanarBody<F> {
        let before = &self.before[slot];
        let (dv, dw) = match &self.pins[slot] {
            Some(pin) => (
                before.centre.sub(pin).perp().scale(&change[0]),
                change[0].clone(),
            ),
            None => (
                Vec2::new(change[0].clone(), change[1].clone()),
                change[2].clone(),
            ),
        };
        PlanarBody {
            velocity: before.velocity.add(&dv),
            omega: before.omega.clone() + &dw,
            ..before.clone()
        }
    }

    /// The pin of the moving body in `slot`, if it has one.
    pub(crate) fn pin(&self, slot: usize) -> Option<&Vec2<F>> {
        self.pins[slot].as_ref()
    }

    /// The relative velocity at contact `k` (A's point minus B's) of the bodies `states` (by
    /// slot).
    pub(crate) fn relative_velocity(
        &self,
        k: usize,
        c: &Contact,
        states: &[PlanarBody<F>],
    ) -> Vec2<F> {
        let point_velocity = |index: usize| match self.slots[index] {
            Some(slot) => states[slot].point_velocity(&self.points[k]),
            None => Vec2::zero(),
        };
        point_velocity(c.a).sub(&point_velocity(c.b))
    }
}

/// A body's coordinates and pin, or `None` for a fixed body.
fn body_coordinates<F: Field>(
    index: usize,
    body: &Body,
) -> Option<(Coordinates<F>, Option<Vec2<F>>)> {
    let (mass, inertia) = (
        F::from_rational(&body.mass),
        F::from_rational(&body.inertia),
    );
    match &body.mobility {
        Mobility::Fixed => None,
        Mobility::Free => Some((
            Coordinates {
                body: index,
                inverse_mass: vec![invert(&mass), invert(&mass), invert(&inertia)],
                before: vec![
                    F::from_rational(&body.velocity.x),
                    F::from_rational(&body.velocity.y),
                    F::from_rational(&body.omega),
                ],
            },
            None,
        )),
        Mobility::Pinned(pin) => {
            let pin: Vec2<F> = lift(pin);
            let arm = lift::<F>(&body.position).sub(&pin);
            let about_pin = inertia + &(mass * &arm.dot(&arm));
            Some((
                Coordinates {
                    body: index,
                    inverse_mass: vec![invert(&about_pin)],
                    before: vec![F::from_rational(&body.omega)],
                },
                Some(pin),
            ))
        }
    }
}

/// A body before the impact as the planar laws see it, lifted.
fn lifted_body<F: Field>(body: &Body) -> PlanarBody<F> {
    PlanarBody {
        mass: F::from_rational(&body.mass),
        inertia: F::from_rational(&body.inertia),
        centre: lift(&body.position),
        velocity: lift(&body.velocity),
        omega: F::from_rational(&body.omega),
    }
}
