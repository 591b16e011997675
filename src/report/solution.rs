//! The answer to one scene, as `rodimpact solve` prints it: JSON (the keys of docs/conventions.md)
//! and an aligned text report.

use super::mathml::escape;
use super::{surd_json, value_json};
use crate::field::Q;
use crate::field::decimal::{self, Rounding};
use crate::impact::EnergyLedger;
use crate::impact::Mode;
use crate::scene::{Oblique, RodInertia, Scene, Support};
use crate::solve::Answer;
use crate::solve::fast::oblique::ObliqueOutcome;
use crate::solve::optimum::{Argmax, Arm, Placement};
use num_traits::{One, Zero};
use serde_json::{Map, Value, json};

/// The JSON object of `solve --json` for `answer`: `scene`, `v`, `V`, `omega`, `impulse` (J on
/// the rod), `energy`, `pivot_impulse` (pivot only), `residuals` (only the laws that apply), `a_star` (with
/// `placement` and `threshold_M`, the rod mass at which a* reaches the end), `omega_max`,
/// `argmax`, `omega_end`, `end_over_max` (omega at the end over omega_max), `gain` (what aiming
/// at a* gains over the end) and `paper_form` (K, b^2, c of the paper's f(x) argument,
/// verified as an identity in a); an oblique scene's keys as in docs/conventions.md. Decimals
/// carry at least 30 significant digits; `a_star`'s bounds satisfy upper - lower <= 10^-digits a*.
///
/// # Examples
/// ```
/// use rodimpact::{report::solution_json, scene::Scene, solve::Answer, field::q};
/// let json = solution_json(&Answer::of(&Scene::builder(q(1, 1), q(1, 1)).build()?), 30);
/// assert_eq!(json["v"]["exact"], "3/5");
/// assert_eq!(json["impulse"]["exact"], "2/5"); // J = m (v0 - v)
/// assert_eq!(json["a_star"]["within_rod"], true);
/// assert!(json.get("pivot_impulse").is_none());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solution_json(answer: &Answer, digits: usize) -> Value {
    let decimal_digits = digits.max(30);
    let value = |x: &Q| value_json(x, decimal_digits);
    let mut out = Map::new();
    out.insert("scene".into(), scene_json(&answer.scene));
    match &answer.impact.oblique {
        None => paper_json(answer, &mut out, &value),
        Some(o) => oblique_json(o, &mut out, &value),
    }
    let Some(o) = &answer.optimum else {
        return Value::Object(out);
    };
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
    if let Some(other) = &o.other_arm {
        let (max, arm) = o.rod_max();
        let argmax = match arm {
            Arm::Struck => o.argmax,
            Arm::Other => other.argmax,
        };
        let mut rod = surd_json(max, decimal_digits);
        if let Value::Object(fields) = &mut rod {
            fields.insert("arm".into(), Value::String(arm.as_str().into()));
            fields.insert("argmax".into(), Value::String(argmax.as_str().into()));
            fields.insert("other_arm".into(), Value::String(other.arm.to_string()));
        }
        out.insert("rod_omega_max".into(), rod);
    }
    let (form, verified) = answer
        .paper_form
        .as_ref()
        .expect("the paper's form accompanies the optimum");
    out.insert(
        "paper_form".into(),
        json!({
            "K": form.k.to_string(),
            "b_squared": form.b_squared.to_string(),
            "c": form.c.to_string(),
            "verified": verified,
        }),
    );
    Value::Object(out)
}
/// The paper scene's `v`, `V`, `omega`, `impulse` (J, the projectile's on the rod), `energy`,
/// `pivot_impulse` and `residuals`.
fn paper_json(answer: &Answer, out: &mut Map<String, Value>, value: &impl Fn(&Q) -> Value) {
    let after = &answer.impact.outcome.after;
    out.insert("v".into(), value(&after.v));
    out.insert("V".into(), value(&after.rod_v));
    out.insert("omega".into(), value(&after.omega));
    out.insert("impulse".into(), value(&answer.impulse));
    let energy = &answer.impact.outcome.energy;
    out.insert(
        "energy".into(),
        json!({
            "before": value(&energy.before),
            "after": value(&energy.after),
            "lost": value(&energy.lost()),
        }),
    );
    if let Some(p) = &answer.impact.outcome.pivot_impulse {
        out.insert("pivot_impulse".into(), value(p));
    }
    out.insert(
        "residuals".into(),
        residuals_json(answer.impact.outcome.residuals.iter()),
    );
}

