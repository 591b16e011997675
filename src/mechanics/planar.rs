//! The conservation laws of rigid bodies moving in a plane, over any field: linear momentum
//! along both axes, angular momentum about a point, kinetic energy, the velocity of a
//! material point, and a solid disc's inertia. Stated once, for any number of bodies.
//!
//! The paper's laws ([`crate::scene::linear_momentum`], [`crate::scene::angular_momentum`],
//! [`crate::scene::kinetic_energy`]), the oblique impact's ([`crate::solve::fast::oblique`]) and the general
//! planar impacts are all these functions applied to their bodies.
//!
//! Conventions: standard axes (x, y), angular velocity and angular momentum counterclockwise
//! positive (about z = x cross y). The paper's omega turns the other way (a rod point at y moves
//! along x with `V + omega y`, so omega = -omega_z) and its angular momentum is `-L_z`: the
//! paper's functions change those two signs, nothing else.

use crate::field::Field;

/// A vector of the plane.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Vec2<F> {
    /// The x component.
    pub x: F,
    /// The y component.
    pub y: F,
}

impl<F: Field> Vec2<F> {
    /// The vector (x, y).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::planar::Vec2;
    /// assert_eq!(Vec2::new(1.0, 2.0).dot(&Vec2::new(3.0, 4.0)), 11.0);
    /// ```
    pub fn new(x: F, y: F) -> Self {
        Vec2 { x, y }
    }

    /// The zero vector.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::planar::Vec2;
    /// assert_eq!(Vec2::<f64>::zero(), Vec2::new(0.0, 0.0));
    /// ```
    pub fn zero() -> Self {
        Vec2::new(F::zero(), F::zero())
    }

    /// The dot product.
    pub fn dot(&self, other: &Self) -> F {
        self.x.clone() * &other.x + &(self.y.clone() * &other.y)
    }

    /// The z component of the cross product, `self.x other.y - self.y other.x`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::planar::Vec2;
    /// assert_eq!(Vec2::new(1.0, 0.0).cross(&Vec2::new(0.0, 1.0)), 1.0);
    /// ```
    pub fn cross(&self, other: &Self) -> F {
        self.x.clone() * &other.y - &(self.y.clone() * &other.x)
    }

    /// The vector turned a quarter turn counterclockwise, (-y, x).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::planar::Vec2;
    /// assert_eq!(Vec2::new(0.0, 1.0).perp(), Vec2::new(-1.0, 0.0));
    /// ```
    pub fn perp(&self) -> Self {
        Vec2::new(-self.y.clone(), self.x.clone())
    }

    /// `self + other`.
    pub fn add(&self, other: &Self) -> Self {
        Vec2::new(self.x.clone() + &other.x, self.y.clone() + &other.y)
    }

    /// `self - other`.
    pub fn sub(&self, other: &Self) -> Self {
        Vec2::new(self.x.clone() - &other.x, self.y.clone() - &other.y)
    }

    /// `k self`.
    pub fn scale(&self, k: &F) -> Self {
        Vec2::new(self.x.clone() * k, self.y.clone() * k)
    }
}

/// A rigid body in the plane at one instant: mass, moment of inertia about its centre of
/// mass, where that centre is, how fast it moves and turns (counterclockwise positive).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarBody<F> {
    /// The mass.
    pub mass: F,
    /// The moment of inertia about the centre of mass.
    pub inertia: F,
    /// The centre of mass.
    pub centre: Vec2<F>,
    /// The velocity of the centre of mass.
    pub velocity: Vec2<F>,
    /// The angular velocity, counterclockwise positive.
    pub omega: F,
}

impl<F: Field> PlanarBody<F> {
    /// The velocity of the body's material point at `point`: `v + omega x (point - centre)`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::mechanics::planar::{PlanarBody, Vec2};
    /// let wheel = PlanarBody { mass: 1.0, inertia: 0.5, centre: Vec2::new(0.0, 1.0), velocity: Vec2::new(2.0, 0.0), omega: 2.0 };
    /// assert_eq!(wheel.point_velocity(&Vec2::new(0.0, 0.0)), Vec2::new(4.0, 0.0));
    /// ```
    pub fn point_velocity(&self, point: &Vec2<F>) -> Vec2<F> {
        let arm = point.sub(&self.centre);
        self.velocity.add(&arm.perp().scale(&self.omega))
    }
}

/// The total linear momentum `sum m v`.
///
/// # Examples
/// ```
/// use rodimpact::mechanics::planar::{linear_momentum, PlanarBody, Vec2};
/// let b = |m: f64, vx: f64| PlanarBody { mass: m, inertia: 0.0, centre: Vec2::new(0.0, 0.0), velocity: Vec2::new(vx, 1.0), omega: 0.0 };
/// assert_eq!(linear_momentum(&[b(1.0, 2.0), b(3.0, -1.0)]), Vec2::new(-1.0, 4.0));
/// ```
pub fn linear_momentum<F: Field>(bodies: &[PlanarBody<F>]) -> Vec2<F> {
    bodies.iter().fold(Vec2::zero(), |total, b| {
        total.add(&b.velocity.scale(&b.mass))
    })
}

/// The total angular momentum about `about`, counterclockwise positive:
/// `sum m (c - about) x v + I omega`.
///
/// # Examples
/// ```
/// use rodimpact::mechanics::planar::{angular_momentum, PlanarBody, Vec2};
/// // A point mass passing above the origin moving along +x turns clockwise about it.
/// let b = PlanarBody { mass: 2.0, inertia: 0.0, centre: Vec2::new(0.0, 1.0), velocity: Vec2::new(3.0, 0.0), omega: 0.0 };
/// assert_eq!(angular_momentum(&[b], &Vec2::new(0.0, 0.0)), -6.0);
/// ```
pub fn angular_momentum<F: Field>(bodies: &[PlanarBody<F>], about: &Vec2<F>) -> F {
    bodies.iter().fold(F::zero(), |total, b| {
        let orbit = b.centre.sub(about).cross(&b.velocity) * &b.mass;
        total + &orbit + &(b.inertia.clone() * &b.omega)
    })
}

/// The total kinetic energy `sum (m |v|^2 + I omega^2)/2`.
///
/// # Examples
/// ```
/// use rodimpact::mechanics::planar::{kinetic_energy, PlanarBody, Vec2};
/// let b = PlanarBody { mass: 2.0, inertia: 0.5, centre: Vec2::new(0.0, 0.0), velocity: Vec2::new(3.0, 4.0), omega: 2.0 };
/// assert_eq!(kinetic_energy(&[b]), 26.0); // (2 * 25 + 0.5 * 4)/2
/// ```
pub fn kinetic_energy<F: Field>(bodies: &[PlanarBody<F>]) -> F {
    let twice = bodies.iter().fold(F::zero(), |total, b| {
        let translation = b.velocity.dot(&b.velocity) * &b.mass;
        total + &translation + &(b.inertia.clone() * &b.omega * &b.omega)
    });
    twice / &F::from_i64(2)
}

/// A solid disc's moment of inertia about its centre, `m r^2/2`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::mechanics::planar::disc_inertia(&2.0, &3.0), 9.0);
/// ```
pub fn disc_inertia<F: Field>(mass: &F, radius: &F) -> F {
    mass.clone() * radius * radius / &F::from_i64(2)
}
