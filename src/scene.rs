//! Scenes: the projectile, the rod, the impact point, the collision law and the support.
//!
//! A [`Scene`] is exact (every number in [`Q`]) and valid by construction: it is built only by
//! [`Scene::builder`] or [`SceneInput::build`], which check the physical constraints and name the
//! offending field. [`Scene::params`] lifts it into any [`Field`] for the solver.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, RatFn};
use crate::number;
use crate::units::{Dimension, parse_si};
use num_traits::{One, Signed, Zero};
use std::fmt;

/// How the rod's mass is distributed (always symmetric about its centre).
#[derive(Debug, Clone, PartialEq)]
pub enum RodInertia {
    /// A uniform rod: I = M l^2 / 3.
    Uniform,
    /// An ideal dumbbell, all the mass at the two ends: I = M l^2.
    Dumbbell,
    /// Given radius of gyration r_G: I = M r_G^2, with 0 < r_G <= l.
    Gyration(Q),
    /// Given moment of inertia about the centre: 0 < I <= M l^2.
    Moment(Q),
}

impl RodInertia {
    /// The moment of inertia about the rod's centre for rod mass `mass` and half-length `l`, in
    /// any field: the one definition of the four mass distributions (I = M l^2/3, M l^2,
    /// M r_G^2, or I as given). Over rational functions it gives the symbolic inertia.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::{q, RatFn};
    /// assert_eq!(RodInertia::Uniform.moment(&q(3, 1), &q(2, 1)), q(4, 1));
    /// assert_eq!(RodInertia::Gyration(q(1, 2)).moment(&q(3, 1), &q(2, 1)), q(3, 4));
    /// let (big_m, l) = (RatFn::symbol("M"), RatFn::symbol("l"));
    /// assert_eq!(RodInertia::Uniform.moment(&big_m, &l).to_string(), "1/3*M*l^2");
    /// ```
    pub fn moment<F: Field>(&self, mass: &F, l: &F) -> F {
        match self {
            RodInertia::Uniform => mass.clone() * l * l / F::from_i64(3),
            RodInertia::Dumbbell => mass.clone() * l * l,
            RodInertia::Gyration(r) => gyration_moment(mass, &F::from_rational(r)),
            RodInertia::Moment(i) => F::from_rational(i),
        }
    }

    /// [`RodInertia::moment`] over the rationals, the same value, computed as one fraction
    /// (the products of the numerators over those of the denominators) reduced once on machine
    /// words: num-rational reduces after every product with num-bigint's GCD, which cost more
    /// than a whole batch row's solve.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::q;
    /// let (big_m, l) = (q(93531, 184198), q(104159, 300644));
    /// for rod in [RodInertia::Uniform, RodInertia::Dumbbell, RodInertia::Gyration(q(3, 7))] {
    ///     assert_eq!(rod.exact_moment(&big_m, &l), rod.moment(&big_m, &l));
    /// }
    /// ```
    pub fn exact_moment(&self, mass: &Q, l: &Q) -> Q {
        let product = |x: &Q, y: &Q, divisor: u32| {
            crate::field::int::reduce(
                x.numer() * y.numer() * y.numer(),
                x.denom() * y.denom() * y.denom() * divisor,
            )
        };
        match self {
            RodInertia::Uniform => product(mass, l, 3),
            RodInertia::Dumbbell => product(mass, l, 1),
            RodInertia::Gyration(r) => product(mass, r, 1),
            RodInertia::Moment(i) => i.clone(),
        }
    }

