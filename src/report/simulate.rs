//! The stiff-contact cross-check as `rodimpact simulate` prints it: the exact impulsive values
//! as exact numbers with decimals, one row per run or per stiffness with every column defined,
//! and the verdict (text and JSON).

use super::solution::{describe, scene_json};
use crate::compliant::{
    CompliantContact, Geometry, Integrator, LOOSEST, Run, RunEnd, Slopes, SweepRow, Tolerance,
    stability_limit,
};
use crate::field::Q;
use crate::field::decimal;
use serde_json::{Value, json};

/// Significant digits of the decimals beside the exact values.
const DIGITS: usize = 15;

/// The text report of one stiffness with one or more integrators: scene, model, exact values,
/// the table of runs, a legend of its columns and the verdict.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, simulate};
/// use rodimpact::{field::q, report::simulation_text, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
/// let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 100.0)?;
/// let text = simulation_text(&c, &[run]);
/// assert!(text.contains("3/11"));
/// assert!(text.contains("| event-rk4 | 0.031 | 100 |"));
/// assert!(text.ends_with("The run reproduces the exact values within its tolerance.\n"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn simulation_text(contact: &CompliantContact, runs: &[Run]) -> String {
    let pivoted = contact.reference_pivot_impulse().is_some();
    let mut out = header(contact);
    out += &format!(
        "Model: {}, k = {:e}, Omega = sqrt(k/mu_eff) = {:.4e} 1/s, {}\n\n",
        geometry_words(contact.geometry()),
        contact.stiffness(),
        contact.frequency(),
        time_words(contact)
    );
    out += &exact_block(contact);
    let pivot_head = if pivoted { " err P |" } else { "" };
    out += &format!(
        "\n| integrator | h Omega | steps | err v | err V | err omega |{pivot_head} lateral/v0 | \
         dE/E | tolerance | verdict | time (s) |\n|{}\n",
        "---|".repeat(if pivoted { 12 } else { 11 })
    );
    let omega_c = contact.frequency();
    for run in runs {
        let pivot_cell = match run.pivot_error {
            Some(e) => format!(" {e:.2e} |"),
            None => String::new(),
        };
        out += &format!(
            "| {} | {} | {} | {:.2e} | {:.2e} | {:.2e} |{pivot_cell} {:+.2e} | {:+.2e} | \
             {:.1e} | {} | {:.2e} |\n",
            run.integrator.name(),
            fixed_or_sci(run.h * omega_c),
            run.steps,
            run.errors[0],
            run.errors[1],
            run.errors[2],
            run.lateral,
            run.energy_change,
            run.tolerance.total(),
            verdict_word(run, false),
            run.seconds
        );
    }
    out += "\nColumns\n";
    out += &format!(
        "  h Omega     the step h times Omega, the integrators' accuracy parameter (for this \
         contact Verlet is stable below {:.3}, RK4 below {:.3})\n",
        stability_limit(contact, Integrator::Verlet).unwrap_or(f64::NAN),
        stability_limit(contact, Integrator::Rk4).unwrap_or(f64::NAN)
    );
    out += &format!("  steps       {}\n", steps_words(contact));
    out += &error_legend(pivoted);
    out += "  lateral/v0  the projectile's velocity along the rod afterwards, over v0 (0 in the \
            impulsive model; O(k^-1/2))\n";
    out += "  dE/E        (E_end - E_0)/E_0, kinetic plus spring energy (the exact value is \
            above)\n";
    out += &tolerance_legend(contact.geometry(), Some(contact));
    out += "  verdict     ok, or MISS with the reason below\n";
    out += "  time (s)    wall-clock time of the run\n\n";
    out += &verdict_lines(runs);
    out
}

/// `true` when the runs of one stiffness pass: none misses.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, simulate};
/// use rodimpact::{field::q, report::simulation_passes, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e2, Geometry::Exact)?; // too soft: the model floor is 0.43
/// let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 100.0)?;
/// assert!(!simulation_passes(&[run]));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn simulation_passes(runs: &[Run]) -> bool {
    runs.iter().all(|r| r.miss.is_none())
}

