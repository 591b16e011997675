//! Several frictionless contacts at once, under each named model, exactly.
//!
//! With `u = u0 + W lam` the normal relative velocities after normal impulses `lam` (W, the
//! Delassus matrix, symmetric and positive semidefinite; `u0^- = min(u0, 0)`):
//!
//! - **simultaneous-newton**: `lam >= 0`, `w = u0 + W lam + e u0^- >= 0`, `lam . w = 0` (an
//!   approaching contact that pushes leaves at `-e u0`; a touching one at 0 or more);
//! - **simultaneous-poisson** (Pfeiffer and Glocker): compression `lam_c >= 0`,
//!   `u_c = u0 + W lam_c >= 0`, `lam_c . u_c = 0`; expansion `lam_e = e lam_c + x`, `x >= 0`,
//!   `u = u_c + W lam_e >= 0`, `x . u = 0`; `lam = lam_c + lam_e`;
//! - **sequential** in an order: passes over the contacts in that order, each approaching
//!   contact (`u_i < 0`) taking the single-contact Newton impulse `-(1 + e_i) u_i / W_ii`, until a
//!   pass fires nothing; every order, or one given;
//! - **pgs:K**: K sweeps of projected Gauss-Seidel from zero impulses, in the contacts' order,
//!   `lam_i <- max(0, lam_i - (u_i + e_i u0_i^-)/W_ii)`, as engines run it.
//!
//! The linear complementarity problems are solved exactly: up to [`MAX_ENUMERATED`] contacts by
//! enumerating the active sets (every subset of the contacts; solutions with the same
//! velocities are one), beyond by Lemke's method with lexicographic pivoting (`lemke.rs`), up
//! to [`MAX_CONTACTS`](crate::model::MAX_CONTACTS) contacts. W is positive semidefinite, so the velocities after are
//! the same for every solution: a model has one answer or none (the impulses may be split
//! otherwise where W is singular).

//!
//! | file | what it does |
//! |---|---|
//! | `mod.rs` | the models, their answers and ledgers, [`solve_several`] |
//! | `common.rs` | the contacts in a field (rows, W's blocks), the answer from the impulses |
//! | `frictionless.rs` | every model without friction |
//! | `friction.rs` | the simultaneous models with Coulomb friction, every mode tried |
//! | `lemke.rs` | Lemke's method for the LCPs of many contacts, exact, lexicographic |

mod common;
mod friction;
mod frictionless;
mod iterative;

pub use iterative::MAX_ENGINE_STEPS;
mod lemke;

use crate::field::Field;
use crate::impact::engines::{Engine, Profile};
use crate::impact::law::Law;
use crate::impact::ledger::EnergyLedger;
use crate::impact::work::Stopped;
use crate::mechanics::planar::Vec2;
use crate::model::System;
use std::cmp::Ordering;
use std::fmt;

/// The most contacts whose active sets the simultaneous models enumerate (2^n of them);
/// beyond, Lemke's method solves them.
pub const MAX_ENUMERATED: usize = 8;
/// The most impacts a sequential model runs before it is reported as not stopping.
pub const MAX_SEQUENTIAL_IMPACTS: usize = 1_000;
/// The most sweeps `pgs:K` runs.
pub const MAX_SWEEPS: u32 = 10_000;
/// The most contacts whose every order the sequential model runs (n! orders).
pub const MAX_ORDERED: usize = 6;

/// How several simultaneous contacts act together.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Model {
    /// The simultaneous Newton law (a linear complementarity problem).
    SimultaneousNewton,
    /// The simultaneous Poisson law (compression, then expansion).
    SimultaneousPoisson,
    /// Single-contact impacts one at a time, in this order of the contacts (0-based), in passes
    /// until one fires nothing.
    Sequential(Vec<usize>),
    /// K sweeps of projected Gauss-Seidel from zero impulses (a normal row, then a friction
    /// row, at each contact).
    Pgs(u32),
    /// Friction without restitution (the simultaneous Newton law with every e = 0), then
    /// restitution without friction (a normal-only LCP that ends at `-e u0_n` or more).
    Split,
    /// An engine's step, replayed exactly ([`crate::impact::Engine::replayed`]), or the law its
    /// iterations converge to.
    Engine(Profile),
}

