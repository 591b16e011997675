//! Shapes of planar bodies: what gives a body its moment of inertia, and where its boundary
//! is, so that a contact point can be checked to lie on it. Everything in Q: a direction is a
//! vector that need not be a unit vector (no square roots), so every check is a rational
//! comparison.

use crate::field::Q;
use crate::mechanics::planar::Vec2;
use num_traits::{Signed, Zero};

/// The shape of a body at the impact instant, placed in the world (its centre of mass is the
/// body's `position`; a rod's or a box's long side runs along `axis`).
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A point mass (inertia 0).
    Point,
    /// A solid disc of this radius (I = m r^2/2).
    Disc {
        /// The radius (> 0).
        radius: Q,
    },
    /// A uniform rod of this length along `axis`, with an optional thickness across it (a thin
    /// rod: thickness 0; I = m (L^2 + h^2)/12).
    Rod {
        /// The length L (> 0).
        length: Q,
        /// The thickness h (>= 0).
        thickness: Q,
        /// The direction of the length (not normalised).
        axis: Vec2<Q>,
    },
    /// A uniform box (rectangle) `width` along `axis` and `height` across it
    /// (I = m (w^2 + h^2)/12).
    Box {
        /// The side along `axis` (> 0).
        width: Q,
        /// The side across `axis` (> 0).
        height: Q,
        /// The direction of the width (not normalised).
        axis: Vec2<Q>,
    },
    /// A uniform convex polygon with these vertices (world coordinates at the impact, in order
    /// around it); its centroid must be the body's position.
    Polygon {
        /// The vertices, at least three, counterclockwise or clockwise.
        vertices: Vec<Vec2<Q>>,
    },
}

impl Shape {
    /// The moment of inertia about the centre of mass of a uniform body of `mass` with this
    /// shape (a polygon's about `centre`, its centroid).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, model::Shape, mechanics::planar::Vec2};
    /// let rod = Shape::Rod { length: q(2, 1), thickness: q(0, 1), axis: Vec2::new(q(3, 1), q(4, 1)) };
    /// assert_eq!(rod.inertia(&q(1, 1), &Vec2::zero()), q(1, 3)); // m L^2/12
    /// let square = Shape::Polygon { vertices: vec![
    ///     Vec2::new(q(-1, 1), q(-1, 1)), Vec2::new(q(1, 1), q(-1, 1)),
    ///     Vec2::new(q(1, 1), q(1, 1)), Vec2::new(q(-1, 1), q(1, 1))] };
    /// assert_eq!(square.inertia(&q(3, 1), &Vec2::zero()), q(2, 1)); // m (w^2 + h^2)/12
    /// ```
    pub fn inertia(&self, mass: &Q, centre: &Vec2<Q>) -> Q {
        let twelfth = |a: &Q, b: &Q| mass * (a * a + b * b) / Q::from_integer(12.into());
        match self {
            Shape::Point => Q::zero(),
            Shape::Disc { radius } => mass * radius * radius / Q::from_integer(2.into()),
            Shape::Rod {
                length, thickness, ..
            } => twelfth(length, thickness),
            Shape::Box { width, height, .. } => twelfth(width, height),
            Shape::Polygon { vertices } => polygon_inertia(vertices, mass, centre),
        }
    }

    /// Whether `point` lies on the shape's boundary when its centre of mass is at `centre` (a
    /// point mass: at its centre; a thin rod: on the segment).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, model::Shape, mechanics::planar::Vec2};
    /// let rod = Shape::Rod { length: q(2, 1), thickness: q(0, 1), axis: Vec2::new(q(3, 1), q(4, 1)) };
    /// let centre = Vec2::new(q(0, 1), q(4, 5));
    /// assert!(rod.on_boundary(&Vec2::new(q(-3, 5), q(0, 1)), &centre)); // its lower end
    /// assert!(!rod.on_boundary(&Vec2::new(q(-1, 1), q(0, 1)), &centre));
    /// let disc = Shape::Disc { radius: q(5, 1) };
    /// assert!(disc.on_boundary(&Vec2::new(q(3, 1), q(4, 1)), &Vec2::zero()));
    /// ```
    pub fn on_boundary(&self, point: &Vec2<Q>, centre: &Vec2<Q>) -> bool {
        let d = point.sub(centre);
        match self {
            Shape::Point => d.x.is_zero() && d.y.is_zero(),
            Shape::Disc { radius } => d.dot(&d) == radius * radius,
            Shape::Rod {
                length,
                thickness,
                axis,
            } => on_rectangle(&d, axis, length, thickness),
            Shape::Box {
                width,
                height,
                axis,
            } => on_rectangle(&d, axis, width, height),
            Shape::Polygon { vertices } => (0..vertices.len()).any(|i| {
                let (a, b) = (&vertices[i], &vertices[(i + 1) % vertices.len()]);
                on_segment(point, a, b)
            }),
        }
    }