    /// Parses the `--rod` forms `uniform`, `dumbbell`, `rg=Q`, `I=Q` (a radius may carry a
    /// length unit, a moment of inertia `kg*m^2`).
    ///
    /// # Errors
    /// `rod: ...` naming the accepted forms, or the number's own parse error.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::RodInertia;
    /// use rodimpact::field::q;
    /// assert_eq!(RodInertia::parse("rg=1/2").unwrap(), RodInertia::Gyration(q(1, 2)));
    /// assert_eq!(RodInertia::parse("rg=25 cm").unwrap(), RodInertia::Gyration(q(1, 4)));
    /// assert!(RodInertia::parse("steel").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self, Error> {
        let text = text.trim();
        match text {
            "uniform" => Ok(RodInertia::Uniform),
            "dumbbell" => Ok(RodInertia::Dumbbell),
            _ => {
                if let Some(r) = text.strip_prefix("rg=") {
                    Ok(RodInertia::Gyration(parse_si("rod", r, Dimension::Length)?))
                } else if let Some(i) = text.strip_prefix("I=") {
                    Ok(RodInertia::Moment(parse_si(
                        "rod",
                        i,
                        Dimension::MomentOfInertia,
                    )?))
                } else {
                    Err(Error::new(
                        "rod",
                        ErrorKind::Invalid(format!(
                            "expected uniform, dumbbell, rg=<radius> or I=<inertia>, got '{}'",
                            crate::echo::echo(text)
                        )),
                    ))
                }
            }
        }
    }
}

impl fmt::Display for RodInertia {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RodInertia::Uniform => write!(f, "uniform"),
            RodInertia::Dumbbell => write!(f, "dumbbell"),
            RodInertia::Gyration(r) => write!(f, "rg={r}"),
            RodInertia::Moment(i) => write!(f, "I={i}"),
        }
    }
}

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
}

/// What an oblique, frictional scene adds to the paper's (docs/conventions.md, "Oblique and
/// frictional impacts"): the projectile's velocity along the rod, Coulomb friction at the
/// contact, a disc projectile with its spin, and the rod's motion before the impact.
///
/// A scene has one only when some part of it differs from the paper's scene; a plain scene
/// reports exactly what it always did.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Oblique {
    /// The projectile's velocity along the rod (+y) before the impact.
    pub v0t: Q,
    /// Coulomb friction coefficient at the contact (>= 0).
    pub mu: Q,
    /// The disc projectile, or `None` for a point projectile.
    pub disc: Option<Disc>,
    /// The rod's motion before the impact (zero: at rest).
    pub rod_before: RodMotion<Q>,
}

/// A solid disc projectile (I = m r^2/2) sliding on the table, its rim touching the rod.
#[derive(Debug, Clone, PartialEq)]
pub struct Disc<F = Q> {
    /// The disc's radius r (> 0).
    pub radius: F,
    /// The disc's angular velocity before the impact, counterclockwise seen from above
    /// (about z = x cross y).
    pub spin: F,
}

/// The rod's motion: the velocity of its centre across (`v`, along x) and along (`vt`, along
/// y) the rod, and its angular velocity `omega` (the sign of docs/conventions.md: the point at
/// y moves along x with `v + omega y`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RodMotion<F> {
    /// Centre velocity along x.
    pub v: F,
    /// Centre velocity along the rod (y).
    pub vt: F,
    /// Angular velocity.
    pub omega: F,
}

impl Oblique {
    /// Lifts the oblique part into the field `F`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Oblique;
    /// use rodimpact::field::q;
    /// let o = Oblique { mu: q(1, 2), ..Default::default() };
    /// assert_eq!(o.params::<f64>().mu, 0.5);
    /// ```
    pub fn params<F: Field>(&self) -> ObliqueParams<F> {
        let lift = F::from_rational;
        ObliqueParams {
            v0t: lift(&self.v0t),
            mu: lift(&self.mu),
            disc: self.disc.as_ref().map(|d| Disc {
                radius: lift(&d.radius),
                spin: lift(&d.spin),
            }),
            rod_before: RodMotion {
                v: lift(&self.rod_before.v),
                vt: lift(&self.rod_before.vt),
                omega: lift(&self.rod_before.omega),
            },
        }
    }
}

/// The oblique part of a scene lifted into a field `F` (see [`Oblique`]), or built directly
/// with symbolic entries for a proof.
#[derive(Debug, Clone, PartialEq)]
pub struct ObliqueParams<F> {
    /// The projectile's velocity along the rod before the impact.
    pub v0t: F,
    /// Coulomb friction coefficient.
    pub mu: F,
    /// The disc projectile, if any.
    pub disc: Option<Disc<F>>,
    /// The rod's motion before the impact (for a pivoted rod only `omega` may be non-zero;
    /// its centre then moves with `v = -omega p`).
    pub rod_before: RodMotion<F>,
}

