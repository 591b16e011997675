//! The iterative solvers, exactly: K sweeps of projected Gauss-Seidel in the generic engine
//! order (a normal row, then a friction row, at each contact), and one step of pymunk 7,
//! Box2D 2.3 and Bullet 3 replayed row by row as their sources compute it
//! (`tests/oracles/engine-laws.md` derives each; [`crate::impact::Engine::source`] cites them).
//!
//! Every row reads the relative velocities as they stand, `u = u0 + W (lam_n, lam_t)`, kept up
//! to date as each impulse changes (a column of W a change), so a sweep costs O(n) a row.

/// The most steps of pymunk's replay before it is reported as not stopping: a contact that a
/// step leaves approaching (a wedged body) takes a step after another with ever smaller
/// impulses, and their exact fractions grow with each.
pub const MAX_ENGINE_STEPS: usize = 60;
use super::common::{Contacts, negative_part};
use crate::field::{Field, Q};
use crate::impact::engines::Profile;
use crate::impact::law::Law;
use crate::impact::work::{Meter, Stopped, Work};
use crate::model::{Shape, System};
use num_bigint::BigInt;
use num_rational::BigRational;
use std::cmp::Ordering;

/// The normal and the tangential impulses of every contact.
type NormalAndTangential<F> = (Vec<F>, Vec<F>);

/// W's blocks between the contacts' normal (n) and tangent (t) rows.
pub(super) struct Blocks<F> {
    pub(super) nn: Vec<Vec<F>>,
    pub(super) nt: Vec<Vec<F>>,
    pub(super) tn: Vec<Vec<F>>,
    pub(super) tt: Vec<Vec<F>>,
}

impl<F: Field> Blocks<F> {
    /// The blocks of `contacts` (`nn` is the Delassus matrix `w`, computed already).
    pub(super) fn of(contacts: &Contacts<F>, w: &[Vec<F>]) -> Blocks<F> {
        Blocks {
            nn: w.to_vec(),
            nt: contacts.coupling(0, 1),
            tn: contacts.coupling(1, 0),
            tt: contacts.coupling(1, 1),
        }
    }
}

/// The impulses and the relative velocities they leave, kept together.
struct State<F> {
    lam_n: Vec<F>,
    lam_t: Vec<F>,
    u_n: Vec<F>,
    u_t: Vec<F>,
}

impl<F: Field> State<F> {
    fn start(u0: (&[F], &[F])) -> State<F> {
        let n = u0.0.len();
        State {
            lam_n: vec![F::zero(); n],
            lam_t: vec![F::zero(); n],
            u_n: u0.0.to_vec(),
            u_t: u0.1.to_vec(),
        }
    }

    /// Charges one sweep: each of the 2n rows updates the velocities at every contact.
    fn charge(&self, meter: &mut Meter) -> Result<(), Stopped> {
        let n = self.lam_n.len();
        meter.charge(
            2 * n * n,
            self.lam_n
                .iter()
                .chain(&self.lam_t)
                .chain(&self.u_n)
                .chain(&self.u_t),
        )
    }

    /// Sets contact `i`'s normal impulse to `value`, the velocities following.
    fn set_normal(&mut self, w: &Blocks<F>, i: usize, value: F) {
        let d = value.clone() - &self.lam_n[i];
        self.follow((&w.nn, &w.tn), i, &d);
        self.lam_n[i] = value;
    }

    /// Sets contact `i`'s tangential impulse to `value`, the velocities following.
    fn set_tangent(&mut self, w: &Blocks<F>, i: usize, value: F) {
        let d = value.clone() - &self.lam_t[i];
        self.follow((&w.nt, &w.tt), i, &d);
        self.lam_t[i] = value;
    }

    /// Adds `d` times column `i` of `(into_n, into_t)` to the normal and tangential velocities:
    /// what a change `d` of one impulse does to every contact.
    fn follow(&mut self, (into_n, into_t): (&[Vec<F>], &[Vec<F>]), i: usize, d: &F) {
        if d.is_zero() {
            return;
        }
        for k in 0..self.u_n.len() {
            self.u_n[k] = self.u_n[k].clone() + &(into_n[k][i].clone() * d);
            self.u_t[k] = self.u_t[k].clone() + &(into_t[k][i].clone() * d);
        }
    }
}

