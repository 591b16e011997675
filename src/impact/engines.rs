//! What physics engines compute for an impact, named: each engine's velocity-level contact
//! solver as a profile (the law it converges to, its iterations, its restitution threshold, how
//! it combines two bodies' coefficients, whether a contact that only touches takes part), and,
//! where one step of it is rational, its exact replay ([`super::solve_several`] with
//! [`super::Model::Engine`]).
//!
//! Three engines' steps are replayed exactly, from their sources (the citations are in
//! [`Engine::source`]; `tests/oracles/engine-laws.md` derives each and an independent oracle,
//! `tests/oracles/engine_laws.py`, replays them too): pymunk 7 (Chipmunk), Box2D 2.3 and Bullet
//! 3 as pybullet runs it. Box2D v3 and Rapier solve a soft contact whose coefficients hold
//! 2 pi (a spring's angular frequency): no rational replay exists, and their profiles answer
//! with the law their substeps converge to, `split`.
//!
//! A scene's contact carries its own e and mu: they are taken as the engine's combined values
//! (a harness sets each body's coefficients so that the engine's rule gives them), and the
//! rule is reported, not applied.

use super::law::Law;
use crate::field::Q;
use num_traits::{One, Zero};
use std::fmt;

/// An engine whose contact solver rodimpact names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Engine {
    /// pymunk 7 (Chipmunk 7.0.3, the Munk2D 2.0.1 fork): projected Gauss-Seidel, 10 iterations.
    Pymunk7,
    /// Box2D 2.3 (pybox2d 2.3.10): friction rows first, 2-point block solver, 8 iterations.
    Box2d23,
    /// Box2D v3: soft substeps, then a restitution pass without friction.
    Box2d3,
    /// Rapier 0.36: soft substeps, then a restitution pass without friction.
    Rapier036,
    /// Bullet 3 as pybullet 3.2.7 runs it: sequential impulses, 50 iterations with early exit.
    Bullet3,
}

/// How an engine combines two bodies' coefficients into a contact's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Combine {
    /// The larger.
    Max,
    /// The product.
    Product,
    /// The square root of the product.
    GeometricMean,
    /// The average.
    Average,
}

impl Combine {
    /// `max`, `product`, `sqrt of product` or `average`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Combine;
    /// assert_eq!(Combine::GeometricMean.name(), "sqrt of product");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Combine::Max => "max",
            Combine::Product => "product",
            Combine::GeometricMean => "sqrt of product",
            Combine::Average => "average",
        }
    }
}

impl Engine {
    /// Every engine, in the order they are reported.
    pub const ALL: [Engine; 5] = [
        Engine::Pymunk7,
        Engine::Box2d23,
        Engine::Box2d3,
        Engine::Rapier036,
        Engine::Bullet3,
    ];