impl Model {
    /// One model by name, for `n` contacts: `simultaneous-newton` (or `lcp-newton`, the same
    /// law), `simultaneous-poisson` (or `lcp-poisson`), `split`, `sequential:2,1,3` (an order of
    /// the contacts, 1-based), `pgs:K`, or an engine's profile (`pymunk-7`, `box2d-2.3:scale=16`,
    /// ...: [`Profile::parse`]).
    ///
    /// # Errors
    /// What is wrong with the name, in words.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Model;
    /// assert_eq!(Model::parse("sequential:2,1", 2), Ok(Model::Sequential(vec![1, 0])));
    /// assert_eq!(Model::parse("pgs:3", 2), Ok(Model::Pgs(3)));
    /// assert!(Model::parse("sequential:1,1", 2).is_err());
    /// assert_eq!(Model::parse("lcp-newton", 2), Ok(Model::SimultaneousNewton));
    /// ```
    pub fn parse(text: &str, n: usize) -> Result<Model, String> {
        let text = text.trim();
        match text {
            "simultaneous-newton" | "lcp-newton" => return Ok(Model::SimultaneousNewton),
            "simultaneous-poisson" | "lcp-poisson" => return Ok(Model::SimultaneousPoisson),
            "split" => return Ok(Model::Split),
            _ => {}
        }
        if Engine::ALL
            .iter()
            .any(|e| text.split(':').next() == Some(e.name()))
        {
            return Profile::parse(text).map(Model::Engine);
        }
        if let Some(order) = text.strip_prefix("sequential:") {
            let parsed: Option<Vec<usize>> = order
                .split(',')
                .map(|k| {
                    k.trim()
                        .parse::<usize>()
                        .ok()
                        .filter(|k| (1..=n).contains(k))
                        .map(|k| k - 1)
                })
                .collect();
            let order = parsed.ok_or_else(|| {
                format!(
                    "sequential:ORDER lists contacts 1 to {n}, got '{}'",
                    crate::echo::echo(order)
                )
            })?;
            let mut sorted = order.clone();
            sorted.sort_unstable();
            if sorted != (0..n).collect::<Vec<_>>() {
                return Err(format!(
                    "sequential:ORDER names each of the {n} contacts once"
                ));
            }
            return Ok(Model::Sequential(order));
        }
        if let Some(k) = text.strip_prefix("pgs:") {
            return k
                .trim()
                .parse::<u32>()
                .ok()
                .filter(|k| (1..=MAX_SWEEPS).contains(k))
                .map(Model::Pgs)
                .ok_or_else(|| format!("pgs:K takes K from 1 to {MAX_SWEEPS}"));
        }
        Err(format!(
            "expected simultaneous-newton, simultaneous-poisson, split, sequential:ORDER, pgs:K or an engine ({}), got '{}'",
            Engine::ALL.map(Engine::name).join(", "),
            crate::echo::echo(text)
        ))
    }

    /// The model of several contacts that is `law` for one: the simultaneous Newton law is
    /// lcp-newton, the simultaneous Poisson law lcp-poisson; `None` for the laws that follow
    /// Routh's path.
    pub fn of_law(law: Law) -> Option<Model> {
        match law {
            Law::LcpNewton => Some(Model::SimultaneousNewton),
            Law::LcpPoisson => Some(Model::SimultaneousPoisson),
            Law::Split => Some(Model::Split),
            Law::Newton | Law::Poisson | Law::Energetic => None,
        }
    }
}

impl Model {
    /// How many of `models`, answered together, share this one's work limit
    /// ([`solve_several_sharing`]): the sequential orders share one limit among them; every
    /// other model has a limit of its own.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::{Model, orders};
    /// let mut models: Vec<Model> = orders(3).into_iter().map(Model::Sequential).collect();
    /// models.push(Model::Pgs(10));
    /// assert_eq!(models[0].share_among(&models), 6);
    /// assert_eq!(Model::Pgs(10).share_among(&models), 1);
    /// ```
    pub fn share_among(&self, models: &[Model]) -> u64 {
        match self {
            Model::Sequential(_) => models
                .iter()
                .filter(|m| matches!(m, Model::Sequential(_)))
                .count()
                .max(1) as u64,
            _ => 1,
        }
    }

    /// Why this model gives no answer on `system` when it is [`ModelOutcome::DoesNotStop`]:
    /// the cap it reached, which is not a proof that it never stops.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::{Model, Profile};
    /// use rodimpact::model::parse_toml;
    /// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
    /// let system = parse_toml("cradle-3", &text)?;
    /// let pymunk = Model::Engine(Profile::parse("pymunk-7").unwrap());
    /// assert!(pymunk.why_it_does_not_stop(&system).starts_with("a contact still approaches after 60 of pymunk-7's steps"));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn why_it_does_not_stop(&self, system: &System) -> String {
        match self {
            Model::Engine(profile) => format!(
                "a contact still approaches after {MAX_ENGINE_STEPS} of {profile}'s steps (the cap, \
                 not a proof that the steps never stop)"
            ),
            _ => {
                let plastic = system
                    .contacts
                    .iter()
                    .all(|c| num_traits::Zero::is_zero(&c.e));
                format!(
                    "the impacts do not stop within {} (the cap, not a proof that they never stop{})",
                    crate::field::count::grouped(MAX_SEQUENTIAL_IMPACTS as u64),
                    if plastic {
                        ": plastic contacts pass the impulse back and forth, converging"
                    } else {
                        ""
                    }
                )
            }
        }
    }
}

