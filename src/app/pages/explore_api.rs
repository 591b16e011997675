//! The explore page's computations: the paper's scene read from the page's fields (m = l =
//! v0 = 1, so every value is a ratio), its exact answer, the optimum, the curves the page draws
//! (from the library's f64 backend) and the motion after the impact.

use super::{exact, kind_message};
use crate::field::{Field, Q, QSqrt, q};
use crate::scene::{Params, RodInertia, Scene, SceneBuilder, Support};
use crate::solve::Outcome;
use crate::solve::fast::linear::solve;
use crate::solve::optimum::{Optimum, Placement, a_star_squared, optimum};
use num_traits::{One, Signed, Zero};
use serde_json::{Map, Value, json};
use std::cmp::Ordering;

/// The page's name of each field, as its error messages start.
const FIELD_NAMES: [(&str, &str); 10] = [
    ("ratio", "M/m"),
    ("a", "a/l"),
    ("e", "e"),
    ("rg", "r_G/l"),
    ("pivot", "p/l"),
    ("guess", "guess"),
    ("v0t", "v0t"),
    ("mu", "μ"),
    ("radius", "r/l"),
    ("spin", "spin"),
];

/// A scene as the page's fields give it.
pub(super) struct PageScene {
    /// The scene, struck at a rational point: `a` itself, or the end on a*'s side.
    pub(super) scene: Scene,
    /// Where it is struck, exactly (a*, irrational, included).
    pub(super) a: QSqrt,
    /// The pivot's position, on a pivot.
    pub(super) pivot: Option<Q>,
    /// Why the a field's a* was struck at the end instead ("" otherwise).
    note: String,
}

/// The fields' errors, by field id (`{"ratio": "M/m: must be > 0"}`).
pub(super) type FieldErrors = Map<String, Value>;

/// The field `id` of the request read as an exact number within the page's limits and checked
/// by `check` (which returns why a value is refused); `None` with the error recorded by field.
pub(super) fn read_field(
    request: &Value,
    id: &str,
    check: &dyn Fn(&Q) -> Option<&'static str>,
    errors: &mut FieldErrors,
) -> Option<Q> {
    read_number(request, id, check)
        .map_err(|why| errors.insert(id.into(), json!(format!("{}: {why}", name_of(id)))))
        .ok()
}

/// The text of `request[key]` read as an exact number within the page's limits and checked by
/// `check`; why it is refused otherwise (without the field's name). What every page's field
/// reading shares.
pub(super) fn read_number(
    request: &Value,
    key: &str,
    check: &dyn Fn(&Q) -> Option<&'static str>,
) -> Result<Q, String> {
    let text = request[key].as_str().unwrap_or_default();
    let value = page_limits(text)
        .and_then(|()| crate::number::parse(text))
        .map_err(|kind| kind_message(&kind))?;
    match check(&value) {
        None => Ok(value),
        Some(why) => Err(why.to_string()),
    }
}

/// Reads the page's fields (`ratio`, `a`, `e`, `kind` = uniform|dumbbell|gyration, `rg`,
/// `pivoted`, `pivot`); the errors by field when one is wrong.
fn page_scene(request: &Value) -> Result<PageScene, FieldErrors> {
    page_scene_with(request, FieldErrors::new(), &|b| b)
}

