//! Any planar impact with one contact, under Newton's, Poisson's and Stronge's energetic
//! restitution laws, with Coulomb friction followed through the impact (the slip may stop,
//! stick or reverse), over any field with square roots (exact Q(sqrt d), or floats).
//!
//! [`solve_contact`] answers a [`System`] with one contact under one [`Law`] in any field
//! with square roots ([`solve_exact`]: exactly, in Q or Q(sqrt d)): every moving
//! body's velocity and spin after, the impulse, the phases of the slip, the contact velocity
//! before and after, the energy before and after with its change decided exactly
//! (`energy_gain`), the pins' impulses, and the balance laws checked exactly. The paper's
//! scenes are special cases (`model::paper_system`): when W is diagonal, as in all of them, the
//! three laws coincide.
//!
//! | file | what it does |
//! |---|---|
//! | `matrix.rs` | each body's response to an impulse, the contact matrix W |
//! | `routh.rs` | the path in the normal impulse (Routh's construction) and each law's end |
//! | `several.rs` | several frictionless contacts under each model: simultaneous Newton and Poisson (exact LCPs), sequential, projected Gauss-Seidel |
//! | `lemke.rs` | Lemke's method for the LCPs of many contacts, exact, lexicographic |
//! | `friction.rs` | several frictional contacts under the simultaneous models, every mode tried |

mod friction;
mod lemke;
mod matrix;
mod routh;
mod several;

pub use matrix::ContactMatrix;
pub use routh::{Jam, Law, Mode, Roots};
pub use several::{
    Ledger, MAX_ENUMERATED, MAX_ORDERED, MAX_SEQUENTIAL_IMPACTS, MAX_SWEEPS, Model, ModelAnswer,
    ModelOutcome, orders,
};

use crate::field::{Field, Q, QSqrt};
use crate::mechanics::planar::{PlanarBody, Vec2, angular_momentum, kinetic_energy};
use crate::model::{Mobility, System};
use matrix::Lifted;
use routh::{Segment, compression_end, end, friction_work, normal_work, path, segment_at};
use std::cmp::Ordering;

/// Answers the system's contacts under `model`.
///
/// # Examples
/// Newton's cradle of three equal balls struck at 1: the simultaneous Newton answer keeps the
/// energy and momentum, yet the first ball rebounds (-1/3) and the other two leave together
/// (2/3); sequential impacts leave only the last ball moving.
/// ```
/// use rodimpact::{field::{q, Q}, model::parse_toml};
/// use rodimpact::solve::impact::{Model, ModelOutcome, solve_several};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
/// let system = parse_toml("cradle-3", &text)?;
/// let ModelOutcome::Answered(answers) = solve_several::<Q>(&system, &Model::SimultaneousNewton) else { panic!() };
/// let v: Vec<Q> = answers[0].bodies.iter().map(|(_, v, _)| v.x.clone()).collect();
/// assert_eq!(v, [q(-1, 3), q(2, 3), q(2, 3)]);
/// assert_eq!(answers[0].ledger.energy_change, q(0, 1));
/// let ModelOutcome::Answered(seq) = solve_several::<Q>(&system, &Model::Sequential(vec![0, 1])) else { panic!() };
/// assert_eq!(seq[0].bodies[2].1.x, q(1, 1));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_several<F: Field>(system: &System, model: &Model) -> ModelOutcome<F> {
    let contacts: several::Contacts<F> = several::Contacts::of(system);
    let w = contacts.delassus();
    let u0 = several::normal_before(system, &contacts);
    if system
        .contacts
        .iter()
        .any(|c| c.mu.sign() == Some(Ordering::Greater))
    {
        friction::with_friction(system, &contacts, &w, &u0, model)
    } else {
        several::frictionless(system, &contacts, &w, &u0, model)
    }
}

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

/// Which balance laws hold exactly (in a float field: within rounding is not decided, and
/// every entry says whether the residual is exactly zero).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LawsHold {
    /// Every free body's momentum changed by the impulse on it (m dv = +-P).
    pub momentum: bool,
    /// Every body's angular momentum, about its centre (free) or its pin (pinned), changed by
    /// the moment of the impulse.
    pub angular_momentum: bool,
    /// The total angular momentum about the contact point is unchanged when no body is fixed
    /// or pinned (`None` otherwise: the ground or a pin takes an impulse).
    pub total_angular_momentum: Option<bool>,
    /// The law itself: newton u_n after = -e u_n before; poisson lam_f = (1 + e) lam_c;
    /// energetic, the restitution work -e^2 times the compression work.
    pub restitution: bool,
    /// Coulomb's law at the end: |tau| <= mu lam (tau = 0 without friction).
    pub coulomb: bool,
    /// The energy change equals the work of the contact impulse: the normal work plus the
    /// friction's, integrated along the path.
    pub energy: bool,
}

