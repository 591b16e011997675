//! The paper's scenes: the projectile, the rod, the impact point, the collision law and the
//! support; a view of the general model ([`Scene::system`] writes a scene as bodies and a
//! contact, which [`crate::impact`] answers), with the paper's own vocabulary: the motion
//! (v, V, omega), the groups r, s, q, D, and the scene's balances.
//!
//! A [`Scene`] is exact (every number in [`Q`]) and valid by construction: it is built only by
//! [`Scene::builder`] or [`SceneInput::build`], which check the physical constraints and name the
//! offending field. [`Scene::params`] lifts it into any [`Field`] for the solver.
//!
//! | file | what it holds |
//! |---|---|
//! | `mod.rs` | [`Scene`], [`Support`] and [`SceneBuilder`] with the validation |
//! | `rod.rs` | [`RodInertia`]: the four mass distributions |
//! | `oblique.rs` | [`Oblique`]: what an oblique scene adds, and its refusals |
//! | `params.rs` | [`Params`], [`ObliqueParams`], [`Disc`], [`RodMotion`]: the scene's numbers in any field |
//! | `keys.rs` | [`SCENE_KEYS`]: the one table of scene inputs (flags, CSV columns, TOML keys, help) |
//! | `input.rs` | [`SceneInput`]: a scene as typed, parsed field by field with units |
//! | `motion.rs` | [`Motion`] (v, V, omega), [`Groups`], the scene's momentum, angular momentum and energy |
//! | `system.rs` | [`Scene::system`]: the scene as the general model's bodies and contact |

mod input;
mod keys;
mod motion;
mod oblique;
mod params;
mod rod;
mod system;

pub use input::{SceneInput, dimension_of, parse_field};
pub use keys::{SCENE_KEYS, SceneKey, flag_help, key_index, scene_key};
pub use motion::{Groups, Motion, angular_momentum, kinetic_energy, linear_momentum};
pub use oblique::{Oblique, no_approach, spin_without_disc};
pub use params::{Disc, ObliqueParams, Params, RodMotion};
pub use rod::{RodInertia, gyration_moment};
pub use system::{PROJECTILE, ROD};

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q};
use num_traits::{One, Signed, Zero};

/// How the rod is held.
#[derive(Debug, Clone, PartialEq)]
pub enum Support<F = Q> {
    /// Free on the frictionless table (the paper's case).
    Free,
    /// On a fixed frictionless pivot at signed position `p` along the rod (|p| <= l).
    Pivot(F),
}

/// A validated, exact scene.
///
/// Conventions (docs/conventions.md): the projectile moves along +x with speed `v0` and hits the
/// rod, which lies along y with its centre at the origin, at signed distance `a` from the centre.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    m: Q,
    rod_mass: Q,
    half_length: Q,
    rod: RodInertia,
    a: Q,
    v0: Q,
    e: Q,
    support: Support,
    oblique: Option<Oblique>,
    /// [`Scene::approach`], worked out once as the scene is validated.
    approach: Q,
}

impl Scene {
    /// Starts a scene with projectile mass `m` and rod mass `rod_mass`; everything else takes
    /// the defaults of `rodimpact solve` (l = 1, v0 = 1, uniform rod, elastic, free, a = l).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build().unwrap();
    /// assert_eq!(s.a(), &q(1, 2));
    /// assert_eq!(s.inertia(), q(1, 3));
    /// ```
    pub fn builder(m: Q, rod_mass: Q) -> SceneBuilder {
        SceneBuilder {
            m,
            rod_mass,
            half_length: Q::one(),
            rod: RodInertia::Uniform,
            a: None,
            v0: Q::one(),
            e: Q::one(),
            support: Support::Free,
            oblique: Oblique::default(),
        }
    }

