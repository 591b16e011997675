//! Runs the rodimpact engine suite (`engines/suite.csv`) in Rapier 2D, f32 and f64, at several
//! time steps and solver iteration counts, and writes the engine's results as CSV, one file per
//! precision: `OUTDIR/rapier2d-0.36.1-f32.csv` and `...-f64.csv`.
//!
//! Usage: `rodimpact-engines-rapier2d SUITE.csv OUTDIR`
//!
//! Output columns: `id,engine,version,float,dt,iters`, the suite's scene columns
//! `class,m,M,l,a,v0,rod,e,pivot`, then the engine's claims `v,V,omega` (rodimpact's signs:
//! omega > 0 when the struck point moves forward), `J` (the contact impulse the engine reports,
//! summed over all steps), `energy_before`, `energy_after` (kinetic energies from the engine's
//! own state, both velocity components and spin). Engine `rapier2d` is the rod free or on a
//! `RevoluteJoint` to a fixed body; `rapier2d-locked` is the pivot made by locking the rod's
//! translations (centre of mass moved to the pivot, inertia I + M p^2), pivot scenes only.

use std::fs;
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

mod suite;

/// The exact Rapier version run (pinned with `=` in Cargo.toml).
const RAPIER_VERSION: &str = "0.36.1";

/// Geometry of the set-up, relative to the rod's half-length l.
pub struct Geometry;

impl Geometry {
    /// The rod is a cuboid of half extents (0.01 l, l): thin, but thicker than a ball's step.
    pub const HALF_THICKNESS_PER_L: suite::Ratio = suite::Ratio { num: 1, den: 100 };
    /// The ball's radius is 0.05 l.
    pub const BALL_RADIUS_PER_L: suite::Ratio = suite::Ratio { num: 1, den: 20 };
    /// The ball starts this many steps (at v0) before touching the rod's face, so it touches
    /// half-way through a step and never tunnels (half a step at v0 = 3, dt = 1/60 is 0.025 l,
    /// less than 0.06 l).
    pub const APPROACH_STEPS: suite::Ratio = suite::Ratio { num: 7, den: 2 };
}

/// How long the run lasts after the nominal contact: 0.1 s, then the state is read.
const AFTER_CONTACT_SECONDS: f64 = 0.1;

/// One combination of time step and solver iterations.
#[derive(Clone, Copy)]
pub struct Settings {
    pub dt: suite::Ratio,
    pub iters: usize,
}

impl Settings {
    /// Steps to run: the approach (3.5 steps, rounded up) plus 0.1 s after it.
    pub fn steps(self) -> usize {
        let steps = Geometry::APPROACH_STEPS;
        let approach = (steps.num + steps.den - 1) / steps.den;
        let dt = self.dt.num as f64 / self.dt.den as f64;
        approach as usize + (AFTER_CONTACT_SECONDS / dt).round() as usize
    }
}

/// How a pivot is modelled (ignored for a free rod).
#[derive(Clone, Copy, PartialEq)]
pub enum PivotModel {
    /// A `RevoluteJoint` from the rod to a fixed body, contacts between them off.
    RevoluteJoint,
    /// The rod's translations locked, its centre of mass at the pivot.
    LockedTranslations,
}

/// The engine's claims for one run, each printed as the shortest round-trip decimal of the
/// engine's float: v, V, omega, J, energy_before, energy_after, and for an oblique scene the
/// velocities along the rod and the ball's spin (claimed_vt, claimed_Vt, claimed_spin; empty
/// otherwise).
pub struct Outcome {
    pub cells: Vec<String>,
}

mod single {
    use rapier2d::prelude::*;
    include!("harness.rs");
}

mod double {
    use rapier2d_f64::prelude::*;
    include!("harness.rs");
}

/// The time steps and iteration counts every scene is run at.
fn all_settings() -> Vec<Settings> {
    let mut all = Vec::new();
    for den in [60, 240, 1000] {
        for iters in [1, 4, 16] {
            all.push(Settings {
                dt: suite::Ratio { num: 1, den },
                iters,
            });
        }
    }
    all
}