impl<F: Field> ObliqueParams<F> {
    /// The rod's motion before the impact as the impulse equations see it: as given for a
    /// free rod; on a pivot at p the centre moves with -omega0 p and not along the rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::{Oblique, RodMotion, Support};
    /// use rodimpact::field::{q, Q};
    /// let o = Oblique { rod_before: RodMotion { v: q(0, 1), vt: q(0, 1), omega: q(-2, 1) }, ..Default::default() };
    /// let r = o.params::<Q>().rod_moving(&Support::Pivot(q(1, 2)));
    /// assert_eq!(r, RodMotion { v: q(1, 1), vt: q(0, 1), omega: q(-2, 1) });
    /// ```
    pub fn rod_moving(&self, support: &Support<F>) -> RodMotion<F> {
        let given = &self.rod_before;
        match support {
            Support::Free => given.clone(),
            Support::Pivot(pivot) => RodMotion {
                v: -(pivot.clone() * &given.omega),
                vt: F::zero(),
                omega: given.omega.clone(),
            },
        }
    }

    /// The slip before the impact, u_t: the velocity along the rod of the projectile's
    /// contact point (a disc's rim adds spin times radius) minus the struck point's.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::{Disc, Oblique, RodMotion, Support};
    /// use rodimpact::field::{q, Q};
    /// let o = Oblique {
    ///     v0t: q(1, 1),
    ///     disc: Some(Disc { radius: q(1, 10), spin: q(3, 1) }),
    ///     rod_before: RodMotion { v: q(0, 1), vt: q(1, 2), omega: q(0, 1) },
    ///     ..Default::default()
    /// };
    /// assert_eq!(o.params::<Q>().slip(&Support::Free), q(4, 5)); // 1 + 3/10 - 1/2
    /// ```
    pub fn slip(&self, support: &Support<F>) -> F {
        let rim = |d: &Disc<F>| d.spin.clone() * &d.radius;
        self.v0t.clone() + &self.disc.as_ref().map_or_else(F::zero, rim)
            - &self.rod_moving(support).vt
    }
}

/// The refusal of `--spin` without `--radius`.
///
/// # Examples
/// ```
/// assert_eq!(rodimpact::scene::spin_without_disc().to_string(),
///            "spin: a point projectile has no spin: give the disc's --radius too");
/// ```
pub fn spin_without_disc() -> Error {
    Error::new(
        "spin",
        ErrorKind::Conflict("a point projectile has no spin: give the disc's --radius too".into()),
    )
}

/// The refusal of a scene whose projectile does not approach the struck point; `is` says what
/// the approach speed is (`is -1, not > 0`).
///
/// # Examples
/// ```
/// use rodimpact::scene::no_approach;
/// assert!(no_approach("is 0, not > 0").to_string().starts_with("v0: no approach at the contact point"));
/// ```
pub fn no_approach(is: &str) -> Error {
    Error::out_of_range(
        "v0",
        format!(
            "no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), {is}"
        ),
    )
}

/// `I = M r^2`: the moment of inertia about the centre of a rod of mass `mass` with radius of
/// gyration `r`, over any field (a symbol `r` as well as a number: [`RodInertia::moment`] is this
/// for a rational `r`).
///
/// # Examples
/// ```
/// use rodimpact::{field::RatFn, scene::gyration_moment};
/// let i = gyration_moment(&RatFn::symbol("M"), &RatFn::symbol("r_G"));
/// assert_eq!(i.to_string(), "M*r_G^2");
/// ```
pub fn gyration_moment<F: Field>(mass: &F, r: &F) -> F {
    mass.clone() * r * r
}

