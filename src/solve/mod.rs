//! The paper's scenes answered, by fast routes, behind one front door.
//!
//! [`answer::Answer::of`] answers any scene the library accepts completely (oblique, moving
//! rod, disc, pivot: both impulses, the contact mode, mu*, the optimum). The scene is a special
//! case of the general model ([`crate::scene::Scene::system`]), and every route here is a fast
//! case of the general solver ([`crate::impact`]): each route's module says which call of the
//! core it must equal, and `tests/lib/fast_routes.rs` holds every route equal to it on random
//! scenes. The routes are in [`fast`]; [`with`] runs one of them by name:
//!
//! | route | module | number types | scenes | used by |
//! |---|---|---|---|---|
//! | [`Route::Linear`] | [`fast::linear`] | any [`Field`] | free and pivoted | claims, `check`, tables, contact, symbolic proofs |
//! | [`Route::ClosedForm`] | [`fast::closed_form`] | any [`Field`] | free and pivoted | `stability`'s exact reference, intervals, `batch --backend f64` |
//! | [`Route::FractionFree`] | [`fast::fraction_free`] | exact rationals ([`Q`]) only | free and pivoted | `solve`, `batch` |
//! | [`Route::Float`] | [`fast::float`] | `f64`, `f32` only | free rod only | `solve --backend`, `stability` |
//! | the fixed-width rows | [`fast::fixed_width`] | machine words, then [`Q`] | free and pivoted, batch cells | `batch` (exact and f64 rows of the paper's columns) |
//! | the oblique completion | [`fast::oblique`] | any [`Field`] | oblique, frictional, disc, moving rod | [`answer::Answer`] |
//!
//! [`with`] runs a paper [`Scene`] through a named route and returns a [`Solved`], or an
//! [`Unsupported`] saying why the route cannot take it in that number type (an oblique scene
//! is refused: its answer is [`answer::Answer`]'s). Every exact route gives the same reduced
//! rationals bit for bit (property tests in `tests/lib/solve_exact.rs` and
//! `tests/lib/fraction_free.rs`); the float routes are measured against them by
//! [`crate::stability`]. Symbolic scenes ([`Params`] over rational functions) go straight to
//! [`fast::linear::solve`]. [`Outcome`] completes velocities into energies and residuals;
//! [`optimum`] finds a* and the largest omega.

pub mod answer;
pub mod fast;
pub mod optimum;
mod outcome;
pub mod working;

pub use answer::{Answer, Impact};
pub use outcome::{Outcome, outcome};

use crate::field::{Field, Interval, Q};
use crate::scene::Motion;
use crate::scene::{Params, Scene};
use fast::float::FloatFormula;
use fast::{closed_form, fraction_free, linear};
use std::fmt;

/// A route to (v, V, omega): which code computes the answer.
///
/// # Examples
/// ```
/// use rodimpact::solve::{Route, fast::float::FloatFormula};
/// assert_eq!(Route::FractionFree.to_string(), "fraction-free");
/// assert_eq!(Route::Float(FloatFormula::Sq).to_string(), "float/sq");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Route {
    /// The impulse equations as a linear system, solved by elimination ([`fast::linear::solve`]):
    /// the reference route, over any field.
    Linear,
    /// The paper's closed forms generalised to e and to a pivot ([`fast::closed_form::closed_form`]),
    /// over any field; in floats this is the naive formula.
    ClosedForm,
    /// Integers over one common denominator, the laws checked as integer identities, one
    /// reduction per output ([`fast::fraction_free::solve`]): exact rationals only.
    FractionFree,
    /// A float formula evaluated from the exact inputs ([`FloatFormula::eval_scene`]): `f64` or `f32`,
    /// free rod only.
    Float(FloatFormula),
}

impl fmt::Display for Route {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Route::Linear => f.write_str("linear"),
            Route::ClosedForm => f.write_str("closed form"),
            Route::FractionFree => f.write_str("fraction-free"),
            Route::Float(formula) => write!(f, "float/{}", formula.name()),
        }
    }
}