/// [`page_scene`] with more of the scene set by `extend` (the oblique tab's fields, read by the
/// caller, whose errors come in `errors`).
pub(super) fn page_scene_with(
    request: &Value,
    mut errors: FieldErrors,
    extend: &dyn Fn(SceneBuilder) -> SceneBuilder,
) -> Result<PageScene, FieldErrors> {
    let one = Q::from_i64(1);
    let on_rod = |x: &Q| x.abs() <= one;
    let ratio = read_field(
        request,
        "ratio",
        &|x| (x.sign() != Some(Ordering::Greater)).then_some("must be > 0"),
        &mut errors,
    );
    let e = read_field(
        request,
        "e",
        &|x| {
            (x.sign() == Some(Ordering::Less) || *x > Q::from_i64(1))
                .then_some("must lie in 0 ≤ e ≤ 1")
        },
        &mut errors,
    );
    let kind = request["kind"].as_str().unwrap_or("uniform");
    let rod = match kind {
        "dumbbell" => Some(RodInertia::Dumbbell),
        "gyration" => read_field(
            request,
            "rg",
            &|x| {
                (x.sign() != Some(Ordering::Greater) || *x > Q::from_i64(1))
                    .then_some("must lie in 0 < r_G/l ≤ 1")
            },
            &mut errors,
        )
        .map(RodInertia::Gyration),
        _ => Some(RodInertia::Uniform),
    };
    let pivot = if request["pivoted"].as_bool().unwrap_or(false) {
        read_field(
            request,
            "pivot",
            &|x| (!on_rod(x)).then_some("must lie on the rod, −1 ≤ p/l ≤ 1"),
            &mut errors,
        )
        .map(Some)
    } else {
        Some(None)
    };
    let (Some(ratio), Some(e), Some(rod), Some(pivot)) = (ratio, e, rod, pivot) else {
        return Err(errors);
    };
    if !errors.is_empty() {
        return Err(errors);
    }
    // A scene the extension refuses (a spin without a disc, no approach): the error by its field.
    let built = |a: Q| {
        let b = Scene::builder(one.clone(), ratio.clone())
            .rod(rod.clone())
            .e(e.clone())
            .a(a);
        extend(match &pivot {
            Some(p) => b.pivot(p.clone()),
            None => b,
        })
        .build()
    };
    if let Err(e) = built(Q::default()) {
        let mut errors = FieldErrors::new();
        let field = e.field.clone();
        let message = e.to_string();
        let reason = message
            .split_once(": ")
            .map_or(message.as_str(), |(_, why)| why);
        errors.insert(
            field.clone(),
            json!(format!("{}: {reason}", name_of(&field))),
        );
        return Err(errors);
    }
    let builder = |a: Q| built(a).expect("every field was checked");
    let text = request["a"].as_str().unwrap_or_default();
    match star(text) {
        Some((from_pivot, side)) => {
            if from_pivot && pivot.is_none() {
                errors.insert("a".into(), json!("a/l: 'p' only on a pivot"));
                return Err(errors);
            }
            let p = pivot.clone().unwrap_or_default();
            // The optimum's a*^2 does not depend on where the rod is struck.
            let a_star = QSqrt::sqrt_of(&a_star_squared(&builder(Q::default()).params::<Q>()));
            let at = QSqrt::rational(Q::from_i64(side)) * &a_star + &QSqrt::rational(p.clone());
            let end = Q::from_i64(match at.sign() {
                Some(Ordering::Less) => -1,
                _ => 1,
            });
            if at.abs().cmp_exact(&QSqrt::one()) != Ordering::Greater {
                // On a*'s side: the end of that side is struck in the scene (the same optimum).
                let side_end = if side > 0 { one.clone() } else { -one.clone() };
                return Ok(PageScene {
                    scene: builder(side_end),
                    a: at,
                    pivot,
                    note: String::new(),
                });
            }
            let pretty = exact(&at);
            let note = format!(
                "{} = {} ≈ {} lies beyond the end of the rod: struck at the end, a/l = {}, where \
                 the spin is fastest on that side.",
                text.trim(),
                pretty["pretty"].as_str().unwrap_or_default(),
                pretty["approx"].as_str().unwrap_or_default(),
                end.to_string().replace('-', "−"),
            );
            Ok(PageScene {
                scene: builder(end.clone()),
                a: QSqrt::rational(end),
                pivot,
                note,
            })
        }
        None => {
            let a = read_field(
                request,
                "a",
                &|x| (!on_rod(x)).then_some("must lie on the rod, −1 ≤ a/l ≤ 1"),
                &mut errors,
            );
            match a {
                Some(a) => Ok(PageScene {
                    scene: builder(a.clone()),
                    a: QSqrt::rational(a),
                    pivot,
                    note: String::new(),
                }),
                None => Err(errors),
            }
        }
    }
}

/// The most digits a page takes in a typed number (before and after the point, leading zeros
/// aside), and in a preset's numerator or denominator: what its floats for drawing and its
/// sliders can follow.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::{PAGE_DIGITS, explore};
/// let long = "1".repeat(PAGE_DIGITS + 1);
/// let answer = explore(&serde_json::json!({"ratio": long, "a": "1", "e": "1"}));
/// assert_eq!(answer["errors"]["ratio"], "M/m: more than 30 digits");
/// ```
pub const PAGE_DIGITS: usize = 30;
/// The largest decimal exponent a page takes in a typed number, in absolute value.
const PAGE_EXPONENT: i64 = 60;

