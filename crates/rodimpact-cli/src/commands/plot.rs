//! `rodimpact plot`: the figures as SVG, and their sampled values as CSV.
//!
//! Every figure takes the scene flags it can honour and refuses, with exit 2 and one line, the
//! ones that would change nothing in it (an impact point for a figure that varies it, a
//! collision law for a* which does not depend on it).

use super::{Failure, SceneFlags, parse_ratios};
use clap::Args;
use rodimpact::io::{write_atomic, write_atomic_bytes};
use rodimpact::report::{self, Figure};
use rodimpact::scene::Scene;
use rodimpact::{Error, ErrorKind};
use std::path::{Path, PathBuf};

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// omega(a) against a: the mass ratios of --ratios, or the scene of --m/--M; pivot and e
    /// honoured.
    Omega,
    /// a* (the best impact point) against M/m, log axis, with min(a*, l), the threshold mass
    /// and the light-rod limit; --m/--M mark the scene.
    Optimum,
    /// The paper's missing Figure 1 for the scene, to scale (pivot and mass distribution drawn).
    Figure1,
    /// Figure 1 before and after the impact: velocity arrows and the rod's rest point
    /// y0 = -r_G^2/a.
    Velocities,
    /// v, V, omega, J and a·J (lever arm times impulse) against a, for the scene.
    Quantities,
    /// The energy partition against a: projectile, rod translation, rod rotation, lost.
    Energy,
}

#[derive(Args, Debug)]
pub(crate) struct PlotArgs {
    /// Which figure.
    #[arg(value_enum)]
    pub(crate) figure: Kind,
    /// The file to write (atomically): SVG, or PNG for FILE.png (twice the SVG's size, the
    /// figure's font carried in the program).
    #[arg(long, value_name = "FILE.svg|FILE.png")]
    pub(crate) out: PathBuf,
    /// Also write the sampled values as CSV, exact beside decimal (omega, optimum, quantities,
    /// energy).
    #[arg(long, value_name = "FILE.csv")]
    pub(crate) data: Option<PathBuf>,
    /// Mass ratios M/m of the curves of `omega` [default: 1/2,1,2,3,10].
    #[arg(long, value_name = "Q,Q,...")]
    pub(crate) ratios: Option<String>,
    #[command(flatten)]
    pub(crate) scene: SceneFlags,
}

/// Checks that `path` ends in `.ext` (any case): the file format follows the name.
///
/// # Errors
/// `field: writes EXT only, got 'NAME'`.
pub(crate) fn check_extension(
    field: &str,
    path: &Path,
    ext: &str,
    hint: &str,
) -> Result<(), Error> {
    let ok = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext));
    if ok {
        Ok(())
    } else {
        Err(Error::new(
            field,
            ErrorKind::Invalid(format!(
                "the file name must end in .{ext}, got '{}'{hint}",
                path.display()
            )),
        ))
    }
}

fn refuse(field: &str, why: &str) -> Error {
    Error::new(field, ErrorKind::Conflict(why.into()))
}

/// The flags the figure cannot honour, refused by name.
fn refuse_unused(args: &PlotArgs) -> Result<(), Error> {
    let s = &args.scene;
    let name = match args.figure {
        Kind::Omega => "omega",
        Kind::Optimum => "optimum",
        Kind::Figure1 => "figure1",
        Kind::Velocities => "velocities",
        Kind::Quantities => "quantities",
        Kind::Energy => "energy",
    };
    let varies_a = matches!(
        args.figure,
        Kind::Omega | Kind::Optimum | Kind::Quantities | Kind::Energy
    );
    if varies_a && (s.a.is_some() || s.from_end.is_some()) {
        let field = if s.a.is_some() { "a" } else { "from-end" };
        return Err(refuse(
            field,
            &format!("plot {name} varies the impact point itself; leave --{field} out"),
        ));
    }
    if args.figure == Kind::Optimum {
        if s.e.is_some() || s.elastic || s.inelastic {
            return Err(refuse(
                "e",
                "plot optimum: a* does not depend on the collision law; leave --e out",
            ));
        }
        if s.v0.is_some() {
            return Err(refuse(
                "v0",
                "plot optimum: a* does not depend on v0; leave --v0 out",
            ));
        }
    }
    if args.ratios.is_some() {
        if args.figure != Kind::Omega {
            return Err(refuse(
                "ratios",
                &format!("plot {name} draws one scene; --ratios is for plot omega"),
            ));
        }
        if s.rod_mass.is_some() {
            return Err(refuse(
                "ratios",
                "give either --M (one curve) or --ratios (one curve per M/m), not both",
            ));
        }
    }
    if args.data.is_some() && matches!(args.figure, Kind::Figure1 | Kind::Velocities) {
        return Err(refuse(
            "data",
            &format!(
                "plot {name} draws one scene, not sampled curves; `rodimpact solve` gives its numbers"
            ),
        ));
    }
    Ok(())
}

/// The scene of the flags, m and M 1 unless given.
fn scene(flags: &SceneFlags) -> Result<Scene, Error> {
    let mut input = flags.input();
    input.m.get_or_insert_with(|| "1".into());
    input.rod_mass.get_or_insert_with(|| "1".into());
    input.build()
}

fn figure(args: &PlotArgs) -> Result<Figure, Error> {
    let scene = scene(&args.scene)?;
    let drawing = |svg: String| Figure { svg, data: None };
    Ok(match args.figure {
        Kind::Omega => {
            let scenes = if args.scene.rod_mass.is_some() {
                vec![scene]
            } else {
                let ratios =
                    parse_ratios("ratios", args.ratios.as_deref().unwrap_or("1/2,1,2,3,10"))?;
                report::mass_ratio_family(&scene, &ratios)?
            };
            report::omega_figure(&scenes)?
        }
        Kind::Optimum => {
            let mark = args.scene.m.is_some() || args.scene.rod_mass.is_some();
            report::optimum_figure(&scene, mark)?
        }
        Kind::Figure1 => drawing(report::plot_figure1(&scene)?),
        Kind::Velocities => drawing(report::velocity_figure(&scene)?),
        Kind::Quantities => report::quantities_figure(&scene)?,
        Kind::Energy => report::energy_figure(&scene)?,
    })
}

pub(crate) fn run_plot(args: &PlotArgs) -> Result<(), Failure> {
    let png = args
        .out
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !png {
        check_extension(
            "out",
            &args.out,
            "svg",
            " (or .png, the figure as a picture)",
        )?;
    }
    if let Some(path) = &args.data {
        check_extension("data", path, "csv", "")?;
    }
    refuse_unused(args)?;
    let drawn = figure(args)?;
    if png {
        write_atomic_bytes(
            "out",
            &args.out,
            &report::svg_to_png(&drawn.svg, report::PNG_SCALE)?,
        )?;
    } else {
        write_atomic("out", &args.out, &drawn.svg)?;
    }
    if let (Some(path), Some(data)) = (&args.data, &drawn.data) {
        write_atomic("data", path, &data.to_csv())?;
    }
    Ok(())
}