/// `true` when a sweep passes: every row either checks (no miss) or is too soft to check (its
/// tolerance above [`LOOSEST`], whatever happened in it), and the stiffest row checks.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{Geometry, Integrator, sweep_k};
/// use rodimpact::{field::q, report::sweep_passes, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let rows = sweep_k(&scene, &[1e2, 1e6], Geometry::Exact, Integrator::EventRk4, 100)?;
/// assert!(rows[0].run.miss.is_some()); // k = 1e2 is too soft to check
/// assert!(sweep_passes(&rows));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn sweep_passes(rows: &[SweepRow]) -> bool {
    rows.iter().all(|r| too_soft(r) || r.run.miss.is_none())
        && rows.last().is_some_and(|r| r.run.miss.is_none())
}

/// A sweep row whose tolerance is above [`LOOSEST`]: too soft (or too coarse) to check.
fn too_soft(row: &SweepRow) -> bool {
    row.run.tolerance.total() > LOOSEST
}

/// h Omega with three decimals, or in scientific form when smaller than 0.001.
fn fixed_or_sci(x: f64) -> String {
    if x >= 1e-3 {
        format!("{x:.3}")
    } else {
        format!("{x:.2e}")
    }
}

/// The JSON report of one stiffness: scene, model, the exact values as exact strings (and
/// their f64 roundings, which the errors are measured against), the runs and `ok`.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{CompliantContact, Geometry, Integrator, simulate};
/// use rodimpact::{field::q, report::simulation_json, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let c = CompliantContact::new(&scene, 1e6, Geometry::Exact)?;
/// let run = simulate(&c, Integrator::EventRk4, c.contact_time() / 100.0)?;
/// let doc = simulation_json(&c, &[run]);
/// assert_eq!(doc["exact"]["v"], "3/11");
/// assert_eq!(doc["runs"][0]["steps"], 100);
/// assert_eq!(doc["ok"], true);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn simulation_json(contact: &CompliantContact, runs: &[Run]) -> Value {
    let omega_c = contact.frequency();
    let rows: Vec<Value> = runs
        .iter()
        .map(|run| {
            let mut row = json!({
                "integrator": run.integrator.name(), "h": run.h, "h_omega": run.h * omega_c,
                "steps": run.steps,
            });
            merge(&mut row, run_json(run));
            row
        })
        .collect();
    let mut doc = model_json(contact);
    merge(
        &mut doc,
        json!({
            "stiffness": contact.stiffness(), "frequency": omega_c,
            "contact_time": contact.contact_time(), "runs": rows,
            "ok": simulation_passes(runs),
        }),
    );
    doc
}

/// The text report of a stiffness sweep: the scene, the exact values, one row per k, the
/// fitted convergence slopes, a legend and the verdict. `rows` must not be empty.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{Geometry, Integrator, sweep_k};
/// use rodimpact::{field::q, report::sweep_text, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let rows = sweep_k(&scene, &[1e4, 1e6, 1e8], Geometry::Exact, Integrator::EventRk4, 400)?;
/// let text = sweep_text(&rows, 400);
/// assert!(text.contains("v -1.000, V -1.000, omega -1.000, lateral -0.500"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn sweep_text(rows: &[SweepRow], steps_per_contact: usize) -> String {
    let Some(first) = rows.first() else {
        return String::new();
    };
    let contact = &first.contact;
    let pivoted = contact.reference_pivot_impulse().is_some();
    let mut out = header(contact);
    out += &format!(
        "Model: {}, {} with {steps_per_contact} steps per T_c, k = {:e} to {:e}\n\n",
        geometry_words(contact.geometry()),
        first.run.integrator.name(),
        contact.stiffness(),
        rows[rows.len() - 1].contact.stiffness()
    );
    out += &exact_block(contact);
    let pivot_head = if pivoted { " err P |" } else { "" };
    out += &format!(
        "\n| k | T_c (s) | turn (rad) | err v | err V | err omega |{pivot_head} lateral/v0 | \
         tolerance | verdict | time (s) |\n|{}\n",
        "---|".repeat(if pivoted { 11 } else { 10 })
    );
    for row in rows {
        let run = &row.run;
        let pivot_cell = match run.pivot_error {
            Some(e) => format!(" {e:.3e} |"),
            None => String::new(),
        };
        out += &format!(
            "| {:.0e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |{pivot_cell} {:.3e} | \
             {:.1e} | {} | {:.2e} |\n",
            row.contact.stiffness(),
            row.contact.contact_time(),
            row.turn(),
            run.errors[0],
            run.errors[1],
            run.errors[2],
            run.lateral.abs(),
            run.tolerance.total(),
            verdict_word(run, true),
            run.seconds
        );
    }
    let slopes = Slopes::of(rows);
    let show = |s: Option<f64>| s.map_or("n/a".to_string(), |s| format!("{s:.3}"));
    let pivot = if pivoted {
        format!(", P {}", show(slopes.pivot))
    } else {
        String::new()
    };
    out += &format!(
        "\nfitted log-log slopes (least squares over k): v {}, V {}, omega {}{pivot}, lateral {}\n",
        show(slopes.errors[0]),
        show(slopes.errors[1]),
        show(slopes.errors[2]),
        show(slopes.lateral)
    );
    out += match contact.geometry() {
        Geometry::Exact => {
            "(the exact geometry predicts -1 for v, V, omega and P, and -0.5 for the lateral \
             velocity; n/a where an error is exactly 0)\n"
        }
        Geometry::Frozen => {
            "(the frozen oscillator is exact for every k: its errors are the integrator's and \
             rounding, with no trend in k)\n"
        }
    };
    out += "\nColumns\n";
    out += &format!(
        "  T_c         {}\n",
        if contact.sticking() {
            "the settle time T_s of the sticking contact, when its remaining relative motion is \
             1e-13 v0"
        } else {
            "the contact time of the frozen oscillator"
        }
    );
    out += "  turn        the rod's turn during the contact, |omega| T_c\n";
    out += &error_legend(pivoted);
    out += "  lateral/v0  |the projectile's velocity along the rod afterwards| over v0\n";
    out += &tolerance_legend(contact.geometry(), None);
    out += "  verdict     ok; loose when the tolerance is above 10 % (k too soft or step too \
            coarse to check; the stiffest k must check); MISS with the reason below\n";
    out += "  time (s)    wall-clock time of the run\n\n";
    out += &sweep_verdict_lines(rows);
    out
}

