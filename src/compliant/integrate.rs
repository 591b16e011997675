//! The integrators: four fixed-step ones over the whole run (approach, contact, departure) and
//! the event-driven RK4 (free flight analytic, only the contact integrated, its end located),
//! with the work each costs.

use super::accuracy::{self, Miss, Tolerance};
use super::slot::{PIVOT_X, POSITIONS, VY};
use super::{CompliantContact, State};
use crate::error::Error;
use crate::field::linear::solve_linear;
use std::time::Instant;

/// A time integrator for [`simulate`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Integrator {
    /// Velocity Verlet (leapfrog; stable for h Omega < 2).
    Verlet,
    /// Classical fourth-order Runge-Kutta (stable for h Omega < 2 sqrt 2).
    Rk4,
    /// The implicit midpoint rule (Newton iteration).
    Midpoint,
    /// Backward Euler (Newton iteration; turns elastic hits plastic once h > T_c).
    BackwardEuler,
    /// RK4 on the contact only, starting at the exact onset and stopping at the contact's end
    /// (separation or settle time), located to the method's order; free flight is analytic.
    EventRk4,
}

impl Integrator {
    /// All five, in the order of the reports.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::compliant::Integrator::ALL.len(), 5);
    /// ```
    pub const ALL: [Integrator; 5] = [
        Integrator::Verlet,
        Integrator::Rk4,
        Integrator::Midpoint,
        Integrator::BackwardEuler,
        Integrator::EventRk4,
    ];

    /// The name used on the command line.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::compliant::Integrator::EventRk4.name(), "event-rk4");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Verlet => "verlet",
            Integrator::Rk4 => "rk4",
            Integrator::Midpoint => "midpoint",
            Integrator::BackwardEuler => "backward-euler",
            Integrator::EventRk4 => "event-rk4",
        }
    }

    /// The work of one step, in units of one force evaluation (about 30 ns here): 2 for Verlet,
    /// 4 for the RK4s, 60 for the implicit methods (measured: mostly one Newton iteration of 13
    /// evaluations for the finite-difference Jacobian and a 12 x 12 solve).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::Integrator;
    /// assert_eq!(Integrator::Midpoint.cost_per_step(), 60.0);
    /// ```
    pub fn cost_per_step(self) -> f64 {
        match self {
            Integrator::Verlet => 2.0,
            Integrator::Rk4 | Integrator::EventRk4 => 4.0,
            Integrator::Midpoint | Integrator::BackwardEuler => 60.0,
        }
    }

    /// `true` for the fixed-step integrators, which run through approach, contact and
    /// departure.
    fn fixed_step(self) -> bool {
        self != Integrator::EventRk4
    }
}

/// How a run's contact ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunEnd {
    /// The point left the rod's line (bouncing contact, e > 0).
    Separated,
    /// The contact was read settled: a sticking contact (e = 0) at its settle time, or a nearly
    /// critically damped bouncing one whose relative motion had decayed below
    /// [`SETTLE_TOLERANCE`](super::SETTLE_TOLERANCE) v0 without the penetration returning to 0.
    Settled,
    /// The point slid past the rod's end while pressing on the rod (exact geometry): the
    /// contact broke off early and the impulse is incomplete.
    SlidOff,
    /// The run ended with the contact still acting (a step or damping that never lets go).
    StillInContact,
}

/// The result of one simulated impact.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// The integrator.
    pub integrator: Integrator,
    /// The time step h (seconds).
    pub h: f64,
    /// Final velocities (v, V, omega), comparable with [`CompliantContact::reference`].
    pub velocities: [f64; 3],
    /// The pivot's impulse on the rod (x-component) integrated while the contact acted;
    /// `None` for a free rod.
    pub pivot_impulse: Option<f64>,
    /// The projectile's final lateral velocity (along the rod) over v0 (0 in the impulsive
    /// model).
    pub lateral: f64,
    /// Relative errors of (v, V, omega) against the exact impulsive values, as [`Tolerance`]
    /// defines them (v against max(|v|, |v0 - v|)).
    pub errors: [f64; 3],
    /// The pivot impulse's relative error (against max(|P|, J)); `None` for a free rod.
    pub pivot_error: Option<f64>,
    /// (E_end - E_0) / E_0, kinetic plus spring energy.
    pub energy_change: f64,
    /// How the contact ended.
    pub ending: RunEnd,
    /// The error the run may have.
    pub tolerance: Tolerance,
    /// Why the run does not reproduce the exact values; `None` when every error is within the
    /// tolerance.
    pub miss: Option<Miss>,
    /// Integration steps taken.
    pub steps: usize,
    /// Wall-clock run time in seconds (reported, never asserted).
    pub seconds: f64,
}

