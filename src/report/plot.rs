//! Figures as SVG (plotters, no font libraries): omega against the impact point, a* against the
//! mass ratio, and the paper's missing Figure 1.
//!
//! Curves are sampled at exact rational points and each exact value is converted to the nearest
//! f64 only for drawing. The output is deterministic, so it can be golden-tested.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt, q};
use crate::optimum::{Placement, optimum};
use crate::scene::{RodInertia, Scene};
use num_traits::{One, ToPrimitive};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Pixel size of every figure.
const SIZE: (u32, u32) = (900, 600);
/// Samples per unit of a/l along a curve.
const SAMPLES: i64 = 240;

const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

fn drawing_error(e: impl std::fmt::Display) -> Error {
    Error::new("plot", ErrorKind::Io(format!("drawing failed: {e}")))
}

fn f(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// Renders with `draw` into an SVG string.
fn svg(
    draw: impl FnOnce(&DrawingArea<SVGBackend, Shift>) -> Result<(), Error>,
    size: (u32, u32),
) -> Result<String, Error> {
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
        root.fill(&WHITE).map_err(drawing_error)?;
        draw(&root)?;
        root.present().map_err(drawing_error)?;
    }
    Ok(out)
}

/// omega(a)/omega_max against a/l for each mass ratio M/m (unit scenes: m = l = v0 = 1), a*
/// marked on each curve, the end of the rod marked; beyond the end the curve is dashed.
///
/// # Errors
/// A mass ratio or rod that makes an invalid scene.
///
/// # Examples
/// ```
/// use rodimpact::field::q;
/// use rodimpact::scene::RodInertia;
/// let svg = rodimpact::report::plot_omega(&[q(1, 1), q(3, 1)], &RodInertia::Uniform).unwrap();
/// assert!(svg.starts_with("<svg"));
/// ```
pub fn plot_omega(ratios: &[Q], rod: &RodInertia) -> Result<String, Error> {
    let scenes: Vec<(Q, Scene)> = ratios
        .iter()
        .map(|r| {
            Ok((
                r.clone(),
                Scene::builder(Q::one(), r.clone())
                    .rod(rod.clone())
                    .build()?,
            ))
        })
        .collect::<Result<_, Error>>()?;
    let x_max = q(6, 5);
    svg(
        |root| {
            let mut chart = ChartBuilder::on(root)
                .caption(
                    format!("Angular velocity against impact point ({rod} rod, elastic)"),
                    ("sans-serif", 24),
                )
                .margin(20)
                .x_label_area_size(55)
                .y_label_area_size(70)
                .build_cartesian_2d(0f64..f(&x_max), 0f64..1.15f64)
                .map_err(drawing_error)?;
            chart
                .configure_mesh()
                .x_desc("impact distance from the centre, a/l")
                .y_desc("omega(a) / omega_max")
                .axis_desc_style(("sans-serif", 18))
                .label_style(("sans-serif", 15))
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(drawing_error)?;
            let end = [(1.0, 0.0), (1.0, 1.15)];
            chart
                .draw_series(DashedLineSeries::new(end, 6, 4, BLACK.stroke_width(2)))
                .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    "end of the rod (a = l)",
                    (1.01, 0.3),
                    ("sans-serif", 15),
                )))
                .map_err(drawing_error)?;
            for (i, (ratio, scene)) in scenes.iter().enumerate() {
                let color = PALETTE[i % PALETTE.len()];
                let o = optimum(scene);
                let a_star = QSqrt::sqrt_of(&o.squared);
                // The universal curve omega(a)/omega(a*) = 2 a a*/(a*^2 + a^2) (exact).
                let value = |a: &Q| {
                    let factor = Q::from_integer(2.into()) * a / (&o.squared + a * a);
                    (QSqrt::rational(factor) * &a_star).nearest_f64()
                };
                let scale = match o.placement {
                    Placement::Beyond => value(&Q::one()),
                    _ => 1.0,
                };
                let curve = |from: i64, to: i64| {
                    (from..=to)
                        .map(|k| {
                            let a = Q::new(k.into(), SAMPLES.into());
                            (f(&a), value(&a) / scale)
                        })
                        .collect::<Vec<_>>()
                };
                let x_end = (f(&x_max) * SAMPLES as f64) as i64;
                chart
                    .draw_series(LineSeries::new(curve(0, SAMPLES), color.stroke_width(3)))
                    .map_err(drawing_error)?
                    .label(format!("M/m = {ratio}"))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3))
                    });
                chart
                    .draw_series(DashedLineSeries::new(
                        curve(SAMPLES, x_end),
                        5,
                        5,
                        color.stroke_width(2),
                    ))
                    .map_err(drawing_error)?;
                let a_star_f = a_star.nearest_f64();
                if a_star_f <= f(&x_max) {
                    let y = 1.0 / scale;
                    chart
                        .draw_series(std::iter::once(Circle::new(
                            (a_star_f, y),
                            6,
                            color.filled(),
                        )))
                        .map_err(drawing_error)?;
                    chart
                        .draw_series(std::iter::once(Text::new(
                            "a*",
                            (a_star_f - 0.012, y + 0.035),
                            ("sans-serif", 15).into_font().color(&color),
                        )))
                        .map_err(drawing_error)?;
                }
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperLeft)
                .margin(25)
                .label_font(("sans-serif", 16))
                .background_style(WHITE.mix(0.9))
                .border_style(BLACK)
                .draw()
                .map_err(drawing_error)?;
            Ok(())
        },
        SIZE,
    )
}