impl LawsHold {
    /// Every entry holds.
    pub fn all(&self) -> bool {
        self.momentum
            && self.angular_momentum
            && self.total_angular_momentum != Some(false)
            && self.restitution
            && self.coulomb
            && self.energy
    }
}

/// Kinetic energy before and after, and the change (after - before).
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyChange<F> {
    /// Before the impact.
    pub before: F,
    /// After the impact.
    pub after: F,
    /// after - before: positive when the law creates energy.
    pub change: F,
}

/// One contact's impact answered under one law.
#[derive(Debug, Clone, PartialEq)]
pub struct LawAnswer<F> {
    /// The law.
    pub law: Law,
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
    /// The relative velocity at the contact (A's point minus B's), along n and t, before.
    pub contact_before: [F; 2],
    /// ... and after.
    pub contact_after: [F; 2],
    /// The normal work in compression and in restitution, and the friction's work.
    pub work: [F; 3],
    /// Kinetic energy.
    pub energy: EnergyChange<F>,
    /// The law creates kinetic energy (decided exactly over an exact field).
    pub energy_gain: bool,
    /// The balance laws, checked.
    pub laws_hold: LawsHold,
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
}

/// The contact matrix W and the relative velocity (u_n, u_t) before the impact of the system's
/// first contact, in the field `F`.
///
/// # Examples
/// The paper's end hit, m = M = 1, l = 1: W_nn = 1/m + 1/M + a^2/I = 5, no coupling.
/// ```
/// use rodimpact::{field::{q, Q}, model::paper_system, scene::Scene, solve::impact::contact_matrix};
/// let (w, u0) = contact_matrix::<Q>(&paper_system(&Scene::builder(q(1, 1), q(1, 1)).build()?));
/// assert_eq!((w.nn, w.nt, w.tt), (q(5, 1), q(0, 1), q(2, 1)));
/// assert_eq!(u0, [q(-1, 1), q(0, 1)]);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn contact_matrix<F: Field>(system: &System) -> (ContactMatrix<F>, [F; 2]) {
    let c = &system.contacts[0];
    let lifted: Lifted<F> = Lifted::of(system, c);
    let rel = system.relative_velocity(c);
    let rel = Vec2::new(F::from_rational(&rel.x), F::from_rational(&rel.y));
    (
        lifted.matrix(),
        [rel.dot(&lifted.normal), rel.dot(&lifted.tangent)],
    )
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
/// use rodimpact::{field::{q, QSqrt}, model::paper_system, scene::Scene};
/// use rodimpact::solve::impact::{solve_contact, Law};
/// let system = paper_system(&Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?);
/// let answer = solve_contact::<QSqrt>(&system, Law::Newton).expect("answered");
/// let (projectile, rod) = (&answer.bodies[0], &answer.bodies[1]);
/// assert_eq!(projectile.velocity.x, QSqrt::rational(q(3, 11)));
/// assert_eq!((rod.velocity.x.clone(), rod.omega.clone()), (QSqrt::rational(q(8, 11)), QSqrt::rational(q(-12, 11))));
/// assert!(answer.laws_hold.all() && !answer.energy_gain);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solve_contact<F: Roots>(system: &System, law: Law) -> Result<LawAnswer<F>, ImpactError> {
    if system.contacts.len() != 1 {
        return Err(ImpactError::SeveralContacts(system.contacts.len()));
    }
    let c = &system.contacts[0];
    let lifted: Lifted<F> = Lifted::of(system, c);
    let (w, u0) = contact_matrix::<F>(system);
    let segments = path(&w, u0.clone(), &lifted.mu).map_err(ImpactError::Jam)?;
    let lam_c = compression_end(&segments).map_err(ImpactError::Jam)?;
    let lam = end(&segments, &lam_c, &u0[0], &lifted.e, law).map_err(ImpactError::Jam)?;
    let [_, _, tau] = segment_at(&segments, &lam).at(&lam);
    let impulse = lifted.normal.scale(&lam).add(&lifted.tangent.scale(&tau));
    let bodies = after(system, c.a, c.b, &lifted, &impulse);
    let before: Vec<PlanarBody<F>> = moving(system).map(|i| lift_body(system, i)).collect();
    let after_bodies: Vec<PlanarBody<F>> = moving(system)
        .zip(&bodies)
        .map(|(i, b)| PlanarBody {
            velocity: b.velocity.clone(),
            omega: b.omega.clone(),
            ..lift_body(system, i)
        })
        .collect();
    let energy_before = kinetic_energy(&before);
    let energy_after = kinetic_energy(&after_bodies);
    let change = energy_after.clone() - &energy_before;
    let contact_after = relative_after(system, &lifted, &bodies);
    let work = [
        normal_work(&segments, &F::zero(), &lam_c),
        normal_work(&segments, &lam_c, &lam),
        friction_work(&segments, &lam),
    ];
    let laws_hold = LawsHold {
        momentum: bodies
            .iter()
            .all(|b| momentum_holds(system, b, c, &lifted, &impulse)),
        angular_momentum: bodies
            .iter()
            .all(|b| spin_holds(system, b, c, &lifted, &impulse)),
        total_angular_momentum: system
            .bodies
            .iter()
            .all(|b| b.mobility == Mobility::Free)
            .then(|| {
                (angular_momentum(&after_bodies, &lifted.point)
                    - &angular_momentum(&before, &lifted.point))
                    .is_zero()
            }),
        restitution: match law {
            Law::Newton => (contact_after[0].clone() + &(lifted.e.clone() * &u0[0])).is_zero(),
            Law::Poisson => (lam.clone() - &((F::one() + &lifted.e) * &lam_c)).is_zero(),
            Law::Energetic => {
                (work[1].clone() + &(lifted.e.clone() * &lifted.e * &work[0])).is_zero()
            }
        },
        coulomb: {
            let bound = lifted.mu.clone() * &lam;
            (bound.clone() - &tau).sign() != Some(Ordering::Less)
                && (bound + &tau).sign() != Some(Ordering::Less)
        },
        energy: (change.clone() - &work[0] - &work[1] - &work[2]).is_zero(),
    };
    Ok(LawAnswer {
        law,
        energy_gain: change.sign() == Some(Ordering::Greater),
        energy: EnergyChange {
            before: energy_before,
            after: energy_after,
            change,
        },
        phases: phases(&segments, &lam),
        bodies,
        impulse,
        lam,
        tau,
        lam_c,
        contact_before: u0,
        contact_after,
        work,
        laws_hold,
    })
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
/// use rodimpact::solve::impact::{contact_path, Mode};
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
    if system.contacts.len() != 1 {
        return Err(ImpactError::SeveralContacts(system.contacts.len()));
    }
    let lifted: Lifted<F> = Lifted::of(system, &system.contacts[0]);
    let (w, u0) = contact_matrix::<F>(system);
    let segments = path(&w, u0, &lifted.mu).map_err(ImpactError::Jam)?;
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
/// use rodimpact::{field::{q, QSqrt}, model::paper_system, scene::Scene};
/// use rodimpact::solve::impact::{solve_contact, solve_exact, Law};
/// let system = paper_system(&Scene::builder(q(1, 1), q(2, 1)).a(q(1, 3)).e(q(1, 2)).build()?);
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