    /// `pymunk-7`, `box2d-2.3`, `box2d-3`, `rapier-0.36` or `bullet-3`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::Engine;
    /// assert_eq!(Engine::Box2d23.name(), "box2d-2.3");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Engine::Pymunk7 => "pymunk-7",
            Engine::Box2d23 => "box2d-2.3",
            Engine::Box2d3 => "box2d-3",
            Engine::Rapier036 => "rapier-0.36",
            Engine::Bullet3 => "bullet-3",
        }
    }

    /// The law the engine's iterations converge to.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::impact::{Engine, Law};
    /// assert_eq!(Engine::Rapier036.law(), Law::Split);
    /// ```
    pub fn law(self) -> Law {
        match self {
            Engine::Pymunk7 | Engine::Box2d23 | Engine::Bullet3 => Law::LcpNewton,
            Engine::Box2d3 | Engine::Rapier036 => Law::Split,
        }
    }

    /// Whether rodimpact replays one step of the engine exactly (its step is rational).
    pub fn replayed(self) -> bool {
        matches!(self, Engine::Pymunk7 | Engine::Box2d23 | Engine::Bullet3)
    }

    /// The velocity iterations of one step (the engine's default, or the harness's setting).
    pub fn iterations(self) -> u32 {
        match self {
            Engine::Pymunk7 => 10,
            Engine::Box2d23 => 8,
            Engine::Box2d3 | Engine::Rapier036 => 4,
            Engine::Bullet3 => 50,
        }
    }

    /// The restitution velocity threshold of the engine's units (m/s): below it an approach
    /// does not bounce (0: none).
    pub fn threshold(self) -> Q {
        match self {
            Engine::Box2d23 | Engine::Box2d3 => Q::one(),
            // Chipmunk has none; Rapier bounces new contacts only; the harnesses set pybullet's
            // restitutionVelocityThreshold to 0.
            Engine::Pymunk7 | Engine::Rapier036 | Engine::Bullet3 => Q::zero(),
        }
    }

    /// How two bodies' restitution and friction coefficients combine.
    pub fn combine(self) -> (Combine, Combine) {
        match self {
            Engine::Pymunk7 | Engine::Bullet3 => (Combine::Product, Combine::Product),
            Engine::Box2d23 | Engine::Box2d3 => (Combine::Max, Combine::GeometricMean),
            Engine::Rapier036 => (Combine::Average, Combine::Average),
        }
    }

    /// What the engine does with a contact that only touches (zero approach).
    pub fn touching(self) -> &'static str {
        match self {
            Engine::Pymunk7 => {
                "not a contact between a circle and a circle or a segment (they collide only \
                 when they overlap), a contact otherwise: a touching cradle is solved one pair \
                 at a time"
            }
            Engine::Box2d23 | Engine::Box2d3 | Engine::Rapier036 | Engine::Bullet3 => {
                "a contact, without restitution (no approach speed to reverse)"
            }
        }
    }

    /// Where the engine's source shows what it computes (repository, version, file and
    /// function).
    pub fn source(self) -> &'static str {
        match self {
            Engine::Pymunk7 => {
                "Munk2D 2.0.1 (pymunk 7.3.1): src/cpArbiter.c cpArbiterPreStep (bounce = e vn, \
                 no threshold) and cpArbiterApplyImpulse (normal and friction from one \
                 velocity, friction bound mu times the new normal impulse); src/cpSpace.c \
                 iterations = 10; src/cpCollision.c circle contacts only on overlap"
            }
            Engine::Box2d23 => {
                "Box2D v2.3.0 (pybox2d 2.3.10): Box2D/Dynamics/Contacts/b2ContactSolver.cpp \
                 InitializeVelocityConstraints (velocityBias = -e vRel when vRel < \
                 -b2_velocityThreshold) and SolveVelocityConstraints (friction first, bound \
                 mu times the normal impulse, then the normal rows, the 2-point block solver); \
                 Box2D/Common/b2Settings.h b2_velocityThreshold = 1"
            }
            Engine::Box2d3 => {
                "Box2D v3.1: src/solver.c b2SolverStep (substeps of a soft contact, relax \
                 iterations) and src/contact_solver.c b2ApplyRestitution (vn = -e vn0 after the \
                 substeps, no friction)"
            }
            Engine::Rapier036 => {
                "Rapier 0.35-0.36: src/dynamics/solver/contact_constraint/ (soft contact, \
                 substeps) and the restitution pass solve_restitution (normal rows only), PR \
                 #114"
            }
            Engine::Bullet3 => {
                "bullet3 (pybullet 3.2.7): src/BulletDynamics/ConstraintSolver/\
                 btSequentialImpulseConstraintSolver.cpp (all normal rows, then all friction \
                 rows, per iteration; restitution below restitutionVelocityThreshold is 0; one \
                 friction direction from the lateral velocity); \
                 examples/SharedMemory/PhysicsServerCommandProcessor.cpp (50 iterations, \
                 least-squares residual threshold 1e-7)"
            }
        }
    }
}

impl fmt::Display for Engine {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An engine with the settings of one harness: the restitution threshold in the scene's units
/// (an engine's threshold divided by the harness's scale of the world), and for Bullet the
/// plane the scene lies in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Profile {
    /// The engine.
    pub engine: Engine,
    /// The restitution threshold in the scene's units.
    pub threshold: Q,
    /// Bullet only: the scene is the x-y plane of the 3D world (`true`), or the x-z plane, the
    /// scene extruded along y (`false`, the harnesses' choice): where the contact starts
    /// without slip, Bullet's one friction direction is then out of the plane.
    pub plane_xy: bool,
    /// The settings as given after the engine's name (`scale=16`), for its name.
    pub settings: String,
}

