//! omega against the impact point: one curve per scene (a family of mass ratios, or the user's
//! own scene), the fastest spin on the rod marked, a* marked where it lies off the rod or off
//! the chart, the formula's continuation beyond the end dashed and explained in the legend.

use super::chart::{Axis, Chart, Swatch};
use super::data::{PlotData, Value};
use super::describe::{multiple, numbers, pivot_of, scene_line, signed};
use super::scale::Scale;
use super::svg::{Shape, Stroke};
use super::{Figure, PALETTE, SIZE};
use crate::error::Error;
use crate::field::decimal;
use crate::field::{Field, Q, QSqrt};
use crate::sampling::{PER_L, arm_optima, check_sampling_cost, f, outcome_at, point};
use crate::scene::{RodInertia, Scene};
use crate::solve::optimum::Argmax;

/// How far past the rod's end the continuation is drawn, in units of l.
const REACH: f64 = 1.2;

/// One curve's samples: (a/l, omega l/v0) on the rod and the dashed parts off it.
struct Curve {
    on_rod: Vec<(f64, f64)>,
    off_rod: Vec<Vec<(f64, f64)>>,
}

fn curve(scene: &Scene, data: &mut PlotData) -> Result<Curve, Error> {
    let pivoted = pivot_of(scene).is_some();
    let reach = (REACH * PER_L as f64).round() as i64;
    let first = if pivoted { -reach } else { 0 };
    let scale = scene.half_length() / scene.v0();
    let ratio = scene.rod_mass() / scene.m();
    let (mut on_rod, mut low, mut high) = (Vec::new(), Vec::new(), Vec::new());
    for k in first..=reach {
        let a = point(scene, k);
        let omega = outcome_at(scene, &a)?.after.omega;
        let xy = (k as f64 / PER_L as f64, f(&(&omega * &scale)));
        if k.abs() <= PER_L {
            on_rod.push(xy);
            data.rows.push(vec![
                Value::Exact(ratio.clone()),
                Value::Exact(a),
                Value::Exact(omega),
            ]);
        }
        // The dashed parts share their end point with the solid one.
        if k <= -PER_L {
            low.push(xy);
        }
        if k >= PER_L {
            high.push(xy);
        }
    }
    Ok(Curve {
        on_rod,
        off_rod: [low, high].into_iter().filter(|c| c.len() > 1).collect(),
    })
}