fn max_zero<F: Field>(x: F) -> F {
    if x.sign() == Some(Ordering::Less) {
        F::zero()
    } else {
        x
    }
}

fn clamp<F: Field>(x: F, limit: &F) -> F {
    if (x.clone() - limit).sign() == Some(Ordering::Greater) {
        limit.clone()
    } else if (x.clone() + limit).sign() == Some(Ordering::Less) {
        -limit.clone()
    } else {
        x
    }
}

/// Whether contact `i` has a friction row: mu > 0 and an impulse along its tangent moves it.
fn rough<F: Field>(contacts: &Contacts<F>, w: &Blocks<F>, i: usize) -> bool {
    contacts.mu[i].sign() == Some(Ordering::Greater) && !w.tt[i][i].is_zero()
}

/// K sweeps of projected Gauss-Seidel from zero impulses, in the contacts' order: at each, the
/// normal row `lam_n <- max(0, lam_n - (u_n + e u0_n^-)/W_nn)` on the current velocities, then
/// (mu > 0) the friction row `lam_t <- clamp(lam_t - u_t/W_tt, +-mu lam_n)` on the velocities
/// after it. Restitution is the bias of the approach speed before, `e u0_n^-`.
pub(super) fn pgs<F: Field>(
    contacts: &Contacts<F>,
    w: &Blocks<F>,
    u0: (&[F], &[F]),
    sweeps: u32,
    share: u64,
) -> Result<(Vec<F>, Vec<F>), Stopped> {
    let n = u0.0.len();
    let mut s = State::start(u0);
    let mut meter = Meter::shared(Work::Sweeps, share);
    for _ in 0..sweeps {
        s.charge(&mut meter)?;
        for i in 0..n {
            if !w.nn[i][i].is_zero() {
                let target = s.u_n[i].clone()
                    - &Law::newton_leaving(&contacts.e[i], &negative_part(&u0.0[i]));
                let next = max_zero(s.lam_n[i].clone() - &(target / &w.nn[i][i]));
                s.set_normal(w, i, next);
            }
            if rough(contacts, w, i) {
                let limit = contacts.mu[i].clone() * &s.lam_n[i];
                let next = clamp(
                    s.lam_t[i].clone() - &(s.u_t[i].clone() / &w.tt[i][i]),
                    &limit,
                );
                s.set_tangent(w, i, next);
            }
        }
    }
    Ok((s.lam_n, s.lam_t))
}

/// How pymunk (Chipmunk) sees a body: its harness's shape (a rod or an unshaped fixed body is
/// a segment, a box or polygon a polygon, a disc or point a circle).
fn circle_or_segment(shape: Option<&Shape>) -> (bool, bool) {
    match shape {
        Some(Shape::Disc { .. }) | Some(Shape::Point) => (true, false),
        None | Some(Shape::Rod { .. }) => (false, true),
        Some(Shape::Box { .. }) | Some(Shape::Polygon { .. }) => (false, false),
    }
}

