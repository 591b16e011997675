//! Planar rigid bodies and their contacts as data: the model of `rodimpact impact`.
//!
//! A [`System`] holds bodies (mass, inertia about the centre of mass, position, velocity and
//! spin; free, pinned at a point, or fixed), optional [`Shape`]s that give the inertia and
//! check that each contact point lies on its body, and contacts (two bodies, a point, a normal
//! that need not be a unit vector, e, mu). Everything stays in Q: no unit vectors, no angles.
//!
//! | file | what it holds |
//! |---|---|
//! | `shape.rs` | [`Shape`]: point, disc, rod (with an optional thickness), box, convex polygon |
//! | `system.rs` | [`Body`], [`Contact`], [`System`] and their validation |
//! | `input.rs` | a system as written: a TOML scene file or one JSON line of a batch |

mod budget;
mod input;
mod shape;
mod system;

pub use budget::MAX_SCENE_DIGITS;
pub use input::{MAX_SCENE_BYTES, MAX_VERTICES, from_value, parse_toml, toml_value};
pub use shape::Shape;
pub use system::{
    Body, Contact, MAX_BODIES, MAX_CONTACTS, MAX_FRICTIONAL_CONTACTS, Mobility, System,
};