/// a*/l against M/m on a log axis (unit scenes), with the rod's end, the mass ratio at which a*
/// reaches it, and the light-rod asymptote a* -> r_G (l/sqrt(3) for a uniform rod).
///
/// # Errors
/// A rod option that makes an invalid scene.
///
/// # Examples
/// ```
/// use rodimpact::scene::RodInertia;
/// let svg = rodimpact::report::plot_optimum(&RodInertia::Uniform).unwrap();
/// assert!(svg.contains("M = 2m"));
/// ```
pub fn plot_optimum(rod: &RodInertia) -> Result<String, Error> {
    let (lo, hi) = (-2i32, 2i32);
    let samples: Vec<(f64, f64)> = (0..=400)
        .map(|k| {
            // M/m = 10^(lo + k (hi - lo)/400), sampled at exact rationals 10^(j/100).
            let exponent = lo * 100 + k * (hi - lo) / 4;
            let ratio = ten_power_hundredths(exponent);
            let s = Scene::builder(Q::one(), ratio.clone())
                .rod(rod.clone())
                .build()?;
            Ok((f(&ratio), number_sqrt(&optimum(&s).squared)))
        })
        .filter(|p: &Result<(f64, f64), Error>| p.as_ref().map_or(true, |(_, y)| *y <= 2.5))
        .collect::<Result<_, Error>>()?;
    let probe = Scene::builder(Q::one(), Q::one())
        .rod(rod.clone())
        .build()?;
    let gyration = probe.inertia(); // I/M with M = l = 1: r_G^2
    let threshold = optimum(&probe).threshold_mass;
    svg(
        |root| {
            let mut chart = ChartBuilder::on(root)
                .caption(
                    format!("Optimal impact distance against mass ratio ({rod} rod)"),
                    ("sans-serif", 24),
                )
                .margin(20)
                .x_label_area_size(55)
                .y_label_area_size(70)
                .build_cartesian_2d((0.01f64..100f64).log_scale(), 0f64..2.5f64)
                .map_err(drawing_error)?;
            chart
                .configure_mesh()
                .x_desc("mass ratio M/m (rod / projectile)")
                .y_desc("a*/l")
                .axis_desc_style(("sans-serif", 18))
                .label_style(("sans-serif", 15))
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(drawing_error)?;
            let end = [(0.01, 1.0), (100.0, 1.0)];
            chart
                .draw_series(LineSeries::new(end, BLACK.stroke_width(2)))
                .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    "end of the rod: a* = l",
                    (0.012, 1.12),
                    ("sans-serif", 15),
                )))
                .map_err(drawing_error)?;
            let r = number_sqrt(&gyration);
            chart
                .draw_series(DashedLineSeries::new(
                    [(0.01, r), (100.0, r)],
                    6,
                    4,
                    PALETTE[2].stroke_width(2),
                ))
                .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    format!("light-rod limit a* -> r_G = {:.4} l", r),
                    (0.012, r - 0.09),
                    ("sans-serif", 15).into_font().color(&PALETTE[2]),
                )))
                .map_err(drawing_error)?;
            if let Some(t) = &threshold {
                let x = f(t);
                chart
                    .draw_series(DashedLineSeries::new(
                        [(x, 0.0), (x, 2.5)],
                        6,
                        4,
                        PALETTE[1].stroke_width(2),
                    ))
                    .map_err(drawing_error)?;
                chart
                    .draw_series(std::iter::once(Text::new(
                        format!("M = {t}m: a* reaches the end"),
                        (x * 1.08, 0.25),
                        ("sans-serif", 15).into_font().color(&PALETTE[1]),
                    )))
                    .map_err(drawing_error)?;
            }
            chart
                .draw_series(LineSeries::new(samples, PALETTE[0].stroke_width(3)))
                .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    "a* = r_G sqrt(1 + M/m)",
                    (12.0, 2.0),
                    ("sans-serif", 16).into_font().color(&PALETTE[0]),
                )))
                .map_err(drawing_error)?;
            Ok(())
        },
        SIZE,
    )
}