impl fmt::Display for Model {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Model::SimultaneousNewton => f.write_str("simultaneous-newton"),
            Model::SimultaneousPoisson => f.write_str("simultaneous-poisson"),
            Model::Sequential(order) => {
                let order: Vec<String> = order.iter().map(|i| (i + 1).to_string()).collect();
                write!(f, "sequential:{}", order.join(","))
            }
            Model::Pgs(k) => write!(f, "pgs:{k}"),
            Model::Split => f.write_str("split"),
            Model::Engine(profile) => write!(f, "{profile}"),
        }
    }
}

/// What a model says of a system.
#[derive(Debug, Clone, PartialEq)]
pub enum ModelOutcome<F> {
    /// The answers: one, or several (a simultaneous model with more than one solution).
    Answered(Vec<ModelAnswer<F>>),
    /// No impulses satisfy the model.
    NoSolution,
    /// A sequential model still firing after [`MAX_SEQUENTIAL_IMPACTS`] impacts, or an
    /// engine's steps after [`MAX_ENGINE_STEPS`].
    DoesNotStop,
    /// The model is frictionless here (sequential impacts), and the scene has friction.
    FrictionlessOnly,
    /// The exact work passed its limit, or the host interrupted it ([`Stopped`]).
    Stopped(Stopped),
}

/// Total momentum, angular momentum about the origin and kinetic energy of the moving bodies,
/// before and after, and the normal velocity after at every contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Ledger<F> {
    /// Linear momentum before.
    pub momentum_before: Vec2<F>,
    /// ... after.
    pub momentum_after: Vec2<F>,
    /// Angular momentum about the origin, counterclockwise, before.
    pub angular_before: F,
    /// ... after.
    pub angular_after: F,
    /// Kinetic energy before and after (its gain decided exactly over an exact field).
    pub energy: EnergyLedger<F>,
    /// The normal relative velocity after at every contact (negative: the model lets the
    /// bodies sink into each other there).
    pub normal_after: Vec<F>,
}

impl<F: Field> Ledger<F> {
    /// The contacts (0-based) whose bodies sink into each other after the impact.
    pub fn sinking(&self) -> Vec<usize> {
        (0..self.normal_after.len())
            .filter(|&i| self.normal_after[i].sign() == Some(Ordering::Less))
            .collect()
    }
}

/// One answer of a model.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelAnswer<F> {
    /// The model.
    pub model: Model,
    /// The normal impulse coefficient at each contact (P_i = lam_i n_i + tau_i t_i on A).
    pub impulses: Vec<F>,
    /// The tangential impulse coefficient at each contact (zero without friction).
    pub tangential: Vec<F>,
    /// The impulses are one split of several that give the same velocities (W singular:
    /// friction at contacts sticking along one line, or normal impulses shared among contacts
    /// on one rigid body); false only where no other impulses give these velocities.
    pub split_indeterminate: bool,
    /// Every moving body after: (index, velocity, spin).
    pub bodies: Vec<(usize, Vec2<F>, F)>,
    /// What the model conserves and what it does not.
    pub ledger: Ledger<F>,
    /// The single-contact impacts a sequential model fired, in order: (contact, impulse).
    pub impacts: Vec<(usize, F)>,
    /// The model's stages, each the (normal, tangential) impulses it adds at every contact:
    /// compression and expansion for the simultaneous Poisson law, friction then restitution
    /// for split, one stage otherwise.
    pub stages: Vec<(Vec<F>, Vec<F>)>,
}

/// Answers the system's contacts under `model`.
///
/// # Examples
/// Newton's cradle of three equal balls struck at 1: the simultaneous Newton answer keeps the
/// energy and momentum, yet the first ball rebounds (-1/3) and the other two leave together
/// (2/3); sequential impacts leave only the last ball moving.
/// ```
/// use rodimpact::{field::{q, Q}, model::parse_toml};
/// use rodimpact::impact::{Model, ModelOutcome, solve_several};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
/// let system = parse_toml("cradle-3", &text)?;
/// let ModelOutcome::Answered(answers) = solve_several::<Q>(&system, &Model::SimultaneousNewton) else { panic!() };
/// let v: Vec<Q> = answers[0].bodies.iter().map(|(_, v, _)| v.x.clone()).collect();
/// assert_eq!(v, [q(-1, 3), q(2, 3), q(2, 3)]);
/// assert_eq!(answers[0].ledger.energy.change, q(0, 1));
/// let ModelOutcome::Answered(seq) = solve_several::<Q>(&system, &Model::Sequential(vec![0, 1])) else { panic!() };
/// assert_eq!(seq[0].bodies[2].1.x, q(1, 1));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_several<F: Field>(system: &System, model: &Model) -> ModelOutcome<F> {
    solve_several_sharing(system, model, 1)
}

