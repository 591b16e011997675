//! The answer to one scene, as `rodimpact solve` prints it: JSON (the keys of docs/conventions.md)
//! and an aligned text report.

use super::value_json;
use crate::field::decimal::{self, Rounding};
use crate::field::{Q, QSqrt};
use crate::optimum::{Argmax, Optimum, PaperForm, Placement, optimum};
use crate::scene::{RodInertia, Scene, Support};
use crate::solve::{self, Outcome, Route};
use num_traits::{One, Zero};
use serde_json::{Map, Value, json};

/// A scene solved exactly, with its optimum.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The scene.
    pub scene: Scene,
    /// Velocities, energies, pivot impulse and residuals.
    pub outcome: Outcome<Q>,
    /// a*, its in-rod decision and the exact maximum of omega.
    pub optimum: Optimum,
}

impl Solution {
    /// Solves `scene` over Q by the fraction-free route ([`Route::FractionFree`]: the laws
    /// checked as integer identities, one reduction per output) and computes its optimum.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Solution, scene::Scene, field::q};
    /// let s = Solution::of(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap());
    /// assert_eq!(s.outcome.after.omega, q(6, 5));
    /// ```
    pub fn of(scene: &Scene) -> Solution {
        let outcome = solve::with::<Q>(scene, Route::FractionFree)
            .expect("the fraction-free route takes every scene in Q")
            .outcome(&scene.params());
        Solution {
            scene: scene.clone(),
            outcome,
            optimum: optimum(scene),
        }
    }

    /// The JSON object of `solve --json`: `scene`, `v`, `V`, `omega`, `energy`,
    /// `pivot_impulse` (pivot only), `residuals` (only the laws that apply), `a_star` (with
    /// `placement` and `threshold_M`, the rod mass at which a* reaches the end), `omega_max`,
    /// `argmax`, `omega_end`, `end_over_max` (omega at the end over omega_max), `gain` (what aiming
    /// at a* gains over the end) and `paper_form` (K, b^2, c of the paper's f(x) argument,
    /// verified as an identity in a). Decimals carry at least 30 significant digits; `a_star`'s
    /// bounds satisfy upper - lower <= 10^-digits a*.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Solution, scene::Scene, field::q};
    /// let json = Solution::of(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap()).to_json(30);
    /// assert_eq!(json["v"]["exact"], "3/5");
    /// assert_eq!(json["a_star"]["within_rod"], true);
    /// assert!(json.get("pivot_impulse").is_none());
    /// ```
    pub fn to_json(&self, digits: usize) -> Value {
        let decimal_digits = digits.max(30);
        let value = |x: &Q| value_json(x, decimal_digits);
        let after = &self.outcome.after;
        let mut out = Map::new();
        out.insert("scene".into(), scene_json(&self.scene));
        out.insert("v".into(), value(&after.v));
        out.insert("V".into(), value(&after.rod_v));
        out.insert("omega".into(), value(&after.omega));
        let energy = &self.outcome.energy;
        out.insert(
            "energy".into(),
            json!({
                "before": value(&energy.before),
                "after": value(&energy.after),
                "lost": value(&energy.lost),
            }),
        );
        if let Some(p) = &self.outcome.pivot_impulse {
            out.insert("pivot_impulse".into(), value(p));
        }
        let residuals: Map<String, Value> = self
            .outcome
            .residuals
            .iter()
            .map(|(name, r)| (name.to_string(), Value::String(r.to_string())))
            .collect();
        out.insert("residuals".into(), Value::Object(residuals));
        let o = &self.optimum;
        // Bounds one digit tighter than asked, printed outward with two more digits, so the
        // printed interval still encloses a* and is at most 10^-digits a* wide.
        let (lower, upper) = decimal::sqrt_bounds(&o.squared, digits + 1);
        out.insert(
            "a_star".into(),
            json!({
                "squared": o.squared.to_string(),
                "exact": decimal::surd(&o.squared),
                "decimal": decimal::decimal_sqrt(&o.squared, decimal_digits),
                "lower": decimal::decimal_rounded(&lower, digits + 2, Rounding::Floor),
                "upper": decimal::decimal_rounded(&upper, digits + 2, Rounding::Ceiling),
                "within_rod": o.within_rod,
                "placement": o.placement.as_str(),
                "threshold_M": o.threshold_mass.as_ref().map(|t| t.to_string()),
            }),
        );
        out.insert("omega_max".into(), surd_json(&o.omega_max, decimal_digits));
        out.insert("argmax".into(), Value::String(o.argmax.as_str().into()));
        out.insert("omega_end".into(), value(&o.omega_end));
        out.insert(
            "end_over_max".into(),
            surd_json(&o.end_to_max(), decimal_digits),
        );
        out.insert("gain".into(), surd_json(&o.gain(), decimal_digits));
        let form = PaperForm::of(&self.scene);
        out.insert(
            "paper_form".into(),
            json!({
                "K": form.k.to_string(),
                "b_squared": form.b_squared.to_string(),
                "c": form.c.to_string(),
                "verified": form.verify(&self.scene),
            }),
        );
        Value::Object(out)
    }