/// 10^(j/100) as an exact rational close to it (a ratio of integers from exact integer roots),
/// for sampling a log axis without floats on the exact path.
fn ten_power_hundredths(j: i32) -> Q {
    // 10^(j/100) = (10^j)^(1/100): take 10^(j/100) ~ floor(10^(j/100) * 10^6) / 10^6, computed as
    // the integer 100th root of 10^(j + 600).
    let scaled = num_bigint::BigInt::from(10).pow((j + 600) as u32);
    Q::new(
        num_integer::Roots::nth_root(&scaled, 100),
        num_bigint::BigInt::from(10).pow(6),
    )
}

/// sqrt(x) for drawing, from the exact decimal bounds.
fn number_sqrt(x: &Q) -> f64 {
    f(&crate::number::sqrt_bounds(x, 17).0)
}

/// The paper's missing Figure 1, to scale: the table seen from above, the rod of length 2l at
/// rest, the projectile m moving at v0 towards the impact point at distance a from the centre.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build().unwrap();
/// let svg = rodimpact::report::plot_figure1(&s).unwrap();
/// assert!(svg.contains("2l"));
/// ```
pub fn plot_figure1(scene: &Scene) -> Result<String, Error> {
    let l = f(scene.half_length());
    let a = f(scene.a()) / l;
    // Everything in units of l: x from -2 to 1.2, y from -1.35 to 1.35 (equal scales).
    let (x0, x1, y0, y1) = (-2.3f64, 1.3f64, -1.45f64, 1.45f64);
    let height = 640u32;
    let width = (f64::from(height) * (x1 - x0) / (y1 - y0)).round() as u32;
    svg(
        |root| {
            let mut chart = ChartBuilder::on(root)
                .caption(
                    "Figure 1: a projectile strikes a rod at rest on a smooth table (top view)",
                    ("sans-serif", 20),
                )
                .margin(15)
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(drawing_error)?;
            let table = RGBColor(236, 226, 206);
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(x0, y0), (x1, y1)],
                    table.filled(),
                )))
                .map_err(drawing_error)?;
            let text =
                |s: String, at: (f64, f64), size: u32| Text::new(s, at, ("sans-serif", size));
            let draw_line =
                |chart: &mut ChartContext<_, _>, pts: Vec<(f64, f64)>, style: ShapeStyle| {
                    chart
                        .draw_series(std::iter::once(PathElement::new(pts, style)))
                        .map(|_| ())
                };
            // The rod.
            let rod_color = RGBColor(90, 60, 30);
            draw_line(
                &mut chart,
                vec![(0.0, -1.0), (0.0, 1.0)],
                rod_color.stroke_width(9),
            )
            .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Circle::new((0.0, 0.0), 5, BLACK.filled())))
                .map_err(drawing_error)?;
            let mut labels = vec![
                text(
                    format!("rod: mass M = {}, {} ", scene.rod_mass(), scene.rod()),
                    (0.12, 1.25),
                    16,
                ),
                text("centre".into(), (0.1, -0.05), 15),
            ];
            // Length 2l, dimensioned on the right.
            let dim = 0.75;
            draw_line(
                &mut chart,
                vec![(dim, -1.0), (dim, 1.0)],
                BLACK.stroke_width(1),
            )
            .map_err(drawing_error)?;
            for y in [-1.0, 1.0] {
                draw_line(
                    &mut chart,
                    vec![(0.08, y), (dim + 0.08, y)],
                    BLACK.stroke_width(1),
                )
                .map_err(drawing_error)?;
            }
            labels.push(text(
                format!("2l = {}", scene.half_length() * Q::from_integer(2.into())),
                (dim + 0.05, 0.0),
                16,
            ));
            // The impact distance a, dimensioned on the left of the rod.
            let ax = -0.25;
            draw_line(
                &mut chart,
                vec![(ax, 0.0), (ax, a)],
                PALETTE[1].stroke_width(2),
            )
            .map_err(drawing_error)?;
            draw_line(
                &mut chart,
                vec![(ax - 0.06, 0.0), (0.0, 0.0)],
                PALETTE[1].stroke_width(1),
            )
            .map_err(drawing_error)?;
            labels.push(Text::new(
                format!("a = {}", scene.a()),
                (ax - 0.42, a / 2.0),
                ("sans-serif", 16).into_font().color(&PALETTE[1]),
            ));
            // The projectile and its velocity.
            let px = -1.55;
            chart
                .draw_series(std::iter::once(Circle::new(
                    (px, a),
                    10,
                    PALETTE[0].filled(),
                )))
                .map_err(drawing_error)?;
            let tip = -0.12;
            draw_line(
                &mut chart,
                vec![(px + 0.12, a), (tip, a)],
                PALETTE[0].stroke_width(3),
            )
            .map_err(drawing_error)?;
            for dy in [-0.06, 0.06] {
                draw_line(
                    &mut chart,
                    vec![(tip - 0.12, a + dy), (tip, a)],
                    PALETTE[0].stroke_width(3),
                )
                .map_err(drawing_error)?;
            }
            labels.push(Text::new(
                format!("m = {}, v0 = {}", scene.m(), scene.v0()),
                (px - 0.15, a + 0.16),
                ("sans-serif", 16).into_font().color(&PALETTE[0]),
            ));
            // The impact point, and axes: x along v0, y along the rod.
            chart
                .draw_series(std::iter::once(Circle::new(
                    (0.0, a),
                    5,
                    PALETTE[1].filled(),
                )))
                .map_err(drawing_error)?;
            labels.push(text("impact point".into(), (0.1, a + 0.05), 15));
            let origin = (-2.1, -1.25);
            for (tip, head) in [
                ((-1.75, -1.25), [(-1.8, -1.22), (-1.8, -1.28)]),
                ((-2.1, -0.9), [(-2.13, -0.95), (-2.07, -0.95)]),
            ] {
                draw_line(&mut chart, vec![origin, tip], BLACK.stroke_width(2))
                    .map_err(drawing_error)?;
                for h in head {
                    draw_line(&mut chart, vec![h, tip], BLACK.stroke_width(2))
                        .map_err(drawing_error)?;
                }
            }
            labels.push(text("x".into(), (-1.72, -1.2), 15));
            labels.push(text("y".into(), (-2.08, -0.86), 15));
            chart.draw_series(labels).map_err(drawing_error)?;
            Ok(())
        },
        (width, height),
    )
}