/// The page's own limits on a typed number (`3/2`, `1.5e-3`), beyond the library's: at most
/// [`PAGE_DIGITS`] digits in each part and an exponent within ±[`PAGE_EXPONENT`].
fn page_limits(text: &str) -> Result<(), crate::error::ErrorKind> {
    use crate::error::ErrorKind;
    for part in text.split('/') {
        let part = part.trim().trim_start_matches(['+', '-']);
        let (mantissa, exponent) = part.split_once(['e', 'E']).unwrap_or((part, "0"));
        let digits = mantissa
            .chars()
            .filter(char::is_ascii_digit)
            .skip_while(|&c| c == '0')
            .count();
        if digits > PAGE_DIGITS {
            return Err(ErrorKind::Invalid(format!(
                "more than {PAGE_DIGITS} digits"
            )));
        }
        // Only an exponent of digits is judged here; any other text is not a number, which
        // the library's reading says.
        let magnitude = exponent.trim().trim_start_matches(['+', '-']);
        let digits_only = !magnitude.is_empty() && magnitude.bytes().all(|b| b.is_ascii_digit());
        if digits_only
            && (magnitude.len() > 3 || magnitude.parse::<i64>().is_ok_and(|x| x > PAGE_EXPONENT))
        {
            return Err(ErrorKind::Invalid(format!(
                "exponent beyond ±{PAGE_EXPONENT}"
            )));
        }
    }
    Ok(())
}

/// The page's name of a field.
fn name_of(id: &str) -> &str {
    FIELD_NAMES
        .iter()
        .find(|(key, _)| *key == id)
        .map_or(id, |(_, name)| name)
}

/// Whether `text` names the impact point a* (`a*`, `-a*`, `p+a*`, `p-a*`, spaces allowed), as
/// the explore page's a field takes it.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::is_a_star;
/// assert!(is_a_star("a*") && is_a_star("p - a*") && !is_a_star("1/2"));
/// ```
pub fn is_a_star(text: &str) -> bool {
    star(text).is_some()
}

/// The impact point `a*`, `-a*` (from the centre), `p+a*`, `p-a*` (from the pivot): whether
/// it is measured from the pivot, and its side; `None` for a number.
fn star(text: &str) -> Option<(bool, i64)> {
    let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let compact = compact.to_ascii_lowercase().replace('−', "-");
    let (from_pivot, rest) = match compact.strip_prefix('p') {
        Some(rest) => (true, rest),
        None => (false, compact.as_str()),
    };
    match rest {
        "a*" | "+a*" => Some((from_pivot, 1)),
        "-a*" => Some((from_pivot, -1)),
        _ => None,
    }
}

/// The scene's parameters in the field `F`, struck at `a`.
pub(super) fn params_at<F: Field>(scene: &Scene, a: F) -> Params<F> {
    Params {
        a,
        ..scene.params::<F>()
    }
}

/// |omega| for a strike at `a`, in f64 (the library's float backend), for the curves.
fn spin_at(scene: &Scene, a: f64) -> f64 {
    solve(&params_at(scene, a)).map_or(f64::NAN, |o| o.after.omega.abs())
}

