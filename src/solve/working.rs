//! The working of one scene, as `solve --explain` and the handout write it out: the paper's
//! normal problem (for an oblique scene, the projectile's normal speed meeting a rod at rest),
//! its answer and its optimum, and the step along the rod of an oblique scene.

use super::Outcome;
use super::fast::{linear, oblique};
use super::optimum::{Optimum, optimum};
use crate::field::Q;
use crate::scene::Scene;

/// Everything the working of a scene writes out, solved.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, solve::working::Working};
/// let w = Working::of(&Scene::builder(q(1, 1), q(1, 1)).build()?);
/// assert_eq!(w.outcome.after.omega, q(6, 5));
/// assert_eq!(w.optimum.squared, q(2, 3));
/// assert!(w.oblique.is_none());
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Working {
    /// The scene as given.
    pub scene: Scene,
    /// Its normal problem: the scene itself, or an oblique scene's normal speed meeting a rod
    /// at rest.
    pub normal: Scene,
    /// The normal problem's answer.
    pub outcome: Outcome<Q>,
    /// The normal problem's optimum: a* (or d* from a pivot) and the largest omega.
    pub optimum: Optimum,
    /// An oblique scene's completion along the rod.
    pub oblique: Option<oblique::ObliqueOutcome<Q>>,
}

impl Working {
    /// The working of `scene`.
    pub fn of(scene: &Scene) -> Working {
        let normal = match scene.oblique() {
            Some(_) => scene.normal_problem(),
            None => scene.clone(),
        };
        let outcome = linear::solve(&normal.params::<Q>()).expect("a valid scene is nonsingular");
        let optimum = optimum(&normal).expect("the normal problem's rod is at rest before it");
        let oblique = scene.oblique().map(|o| {
            oblique::solve(&scene.params::<Q>(), &o.params::<Q>(), None)
                .expect("Q decides stick or slide, and a valid scene is nonsingular")
        });
        Working {
            scene: scene.clone(),
            normal,
            outcome,
            optimum,
            oblique,
        }
    }
}
