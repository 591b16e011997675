//! `rodimpact simulate`: the compliant (penalty) contact integrated in time, against the exact
//! impulsive result; `--sweep-k` prints the convergence in the stiffness with fitted slopes.

use super::{Failure, SceneFlags, print_out};
use clap::{Args, ValueEnum};
use rodimpact::Error;
use rodimpact::contact::{
    Contact, Geometry, Integrator, MAX_STEPS, Run, SweepRow, fit_slope, simulate, steps_needed,
    sweep_k,
};
use rodimpact::field::Field;
use rodimpact::scene::parse_field;
use serde_json::json;

/// The stiffnesses of `--sweep-k`: 1e2 to 1e10, one per decade.
const SWEEP_K: [f64; 9] = [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
/// Default steps per contact time of `--sweep-k`.
const SWEEP_STEPS: u32 = 1000;

#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum IntegratorArg {
    /// Velocity Verlet.
    Verlet,
    /// Classical Runge-Kutta 4.
    Rk4,
    /// Implicit midpoint rule.
    Midpoint,
    /// Backward Euler.
    BackwardEuler,
    /// RK4 on the contact only, free flight analytic, separation located.
    EventRk4,
}

#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GeometryArg {
    /// The rod turns during contact (converges to the impulsive result as k grows).
    Exact,
    /// Normal and lever arm frozen: a linear oscillator (the impulsive result for every k).
    Frozen,
}

#[derive(Args, Debug)]
pub(crate) struct SimulateArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// Spring stiffness k (> 0); the dashpot for e < 1 follows from e.
    #[arg(
        long,
        value_name = "Q",
        allow_hyphen_values = true,
        required_unless_present = "sweep_k"
    )]
    pub(crate) stiffness: Option<String>,
    /// Contact geometry.
    #[arg(long, value_enum, default_value = "exact")]
    pub(crate) geometry: GeometryArg,
    /// One integrator [default: all five for one k, event-rk4 for --sweep-k].
    #[arg(long, value_enum)]
    pub(crate) integrator: Option<IntegratorArg>,
    /// Steps per contact time T_c [default: 100, 1000 for --sweep-k so that the integrator's
    /// error stays below the model's O(1/k) up to k = 1e10].
    #[arg(long, value_name = "N", conflicts_with = "dt",
          value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) steps: Option<u32>,
    /// Fixed time step h in seconds, instead of --steps.
    #[arg(long, value_name = "Q", allow_hyphen_values = true)]
    pub(crate) dt: Option<String>,
    /// Print the convergence table for k = 1e2 .. 1e10 with fitted log-log slopes.
    #[arg(long, conflicts_with_all = ["stiffness", "dt"])]
    pub(crate) sweep_k: bool,
    /// JSON instead of Markdown.
    #[arg(long)]
    pub(crate) json: bool,
}

fn integrator(arg: IntegratorArg) -> Integrator {
    match arg {
        IntegratorArg::Verlet => Integrator::Verlet,
        IntegratorArg::Rk4 => Integrator::Rk4,
        IntegratorArg::Midpoint => Integrator::Midpoint,
        IntegratorArg::BackwardEuler => Integrator::BackwardEuler,
        IntegratorArg::EventRk4 => Integrator::EventRk4,
    }
}

/// A positive exact number, rounded to a finite f64.
fn positive_f64(field: &str, text: &str) -> Result<f64, Error> {
    let x = parse_field(field, text)?.nearest_f64();
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(Error::out_of_range(
            field,
            "must be > 0 and within the f64 range",
        ))
    }
}

/// The step for `contact`: --dt, or T_c / --steps; refused beyond MAX_STEPS steps.
fn step(
    args: &SimulateArgs,
    contact: &Contact,
    k: f64,
    method: Integrator,
    default_steps: u32,
) -> Result<f64, Error> {
    let (h, field) = match &args.dt {
        Some(text) => (positive_f64("dt", text)?, "dt"),
        None => (
            contact.contact_time() / f64::from(args.steps.unwrap_or(default_steps)),
            "steps",
        ),
    };
    if steps_needed(contact, method, h) > MAX_STEPS as f64 {
        return Err(Error::out_of_range(
            field,
            format!(
                "{} needs more than {MAX_STEPS} steps at k = {k:e}",
                method.name()
            ),
        ));
    }
    Ok(h)
}