/// `explore`: the exact answer of the page's scene, the optimum, the guess's share of the best
/// spin, the curves, and when the puck meets the rod again. Its keys: `errors` (by field,
/// when one is wrong: nothing else then), or `scene`, `values` (each an exact number, see
/// [`exact`]), `energy` (shares of the kinetic energy before), the flags `pivoted`, `inside`,
/// `at_end`, `at_a_star`, `stuck`, `side`, `note`, `curve`, `threshold_curve`, `motion`, and
/// `guess` when the request has one.
///
/// # Examples
/// The paper's M = m rod struck at l/2: omega = 12/11 v0/l, a* = sqrt(6)/3 l on the rod.
/// ```
/// use serde_json::json;
/// let answer = rodimpact::app::pages::explore(&json!({
///     "ratio": "1", "a": "1/2", "e": "1", "kind": "uniform", "pivoted": false
/// }));
/// assert_eq!(answer["values"]["omega"]["text"], "12/11");
/// assert_eq!(answer["values"]["a_star"]["text"], "sqrt(6)/3");
/// assert_eq!(answer["inside"], true);
/// let wrong = rodimpact::app::pages::explore(&json!({"ratio": "-1", "a": "1/2", "e": "2"}));
/// assert_eq!(wrong["errors"]["ratio"], "M/m: must be > 0");
/// assert_eq!(wrong["errors"]["e"], "e: must lie in 0 ≤ e ≤ 1");
/// ```
pub fn explore(request: &Value) -> Value {
    let s = match page_scene(request) {
        Ok(s) => s,
        Err(errors) => return json!({ "errors": errors }),
    };
    let scene = &s.scene;
    let out: Outcome<QSqrt> = solve(&params_at(scene, s.a.clone())).expect("a valid scene solves");
    let o = optimum(scene).expect("the rod is at rest before the impact");
    let lift = |x: &Q| QSqrt::rational(x.clone());
    let (one, two) = (QSqrt::one(), QSqrt::from_i64(2));
    let e = lift(scene.e());
    let m_rod = lift(scene.rod_mass());
    let p = s.pivot.clone().map(|p| lift(&p));
    let lever = s.a.clone() - &p.clone().unwrap_or_else(QSqrt::zero);
    let omega = out.after.omega.clone();
    let a_star = QSqrt::sqrt_of(&o.squared);
    let ratio_to_max = (!o.omega_max.is_zero()).then(|| omega.abs() / &o.omega_max);
    // The kinetic energy before is m v0^2/2 = 1/2: each share is twice the part.
    let share = |x: QSqrt| x * &two;
    let half = QSqrt::rational(q(1, 2));
    let puck = out.after.v.square() * &half;
    let moving = m_rod.clone() * &out.after.rod_v.square() * &half;
    let turning = lift(&scene.inertia()) * &omega.square() * &half;
    let mut values = Map::new();
    let mut put = |key: &str, x: &QSqrt| {
        values.insert(key.into(), exact(x));
    };
    put("v", &out.after.v);
    put("V", &out.after.rod_v);
    put("omega", &omega);
    put("J", &(one.clone() - &out.after.v));
    if let Some(impulse) = &out.pivot_impulse {
        put("pivot_impulse", impulse);
    }
    put("energy_lost", &out.energy.lost());
    put("lost_fraction", &share(out.energy.lost()));
    put("a_star", &a_star);
    put("a_star_squared", &lift(&o.squared));
    put("arm", &lift(&o.arm));
    put("omega_max", &o.omega_max);
    put("omega_end", &lift(&o.omega_end));
    if let Some(ratio) = &ratio_to_max {
        put("ratio_to_max", ratio);
    }
    put("omega_lever", &(omega.clone() * &lever));
    if s.pivot.is_none() {
        // The mass ratio at which a* reaches the end (m = 1); 0 when a* is beyond it for every mass.
        put(
            "threshold",
            &o.threshold_mass.as_ref().map_or_else(QSqrt::zero, lift),
        );
    }
    let mut energy = json!({
        "before_puck": exact(&one),
        "before_rod": exact(&QSqrt::zero()),
        "puck": exact(&share(puck)),
        "moving": exact(&share(moving)),
        "turning": exact(&share(turning)),
    });
    let elastic = *scene.e() == Q::from_i64(1);
    if !elastic {
        energy["lost"] = exact(&share(out.energy.lost()));
    }
    let stuck = scene.e().is_zero();
    let mut answer = json!({
        "scene": {
            "ratio": exact(&m_rod),
            "a": exact(&s.a),
            "e": exact(&e),
            "pivot": p.as_ref().map(exact),
            "inertia_factor": exact(&(lift(&scene.inertia()) / &m_rod)),
        },
        // m v0/(m + M): the speed of the centre of mass of puck and rod (the animation's camera).
        "centre_of_mass_speed": exact(&(one.clone() / &(one.clone() + &m_rod))),
        "values": values,
        "energy": energy,
        "pivoted": s.pivot.is_some(),
        "inside": o.within_rod,
        "at_end": o.placement == Placement::AtEnd,
        "at_a_star": lever.square() == lift(&o.squared),
        "elastic": elastic,
        "stuck": stuck,
        "side": if lever.sign() == Some(Ordering::Less) { -1 } else { 1 },
        "note": s.note,
        "curve": curve(scene, &s, &o, &a_star, &omega),
        "threshold_curve": threshold_curve(scene, s.pivot.as_ref()),
        "motion": { "second": Kinematics::of(scene, &s, &out).second(12.0), "stuck": stuck },
    });
    if let Some(text) = request["guess"].as_str().filter(|t| !t.trim().is_empty()) {
        answer["guess"] = match crate::number::parse(text) {
            Ok(g) => {
                let at: Outcome<QSqrt> = solve(&params_at(scene, QSqrt::rational(g.clone())))
                    .expect("a valid scene solves");
                match &ratio_to_max {
                    Some(_) => {
                        let share = at.after.omega.abs() / &o.omega_max;
                        json!({ "a": exact(&QSqrt::rational(g)), "share": exact(&share) })
                    }
                    None => Value::Null,
                }
            }
            Err(kind) => json!({ "error": format!("guess: {}", kind_message(&kind)) }),
        };
    }
    answer
}

