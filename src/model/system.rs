//! Planar rigid bodies and the contacts between them at one impact instant: a validated
//! [`System`], exact (every number in Q).

use super::shape::Shape;
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::mechanics::planar::{PlanarBody, Vec2};
use num_traits::{One, Signed, Zero};

/// How a body may move.
#[derive(Debug, Clone, PartialEq)]
pub enum Mobility {
    /// Free in the plane.
    Free,
    /// Held at a point of the plane (a frictionless pin, the paper's pivot): it can only turn
    /// about it; the pin takes whatever impulse that needs.
    Pinned(Vec2<Q>),
    /// Never moves (the ground, a wall): its mass is infinite.
    Fixed,
}

/// A body at the impact instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Its name (unique in the system).
    pub name: String,
    /// Free, pinned or fixed.
    pub mobility: Mobility,
    /// Mass (> 0; 0 for a fixed body).
    pub mass: Q,
    /// Moment of inertia about the centre of mass (>= 0).
    pub inertia: Q,
    /// The centre of mass.
    pub position: Vec2<Q>,
    /// The velocity of the centre of mass before the impact.
    pub velocity: Vec2<Q>,
    /// The angular velocity before the impact, counterclockwise positive.
    pub omega: Q,
    /// The shape, if given (it gave the inertia when none was given, and contact points must
    /// lie on its boundary).
    pub shape: Option<Shape>,
}

impl Body {
    /// Whether the body moves in the impact (free or pinned).
    pub fn moves(&self) -> bool {
        self.mobility != Mobility::Fixed
    }

    /// The body as the planar laws see it (fixed bodies have no momentum to count).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, model::{Body, Mobility}, mechanics::planar::Vec2};
    /// let b = Body { name: "ball".into(), mobility: Mobility::Free, mass: q(2, 1), inertia: q(0, 1),
    ///     position: Vec2::zero(), velocity: Vec2::new(q(1, 1), q(0, 1)), omega: q(0, 1), shape: None };
    /// assert_eq!(b.planar().mass, q(2, 1));
    /// ```
    pub fn planar(&self) -> PlanarBody<Q> {
        PlanarBody {
            mass: self.mass.clone(),
            inertia: self.inertia.clone(),
            centre: self.position.clone(),
            velocity: self.velocity.clone(),
            omega: self.omega.clone(),
        }
    }
}

/// A contact between bodies `a` and `b` (indices into the system's bodies).
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    /// Body A: the impulse on it is P.
    pub a: usize,
    /// Body B: the impulse on it is -P.
    pub b: usize,
    /// The contact point.
    pub point: Vec2<Q>,
    /// The normal from B into A (the direction the impulse pushes A); not normalised.
    pub normal: Vec2<Q>,
    /// The coefficient of restitution, 0 <= e <= 1.
    pub e: Q,
    /// The Coulomb friction coefficient, mu >= 0.
    pub mu: Q,
}

impl Contact {
    /// The tangent: the normal turned a quarter turn counterclockwise.
    pub fn tangent(&self) -> Vec2<Q> {
        self.normal.perp()
    }
}

/// Bodies and contacts at one impact instant, validated: what `rodimpact impact` answers.
#[derive(Debug, Clone, PartialEq)]
pub struct System {
    /// An optional title.
    pub title: Option<String>,
    /// The bodies.
    pub bodies: Vec<Body>,
    /// The contacts (at least one).
    pub contacts: Vec<Contact>,
}

/// The most bodies and contacts a system may hold.
pub const MAX_BODIES: usize = 1_000;
/// The most contacts a system may hold (the simultaneous models solve them by Lemke's method
/// beyond eight).
pub const MAX_CONTACTS: usize = 64;
/// The most contacts a system with friction may hold (the simultaneous models with friction try
/// every one of the 6^n modes of its contacts in each phase).
pub const MAX_FRICTIONAL_CONTACTS: usize = 4;

