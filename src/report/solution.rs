//! The answer to one scene, as `rodimpact solve` prints it: JSON (the contract of DESIGN.md §3)
//! and an aligned text report.

use super::value_json;
use crate::field::{Q, QSqrt};
use crate::number::{self, Rounding};
use crate::optimum::{Argmax, Optimum, PaperForm, Placement, optimum};
use crate::scene::{RodInertia, Scene, Support};
use crate::solve::{Outcome, solve};
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
    /// Solves `scene` over Q and computes its optimum.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Solution, scene::Scene, field::q};
    /// let s = Solution::of(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap());
    /// assert_eq!(s.outcome.after.omega, q(6, 5));
    /// ```
    pub fn of(scene: &Scene) -> Solution {
        let outcome = solve(&scene.params::<Q>())
            .expect("a valid scene has a nonzero determinant -(mI + MI + Mma^2) over Q");
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
        let (lower, upper) = number::sqrt_bounds(&o.squared, digits + 1);
        out.insert(
            "a_star".into(),
            json!({
                "squared": o.squared.to_string(),
                "exact": number::surd(&o.squared),
                "decimal": number::decimal_sqrt(&o.squared, decimal_digits),
                "lower": number::decimal_rounded(&lower, digits + 2, Rounding::Floor),
                "upper": number::decimal_rounded(&upper, digits + 2, Rounding::Ceiling),
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

    /// The aligned, human-readable report of `solve` (decimals to `digits` significant digits).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Solution, scene::Scene, field::q};
    /// let text = Solution::of(&Scene::builder(q(1, 1), q(1, 1)).build().unwrap()).to_text(6);
    /// assert!(text.contains("omega"));
    /// assert!(text.contains("6/5"));
    /// ```
    pub fn to_text(&self, digits: usize) -> String {
        let s = &self.scene;
        let after = &self.outcome.after;
        let mut t = Table::default();
        let mut out = String::new();
        out.push_str(&format!("Scene: {}\n", describe(s)));
        out.push_str(&format!(
            "  m = {}, M = {}, l = {} (rod length {}), a = {}, v0 = {}\n\n",
            s.m(),
            s.rod_mass(),
            s.half_length(),
            s.half_length() * Q::from_integer(2.into()),
            s.a(),
            s.v0()
        ));
        let dec = |x: &Q| number::decimal(x, digits);
        t.section("After the impact");
        t.row(
            "v",
            "projectile velocity",
            after.v.to_string(),
            dec(&after.v),
        );
        t.row(
            "V",
            "rod centre velocity",
            after.rod_v.to_string(),
            dec(&after.rod_v),
        );
        t.row(
            "omega",
            "rod angular velocity",
            after.omega.to_string(),
            dec(&after.omega),
        );
        let impulse = self.outcome.impulse(&s.params::<Q>());
        t.row(
            "J",
            "impulse on the rod, m (v0 - v)",
            impulse.to_string(),
            dec(&impulse),
        );
        if let Some(p) = &self.outcome.pivot_impulse {
            t.row(
                "P",
                "impulse of the pivot on the rod",
                p.to_string(),
                dec(p),
            );
        }
        t.section("Kinetic energy");
        let e = &self.outcome.energy;
        t.row("K0", "before", e.before.to_string(), dec(&e.before));
        t.row("K1", "after", e.after.to_string(), dec(&e.after));
        t.row("dK", "lost", e.lost.to_string(), dec(&e.lost));
        t.section("Conservation residuals, after - before (0 = the law holds exactly)");
        for (name, r) in self.outcome.residuals.iter() {
            let label = match (name, s.support()) {
                ("angular_momentum", Support::Free) => "angular momentum about the rod's centre",
                ("angular_momentum", Support::Pivot(_)) => "angular momentum about the pivot",
                ("linear_momentum", _) => "linear momentum",
                _ => "kinetic energy (elastic)",
            };
            t.row("", label, r.to_string(), String::new());
        }
        let o = &self.optimum;
        let (symbol, formula) = match s.support() {
            Support::Free => ("a*^2", "I (M + m)/(m M)"),
            Support::Pivot(_) => ("d*^2", "I_p/m, from the pivot"),
        };
        t.section("Fastest spin");
        t.row(symbol, formula, o.squared.to_string(), dec(&o.squared));
        t.row(
            &symbol[..2],
            "optimal distance",
            number::surd(&o.squared),
            number::decimal_sqrt(&o.squared, digits),
        );
        let star = &symbol[..2];
        let place = match o.placement {
            Placement::Inside => format!("inside: {star} < {}", o.arm),
            Placement::AtEnd => format!("exactly at the end: {star} = {}", o.arm),
            Placement::Beyond => format!("beyond the end: {star} > {}", o.arm),
        };
        t.row("", "on the rod", place, String::new());
        let threshold = match &o.threshold_mass {
            Some(t) => format!("M <= {t}, i.e. M/m <= {}", t / s.m()),
            None => "never (dumbbell: a* > l for every M)".into(),
        };
        t.row("", "on the rod when (this I/M)", threshold, String::new());
        let at = match o.argmax {
            Argmax::AStar => "max |omega|, reached at the optimum",
            Argmax::End => "max |omega|, reached at the end",
        };
        t.row("", at, o.omega_max.to_string(), o.omega_max.decimal(digits));
        let ratio = o.end_to_max();
        t.row(
            "",
            "omega(end)/omega_max",
            ratio.to_string(),
            ratio.decimal(digits),
        );
        let form = PaperForm::of(s);
        let x = match s.support() {
            Support::Free => "x = a",
            Support::Pivot(_) => "x = a - p",
        };
        t.row(
            "K",
            &format!("omega = K x/(b^2 + c^2 x^2), {x}"),
            form.k.to_string(),
            String::new(),
        );
        let verdict = if form.verify(s) {
            "identity in x: checked"
        } else {
            "identity in x: FAILS"
        };
        t.row(
            "b^2",
            &format!("c = {}; {verdict}", form.c),
            form.b_squared.to_string(),
            String::new(),
        );
        out.push_str(&t.render());
        out
    }
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
        Support::Pivot(p) => format!("rod on a fixed pivot at p = {p}"),
    };
    let rod = match s.rod() {
        RodInertia::Uniform => "uniform rod, I = M l^2/3".to_string(),
        RodInertia::Dumbbell => "dumbbell, I = M l^2".to_string(),
        RodInertia::Gyration(r) => format!("radius of gyration r_G = {r}, I = M r_G^2"),
        RodInertia::Moment(_) => "given moment of inertia".to_string(),
    };
    let law = if s.e().is_one() {
        "elastic (e = 1)".to_string()
    } else if s.e().is_zero() {
        "totally inelastic, sticking (e = 0)".to_string()
    } else {
        format!("restitution e = {}", s.e())
    };
    format!("{support}; {rod} = {}; {law}", s.inertia())
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

    fn row(&mut self, symbol: &str, meaning: &str, exact: String, decimal: String) {
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
            let approx = if decimal.is_empty() || decimal == exact {
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
