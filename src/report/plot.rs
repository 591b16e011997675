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
                .build_cartesian_2d(0f64..f(&x_max), 0f64..1.08f64)
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
            let end = [(1.0, 0.0), (1.0, 1.08)];
            chart
                .draw_series(DashedLineSeries::new(end, 6, 4, BLACK.stroke_width(2)))
                .map_err(drawing_error)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    "end of the rod (a = l)",
                    (1.01, 0.06),
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
                .position(SeriesLabelPosition::LowerRight)
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
