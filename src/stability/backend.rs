//! The backends compared by the stability report: f64 and f32 with each [`FloatFormula`], the
//! outward-rounded interval, and exact rationals; each evaluated and measured on one scene,
//! each through its named [`Route`].

use super::{Accuracy, condition};
use crate::field::big::{RBig, to_q};
use crate::field::{Field, Interval, Q};
use crate::scene::Motion;
use crate::scene::{Params, Scene, Support};
use crate::solve::fast::closed_form::closed_form;
use crate::solve::fast::float::{FloatFormula, Real};
use crate::solve::{self, Route};
use num_traits::{Signed, Zero};
use std::sync::OnceLock;

/// A number format and the formula evaluated in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Backend {
    /// IEEE binary64, by [`Route::Float`].
    F64(FloatFormula),
    /// IEEE binary32, by [`Route::Float`].
    F32(FloatFormula),
    /// Outward-rounded f64 intervals, by [`Route::ClosedForm`].
    Interval,
    /// Exact rationals, by [`Route::ClosedForm`] (the reference).
    Exact,
}

/// The exact answer for a free-rod scene, with its condition numbers.
///
/// The answer is computed by the closed form over dashu's rationals ([`RBig`]), whose Lehmer
/// GCD keeps the sweep's scenes of hundreds of digits cheap, and the measurements run there
/// too; the [`Backend::Exact`] row computes the same closed form over [`Q`] (num-rational), so
/// the two big-number libraries check each other.
#[derive(Debug, Clone)]
pub struct Reference {
    /// Exact (v, V, omega).
    pub motion: Motion<Q>,
    /// The exact scene inputs.
    pub params: Params<Q>,
    /// `motion` over dashu, as the measurements use it.
    exact: Motion<RBig>,
    /// `params` over dashu.
    big_params: Params<RBig>,
    /// The condition numbers, computed on first use and shared by every backend: for an `e`
    /// the format holds exactly (index 0) and for one it rounds (index 1).
    conditions: [OnceLock<Motion<Option<RBig>>>; 2],
}

/// Two references are equal when their scenes and answers are: whether the condition numbers
/// have been computed yet does not matter.
impl PartialEq for Reference {
    fn eq(&self, other: &Reference) -> bool {
        (&self.motion, &self.params) == (&other.motion, &other.params)
    }
}

impl Reference {
    /// The exact reference of a free-rod scene (`None` for a pivoted rod).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, field::q, stability::Reference};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// assert_eq!(Reference::of(&s).unwrap().motion.v, q(3, 11));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(scene: &Scene) -> Option<Reference> {
        let params = scene.params::<Q>();
        if params.support != Support::Free || scene.oblique().is_some() {
            return None;
        }
        let big_params = scene.params::<RBig>();
        let exact = closed_form(&big_params)?;
        Some(Reference {
            motion: exact.as_ref().map(to_q),
            params,
            exact,
            big_params,
            conditions: Default::default(),
        })
    }

    /// Whether the scene is in range for the format `T`: every nonzero input (m, M, I, a, v0,
    /// e) and every nonzero exact output (v, V, omega) is a normal number of `T` once rounded.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, field::q, number::parse, stability::Reference};
    /// let s = Scene::builder(q(1, 1), parse("1e200").unwrap()).build()?;
    /// let reference = Reference::of(&s).unwrap();
    /// assert!(reference.in_range::<f64>());
    /// assert!(!reference.in_range::<f32>()); // M = 1e200 overflows f32
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn in_range<T: Real>(&self) -> bool {
        let (p, x) = (&self.params, &self.motion);
        [
            &p.m,
            &p.rod_mass,
            &p.inertia,
            &p.a,
            &p.v0,
            &p.e,
            &x.v,
            &x.rod_v,
            &x.omega,
        ]
        .iter()
        .all(|value| value.is_zero() || T::from_rational(&value.abs()).normal())
    }
}

impl Backend {
    /// Every backend, in report order.
    pub const ALL: [Backend; 8] = [
        Backend::F64(FloatFormula::Naive),
        Backend::F64(FloatFormula::Sq),
        Backend::F64(FloatFormula::Scomp),
        Backend::F32(FloatFormula::Naive),
        Backend::F32(FloatFormula::Sq),
        Backend::F32(FloatFormula::Scomp),
        Backend::Interval,
        Backend::Exact,
    ];

    /// The route the backend computes by: the float formula, or the closed form.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{solve::{fast::float::FloatFormula, Route}, stability::Backend};
    /// assert_eq!(Backend::F32(FloatFormula::Scomp).route(), Route::Float(FloatFormula::Scomp));
    /// assert_eq!(Backend::Interval.route(), Route::ClosedForm);
    /// ```
    pub fn route(self) -> Route {
        match self {
            Backend::F64(formula) | Backend::F32(formula) => Route::Float(formula),
            Backend::Interval | Backend::Exact => Route::ClosedForm,
        }
    }