/// |omega| against the impact point, in f64: 201 points on the rod (and 201 beyond its end when
/// a free rod's a* lies beyond it), the range drawn, the marks at a* and the peak.
fn curve(scene: &Scene, s: &PageScene, o: &Optimum, a_star: &QSqrt, spin: &QSqrt) -> Value {
    let p = s.pivot.as_ref().map_or(0.0, Field::nearest_f64);
    let star = a_star.nearest_f64();
    let xs = if s.pivot.is_some() {
        [-1.0, 1.0]
    } else {
        [0.0, (star * 1.15).clamp(1.0, 2.0)]
    };
    let points = |from: f64, to: f64| -> Vec<[f64; 2]> {
        (0..=200)
            .map(|i| {
                let a = from + (to - from) * f64::from(i) / 200.0;
                [a, spin_at(scene, a)]
            })
            .collect()
    };
    let marks: Vec<Value> = [1.0, -1.0]
        .into_iter()
        .take(if s.pivot.is_some() { 2 } else { 1 })
        .filter_map(|side| {
            let at = p + side * star;
            (at >= xs[0] - 1e-9 && at <= xs[1] + 1e-9)
                .then(|| json!({ "a": at, "spin": spin_at(scene, at), "side": side }))
        })
        .collect();
    let unbounded_peak = spin_at(scene, p + star);
    let peak = [unbounded_peak, spin_at(scene, 1.0), spin_at(scene, -1.0)]
        .into_iter()
        .fold(0.0, f64::max);
    json!({
        "range": xs,
        "on_rod": points(xs[0], xs[1].min(1.0)),
        "beyond": if xs[1] > 1.0 { points(1.0, xs[1]) } else { Vec::new() },
        "a_star_marks": marks,
        "here": [s.a.nearest_f64(), spin.nearest_f64().abs()],
        "peak": peak,
        "omega_max": o.omega_max.nearest_f64(),
    })
}

/// a* (from the centre, or from the pivot) against the mass ratio M/m from 1/100 to 100 on a
/// log scale: 401 points `[log10(M/m), a*]`, in f64.
fn threshold_curve(scene: &Scene, pivot: Option<&Q>) -> Vec<[f64; 2]> {
    (0..=400)
        .map(|i| {
            let log_ratio = -2.0 + 4.0 * f64::from(i) / 400.0;
            let rod_mass = 10f64.powf(log_ratio);
            let params = Params {
                rod_mass,
                inertia: scene.rod().moment(&rod_mass, &1.0),
                support: pivot.map_or(Support::Free, |p| Support::Pivot(p.nearest_f64())),
                ..scene.params::<f64>()
            };
            [log_ratio, a_star_squared(&params).sqrt()]
        })
        .collect()
}

/// The motion after the impact, in floats for the animation (units m = l = v0 = 1): the puck
/// straight on at v and the rod moving and turning freely, or, at e = 0, the two stuck together
/// turning about the pivot or about their common centre of mass.
struct Kinematics {
    a: f64,
    pivot: Option<f64>,
    v: f64,
    rod_v: f64,
    omega: f64,
    mass_ratio: f64,
    stuck: bool,
}

/// Where puck and rod are at one time: the puck's centre, the rod's centre, the rod's angle.
struct State {
    ball: [f64; 2],
    centre: [f64; 2],
    phi: f64,
}

impl Kinematics {
    fn of(scene: &Scene, s: &PageScene, out: &Outcome<QSqrt>) -> Kinematics {
        Kinematics {
            a: s.a.nearest_f64(),
            pivot: s.pivot.as_ref().map(Field::nearest_f64),
            v: out.after.v.nearest_f64(),
            rod_v: out.after.rod_v.nearest_f64(),
            omega: out.after.omega.nearest_f64(),
            mass_ratio: scene.rod_mass().nearest_f64(),
            stuck: scene.e().is_zero(),
        }
    }