/// The aligned, human-readable report of `solve` (decimals to `digits` significant digits),
/// every value with its SI unit; a number too long to read is shown as a decimal (the
/// exact value is in the JSON).
///
/// # Examples
/// ```
/// use rodimpact::{report::solution_text, scene::Scene, solve::Answer, field::q};
/// let text = solution_text(&Answer::of(&Scene::builder(q(1, 1), q(1, 1)).build()?), 6);
/// assert!(text.contains("6/5 rad/s"));
/// assert!(text.contains("a* is on the rod when") && text.contains("M ≤ 2m (here M = m)"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solution_text(answer: &Answer, digits: usize) -> String {
    let (head, table) = solution_parts(answer, digits);
    head + "\n" + &table.render()
}

/// The same report as [`solution_text`] for a web page: the scene's lines as a paragraph, the
/// values as an HTML table (one heading row per section; exact value and decimal in columns
/// of their own), every word and value as `solve` prints it.
///
/// # Examples
/// ```
/// use rodimpact::{report::solution_html, scene::Scene, solve::Answer, field::q};
/// let html = solution_html(&Answer::of(&Scene::builder(q(1, 1), q(1, 1)).build()?), 6);
/// assert!(html.starts_with("<p class=\"scene\">Scene: free rod"));
/// assert!(html.contains("<tr><th scope=\"row\">omega</th><td>rod angular velocity</td><td>6/5 rad/s</td><td class=\"decimal\">~ 1.20000</td></tr>"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn solution_html(answer: &Answer, digits: usize) -> String {
    let (head, table) = solution_parts(answer, digits);
    let head: Vec<String> = head.lines().map(|l| escape(l.trim())).collect();
    format!(
        "<p class=\"scene\">{}</p>\n{}",
        head.join("<br>\n"),
        table.html()
    )
}

