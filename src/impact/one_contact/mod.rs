//! One contact's impact under Newton's, Poisson's and Stronge's energetic restitution laws,
//! with Coulomb friction followed through the impact (the slip may stop, stick or reverse),
//! over any field with square roots (exact Q(sqrt d), or floats).
//!
//! [`solve_contact`] answers a [`System`] with one contact under one [`Law`] in any field with
//! square roots ([`solve_exact`]: exactly, in Q or Q(sqrt d)): every moving body's velocity and
//! spin after, the impulse, the phases of the slip, the contact velocity before and after, the
//! energy before and after with its change decided exactly, the pins' impulses, and the
//! balance laws checked exactly. The paper's scenes are special cases (`Scene::system`): when
//! W is diagonal, as in all of them, the three laws coincide.
//!
//! | file | what it does |
//! |---|---|
//! | `mod.rs` | the answer: the contact's rows and W, the path's end, the bodies after, the checks |
//! | `path.rs` | Routh's construction: the path in the normal impulse and each law's end |

mod path;

pub use path::{Jam, Roots};

use super::coulomb::{Mode, cone_excess};
use super::engines::Profile;
use super::jacobian::{ContactMatrix, coordinate_changes, velocities_before};
use super::law::{Ends, Law};
use super::ledger::{Balance, Balances, EnergyLedger};
use super::multi_contact::{Model, ModelOutcome, solve_several};
use super::planar::PlanarSystem;
use super::work::Stopped;
use crate::field::{Field, Q, QSqrt};
use crate::mechanics::planar::{PlanarBody, Vec2, angular_momentum, kinetic_energy};
use crate::model::{Mobility, System};
use path::{Segment, compression_end, end, friction_work, normal_work, path, segment_at, staged};
use std::cmp::Ordering;

/// A phase of the impact as reported: its mode between two values of the normal impulse.
#[derive(Debug, Clone, PartialEq)]
pub struct Phase<F> {
    /// What friction does.
    pub mode: Mode,
    /// lam at its start.
    pub from: F,
    /// lam at its end.
    pub to: F,
}

/// A moving body after the impact.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyAfter<F> {
    /// The body's index in the system.
    pub index: usize,
    /// The velocity of its centre of mass.
    pub velocity: Vec2<F>,
    /// Its angular velocity (counterclockwise).
    pub omega: F,
    /// The impulse of its pin on it, for a pinned body.
    pub pin_impulse: Option<Vec2<F>>,
}

/// One contact's impact answered under one law.
#[derive(Debug, Clone, PartialEq)]
pub struct LawAnswer<F> {
    /// The law (an engine's: the law its iterations converge to).
    pub law: Law,
    /// The engine whose step this is, for an engine's answer.
    pub engine: Option<Profile>,
    /// Every moving body after the impact, in the system's order.
    pub bodies: Vec<BodyAfter<F>>,
    /// The impulse P on body A, in the world frame.
    pub impulse: Vec2<F>,
    /// Its coefficients, P = lam n + tau t.
    pub lam: F,
    /// The tangential coefficient.
    pub tau: F,
    /// The end of compression.
    pub lam_c: F,
    /// The phases up to the end.
    pub phases: Vec<Phase<F>>,
    /// The contact matrix W the impact was solved with.
    pub matrix: ContactMatrix<F>,
    /// The relative velocity at the contact (A's point minus B's), along n and t, before.
    pub contact_before: [F; 2],
    /// ... and after.
    pub contact_after: [F; 2],
    /// The normal work in compression and in restitution, and the friction's work.
    pub work: [F; 3],
    /// Kinetic energy before and after (its gain decided exactly over an exact field).
    pub energy: EnergyLedger<F>,
    /// The balance laws, checked: momentum, angular momentum, the total angular momentum
    /// (without fixed or pinned bodies), the restitution law, Coulomb's law and the energy
    /// against the work.
    pub balances: Balances<F>,
}

