//! The float-backend values of `solve --backend`, judged: each of v, V, omega in the float
//! format with its exact value, relative error and condition number, and the reasons it cannot
//! be trusted (none: `reliable`); or for the interval backend, its enclosure and whether it
//! holds the exact value. `crate::report::backend_json` renders them; `docs/stability.md`
//! explains the condition numbers and what `reliable` promises.

use super::{Accuracy, Backend, Class, Reference};
use crate::error::{Error, ErrorKind};
use crate::field::decimal;
use crate::field::{Interval, Q};
use crate::scene::Motion;
use crate::scene::Scene;
use crate::solve::fast::float::Real;
use crate::solve::{self, Solvable};
use num_traits::Zero;

/// A reliable float is within this many cond·u of the exact value (the stable formulas stay
/// within it on every in-range scene of the stability suite and sweeps).
///
/// # Examples
/// ```
/// use rodimpact::{report::backend_json, scene::Scene, field::q};
/// use rodimpact::{solve::fast::float::FloatFormula, stability::{Backend, ERROR_BOUND, judge}};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let j = backend_json(&judge(&s, Backend::F64(FloatFormula::Sq))?);
/// // omega = 12/11: error 7.40e-17 <= 4 cond u, cond = 2.91.
/// assert_eq!(ERROR_BOUND, 4);
/// assert_eq!((j["omega"]["rel_error"].as_str(), j["omega"]["reliable"].as_bool()),
///            (Some("7.40e-17"), Some(true)));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub const ERROR_BOUND: u32 = 4;

/// The values v, V, omega of `scene` solved in `backend` by its route, judged
/// ([`Backend::route`]: `solve --backend` passes the stable formula, route `float/sq`, evaluated
/// from the exact inputs; the interval runs the closed form).
///
/// A float value is `reliable` only when all of these hold: every input (m, M, I, a, v0, e)
/// is 0 or a normal number of the format; the exact value is 0 or a normal number of the
/// format; the problem is well conditioned, cond·u <= 1e-3; and the float's exact relative
/// error is at most [`ERROR_BOUND`] cond·u. Otherwise its doubts say what failed.
///
/// # Errors
/// A pivoted rod with a float backend (the float formulas and condition numbers cover the free
/// rod), or the exact backend (nothing to compare).
///
/// # Examples
/// ```
/// use rodimpact::{report::backend_json, scene::Scene, field::q, stability::{Backend, judge}};
/// use rodimpact::solve::fast::float::FloatFormula;
/// let s = Scene::builder(q(4, 7), q(1, 1)).a(q(1, 2)).build()?; // v = 0 exactly
/// let j = backend_json(&judge(&s, Backend::F64(FloatFormula::Sq))?);
/// assert_eq!(j["v"]["exact"], "0");
/// assert_eq!(j["v"]["reliable"], false);
/// assert!(j["v"]["because"].as_str().unwrap().starts_with("ill-conditioned: cond is infinite"));
/// assert_eq!(j["V"]["reliable"], true);
/// assert!(j["V"].get("because").is_none());
/// // a = 7.9e-343 underflows f64: nothing is reliable, and omega (2.37e-342) underflows too.
/// let a = rodimpact::number::parse("7.9e-343").expect("a number");
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(a).build()?;
/// let j = backend_json(&judge(&s, Backend::F64(FloatFormula::Sq))?);
/// assert_eq!(j["omega"]["float"], "0");
/// assert_eq!(j["omega"]["reliable"], false);
/// assert_eq!(
///     j["omega"]["because"],
///     "input a = 7.90e-343 underflows f64; the exact value 2.37e-342 underflows f64; \
///      error 1.00 exceeds 4 cond u = 1.78e-15"
/// );
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn judge(scene: &Scene, backend: Backend) -> Result<Judged, Error> {
    let refuse = |why: &str| Error::new("backend", ErrorKind::Invalid(why.into()));
    if backend == Backend::Exact {
        return Err(refuse("the exact backend has no float values"));
    }
    let Some(reference) = Reference::of(scene) else {
        return Err(refuse(
            "the float backends cover the free rod; drop --pivot or use --backend exact",
        ));
    };
    let exact = &reference.motion;
    let names = Motion::<Q>::NAMES;
    if backend == Backend::Interval {
        let x = solve::with::<Interval>(scene, backend.route())
            .expect("the closed form takes a free rod in intervals")
            .after;
        let enclosures = names
            .iter()
            .zip(x.iter().zip(exact.iter()))
            .map(|(name, (x, exact))| Enclosure {
                name,
                lower: x.lower().shortest(),
                upper: x.upper().shortest(),
                exact: exact.clone(),
                encloses: x.contains(exact),
            })
            .collect();
        return Ok(Judged::Interval(enclosures));
    }
    let (measured, _) = backend
        .measure(scene, &reference)
        .expect("a free rod is measured");
    let floats = match backend {
        Backend::F32(_) => shortest::<f32>(scene, backend),
        Backend::F64(_) => shortest::<f64>(scene, backend),
        Backend::Interval | Backend::Exact => unreachable!("handled above"),
    };
    let cond = backend.condition(&reference);
    let inputs = unrepresentable_inputs(backend, &reference);
    let rows = floats.zip(exact.as_ref().zip(measured.zip(cond)));
    let values = names
        .iter()
        .zip(rows.into_array())
        .map(|(name, (float, (exact, (measured, cond))))| {
            let mut doubts = inputs.clone();
            doubts.extend(doubts_about_output(
                backend,
                exact,
                &measured,
                cond.as_ref(),
            ));
            JudgedFloat {
                name,
                float,
                exact: exact.clone(),
                rel_error: measured.rel_error,
                cond,
                doubts,
            }
        })
        .collect();
    Ok(Judged::Float(values))
}