/// The impulses one pymunk 7 step after another leave, until no contact approaches.
///
/// A step takes the contacts that approach (they overlap after the positions move) and those
/// that touch, unless the pair is a circle and a circle or a segment (Chipmunk's circle tests
/// are strict: touching circles do not collide); each with the bounce `e u_n` of the step's
/// start (no threshold) and impulses from zero; 10 iterations, each contact in order: the
/// normal and tangential increments from the same velocities, the friction bounded by mu times
/// the new normal impulse, applied together. The pose is the scene's throughout. `None` when a
/// contact still approaches after [`MAX_ENGINE_STEPS`] steps.
pub(super) fn pymunk<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &Blocks<F>,
    u0: (&[F], &[F]),
    iterations: u32,
) -> Result<Option<NormalAndTangential<F>>, Stopped> {
    let n = u0.0.len();
    let mut s = State::start(u0);
    let mut meter = Meter::new(Work::EngineSteps);
    let mut total_n = vec![F::zero(); n];
    let mut total_t = vec![F::zero(); n];
    for _ in 0..MAX_ENGINE_STEPS {
        if !s.u_n.iter().any(|u| u.sign() == Some(Ordering::Less)) {
            return Ok(Some((total_n, total_t)));
        }
        let start = s.u_n.clone();
        let active: Vec<usize> = (0..n)
            .filter(|&i| match start[i].sign() {
                Some(Ordering::Less) => true,
                Some(Ordering::Greater) | None => false,
                Some(Ordering::Equal) => {
                    let c = &system.contacts[i];
                    let (a, b) = (
                        circle_or_segment(system.bodies[c.a].shape.as_ref()),
                        circle_or_segment(system.bodies[c.b].shape.as_ref()),
                    );
                    let circles = (a.0 && (b.0 || b.1)) || (b.0 && (a.0 || a.1));
                    !circles
                }
            })
            .collect();
        s.lam_n = vec![F::zero(); n];
        s.lam_t = vec![F::zero(); n];
        for _ in 0..iterations {
            s.charge(&mut meter)?;
            for &i in &active {
                let (vn, vt) = (s.u_n[i].clone(), s.u_t[i].clone());
                let bounce = contacts.e[i].clone() * &start[i];
                let jn = max_zero(s.lam_n[i].clone() - &((bounce + &vn) / &w.nn[i][i]));
                let jt = if rough(contacts, w, i) {
                    let limit = contacts.mu[i].clone() * &jn;
                    clamp(s.lam_t[i].clone() - &(vt / &w.tt[i][i]), &limit)
                } else {
                    s.lam_t[i].clone()
                };
                s.set_normal(w, i, jn);
                s.set_tangent(w, i, jt);
            }
        }
        for i in 0..n {
            total_n[i] = total_n[i].clone() + &s.lam_n[i];
            total_t[i] = total_t[i].clone() + &s.lam_t[i];
        }
    }
    Ok(None)
}

/// Whether the approach `u_n` (along a normal of squared length `n2`) is faster than
/// `threshold`: `u_n/|n| < -threshold`, decided without a root.
/// Whether each contact approaches slower than `profile`'s restitution threshold (per unit
/// normal), where Box2D v3 gives it no restitution (`b2ApplyRestitution` skips a point whose
/// `relativeVelocity > -threshold`: one approaching at exactly the threshold bounces, unlike
/// Box2D 2.3's `vRel < -threshold`). All false without a threshold.
pub(super) fn below_threshold<F: Field>(
    system: &System,
    u_n: &[F],
    profile: &Profile,
) -> Vec<bool> {
    let threshold = F::from_rational(&profile.threshold);
    system
        .contacts
        .iter()
        .zip(u_n)
        .map(|(c, u)| {
            let n2 = F::from_rational(&c.normal.dot(&c.normal));
            !threshold.is_zero()
                && (u.sign() != Some(Ordering::Less)
                    || (u.clone() * u - &(threshold.clone() * &threshold * &n2)).sign()
                        == Some(Ordering::Less))
        })
        .collect()
}

fn faster_than<F: Field>(u_n: &F, n2: &F, threshold: &F) -> bool {
    if u_n.sign() != Some(Ordering::Less) {
        return false;
    }
    threshold.is_zero()
        || (u_n.clone() * u_n - &(threshold.clone() * threshold * n2)).sign()
            == Some(Ordering::Greater)
}

/// Box2D's manifolds: the contacts between the same two bodies with parallel normals, two
/// points at most, in the contacts' order.
fn manifolds(system: &System) -> Vec<Vec<usize>> {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for (i, c) in system.contacts.iter().enumerate() {
        let joined = groups.iter_mut().find(|g| {
            let first = &system.contacts[g[0]];
            let same_pair = (first.a, first.b) == (c.a, c.b) || (first.a, first.b) == (c.b, c.a);
            let along = if first.a == c.a {
                first.normal.clone()
            } else {
                first.normal.scale(&-Q::from_integer(1.into()))
            };
            g.len() < 2
                && same_pair
                && along.cross(&c.normal) == Q::from_integer(0.into())
                && along.dot(&c.normal) > Q::from_integer(0.into())
        });
        match joined {
            Some(g) => g.push(i),
            None => groups.push(vec![i]),
        }
    }
    groups
}

