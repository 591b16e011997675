//! The time-resolved compliant-contact model (docs/stability.md): a penalty spring of stiffness k
//! (and, for e < 1, a dashpot) acts while the projectile's point penetrates the rod's line.
//!
//! Two forms: [`Geometry::Frozen`] keeps the normal and the lever arm fixed (a linear oscillator
//! with mass mu_eff = m M_eff / (m + M_eff): for every k it returns the impulsive result, so its
//! only error is the integrator's); [`Geometry::Exact`] lets the rod turn during contact, so the
//! normal outputs converge to the impulsive values as O(1/k) and the lateral velocity as
//! O(k^-1/2). This is a float simulation; its references come from the exact solver, converted
//! to f64 at the end.

mod integrate;
mod sweep;

pub use integrate::{Integrator, MAX_STEPS, Run, simulate, steps_needed};
pub use sweep::{SweepRow, fit_slope, sweep_k};

use crate::error::{Error, ErrorKind};
use crate::field::Field;
use crate::scene::{Scene, Support};
use crate::solve::solve;

/// Which contact geometry the simulation uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Normal and lever arm frozen at the impact configuration: a linear oscillator.
    Frozen,
    /// The rod turns during contact: normal n(theta), lever arm (p - c) . u(theta).
    Exact,
}

/// The state: projectile (x, y), rod centre (X, Y), rod angle theta (clockwise, so a hit at
/// a > 0 gives theta' > 0 as the impulsive omega), then the five velocities.
pub(crate) type State = [f64; 10];

/// A compliant contact built from an exact scene, in f64.
///
/// # Examples
/// ```
/// use rodimpact::contact::{Contact, Geometry};
/// use rodimpact::{field::q, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = Contact::new(&scene, 1e6, Geometry::Frozen)?;
/// assert!((c.reference()[2] - 12.0 / 11.0).abs() < 1e-15); // omega = 12/11
/// # Ok::<(), rodimpact::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    m: f64,
    rod_mass: f64,
    inertia: f64,
    half_length: f64,
    a: f64,
    v0: f64,
    k: f64,
    damping: f64,
    zeta: f64,
    geometry: Geometry,
    reference: [f64; 3],
}

