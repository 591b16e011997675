//! `rodimpact simulate`: the compliant (penalty) contact integrated in time, against the exact
//! impulsive result; `--sweep-k` prints the convergence in the stiffness with fitted slopes.
//! The model lives in `rodimpact::compliant`, the report in `rodimpact::report`.

use super::{Failure, SceneFlags, print_out};
use clap::{Args, ValueEnum};
use rodimpact::Error;
use rodimpact::compliant::{
    CompliantContact, Geometry, Integrator, MAX_WORK, simulate, sweep_k, work,
};
use rodimpact::field::Field;
use rodimpact::report::{
    simulation_json, simulation_passes, simulation_text, sweep_json, sweep_passes, sweep_text,
};
use rodimpact::scene::parse_field;

/// The stiffnesses of `--sweep-k`: 1e2 to 1e10, one per decade.
const SWEEP_K: [f64; 9] = [1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
/// Steps per pi/Omega (an elastic contact time) by default: h Omega = pi/100.
const STEPS: u32 = 100;
/// Steps per pi/Omega by default for `--sweep-k`, ten times finer.
const SWEEP_STEPS: u32 = 1000;

/// The default steps per contact time: `base` per pi/Omega, so that h Omega = pi/base whatever
/// the law (a damped contact lasts longer than pi/Omega, a sticking one's settle time T_s about
/// 34/Omega).
fn default_steps(contact: &CompliantContact, base: u32) -> u32 {
    let halves = contact.contact_time() * contact.frequency() / std::f64::consts::PI;
    (f64::from(base) * halves).ceil().min(1e6) as u32
}

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
    /// RK4 on the contact only, free flight analytic, the contact's end located.
    EventRk4,
}

#[derive(ValueEnum, Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GeometryArg {
    /// The rod turns during contact (converges to the impulsive result as k grows; not for a
    /// hit at the rod's end, where the point slides off).
    Exact,
    /// Normal and lever arm frozen: a linear oscillator (the impulsive result for every k).
    Frozen,
}

#[derive(Args, Debug)]
pub(crate) struct SimulateArgs {
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
    /// Spring stiffness k (> 0). For 0 < e < 1 a dashpot follows from e; e = 0 glues the point
    /// on (a critically damped spring that also pulls once engaged).
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
    /// Steps per contact time T_c (the settle time T_s for e = 0) [default: h Omega = pi/100,
    /// which is 100 steps for an elastic contact and more for damped or sticking ones;
    /// pi/1000 for --sweep-k so that the integrator's error stays below the model's O(1/k) up to
    /// k = 1e10].
    #[arg(long, value_name = "N", conflicts_with = "dt",
          value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub(crate) steps: Option<u32>,
    /// Fixed time step h in seconds, at most T_c, instead of --steps.
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

/// The step for `contact`: --dt (refused beyond the contact time, where a step would jump over
/// the contact), or T_c / --steps.
fn step(args: &SimulateArgs, contact: &CompliantContact) -> Result<f64, Error> {
    let Some(text) = &args.dt else {
        let steps = args.steps.unwrap_or_else(|| default_steps(contact, STEPS));
        return Ok(contact.contact_time() / f64::from(steps));
    };
    let h = positive_f64("dt", text)?;
    let t_c = contact.contact_time();
    if h > t_c {
        return Err(Error::out_of_range(
            "dt",
            format!(
                "{h:e} s is longer than the contact time T_c = {t_c:.3e} s at k = {:e}, so a step \
                 would jump over the contact: use --dt {:.1e} (T_c/100) or --steps N",
                contact.stiffness(),
                t_c / 100.0
            ),
        ));
    }
    Ok(h)
}

/// Refuses runs whose total work exceeds [`MAX_WORK`], before any is started; names the flag
/// that set the step (or the stiffness or the sweep, which set it through T_c).
fn check_work(
    args: &SimulateArgs,
    runs: &[(&CompliantContact, Integrator, f64)],
) -> Result<(), Error> {
    let total: f64 = runs.iter().map(|(c, m, h)| work(c, *m, *h)).sum();
    if total <= MAX_WORK {
        return Ok(());
    }
    let field = if args.dt.is_some() {
        "dt"
    } else if args.steps.is_some() {
        "steps"
    } else if args.sweep_k {
        "sweep-k"
    } else {
        "stiffness"
    };
    Err(Error::out_of_range(
        field,
        format!(
            "the runs would take {total:.1e} force evaluations, beyond the limit {MAX_WORK:.0e} \
             (about ten seconds; an implicit step costs 60, an RK4 step 4): use fewer --steps, a \
             larger --dt, a smaller --stiffness, or --integrator event-rk4, whose cost does not \
             grow with k (the fixed-step methods integrate the approach at the contact's step)"
        ),
    ))
}

pub(crate) fn run_simulate(args: &SimulateArgs) -> Result<(), Failure> {
    let scene = args.scene.input().build()?;
    let geometry = match args.geometry {
        GeometryArg::Exact => Geometry::Exact,
        GeometryArg::Frozen => Geometry::Frozen,
    };
    if args.sweep_k {
        let method = args.integrator.map_or(Integrator::EventRk4, integrator);
        let contacts = SWEEP_K
            .iter()
            .map(|&k| CompliantContact::new(&scene, k, geometry))
            .collect::<Result<Vec<_>, _>>()?;
        let steps = args
            .steps
            .unwrap_or_else(|| default_steps(&contacts[0], SWEEP_STEPS));
        let planned: Vec<_> = contacts
            .iter()
            .map(|c| (c, method, c.contact_time() / f64::from(steps)))
            .collect();
        check_work(args, &planned)?;
        let rows = sweep_k(&scene, &SWEEP_K, geometry, method, steps as usize)?;
        let ok = sweep_passes(&rows);
        print_out(&if args.json {
            json_text(&sweep_json(&rows, steps as usize))
        } else {
            sweep_text(&rows, steps as usize)
        });
        return if ok { Ok(()) } else { Err(Failure::Check) };
    }
    let k = positive_f64("stiffness", args.stiffness.as_deref().unwrap_or_default())?;
    let contact = CompliantContact::new(&scene, k, geometry)?;
    let methods: Vec<Integrator> = match args.integrator {
        Some(arg) => vec![integrator(arg)],
        None => Integrator::ALL.to_vec(),
    };
    let h = step(args, &contact)?;
    let planned: Vec<_> = methods.iter().map(|&m| (&contact, m, h)).collect();
    check_work(args, &planned)?;
    let runs = methods
        .iter()
        .map(|&m| simulate(&contact, m, h))
        .collect::<Result<Vec<_>, _>>()?;
    let ok = simulation_passes(&runs);
    print_out(&if args.json {
        json_text(&simulation_json(&contact, &runs))
    } else {
        simulation_text(&contact, &runs)
    });
    if ok { Ok(()) } else { Err(Failure::Check) }
}

fn json_text(doc: &serde_json::Value) -> String {
    format!(
        "{}\n",
        serde_json::to_string_pretty(doc).expect("JSON of numbers and strings")
    )
}
