//! `rodimpact explore`'s paper page, written: its preset from the scene flags, the reference
//! answers it carries (computed here natively, those at a* in Q(sqrt d)), rendered by
//! [`crate::report::explore::explore_html`].

use super::PAGE_DIGITS;
use crate::Error;
use crate::error::ErrorKind;
use crate::field::{Q, QSqrt, q};
use crate::report::page::link_of;
use crate::report::solution_json;
use crate::scene::{RodInertia, SceneInput, Support};
use crate::solve::Answer;
use crate::solve::fast::linear::solve_at;
use crate::solve::optimum::a_star_squared;
use serde_json::{Value, json};

/// The scenes (M/m, a/l, e, rod, pivot p/l; m = l = v0 = 1) whose exact answers the page
/// carries to check its own arithmetic: free and pivoted, every rod kind, elastic to sticking,
/// a* inside and beyond the end, on either side of a pivot; and struck exactly at a* (the impact
/// point as the page's a field takes it: `a*`, `-a*`, or `p+a*`, `p-a*` on a pivot), where the
/// answers are irrational (a pivot's impulse `x + y*sqrt(d)`).
pub const REFERENCE_SCENES: &[(&str, &str, &str, &str, Option<&str>)] = &[
    ("1", "1/2", "1", "uniform", None),
    ("3/2", "1/2", "1/2", "uniform", None),
    ("3", "1", "1", "uniform", None),
    ("1/10", "1", "0", "uniform", None),
    ("1", "3/4", "0", "dumbbell", None),
    ("2", "1/3", "1", "rg=1/2", None),
    ("7/3", "-2/5", "3/10", "rg=3/10", None),
    ("3/2", "1/2", "1/2", "uniform", Some("1/4")),
    ("1", "-1/2", "1", "uniform", Some("-1")),
    ("3/2", "1/2", "1/2", "uniform", Some("1")),
    ("5", "0", "1/2", "dumbbell", Some("1/2")),
    ("1", "a*", "1", "uniform", None),
    ("3/2", "-a*", "1/2", "rg=1/2", None),
    ("1", "p+a*", "1/3", "uniform", Some("-1")),
    ("2", "p-a*", "0", "rg=1/3", Some("1/2")),
];

/// Where a reference scene is struck: a rational `a` (`None`), or a* on the side `+1` or `-1`
/// (`Some(side)`), from the centre or, on a pivot, from the pivot.
fn star_side(a: &str) -> Option<i64> {
    match a.trim_start_matches('p') {
        "a*" | "+a*" => Some(1),
        "-a*" => Some(-1),
        _ => None,
    }
}

/// rodimpact's exact answers for [`REFERENCE_SCENES`], as the page reads them: per scene its
/// `input` and the exact strings of `v`, `V`, `omega`, `energy_lost`, `a_star`, `omega_max`
/// (and `pivot_impulse` on a pivot), as `solve --json` prints them.
///
/// # Errors
/// None in practice: the reference scenes are valid (an error would name the bad field).
///
/// # Examples
/// ```
/// let reference = rodimpact::app::pages::reference_answers()?;
/// assert_eq!(reference[0]["a_star"], "sqrt(6)/3");
/// assert_eq!(reference[0]["omega"], "12/11");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn reference_answers() -> Result<Vec<Value>, Error> {
    REFERENCE_SCENES
        .iter()
        .map(|&(ratio, a, e, rod, pivot)| {
            let side = star_side(a);
            // Struck at a*: the scene as if struck at the end of that side (the same optimum).
            let rational_a = side.map_or(a, |s| if s > 0 { "1" } else { "-1" });
            let input = SceneInput {
                m: Some("1".into()),
                rod_mass: Some(ratio.into()),
                a: Some(rational_a.into()),
                e: Some(e.into()),
                rod: Some(rod.into()),
                pivot: pivot.map(Into::into),
                ..Default::default()
            };
            let scene = input.build()?;
            let json = solution_json(&Answer::of(&scene), 6);
            let exact = |path: &[&str]| {
                path.iter()
                    .fold(&json, |v, key| &v[*key])
                    .as_str()
                    .map(str::to_string)
            };
            let mut answer = json!({
                "input": { "M": ratio, "a": a, "e": e, "rod": rod, "pivot": pivot },
                "v": exact(&["v", "exact"]),
                "V": exact(&["V", "exact"]),
                "omega": exact(&["omega", "exact"]),
                "energy_lost": exact(&["energy", "lost", "exact"]),
                "a_star": exact(&["a_star", "exact"]),
                "omega_max": exact(&["omega_max", "exact"]),
            });
            if pivot.is_some() {
                answer["pivot_impulse"] = json!(exact(&["pivot_impulse", "exact"]));
            }
            if let Some(side) = side {
                // The lever arm is a* = sqrt(a*^2) exactly: solved in Q(sqrt d).
                let arm =
                    QSqrt::sqrt_of(&a_star_squared(&scene.params())) * &QSqrt::rational(q(side, 1));
                let pivot = match scene.support() {
                    Support::Free => q(0, 1),
                    Support::Pivot(p) => p.clone(),
                };
                let outcome = solve_at(&scene, arm + &QSqrt::rational(pivot))
                    .expect("a valid scene is nonsingular");
                answer["v"] = json!(outcome.after.v.to_string());
                answer["V"] = json!(outcome.after.rod_v.to_string());
                answer["omega"] = json!(outcome.after.omega.to_string());
                answer["energy_lost"] = json!(outcome.energy.lost().to_string());
                if let Some(impulse) = &outcome.pivot_impulse {
                    answer["pivot_impulse"] = json!(impulse.to_string());
                }
            }
            Ok(answer)
        })
        .collect()
}