/// The values of a float backend, judged ([`judge`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Judged {
    /// The interval backend: each value's enclosure.
    Interval(Vec<Enclosure>),
    /// A float backend: each value in the float format.
    Float(Vec<JudgedFloat>),
}

/// One value of the interval backend.
#[derive(Debug, Clone, PartialEq)]
pub struct Enclosure {
    /// `v`, `V` or `omega`.
    pub name: &'static str,
    /// The lower and upper ends, as their shortest round-trip texts.
    pub lower: String,
    /// The upper end.
    pub upper: String,
    /// The exact value.
    pub exact: Q,
    /// Whether the interval holds it.
    pub encloses: bool,
}

/// One value of a float backend, judged.
#[derive(Debug, Clone, PartialEq)]
pub struct JudgedFloat {
    /// `v`, `V` or `omega`.
    pub name: &'static str,
    /// The float, as its shortest round-trip text.
    pub float: String,
    /// The exact value.
    pub exact: Q,
    /// Its exact relative error (`None`: infinite).
    pub rel_error: Option<Q>,
    /// The condition number (`None`: infinite).
    pub cond: Option<Q>,
    /// Why it cannot be trusted; empty when it is reliable.
    pub doubts: Vec<String>,
}

/// The format's name and how `x` fares when rounded into it: `None` when it is 0 or a normal
/// number, else "overflows" or "underflows" (to a subnormal or 0).
fn fit(backend: Backend, x: &Q) -> (&'static str, Option<&'static str>) {
    fn judge<T: Real>(x: &Q) -> Option<&'static str> {
        let rounded = T::from_rational(x);
        if x.is_zero() || rounded.normal() {
            None
        } else if rounded.finite() {
            Some("underflows")
        } else {
            Some("overflows")
        }
    }
    match backend {
        Backend::F32(_) => ("f32", judge::<f32>(x)),
        _ => ("f64", judge::<f64>(x)),
    }
}

/// "input a = 7.90e-343 underflows f64", for each input of the float formulas (m, M, I, a,
/// v0, e) that the format cannot hold.
fn unrepresentable_inputs(backend: Backend, reference: &Reference) -> Vec<String> {
    let p = &reference.params;
    let inputs = [
        ("m", &p.m),
        ("M", &p.rod_mass),
        ("I", &p.inertia),
        ("a", &p.a),
        ("v0", &p.v0),
        ("e", &p.e),
    ];
    inputs
        .iter()
        .filter_map(|(name, x)| {
            let (format, verdict) = fit(backend, x);
            verdict.map(|v| format!("input {name} = {} {v} {format}", decimal::decimal(x, 3)))
        })
        .collect()
}

/// Why one float output, measured against `exact` with condition number `cond` (`None`:
/// infinite), cannot be trusted: the exact value out of the format's range, an ill-conditioned
/// problem, a NaN/infinite/wrong-zero float, or an error above [`ERROR_BOUND`] cond·u.
fn doubts_about_output(
    backend: Backend,
    exact: &Q,
    measured: &Accuracy,
    cond: Option<&Q>,
) -> Vec<String> {
    let mut doubts = Vec::new();
    if let (format, Some(verdict)) = fit(backend, exact) {
        doubts.push(format!(
            "the exact value {} {verdict} {format}",
            decimal::decimal(exact, 3)
        ));
    }
    let u = backend.unit_roundoff();
    match cond {
        None => doubts.push(
            "ill-conditioned: cond is infinite (v = 0 exactly: only exact arithmetic decides it)"
                .into(),
        ),
        Some(c) if !Accuracy::well_conditioned(Some(c), &u) => doubts.push(format!(
            "ill-conditioned: cond u = {} > 1e-3",
            decimal::decimal(&(c * &u), 3)
        )),
        Some(_) => {}
    }
    match (&measured.rel_error, measured.class) {
        (_, Class::Nan) => doubts.push("the float is NaN".into()),
        (_, Class::Infinite) => doubts.push("the float is infinite".into()),
        (_, Class::MissedZero) => doubts.push("the float is not 0, the exact value is".into()),
        (Some(error), _) => {
            if let Some(c) = cond {
                let bound = c * &u * Q::from_integer(ERROR_BOUND.into());
                if *error > bound {
                    doubts.push(format!(
                        "error {} exceeds {ERROR_BOUND} cond u = {}",
                        decimal::decimal(error, 3),
                        decimal::decimal(&bound, 3)
                    ));
                }
            }
        }
        (None, _) => doubts.push("the error is undefined".into()),
    }
    doubts
}

/// (v, V, omega) of a free-rod `scene` by the backend's float route, each as its shortest
/// round-trip text.
fn shortest<T: Solvable + Real>(scene: &Scene, backend: Backend) -> Motion<String> {
    solve::with::<T>(scene, backend.route())
        .expect("a float formula takes a free rod")
        .after
        .map(Real::shortest)
}