/// Why a system cannot be answered.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ImpactError {
    /// This solver takes one contact; the system has more.
    #[error(
        "{0} contacts: this solves one contact (several are answered by the simultaneous models)"
    )]
    SeveralContacts(usize),
    /// The impact has no end under a law.
    #[error("{0}")]
    Jam(Jam),
    /// An engine's law or step gives no answer (no solution, or steps that do not stop).
    #[error("{0}: {1}")]
    Unanswered(String, String),
    /// The exact work passed its limit, or the host interrupted it.
    #[error("{0}: {1}")]
    Stopped(String, Stopped),
}

impl ImpactError {
    /// Why there is no answer, without the law's or engine's name the message starts with
    /// (a report that names it already).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::ImpactError;
    /// let e = ImpactError::Unanswered("pymunk-7".into(), "its steps do not stop".into());
    /// assert_eq!((e.to_string().as_str(), e.why().as_str()), ("pymunk-7: its steps do not stop", "its steps do not stop"));
    /// ```
    pub fn why(&self) -> String {
        match self {
            ImpactError::Unanswered(_, why) => why.clone(),
            ImpactError::Stopped(_, stopped) => stopped.to_string(),
            ImpactError::SeveralContacts(_) | ImpactError::Jam(_) => self.to_string(),
        }
    }
}

/// The system's one contact in a field: the bodies' coordinates and the contact's rows, W and
/// the relative velocity (u_n, u_t) before.
struct OneContact<F> {
    planar: PlanarSystem<F>,
    w: ContactMatrix<F>,
    u0: [F; 2],
}

impl<F: Field> OneContact<F> {
    fn of(system: &System) -> Result<OneContact<F>, ImpactError> {
        if system.contacts.len() != 1 {
            return Err(ImpactError::SeveralContacts(system.contacts.len()));
        }
        let planar = PlanarSystem::<F>::of(system);
        let rows = &planar.rows[0];
        let w = ContactMatrix::of(rows, &planar.coordinates);
        let before = velocities_before(&planar.coordinates);
        let u0 = [
            rows.normal.velocity(&before),
            rows.tangent.velocity(&before),
        ];
        Ok(OneContact { planar, w, u0 })
    }
}

/// The contact matrix W and the relative velocity (u_n, u_t) before the impact of the system's
/// first contact, in the field `F`.
///
/// # Examples
/// The paper's end hit, m = M = 1, l = 1: W_nn = 1/m + 1/M + a^2/I = 5, no coupling.
/// ```
/// use rodimpact::{field::{q, Q}, scene::Scene, impact::contact_matrix};
/// let (w, u0) = contact_matrix::<Q>(&Scene::builder(q(1, 1), q(1, 1)).build()?.system());
/// assert_eq!((w.nn, w.nt, w.tt), (q(5, 1), q(0, 1), q(2, 1)));
/// assert_eq!(u0, [q(-1, 1), q(0, 1)]);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn contact_matrix<F: Field>(system: &System) -> (ContactMatrix<F>, [F; 2]) {
    let first = System {
        contacts: system.contacts[..1].to_vec(),
        ..system.clone()
    };
    let one = OneContact::<F>::of(&first).expect("one contact");
    (one.w, one.u0)
}

/// Answers the system's one contact under `law`, in the field `F` (exact: [`QSqrt`]).
///
/// # Errors
/// [`ImpactError::SeveralContacts`], or [`ImpactError::Jam`] when the law never ends the
/// impact (or a sign is undecided in `F`).
///
/// # Examples
/// The paper's scene as bodies, struck at a = 1/2 (m = M = 1, l = 1, e = 1): v = 3/11,
/// V = 8/11, and the rod turns clockwise at 12/11 (the paper's omega).
/// ```
/// use rodimpact::{field::{q, QSqrt}, scene::Scene};
/// use rodimpact::impact::{solve_contact, Law};
/// let system = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?.system();
/// let answer = solve_contact::<QSqrt>(&system, Law::Newton).expect("answered");
/// let (projectile, rod) = (&answer.bodies[0], &answer.bodies[1]);
/// assert_eq!(projectile.velocity.x, QSqrt::rational(q(3, 11)));
/// assert_eq!((rod.velocity.x.clone(), rod.omega.clone()), (QSqrt::rational(q(8, 11)), QSqrt::rational(q(-12, 11))));
/// assert!(answer.balances.all_zero() && !answer.energy.gain());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_contact<F: Roots>(system: &System, law: Law) -> Result<LawAnswer<F>, ImpactError> {
    solve_one(system, law, None)
}