/// omega(a) l/v0 against a/l for each scene (drawn with the rod, support and collision law of
/// the first; typically one mass ratio each), with the data sampled at a = k l/200.
///
/// # Errors
/// An empty list of scenes.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).pivot(q(-1, 2)).build().unwrap();
/// let fig = rodimpact::report::omega_figure(&[s]).unwrap();
/// assert!(fig.svg.contains("on a fixed pivot at p = −l/2"));
/// // omega at a = l: (1 + e) m d v0/(I_p + m d^2) = 2 (3/2)/(7/12 + 9/4) = 18/17.
/// assert!(fig.data.unwrap().to_csv().lines().last().unwrap().starts_with("1,1.0000000000000000,1,1.0000000000000000,18/17,"));
/// ```
pub fn omega_figure(scenes: &[Scene]) -> Result<Figure, Error> {
    check_sampling_cost(scenes)?;
    let Some(first) = scenes.first() else {
        return Err(Error::new(
            "ratios",
            crate::error::ErrorKind::Invalid("no curve to draw".into()),
        ));
    };
    let pivoted = pivot_of(first).is_some();
    let mut data = PlotData::new(&["M_over_m", "a", "omega"]);
    let curves: Vec<Curve> = scenes
        .iter()
        .map(|s| curve(s, &mut data))
        .collect::<Result<_, _>>()?;
    let arms: Vec<_> = scenes.iter().map(arm_optima).collect::<Result<_, _>>()?;
    let unit = f(&(first.half_length() / first.v0()));
    let values = curves
        .iter()
        .flat_map(|c| c.on_rod.iter().chain(c.off_rod.iter().flatten()))
        .map(|p| p.1)
        .chain(
            arms.iter()
                .flatten()
                .map(|a| f64::from(a.side) * a.peak.nearest_f64() * unit),
        );
    let (lo, hi) = values.fold((0.0f64, 0.0f64), |(lo, hi), y| (lo.min(y), hi.max(y)));
    let x_scale = if pivoted {
        Scale::Linear {
            lo: -REACH,
            hi: REACH,
        }
    } else {
        Scale::Linear { lo: 0.0, hi: REACH }
    };
    let y_scale = Scale::linear_nice(lo * 1.06, hi * 1.06);
    let single = scenes.len() == 1;
    let subtitle = vec![
        scene_line(first),
        if single {
            numbers(first, true)
        } else {
            format!("{}; M = (M/m)·m for each curve", numbers(first, false))
        },
    ];
    let x_title = if pivoted {
        "impact point a/l (signed distance from the centre)"
    } else {
        "impact point a/l (distance from the centre)"
    };
    let mut legend: Vec<(Swatch, String)> = scenes
        .iter()
        .enumerate()
        .map(|(i, scene)| {
            (
                Swatch::Line(Stroke::solid(PALETTE[i % PALETTE.len()], 2.8)),
                format!("M/m = {}", signed(&(scene.rod_mass() / scene.m()))),
            )
        })
        .collect();
    legend.push((
        Swatch::Line(Stroke::dashed("#555555", 2.0)),
        "off the rod, |a| > l".into(),
    ));
    legend.push((
        Swatch::Marker(Shape::Circle, "#555555", true),
        "fastest spin on the rod, ω_{max}".into(),
    ));
    let beyond = arms
        .iter()
        .flatten()
        .filter(|a| a.optimum.argmax == Argmax::End);
    if beyond.clone().any(|a| a.peak_at.abs() <= REACH) {
        legend.push((
            Swatch::Marker(Shape::Circle, "#555555", false),
            format!("{} off the rod", if pivoted { "d*" } else { "a*" }),
        ));
    }
    if beyond.clone().any(|a| a.peak_at.abs() > REACH) {
        legend.push((
            Swatch::Marker(Shape::TriangleRight, "#555555", false),
            format!("{} beyond this chart", if pivoted { "d*" } else { "a*" }),
        ));
    }
    let mut chart = Chart::new(
        SIZE.0,
        SIZE.1,
        "Angular velocity ω of the rod against the impact point",
        &subtitle,
        Axis {
            scale: x_scale,
            title: x_title.into(),
        },
        Axis {
            scale: y_scale,
            title: "ω l / v_{0}".into(),
        },
        &legend,
    );
    // The rod's ends, the pivot and the zero line.
    chart.svg.open("rod-ends");
    let ends: &[f64] = if pivoted { &[-1.0, 1.0] } else { &[1.0] };
    let (y_lo, y_hi) = y_scale.range();
    for &x in ends {
        chart.rule((x, y_lo), (x, y_hi), &Stroke::dashed("#000000", 1.6));
    }
    if lo < 0.0 {
        chart.rule((-REACH, 0.0), (REACH, 0.0), &Stroke::solid("#888888", 1.0));
    }
    chart.svg.close();
    let mut pivot_label = None;
    if let Some(p) = pivot_of(first) {
        chart.svg.open("pivot");
        let x = f(&(p / first.half_length()));
        chart.rule((x, y_lo), (x, y_hi), &Stroke::dotted("#000000", 1.6));
        chart.marker((x, 0.0), Shape::TriangleUp, "#000000", true);
        chart.svg.close();
        let label = format!("pivot (p = {})", multiple(&(p / first.half_length()), "l"));
        pivot_label = Some((label, (x, y_lo + 0.06 * (y_hi - y_lo))));
    }
    let mut marks = Vec::new();
    for (i, ((scene, c), arms)) in scenes.iter().zip(&curves).zip(&arms).enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        chart.svg.open("curve");
        chart.curve(&c.on_rod, &Stroke::solid(color, 2.8));
        for part in &c.off_rod {
            chart.curve(part, &Stroke::dashed(color, 2.0));
        }
        chart.svg.close();
        for arm in arms {
            marks.push((i, color, scene, arm));
        }
    }
    // Markers first (labels avoid them all), then the labels.
    let mut labels = Vec::new();
    let star_name = if pivoted { "d*" } else { "a*" };
    for &(_, color, scene, arm) in &marks {
        let o = &arm.optimum;
        let side = f64::from(arm.side);
        let best = match o.argmax {
            Argmax::AStar => arm.peak_at,
            Argmax::End => side,
        };
        let best_y = side * o.omega_max.nearest_f64() * unit;
        chart.svg.open("omega-max");
        let at = chart.marker((best, best_y), Shape::Circle, color, true);
        chart.svg.close();
        let a_star = star(scene, &o.squared);
        if single {
            let place = match o.argmax {
                Argmax::AStar => format!("at {a_star}"),
                Argmax::End => "at the end".into(),
            };
            labels.push((
                format!(
                    "ω_{{max}} = {} v_{{0}}/l {place}",
                    (o.omega_max.clone() * &QSqrt::rational(scene.half_length() / scene.v0()))
                        .decimal(3)
                ),
                at,
                color,
            ));
        } else if o.argmax == Argmax::AStar {
            labels.push((star_name.into(), at, color));
        }
        if o.argmax == Argmax::End {
            let peak = (arm.peak_at, side * arm.peak.nearest_f64() * unit);
            if arm.peak_at.abs() <= REACH {
                chart.svg.open("a-star-off-rod");
                let at = chart.marker(peak, Shape::Circle, color, false);
                chart.svg.close();
                labels.push((star_name.into(), at, color));
            } else {
                let edge = side * REACH;
                chart.svg.open("a-star-off-chart");
                let y = chart.px_y(peak.1);
                let x = chart.px_x(edge) - side * 8.0;
                let shape = if side > 0.0 {
                    Shape::TriangleRight
                } else {
                    Shape::TriangleLeft
                };
                chart.marker_px((x, y), shape, color, false);
                chart.svg.close();
                if single {
                    labels.push((a_star, (x, y), color));
                }
            }
        }
    }
    let end_label = if pivoted {
        "end of the rod (a = ±l)"
    } else {
        "end of the rod (a = l)"
    };
    chart.label(end_label, (1.0, y_lo + 0.25 * (y_hi - y_lo)), "#000000");
    for (markup, at, color) in labels {
        chart.label_px(&markup, at, color);
    }
    if let Some((label, at)) = pivot_label {
        chart.label(&label, at, "#000000");
    }
    Ok(Figure {
        svg: chart.finish()?,
        data: Some(data),
    })
}