    /// Projectile mass m.
    pub fn m(&self) -> &Q {
        &self.m
    }
    /// Rod mass M.
    pub fn rod_mass(&self) -> &Q {
        &self.rod_mass
    }
    /// Rod half-length l (the rod is 2l long).
    pub fn half_length(&self) -> &Q {
        &self.half_length
    }
    /// The rod's mass distribution.
    pub fn rod(&self) -> &RodInertia {
        &self.rod
    }
    /// Signed impact distance from the rod's centre.
    pub fn a(&self) -> &Q {
        &self.a
    }
    /// Projectile speed before the impact.
    pub fn v0(&self) -> &Q {
        &self.v0
    }
    /// Coefficient of restitution.
    pub fn e(&self) -> &Q {
        &self.e
    }
    /// Free rod or pivot.
    pub fn support(&self) -> &Support {
        &self.support
    }
    /// The oblique and frictional part, or `None` for the paper's scene.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
    /// assert!(s.oblique().is_none());
    /// let t = Scene::builder(q(1, 1), q(1, 1)).v0t(q(1, 2)).build().unwrap();
    /// assert_eq!(t.oblique().unwrap().v0t, q(1, 2));
    /// ```
    pub fn oblique(&self) -> Option<&Oblique> {
        self.oblique.as_ref()
    }

    /// The rod's motion before the impact as it enters the impulse equations: for a pivoted
    /// rod spinning with omega0 the centre moves with -omega0 p.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).pivot(q(-1, 1)).rod_before(q(0, 1), q(0, 1), q(-1, 2)).build().unwrap();
    /// assert_eq!(s.rod_before().v, q(-1, 2)); // -omega0 p
    /// ```
    pub fn rod_before(&self) -> RodMotion<Q> {
        // The given motion alone, not the whole oblique part copied and lifted (14 rationals:
        // 2,000 instructions of an oblique scene's solve, which asks for it twice).
        self.oblique
            .as_ref()
            .map_or_else(RodMotion::default, |o| o.rod_before.on(&self.support))
    }

    /// The approach speed at the contact: the projectile's normal velocity minus that of the
    /// struck point of the rod, v0 - (V0 + omega0 a). The paper's v0 for a rod at rest.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).a(q(1, 2)).rod_before(q(1, 1), q(0, 1), q(2, 1)).build().unwrap();
    /// assert_eq!(s.approach(), q(1, 1)); // 3 - (1 + 2 * 1/2)
    /// ```
    pub fn approach(&self) -> Q {
        self.approach.clone()
    }

    /// [`Scene::approach`] worked out: `v0` itself for a rod at rest (no arithmetic: this
    /// runs for every scene built).
    fn approach_of(v0: &Q, a: &Q, oblique: Option<&Oblique>, support: &Support) -> Q {
        match oblique {
            None => v0.clone(),
            Some(o) => {
                // Most oblique scenes have the rod at rest: no rational arithmetic on zeros
                // (each operation's GCDs cost as much as on any other value).
                let rod = o.rod_before.on(support);
                let mut approach = v0.clone();
                if !rod.v.is_zero() {
                    approach -= rod.v;
                }
                if !rod.omega.is_zero() {
                    approach -= rod.omega * a;
                }
                approach
            }
        }
    }

    /// The paper's scene with the same bodies, impact point, law and support, the rod at rest
    /// and the projectile arriving at the approach speed [`Scene::approach`]: the normal
    /// impulse problem of this scene. For a plain scene it is the scene itself.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).v0(q(3, 1)).mu(q(1, 2)).rod_before(q(1, 1), q(0, 1), q(0, 1)).build().unwrap();
    /// let n = s.normal_problem();
    /// assert_eq!((n.v0(), n.oblique()), (&q(2, 1), None));
    /// ```
    pub fn normal_problem(&self) -> Scene {
        Scene {
            v0: self.approach.clone(),
            oblique: None,
            ..self.clone()
        }
    }

    /// Moment of inertia about the rod's centre.
    pub fn inertia(&self) -> Q {
        self.rod.exact_moment(&self.rod_mass, &self.half_length)
    }