/// Answers the system's one contact as `profile`'s engine does: one step of its solver replayed
/// exactly ([`crate::impact::Engine::replayed`]), or the law its substeps converge to. The
/// answer's `law` is the engine's converged law, against which its balances are checked (a step
/// of a few iterations need not reach it).
///
/// # Errors
/// Those of [`solve_contact`], or [`ImpactError::Unanswered`] when the engine's steps do not
/// stop.
///
/// # Examples
/// pymunk's 10 iterations on the tilted rod: 6e-3 from lcp-newton's exact answer, and gaining
/// energy as it does.
/// ```
/// use rodimpact::{field::Q, model::parse_toml};
/// use rodimpact::impact::{Engine, Profile, solve_engine};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/tilted-rod-rough-floor.toml")).unwrap();
/// let step = solve_engine::<Q>(&parse_toml("tilted", &text)?, &Profile::of(Engine::Pymunk7))?;
/// assert!(step.energy.gain());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn solve_engine<F: Roots>(
    system: &System,
    profile: &Profile,
) -> Result<LawAnswer<F>, ImpactError> {
    solve_one(system, profile.engine.law(), Some(profile))
}

/// The one contact under `law`, or as `engine` computes it.
fn solve_one<F: Roots>(
    system: &System,
    law: Law,
    engine: Option<&Profile>,
) -> Result<LawAnswer<F>, ImpactError> {
    let one = OneContact::<F>::of(system)?;
    let c = &system.contacts[0];
    let (e, mu) = (F::from_rational(&c.e), F::from_rational(&c.mu));
    let staged_model = match engine {
        Some(profile) => Some(Model::Engine(profile.clone())),
        None => Model::of_law(law),
    };
    let (segments, lam_c, lam) = match staged_model {
        Some(model) => {
            let stages = stages_of::<F>(system, &model)?;
            let segments =
                staged(&one.w, one.u0.clone(), &mu, &stages).map_err(ImpactError::Jam)?;
            let lam_c = compression_end(&segments).map_err(ImpactError::Jam)?;
            let lam = stages
                .iter()
                .fold(F::zero(), |acc, (d_lam, _, _)| acc + d_lam);
            (segments, lam_c, lam)
        }
        None => {
            let segments = path(&one.w, one.u0.clone(), &mu).map_err(ImpactError::Jam)?;
            let lam_c = compression_end(&segments).map_err(ImpactError::Jam)?;
            let lam = end(&segments, &lam_c, &one.u0[0], &e, law).map_err(ImpactError::Jam)?;
            (segments, lam_c, lam)
        }
    };
    let [_, _, tau] = segment_at(&segments, &lam).at(&lam);
    let planar = &one.planar;
    let (normal, tangent) = (&planar.normals[0], planar.normals[0].perp());
    let impulse = normal.scale(&lam).add(&tangent.scale(&tau));
    let changes = coordinate_changes(
        &planar.coordinates,
        &planar.rows,
        &[[lam.clone(), tau.clone()]],
    );
    let after: Vec<PlanarBody<F>> = (0..planar.coordinates.len())
        .map(|slot| planar.body_after(slot, &changes[slot]))
        .collect();
    let bodies = bodies_after(system, planar, &after, &impulse);
    let energy = EnergyLedger::new(kinetic_energy(&planar.before), kinetic_energy(&after));
    let relative = planar.relative_velocity(0, c, &after);
    let contact_after = [relative.dot(normal), relative.dot(&tangent)];
    let work = [
        normal_work(&segments, &F::zero(), &lam_c),
        normal_work(&segments, &lam_c, &lam),
        friction_work(&segments, &lam),
    ];
    let ends = Ends {
        u_n_before: one.u0[0].clone(),
        u_n_after: contact_after[0].clone(),
        lam_c: lam_c.clone(),
        lam: lam.clone(),
        work_compression: work[0].clone(),
        work_restitution: work[1].clone(),
    };
    let mut balances = body_balances(system, planar, &after, &impulse);
    balances.push(Balance::Restitution, law.residual(&e, &ends));
    balances.push(Balance::Coulomb, cone_excess(&mu, &lam, &tau));
    balances.push(
        Balance::EnergyEqualsWork,
        energy.change.clone() - &work[0] - &work[1] - &work[2],
    );
    Ok(LawAnswer {
        law,
        engine: engine.cloned(),
        energy,
        phases: phases(&segments, &lam),
        bodies,
        impulse,
        lam,
        tau,
        lam_c,
        matrix: one.w,
        contact_before: one.u0,
        contact_after,
        work,
        balances,
    })
}