/// The JSON report of a stiffness sweep: scene, exact values, rows, slopes and `ok`.
/// `rows` must not be empty.
///
/// # Examples
/// ```
/// use rodimpact::compliant::{Geometry, Integrator, sweep_k};
/// use rodimpact::{field::q, report::sweep_json, scene::Scene};
/// let scene = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).pivot(q(0, 1)).build()?;
/// let rows = sweep_k(&scene, &[1e4, 1e6, 1e8], Geometry::Exact, Integrator::EventRk4, 400)?;
/// let doc = sweep_json(&rows, 400);
/// assert_eq!(doc["exact"]["P"], "-8/7");
/// assert!((doc["slopes"]["P"].as_f64().unwrap() + 1.0).abs() < 0.01);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn sweep_json(rows: &[SweepRow], steps_per_contact: usize) -> Value {
    let Some(first) = rows.first() else {
        return Value::Null;
    };
    let table: Vec<Value> = rows
        .iter()
        .map(|r| {
            let mut row = json!({
                "k": r.contact.stiffness(), "contact_time": r.contact.contact_time(),
                "turn": r.turn(), "steps": r.run.steps,
            });
            merge(&mut row, run_json(&r.run));
            row
        })
        .collect();
    let slopes = Slopes::of(rows);
    let mut slope_doc = json!({
        "v": slopes.errors[0], "V": slopes.errors[1], "omega": slopes.errors[2],
        "lateral": slopes.lateral,
    });
    if first.contact.reference_pivot_impulse().is_some() {
        slope_doc["P"] = json!(slopes.pivot);
    }
    let mut doc = model_json(&first.contact);
    merge(
        &mut doc,
        json!({
            "integrator": first.run.integrator.name(), "steps_per_contact": steps_per_contact,
            "rows": table, "slopes": slope_doc,
            "ok": sweep_passes(rows),
        }),
    );
    doc
}

/// Adds the members of the object `extra` to the object `doc`.
fn merge(doc: &mut Value, extra: Value) {
    if let (Value::Object(doc), Value::Object(extra)) = (doc, extra) {
        doc.extend(extra);
    }
}

/// The scene (words and numbers).
fn header(contact: &CompliantContact) -> String {
    let scene = contact.scene();
    let numbers = scene_json(scene);
    let list: Vec<String> = ["m", "M", "l", "a", "v0"]
        .iter()
        .map(|key| format!("{key} = {}", numbers[*key].as_str().unwrap_or("?")))
        .collect();
    format!(
        "Stiff-contact cross-check of the impulse. Scene: {}\n  {}\n",
        describe(scene),
        list.join(", ")
    )
}