impl System {
    /// Checks a system and returns it: names unique, masses positive, inertias non-negative (a
    /// turning body needs inertia), every contact between two bodies that are not both fixed,
    /// its normal not zero, its point on both bodies' shapes (a body without a shape is not
    /// checked), 0 <= e <= 1, mu >= 0, a pinned point at rest, and a contact approaching (with
    /// several contacts, the others may touch).
    ///
    /// # Errors
    /// One error naming the field (`body[2].mass`, `contact[1].normal`, ...) and the reason.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, model::{Body, Contact, Mobility, System}, mechanics::planar::Vec2};
    /// let ball = Body { name: "ball".into(), mobility: Mobility::Free, mass: q(1, 1), inertia: q(0, 1),
    ///     position: Vec2::zero(), velocity: Vec2::new(q(0, 1), q(-1, 1)), omega: q(0, 1), shape: None };
    /// let floor = Body { name: "floor".into(), mobility: Mobility::Fixed, mass: q(0, 1), inertia: q(0, 1),
    ///     position: Vec2::zero(), velocity: Vec2::zero(), omega: q(0, 1), shape: None };
    /// let hit = Contact { a: 0, b: 1, point: Vec2::zero(), normal: Vec2::new(q(0, 1), q(1, 1)), e: q(1, 1), mu: q(0, 1) };
    /// assert!(System::new(None, vec![ball.clone(), floor.clone()], vec![hit.clone()]).is_ok());
    /// let away = Contact { normal: Vec2::new(q(0, 1), q(-1, 1)), ..hit };
    /// let err = System::new(None, vec![ball, floor], vec![away]).unwrap_err();
    /// assert!(err.to_string().starts_with("contact[1]: no approach"), "{err}");
    /// ```
    pub fn new(
        title: Option<String>,
        bodies: Vec<Body>,
        contacts: Vec<Contact>,
    ) -> Result<System, Error> {
        if bodies.len() > MAX_BODIES {
            return Err(invalid(
                "body",
                format!("more than {MAX_BODIES} bodies (limit)"),
            ));
        }
        if contacts.is_empty() {
            return Err(Error::new("contact", ErrorKind::Missing));
        }
        if contacts.len() > MAX_CONTACTS {
            return Err(invalid(
                "contact",
                format!("more than {MAX_CONTACTS} contacts (limit)"),
            ));
        }
        if contacts.len() > MAX_FRICTIONAL_CONTACTS && contacts.iter().any(|c| c.mu.is_positive()) {
            return Err(invalid(
                "contact",
                format!(
                    "{} contacts with friction: at most {MAX_FRICTIONAL_CONTACTS} when any has mu > 0 (limit)",
                    contacts.len()
                ),
            ));
        }
        check_names(&bodies)?;
        for (i, b) in bodies.iter().enumerate() {
            check_body(i, b)?;
        }
        let system = System {
            title,
            bodies,
            contacts,
        };
        for (k, c) in system.contacts.iter().enumerate() {
            system.check_contact(k, c)?;
        }
        // At least one contact approaches; with several, the others may touch (a resting ball
        // of Newton's cradle) or separate.
        let approaching = |c: &Contact| system.relative_velocity(c).dot(&c.normal).is_negative();
        if !system.contacts.iter().any(approaching) {
            let c = &system.contacts[0];
            let u_n = system.relative_velocity(c).dot(&c.normal);
            let (field, what) = if system.contacts.len() == 1 {
                let sign = if u_n.is_positive() {
                    "; if the bodies do approach, the normal points the wrong way: it must point from \
                     the second body into the first"
                } else {
                    ""
                };
                ("contact[1]".to_string(), format!("is {u_n}, not < 0{sign}"))
            } else {
                (
                    "contact".to_string(),
                    "is >= 0 at every contact".to_string(),
                )
            };
            return Err(Error::out_of_range(
                field,
                format!(
                    "no approach: the normal relative velocity (A's point minus B's, along the normal) {what}"
                ),
            ));
        }
        Ok(system)
    }

    /// The velocity of body `index`'s material point at `point` before the impact (zero for a
    /// fixed body).
    pub fn point_velocity(&self, index: usize, point: &Vec2<Q>) -> Vec2<Q> {
        let b = &self.bodies[index];
        if !b.moves() {
            return Vec2::zero();
        }
        b.planar().point_velocity(point)
    }