/// The stages of `model` at the system's one contact: the (normal, tangential) impulse each
/// adds, and whether Coulomb's law acts in it (not in split's restitution stage).
fn stages_of<F: Field>(system: &System, model: &Model) -> Result<Vec<(F, F, bool)>, ImpactError> {
    let unanswered = |why: &str| ImpactError::Unanswered(model.to_string(), why.to_owned());
    match solve_several::<F>(system, model) {
        ModelOutcome::Answered(answers) => {
            let answer = answers.into_iter().next().expect("an answer");
            let restitution_alone = match model {
                Model::Split => true,
                Model::Engine(p) => !p.engine.replayed() && p.engine.law() == Law::Split,
                _ => false,
            };
            Ok(answer
                .stages
                .into_iter()
                .enumerate()
                .map(|(k, (normal, tangential))| {
                    let (n, t) = (normal[0].clone(), tangential[0].clone());
                    (n, t, !(restitution_alone && k == 1))
                })
                .collect())
        }
        ModelOutcome::NoSolution => Err(unanswered("no impulses satisfy it")),
        ModelOutcome::DoesNotStop => Err(unanswered(&model.why_it_does_not_stop(system))),
        ModelOutcome::FrictionlessOnly => Err(unanswered("it takes no friction")),
        ModelOutcome::Stopped(stopped) => Err(ImpactError::Stopped(model.to_string(), stopped)),
    }
}

/// Every moving body after the impact, with its pin's impulse (its momentum change less the
/// contact's impulse on it).
fn bodies_after<F: Field>(
    system: &System,
    planar: &PlanarSystem<F>,
    after: &[PlanarBody<F>],
    impulse: &Vec2<F>,
) -> Vec<BodyAfter<F>> {
    let c = &system.contacts[0];
    planar
        .coordinates
        .iter()
        .enumerate()
        .map(|(slot, coords)| {
            let (before, now) = (&planar.before[slot], &after[slot]);
            let pin_impulse = planar.pin(slot).map(|_| {
                let push = push_on(coords.body, c, impulse);
                now.velocity
                    .sub(&before.velocity)
                    .scale(&before.mass)
                    .sub(&push)
            });
            BodyAfter {
                index: coords.body,
                velocity: now.velocity.clone(),
                omega: now.omega.clone(),
                pin_impulse,
            }
        })
        .collect()
}

/// The push on body `index` (P on A, -P on B, nothing on others).
fn push_on<F: Field>(index: usize, c: &crate::model::Contact, impulse: &Vec2<F>) -> Vec2<F> {
    if index == c.a {
        impulse.clone()
    } else if index == c.b {
        impulse.scale(&-F::one())
    } else {
        Vec2::zero()
    }
}