fn geometry_words(geometry: Geometry) -> &'static str {
    match geometry {
        Geometry::Exact => "exact geometry (the rod turns during the contact)",
        Geometry::Frozen => "frozen geometry (normal and lever arm fixed: a linear oscillator)",
    }
}

fn time_words(contact: &CompliantContact) -> String {
    if contact.sticking() {
        format!(
            "T_s = {:.4e} s (settle time of the glued, critically damped contact)",
            contact.contact_time()
        )
    } else {
        format!("T_c = {:.4e} s (contact time)", contact.contact_time())
    }
}

fn steps_words(contact: &CompliantContact) -> &'static str {
    if contact.sticking() {
        "fixed-step methods run through the approach (l/10 at v0) and T_s; event-rk4 integrates \
         only the contact, from its onset to T_s"
    } else {
        "fixed-step methods run from rest through the approach (l/10 at v0) and the contact, to \
         the first step after separation; event-rk4 integrates only the contact, from its onset \
         to the located separation"
    }
}

/// The exact values, exact with a decimal beside, and the energy change they imply.
fn exact_block(contact: &CompliantContact) -> String {
    let exact = contact.exact();
    let mut rows: Vec<(&str, &str, Q)> = vec![
        ("v", "projectile velocity", exact.after.v.clone()),
        ("V", "rod centre velocity", exact.after.rod_v.clone()),
        ("omega", "rod angular velocity", exact.after.omega.clone()),
    ];
    if let Some(p) = &exact.pivot_impulse {
        rows.push(("P", "impulse of the pivot on the rod", p.clone()));
    }
    rows.push((
        "dE/E",
        "energy change, -lost/before",
        -(exact.energy.lost() / &exact.energy.before),
    ));
    let width = |i: usize| {
        rows.iter()
            .map(|r| [r.0, r.1][i].chars().count())
            .max()
            .unwrap_or(0)
    };
    let (w0, w1) = (width(0), width(1));
    let exacts: Vec<String> = rows.iter().map(|r| r.2.to_string()).collect();
    let w2 = exacts.iter().map(|s| s.chars().count()).max().unwrap_or(0);
    let mut out = String::from("Exact impulsive values (the exact solver)\n");
    for ((symbol, meaning, value), text) in rows.iter().zip(&exacts) {
        let decimal = decimal::decimal(value, DIGITS);
        let beside = if &decimal == text {
            String::new()
        } else {
            format!("  ~ {decimal}")
        };
        let line = format!("  {symbol:<w0$}  {meaning:<w1$}  {text:<w2$}{beside}");
        out += line.trim_end();
        out.push('\n');
    }
    out
}

fn error_legend(pivoted: bool) -> String {
    let p = if pivoted {
        "; P: over max(|P|, J), J = m (v0 - v) the contact impulse"
    } else {
        ""
    };
    format!(
        "  err X       relative error |X_sim - X_exact| / |X_exact| (v: over max(|v|, |v0 - v|){p}; \
         over v0 or v0/l where X_exact = 0)\n"
    )
}

/// The tolerance column's definition; `contact` gives the model floor's value (one stiffness),
/// `None` in a sweep, where it falls with k.
fn tolerance_legend(geometry: Geometry, contact: Option<&CompliantContact>) -> String {
    let value = contact.map_or(String::new(), |c| {
        let model = Tolerance::of(c, Integrator::EventRk4, 0.0, 0).model;
        format!(" {model:.1e}")
    });
    let floor = match geometry {
        Geometry::Exact => format!(
            "the model's O(1/k) floor{value} (10 theta_c^2, theta_c = max(|omega|, v0/l) T_c, T_s \
             where that is shorter)"
        ),
        Geometry::Frozen => "no model floor (the frozen oscillator is exact)".to_string(),
    };
    format!(
        "  tolerance   the largest error accepted: {floor} + the integrator's error at h Omega \
         (x/5 + x^2/5 Verlet and RK4, x/2 + x^2/5 midpoint, 2x backward Euler, x^4/50 \
         event-rk4) + rounding\n"
    )
}

/// The verdict cell: `ok`, `MISS`, or in a sweep `loose` for a row too soft to check.
fn verdict_word(run: &Run, sweep: bool) -> &'static str {
    if run.miss.is_none() {
        "ok"
    } else if sweep && run.tolerance.total() > LOOSEST {
        "loose"
    } else {
        "MISS"
    }
}