/// The report's scene lines (ending in a newline) and its table of values.
fn solution_parts(answer: &Answer, digits: usize) -> (String, Table) {
    let s = &answer.scene;
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
    if let Some(o) = s.oblique() {
        out.push_str(&format!("  {}\n", describe_oblique(o)));
    }
    out.push_str("  (SI units; a number given without a unit is read in SI)\n");
    let value = |x: &Q, unit: &str| rational_cells(x, unit, digits);
    match &answer.impact.oblique {
        None => paper_rows(answer, &mut t, &value),
        Some(o) => oblique_rows(answer, o, &mut t, &value),
    }
    let Some(o) = &answer.optimum else {
        t.section("Fastest spin");
        t.row(
            "",
            "not reported",
            plain("the rod turns before the impact, so the approach speed depends on a".into()),
        );
        return (out, t);
    };
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
    let side = if o.other_arm.is_some() {
        " on the struck arm"
    } else {
        ""
    };
    let at = match o.argmax {
        Argmax::AStar => format!("max |omega|{side}, reached at {star}"),
        Argmax::End => format!("max |omega|{side}, reached at the end"),
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
    if let Some(other) = &o.other_arm {
        let (max, arm) = o.rod_max();
        let place = match (arm, other.argmax) {
            (Arm::Struck, _) => "on the struck arm".to_string(),
            (Arm::Other, Argmax::AStar) => format!("at {star} on the other arm"),
            (Arm::Other, Argmax::End) => "at the other arm's end".to_string(),
        };
        t.row(
            "",
            &format!("max |omega| over the rod, {place}"),
            cells(max.to_string(), max.decimal(digits), "rad/s"),
        );
    }
    (out, t)
}
/// The paper scene's rows: velocities after, impulses, energy and residuals.
fn paper_rows(answer: &Answer, t: &mut Table, value: &impl Fn(&Q, &str) -> [String; 2]) {
    let s = &answer.scene;
    let after = &answer.impact.outcome.after;
    t.section("After the impact");
    t.row("v", "projectile velocity", value(&after.v, "m/s"));
    t.row("V", "rod centre velocity", value(&after.rod_v, "m/s"));
    t.row(
        "omega",
        "rod angular velocity",
        value(&after.omega, "rad/s"),
    );
    t.row(
        "J",
        "impulse on the rod, m (v0 - v)",
        value(&answer.impulse, "N s"),
    );
    if let Some(p) = &answer.impact.outcome.pivot_impulse {
        t.row("P", "impulse of the pivot on the rod", value(p, "N s"));
    }
    energy_rows(t, &answer.impact.outcome.energy, value);
    residual_rows(s, t, answer.impact.outcome.residuals.iter(), value);
}

/// The oblique scene's `v`, `V`, `omega`, `vt`, `Vt`, `spin` (disc), `tangential_impulse`,
/// `contact` (with friction), `energy` (with the closed-form losses), `pivot_impulse` and
/// `pivot_impulse_t` (pivot) and `residuals`.
fn oblique_json(o: &ObliqueOutcome<Q>, out: &mut Map<String, Value>, value: &impl Fn(&Q) -> Value) {
    let after = &o.after;
    out.insert("v".into(), value(&after.v));
    out.insert("V".into(), value(&after.rod.v));
    out.insert("omega".into(), value(&after.rod.omega));
    out.insert("vt".into(), value(&after.vt));
    out.insert("Vt".into(), value(&after.rod.vt));
    if let Some(spin) = &after.spin {
        out.insert("spin".into(), value(spin));
    }
    out.insert("impulse".into(), value(&o.impulse));
    out.insert("tangential_impulse".into(), value(&o.tangential_impulse));
    if let Some(contact) = o.contact {
        out.insert("contact".into(), Value::String(contact.kind().into()));
        out.insert("mu_star".into(), value(&o.mu_star()));
    }
    let energy = &o.energy;
    out.insert(
        "energy".into(),
        json!({
            "before": value(&energy.before),
            "after": value(&energy.after),
            "lost": value(&energy.lost()),
            "lost_restitution": value(&o.lost_restitution),
            "lost_friction": value(&o.lost_friction),
        }),
    );
    if let Some((across, along)) = &o.pivot_impulse {
        out.insert("pivot_impulse".into(), value(across));
        out.insert("pivot_impulse_t".into(), value(along));
    }
    out.insert("residuals".into(), residuals_json(o.residuals.iter()));
}

/// `{"name": "exact residual", ...}`.
fn residuals_json<'a>(residuals: impl Iterator<Item = (&'static str, &'a Q)>) -> Value {
    Value::Object(
        residuals
            .map(|(name, r)| (name.to_string(), Value::String(r.to_string())))
            .collect(),
    )
}

/// The oblique scene's rows: both axes after the impact, the disc's spin, both impulses, the
/// contact, energy (with the closed-form losses) and residuals.
fn oblique_rows(
    answer: &Answer,
    o: &ObliqueOutcome<Q>,
    t: &mut Table,
    value: &impl Fn(&Q, &str) -> [String; 2],
) {
    let after = &o.after;
    t.section("After the impact (x across the rod, t along it)");
    t.row(
        "v",
        "projectile velocity across the rod",
        value(&after.v, "m/s"),
    );
    t.row(
        "vt",
        "projectile velocity along the rod",
        value(&after.vt, "m/s"),
    );
    if let Some(spin) = &after.spin {
        t.row(
            "spin",
            "disc angular velocity (counterclockwise)",
            value(spin, "rad/s"),
        );
    }
    t.row(
        "V",
        "rod centre velocity across the rod",
        value(&after.rod.v, "m/s"),
    );
    t.row(
        "Vt",
        "rod centre velocity along the rod",
        value(&after.rod.vt, "m/s"),
    );
    t.row(
        "omega",
        "rod angular velocity",
        value(&after.rod.omega, "rad/s"),
    );
    t.row("J", "normal impulse on the rod", value(&o.impulse, "N s"));
    t.row(
        "Jt",
        "tangential impulse on the rod",
        value(&o.tangential_impulse, "N s"),
    );
    if let Some(contact) = o.contact {
        let meaning = match contact {
            Mode::Stick => "contact: the slip stops (mu >= mu*)",
            Mode::Slide { .. } => "contact: slides throughout, |Jt| = mu J",
            Mode::Frictionless => "contact: frictionless",
        };
        t.row("", meaning, plain(contact.kind().into()));
        t.row(
            "mu*",
            "friction needed to stick, |Jt_stick|/J",
            value(&o.mu_star(), ""),
        );
    }
    if let Some((across, along)) = &o.pivot_impulse {
        t.row(
            "P",
            "impulse of the pivot across the rod",
            value(across, "N s"),
        );
        t.row(
            "Pt",
            "impulse of the pivot along the rod",
            value(along, "N s"),
        );
    }
    energy_rows(t, &o.energy, value);
    t.row(
        "",
        "to restitution (closed form)",
        value(&o.lost_restitution, "J"),
    );
    t.row(
        "",
        "to friction (closed form)",
        value(&o.lost_friction, "J"),
    );
    residual_rows(&answer.scene, t, o.residuals.iter(), value);
}