/// The numbers the solver needs, lifted into a field `F`.
///
/// Built from a validated [`Scene`] by [`Scene::params`], or directly (for example with symbolic
/// entries over [`crate::field::RatFn`]) when a proof needs all parameter values at once.
#[derive(Debug, Clone, PartialEq)]
pub struct Params<F> {
    /// Projectile mass m.
    pub m: F,
    /// Rod mass M.
    pub rod_mass: F,
    /// Rod half-length l.
    pub half_length: F,
    /// Moment of inertia I about the rod's centre.
    pub inertia: F,
    /// Signed impact distance a from the rod's centre.
    pub a: F,
    /// Projectile speed before the impact.
    pub v0: F,
    /// Coefficient of restitution e.
    pub e: F,
    /// Free rod or pivot position.
    pub support: Support<F>,
}

impl Params<RatFn> {
    /// The general free-rod scene in symbols: `m`, `M`, `l`, `a`, `v0` and the given moment of
    /// inertia and restitution (themselves symbols or expressions), the one symbolic scene the
    /// claims are decided in.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::{Field, RatFn}, scene::{Params, RodInertia}, solve::linear::solve};
    /// let (big_m, l) = (RatFn::symbol("M"), RatFn::symbol("l"));
    /// let p = Params::symbolic(RodInertia::Uniform.moment(&big_m, &l), RatFn::from_i64(1));
    /// let omega = solve(&p).unwrap().after.omega;
    /// assert_eq!(omega.to_string(), "6*a*m*v0/(M*l^2 + 3*a^2*m + l^2*m)");
    /// ```
    pub fn symbolic(inertia: RatFn, e: RatFn) -> Params<RatFn> {
        Params {
            m: RatFn::symbol("m"),
            rod_mass: RatFn::symbol("M"),
            half_length: RatFn::symbol("l"),
            inertia,
            a: RatFn::symbol("a"),
            v0: RatFn::symbol("v0"),
            e,
            support: Support::Free,
        }
    }
}

impl<F: Field> Params<F> {
    /// The moment of inertia about the point the angular-momentum balance is taken about: the
    /// centre (I) for a free rod, the pivot (I + M p^2) for a pivoted one.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::{q, Q};
    /// let s = Scene::builder(q(1, 1), q(3, 1)).pivot(q(-1, 1)).build().unwrap();
    /// assert_eq!(s.params::<Q>().inertia_about_axis(), q(4, 1)); // 1 + 3*1^2
    /// ```
    pub fn inertia_about_axis(&self) -> F {
        match &self.support {
            Support::Free => self.inertia.clone(),
            Support::Pivot(p) => self.inertia.clone() + &(self.rod_mass.clone() * p * p),
        }
    }