/// How the animation is viewed: moving with the centre of mass of puck and rod (the default),
/// or from the table (the lab frame). A rod on a pivot is always seen from the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Moving with the system's centre of mass: the rod turns in place.
    CentreOfMass,
    /// From the table: the struck rod drifts away as it turns.
    Lab,
}

impl Frame {
    /// The name the page's link (`#frame=lab`) and `explore --frame` take.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::app::pages::Frame;
    /// assert_eq!(Frame::Lab.name(), "lab");
    /// assert_eq!(Frame::CentreOfMass.name(), "centre-of-mass");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Frame::CentreOfMass => "centre-of-mass",
            Frame::Lab => "lab",
        }
    }
}

/// How the page opens: the controls it presets, in the page's units m = l = v0 = 1, as the
/// fields take them, with the keys of the page's link (`explore.html#M=1/2&a=1`): `M` (the mass
/// ratio M/m), `a` (a/l), `e`, `rod` (`uniform`, `dumbbell`, `rg=r_G/l`), `pivot` (p/l),
/// `predict` (`1` or `0`) and `frame`. A control not preset keeps the page's default (M = m,
/// a = l/2, elastic, uniform, free, predict first, the centre-of-mass view).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Preset {
    fields: Vec<(&'static str, String)>,
}

impl Preset {
    /// The preset of a scene given as `solve` takes it (any units; m defaults to 1 and M to m):
    /// each of M/m, a, e, the rod and the pivot preset when `input` gives it, the others left to
    /// the page; `predict` and `frame` when given.
    ///
    /// # Errors
    /// The scene's own errors, naming the flag (`M: must be > 0`); `rod` when its moment of
    /// inertia has no rational radius of gyration (the page takes `rg=`); a ratio with more
    /// than 30 digits in its numerator or denominator, which the page would refuse, naming its
    /// flag.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::app::pages::{Frame, Preset};
    /// use rodimpact::scene::SceneInput;
    /// let input = SceneInput {
    ///     rod_mass: Some("500 g".into()),
    ///     m: Some("1 kg".into()),
    ///     a: Some("1".into()),
    ///     rod: Some("rg=1/2".into()),
    ///     ..Default::default()
    /// };
    /// let preset = Preset::of_scene(&input, Some(false), Some(Frame::Lab))?;
    /// assert_eq!(preset.link(), "M=1/2&a=1&rod=rg=1/2&predict=0&frame=lab");
    /// let heavy = SceneInput { rod_mass: Some("-1".into()), ..Default::default() };
    /// assert_eq!(Preset::of_scene(&heavy, None, None).unwrap_err().to_string(), "M: must be > 0, got -1");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of_scene(
        input: &SceneInput,
        predict: Option<bool>,
        frame: Option<Frame>,
    ) -> Result<Preset, Error> {
        let m = input.m.clone().unwrap_or_else(|| "1".into());
        // The impact point a* itself (`a*`, `-a*`, `p+a*`, `p-a*`) goes to the page as typed:
        // the page strikes it exactly.
        let star = input.a.as_deref().filter(|a| super::is_a_star(a));
        let scene = SceneInput {
            rod_mass: input.rod_mass.clone().or_else(|| Some(m.clone())),
            m: Some(m),
            a: if star.is_some() {
                None
            } else {
                input.a.clone()
            },
            ..input.clone()
        }
        .build()?;
        let l = scene.half_length();
        let mut fields = Vec::new();
        let number = |fields: &mut Vec<_>, key: &'static str, flag: &str, given: bool, value: Q| {
            if given {
                fields.push((key, page_number(flag, &value)?));
            }
            Ok::<_, Error>(())
        };
        let mass_flag = if input.rod_mass.is_some() { "M" } else { "m" };
        number(
            &mut fields,
            "M",
            mass_flag,
            input.m.is_some() || input.rod_mass.is_some(),
            scene.rod_mass() / scene.m(),
        )?;
        let a_flag = if input.from_end.is_some() {
            "from-end"
        } else {
            "a"
        };
        match star {
            Some(text) => {
                if text.trim_start().starts_with('p') && input.pivot.is_none() {
                    return Err(Error::new(
                        "a",
                        ErrorKind::Invalid(
                            "'p+a*' and 'p-a*' are measured from a pivot: give --pivot".into(),
                        ),
                    ));
                }
                fields.push(("a", text.split_whitespace().collect()));
            }
            None => number(
                &mut fields,
                "a",
                a_flag,
                input.a.is_some() || input.from_end.is_some(),
                scene.a() / l,
            )?,
        }
        number(&mut fields, "e", "e", input.e.is_some(), scene.e().clone())?;
        if input.rod.is_some() {
            let rod = match scene.rod() {
                RodInertia::Uniform => "uniform".to_string(),
                RodInertia::Dumbbell => "dumbbell".to_string(),
                RodInertia::Gyration(r) => format!("rg={}", page_number("rod", &(r / l))?),
                RodInertia::Moment(i) => {
                    let squared = i / (scene.rod_mass() * l * l);
                    let root = QSqrt::sqrt_of(&squared);
                    if root.d().is_some() {
                        return Err(Error::new(
                            "rod",
                            ErrorKind::Invalid(format!(
                                "the page takes uniform, dumbbell or rg=<radius>; this moment of \
                                 inertia gives r_G = {root} l, not a fraction"
                            )),
                        ));
                    }
                    format!("rg={}", page_number("rod", root.x())?)
                }
            };
            fields.push(("rod", rod));
        }
        if let (Some(_), Support::Pivot(p)) = (&input.pivot, scene.support()) {
            fields.push(("pivot", page_number("pivot", &(p / l))?));
        }
        if let Some(oblique) = scene.oblique() {
            if let Some(flag) = [
                ("rod-v", &input.rod_v),
                ("rod-vt", &input.rod_vt),
                ("rod-omega", &input.rod_omega),
            ]
            .into_iter()
            .find_map(|(flag, value)| value.as_ref().map(|_| flag))
            {
                return Err(Error::new(
                    flag,
                    ErrorKind::Invalid(
                        "the page's oblique tab takes a rod at rest (--v0t, --mu, --radius and --spin)".into(),
                    ),
                ));
            }
            // The oblique tab, in the page's units m = l = v0 = 1.
            fields.push(("tab", "oblique".into()));
            let v0 = scene.v0();
            fields.push(("v0t", page_number("v0t", &(oblique.v0t.clone() / v0))?));
            fields.push(("mu", page_number("mu", &oblique.mu)?));
            if let Some(disc) = &oblique.disc {
                fields.push(("radius", page_number("radius", &(disc.radius.clone() / l))?));
                fields.push(("spin", page_number("spin", &(disc.spin.clone() * l / v0))?));
            }
        }
        if let Some(on) = predict {
            fields.push(("predict", if on { "1" } else { "0" }.into()));
        }
        if let Some(frame) = frame {
            fields.push(("frame", frame.name().into()));
        }
        Ok(Preset { fields })
    }

    /// The preset as the page's link spells it after `#` (`M=1/2&a=1`; empty: nothing preset).
    /// Its values need no escaping: numbers, `/`, `-`, `.`, `=` and the words above.
    pub fn link(&self) -> String {
        link_of(&self.fields)
    }
}