    /// The relative velocity at contact `c` before the impact, A's material point minus B's.
    pub fn relative_velocity(&self, c: &Contact) -> Vec2<Q> {
        self.point_velocity(c.a, &c.point)
            .sub(&self.point_velocity(c.b, &c.point))
    }

    fn check_contact(&self, k: usize, c: &Contact) -> Result<(), Error> {
        let field = |what: &str| format!("contact[{}].{what}", k + 1);
        let (a, b) = (&self.bodies[c.a], &self.bodies[c.b]);
        if c.a == c.b {
            return Err(invalid(
                &field("bodies"),
                format!("a contact joins two bodies, and both are '{}'", a.name),
            ));
        }
        if !a.moves() && !b.moves() {
            return Err(invalid(&field("bodies"), "both bodies are fixed".into()));
        }
        if c.normal.x.is_zero() && c.normal.y.is_zero() {
            return Err(Error::out_of_range(
                field("normal"),
                "the normal is zero: give the direction the impulse pushes A",
            ));
        }
        if c.e.is_negative() || c.e > Q::one() {
            return Err(Error::out_of_range(
                field("e"),
                format!("coefficient of restitution must lie in [0, 1], got {}", c.e),
            ));
        }
        if c.mu.is_negative() {
            return Err(Error::out_of_range(
                field("mu"),
                format!("friction coefficient must be >= 0, got {}", c.mu),
            ));
        }
        for body in [a, b] {
            if !lies_on(body, &c.point) {
                return Err(Error::out_of_range(
                    field("point"),
                    format!(
                        "({}, {}) is not on the boundary of the shape of body '{}'",
                        c.point.x, c.point.y, body.name
                    ),
                ));
            }
            if body.moves() && body.inertia.is_zero() && body.position != c.point {
                return Err(Error::out_of_range(
                    field("point"),
                    format!(
                        "body '{}' has no moment of inertia, so it can be struck only at its centre",
                        body.name
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// Whether `point` lies on `body`: on its shape's boundary when it has one. A body without a
/// shape has nothing to check against: a moving one is given by its inertia alone (a point
/// mass, inertia 0, is checked apart to be struck at its centre), and a fixed one (the ground,
/// a wall, a step) is a face through the contact point across the normal.
fn lies_on(body: &Body, point: &Vec2<Q>) -> bool {
    match &body.shape {
        Some(shape) => shape.on_boundary(point, &body.position),
        None => true,
    }
}

/// Every body's name is its own.
pub(super) fn check_names(bodies: &[Body]) -> Result<(), Error> {
    for (i, b) in bodies.iter().enumerate() {
        if bodies[..i].iter().any(|other| other.name == b.name) {
            return Err(invalid(
                &format!("body[{}].name", i + 1),
                format!("'{}' names two bodies", crate::echo::echo(&b.name)),
            ));
        }
    }
    Ok(())
}

fn check_body(i: usize, b: &Body) -> Result<(), Error> {
    let field = |what: &str| format!("body[{}].{what}", i + 1);
    if !b.moves() {
        return Ok(());
    }
    if !b.mass.is_positive() {
        return Err(Error::out_of_range(
            field("mass"),
            format!("must be > 0, got {}", b.mass),
        ));
    }
    if b.inertia.is_negative() {
        return Err(Error::out_of_range(
            field("inertia"),
            format!("must be >= 0, got {}", b.inertia),
        ));
    }
    if let Mobility::Pinned(pin) = &b.mobility {
        let moving = b.planar().point_velocity(pin);
        if !moving.x.is_zero() || !moving.y.is_zero() {
            return Err(Error::out_of_range(
                format!("pin[{}]", i + 1),
                format!(
                    "the pinned point of '{}' moves before the impact ({}, {}): a pin holds it at rest",
                    b.name, moving.x, moving.y
                ),
            ));
        }
    }
    Ok(())
}

fn invalid(field: &str, why: String) -> Error {
    Error::new(field, ErrorKind::Invalid(why))
}