/// The largest work one command may do, summed over its runs, in force evaluations (see
/// [`Integrator::cost_per_step`]): 3e8, about ten seconds here, so 5e6 implicit steps or
/// 7.5e7 RK4 steps.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{Integrator, MAX_WORK};
/// assert_eq!(MAX_WORK / Integrator::BackwardEuler.cost_per_step(), 5e6);
/// ```
pub const MAX_WORK: f64 = 3e8;

/// The longest time after the onset that a run covers: the settle time of a sticking contact
/// (where it is read), four contact times of a bouncing one (which ends at its separation,
/// normally after one).
fn contact_span(c: &CompliantContact) -> f64 {
    if c.sticking {
        c.contact_time()
    } else {
        4.0 * c.contact_time()
    }
}

/// The most steps a run of `integrator` with step `h` takes: fixed-step runs cover the approach
/// (l/10 at v0) and [`contact_span`]; the event-driven one only the latter.
fn steps_needed(c: &CompliantContact, integrator: Integrator, h: f64) -> f64 {
    let approach = if integrator.fixed_step() {
        c.gap() / c.v0
    } else {
        0.0
    };
    ((approach + contact_span(c)) / h).ceil()
}

/// The most work one run of `integrator` with step `h` can take, in force evaluations, for
/// comparison with [`MAX_WORK`] before running.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, work};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
/// let units = work(&c, Integrator::EventRk4, c.contact_time() / 100.0);
/// // At most 4 T_c of steps of 4 evaluations (the contact separates after about 100).
/// assert!((1600.0..=1604.0).contains(&units));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn work(c: &CompliantContact, integrator: Integrator, h: f64) -> f64 {
    steps_needed(c, integrator, h) * integrator.cost_per_step()
}

/// Simulates the impact with step `h` (seconds).
///
/// # Errors
/// `dt` when `h` is not a positive finite number or the run's [`work`] exceeds [`MAX_WORK`].
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, RunEnd, Geometry, Integrator, simulate};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Frozen)?;
/// let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 100.0)?;
/// assert!(run.errors.iter().all(|e| *e < 1e-8));
/// assert_eq!(run.ending, RunEnd::Separated);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn simulate(c: &CompliantContact, integrator: Integrator, h: f64) -> Result<Run, Error> {
    if !(h.is_finite() && h > 0.0) {
        return Err(Error::out_of_range("dt", "must be a positive finite step"));
    }
    let units = work(c, integrator, h);
    if units > MAX_WORK {
        return Err(Error::out_of_range(
            "dt",
            format!(
                "{} would do {units:.1e} force evaluations, more than the limit {MAX_WORK:.0e}",
                integrator.name()
            ),
        ));
    }
    let clock = Instant::now();
    let (state, steps, ending) = if integrator.fixed_step() {
        fixed_step(c, integrator, h)
    } else {
        event_rk4(c, h)
    };
    let seconds = clock.elapsed().as_secs_f64();
    let velocities = c.outputs(&state);
    let pivot_impulse = c.pivot.map(|_| state[PIVOT_X]);
    let (errors, pivot_error) = accuracy::errors(c, &velocities, pivot_impulse);
    let tolerance = Tolerance::of(c, integrator, h, steps);
    let miss = accuracy::judge(
        c,
        integrator,
        h * c.frequency(),
        ending,
        &errors,
        pivot_error,
        &tolerance,
    );
    let e0 = c.energy(&c.start(c.gap()));
    Ok(Run {
        integrator,
        h,
        velocities,
        pivot_impulse,
        lateral: state[VY] / c.v0,
        errors,
        pivot_error,
        energy_change: (c.energy(&state) - e0) / e0,
        ending,
        tolerance,
        miss,
        steps,
        seconds,
    })
}

/// A fixed-step run from rest, the point l/10 short of the rod, through the approach and the
/// contact: to the first step after separation (bouncing) or over the settle time (sticking).
/// A pivoted rod's centre turns on after the contact, so the velocities are read when it ends.
fn fixed_step(c: &CompliantContact, integrator: Integrator, h: f64) -> (State, usize, RunEnd) {
    let limit = steps_needed(c, integrator, h) as usize;
    let mut s = c.start(c.gap());
    let mut touched = false;
    for taken in 1..=limit {
        s = match integrator {
            Integrator::Verlet => verlet(c, &s, h),
            Integrator::Rk4 => rk4(c, &s, h, true),
            Integrator::Midpoint => implicit(c, &s, h, 0.5),
            _ => implicit(c, &s, h, 1.0),
        };
        if c.slid_off(&s) {
            return (s, taken, RunEnd::SlidOff);
        }
        if !c.sticking {
            let in_contact = c.gap_function(&s) > 0.0;
            if touched && !in_contact {
                return (s, taken, RunEnd::Separated);
            }
            touched |= in_contact;
        }
    }
    (s, limit, unfinished(c, &s))
}

