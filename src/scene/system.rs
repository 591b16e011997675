//! The paper's scene written as bodies: the projectile and the rod of a [`Scene`] as a
//! [`System`] ([`Scene::system`]), so that the general solver ([`crate::impact`]) answers it
//! and the paper's routes are checked against it.
//!
//! Axes as in docs/conventions.md: the rod lies along y with its centre at the origin, the
//! projectile (a point at (0, a), or a disc whose centre is at (-r, a)) moves along +x. The
//! contact is at (0, a) with the normal (-1, 0) from the rod into the projectile (A is the
//! projectile, B the rod). The paper's omega turns the other way from the counterclockwise
//! spin of the planar model: the rod's spin is -omega.

use super::{Scene, Support};
use crate::field::Q;
use crate::mechanics::planar::Vec2;
use crate::model::{Body, Contact, Mobility, Shape, System};
use num_traits::Zero;

/// The projectile's name in [`Scene::system`].
pub const PROJECTILE: &str = "projectile";
/// The rod's name in [`Scene::system`].
pub const ROD: &str = "rod";

impl Scene {
    /// The scene as two bodies and one contact (a pinned rod for a pivot): the general
    /// system that [`crate::impact`] answers, and that every route of [`crate::solve`] must
    /// agree with.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, scene::Scene};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?.system();
    /// assert_eq!((s.bodies.len(), s.contacts.len()), (2, 1));
    /// assert_eq!(s.bodies[1].inertia, q(1, 3));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn system(&self) -> System {
        let scene = self;
        let o = scene.oblique().cloned().unwrap_or_default();
        let rod_before = scene.rod_before();
        let a = scene.a().clone();
        let (centre, inertia, shape) = match &o.disc {
            Some(d) => (
                Vec2::new(-d.radius.clone(), a.clone()),
                scene.m() * &d.radius * &d.radius / Q::from_integer(2.into()),
                Some(Shape::Disc {
                    radius: d.radius.clone(),
                }),
            ),
            None => (Vec2::new(Q::zero(), a.clone()), Q::zero(), None),
        };
        let projectile = Body {
            name: PROJECTILE.into(),
            mobility: Mobility::Free,
            mass: scene.m().clone(),
            inertia,
            position: centre,
            velocity: Vec2::new(scene.v0().clone(), o.v0t.clone()),
            omega: o.disc.as_ref().map_or_else(Q::zero, |d| d.spin.clone()),
            shape,
        };
        let rod = Body {
            name: ROD.into(),
            mobility: match scene.support() {
                Support::Free => Mobility::Free,
                Support::Pivot(p) => Mobility::Pinned(Vec2::new(Q::zero(), p.clone())),
            },
            mass: scene.rod_mass().clone(),
            inertia: scene.inertia(),
            position: Vec2::zero(),
            velocity: Vec2::new(rod_before.v, rod_before.vt),
            omega: -rod_before.omega,
            shape: Some(Shape::Rod {
                length: scene.half_length() * Q::from_integer(2.into()),
                thickness: Q::zero(),
                axis: Vec2::new(Q::zero(), Q::from_integer(1.into())),
            }),
        };
        let contact = Contact {
            a: 0,
            b: 1,
            point: Vec2::new(Q::zero(), a),
            normal: Vec2::new(Q::from_integer((-1).into()), Q::zero()),
            e: scene.e().clone(),
            mu: o.mu,
        };
        System::new(None, vec![projectile, rod], vec![contact]).expect(
        "a valid scene is a valid system: the masses are positive and the projectile approaches",
    )
    }
}