pub(crate) fn run_simulate(args: &SimulateArgs) -> Result<(), Failure> {
    let scene = args.scene.input().build()?;
    let geometry = match args.geometry {
        GeometryArg::Exact => Geometry::Exact,
        GeometryArg::Frozen => Geometry::Frozen,
    };
    if args.sweep_k {
        let method = args.integrator.map_or(Integrator::EventRk4, integrator);
        let k = SWEEP_K[SWEEP_K.len() - 1];
        step(
            args,
            &Contact::new(&scene, k, geometry)?,
            k,
            method,
            SWEEP_STEPS,
        )?;
        let steps = args.steps.unwrap_or(SWEEP_STEPS) as usize;
        let rows = sweep_k(&scene, &SWEEP_K, geometry, method, steps)?;
        print_out(&sweep_report(&rows, method, args.json));
        return Ok(());
    }
    let k = positive_f64("stiffness", args.stiffness.as_deref().unwrap_or_default())?;
    let contact = Contact::new(&scene, k, geometry)?;
    let methods: Vec<Integrator> = match args.integrator {
        Some(arg) => vec![integrator(arg)],
        None => Integrator::ALL.to_vec(),
    };
    let mut runs = Vec::new();
    for method in methods {
        let h = step(args, &contact, k, method, 100)?;
        runs.push((method, h, simulate(&contact, method, h)));
    }
    print_out(&run_report(&contact, k, &runs, args.json));
    Ok(())
}

fn run_report(contact: &Contact, k: f64, runs: &[(Integrator, f64, Run)], as_json: bool) -> String {
    let [v, rod_v, omega] = contact.reference();
    let omega_c = contact.frequency();
    if as_json {
        let rows: Vec<_> = runs
            .iter()
            .map(|(method, h, run)| {
                json!({
                    "integrator": method.name(), "h": h, "h_omega": h * omega_c,
                    "steps": run.steps,
                    "v": run.velocities[0], "V": run.velocities[1], "omega": run.velocities[2],
                    "rel_err": {"v": run.errors[0], "V": run.errors[1], "omega": run.errors[2]},
                    "lateral": run.lateral, "energy_change": run.energy_change,
                    "seconds": run.seconds,
                })
            })
            .collect();
        let doc = json!({
            "stiffness": k, "contact_time": contact.contact_time(), "frequency": omega_c,
            "exact": {"v": v, "V": rod_v, "omega": omega}, "runs": rows,
        });
        return format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).expect("JSON of numbers")
        );
    }
    let mut out = format!(
        "compliant contact: k = {k:e}, T_c = {:.4e} s, Omega = {omega_c:.4e} 1/s\n\
         exact impulsive: v = {v:.15e}, V = {rod_v:.15e}, omega = {omega:.15e}\n\n\
         | integrator | h Omega | steps | err v | err V | err omega | lateral/v0 | dE/E | time (s) |\n\
         |---|---|---|---|---|---|---|---|---|\n",
        contact.contact_time()
    );
    for (method, h, run) in runs {
        out += &format!(
            "| {} | {:.3} | {} | {:.2e} | {:.2e} | {:.2e} | {:.2e} | {:+.2e} | {:.2e} |\n",
            method.name(),
            h * omega_c,
            run.steps,
            run.errors[0],
            run.errors[1],
            run.errors[2],
            run.lateral,
            run.energy_change,
            run.seconds
        );
    }
    out
}

fn sweep_report(rows: &[SweepRow], method: Integrator, as_json: bool) -> String {
    let ks: Vec<f64> = rows.iter().map(|r| r.k).collect();
    let slopes: Vec<Option<f64>> = (0..4)
        .map(|i| fit_slope(&ks, &rows.iter().map(|r| r.errors[i]).collect::<Vec<_>>()))
        .collect();
    if as_json {
        let table: Vec<_> = rows
            .iter()
            .map(|r| {
                json!({"k": r.k, "contact_time": r.contact_time, "turn": r.turn,
                       "rel_err": {"v": r.errors[0], "V": r.errors[1], "omega": r.errors[2]},
                       "lateral": r.errors[3], "seconds": r.seconds})
            })
            .collect();
        let doc = json!({
            "integrator": method.name(), "rows": table,
            "slopes": {"v": slopes[0], "V": slopes[1], "omega": slopes[2], "lateral": slopes[3]},
        });
        return format!(
            "{}\n",
            serde_json::to_string_pretty(&doc).expect("JSON of numbers")
        );
    }
    let mut out = format!(
        "convergence in k ({}): relative error against the exact impulsive values\n\n\
         | k | T_c (s) | turn (rad) | err v | err V | err omega | lateral/v0 | time (s) |\n\
         |---|---|---|---|---|---|---|---|\n",
        method.name()
    );
    for r in rows {
        out += &format!(
            "| {:.0e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.2e} |\n",
            r.k,
            r.contact_time,
            r.turn,
            r.errors[0],
            r.errors[1],
            r.errors[2],
            r.errors[3],
            r.seconds
        );
    }
    let show = |s: Option<f64>| s.map_or("n/a".to_string(), |s| format!("{s:.3}"));
    out += &format!(
        "\nfitted log-log slopes (least squares): v {}, V {}, omega {}, lateral {}\n",
        show(slopes[0]),
        show(slopes[1]),
        show(slopes[2]),
        show(slopes[3])
    );
    out
}