/// The bodies' balances, checked with the planar laws (not with the rows that solved them):
/// each free body's momentum changed by its push (m dv = +-P); each body's angular momentum,
/// about its centre (free) or its pin (pinned), changed by the push's moment, the pinned point
/// kept at rest; and the total angular momentum about the contact point unchanged when no body
/// is fixed or pinned.
fn body_balances<F: Field>(
    system: &System,
    planar: &PlanarSystem<F>,
    after: &[PlanarBody<F>],
    impulse: &Vec2<F>,
) -> Balances<F> {
    let c = &system.contacts[0];
    let point = &planar.points[0];
    let mut balances = Balances::new();
    for (slot, coords) in planar.coordinates.iter().enumerate() {
        let (before, now) = (&planar.before[slot], &after[slot]);
        let push = push_on(coords.body, c, impulse);
        if planar.pin(slot).is_none() {
            let residual = now
                .velocity
                .sub(&before.velocity)
                .scale(&before.mass)
                .sub(&push);
            balances.push(Balance::Momentum, residual.x);
            balances.push(Balance::Momentum, residual.y);
        }
    }
    for (slot, coords) in planar.coordinates.iter().enumerate() {
        let (before, now) = (&planar.before[slot], &after[slot]);
        let push = push_on(coords.body, c, impulse);
        match planar.pin(slot) {
            Some(pin) => {
                let moment = point.sub(pin).cross(&push);
                let change = angular_momentum(std::slice::from_ref(now), pin)
                    - &angular_momentum(std::slice::from_ref(before), pin);
                let still = now.point_velocity(pin);
                balances.push(Balance::AngularMomentum, change - &moment);
                balances.push(Balance::AngularMomentum, still.x);
                balances.push(Balance::AngularMomentum, still.y);
            }
            None => {
                let moment = point.sub(&before.centre).cross(&push);
                let change = (now.omega.clone() - &before.omega) * &before.inertia;
                balances.push(Balance::AngularMomentum, change - &moment);
            }
        }
    }
    if system.bodies.iter().all(|b| b.mobility == Mobility::Free) {
        balances.push(
            Balance::TotalAngularMomentum,
            angular_momentum(after, point) - &angular_momentum(&planar.before, point),
        );
    }
    balances
}

/// A point of Routh's path: the contact's relative velocity and the tangential impulse at one
/// value of the normal impulse, and what friction does from there on.
#[derive(Debug, Clone, PartialEq)]
pub struct PathPoint<F> {
    /// The normal impulse lam.
    pub lam: F,
    /// The relative velocity at the contact (A's point minus B's), along n and t.
    pub u: [F; 2],
    /// The tangential impulse tau.
    pub tau: F,
    /// The phase that starts here (at the last point: the phase it ends).
    pub mode: Mode,
}

/// Routh's path of the system's one contact from lam = 0 to lam = `upto`: the start, each
/// phase change before `upto`, and `upto` itself. The contact velocity and tau are linear in
/// lam between two points, and the path is the same under every law (a law only chooses where
/// it ends: [`LawAnswer::lam`]).
///
/// # Errors
/// [`ImpactError::SeveralContacts`], or [`ImpactError::Jam`] when the path is undecided.
///
/// # Examples
/// The tilted rod on a rough floor: it slides backward (u_t < 0) until lam = 75/181, then
/// forward; Newton's law ends at lam = 725/724.
/// ```
/// use rodimpact::{field::{q, Q}, model::parse_toml};
/// use rodimpact::impact::{contact_path, Mode};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/tilted-rod-rough-floor.toml")).unwrap();
/// let path = contact_path::<Q>(&parse_toml("tilted", &text)?, &q(725, 724))?;
/// let lams: Vec<Q> = path.iter().map(|p| p.lam.clone()).collect();
/// assert_eq!(lams, [q(0, 1), q(75, 181), q(725, 724)]);
/// assert_eq!(path[1].u[1], q(0, 1));
/// assert_eq!((path[0].mode, path[1].mode), (Mode::Slide { forward: false }, Mode::Slide { forward: true }));
/// assert_eq!(path[2].u[0], q(1, 1)); // Newton's end: u_n after = -e u_n before
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn contact_path<F: Roots>(system: &System, upto: &F) -> Result<Vec<PathPoint<F>>, ImpactError> {
    let one = OneContact::<F>::of(system)?;
    let mu = F::from_rational(&system.contacts[0].mu);
    let segments = path(&one.w, one.u0, &mu).map_err(ImpactError::Jam)?;
    let point = |segment: &Segment<F>, lam: &F| {
        let [u_n, u_t, tau] = segment.at(lam);
        PathPoint {
            lam: lam.clone(),
            u: [u_n, u_t],
            tau,
            mode: segment.mode,
        }
    };
    let mut points: Vec<PathPoint<F>> = segments
        .iter()
        .take_while(|s| (s.from.clone() - upto).sign() == Some(Ordering::Less) || s.from.is_zero())
        .map(|s| point(s, &s.from))
        .collect();
    if points.last().map(|p| &p.lam) != Some(upto) {
        points.push(point(segment_at(&segments, upto), upto));
    }
    Ok(points)
}