    /// The same scene hit at another point `a` (validated).
    ///
    /// # Errors
    /// `a: ...` when |a| > l.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
    /// assert_eq!(s.with_a(q(1, 4)).unwrap().a(), &q(1, 4));
    /// assert!(s.with_a(q(2, 1)).is_err());
    /// ```
    pub fn with_a(&self, a: Q) -> Result<Scene, Error> {
        check_on_rod("a", &a, &self.half_length)?;
        let approach = Scene::approach_of(&self.v0, &a, self.oblique.as_ref(), &self.support);
        Ok(Scene {
            a,
            approach,
            ..self.clone()
        })
    }

    /// Lifts the scene's numbers into the field `F` for the solver.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
    /// let p = s.params::<f64>();
    /// assert!((p.inertia - 1.0 / 3.0).abs() < 1e-16);
    /// ```
    pub fn params<F: Field>(&self) -> Params<F> {
        let lift = F::from_rational;
        Params {
            m: lift(&self.m),
            rod_mass: lift(&self.rod_mass),
            half_length: lift(&self.half_length),
            inertia: lift(&self.inertia()),
            a: lift(&self.a),
            v0: lift(&self.v0),
            e: lift(&self.e),
            support: match &self.support {
                Support::Free => Support::Free,
                Support::Pivot(p) => Support::Pivot(lift(p)),
            },
        }
    }
}

/// Builds a [`Scene`] from exact numbers, validating on [`SceneBuilder::build`].
#[derive(Debug, Clone)]
pub struct SceneBuilder {
    m: Q,
    rod_mass: Q,
    half_length: Q,
    rod: RodInertia,
    a: Option<Q>,
    v0: Q,
    e: Q,
    support: Support,
    oblique: Oblique,
}

impl SceneBuilder {
    /// The projectile's velocity along the rod (+y) before the impact (default 0).
    pub fn v0t(mut self, v0t: Q) -> Self {
        self.oblique.v0t = v0t;
        self
    }
    /// Coulomb friction coefficient at the contact (default 0).
    pub fn mu(mut self, mu: Q) -> Self {
        self.oblique.mu = mu;
        self
    }
    /// A solid disc projectile of radius r spinning counterclockwise (seen from above) with
    /// `spin` before the impact.
    pub fn disc(mut self, radius: Q, spin: Q) -> Self {
        self.oblique.disc = Some(Disc { radius, spin });
        self
    }
    /// The rod's motion before the impact: centre velocity `v` across and `vt` along the rod,
    /// angular velocity `omega` (a pivoted rod takes only `omega`).
    pub fn rod_before(mut self, v: Q, vt: Q, omega: Q) -> Self {
        self.oblique.rod_before = RodMotion { v, vt, omega };
        self
    }
    /// Rod half-length l.
    pub fn half_length(mut self, l: Q) -> Self {
        self.half_length = l;
        self
    }
    /// Mass distribution of the rod.
    pub fn rod(mut self, rod: RodInertia) -> Self {
        self.rod = rod;
        self
    }
    /// Signed impact distance from the centre (default: l, the end).
    pub fn a(mut self, a: Q) -> Self {
        self.a = Some(a);
        self
    }
    /// Projectile speed before the impact.
    pub fn v0(mut self, v0: Q) -> Self {
        self.v0 = v0;
        self
    }
    /// Coefficient of restitution (1 elastic, 0 sticking).
    pub fn e(mut self, e: Q) -> Self {
        self.e = e;
        self
    }
    /// A fixed pivot at signed position p along the rod.
    pub fn pivot(mut self, p: Q) -> Self {
        self.support = Support::Pivot(p);
        self
    }

