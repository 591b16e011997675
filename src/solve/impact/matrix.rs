//! The contact's mechanics in a field: each moving body's response to an impulse at a point,
//! and the contact matrix W that maps an impulse `P = lam n + tau t` to the change of the
//! relative velocity at the contact, `(du_n, du_t) = W (dlam, dtau)`, with `u_n = u.n` and
//! `u_t = u.t` (n not normalised, t = n turned a quarter turn counterclockwise, so |t| = |n|).
//!
//! A free body of mass m and inertia I about its centre c changes the velocity of its point p
//! by `P/m + r_perp (r_perp . P)/I` (r = p - c, r_perp = (-r_y, r_x)); a body pinned at q turns
//! about it only, `s_perp (s_perp . P)/I_q` (s = p - q, I_q = I + m |c - q|^2); a fixed body
//! does not move. The impulse on B is -P and the relative velocity is A's minus B's, so both
//! bodies add: W = [n.K.n, n.K.t; t.K.n, t.K.t] with K the sum of the two responses. W is
//! symmetric and positive semidefinite.

use crate::field::Field;
use crate::mechanics::planar::Vec2;
use crate::model::{Body, Contact, Mobility, System};

/// A moving body's response to impulses, lifted into a field.
#[derive(Debug, Clone)]
pub(crate) struct Response<F> {
    /// 1/m for a free body, 0 for a pinned one (its centre follows its spin).
    inverse_mass: F,
    /// 1/I about the centre (free) or about the pin (pinned); 0 when I = 0 (a point mass,
    /// struck at its centre).
    inverse_inertia: F,
    /// The point the body turns about: its centre (free) or the pin.
    about: Vec2<F>,
}

impl<F: Field> Response<F> {
    /// The response of `body`, or `None` for a fixed body.
    pub(crate) fn of(body: &Body) -> Option<Response<F>> {
        let lift = |x: &crate::field::Q| F::from_rational(x);
        let centre = Vec2::new(lift(&body.position.x), lift(&body.position.y));
        let invert = |x: &F| {
            if x.is_zero() { F::zero() } else { F::one() / x }
        };
        match &body.mobility {
            Mobility::Fixed => None,
            Mobility::Free => Some(Response {
                inverse_mass: invert(&lift(&body.mass)),
                inverse_inertia: invert(&lift(&body.inertia)),
                about: centre,
            }),
            Mobility::Pinned(pin) => {
                let pin = Vec2::new(lift(&pin.x), lift(&pin.y));
                let arm = centre.sub(&pin);
                let about_pin = lift(&body.inertia) + &(lift(&body.mass) * &arm.dot(&arm));
                Some(Response {
                    inverse_mass: F::zero(),
                    inverse_inertia: invert(&about_pin),
                    about: pin,
                })
            }
        }
    }

    /// The change of the velocity of the body's point `p` under the impulse `impulse` there.
    pub(crate) fn point_change(&self, p: &Vec2<F>, impulse: &Vec2<F>) -> Vec2<F> {
        self.point_change_at(p, p, impulse)
    }

    /// The change of the velocity of the body's point `p` under the impulse `impulse` applied at
    /// another point `at`.
    pub(crate) fn point_change_at(&self, p: &Vec2<F>, at: &Vec2<F>, impulse: &Vec2<F>) -> Vec2<F> {
        let arm_p = p.sub(&self.about).perp();
        let arm_at = at.sub(&self.about).perp();
        impulse
            .scale(&self.inverse_mass)
            .add(&arm_p.scale(&(arm_at.dot(impulse) * &self.inverse_inertia)))
    }

    /// The change of the body's spin (counterclockwise) under `impulse` at `p`.
    pub(crate) fn spin_change(&self, p: &Vec2<F>, impulse: &Vec2<F>) -> F {
        p.sub(&self.about).cross(impulse) * &self.inverse_inertia
    }

    /// The change of the velocity of the body's centre `centre` under `impulse` at `p`: the
    /// impulse over the mass (free), or the new spin about the pin carried to the centre
    /// (pinned).
    pub(crate) fn centre_change(
        &self,
        centre: &Vec2<F>,
        p: &Vec2<F>,
        impulse: &Vec2<F>,
    ) -> Vec2<F> {
        if self.inverse_mass.is_zero() {
            centre
                .sub(&self.about)
                .perp()
                .scale(&self.spin_change(p, impulse))
        } else {
            impulse.scale(&self.inverse_mass)
        }
    }
}

/// One contact lifted into a field: its point, normal and tangent, the responses of its two
/// bodies (`None` for a fixed one), e and mu.
#[derive(Debug, Clone)]
pub(crate) struct Lifted<F> {
    pub(crate) point: Vec2<F>,
    pub(crate) normal: Vec2<F>,
    pub(crate) tangent: Vec2<F>,
    pub(crate) a: Option<Response<F>>,
    pub(crate) b: Option<Response<F>>,
    pub(crate) e: F,
    pub(crate) mu: F,
}

/// The 2x2 contact matrix W (symmetric).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactMatrix<F> {
    /// n.K.n: how an impulse along n changes u_n.
    pub nn: F,
    /// n.K.t = t.K.n: the coupling. Zero in every scene of the paper's family.
    pub nt: F,
    /// t.K.t: how an impulse along t changes u_t.
    pub tt: F,
}

impl<F: Field> Lifted<F> {
    /// Contact `c` of `system` in the field `F`.
    pub(crate) fn of(system: &System, c: &Contact) -> Lifted<F> {
        let lift =
            |v: &Vec2<crate::field::Q>| Vec2::new(F::from_rational(&v.x), F::from_rational(&v.y));
        let normal = lift(&c.normal);
        Lifted {
            point: lift(&c.point),
            tangent: normal.perp(),
            normal,
            a: Response::of(&system.bodies[c.a]),
            b: Response::of(&system.bodies[c.b]),
            e: F::from_rational(&c.e),
            mu: F::from_rational(&c.mu),
        }
    }

    /// The change of the relative velocity at the contact under the impulse P on A (-P on B).
    pub(crate) fn relative_change(&self, impulse: &Vec2<F>) -> Vec2<F> {
        let mut change = Vec2::zero();
        for body in self.a.iter().chain(&self.b) {
            change = change.add(&body.point_change(&self.point, impulse));
        }
        change
    }

    /// The contact matrix W.
    pub(crate) fn matrix(&self) -> ContactMatrix<F> {
        let (n, t) = (&self.normal, &self.tangent);
        let (kn, kt) = (self.relative_change(n), self.relative_change(t));
        ContactMatrix {
            nn: n.dot(&kn),
            nt: n.dot(&kt),
            tt: t.dot(&kt),
        }
    }
}