/// Why a route cannot take a scene in a number type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Why {
    /// The route covers the free rod only (the float formulas), and the rod is on a pivot.
    FreeRodOnly,
    /// The route is exact (fraction-free) and computes in [`Q`] only.
    ExactOnly,
    /// The route is a float formula and computes in `f64` or `f32` only.
    FloatOnly,
    /// The system is singular in this number type: a float underflowed to zero (a valid scene
    /// is never singular over an exact field).
    Singular,
    /// The scene is oblique or frictional, or its rod moves before the impact: a route solves
    /// the paper's scene only; [`answer::Answer::of`] answers this one (or a route takes its
    /// normal problem, [`Scene::normal_problem`], asked for by name).
    Oblique,
}

impl fmt::Display for Why {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Why::FreeRodOnly => "it covers the free rod only, and this rod is on a pivot",
            Why::ExactOnly => "it is exact and computes in Q only",
            Why::FloatOnly => "it is a float formula and computes in f64 or f32 only",
            Why::Singular => {
                "the impulse equations are singular in this number type (an underflow)"
            }
            Why::Oblique => {
                "it solves the paper's scene, and this one is oblique, frictional or has a moving rod (answer it with solve::answer::Answer::of)"
            }
        })
    }
}

/// The error of [`with`]: this route cannot take this scene in this number type.
///
/// When it happens: a float formula asked for a pivoted rod ([`Why::FreeRodOnly`]), a route
/// asked for a number type it does not compute in ([`Why::ExactOnly`], [`Why::FloatOnly`]), or
/// a float system that underflowed to a singular one ([`Why::Singular`]). How to handle it:
/// take another route; [`Route::Linear`] takes every scene in every number type except where
/// a float underflows. Nothing is computed when the route or number type is refused up front.
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, solve::{self, fast::float::FloatFormula, Route, Why}};
/// let pivoted = Scene::builder(q(1, 1), q(3, 1)).pivot(q(0, 1)).build()?;
/// let err = solve::with::<f64>(&pivoted, Route::Float(FloatFormula::Sq)).unwrap_err();
/// assert_eq!(err.why, Why::FreeRodOnly);
/// assert_eq!(err.to_string(), "route float/sq cannot take this scene: it covers the free rod only, and this rod is on a pivot");
/// assert!(solve::with::<f64>(&pivoted, Route::Linear).is_ok());
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, thiserror::Error)]
#[error("route {route} cannot take this scene: {why}")]
pub struct Unsupported {
    /// The route that was asked for.
    pub route: Route,
    /// Why it cannot take the scene.
    pub why: Why,
}

/// What a route gives: the velocities after the impact and, where the route decides it,
/// whether the conservation laws that apply hold exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct Solved<F> {
    /// The route that computed it.
    pub route: Route,
    /// v, V, omega right after the impact.
    pub after: Motion<F>,
    /// `Some(true)` when every applicable law was checked and holds exactly (the linear route
    /// over an exact field, the fraction-free route); `None` when the route does not check
    /// them (closed form, floats): [`Solved::outcome`] computes the residuals then.
    pub laws_hold: Option<bool>,
}

/// A number type a [`Scene`] can be solved in: what [`Route::FractionFree`] and
/// [`Route::Float`] do in it (by default they refuse). [`Route::Linear`] and
/// [`Route::ClosedForm`] run in every [`Field`].
pub trait Solvable: Field {
    /// The fraction-free route in this type: exact rationals only.
    ///
    /// # Errors
    /// [`Why::ExactOnly`] for every type but [`Q`].
    fn fraction_free(_scene: &Scene) -> Result<(Motion<Self>, bool), Why> {
        Err(Why::ExactOnly)
    }

    /// A float formula in this type: `f64` and `f32` only.
    ///
    /// # Errors
    /// [`Why::FloatOnly`] for non-float types, [`Why::FreeRodOnly`] for a pivoted rod.
    fn float(_formula: FloatFormula, _scene: &Scene) -> Result<Motion<Self>, Why> {
        Err(Why::FloatOnly)
    }
}