/// The columns of a log of the perpendicular scenes (the suite's first ten, then the claims).
const HEADER: &str = "id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,\
                      v,V,omega,J,energy_before,energy_after";
/// The columns of a log of the oblique scenes: every suite column, the claims rodimpact's
/// `batch` checks for an oblique scene (v, V, omega), then what it passes through for the
/// comparison along the rod (claimed_vt, claimed_Vt, claimed_spin) and the engine's impulse
/// and energies (engine_J, engine_energy_before, engine_energy_after).
const OBLIQUE_HEADER: &str = "id,engine,version,float,dt,iters,class,m,M,l,a,v0,rod,e,pivot,\
                              v0t,mu,radius,spin,rod-v,rod-vt,rod-omega,v,V,omega,\
                              claimed_vt,claimed_Vt,claimed_spin,engine_J,engine_energy_before,engine_energy_after";

/// Runs every scene at every setting and writes two logs: the perpendicular scenes
/// (`rapier2d-VERSION-FLOAT.csv`) and the oblique ones (`...-oblique.csv`).
fn write_runs(
    out: &Path,
    float: &str,
    scenes: &[suite::Scene],
    run: fn(&suite::Scene, Settings, PivotModel) -> Outcome,
) -> Result<usize, String> {
    let mut perpendicular = format!("{HEADER}\n");
    let mut oblique = format!("{OBLIQUE_HEADER}\n");
    let mut rows = 0;
    for (engine, model) in [
        ("rapier2d", PivotModel::RevoluteJoint),
        ("rapier2d-locked", PivotModel::LockedTranslations),
    ] {
        for scene in scenes {
            if model == PivotModel::LockedTranslations && scene.pivot.is_none() {
                continue;
            }
            for settings in all_settings() {
                let c = run(scene, settings, model).cells;
                let head = format!(
                    "{},{engine},{RAPIER_VERSION},{float},{},{}",
                    scene.cells[0], settings.dt, settings.iters
                );
                if scene.oblique.is_some() {
                    oblique.push_str(&format!(
                        "{head},{},{},{},{},{},{}\n",
                        scene.cells[1..].join(","),
                        c[..3].join(","),
                        c[6..9].join(","),
                        c[3],
                        c[4],
                        c[5]
                    ));
                } else {
                    perpendicular.push_str(&format!(
                        "{head},{},{}\n",
                        scene.cells[1..10].join(","),
                        c[..6].join(",")
                    ));
                }
                rows += 1;
            }
        }
    }
    for (name, text) in [("", perpendicular), ("-oblique", oblique)] {
        let path = out.join(format!("rapier2d-{RAPIER_VERSION}-{float}{name}.csv"));
        let mut file = fs::File::create(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        file.write_all(text.as_bytes())
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(rows)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 3 {
        eprintln!("usage: rodimpact-engines-rapier2d SUITE.csv OUTDIR");
        return ExitCode::from(2);
    }
    let scenes = match fs::read_to_string(&args[1])
        .map_err(|e| format!("{}: {e}", args[1]))
        .and_then(|text| suite::parse_suite(&text))
    {
        Ok(scenes) => scenes,
        Err(message) => {
            eprintln!("error: {message}");
            return ExitCode::from(2);
        }
    };
    let out = Path::new(&args[2]);
    for (float, run) in [
        ("f32", single::run as fn(&_, _, _) -> _),
        ("f64", double::run as fn(&_, _, _) -> _),
    ] {
        match write_runs(out, float, &scenes, run) {
            Ok(rows) => eprintln!("rapier2d {RAPIER_VERSION} {float}: {rows} runs"),
            Err(message) => {
                eprintln!("error: {message}");
                return ExitCode::from(2);
            }
        }
    }
    ExitCode::SUCCESS
}
