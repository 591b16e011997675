//! The time-resolved compliant-contact model (docs/stability.md): a penalty spring of stiffness k
//! (and, for e < 1, a dashpot) acts while the projectile's point penetrates the rod's line.
//!
//! Two forms: [`Geometry::Frozen`] keeps the normal and the lever arm fixed (a linear oscillator
//! with mass mu_eff = 1 / (1/m + d^2/I_axis), d the lever arm about the rod's centre or pivot:
//! for every k it returns the impulsive result, so its only error is the integrator's);
//! [`Geometry::Exact`] lets the rod turn during contact, so the normal outputs converge to the
//! impulsive values as O(1/k) and the lateral velocity as O(k^-1/2).
//!
//! The rod is free, or turns about a fixed frictionless pivot (the rod's point p stays put; the
//! pivot's reaction is whatever keeps it there, and its impulse over the contact is integrated
//! alongside the motion). The contact law follows e:
//!
//! - e > 0 (bouncing): unilateral spring-dashpot, c = 2 zeta sqrt(k mu_eff) with zeta =
//!   -ln e / sqrt(pi^2 + ln^2 e), so that the frozen oscillator's restitution is exactly e;
//!   contact ends when the penetration returns to 0.
//! - e = 0 (sticking): a critically damped (zeta = 1) spring-dashpot that, once engaged, also
//!   pulls (bilateral, like glue), so the projectile moves on with the struck point. The relative
//!   motion decays as (1 + Omega t) e^(-Omega t) and never ends; the state is read at the settle
//!   time T_s, when the frozen oscillator's remaining relative motion (Omega delta + |delta'|) is
//!   [`SETTLE_TOLERANCE`] v0. The frozen model's error is then below that tolerance for every
//!   k; the exact geometry's converges as O(1/k) like the bouncing one.
//!
//! This is a float simulation; its references come from the exact solver, converted to f64 at
//! the end.

mod accuracy;
mod integrate;
mod sweep;

pub use accuracy::{LOOSEST, Miss, Tolerance, stability_limit};
pub use integrate::{Integrator, MAX_WORK, Run, RunEnd, simulate, work};
pub use sweep::{Slopes, SweepRow, fit_slope, sweep_k};

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q};
use crate::scene::{Scene, Support};
use crate::solve::Outcome;
use crate::solve::fast::linear::solve;

/// Which contact geometry the simulation uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Normal and lever arm frozen at the impact configuration: a linear oscillator.
    Frozen,
    /// The rod turns during contact: normal n(theta), lever arm (p - c) . u(theta).
    Exact,
}

/// The remaining relative motion (Omega delta + |delta'|, over v0) of the frozen sticking
/// oscillator at the settle time T_s, where a sticking (e = 0) run is read.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::compliant::SETTLE_TOLERANCE, 1e-13);
/// ```
pub const SETTLE_TOLERANCE: f64 = 1e-13;

/// The state: projectile (x, y), rod centre (X, Y), rod angle theta (clockwise, so a hit at
/// a > 0 gives theta' > 0 as the impulsive omega), then the five velocities, then the pivot's
/// impulse on the rod (x, y) accumulated while the contact acts. A pivoted rod's centre is a
/// function of theta: its four slots stay 0.
pub(crate) type State = [f64; 12];

/// Slots of [`State`].
pub(crate) mod slot {
    pub const X: usize = 0;
    pub const Y: usize = 1;
    pub const ROD_X: usize = 2;
    pub const ROD_Y: usize = 3;
    pub const THETA: usize = 4;
    pub const VX: usize = 5;
    pub const VY: usize = 6;
    pub const ROD_VX: usize = 7;
    pub const ROD_VY: usize = 8;
    pub const OMEGA: usize = 9;
    pub const PIVOT_X: usize = 10;
    /// One past the last position slot; velocities and accumulated impulses follow.
    pub const POSITIONS: usize = 5;
}
use slot::*;

/// A compliant contact built from an exact scene, in f64.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Frozen)?;
/// assert!((c.reference()[2] - 12.0 / 11.0).abs() < 1e-15); // omega = 12/11
/// assert_eq!(c.exact().after.omega, q(12, 11));
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CompliantContact {
    m: f64,
    rod_mass: f64,
    inertia: f64,
    half_length: f64,
    a: f64,
    pivot: Option<f64>,
    v0: f64,
    k: f64,
    damping: f64,
    zeta: f64,
    sticking: bool,
    geometry: Geometry,
    scene: Scene,
    exact: Outcome<Q>,
    reference: [f64; 3],
    reference_pivot: Option<f64>,
}

