//! The integrators: four fixed-step ones over the whole run (approach, contact, departure) and
//! the event-driven RK4 (free flight analytic, only the contact integrated, separation located).

use super::{Contact, State};
use crate::solve::solve_linear;
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
    /// RK4 on the contact only, starting at the exact onset and stopping at the separation
    /// event located to the method's order; free flight is analytic.
    EventRk4,
}

impl Integrator {
    /// All five, in the order of the reports.
    ///
    /// # Examples
    /// ```
    /// assert_eq!(rodimpact::contact::Integrator::ALL.len(), 5);
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
    /// assert_eq!(rodimpact::contact::Integrator::EventRk4.name(), "event-rk4");
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
}

/// The result of one simulated impact.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Final velocities (v, V, omega), comparable with [`Contact::reference`].
    pub velocities: [f64; 3],
    /// The projectile's final lateral velocity over v0 (0 in the impulsive model).
    pub lateral: f64,
    /// Relative errors of (v, V, omega) against the exact impulsive values (|v| / v0 where the
    /// exact value is 0).
    pub errors: [f64; 3],
    /// (E_end - E_0) / E_0.
    pub energy_change: f64,
    /// Integration steps taken.
    pub steps: usize,
    /// Wall-clock run time in seconds (reported, never asserted).
    pub seconds: f64,
}

/// The largest number of steps one run may take.
pub const MAX_STEPS: usize = 100_000_000;

/// Number of steps a run of `integrator` with step `h` needs: fixed-step runs cover the approach
/// and three contact times.
///
/// # Examples
/// ```
/// use rodimpact::contact::{Contact, Geometry, Integrator, steps_needed};
/// use rodimpact::{field::q, scene::Scene};
/// let c = Contact::new(&Scene::builder(q(1, 1), q(1, 1)).build()?, 1e6, Geometry::Exact)?;
/// let n = steps_needed(&c, Integrator::EventRk4, c.contact_time() / 100.0);
/// assert!((100.0..=101.0).contains(&n)); // ceil(T_c / h) in f64
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn steps_needed(c: &Contact, integrator: Integrator, h: f64) -> f64 {
    let span = match integrator {
        Integrator::EventRk4 => c.contact_time(),
        _ => c.gap() / c.v0 + 3.0 * c.contact_time(),
    };
    (span / h).ceil()
}

/// Simulates the impact with step `h` (seconds).
///
/// # Panics
/// If the run would take more than [`MAX_STEPS`] steps (check with [`steps_needed`] first) or
/// `h` is not positive.
///
/// # Examples
/// ```
/// use rodimpact::contact::{Contact, Geometry, Integrator, simulate};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = Contact::new(&scene, 1e6, Geometry::Frozen)?;
/// let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 100.0);
/// assert!(run.errors.iter().all(|e| *e < 1e-8));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn simulate(c: &Contact, integrator: Integrator, h: f64) -> Run {
    assert!(h > 0.0 && steps_needed(c, integrator, h) <= MAX_STEPS as f64);
    let clock = Instant::now();
    let (state, steps) = match integrator {
        Integrator::EventRk4 => event_rk4(c, h),
        _ => {
            let n = steps_needed(c, integrator, h) as usize;
            let mut s = c.start(c.gap());
            for _ in 0..n {
                s = match integrator {
                    Integrator::Verlet => verlet(c, &s, h),
                    Integrator::Rk4 => rk4(c, &s, h, true),
                    Integrator::Midpoint => implicit(c, &s, h, 0.5),
                    _ => implicit(c, &s, h, 1.0),
                };
            }
            (s, n)
        }
    };
    let seconds = clock.elapsed().as_secs_f64();
    let velocities = [state[5], state[7], state[9]];
    let reference = c.reference();
    let errors = std::array::from_fn(|i| {
        let scale = if reference[i] == 0.0 {
            c.v0
        } else {
            reference[i].abs()
        };
        (velocities[i] - reference[i]).abs() / scale
    });
    let e0 = c.energy(&c.start(c.gap()));
    Run {
        velocities,
        lateral: state[6] / c.v0,
        errors,
        energy_change: (c.energy(&state) - e0) / e0,
        steps,
        seconds,
    }
}

fn axpy(y: &State, h: f64, d: &State) -> State {
    std::array::from_fn(|i| y[i] + h * d[i])
}

fn rk4(c: &Contact, s: &State, h: f64, switched: bool) -> State {
    let k1 = c.derivative(s, switched);
    let k2 = c.derivative(&axpy(s, h / 2.0, &k1), switched);
    let k3 = c.derivative(&axpy(s, h / 2.0, &k2), switched);
    let k4 = c.derivative(&axpy(s, h, &k3), switched);
    std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
}

/// Velocity Verlet; the dashpot's velocity is taken at the half step (explicit).
fn verlet(c: &Contact, s: &State, h: f64) -> State {
    let half = |s: &State| {
        let d = c.derivative(s, true);
        let mut out = *s;
        for i in 5..10 {
            out[i] += h / 2.0 * d[i];
        }
        out
    };
    let mut t = half(s);
    for i in 0..5 {
        t[i] += h * t[i + 5];
    }
    half(&t)
}

/// One step of y1 = y0 + h f(y0 + theta (y1 - y0)): theta = 1/2 the implicit midpoint rule,
/// theta = 1 backward Euler. Newton's method with a finite-difference Jacobian.
fn implicit(c: &Contact, y0: &State, h: f64, theta: f64) -> State {
    let residual = |y1: &State| -> State {
        let mid: State = std::array::from_fn(|i| y0[i] + theta * (y1[i] - y0[i]));
        let f = c.derivative(&mid, true);
        std::array::from_fn(|i| y1[i] - y0[i] - h * f[i])
    };
    let mut y1 = axpy(y0, h, &c.derivative(y0, true));
    for _ in 0..30 {
        let g = residual(&y1);
        let mut jacobian = vec![vec![0.0; 10]; 10];
        for j in 0..10 {
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
/// integrated with step h, and the last step is shortened by bisection on the event function
/// so that it ends on the separation. Returns the state at separation (free flight after it
/// does not change the velocities) and the number of full steps.
fn event_rk4(c: &Contact, h: f64) -> (State, usize) {
    let mut s = c.start(0.0);
    let mut steps = 0;
    loop {
        let next = rk4(c, &s, h, false);
        steps += 1;
        if c.gap_function(&next) > 0.0 && steps < MAX_STEPS {
            s = next;
            continue;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if c.gap_function(&rk4(c, &s, mid * h, false)) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return (rk4(c, &s, hi * h, false), steps);
    }
}