    /// The reference point of the angular-momentum balance: 0 (the centre) or the pivot p.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::Scene;
    /// use rodimpact::field::{q, Q};
    /// let s = Scene::builder(q(1, 1), q(3, 1)).pivot(q(-1, 2)).build().unwrap();
    /// assert_eq!(s.params::<Q>().axis(), q(-1, 2));
    /// ```
    pub fn axis(&self) -> F {
        match &self.support {
            Support::Free => F::zero(),
            Support::Pivot(p) => p.clone(),
        }
    }
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
        self.oblique
            .clone()
            .unwrap_or_default()
            .params::<Q>()
            .rod_moving(&self.support)
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
        if self.oblique.is_none() {
            // The rod at rest: no arithmetic (this runs for every scene built).
            return self.v0.clone();
        }
        let rod = self.rod_before();
        &self.v0 - (rod.v + rod.omega * &self.a)
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
            v0: self.approach(),
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
        Ok(Scene { a, ..self.clone() })
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
        let scene = Scene {
            m: self.m,
            rod_mass: self.rod_mass,
            half_length: self.half_length,
            rod: self.rod,
            a,
            v0: self.v0,
            e: self.e,
            support: self.support,
            oblique,
        };
        let approach = scene.approach();
        if !approach.is_positive() {
            return Err(no_approach(&format!("is {approach}, not > 0")));
        }
        Ok(scene)
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

/// A scene as the user typed it: every number still a string, each parsed with its field name.
///
/// This is what the command line and scene files fill in; [`SceneInput::build`] turns it into a
/// [`Scene`] or one error naming the field.
#[derive(Debug, Clone, Default)]
pub struct SceneInput {
    /// Projectile mass (required).
    pub m: Option<String>,
    /// Rod mass (required).
    pub rod_mass: Option<String>,
    /// Half-length l (default 1).
    pub l: Option<String>,
    /// Full length L = 2l, the textbook alternative to `l`.
    pub length: Option<String>,
    /// Impact distance from the centre (default l).
    pub a: Option<String>,
    /// Impact distance from the nearer end, a = l - d, the textbook alternative to `a`.
    pub from_end: Option<String>,
    /// Projectile speed (default 1).
    pub v0: Option<String>,
    /// `uniform`, `dumbbell`, `rg=Q` or `I=Q` (default uniform).
    pub rod: Option<String>,
    /// Coefficient of restitution (default 1).
    pub e: Option<String>,
    /// Pivot position, if the rod is pivoted.
    pub pivot: Option<String>,
    /// The projectile's velocity along the rod (default 0).
    pub v0t: Option<String>,
    /// Coulomb friction coefficient at the contact (default 0).
    pub mu: Option<String>,
    /// Radius of a disc projectile (default: a point projectile).
    pub radius: Option<String>,
    /// The disc's spin before the impact, counterclockwise seen from above (needs `radius`).
    pub spin: Option<String>,
    /// The rod centre's velocity across the rod before the impact (default 0).
    pub rod_v: Option<String>,
    /// The rod centre's velocity along the rod before the impact (default 0).
    pub rod_vt: Option<String>,
    /// The rod's angular velocity before the impact (default 0).
    pub rod_omega: Option<String>,
}

impl SceneInput {
    /// The oblique inputs by name, in the order they are read: `v0t`, `mu`, `radius`, `spin`,
    /// `rod-v`, `rod-vt`, `rod-omega`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// let input = SceneInput { mu: Some("1/4".into()), ..Default::default() };
    /// let given: Vec<_> = input.oblique_inputs().into_iter().filter(|(_, t)| t.is_some()).map(|(k, _)| k).collect();
    /// assert_eq!(given, ["mu"]);
    /// ```
    pub fn oblique_inputs(&self) -> [(&'static str, &Option<String>); 7] {
        [
            ("v0t", &self.v0t),
            ("mu", &self.mu),
            ("radius", &self.radius),
            ("spin", &self.spin),
            ("rod-v", &self.rod_v),
            ("rod-vt", &self.rod_vt),
            ("rod-omega", &self.rod_omega),
        ]
    }

    /// The first oblique input given, if any (the scene is then oblique or frictional).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// assert_eq!(SceneInput { spin: Some("3".into()), ..Default::default() }.first_oblique(), Some("spin"));
    /// assert_eq!(SceneInput::default().first_oblique(), None);
    /// ```
    pub fn first_oblique(&self) -> Option<&'static str> {
        self.oblique_inputs()
            .into_iter()
            .find_map(|(key, text)| text.is_some().then_some(key))
    }

    /// The slot of the input named `key` (the command-line flag without dashes: `m`, `M`, `l`,
    /// `length`, `a`, `from-end`, `v0`, `rod`, `e`, `pivot`, `v0t`, `mu`, `radius`, `spin`,
    /// `rod-v`, `rod-vt`, `rod-omega`), or `None` for an unknown key.
    ///
    /// Scene files, batch columns and tests fill a scene by name through this one map.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// let mut input = SceneInput::default();
    /// *input.slot("M").unwrap() = Some("3".into());
    /// assert_eq!(input.rod_mass.as_deref(), Some("3"));
    /// assert!(input.slot("mass").is_none());
    /// ```
    pub fn slot(&mut self, key: &str) -> Option<&mut Option<String>> {
        Some(match key {
            "m" => &mut self.m,
            "M" => &mut self.rod_mass,
            "l" => &mut self.l,
            "length" => &mut self.length,
            "a" => &mut self.a,
            "from-end" => &mut self.from_end,
            "v0" => &mut self.v0,
            "rod" => &mut self.rod,
            "e" => &mut self.e,
            "pivot" => &mut self.pivot,
            "v0t" => &mut self.v0t,
            "mu" => &mut self.mu,
            "radius" => &mut self.radius,
            "spin" => &mut self.spin,
            "rod-v" => &mut self.rod_v,
            "rod-vt" => &mut self.rod_vt,
            "rod-omega" => &mut self.rod_omega,
            _ => return None,
        })
    }