impl LawAnswer<Q> {
    /// The same answer in Q(sqrt d).
    fn lift(self) -> LawAnswer<QSqrt> {
        let x = |q: Q| QSqrt::rational(q);
        let v = |p: Vec2<Q>| Vec2::new(x(p.x), x(p.y));
        LawAnswer {
            law: self.law,
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
            contact_before: self.contact_before.map(x),
            contact_after: self.contact_after.map(x),
            work: self.work.map(x),
            energy: EnergyChange {
                before: x(self.energy.before),
                after: x(self.energy.after),
                change: x(self.energy.change),
            },
            energy_gain: self.energy_gain,
            laws_hold: self.laws_hold,
        }
    }
}

/// The indices of the moving bodies.
fn moving(system: &System) -> impl Iterator<Item = usize> + '_ {
    (0..system.bodies.len()).filter(|&i| system.bodies[i].moves())
}

/// Body `i` before the impact, lifted.
fn lift_body<F: Field>(system: &System, i: usize) -> PlanarBody<F> {
    let b = system.bodies[i].planar();
    let v = |x: &Vec2<crate::field::Q>| Vec2::new(F::from_rational(&x.x), F::from_rational(&x.y));
    PlanarBody {
        mass: F::from_rational(&b.mass),
        inertia: F::from_rational(&b.inertia),
        centre: v(&b.centre),
        velocity: v(&b.velocity),
        omega: F::from_rational(&b.omega),
    }
}