/// Converts an exact input to a positive finite f64, or names the field.
fn to_f64(field: &str, x: &Q) -> Result<f64, Error> {
    let f = x.nearest_f64();
    if f.is_finite() && f > 0.0 {
        Ok(f)
    } else {
        Err(Error::out_of_range(
            field,
            "outside the normal f64 range, which the float simulation needs",
        ))
    }
}

/// x with (2x - 1) e^-x = tol, x > 3/2: Omega T_s for the critically damped oscillator, whose
/// Omega delta + |delta'| is v0 (2 Omega t - 1) e^(-Omega t) once Omega t > 1.
fn settle_phase(tol: f64) -> f64 {
    let mut x = -tol.ln();
    for _ in 0..50 {
        x = ((2.0 * x - 1.0) / tol).ln();
    }
    x
}

impl CompliantContact {
    /// The model for `scene` (free or pivoted rod, any e in [0, 1]) with spring stiffness `k`.
    ///
    /// # Errors
    /// `stiffness` (k not a positive finite number), `a` (a hit at the rod's end with the exact
    /// geometry: the point slides off the end at once), `e` (e > 0 but below the f64 range: use
    /// e = 0 for sticking), or an input outside f64.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(3, 1)).a(q(1, 2)).pivot(q(0, 1)).e(q(0, 1)).build()?;
    /// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
    /// assert!(c.sticking());
    /// assert_eq!(c.exact().pivot_impulse, Some(q(-4, 5)));
    /// assert_eq!(CompliantContact::new(&scene, 0.0, Geometry::Exact).unwrap_err().field, "stiffness");
    /// let end = Scene::builder(q(1, 1), q(1, 1)).build()?; // a = l by default
    /// assert_eq!(CompliantContact::new(&end, 1e6, Geometry::Exact).unwrap_err().field, "a");
    /// assert!(CompliantContact::new(&end, 1e6, Geometry::Frozen).is_ok());
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn new(scene: &Scene, k: f64, geometry: Geometry) -> Result<CompliantContact, Error> {
        if !(k.is_finite() && k > 0.0) {
            return Err(Error::out_of_range(
                "stiffness",
                "must be a positive finite number",
            ));
        }
        if geometry == Geometry::Exact && num_traits::Signed::abs(scene.a()) == *scene.half_length()
        {
            let inside = scene.a() * Q::new(999.into(), 1000.into());
            return Err(Error::out_of_range(
                "a",
                format!(
                    "a hit at the rod's end (|a| = l) slides off the end as the rod turns, so the \
                     exact geometry transfers no impulse: hit inside the rod (--a {inside}) or \
                     use --geometry frozen"
                ),
            ));
        }
        let sticking = num_traits::Zero::is_zero(scene.e());
        let e = scene.e().nearest_f64();
        if !sticking && e <= 0.0 {
            return Err(Error::out_of_range(
                "e",
                "is > 0 but below the f64 range the float simulation needs (e = 0 is the \
                 sticking case: --inelastic)",
            ));
        }
        let exact = solve(&scene.params::<Q>())
            .ok_or_else(|| Error::new("scene", ErrorKind::Invalid("singular".into())))?;
        let reference = [
            exact.after.v.nearest_f64(),
            exact.after.rod_v.nearest_f64(),
            exact.after.omega.nearest_f64(),
        ];
        let reference_pivot = exact.pivot_impulse.as_ref().map(Field::nearest_f64);
        let a = scene.a().nearest_f64();
        let pivot = match scene.support() {
            Support::Free => None,
            Support::Pivot(p) => Some(p.nearest_f64()),
        };
        let finite = a.is_finite()
            && pivot.is_none_or(f64::is_finite)
            && reference
                .iter()
                .chain(&reference_pivot)
                .all(|x| x.is_finite());
        if !finite {
            return Err(Error::out_of_range(
                "a",
                "the scene is outside the f64 range the float simulation needs",
            ));
        }
        let zeta = if sticking {
            1.0
        } else {
            let log_e = e.ln();
            -log_e / (std::f64::consts::PI.powi(2) + log_e * log_e).sqrt()
        };
        let mut c = CompliantContact {
            m: to_f64("m", scene.m())?,
            rod_mass: to_f64("M", scene.rod_mass())?,
            inertia: to_f64("rod", &scene.inertia())?,
            half_length: to_f64("l", scene.half_length())?,
            a,
            pivot,
            v0: to_f64("v0", scene.v0())?,
            k,
            damping: 0.0,
            zeta,
            sticking,
            geometry,
            scene: scene.clone(),
            exact,
            reference,
            reference_pivot,
        };
        c.damping = 2.0 * zeta * (k * c.reduced_mass()).sqrt();
        if !(c.frequency().is_finite() && c.contact_time() > 0.0 && c.damping.is_finite()) {
            return Err(Error::out_of_range(
                "stiffness",
                "the contact's time scale is outside the f64 range",
            ));
        }
        Ok(c)
    }