/// The kinetic energy section.
fn energy_rows(t: &mut Table, e: &EnergyLedger<Q>, value: &impl Fn(&Q, &str) -> [String; 2]) {
    t.section("Kinetic energy");
    t.row("K0", "before", value(&e.before, "J"));
    t.row("K1", "after", value(&e.after, "J"));
    t.row("dK", "lost", value(&e.lost(), "J"));
}

/// The conservation residuals section.
fn residual_rows<'a>(
    s: &Scene,
    t: &mut Table,
    residuals: impl Iterator<Item = (&'static str, &'a Q)>,
    value: &impl Fn(&Q, &str) -> [String; 2],
) {
    t.section("Conservation residuals, after - before (0 = the law holds exactly)");
    for (name, r) in residuals {
        let (label, unit) = match (name, s.support()) {
            ("angular_momentum", Support::Free) => {
                ("angular momentum about the rod's centre", "kg m^2/s")
            }
            ("angular_momentum", Support::Pivot(_)) => {
                ("angular momentum about the pivot", "kg m^2/s")
            }
            ("linear_momentum", _) => ("linear momentum", "kg m/s"),
            ("tangential_momentum", _) => ("linear momentum along the rod", "kg m/s"),
            ("energy_loss", _) => ("energy lost - its closed forms", "J"),
            _ => ("kinetic energy (elastic)", "J"),
        };
        t.row("", label, value(r, unit));
    }
}

/// One line with the oblique inputs that are not zero.
fn describe_oblique(o: &Oblique) -> String {
    let c = decimal::compact;
    let mut parts = vec![
        format!("v0t = {} m/s", c(&o.v0t)),
        format!("mu = {}", c(&o.mu)),
    ];
    if let Some(d) = &o.disc {
        parts.push(format!(
            "disc projectile r = {} m (I = m r^2/2), spin = {} rad/s",
            c(&d.radius),
            c(&d.spin)
        ));
    }
    let rod = &o.rod_before;
    if *rod != Default::default() {
        parts.push(format!(
            "rod before: V0 = {} m/s, Vt0 = {} m/s, omega0 = {} rad/s",
            c(&rod.v),
            c(&rod.vt),
            c(&rod.omega)
        ));
    }
    parts.join(", ")
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
    if let Some(o) = s.oblique() {
        put("v0t", o.v0t.to_string());
        put("mu", o.mu.to_string());
        if let Some(d) = &o.disc {
            put("radius", d.radius.to_string());
            put("spin", d.spin.to_string());
        }
        put("rod_v", o.rod_before.v.to_string());
        put("rod_vt", o.rod_before.vt.to_string());
        put("rod_omega", o.rod_before.omega.to_string());
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

    /// The table in HTML: a heading row per section, a row per line (the symbol as its header
    /// cell), the decimal after `~` in a cell of its own.
    fn html(&self) -> String {
        let mut out = String::from("<table class=\"answer\">\n");
        for (i, line) in self.lines.iter().enumerate() {
            for (_, title) in self.headings.iter().filter(|(at, _)| *at == i) {
                out.push_str(&format!(
                    "<tr class=\"section\"><th colspan=\"4\" scope=\"colgroup\">{}</th></tr>\n",
                    escape(title)
                ));
            }
            let [sym, meaning, exact, decimal] = line.each_ref().map(|x| escape(x));
            let approx = if decimal.is_empty() {
                String::new()
            } else {
                format!("~ {decimal}")
            };
            out.push_str(&format!(
                "<tr><th scope=\"row\">{sym}</th><td>{meaning}</td><td>{exact}</td><td class=\"decimal\">{approx}</td></tr>\n"
            ));
        }
        out.push_str("</table>\n");
        out
    }
}