    /// The aligned, human-readable report of `solve` (decimals to `digits` significant digits),
    /// every value with its SI unit; a number too long to read is shown as a decimal (the
    /// exact value is in the JSON).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Solution, scene::Scene, field::q};
    /// let text = Solution::of(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap()).to_text(6);
    /// assert!(text.contains("6/5 rad/s"));
    /// assert!(text.contains("a* is on the rod when") && text.contains("M ≤ 2m (here M = m)"));
    /// ```
    pub fn to_text(&self, digits: usize) -> String {
        let s = &self.scene;
        let after = &self.outcome.after;
        let mut t = Table::default();
        let mut out = String::new();
        out.push_str(&format!("Scene: {}\n", describe(s)));
        let length = |x: &Q| format!("{} m", decimal::compact(x));
        out.push_str(&format!(
            "  m = {} kg, M = {} kg, l = {} (rod length {}), a = {}, v0 = {} m/s\n",
            decimal::compact(s.m()),
            decimal::compact(s.rod_mass()),
            length(s.half_length()),
            length(&(s.half_length() * Q::from_integer(2.into()))),
            length(s.a()),
            decimal::compact(s.v0())
        ));
        out.push_str("  (SI units; a number given without a unit is read in SI)\n\n");
        let value = |x: &Q, unit: &str| rational_cells(x, unit, digits);
        t.section("After the impact");
        t.row("v", "projectile velocity", value(&after.v, "m/s"));
        t.row("V", "rod centre velocity", value(&after.rod_v, "m/s"));
        t.row(
            "omega",
            "rod angular velocity",
            value(&after.omega, "rad/s"),
        );
        let impulse = self.outcome.impulse(&s.params::<Q>());
        t.row(
            "J",
            "impulse on the rod, m (v0 - v)",
            value(&impulse, "N s"),
        );
        if let Some(p) = &self.outcome.pivot_impulse {
            t.row("P", "impulse of the pivot on the rod", value(p, "N s"));
        }
        t.section("Kinetic energy");
        let e = &self.outcome.energy;
        t.row("K0", "before", value(&e.before, "J"));
        t.row("K1", "after", value(&e.after, "J"));
        t.row("dK", "lost", value(&e.lost, "J"));
        t.section("Conservation residuals, after - before (0 = the law holds exactly)");
        for (name, r) in self.outcome.residuals.iter() {
            let (label, unit) = match (name, s.support()) {
                ("angular_momentum", Support::Free) => {
                    ("angular momentum about the rod's centre", "kg m^2/s")
                }
                ("angular_momentum", Support::Pivot(_)) => {
                    ("angular momentum about the pivot", "kg m^2/s")
                }
                ("linear_momentum", _) => ("linear momentum", "kg m/s"),
                _ => ("kinetic energy (elastic)", "J"),
            };
            t.row("", label, value(r, unit));
        }
        let o = &self.optimum;
        let (symbol, formula) = match s.support() {
            Support::Free => ("a*^2", "I (M + m)/(m M)"),
            Support::Pivot(_) => ("d*^2", "I_p/m, from the pivot"),
        };
        let star = &symbol[..2];
        t.section("Fastest spin");
        t.row(symbol, formula, value(&o.squared, "m^2"));
        t.row(
            star,
            "optimal distance",
            cells(
                decimal::surd(&o.squared),
                decimal::decimal_sqrt(&o.squared, digits),
                "m",
            ),
        );
        let end = match s.support() {
            Support::Free => "l",
            Support::Pivot(_) => "the pivot-to-end distance",
        };
        let arm = length(&o.arm);
        let place = match o.placement {
            Placement::Inside => format!("inside: {star} < {end} = {arm}"),
            Placement::AtEnd => format!("exactly at the end: {star} = {end} = {arm}"),
            Placement::Beyond => format!("beyond the end: {star} > {end} = {arm}"),
        };
        t.row("", "on the rod", plain(place));
        t.row(
            "",
            &format!("{star} is on the rod when"),
            plain(on_the_rod_when(s, o.threshold_mass.as_ref())),
        );
        let at = match o.argmax {
            Argmax::AStar => format!("max |omega|, reached at {star}"),
            Argmax::End => "max |omega|, reached at the end".to_string(),
        };
        t.row(
            "",
            &at,
            cells(
                o.omega_max.to_string(),
                o.omega_max.decimal(digits),
                "rad/s",
            ),
        );
        let ratio = o.end_to_max();
        t.row(
            "",
            "omega(end)/omega_max",
            cells(ratio.to_string(), ratio.decimal(digits), ""),
        );
        out.push_str(&t.render());
        out
    }
}