    /// Parses and validates every field. Numbers may carry a unit of their field's dimension
    /// (`100 g`, `120 cm`, `36 km/h`), converted exactly to SI.
    ///
    /// # Errors
    /// The first bad field: missing `m`/`M`, a number that does not parse, conflicting
    /// alternatives (`l` with `length`, `a` with `from-end`), or a violated constraint.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// use rodimpact::field::q;
    /// let input = SceneInput {
    ///     m: Some("0.25".into()),
    ///     rod_mass: Some("3/4".into()),
    ///     length: Some("2".into()),
    ///     from_end: Some("1/2".into()),
    ///     ..Default::default()
    /// };
    /// let s = input.build().unwrap();
    /// assert_eq!((s.m(), s.half_length(), s.a()), (&q(1, 4), &q(1, 1), &q(1, 2)));
    /// let grams = SceneInput { m: Some("100 g".into()), rod_mass: Some("1.5kg".into()), ..Default::default() };
    /// assert_eq!(grams.build().unwrap().m(), &q(1, 10));
    /// let bad = SceneInput { m: Some("1/0".into()), rod_mass: Some("1".into()), ..Default::default() };
    /// assert_eq!(bad.build().unwrap_err().to_string(), "m: division by zero");
    /// ```
    pub fn build(&self) -> Result<Scene, Error> {
        let m = required("m", &self.m)?;
        let rod_mass = required("M", &self.rod_mass)?;
        let mut builder = Scene::builder(m, rod_mass);
        let half_length = match (&self.l, &self.length) {
            (Some(_), Some(_)) => {
                return Err(conflict("length", "give either --l or --length, not both"));
            }
            (Some(l), None) => number_of("l", l)?,
            (None, Some(len)) => {
                let len = number_of("length", len)?;
                if !len.is_positive() {
                    return Err(Error::out_of_range(
                        "length",
                        format!("must be > 0, got {len}"),
                    ));
                }
                len / Q::from_integer(2.into())
            }
            (None, None) => Q::one(),
        };
        builder = builder.half_length(half_length.clone());
        match (&self.a, &self.from_end) {
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "from-end",
                    "give either --a or --from-end, not both",
                ));
            }
            (Some(a), None) => builder = builder.a(number_of("a", a)?),
            (None, Some(d)) => {
                let d = number_of("from-end", d)?;
                if d.is_negative() || d > &half_length * Q::from_integer(2.into()) {
                    return Err(Error::out_of_range(
                        "from-end",
                        format!(
                            "distance from the end must lie in [0, 2l] = [0, {}], got {d}",
                            &half_length * Q::from_integer(2.into())
                        ),
                    ));
                }
                builder = builder.a(&half_length - d);
            }
            (None, None) => {}
        }
        if let Some(v0) = &self.v0 {
            builder = builder.v0(number_of("v0", v0)?);
        }
        if let Some(rod) = &self.rod {
            builder = builder.rod(RodInertia::parse(rod)?);
        }
        if let Some(e) = &self.e {
            builder = builder.e(number_of("e", e)?);
        }
        if let Some(p) = &self.pivot {
            builder = builder.pivot(number_of("pivot", p)?);
        }
        let optional = |key: &str, text: &Option<String>| -> Result<Option<Q>, Error> {
            text.as_deref().map(|t| number_of(key, t)).transpose()
        };
        if let Some(v0t) = optional("v0t", &self.v0t)? {
            builder = builder.v0t(v0t);
        }
        if let Some(mu) = optional("mu", &self.mu)? {
            builder = builder.mu(mu);
        }
        match (
            optional("radius", &self.radius)?,
            optional("spin", &self.spin)?,
        ) {
            (Some(radius), spin) => builder = builder.disc(radius, spin.unwrap_or_default()),
            (None, Some(_)) => return Err(spin_without_disc()),
            (None, None) => {}
        }
        let rod = [
            optional("rod-v", &self.rod_v)?,
            optional("rod-vt", &self.rod_vt)?,
            optional("rod-omega", &self.rod_omega)?,
        ];
        if rod.iter().any(Option::is_some) {
            let [v, vt, omega] = rod.map(Option::unwrap_or_default);
            builder = builder.rod_before(v, vt, omega);
        }
        builder.build()
    }
}