/// [`solve_several`] for one of `share` models answered together (every sequential order of
/// a scene): its work stops at a `share`-th of its limit ([`crate::impact::Work`]), so that
/// together they stay within one.
///
/// # Examples
/// ```
/// use rodimpact::{field::Q, model::parse_toml};
/// use rodimpact::impact::{Model, ModelOutcome, solve_several_sharing};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml"))?;
/// let system = parse_toml("cradle", &text)?;
/// let outcome = solve_several_sharing::<Q>(&system, &Model::Sequential(vec![0, 1]), 2);
/// assert!(matches!(outcome, ModelOutcome::Answered(_)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_several_sharing<F: Field>(
    system: &System,
    model: &Model,
    share: u64,
) -> ModelOutcome<F> {
    solve_model(system, model, share).unwrap_or_else(ModelOutcome::Stopped)
}

/// [`solve_several_sharing`], the work's stop as an error.
fn solve_model<F: Field>(
    system: &System,
    model: &Model,
    share: u64,
) -> Result<ModelOutcome<F>, Stopped> {
    let contacts = common::Contacts::<F>::of(system);
    let w = contacts.delassus();
    let u0 = contacts.before(0);
    let iterated = |(lam_n, lam_t): (Vec<F>, Vec<F>)| {
        ModelOutcome::Answered(vec![common::finish(
            system,
            &contacts,
            model.clone(),
            (lam_n, lam_t, false),
            Vec::new(),
        )])
    };
    let blocks = || iterative::Blocks::of(&contacts, &w);
    let ut0 = || contacts.before(1);
    match model {
        Model::Pgs(sweeps) => {
            return Ok(iterated(iterative::pgs(
                &contacts,
                &blocks(),
                (&u0, &ut0()),
                *sweeps,
                share,
            )?));
        }
        Model::Engine(profile) => {
            let (w_blocks, ut0) = (blocks(), ut0());
            let u = (&u0[..], &ut0[..]);
            return Ok(match profile.engine {
                Engine::Pymunk7 => {
                    let iterations = profile.engine.iterations();
                    match iterative::pymunk(system, &contacts, &w_blocks, u, iterations)? {
                        Some(impulses) => iterated(impulses),
                        None => ModelOutcome::DoesNotStop,
                    }
                }
                Engine::Box2d23 => {
                    iterated(iterative::box2d(system, &contacts, &w_blocks, u, profile)?)
                }
                Engine::Bullet3 => {
                    iterated(iterative::bullet(system, &contacts, &w_blocks, u, profile)?)
                }
                Engine::Box2d3 | Engine::Rapier036 => {
                    // The law the soft substeps converge to, without restitution where a
                    // contact approaches below the threshold (Box2D v3's b2ApplyRestitution).
                    let converged = Model::of_law(profile.engine.law()).expect("an engine's law");
                    let slow = iterative::below_threshold(system, &u0, profile);
                    let outcome = if slow.contains(&true) {
                        let mut quiet = system.clone();
                        for (contact, slow) in quiet.contacts.iter_mut().zip(slow) {
                            if slow {
                                contact.e = num_traits::Zero::zero();
                            }
                        }
                        solve_model(&quiet, &converged, share)?
                    } else {
                        solve_model(system, &converged, share)?
                    };
                    relabel(outcome, model)
                }
            });
        }
        _ => {}
    }
    if system
        .contacts
        .iter()
        .any(|c| c.mu.sign() == Some(Ordering::Greater))
    {
        friction::with_friction(system, &contacts, &w, &u0, model)
    } else {
        frictionless::frictionless(system, &contacts, &w, &u0, model, share)
    }
}

/// `outcome`'s answers under the name of `model`.
fn relabel<F>(outcome: ModelOutcome<F>, model: &Model) -> ModelOutcome<F> {
    match outcome {
        ModelOutcome::Answered(answers) => ModelOutcome::Answered(
            answers
                .into_iter()
                .map(|a| ModelAnswer {
                    model: model.clone(),
                    ..a
                })
                .collect(),
        ),
        other => other,
    }
}

/// Every order of the contacts `0..n` (n! of them, n at most [`MAX_ORDERED`]), in
/// lexicographic order.
///
/// # Examples
/// ```
/// use rodimpact::impact::orders;
/// assert_eq!(orders(3).len(), 6);
/// assert_eq!(orders(2), [vec![0, 1], vec![1, 0]]);
/// ```
pub fn orders(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![Vec::new()];
    }
    let mut out = Vec::new();
    for first in 0..n {
        for rest in orders(n - 1) {
            let mut order = vec![first];
            order.extend(rest.into_iter().map(|i| if i >= first { i + 1 } else { i }));
            out.push(order);
        }
    }
    out
}