/// Converts an exact input to a positive finite f64, or names the field.
fn to_f64(field: &str, x: &crate::field::Q) -> Result<f64, Error> {
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

impl Contact {
    /// The model for `scene` (free rod, e > 0) with spring stiffness `k`. The dashpot is
    /// c = 2 zeta sqrt(k mu_eff) with zeta = -ln e / sqrt(pi^2 + ln^2 e), so that the frozen
    /// oscillator's restitution is exactly e.
    ///
    /// # Errors
    /// `pivot` (only a free rod is simulated), `e` (e = 0: a critically damped contact never
    /// separates), `stiffness` (k not a positive finite number), or an input outside f64.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::contact::{Contact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).e(q(0, 1)).build()?;
    /// assert_eq!(Contact::new(&scene, 1e6, Geometry::Exact).unwrap_err().field, "e");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn new(scene: &Scene, k: f64, geometry: Geometry) -> Result<Contact, Error> {
        if !matches!(scene.support(), Support::Free) {
            return Err(Error::new(
                "pivot",
                ErrorKind::Invalid("simulate models a free rod only".into()),
            ));
        }
        if !(k.is_finite() && k > 0.0) {
            return Err(Error::out_of_range(
                "stiffness",
                "must be a positive finite number",
            ));
        }
        let e = scene.e().nearest_f64();
        if e <= 0.0 {
            return Err(Error::out_of_range(
                "e",
                "must be > 0 for simulate (a critically damped contact never separates)",
            ));
        }
        let a = scene.a().nearest_f64();
        let exact = solve(&scene.params::<crate::field::Q>())
            .ok_or_else(|| Error::new("scene", ErrorKind::Invalid("singular".into())))?;
        let reference = [
            exact.after.v.nearest_f64(),
            exact.after.rod_v.nearest_f64(),
            exact.after.omega.nearest_f64(),
        ];
        let mut c = Contact {
            m: to_f64("m", scene.m())?,
            rod_mass: to_f64("M", scene.rod_mass())?,
            inertia: to_f64("rod", &scene.inertia())?,
            half_length: to_f64("l", scene.half_length())?,
            a,
            v0: to_f64("v0", scene.v0())?,
            k,
            damping: 0.0,
            zeta: 0.0,
            geometry,
            reference,
        };
        if !(a.is_finite() && reference.iter().all(|x| x.is_finite())) {
            return Err(Error::out_of_range(
                "a",
                "the scene is outside the f64 range the float simulation needs",
            ));
        }
        let log_e = e.ln();
        c.zeta = -log_e / (std::f64::consts::PI.powi(2) + log_e * log_e).sqrt();
        c.damping = 2.0 * c.zeta * (k * c.reduced_mass()).sqrt();
        Ok(c)
    }

    /// The impulsive result (v, V, omega) from the exact solver, rounded to f64.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::contact::{Contact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let r = Contact::new(&scene, 1e2, Geometry::Exact)?.reference();
    /// assert_eq!(r, [3.0 / 11.0, 8.0 / 11.0, 12.0 / 11.0]);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn reference(&self) -> [f64; 3] {
        self.reference
    }

    /// mu_eff = m M_eff / (m + M_eff), with M_eff = 1 / (1/M + a^2/I).
    fn reduced_mass(&self) -> f64 {
        let inv = 1.0 / self.m + 1.0 / self.rod_mass + self.a * self.a / self.inertia;
        1.0 / inv
    }

    /// Omega = sqrt(k / mu_eff), the contact's angular frequency (1/s).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::contact::{Contact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).build()?;
    /// let c = Contact::new(&scene, 8.0, Geometry::Frozen)?;
    /// assert!((c.frequency() - 4.0).abs() < 1e-15); // mu_eff = 1/2
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn frequency(&self) -> f64 {
        (self.k / self.reduced_mass()).sqrt()
    }

    /// T_c, the contact duration of the frozen oscillator: pi / (Omega sqrt(1 - zeta^2)).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::contact::{Contact, Geometry};
    /// use rodimpact::{field::q, scene::Scene};
    /// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(0, 1)).build()?;
    /// let c = Contact::new(&scene, 8.0, Geometry::Frozen)?;
    /// assert!((c.contact_time() - std::f64::consts::PI / 4.0).abs() < 1e-15);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn contact_time(&self) -> f64 {
        std::f64::consts::PI / (self.frequency() * (1.0 - self.zeta * self.zeta).sqrt())
    }

    /// The approach distance of fixed-step runs: l/10, so that contact begins off the step grid.
    fn gap(&self) -> f64 {
        self.half_length / 10.0
    }

    /// The state at rest before the approach: the projectile `gap` short of the rod line.
    fn start(&self, gap: f64) -> State {
        let mut s = [0.0; 10];
        s[0] = -gap;
        s[1] = self.a;
        s[5] = self.v0;
        s
    }

    /// (penetration delta, lever arm s, unit normal n) of the state.
    fn geometry_of(&self, s: &State) -> (f64, f64, [f64; 2]) {
        let (rx, ry) = (s[0] - s[2], s[1] - s[3]);
        match self.geometry {
            Geometry::Frozen => (rx - self.a * s[4], self.a, [1.0, 0.0]),
            Geometry::Exact => {
                let (sin, cos) = s[4].sin_cos();
                let n = [cos, -sin];
                (rx * n[0] + ry * n[1], rx * sin + ry * cos, n)
            }
        }
    }

    /// The event function: > 0 exactly while the point is in contact (penetrating, and within
    /// the rod's length in the exact form).
    fn gap_function(&self, s: &State) -> f64 {
        let (delta, arm, _) = self.geometry_of(s);
        match self.geometry {
            Geometry::Frozen => delta,
            Geometry::Exact => delta.min(self.half_length - arm.abs()),
        }
    }

    /// The time derivative of the state. `switched`: the force acts only while in contact
    /// (fixed-step integrators); otherwise the contact branch is used everywhere (the
    /// event-driven integrator, which stops at the separation event).
    fn derivative(&self, s: &State, switched: bool) -> State {
        let (delta, arm, n) = self.geometry_of(s);
        let rate = (s[5] - s[7]) * n[0] + (s[6] - s[8]) * n[1] - arm * s[9];
        let force = if !switched || self.gap_function(s) > 0.0 {
            self.k * delta + self.damping * rate
        } else {
            0.0
        };
        [
            s[5],
            s[6],
            s[7],
            s[8],
            s[9],
            -force * n[0] / self.m,
            -force * n[1] / self.m,
            force * n[0] / self.rod_mass,
            force * n[1] / self.rod_mass,
            arm * force / self.inertia,
        ]
    }

    /// Kinetic energy plus the spring's energy while in contact.
    fn energy(&self, s: &State) -> f64 {
        let kinetic = 0.5 * self.m * (s[5] * s[5] + s[6] * s[6])
            + 0.5 * self.rod_mass * (s[7] * s[7] + s[8] * s[8])
            + 0.5 * self.inertia * s[9] * s[9];
        let delta = self.geometry_of(s).0;
        if self.gap_function(s) > 0.0 {
            kinetic + 0.5 * self.k * delta * delta
        } else {
            kinetic
        }
    }
}