/// "M ≤ 2m (here M = m)": the rod masses for which a* lies on the rod, in the scene's terms.
fn on_the_rod_when(s: &Scene, threshold: Option<&Q>) -> String {
    let Some(t) = threshold else {
        return "never: with r_G = l, a* lies beyond the end for every M".into();
    };
    let times_m = |k: &Q| {
        if k.is_one() {
            "m".to_string()
        } else if k.is_integer() {
            format!("{}m", decimal::compact(k))
        } else {
            format!("({})m", decimal::compact(k))
        }
    };
    format!(
        "M ≤ {} (here M = {})",
        times_m(&(t / s.m())),
        times_m(&(s.rod_mass() / s.m()))
    )
}

/// The exact and decimal cells of a rational with its unit.
fn rational_cells(x: &Q, unit: &str, digits: usize) -> [String; 2] {
    let decimal = decimal::decimal(x, digits);
    match decimal::compact(x) {
        c if c.starts_with('≈') => cells(x.to_string(), decimal, unit),
        c => cells(c, decimal, unit),
    }
}

/// The exact and decimal cells with the unit after the exact value; an exact value too long
/// to read becomes `≈ decimal`.
fn cells(exact: String, decimal: String, unit: &str) -> [String; 2] {
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    if exact.chars().count() > decimal::COMPACT_CHARS {
        [format!("≈ {decimal}{unit}"), String::new()]
    } else if exact == decimal {
        [format!("{exact}{unit}"), String::new()]
    } else {
        [format!("{exact}{unit}"), decimal]
    }
}

/// A text cell with no decimal.
fn plain(text: String) -> [String; 2] {
    [text, String::new()]
}

/// The `{"exact": "...", "decimal": "..."}` form of an element of Q(sqrt d).
fn surd_json(x: &QSqrt, digits: usize) -> Value {
    json!({ "exact": x.to_string(), "decimal": x.decimal(digits) })
}

pub(super) fn scene_json(s: &Scene) -> Value {
    let mut out = Map::new();
    let mut put = |k: &str, v: String| {
        out.insert(k.into(), Value::String(v));
    };
    put("m", s.m().to_string());
    put("M", s.rod_mass().to_string());
    put("l", s.half_length().to_string());
    put("a", s.a().to_string());
    put("v0", s.v0().to_string());
    put("e", s.e().to_string());
    put("rod", s.rod().to_string());
    put("I", s.inertia().to_string());
    match s.support() {
        Support::Free => put("support", "free".into()),
        Support::Pivot(p) => {
            put("support", "pivot".into());
            put("pivot", p.to_string());
        }
    }
    Value::Object(out)
}

/// One line describing the scene in words.
pub(super) fn describe(s: &Scene) -> String {
    let support = match s.support() {
        Support::Free => "free rod on a frictionless table".to_string(),
        Support::Pivot(p) => format!("rod on a fixed pivot at p = {} m", decimal::compact(p)),
    };
    let rod = match s.rod() {
        RodInertia::Uniform => "uniform rod, I = M l^2/3".to_string(),
        RodInertia::Dumbbell => "dumbbell, I = M l^2".to_string(),
        RodInertia::Gyration(r) => format!(
            "radius of gyration r_G = {} m, I = M r_G^2",
            decimal::compact(r)
        ),
        RodInertia::Moment(_) => "given moment of inertia".to_string(),
    };
    let law = if s.e().is_one() {
        "elastic (e = 1)".to_string()
    } else if s.e().is_zero() {
        "totally inelastic, sticking (e = 0)".to_string()
    } else {
        format!("restitution e = {}", s.e())
    };
    format!(
        "{support}; {rod} = {} kg m^2; {law}",
        decimal::compact(&s.inertia())
    )
}

/// A small aligned table of (symbol, meaning, exact, decimal) rows under section headings.
#[derive(Default)]
struct Table {
    lines: Vec<[String; 4]>,
    headings: Vec<(usize, String)>,
}

impl Table {
    fn section(&mut self, title: &str) {
        self.headings.push((self.lines.len(), title.to_string()));
    }

    fn row(&mut self, symbol: &str, meaning: &str, [exact, decimal]: [String; 2]) {
        self.lines
            .push([symbol.to_string(), meaning.to_string(), exact, decimal]);
    }

    fn render(&self) -> String {
        let width = |i: usize| {
            self.lines
                .iter()
                .map(|r| r[i].chars().count())
                .max()
                .unwrap_or(0)
        };
        let (w0, w1, w2) = (width(0), width(1), width(2));
        let mut out = String::new();
        for (i, line) in self.lines.iter().enumerate() {
            for (_, title) in self.headings.iter().filter(|(at, _)| *at == i) {
                if i > 0 {
                    out.push('\n');
                }
                out.push_str(title);
                out.push('\n');
            }
            let [sym, meaning, exact, decimal] = line;
            let approx = if decimal.is_empty() {
                String::new()
            } else {
                format!("  ~ {decimal}")
            };
            let row = format!("  {sym:<w0$}  {meaning:<w1$}  {exact:<w2$}{approx}");
            out.push_str(row.trim_end());
            out.push('\n');
        }
        out
    }
}