/// Error against run time, log-log, one labelled point per backend/formula (the exact backend,
/// error 0, is drawn on the bottom edge).
///
/// # Errors
/// Drawing fails (not expected for an in-memory SVG).
///
/// # Examples
/// ```
/// let rows = rodimpact::stability::report(5);
/// assert!(rodimpact::report::plot_stability(&rows).unwrap().starts_with("<svg"));
/// ```
pub fn plot_stability(rows: &[crate::stability::Row]) -> Result<String, Error> {
    let floor = 1e-3;
    // An error beyond f64's range (max = inf) is drawn on the top edge.
    let finite_max = rows.iter().map(|r| r.max).filter(|m| m.is_finite());
    let y_max = finite_max.fold(10.0, f64::max) * 30.0;
    let t_min = rows.iter().map(|r| r.nanos).fold(f64::INFINITY, f64::min) / 3.0;
    let t_max = rows.iter().map(|r| r.nanos).fold(0.0, f64::max) * 10.0;
    svg(
        |root| {
            let mut chart = ChartBuilder::on(root)
                .caption(
                    "Float error against run time (suite + sweep, in-range scenes)",
                    ("sans-serif", 24),
                )
                .margin(20)
                .x_label_area_size(55)
                .y_label_area_size(80)
                .build_cartesian_2d((t_min..t_max).log_scale(), (floor..y_max).log_scale())
                .map_err(drawing_error)?;
            chart
                .configure_mesh()
                .x_desc("median run time per scene (ns)")
                .y_desc("max error / (cond * u)")
                .axis_desc_style(("sans-serif", 18))
                .label_style(("sans-serif", 15))
                .x_label_formatter(&|x| format!("{x:.0e}"))
                .y_label_formatter(&|y| format!("{y:.0e}"))
                .light_line_style(WHITE.mix(0.0))
                .draw()
                .map_err(drawing_error)?;
            for (i, r) in rows.iter().enumerate() {
                let color = PALETTE[i % PALETTE.len()];
                let y = r.max.clamp(floor * 5.0, y_max / 2.0);
                let label = match r.max {
                    0.0 => format!("{} (error 0)", r.backend.name()),
                    m if m.is_infinite() => format!("{} (error > 1e308)", r.backend.name()),
                    _ => r.backend.name(),
                };
                chart
                    .draw_series(std::iter::once(Circle::new(
                        (r.nanos, y),
                        6,
                        color.filled(),
                    )))
                    .map_err(drawing_error)?;
                // Labels step through four heights so neighbours (f64 and f32 of one formula
                // cost the same) do not collide.
                let dy = [1.3, 0.15, 8.0, 0.02][i % 4];
                chart
                    .draw_series(std::iter::once(Text::new(
                        label,
                        (r.nanos * 1.15, y * dy),
                        ("sans-serif", 15),
                    )))
                    .map_err(drawing_error)?;
            }
            Ok(())
        },
        SIZE,
    )
}