/// Every moving body after the impulse `impulse` on A (-impulse on B) at the contact.
fn after<F: Field>(
    system: &System,
    a: usize,
    b: usize,
    lifted: &Lifted<F>,
    impulse: &Vec2<F>,
) -> Vec<BodyAfter<F>> {
    moving(system)
        .map(|i| {
            let before = lift_body::<F>(system, i);
            let (response, push) = if i == a {
                (lifted.a.as_ref(), impulse.clone())
            } else if i == b {
                (lifted.b.as_ref(), impulse.scale(&-F::one()))
            } else {
                (None, Vec2::zero())
            };
            let (dv, dw) = match response {
                Some(r) => (
                    r.centre_change(&before.centre, &lifted.point, &push),
                    r.spin_change(&lifted.point, &push),
                ),
                None => (Vec2::zero(), F::zero()),
            };
            let velocity = before.velocity.add(&dv);
            let pin_impulse = matches!(system.bodies[i].mobility, Mobility::Pinned(_))
                .then(|| dv.scale(&before.mass).sub(&push));
            BodyAfter {
                index: i,
                velocity,
                omega: before.omega.clone() + &dw,
                pin_impulse,
            }
        })
        .collect()
}

/// (u_n, u_t) after, from the bodies' velocities after (not from the path).
fn relative_after<F: Field>(
    system: &System,
    lifted: &Lifted<F>,
    bodies: &[BodyAfter<F>],
) -> [F; 2] {
    let c = &system.contacts[0];
    let point_velocity = |index: usize| -> Vec2<F> {
        match bodies.iter().find(|b| b.index == index) {
            Some(b) => PlanarBody {
                velocity: b.velocity.clone(),
                omega: b.omega.clone(),
                ..lift_body(system, index)
            }
            .point_velocity(&lifted.point),
            None => Vec2::zero(),
        }
    };
    let rel = point_velocity(c.a).sub(&point_velocity(c.b));
    [rel.dot(&lifted.normal), rel.dot(&lifted.tangent)]
}

/// The push on body `b` (P on A, -P on B, nothing on others).
fn push_on<F: Field>(b: &BodyAfter<F>, c: &crate::model::Contact, impulse: &Vec2<F>) -> Vec2<F> {
    if b.index == c.a {
        impulse.clone()
    } else if b.index == c.b {
        impulse.scale(&-F::one())
    } else {
        Vec2::zero()
    }
}

/// m dv = the push (plus the pin's impulse, which is reported as exactly that difference: a
/// pinned body's check is its angular momentum about the pin).
fn momentum_holds<F: Field>(
    system: &System,
    b: &BodyAfter<F>,
    c: &crate::model::Contact,
    _lifted: &Lifted<F>,
    impulse: &Vec2<F>,
) -> bool {
    if b.pin_impulse.is_some() {
        return true;
    }
    let before = lift_body::<F>(system, b.index);
    let dp = b.velocity.sub(&before.velocity).scale(&before.mass);
    let residual = dp.sub(&push_on(b, c, impulse));
    residual.x.is_zero() && residual.y.is_zero()
}

/// The angular momentum about the centre (free) or the pin (pinned) changes by the moment of
/// the push; a pinned body also keeps its pinned point at rest.
fn spin_holds<F: Field>(
    system: &System,
    b: &BodyAfter<F>,
    c: &crate::model::Contact,
    lifted: &Lifted<F>,
    impulse: &Vec2<F>,
) -> bool {
    let before = lift_body::<F>(system, b.index);
    let push = push_on(b, c, impulse);
    match &system.bodies[b.index].mobility {
        Mobility::Pinned(pin) => {
            let pin = Vec2::new(F::from_rational(&pin.x), F::from_rational(&pin.y));
            let after = PlanarBody {
                velocity: b.velocity.clone(),
                omega: b.omega.clone(),
                ..before.clone()
            };
            let moment = lifted.point.sub(&pin).cross(&push);
            let change = angular_momentum(std::slice::from_ref(&after), &pin)
                - &angular_momentum(std::slice::from_ref(&before), &pin);
            let still = after.point_velocity(&pin);
            (change - &moment).is_zero() && still.x.is_zero() && still.y.is_zero()
        }
        _ => {
            let moment = lifted.point.sub(&before.centre).cross(&push);
            ((b.omega.clone() - &before.omega) * &before.inertia - &moment).is_zero()
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