impl Profile {
    /// The engine with its own defaults.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, impact::{Engine, Profile}};
    /// assert_eq!(Profile::of(Engine::Box2d23).threshold, q(1, 1));
    /// ```
    pub fn of(engine: Engine) -> Profile {
        Profile {
            engine,
            threshold: engine.threshold(),
            plane_xy: false,
            settings: String::new(),
        }
    }

    /// A profile by name: an engine's name, optionally with settings after a colon:
    /// `box2d-2.3:scale=16` (the world scaled by 16: the threshold is 1/16 of the scene's
    /// units), `:threshold=T` (in the scene's units), `bullet-3:plane=xy`.
    ///
    /// # Errors
    /// What is wrong with the name, in words.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::q, impact::{Engine, Profile}};
    /// let p = Profile::parse("box2d-2.3:scale=16")?;
    /// assert_eq!((p.engine, &p.threshold), (Engine::Box2d23, &q(1, 16)));
    /// assert_eq!(p.to_string(), "box2d-2.3:scale=16");
    /// assert!(Profile::parse("havok").is_err());
    /// # Ok::<(), String>(())
    /// ```
    pub fn parse(text: &str) -> Result<Profile, String> {
        let (name, settings) = text.trim().split_once(':').unwrap_or((text.trim(), ""));
        let engine = Engine::ALL
            .into_iter()
            .find(|e| e.name() == name)
            .ok_or_else(|| {
                format!(
                    "expected one of {}, got '{}'",
                    Engine::ALL.map(Engine::name).join(", "),
                    crate::echo::echo(name)
                )
            })?;
        let mut profile = Profile::of(engine);
        profile.settings = settings.split_whitespace().collect();
        let mut seen: Vec<&str> = Vec::new();
        for setting in settings.split(',').filter(|s| !s.trim().is_empty()) {
            let (key, value) = setting.split_once('=').unwrap_or((setting, ""));
            let key = key.trim();
            if seen.contains(&key) {
                return Err(format!("{key} is given twice"));
            }
            if matches!(key, "threshold" | "scale") {
                if engine.threshold().is_zero() {
                    return Err(format!(
                        "{name} has no restitution threshold (threshold= and scale= apply to box2d-2.3 and box2d-3)"
                    ));
                }
                if seen.iter().any(|k| matches!(*k, "threshold" | "scale")) {
                    return Err("threshold= and scale= both set the threshold: give one".into());
                }
            }
            seen.push(key);
            let number = || {
                crate::number::parse(value)
                    .ok()
                    .filter(|x| *x >= Q::zero())
                    .ok_or_else(|| {
                        format!(
                            "{key} takes a number >= 0, got '{}'",
                            crate::echo::echo(value)
                        )
                    })
            };
            match key {
                "threshold" => profile.threshold = number()?,
                "scale" => {
                    let scale = number()?;
                    if scale.is_zero() {
                        return Err("scale must be > 0".into());
                    }
                    profile.threshold = engine.threshold() / scale;
                }
                "plane" if engine == Engine::Bullet3 => {
                    profile.plane_xy = match value.trim() {
                        "xy" => true,
                        "xz" => false,
                        other => {
                            return Err(format!(
                                "plane takes xy or xz, got '{}'",
                                crate::echo::echo(other)
                            ));
                        }
                    };
                }
                other => {
                    let takes = match engine {
                        Engine::Bullet3 => "plane=xy|xz",
                        Engine::Box2d23 | Engine::Box2d3 => "threshold=T or scale=S",
                        Engine::Pymunk7 | Engine::Rapier036 => "no settings",
                    };
                    return Err(format!(
                        "{name} takes {takes}, got '{}'",
                        crate::echo::echo(other)
                    ));
                }
            }
        }
        Ok(profile)
    }
}

impl fmt::Display for Profile {
    /// The name as given: `box2d-2.3:scale=16`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.engine.name())?;
        if !self.settings.is_empty() {
            write!(f, ":{}", self.settings)?;
        }
        Ok(())
    }
}