    /// The state at time `t` (t < 0: the approach at v0 = 1).
    fn at(&self, t: f64) -> State {
        let a = self.a;
        if t <= 0.0 {
            return State {
                ball: [t, a],
                centre: [0.0, 0.0],
                phi: 0.0,
            };
        }
        let phi = -self.omega * t; // the rod's counterclockwise angle
        // (0, y) turned counterclockwise by phi.
        let turned = |y: f64| [-y * phi.sin(), y * phi.cos()];
        if self.stuck || self.pivot.is_some() {
            // The point the pair (or the pivoted rod) turns about.
            let (hub_y, hub_speed) = match self.pivot {
                Some(p) => (p, 0.0),
                None => (a / (1.0 + self.mass_ratio), 1.0 / (1.0 + self.mass_ratio)),
            };
            let hub_x = hub_speed * t;
            let rim = |y: f64| {
                let [x, z] = turned(y - hub_y);
                [hub_x + x, hub_y + z]
            };
            let ball = if self.stuck { rim(a) } else { [self.v * t, a] };
            return State {
                ball,
                centre: rim(0.0),
                phi,
            };
        }
        State {
            ball: [self.v * t, a],
            centre: [self.rod_v * t, 0.0],
            phi,
        }
    }

    /// The puck's distance from the rod's line and its position along the rod at `t`.
    fn relative(&self, t: f64) -> (f64, f64) {
        let s = self.at(t);
        let (dx, dy) = (s.ball[0] - s.centre[0], s.ball[1] - s.centre[1]);
        (
            dx * s.phi.cos() + dy * s.phi.sin(),
            -dx * s.phi.sin() + dy * s.phi.cos(),
        )
    }

    /// When the rod meets the puck again within `horizon` (l/v0 units): found by scanning in
    /// steps of 1/1000 and bisecting the crossing; `None` when stuck or never.
    fn second(&self, horizon: f64) -> Option<f64> {
        if self.stuck {
            return None;
        }
        let touches = |along: f64| along.abs() <= 1.0;
        let dt = 1e-3;
        let mut before = self.relative(dt);
        let mut step = 2;
        loop {
            let t = f64::from(step) * dt;
            if t > horizon {
                return None;
            }
            let now = self.relative(t);
            if (before.0 < 0.0) != (now.0 < 0.0) && (touches(now.1) || touches(before.1)) {
                let (mut lo, mut hi) = (t - dt, t);
                for _ in 0..60 {
                    let mid = (lo + hi) / 2.0;
                    if (self.relative(mid).0 < 0.0) == (before.0 < 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                if touches(self.relative(hi).1) {
                    return Some(hi);
                }
            }
            before = now;
            step += 1;
        }
    }
}

/// `explore_motion`: the page's scene (the fields of [`explore`]) at each of `times`: per time
/// the puck's centre `ball`, the rod's `centre` and its angle `phi` (counterclockwise), in
/// floats for the animation.
///
/// # Examples
/// ```
/// use serde_json::json;
/// let states = rodimpact::app::pages::explore_motion(&json!({
///     "ratio": "1", "a": "1/2", "e": "1", "times": [-1.0, 0.0, 11.0]
/// }));
/// assert_eq!(states["states"][0]["ball"], json!([-1.0, 0.5]));
/// // After 11 l/v0 the puck (v = 3/11) has moved 3 l.
/// assert!((states["states"][2]["ball"][0].as_f64().unwrap() - 3.0).abs() < 1e-12);
/// ```
pub fn explore_motion(request: &Value) -> Value {
    let s = match page_scene(request) {
        Ok(s) => s,
        Err(errors) => return json!({ "errors": errors }),
    };
    let out: Outcome<QSqrt> =
        solve(&params_at(&s.scene, s.a.clone())).expect("a valid scene solves");
    let kinematics = Kinematics::of(&s.scene, &s, &out);
    let states: Vec<Value> = request["times"]
        .as_array()
        .map(Vec::as_slice)
        .unwrap_or_default()
        .iter()
        .filter_map(Value::as_f64)
        .map(|t| {
            let state = kinematics.at(t);
            json!({ "ball": state.ball, "centre": state.centre, "phi": state.phi })
        })
        .collect();
    json!({ "states": states })
}