    /// The centroid of a polygon's area (`None` for the other shapes, centred on the body).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, model::Shape, mechanics::planar::Vec2};
    /// let triangle = Shape::Polygon { vertices: vec![
    ///     Vec2::new(q(0, 1), q(0, 1)), Vec2::new(q(3, 1), q(0, 1)), Vec2::new(q(0, 1), q(3, 1))] };
    /// assert_eq!(triangle.centroid(), Some(Vec2::new(q(1, 1), q(1, 1))));
    /// ```
    pub fn centroid(&self) -> Option<Vec2<Q>> {
        let Shape::Polygon { vertices } = self else {
            return None;
        };
        let (mut area2, mut cx, mut cy) = (Q::zero(), Q::zero(), Q::zero());
        for i in 0..vertices.len() {
            let (a, b) = (&vertices[i], &vertices[(i + 1) % vertices.len()]);
            let cross = a.cross(b);
            cx += (&a.x + &b.x) * &cross;
            cy += (&a.y + &b.y) * &cross;
            area2 += cross;
        }
        let six_area = area2 * Q::from_integer(3.into());
        Some(Vec2::new(cx / &six_area, cy / &six_area))
    }
}

/// Twice the signed area of a polygon.
pub(super) fn twice_area(vertices: &[Vec2<Q>]) -> Q {
    (0..vertices.len()).fold(Q::zero(), |total, i| {
        total + vertices[i].cross(&vertices[(i + 1) % vertices.len()])
    })
}

/// Whether the polygon is convex and not degenerate: every turn the same way, area not zero.
pub(super) fn is_convex(vertices: &[Vec2<Q>]) -> bool {
    let n = vertices.len();
    let turns: Vec<Q> = (0..n)
        .map(|i| {
            let (a, b, c) = (&vertices[i], &vertices[(i + 1) % n], &vertices[(i + 2) % n]);
            b.sub(a).cross(&c.sub(b))
        })
        .collect();
    !twice_area(vertices).is_zero()
        && (turns.iter().all(|t| !t.is_negative()) || turns.iter().all(|t| !t.is_positive()))
}

/// The moment of inertia of a uniform polygon of `mass` about `centre` (its centroid).
fn polygon_inertia(vertices: &[Vec2<Q>], mass: &Q, centre: &Vec2<Q>) -> Q {
    // About the centroid: shift the vertices so the centroid is the origin, then
    // J = sum cross_i (a.a + a.b + b.b) / 12 over the edges, per unit density, and
    // I = mass J / area.
    let shifted: Vec<Vec2<Q>> = vertices.iter().map(|v| v.sub(centre)).collect();
    let mut j = Q::zero();
    for i in 0..shifted.len() {
        let (a, b) = (&shifted[i], &shifted[(i + 1) % shifted.len()]);
        let cross = a.cross(b);
        j += cross * (a.dot(a) + a.dot(b) + b.dot(b));
    }
    let area2 = twice_area(&shifted);
    // J/12 over the area (area2/2): mass J / (6 area2).
    mass * j / (area2 * Q::from_integer(6.into()))
}

/// Whether `d` (from the centre) lies on the boundary of the rectangle `long` along `axis` and
/// `across` across it; a rectangle of zero width across is the segment itself.
fn on_rectangle(d: &Vec2<Q>, axis: &Vec2<Q>, long: &Q, across: &Q) -> bool {
    // With A = |axis|^2: the coordinate along is x = d.axis / |axis|, across y = axis x d / |axis|;
    // |x| <= long/2 iff (d.axis)^2 <= long^2 A/4, and so on, all without square roots.
    let a = axis.dot(axis);
    let along = d.dot(axis);
    let side = axis.cross(d);
    let four = Q::from_integer(4.into());
    let half_long = long * long * &a / &four;
    let half_across = across * across * &a / &four;
    let (x2, y2) = (&along * &along, &side * &side);
    if across.is_zero() {
        return side.is_zero() && x2 <= half_long;
    }
    x2 <= half_long && y2 <= half_across && (x2 == half_long || y2 == half_across)
}

/// Whether `p` lies on the segment from `a` to `b`.
fn on_segment(p: &Vec2<Q>, a: &Vec2<Q>, b: &Vec2<Q>) -> bool {
    let (ab, ap) = (b.sub(a), p.sub(a));
    ab.cross(&ap).is_zero() && !ap.dot(&ab).is_negative() && ap.dot(&ab) <= ab.dot(&ab)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    fn v(x: i64, y: i64) -> Vec2<Q> {
        Vec2::new(q(x, 1), q(y, 1))
    }

    #[test]
    fn a_box_corner_is_on_it_and_its_centre_is_not() {
        let b = Shape::Box {
            width: q(2, 1),
            height: q(1, 1),
            axis: v(1, 0),
        };
        let c = Vec2::new(q(0, 1), q(1, 2));
        assert!(b.on_boundary(&v(-1, 0), &c));
        assert!(b.on_boundary(&Vec2::new(q(1, 3), q(0, 1)), &c)); // on the bottom face
        assert!(!b.on_boundary(&c, &c));
        assert!(!b.on_boundary(&v(2, 0), &c));
        assert_eq!(b.inertia(&q(1, 1), &c), q(5, 12));
    }

    #[test]
    fn a_triangle_about_its_centroid() {
        // Right triangle with legs 3: I about the centroid = m (a^2 + b^2)/18 = m.
        let t = Shape::Polygon {
            vertices: vec![v(0, 0), v(3, 0), v(0, 3)],
        };
        let c = t.centroid().unwrap();
        assert_eq!(t.inertia(&q(1, 1), &c), q(1, 1));
        assert!(t.on_boundary(&Vec2::new(q(3, 2), q(3, 2)), &c));
        assert!(is_convex(&[v(0, 0), v(3, 0), v(0, 3)]));
        assert!(!is_convex(&[v(0, 0), v(2, 0), v(1, 1), v(2, 2), v(0, 2)]));
    }
}
