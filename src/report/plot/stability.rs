//! The float stability chart: the error of every backend and formula against its run time,
//! colour for the formula and marker shape for the number format (readable in grey too), the
//! maximum filled and the median open; an error of exactly 0 (exact arithmetic) and an
//! unbounded one (an interval end overflowed) in marked bands past axis breaks, not at fake
//! values on the log axis.

use super::chart::{Axis, Chart, OffScale, Swatch};
use super::scale::Scale;
use super::svg::{Shape, Stroke};
use super::{PALETTE, SIZE};
use crate::error::Error;
use crate::solve::fast::float::FloatFormula;
use crate::stability::{Backend, BackendStats};

/// The colour of a backend: by formula (interval and exact their own).
fn color(backend: Backend) -> &'static str {
    match backend {
        Backend::F64(f) | Backend::F32(f) => match f {
            FloatFormula::Naive => PALETTE[1],
            FloatFormula::Sq => PALETTE[0],
            FloatFormula::Scomp => PALETTE[2],
        },
        Backend::Interval => PALETTE[3],
        Backend::Exact => "#000000",
    }
}

/// The marker of a backend: by number format.
fn shape(backend: Backend) -> Shape {
    match backend {
        Backend::F64(_) => Shape::Circle,
        Backend::F32(_) => Shape::Square,
        Backend::Interval => Shape::Diamond,
        Backend::Exact => Shape::Star,
    }
}

/// Where an error value goes: on the scale, or in a band.
enum Place {
    Scale(f64),
    Zero,
    Unbounded,
}

fn place(error: f64) -> Place {
    if error == 0.0 {
        Place::Zero
    } else if error.is_finite() {
        Place::Scale(error)
    } else {
        Place::Unbounded
    }
}

/// Error against run time, log-log, one marker pair (max filled, median open) per
/// backend/formula, each labelled.
///
/// # Errors
/// None (kept for the uniform signature of the figures).
///
/// # Examples
/// ```
/// let rows = rodimpact::stability::compare_backends(5);
/// let svg = rodimpact::report::plot_stability(&rows).unwrap();
/// assert!(svg.contains("error exactly 0"));
/// ```
pub fn plot_stability(rows: &[BackendStats]) -> Result<String, Error> {
    let finite = rows
        .iter()
        .flat_map(|r| [r.max, r.median])
        .filter(|e| e.is_finite() && *e > 0.0);
    let (lo, hi) = finite.fold((f64::INFINITY, 0.0f64), |(lo, hi), e| {
        (lo.min(e), hi.max(e))
    });
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.1, 10.0) };
    let times = rows.iter().map(|r| r.nanos).filter(|t| *t > 0.0);
    let (t_lo, t_hi) = times.fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
        (lo.min(t), hi.max(t))
    });
    let (t_lo, t_hi) = if t_lo <= t_hi {
        (t_lo, t_hi)
    } else {
        (1.0, 10.0)
    };
    let bands = OffScale {
        below: rows
            .iter()
            .any(|r| r.max == 0.0 || r.median == 0.0)
            .then(|| ("0".to_string(), "off scale: error exactly 0".to_string())),
        above: rows.iter().any(|r| r.max.is_infinite()).then(|| {
            (
                "∞".to_string(),
                "off scale: unbounded (an end overflowed)".to_string(),
            )
        }),
    };
    let mut legend: Vec<(Swatch, String)> = rows
        .iter()
        .map(|r| {
            (
                Swatch::Marker(shape(r.backend), color(r.backend), true),
                r.backend.name(),
            )
        })
        .collect();
    legend.push((
        Swatch::Marker(Shape::Circle, "#555555", true),
        "filled: max error".into(),
    ));
    legend.push((
        Swatch::Marker(Shape::Circle, "#555555", false),
        "open: median error".into(),
    ));
    let mut chart = Chart::with_bands(
        SIZE.0,
        SIZE.1,
        "Float error against run time, every backend and formula",
        &[
            "suite + seeded sweep, the scenes in range for each format; error in units of cond·u"
                .to_string(),
            "colour: formula (naive, sq, scomp); marker: format (● f64, ■ f32, ◆ interval, ★ exact)"
                .to_string(),
        ],
        Axis {
            scale: Scale::log_decades(t_lo / 1.5, t_hi * 1.5),
            title: "median time per evaluation (ns)".into(),
        },
        Axis {
            scale: Scale::log_decades(lo / 2.0, hi * 2.0),
            title: "error / (cond·u)".into(),
        },
        &legend,
        &bands,
    );
    let mut labels = Vec::new();
    for r in rows {
        let (c, s) = (color(r.backend), shape(r.backend));
        let x = chart.px_x(r.nanos);
        let y_of = |chart: &Chart, error: f64| match place(error) {
            Place::Scale(e) => chart.px_y(e),
            Place::Zero => chart.band_y(false),
            Place::Unbounded => chart.band_y(true),
        };
        let (y_max, y_median) = (y_of(&chart, r.max), y_of(&chart, r.median));
        chart.svg.open("backend");
        if (y_max - y_median).abs() > 1.0 {
            let stroke = Stroke::solid(c, 1.2);
            chart.svg.line((x, y_median), (x, y_max), &stroke);
            chart.obstacles.add_segment((x, y_median), (x, y_max));
            chart.marker_px((x, y_median), s, c, false);
        }
        chart.marker_px((x, y_max), s, c, true);
        chart.svg.close();
        labels.push((r.backend.name(), (x, y_max), c));
    }
    for (name, at, c) in labels {
        chart.label_px(&name, at, c);
    }
    chart.finish()
}