impl Solvable for Q {
    fn fraction_free(scene: &Scene) -> Result<(Motion<Q>, bool), Why> {
        let solved = fraction_free::solve(scene);
        Ok((solved.after, solved.laws_hold))
    }
}

impl Solvable for f64 {
    fn float(formula: FloatFormula, scene: &Scene) -> Result<Motion<f64>, Why> {
        formula.eval_scene(scene).ok_or(Why::FreeRodOnly)
    }
}

impl Solvable for f32 {
    fn float(formula: FloatFormula, scene: &Scene) -> Result<Motion<f32>, Why> {
        formula.eval_scene(scene).ok_or(Why::FreeRodOnly)
    }
}

impl Solvable for Interval {}

/// The front door: solves `scene` in the number type `F` by the named `route`.
///
/// # Errors
/// [`Unsupported`] when the route cannot take the scene in `F` (see there).
///
/// # Examples
/// Every exact route gives the same reduced rationals:
/// ```
/// use rodimpact::{field::{q, Q}, scene::Scene, solve::{self, Route}};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build()?;
/// for route in [Route::Linear, Route::ClosedForm, Route::FractionFree] {
///     let out = solve::with::<Q>(&s, route)?;
///     assert_eq!((out.after.v, out.after.rod_v, out.after.omega), (q(3, 5), q(2, 5), q(6, 5)));
/// }
/// assert_eq!(solve::with::<Q>(&s, Route::FractionFree)?.laws_hold, Some(true));
/// assert!(solve::with::<f64>(&s, Route::FractionFree).is_err());
/// // An oblique scene is refused, never answered in part:
/// let oblique = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).rod_before(q(1, 1), q(0, 1), q(0, 1)).build()?;
/// assert_eq!(solve::with::<Q>(&oblique, Route::FractionFree).unwrap_err().why, solve::Why::Oblique);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn with<F: Solvable>(scene: &Scene, route: Route) -> Result<Solved<F>, Unsupported> {
    let refused = |why| Unsupported { route, why };
    if scene.oblique().is_some() {
        return Err(refused(Why::Oblique));
    }
    let (after, laws_hold) = match route {
        Route::Linear => {
            let out = linear::solve(&scene.params::<F>()).ok_or(refused(Why::Singular))?;
            let laws_hold = F::EXACT.then(|| out.residuals.all_zero());
            (out.after, laws_hold)
        }
        Route::ClosedForm => {
            let after = closed_form::closed_form(&scene.params::<F>());
            (after.ok_or(refused(Why::Singular))?, None)
        }
        Route::FractionFree => {
            let (after, laws_hold) = F::fraction_free(scene).map_err(refused)?;
            (after, Some(laws_hold))
        }
        Route::Float(formula) => (F::float(formula, scene).map_err(refused)?, None),
    };
    Ok(Solved {
        route,
        after,
        laws_hold,
    })
}

impl<F: Field> Solved<F> {
    /// Completes the answer into an [`Outcome`] for the scene's parameters `p`: pivot impulse,
    /// energies and residuals. Where the route proved the laws exactly (`laws_hold ==
    /// Some(true)`), their residuals are exactly zero and the energy after an elastic impact
    /// equals the energy before; nothing of it is recomputed.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::{q, Q}, scene::Scene, solve::{self, Route}};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).e(q(1, 2)).build()?;
    /// let p = s.params::<Q>();
    /// let fast = solve::with::<Q>(&s, Route::FractionFree)?.outcome(&p);
    /// assert_eq!(fast, solve::fast::linear::solve(&p).unwrap());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn outcome(self, p: &Params<F>) -> Outcome<F> {
        if self.laws_hold == Some(true) {
            outcome::proven(p, self.after)
        } else {
            outcome(p, self.after)
        }
    }
}