/// One Box2D 2.3 step (b2ContactSolver): the restitution bias `-e u0_n` where the approach is
/// faster than the threshold; 8 iterations, each manifold in order: its friction rows first
/// (bounded by mu times the normal impulse so far), then its normal rows: one point by a
/// projected row, two by the exact 2x2 block LCP (a second point whose block is
/// ill-conditioned, `k11^2 >= 1000 det`, is left out, as Box2D does).
pub(super) fn box2d<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &Blocks<F>,
    u0: (&[F], &[F]),
    profile: &Profile,
) -> Result<(Vec<F>, Vec<F>), Stopped> {
    let n = u0.0.len();
    let threshold = F::from_rational(&profile.threshold);
    let n2: Vec<F> = system
        .contacts
        .iter()
        .map(|c| F::from_rational(&c.normal.dot(&c.normal)))
        .collect();
    let bias: Vec<F> = (0..n)
        .map(|i| {
            if faster_than(&u0.0[i], &n2[i], &threshold) {
                Law::newton_leaving(&contacts.e[i], &u0.0[i])
            } else {
                F::zero()
            }
        })
        .collect();
    let thousand = F::from_i64(1000);
    let solved: Vec<Vec<usize>> = manifolds(system)
        .into_iter()
        .map(|g| {
            if let [i, j] = g[..] {
                let (k11, k22, k12) = (&w.nn[i][i], &w.nn[j][j], &w.nn[i][j]);
                let det = k11.clone() * k22 - &(k12.clone() * k12);
                let conditioned =
                    (k11.clone() * k11 * &n2[j] - &(thousand.clone() * &det * &n2[i])).sign()
                        == Some(Ordering::Less);
                if !conditioned {
                    return vec![i];
                }
            }
            g
        })
        .collect();
    let mut s = State::start(u0);
    let mut meter = Meter::new(Work::EngineSteps);
    for _ in 0..profile.engine.iterations() {
        s.charge(&mut meter)?;
        for g in &solved {
            for &i in g {
                if rough(contacts, w, i) {
                    let limit = contacts.mu[i].clone() * &s.lam_n[i];
                    let next = clamp(
                        s.lam_t[i].clone() - &(s.u_t[i].clone() / &w.tt[i][i]),
                        &limit,
                    );
                    s.set_tangent(w, i, next);
                }
            }
            match g[..] {
                [i] => {
                    let next = max_zero(
                        s.lam_n[i].clone() - &((s.u_n[i].clone() - &bias[i]) / &w.nn[i][i]),
                    );
                    s.set_normal(w, i, next);
                }
                [i, j] => {
                    if let Some((x1, x2)) = block(w, &s, &bias, i, j) {
                        s.set_normal(w, i, x1);
                        s.set_normal(w, j, x2);
                    }
                }
                _ => unreachable!("a manifold holds one or two points"),
            }
        }
    }
    Ok((s.lam_n, s.lam_t))
}

/// Box2D's 2-point block solver: the normal impulses of points `i` and `j` that solve their
/// 2x2 LCP with the others held, tried case by case (both pushing, the first only, the second
/// only, neither); `None` when no case holds (the impulses are kept).
fn block<F: Field>(w: &Blocks<F>, s: &State<F>, bias: &[F], i: usize, j: usize) -> Option<(F, F)> {
    let nonnegative = |x: &F| x.sign() != Some(Ordering::Less);
    let (k11, k22, k12) = (&w.nn[i][i], &w.nn[j][j], &w.nn[i][j]);
    let (a1, a2) = (&s.lam_n[i], &s.lam_n[j]);
    let bx = s.u_n[i].clone() - &bias[i] - &(k11.clone() * a1 + &(k12.clone() * a2));
    let by = s.u_n[j].clone() - &bias[j] - &(k12.clone() * a1 + &(k22.clone() * a2));
    let det = k11.clone() * k22 - &(k12.clone() * k12);
    let x1 = -(k22.clone() * &bx - &(k12.clone() * &by)) / &det;
    let x2 = -(k11.clone() * &by - &(k12.clone() * &bx)) / &det;
    if nonnegative(&x1) && nonnegative(&x2) {
        return Some((x1, x2));
    }
    let x1 = -(bx.clone() / k11);
    if nonnegative(&x1) && nonnegative(&(k12.clone() * &x1 + &by)) {
        return Some((x1, F::zero()));
    }
    let x2 = -(by.clone() / k22);
    if nonnegative(&x2) && nonnegative(&(k12.clone() * &x2 + &bx)) {
        return Some((F::zero(), x2));
    }
    (nonnegative(&bx) && nonnegative(&by)).then(|| (F::zero(), F::zero()))
}