/// The dimension of the numeric scene input named `key` (`m`, `M`, `l`, `length`, `a`,
/// `from-end`, `v0`, `e`, `pivot`, `v0t`, `mu`, `radius`, `spin`, `rod-v`, `rod-vt`,
/// `rod-omega`): what a unit written after its number must measure.
///
/// # Examples
/// ```
/// use rodimpact::{scene::dimension_of, units::Dimension};
/// assert_eq!(dimension_of("from-end"), Dimension::Length);
/// assert_eq!(dimension_of("e"), Dimension::Pure);
/// ```
pub fn dimension_of(key: &str) -> Dimension {
    match key {
        "m" | "M" => Dimension::Mass,
        "l" | "length" | "a" | "from-end" | "pivot" | "radius" => Dimension::Length,
        "v0" | "v0t" | "rod-v" | "rod-vt" => Dimension::Speed,
        "spin" | "rod-omega" => Dimension::AngularSpeed,
        _ => Dimension::Pure,
    }
}

/// The numeric scene input `key`, with an optional unit of its dimension, in SI.
fn number_of(key: &str, text: &str) -> Result<Q, Error> {
    parse_si(key, text, dimension_of(key))
}

fn required(field: &str, text: &Option<String>) -> Result<Q, Error> {
    match text {
        Some(t) => number_of(field, t),
        None => Err(Error::new(field, ErrorKind::Missing)),
    }
}