    /// The scene the model was built from.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// assert_eq!(CompliantContact::new(&scene, 1e6, Geometry::Exact)?.scene(), &scene);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The exact impulsive outcome (v, V, omega, the pivot impulse, energies) from the solver.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
    /// assert_eq!(c.exact().after.v, q(3, 11));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn exact(&self) -> &Outcome<Q> {
        &self.exact
    }

    /// The impulsive result (v, V, omega) from the exact solver, rounded to f64.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let r = CompliantContact::new(&scene, 1e2, Geometry::Exact)?.reference();
    /// assert_eq!(r, [3.0 / 11.0, 8.0 / 11.0, 12.0 / 11.0]);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn reference(&self) -> [f64; 3] {
        self.reference
    }

    /// The exact pivot impulse on the rod (x-component) rounded to f64; `None` for a free rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).pivot(q(0, 1)).build()?;
    /// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
    /// assert_eq!(c.reference_pivot_impulse(), Some(-8.0 / 7.0));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn reference_pivot_impulse(&self) -> Option<f64> {
        self.reference_pivot
    }

    /// `true` for the sticking contact (e = 0).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).e(q(0, 1)).build()?;
    /// assert!(CompliantContact::new(&scene, 1e6, Geometry::Frozen)?.sticking());
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn sticking(&self) -> bool {
        self.sticking
    }

    /// The contact geometry.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).build()?;
    /// assert_eq!(CompliantContact::new(&scene, 1e6, Geometry::Frozen)?.geometry(), Geometry::Frozen);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn geometry(&self) -> Geometry {
        self.geometry
    }

    /// The spring stiffness k.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).build()?;
    /// assert_eq!(CompliantContact::new(&scene, 1e6, Geometry::Frozen)?.stiffness(), 1e6);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn stiffness(&self) -> f64 {
        self.k
    }

    /// The rod's lever arm about its axis of rotation: a (free rod) or a - p (pivoted).
    fn lever(&self) -> f64 {
        self.a - self.pivot.unwrap_or(0.0)
    }

    /// The rod's moment of inertia about its axis: I (free) or I + M p^2 (pivoted).
    fn axis_inertia(&self) -> f64 {
        match self.pivot {
            None => self.inertia,
            Some(p) => self.inertia + self.rod_mass * p * p,
        }
    }

    /// mu_eff = 1 / (1/m + 1/M + a^2/I) for a free rod, 1 / (1/m + (a - p)^2/I_p) for a pivoted
    /// one: the mass of the frozen oscillator.
    fn reduced_mass(&self) -> f64 {
        let rod = match self.pivot {
            None => 1.0 / self.rod_mass,
            Some(_) => 0.0,
        };
        let d = self.lever();
        1.0 / (1.0 / self.m + rod + d * d / self.axis_inertia())
    }

    /// Omega = sqrt(k / mu_eff), the contact's angular frequency (1/s).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).build()?;
    /// let c = CompliantContact::new(&scene, 8.0, Geometry::Frozen)?;
    /// assert!((c.frequency() - 4.0).abs() < 1e-15); // mu_eff = 1/2
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn frequency(&self) -> f64 {
        (self.k / self.reduced_mass()).sqrt()
    }

    /// T_c, the time the frozen contact lasts: pi / (Omega sqrt(1 - zeta^2)) for e > 0 (then
    /// the point separates), the settle time T_s for e = 0 (then [`SETTLE_TOLERANCE`] of the
    /// relative motion is left).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::compliant::{CompliantContact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).build()?;
    /// let c = CompliantContact::new(&scene, 8.0, Geometry::Frozen)?;
    /// assert!((c.contact_time() - std::f64::consts::PI / 4.0).abs() < 1e-15);
    /// let glued = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).e(q(0, 1)).build()?;
    /// let sticking = CompliantContact::new(&glued, 8.0, Geometry::Frozen)?;
    /// let x = 4.0 * sticking.contact_time(); // Omega T_s
    /// assert!(((2.0 * x - 1.0) * (-x).exp() / 1e-13 - 1.0).abs() < 1e-9);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn contact_time(&self) -> f64 {
        if self.sticking {
            self.settle_time()
        } else {
            std::f64::consts::PI / (self.frequency() * (1.0 - self.zeta * self.zeta).sqrt())
        }
    }

    /// T_s: when the critically damped oscillator's remaining relative motion is
    /// [`SETTLE_TOLERANCE`] v0. A nearly critically damped bouncing contact (tiny e) has
    /// delivered its impulse by then too, however long its penetration takes to return to 0.
    fn settle_time(&self) -> f64 {
        settle_phase(SETTLE_TOLERANCE) / self.frequency()
    }

    /// The time over which the contact delivers its impulse: T_c, or T_s where that is shorter.
    pub(crate) fn active_time(&self) -> f64 {
        self.contact_time().min(self.settle_time())
    }

    /// The approach distance of fixed-step runs: l/10, so that contact begins off the step grid.
    fn gap(&self) -> f64 {
        self.half_length / 10.0
    }

    /// The state at rest before the approach: the projectile `gap` short of the rod line.
    fn start(&self, gap: f64) -> State {
        let mut s = [0.0; 12];
        s[X] = -gap;
        s[Y] = self.a;
        s[VX] = self.v0;
        s
    }

    /// The rod centre's position and velocity: from the state for a free rod; from theta for a
    /// pivoted one, whose point p stays at (0, p).
    fn rod_centre(&self, s: &State) -> ([f64; 2], [f64; 2]) {
        let Some(p) = self.pivot else {
            return ([s[ROD_X], s[ROD_Y]], [s[ROD_VX], s[ROD_VY]]);
        };
        let (theta, w) = (s[THETA], s[OMEGA]);
        match self.geometry {
            Geometry::Frozen => ([-p * theta, 0.0], [-p * w, 0.0]),
            Geometry::Exact => {
                let (sin, cos) = theta.sin_cos();
                ([-p * sin, p - p * cos], [-p * w * cos, p * w * sin])
            }
        }
    }

    /// (penetration delta, lever arm s from the rod's centre, unit normal n, d delta / dt).
    fn geometry_of(&self, s: &State) -> (f64, f64, [f64; 2], f64) {
        let (centre, centre_v) = self.rod_centre(s);
        let (rx, ry) = (s[X] - centre[0], s[Y] - centre[1]);
        let (delta, arm, n) = match self.geometry {
            Geometry::Frozen => (rx - self.a * s[THETA], self.a, [1.0, 0.0]),
            Geometry::Exact => {
                let (sin, cos) = s[THETA].sin_cos();
                let n = [cos, -sin];
                (rx * n[0] + ry * n[1], rx * sin + ry * cos, n)
            }
        };
        let rate = (s[VX] - centre_v[0]) * n[0] + (s[VY] - centre_v[1]) * n[1] - arm * s[OMEGA];
        (delta, arm, n, rate)
    }

    /// > 0 while the point is within the rod's length (always, in the frozen form).
    fn on_rod(&self, arm: f64) -> f64 {
        match self.geometry {
            Geometry::Frozen => 1.0,
            Geometry::Exact => self.half_length - arm.abs(),
        }
    }

    /// The event function: > 0 exactly while the contact acts. Bouncing: penetrating and on
    /// the rod; sticking: on the rod (the glued spring also pulls).
    fn gap_function(&self, s: &State) -> f64 {
        let (delta, arm, _, _) = self.geometry_of(s);
        if self.sticking {
            self.on_rod(arm)
        } else {
            delta.min(self.on_rod(arm))
        }
    }

    /// `true` when the relative motion at the contact, Omega |delta| + |delta'|, is at most
    /// [`SETTLE_TOLERANCE`] v0: whatever impulse is left to deliver is below it.
    fn settled(&self, s: &State) -> bool {
        let (delta, _, _, rate) = self.geometry_of(s);
        self.frequency() * delta.abs() + rate.abs() <= SETTLE_TOLERANCE * self.v0
    }

    /// Whether the contact has engaged: the point penetrates the rod's line, or (sticking) the
    /// glued spring holds it. The rod is at rest until the point reaches it, so a moving rod
    /// means a sticking contact has engaged.
    fn engaged(&self, s: &State, delta: f64) -> bool {
        delta > 0.0 || (self.sticking && s[ROD_VX..=OMEGA].iter().any(|v| *v != 0.0))
    }

    /// `true` when the engaged point is beyond the rod's end: it has slid off.
    fn slid_off(&self, s: &State) -> bool {
        let (delta, arm, _, _) = self.geometry_of(s);
        self.engaged(s, delta) && self.on_rod(arm) <= 0.0
    }

    /// Whether the force acts in a fixed-step run, which passes through approach, contact and
    /// departure: engaged and on the rod.
    fn acting(&self, s: &State, delta: f64, arm: f64) -> bool {
        self.engaged(s, delta) && self.on_rod(arm) > 0.0
    }

    /// The time derivative of the state. `switched`: the force acts only while in contact
    /// (fixed-step integrators); otherwise the contact branch is used everywhere (the
    /// event-driven integrator, which stops at the contact's end).
    fn derivative(&self, s: &State, switched: bool) -> State {
        let (delta, arm, n, rate) = self.geometry_of(s);
        let acting = !switched || self.acting(s, delta, arm);
        let force = if acting {
            self.k * delta + self.damping * rate
        } else {
            0.0
        };
        let mut d = [0.0; 12];
        d[X] = s[VX];
        d[Y] = s[VY];
        d[THETA] = s[OMEGA];
        d[VX] = -force * n[0] / self.m;
        d[VY] = -force * n[1] / self.m;
        match self.pivot {
            None => {
                d[ROD_X] = s[ROD_VX];
                d[ROD_Y] = s[ROD_VY];
                d[ROD_VX] = force * n[0] / self.rod_mass;
                d[ROD_VY] = force * n[1] / self.rod_mass;
                d[OMEGA] = arm * force / self.inertia;
            }
            Some(p) => {
                let alpha = (arm - p) * force / self.axis_inertia();
                d[OMEGA] = alpha;
                if acting {
                    // Reaction R = M c'' - f n, with c'' the centre's acceleration about p.
                    let w2 = s[OMEGA] * s[OMEGA];
                    let centre_acc = match self.geometry {
                        Geometry::Frozen => [-p * alpha, 0.0],
                        Geometry::Exact => {
                            let (sin, cos) = s[THETA].sin_cos();
                            [
                                -p * alpha * cos + p * w2 * sin,
                                p * alpha * sin + p * w2 * cos,
                            ]
                        }
                    };
                    d[PIVOT_X] = self.rod_mass * centre_acc[0] - force * n[0];
                    d[PIVOT_X + 1] = self.rod_mass * centre_acc[1] - force * n[1];
                }
            }
        }
        d
    }

    /// The outputs (v, V, omega) of a state: the projectile's and the rod centre's x-velocity
    /// and the rod's angular velocity.
    fn outputs(&self, s: &State) -> [f64; 3] {
        [s[VX], self.rod_centre(s).1[0], s[OMEGA]]
    }

    /// Kinetic energy plus the spring's energy while the contact acts.
    fn energy(&self, s: &State) -> f64 {
        let (_, centre_v) = self.rod_centre(s);
        let kinetic = 0.5 * self.m * (s[VX] * s[VX] + s[VY] * s[VY])
            + 0.5 * self.rod_mass * (centre_v[0] * centre_v[0] + centre_v[1] * centre_v[1])
            + 0.5 * self.inertia * s[OMEGA] * s[OMEGA];
        let (delta, arm, _, _) = self.geometry_of(s);
        if self.acting(s, delta, arm) {
            kinetic + 0.5 * self.k * delta * delta
        } else {
            kinetic
        }
    }
}