/// The closing lines of one stiffness: every run within tolerance, or each miss with its reason.
fn verdict_lines(runs: &[Run]) -> String {
    let misses: Vec<String> = runs
        .iter()
        .filter_map(|run| {
            let miss = run.miss.as_ref()?;
            Some(format!("  {}: {miss}\n", run.integrator.name()))
        })
        .collect();
    let n = runs.len();
    match (misses.len(), n) {
        (0, 1) => "The run reproduces the exact values within its tolerance.\n".to_string(),
        (0, _) => format!("All {n} runs reproduce the exact values within their tolerances.\n"),
        (1, 1) => format!(
            "MISS: the run misses the exact values:\n{}",
            misses.concat()
        ),
        (missed, _) => format!(
            "MISS: {missed} of {n} runs miss the exact values:\n{}",
            misses.concat()
        ),
    }
}

/// The closing lines of a sweep: the count of rows that check and of those too soft to, or
/// each miss with its reason.
fn sweep_verdict_lines(rows: &[SweepRow]) -> String {
    let last = rows.len() - 1;
    let misses: Vec<String> = rows
        .iter()
        .enumerate()
        .filter(|(i, row)| row.run.miss.is_some() && (!too_soft(row) || *i == last))
        .map(|(_, row)| {
            let miss = row.run.miss.as_ref().map(ToString::to_string);
            format!(
                "  k = {:e}: {}\n",
                row.contact.stiffness(),
                miss.unwrap_or_default()
            )
        })
        .collect();
    if !misses.is_empty() {
        return format!(
            "MISS: the sweep does not check the impulse:\n{}",
            misses.concat()
        );
    }
    let soft = rows
        .iter()
        .filter(|row| row.run.miss.is_some() && too_soft(row))
        .count();
    let checked = rows.len() - soft;
    let soft_note = match soft {
        0 => String::new(),
        1 => "; 1 is too soft to check (loose)".to_string(),
        _ => format!("; {soft} are too soft to check (loose)"),
    };
    format!(
        "The sweep passes: {checked} of {} stiffnesses reproduce the exact values within their \
         tolerances{soft_note}.\n",
        rows.len()
    )
}

/// The scene, the model and the exact values (as exact strings, and rounded to f64).
fn model_json(contact: &CompliantContact) -> Value {
    let exact = contact.exact();
    let mut exact_doc = json!({
        "v": exact.after.v.to_string(), "V": exact.after.rod_v.to_string(),
        "omega": exact.after.omega.to_string(),
        "energy_change": (-(exact.energy.lost() / &exact.energy.before)).to_string(),
    });
    let [v, rod_v, omega] = contact.reference();
    let mut reference = json!({"v": v, "V": rod_v, "omega": omega});
    if let (Some(p), Some(p64)) = (&exact.pivot_impulse, contact.reference_pivot_impulse()) {
        exact_doc["P"] = json!(p.to_string());
        reference["P"] = json!(p64);
    }
    json!({
        "scene": scene_json(contact.scene()),
        "geometry": match contact.geometry() { Geometry::Exact => "exact", Geometry::Frozen => "frozen" },
        "contact": if contact.sticking() { "sticking" } else { "bouncing" },
        "exact": exact_doc, "exact_f64": reference,
    })
}

/// The fields of one run shared by both JSON reports.
fn run_json(run: &Run) -> Value {
    let mut doc = json!({
        "v": run.velocities[0], "V": run.velocities[1], "omega": run.velocities[2],
        "rel_err": {"v": run.errors[0], "V": run.errors[1], "omega": run.errors[2]},
        "lateral": run.lateral, "energy_change": run.energy_change,
        "ending": match run.ending {
            RunEnd::Separated => "separated",
            RunEnd::Settled => "settled",
            RunEnd::SlidOff => "slid off the rod's end",
            RunEnd::StillInContact => "still in contact",
        },
        "tolerance": {
            "model": run.tolerance.model, "integrator": run.tolerance.integrator,
            "rounding": run.tolerance.rounding, "total": run.tolerance.total(),
        },
        "ok": run.miss.is_none(),
        "miss": run.miss.as_ref().map(ToString::to_string),
        "seconds": run.seconds,
    });
    if let (Some(p), Some(err)) = (run.pivot_impulse, run.pivot_error) {
        doc["P"] = json!(p);
        doc["rel_err"]["P"] = json!(err);
    }
    doc
}