/// a* = 0.816 l (free rod) or d* = 0.764 l from the pivot, from the exact square.
fn star(scene: &Scene, squared: &Q) -> String {
    let l = scene.half_length();
    let value = decimal::decimal_sqrt(&(squared / (l * l)), 3);
    match pivot_of(scene) {
        None => format!("a* = {value} l"),
        Some(_) => format!("d* = {value} l from the pivot"),
    }
}

/// The scenes of `base` with rod mass `ratio * m` for each ratio, the mass distribution kept
/// (a rod given by its moment of inertia keeps I/M, so r_G stays the same).
///
/// # Errors
/// A ratio that makes an invalid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q, report::mass_ratio_family};
/// let base = Scene::builder(q(2, 1), q(1, 1)).e(q(1, 2)).build().unwrap();
/// let family = mass_ratio_family(&base, &[q(1, 2), q(3, 1)]).unwrap();
/// assert_eq!(family[1].rod_mass(), &q(6, 1));
/// assert_eq!(family[1].e(), &q(1, 2));
/// ```
pub fn mass_ratio_family(base: &Scene, ratios: &[Q]) -> Result<Vec<Scene>, Error> {
    ratios
        .iter()
        .map(|ratio| {
            let rod_mass = ratio * base.m();
            let rod = match base.rod() {
                RodInertia::Moment(i) => RodInertia::Moment(i * &rod_mass / base.rod_mass()),
                other => other.clone(),
            };
            let builder = Scene::builder(base.m().clone(), rod_mass)
                .half_length(base.half_length().clone())
                .rod(rod)
                .v0(base.v0().clone())
                .e(base.e().clone());
            match pivot_of(base) {
                Some(p) => builder.pivot(p.clone()),
                None => builder,
            }
            .build()
        })
        .collect()
}

/// The paper's family: omega(a) for unit scenes (m = l = v0 = 1, elastic, free) of the mass
/// ratios M/m given, with this rod.
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
    let base = Scene::builder(Q::from_integer(1.into()), Q::from_integer(1.into()))
        .rod(rod.clone())
        .build()?;
    Ok(omega_figure(&mass_ratio_family(&base, ratios)?)?.svg)
}