/// How a run that reached its last step without a separation ended: settled if the contact is
/// sticking or its relative motion has decayed (a nearly critically damped bouncing contact
/// whose penetration lingers at the rounding level), else still in contact.
fn unfinished(c: &CompliantContact, s: &State) -> RunEnd {
    if c.sticking || c.settled(s) {
        RunEnd::Settled
    } else {
        RunEnd::StillInContact
    }
}

fn axpy(y: &State, h: f64, d: &State) -> State {
    std::array::from_fn(|i| y[i] + h * d[i])
}

fn rk4(c: &CompliantContact, s: &State, h: f64, switched: bool) -> State {
    let k1 = c.derivative(s, switched);
    let k2 = c.derivative(&axpy(s, h / 2.0, &k1), switched);
    let k3 = c.derivative(&axpy(s, h / 2.0, &k2), switched);
    let k4 = c.derivative(&axpy(s, h, &k3), switched);
    std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// Velocity Verlet; the dashpot's velocity is taken at the half step (explicit). The pivot's
/// impulse is kicked like a velocity (the trapezoidal rule).
fn verlet(c: &CompliantContact, s: &State, h: f64) -> State {
    let half = |s: &State| {
        let d = c.derivative(s, true);
        let mut out = *s;
        for i in POSITIONS..out.len() {
            out[i] += h / 2.0 * d[i];
        }
        out
    };
    let mut t = half(s);
    for i in 0..POSITIONS {
        t[i] += h * t[i + POSITIONS];
    }
    half(&t)
}

/// One step of y1 = y0 + h f(y0 + theta (y1 - y0)): theta = 1/2 the implicit midpoint rule,
/// theta = 1 backward Euler. Newton's method with a finite-difference Jacobian.
fn implicit(c: &CompliantContact, y0: &State, h: f64, theta: f64) -> State {
    let residual = |y1: &State| -> State {
        let mid: State = std::array::from_fn(|i| y0[i] + theta * (y1[i] - y0[i]));
        let f = c.derivative(&mid, true);
        std::array::from_fn(|i| y1[i] - y0[i] - h * f[i])
    };
    let n = y0.len();
    let mut y1 = axpy(y0, h, &c.derivative(y0, true));
    for _ in 0..30 {
        let g = residual(&y1);
        let mut jacobian = vec![vec![0.0; n]; n];
        for j in 0..n {
            let eps = 1e-7 * (y1[j].abs() + c.gap() * 1e-3);
            let mut shifted = y1;
            shifted[j] += eps;
            let gj = residual(&shifted);
            for (row, (a, b)) in jacobian.iter_mut().zip(gj.iter().zip(&g)) {
                row[j] = (a - b) / eps;
            }
        }
        let Some(dy) = solve_linear(jacobian, g.iter().map(|x| -x).collect()) else {
            break;
        };
        let mut size = 0.0f64;
        for (y, d) in y1.iter_mut().zip(&dy) {
            *y += d;
            size = size.max(d.abs() / (y.abs() + c.gap() * 1e-3));
        }
        if size < 1e-14 {
            break;
        }
    }
    y1
}

/// Event-driven RK4: the rod is at rest until the exact onset (delta = 0), the contact branch is
/// integrated with step h, and the last step is shortened so that it ends on the contact's end:
/// the separation or slide-off event, located by bisection on the event function, or the
/// settle time of a sticking contact (the last step shortened to end on it). Returns the state
/// then (free flight after it does not change the velocities), the number of steps and how the
/// contact ended. A bouncing contact still acting after four contact times is given up.
fn event_rk4(c: &CompliantContact, h: f64) -> (State, usize, RunEnd) {
    let mut s = c.start(0.0);
    let span = contact_span(c);
    let (steps, last, settles) = if c.sticking {
        let n = (span / h).ceil().max(1.0);
        (n as usize, span - (n - 1.0) * h, true)
    } else {
        ((span / h).ceil() as usize, h, false)
    };
    for taken in 1..=steps {
        let step = if taken == steps { last } else { h };
        let next = rk4(c, &s, step, false);
        if c.gap_function(&next) <= 0.0 {
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if c.gap_function(&rk4(c, &s, mid * step, false)) > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let end = rk4(c, &s, hi * step, false);
            let (delta, arm, _, _) = c.geometry_of(&end);
            let ending = if c.sticking || c.on_rod(arm) < delta {
                RunEnd::SlidOff
            } else {
                RunEnd::Separated
            };
            return (end, taken, ending);
        }
        s = next;
    }
    let ending = if settles {
        RunEnd::Settled
    } else {
        unfinished(c, &s)
    };
    (s, steps, ending)
}