/// A ratio as the page's fields take it (`3/2`, `-1`), or the error naming `flag` when its
/// numerator or denominator has more digits than the page reads.
fn page_number(flag: &str, value: &Q) -> Result<String, Error> {
    let digits = |n: String| n.trim_start_matches('-').len();
    if digits(value.numer().to_string()) > PAGE_DIGITS
        || digits(value.denom().to_string()) > PAGE_DIGITS
    {
        return Err(Error::out_of_range(
            flag,
            format!(
                "the page takes at most {PAGE_DIGITS} digits above and below the fraction bar, got {}",
                crate::echo::echo(&value.to_string())
            ),
        ));
    }
    Ok(value.to_string())
}

/// The page, complete, opening on `preset`: the reference answers computed, the page rendered
/// ([`crate::report::explore::explore_html`]) with the WebAssembly `module` (compressed, in
/// base64: the command-line tool's build makes it).
///
/// # Errors
/// As [`reference_answers`], or when `module` is empty.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::{Preset, explore_page};
/// let page = explore_page(&Preset::default(), "eJwDAAAAAAE=")?;
/// assert!(page.contains("\"a_star\":\"sqrt(6)/3\""));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn explore_page(preset: &Preset, module: &str) -> Result<String, Error> {
    let reference = Value::Array(reference_answers()?);
    crate::report::explore::explore_html(&preset.link(), &reference, module)
}