/// pybullet's least-squares residual threshold, 1e-7 as the double it is (exactly).
fn bullet_residual() -> Q {
    BigRational::from_float(1e-7).expect("a finite double")
}

/// One Bullet 3 step as pybullet runs it (btSequentialImpulseConstraintSolver, rigid bodies):
/// the restitution target `-e u0_n` (0 below the threshold, strictly); per iteration every
/// normal row, then every friction row (a contact that starts without slip has its one friction
/// direction out of an x-z scene's plane: no friction in the plane), each bounded by mu times
/// its normal impulse and skipped while that is 0; 50 iterations, stopping after the first whose
/// largest squared row residual (the change of impulse times the row's mass, per unit normal)
/// is at most 1e-7.
pub(super) fn bullet<F: Field>(
    system: &System,
    contacts: &Contacts<F>,
    w: &Blocks<F>,
    u0: (&[F], &[F]),
    profile: &Profile,
) -> Result<(Vec<F>, Vec<F>), Stopped> {
    let n = u0.0.len();
    let threshold = F::from_rational(&profile.threshold);
    let epsilon = F::from_rational(&Q::new(BigInt::from(1), BigInt::from(2).pow(52u32)));
    let residual_exit = F::from_rational(&bullet_residual());
    let n2: Vec<F> = system
        .contacts
        .iter()
        .map(|c| F::from_rational(&c.normal.dot(&c.normal)))
        .collect();
    let target: Vec<F> = (0..n)
        .map(|i| {
            let slow = (u0.0[i].clone() * &u0.0[i] - &(threshold.clone() * &threshold * &n2[i]))
                .sign()
                == Some(Ordering::Less);
            if slow {
                F::zero()
            } else {
                max_zero(Law::newton_leaving(&contacts.e[i], &u0.0[i]))
            }
        })
        .collect();
    let friction: Vec<bool> = (0..n)
        .map(|i| {
            let slipping = (u0.1[i].clone() * &u0.1[i] - &(epsilon.clone() * &n2[i])).sign()
                == Some(Ordering::Greater);
            rough(contacts, w, i) && (slipping || profile.plane_xy)
        })
        .collect();
    let mut s = State::start(u0);
    let mut meter = Meter::new(Work::EngineSteps);
    for _ in 0..profile.engine.iterations() {
        s.charge(&mut meter)?;
        let mut worst = F::zero();
        let mut note = |d: &F, k: &F, n2: &F| {
            let r = d.clone() * d * k * k / n2;
            if (r.clone() - &worst).sign() == Some(Ordering::Greater) {
                worst = r;
            }
        };
        for i in 0..n {
            let next =
                max_zero(s.lam_n[i].clone() + &((target[i].clone() - &s.u_n[i]) / &w.nn[i][i]));
            note(&(next.clone() - &s.lam_n[i]), &w.nn[i][i], &n2[i]);
            s.set_normal(w, i, next);
        }
        for i in 0..n {
            if friction[i] && s.lam_n[i].sign() == Some(Ordering::Greater) {
                let limit = contacts.mu[i].clone() * &s.lam_n[i];
                let next = clamp(
                    s.lam_t[i].clone() - &(s.u_t[i].clone() / &w.tt[i][i]),
                    &limit,
                );
                note(&(next.clone() - &s.lam_t[i]), &w.tt[i][i], &n2[i]);
                s.set_tangent(w, i, next);
            }
        }
        if (worst - &residual_exit).sign() != Some(Ordering::Greater) {
            break;
        }
    }
    Ok((s.lam_n, s.lam_t))
}