/// Parses one number, naming `field` in the error.
///
/// # Examples
/// ```
/// use rodimpact::scene::parse_field;
/// assert_eq!(parse_field("a", "0.5").unwrap().to_string(), "1/2");
/// assert_eq!(parse_field("a", "").unwrap_err().to_string(), "a: empty number");
/// ```
pub fn parse_field(field: &str, text: &str) -> Result<Q, Error> {
    number::parse(text).map_err(|kind| Error::new(field, kind))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;
    use proptest::prelude::*;

    /// A rational of up to ~150 bits either side (so that the products pass 256 bits and take
    /// the big-integer reduction too), any sign for the numerator.
    fn rational() -> impl Strategy<Value = Q> {
        (any::<i64>(), any::<u64>(), 1u64.., 0u32..3).prop_map(|(n, big, d, scale)| {
            let n = num_bigint::BigInt::from(n) * num_bigint::BigInt::from(big).pow(scale);
            Q::new(n, num_bigint::BigInt::from(d))
        })
    }

    proptest! {
        /// The machine-word moment of inertia is the generic one, value and representation.
        #[test]
        fn exact_moment_is_the_moment(mass in rational(), l in rational(), r in rational()) {
            for rod in [RodInertia::Uniform, RodInertia::Dumbbell, RodInertia::Gyration(r.clone()), RodInertia::Moment(r.clone())] {
                let fast = rod.exact_moment(&mass, &l);
                let slow = rod.moment(&mass, &l);
                prop_assert_eq!((fast.numer(), fast.denom()), (slow.numer(), slow.denom()));
            }
        }
    }

    fn input(pairs: &[(&str, &str)]) -> SceneInput {
        let mut s = SceneInput::default();
        for (k, v) in pairs {
            *s.slot(k).expect("a known test key") = Some(v.to_string());
        }
        s
    }

    #[test]
    fn inertia_of_each_rod_kind() {
        let cases = [
            ("uniform", "3", "2", q(4, 1)),
            ("dumbbell", "3", "2", q(12, 1)),
            ("rg=1", "3", "2", q(3, 1)),
            ("I=5/2", "3", "2", q(5, 2)),
        ];
        for (rod, big_m, l, want) in cases {
            let s = input(&[("m", "1"), ("M", big_m), ("l", l), ("rod", rod)])
                .build()
                .unwrap();
            assert_eq!(s.inertia(), want, "rod {rod}");
        }
    }

    #[test]
    fn bad_inputs_name_their_field() {
        let cases: &[(&[(&str, &str)], &str)] = &[
            (&[("M", "1")], "m: required, but not given"),
            (&[("m", "1")], "M: required, but not given"),
            (&[("m", "-1"), ("M", "1")], "m: must be > 0, got -1"),
            (&[("m", "1"), ("M", "0")], "M: must be > 0, got 0"),
            (
                &[("m", "1"), ("M", "1"), ("l", "0")],
                "l: must be > 0, got 0",
            ),
            (
                &[("m", "1"), ("M", "1"), ("v0", "-2")],
                "v0: must be > 0, got -2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "2")],
                "a: must lie on the rod, |a| <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "-3/2")],
                "a: must lie on the rod, |a| <= l = 1, got -3/2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("e", "3/2")],
                "e: coefficient of restitution must lie in [0, 1], got 3/2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("e", "-1")],
                "e: coefficient of restitution must lie in [0, 1], got -1",
            ),
            (
                &[("m", "1"), ("M", "1"), ("pivot", "2")],
                "pivot: must lie on the rod, |pivot| <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "rg=2")],
                "rod: radius of gyration must satisfy 0 < r_G <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "rg=0")],
                "rod: radius of gyration must satisfy 0 < r_G <= l = 1, got 0",
            ),
            (
                &[("m", "1"), ("M", "2"), ("rod", "I=3")],
                "rod: moment of inertia must satisfy 0 < I <= M l^2 = 2, got 3",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "wood")],
                "rod: expected uniform, dumbbell, rg=<radius> or I=<inertia>, got 'wood'",
            ),
            (
                &[("m", "1"), ("M", "1"), ("l", "1"), ("length", "2")],
                "length: give either --l or --length, not both",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "1"), ("from-end", "0")],
                "from-end: give either --a or --from-end, not both",
            ),
            (
                &[("m", "1"), ("M", "1"), ("from-end", "3")],
                "from-end: distance from the end must lie in [0, 2l] = [0, 2], got 3",
            ),
            (
                &[("m", "1"), ("M", "1"), ("length", "-2")],
                "length: must be > 0, got -2",
            ),
            (&[("m", "1/0"), ("M", "1")], "m: division by zero"),
        ];
        for (pairs, want) in cases {
            let err = input(pairs).build().unwrap_err();
            assert_eq!(err.to_string(), *want, "input {pairs:?}");
        }
    }

    #[test]
    fn textbook_conveniences_convert_exactly() {
        let s = input(&[("m", "1"), ("M", "1"), ("length", "3"), ("from-end", "0.5")])
            .build()
            .unwrap();
        assert_eq!(s.half_length(), &q(3, 2));
        assert_eq!(s.a(), &q(1, 1));
        let far = input(&[("m", "1"), ("M", "1"), ("length", "3"), ("from-end", "3")])
            .build()
            .unwrap();
        assert_eq!(far.a(), &q(-3, 2));
    }

    #[test]
    fn defaults_are_those_of_solve() {
        let s = input(&[("m", "1"), ("M", "2")]).build().unwrap();
        assert_eq!(
            (s.half_length(), s.a(), s.v0(), s.e()),
            (&q(1, 1), &q(1, 1), &q(1, 1), &q(1, 1))
        );
        assert_eq!(s.rod(), &RodInertia::Uniform);
        assert_eq!(s.support(), &Support::Free);
    }
}