    /// Name in reports: `f64/sq`, `f32/naive`, `interval`, `exact`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{solve::fast::float::FloatFormula, stability::Backend};
    /// assert_eq!(Backend::F64(FloatFormula::Sq).name(), "f64/sq");
    /// ```
    pub fn name(self) -> String {
        match self {
            Backend::F64(f) => format!("f64/{}", f.name()),
            Backend::F32(f) => format!("f32/{}", f.name()),
            Backend::Interval => "interval".into(),
            Backend::Exact => "exact".into(),
        }
    }

    /// The unit roundoff of the format, exactly (0 for exact).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::stability::Backend;
    /// assert_eq!(Backend::Interval.unit_roundoff().to_string(), "1/9007199254740992");
    /// ```
    pub fn unit_roundoff(self) -> Q {
        match self {
            Backend::F64(_) | Backend::Interval => <f64 as Real>::unit_roundoff(),
            Backend::F32(_) => <f32 as Real>::unit_roundoff(),
            Backend::Exact => Q::zero(),
        }
    }

    /// The condition numbers for this format: the e terms count when e is not a float of it.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, field::q, stability::Backend, solve::fast::float::FloatFormula};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).e(q(1, 10)).build()?;
    /// let r = rodimpact::stability::Reference::of(&s).unwrap();
    /// let with_e = Backend::F64(FloatFormula::Sq).condition(&r).rod_v.unwrap();
    /// assert!(with_e > Backend::Exact.condition(&r).rod_v.unwrap());
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn condition(self, reference: &Reference) -> Motion<Option<Q>> {
        self.big_condition(reference)
            .as_ref()
            .map(|c| c.as_ref().map(to_q))
    }

    /// [`Backend::condition`] over dashu, computed once per reference and `e_rounds`.
    fn big_condition(self, reference: &Reference) -> &Motion<Option<RBig>> {
        let e = &reference.params.e;
        let e_rounds = match self {
            Backend::F64(_) | Backend::Interval => f64::from_rational(e).to_exact(),
            Backend::F32(_) => f32::from_rational(e).to_exact(),
            Backend::Exact => Some(e.clone()),
        }
        .as_ref()
            != Some(e);
        reference.conditions[usize::from(e_rounds)]
            .get_or_init(|| condition(&reference.big_params, e_rounds))
    }

    /// Evaluates `scene` from its exact inputs ([`FloatFormula::eval_scene`]) and measures (v, V,
    /// omega) against the reference; for the interval also whether each enclosure holds the
    /// exact value. `None` for a pivoted rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::Scene, field::q, stability::{Backend, Reference}, solve::fast::float::FloatFormula};
    /// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
    /// let r = Reference::of(&s).unwrap();
    /// let (m, encloses) = Backend::F64(FloatFormula::Sq).measure(&s, &r).unwrap();
    /// assert!(m.v.ratio.unwrap() <= 4.0);
    /// assert!(encloses);
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn measure(self, scene: &Scene, reference: &Reference) -> Option<(Motion<Accuracy>, bool)> {
        let cond = self.big_condition(reference);
        let u = RBig::from_rational(&self.unit_roundoff());
        let exact = reference.exact.as_ref().zip(cond.as_ref());
        let route = self.route();
        let floats = |x: Motion<f64>| {
            let measured = x.zip(exact.clone());
            let measure = |(x, (exact, cond)): (f64, (&RBig, &Option<RBig>))| {
                Accuracy::of_big(x, exact, cond.as_ref(), &u)
            };
            (measured.map(measure), true)
        };
        match self {
            Backend::F64(_) => Some(floats(solve::with::<f64>(scene, route).ok()?.after)),
            // f32 -> f64 is exact, so the measurement is unchanged.
            Backend::F32(_) => Some(floats(
                solve::with::<f32>(scene, route).ok()?.after.map(f64::from),
            )),
            Backend::Interval => {
                let x = solve::with::<Interval>(scene, route).ok()?.after;
                let encloses = x
                    .iter()
                    .zip(reference.motion.iter())
                    .all(|(x, e)| x.contains(e));
                let measured = x.zip(exact).map(|(x, (exact, cond))| {
                    Accuracy::of_big_interval(&x, exact, cond.as_ref(), &u)
                });
                Some((measured, encloses))
            }
            Backend::Exact => {
                let x = solve::with::<Q>(scene, route).ok()?.after;
                let measured = x
                    .zip(reference.motion.as_ref())
                    .map(|(x, exact)| Accuracy::of_exact(&x, exact));
                Some((measured, true))
            }
        }
    }
}