/// Answers the system's one contact under `law` exactly: in Q where the answer is rational
/// (always under Newton's and Poisson's laws), about three times faster, and in Q(sqrt d)
/// where the energetic law's end is a surd; the answer is the same either way.
///
/// # Errors
/// Those of [`solve_contact`].
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, QSqrt}, scene::Scene};
/// use rodimpact::impact::{solve_contact, solve_exact, Law};
/// let system = Scene::builder(q(1, 1), q(2, 1)).a(q(1, 3)).e(q(1, 2)).build()?.system();
/// for law in Law::ALL {
///     assert_eq!(solve_exact(&system, law), solve_contact::<QSqrt>(&system, law));
/// }
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_exact(system: &System, law: Law) -> Result<LawAnswer<QSqrt>, ImpactError> {
    match solve_contact::<Q>(system, law) {
        Ok(rational) => Ok(rational.lift()),
        Err(ImpactError::Jam(Jam::Restitution(Law::Energetic))) => {
            solve_contact::<QSqrt>(system, law)
        }
        Err(other) => Err(other),
    }
}

/// [`solve_engine`] exactly: an engine's step and the laws engines converge to are rational.
///
/// # Errors
/// Those of [`solve_engine`].
pub fn solve_engine_exact(
    system: &System,
    profile: &Profile,
) -> Result<LawAnswer<QSqrt>, ImpactError> {
    solve_engine::<Q>(system, profile).map(LawAnswer::lift)
}

impl LawAnswer<Q> {
    /// The same answer in Q(sqrt d).
    fn lift(self) -> LawAnswer<QSqrt> {
        let x = &mut |q: Q| QSqrt::rational(q);
        let v = |p: Vec2<Q>| Vec2::new(QSqrt::rational(p.x), QSqrt::rational(p.y));
        LawAnswer {
            law: self.law,
            engine: self.engine,
            bodies: self
                .bodies
                .into_iter()
                .map(|b| BodyAfter {
                    index: b.index,
                    velocity: v(b.velocity),
                    omega: x(b.omega),
                    pin_impulse: b.pin_impulse.map(v),
                })
                .collect(),
            impulse: v(self.impulse),
            lam: x(self.lam),
            tau: x(self.tau),
            lam_c: x(self.lam_c),
            phases: self
                .phases
                .into_iter()
                .map(|p| Phase {
                    mode: p.mode,
                    from: x(p.from),
                    to: x(p.to),
                })
                .collect(),
            matrix: ContactMatrix {
                nn: x(self.matrix.nn),
                nt: x(self.matrix.nt),
                tt: x(self.matrix.tt),
            },
            contact_before: self.contact_before.map(&mut *x),
            contact_after: self.contact_after.map(&mut *x),
            work: self.work.map(&mut *x),
            energy: self.energy.map(x),
            balances: self.balances.map(x),
        }
    }
}

/// The phases cut at the end of the impact.
fn phases<F: Field>(segments: &[Segment<F>], lam: &F) -> Vec<Phase<F>> {
    let mut out = Vec::new();
    for s in segments {
        if (s.from.clone() - lam).sign() == Some(Ordering::Greater)
            || (!out.is_empty() && (s.from.clone() - lam).is_zero())
        {
            break;
        }
        let to = match &s.to {
            Some(to) if (to.clone() - lam).sign() == Some(Ordering::Less) => to.clone(),
            _ => lam.clone(),
        };
        out.push(Phase {
            mode: s.mode,
            from: s.from.clone(),
            to,
        });
    }
    out
}