    /// Checks every constraint and returns the scene.
    ///
    /// # Errors
    /// The first violated constraint, naming its field: m, M, l, v0 > 0; 0 < r_G <= l (`rod`);
    /// 0 < I <= M l^2 (`rod`); |a| <= l (`a`); 0 <= e <= 1 (`e`); |p| <= l (`pivot`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::q;
    /// let err = Scene::builder(q(-1, 1), q(1, 1)).build().unwrap_err();
    /// assert_eq!(err.to_string(), "m: must be > 0, got -1");
    /// ```
    pub fn build(self) -> Result<Scene, Error> {
        check_positive("m", &self.m)?;
        check_positive("M", &self.rod_mass)?;
        check_positive("l", &self.half_length)?;
        check_positive("v0", &self.v0)?;
        let l = &self.half_length;
        match &self.rod {
            RodInertia::Gyration(r) => {
                if !r.is_positive() || r > l {
                    return Err(Error::out_of_range(
                        "rod",
                        format!("radius of gyration must satisfy 0 < r_G <= l = {l}, got {r}"),
                    ));
                }
            }
            RodInertia::Moment(i) => {
                let max = &self.rod_mass * l * l;
                if !i.is_positive() || *i > max {
                    return Err(Error::out_of_range(
                        "rod",
                        format!("moment of inertia must satisfy 0 < I <= M l^2 = {max}, got {i}"),
                    ));
                }
            }
            RodInertia::Uniform | RodInertia::Dumbbell => {}
        }
        let a = self.a.unwrap_or_else(|| l.clone());
        check_on_rod("a", &a, l)?;
        if self.e.is_negative() || self.e > Q::one() {
            return Err(Error::out_of_range(
                "e",
                format!(
                    "coefficient of restitution must lie in [0, 1], got {}",
                    self.e
                ),
            ));
        }
        if let Support::Pivot(p) = &self.support {
            check_on_rod("pivot", p, l)?;
        }
        let oblique = check_oblique(self.oblique, &self.support)?;
        let approach = Scene::approach_of(&self.v0, &a, oblique.as_ref(), &self.support);
        if !approach.is_positive() {
            return Err(no_approach(&format!("is {approach}, not > 0")));
        }
        Ok(Scene {
            m: self.m,
            rod_mass: self.rod_mass,
            half_length: self.half_length,
            rod: self.rod,
            a,
            v0: self.v0,
            e: self.e,
            support: self.support,
            oblique,
            approach,
        })
    }
}

/// Validates the oblique part (mu >= 0, radius > 0, a pivoted rod's centre not moving on
/// its own) and keeps it only when it differs from the paper's scene.
fn check_oblique(o: Oblique, support: &Support) -> Result<Option<Oblique>, Error> {
    if o.mu.is_negative() {
        return Err(Error::out_of_range(
            "mu",
            format!("friction coefficient must be >= 0, got {}", o.mu),
        ));
    }
    if let Some(d) = &o.disc {
        check_positive("radius", &d.radius)?;
    }
    if let Support::Pivot(_) = support {
        for (field, x) in [("rod-v", &o.rod_before.v), ("rod-vt", &o.rod_before.vt)] {
            if !x.is_zero() {
                return Err(Error::new(
                    field,
                    ErrorKind::Conflict(
                        "a pivoted rod's centre moves only by turning about the pivot; give --rod-omega only".into(),
                    ),
                ));
            }
        }
    }
    Ok((o != Oblique::default()).then_some(o))
}

fn conflict(field: &str, why: &str) -> Error {
    Error::new(field, ErrorKind::Conflict(why.into()))
}

fn check_positive(field: &str, x: &Q) -> Result<(), Error> {
    if x.is_positive() {
        Ok(())
    } else {
        Err(Error::out_of_range(field, format!("must be > 0, got {x}")))
    }
}

fn check_on_rod(field: &str, x: &Q, l: &Q) -> Result<(), Error> {
    if x.abs() <= *l {
        Ok(())
    } else {
        Err(Error::out_of_range(
            field,
            format!("must lie on the rod, |{field}| <= l = {l}, got {x}"),
        ))
    }
}
