//! a* against the mass ratio M/m (log axis, adapted to the threshold), with the best impact
//! point actually on the rod, min(a*, l), the end of the rod, the threshold mass and the
//! light-rod asymptote; the user's scene marked when given.

use super::chart::{Axis, Chart, Swatch};
use super::data::{PlotData, Value};
use super::describe::{multiple, pivot_of, rod, signed};
use super::omega::mass_ratio_family;
use super::scale::Scale;
use super::svg::{Shape, Stroke};
use super::{Figure, PALETTE, SIZE};
use crate::error::Error;
use crate::field::decimal;
use crate::field::{Q, TrySqrt};
use crate::sampling::{a_star_squared_of, check_sampling_cost, f, optimum_of};
use crate::scene::{RodInertia, Scene};
use crate::solve::optimum::Optimum;
use num_bigint::BigInt;
use num_traits::{One, Signed};

/// 10^(j/100) as an exact rational close to it, to 7 significant digits (10^(j div 100) times
/// the integer 100th root of 10^(j mod 100 + 600), over 10^6), for sampling a log axis without
/// floats on the exact path; the root is of a 700-digit number whatever j is.
fn ten_power_hundredths(j: i32) -> Q {
    let (decades, hundredths) = (j.div_euclid(100), j.rem_euclid(100));
    let root = num_integer::Roots::nth_root(&BigInt::from(10).pow((hundredths + 600) as u32), 100);
    let decade = Q::from_integer(BigInt::from(10).pow(decades.unsigned_abs()));
    let mantissa = Q::new(root, BigInt::from(10).pow(6));
    if decades >= 0 {
        mantissa * decade
    } else {
        mantissa / decade
    }
}

/// The most samples of the mass-ratio axis: every hundredth of a decade up to ten decades,
/// evenly fewer beyond (an axis of 300 decades is drawn from 1,000 points, not 30,000).
const MAX_SAMPLES: i32 = 1_000;

/// The scene whose optimum is drawn: on a pivot, struck on the longer arm.
fn struck(scene: &Scene) -> Result<Scene, Error> {
    let l = scene.half_length();
    match pivot_of(scene) {
        Some(p) if p.is_positive() => scene.with_a(-l.clone()),
        _ => scene.with_a(l.clone()),
    }
}

/// `sqrt(k) unit` for a rational k >= 0: `l/√3`, `l/10`, `√(2/5) l`.
fn root_multiple(k: &Q, unit: &str) -> String {
    if let Some(root) = k.try_sqrt() {
        return multiple(&root, unit);
    }
    match (k.numer().sqrt(), k.denom().sqrt()) {
        (n, _) if &(&n * &n) == k.numer() => {
            let over = if n.is_one() {
                unit.to_string()
            } else {
                format!("{n}{unit}")
            };
            format!("{over}/√{}", k.denom())
        }
        _ => format!("√({k}) {unit}"),
    }
}

/// a*/l (or d*/l on a pivot) against M/m, for the mass distribution, length and support of
/// `base`; with `mark`, `base`'s own M/m marked.
///
/// # Errors
/// A rod that makes an invalid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::{RodInertia, Scene}, field::q};
/// let s = Scene::builder(q(1, 1), q(3, 1)).rod(RodInertia::Gyration(q(1, 10))).build().unwrap();
/// let fig = rodimpact::report::optimum_figure(&s, true).unwrap();
/// assert!(fig.svg.contains("M = 99m: a* reaches the end"));
/// assert!(fig.svg.contains("this scene"));
/// ```
pub fn optimum_figure(base: &Scene, mark: bool) -> Result<Figure, Error> {
    check_sampling_cost(std::slice::from_ref(base))?;
    let l = base.half_length().clone();
    let pivoted = pivot_of(base).is_some();
    let probe = struck(base)?;
    let probe_optimum = optimum_of(&probe);
    let arm = f(&(&probe_optimum.arm / &l));
    let threshold = probe_optimum.threshold_mass.as_ref().map(|t| t / base.m());
    let own = base.rod_mass() / base.m();
    let mut top = threshold
        .as_ref()
        .map_or(2.0, |t| f(t).log10().ceil() + 1.0);
    if mark {
        top = top.max(f(&own).log10().ceil() + 1.0);
    }
    // The axis runs to 10^top in hundredths of a decade: past the f64 range (M/m = 1e400) it
    // cannot be drawn (and the count of samples would overflow).
    if top.is_nan() || top > 310.0 {
        return Err(super::svg::beyond_drawing());
    }
    let (first, last) = (-200, (top.max(2.0) as i32) * 100);
    let mut data = PlotData::new(&[
        "M_over_m",
        if pivoted { "d_star" } else { "a_star" },
        "best",
    ]);
    let (mut star_curve, mut best_curve) = (Vec::new(), Vec::new());
    let arm_squared = &probe_optimum.arm * &probe_optimum.arm;
    let l_squared = &l * &l;
    let step = ((last - first) + MAX_SAMPLES - 1) / MAX_SAMPLES;
    for j in (first..=last).step_by(step.max(1) as usize) {
        let ratio = ten_power_hundredths(j);
        // Only a* moves along the axis: the struck arm is the probe's.
        let scene = struck(&mass_ratio_family(base, std::slice::from_ref(&ratio))?[0])?;
        let squared = a_star_squared_of(&scene);
        let best = best_of(&squared, &arm_squared);
        let x = f(&ratio);
        star_curve.push((x, f(&decimal::sqrt_bounds(&(&squared / &l_squared), 17).0)));
        best_curve.push((x, f(&decimal::sqrt_bounds(&(&best / &l_squared), 17).0)));
        data.rows.push(vec![
            Value::Exact(ratio),
            Value::Root(squared),
            Value::Root(best),
        ]);
    }
    let x_scale = Scale::log_decades(10f64.powi(first / 100), 10f64.powi(last / 100));
    let y_scale = Scale::linear_nice(0.0, 2.0 * arm);
    let star = if pivoted { "d*" } else { "a*" };
    let (star_name, best_name) = if pivoted {
        (
            "d* = √(I_{p}/m), from the pivot",
            "best point on the rod: min(d*, arm)",
        )
    } else {
        ("a* = r_{G} √(1 + M/m)", "best point on the rod: min(a*, l)")
    };
    let mut legend = vec![
        (
            Swatch::Line(Stroke::solid(PALETTE[4], 7.0)),
            best_name.to_string(),
        ),
        (
            Swatch::Line(Stroke::solid(PALETTE[0], 2.2)),
            star_name.to_string(),
        ),
        (
            Swatch::Line(Stroke::solid("#000000", 1.6)),
            "end of the rod".to_string(),
        ),
    ];
    if threshold.is_some() {
        legend.push((
            Swatch::Line(Stroke::dashed(PALETTE[1], 1.8)),
            format!("threshold: {star} reaches the end"),
        ));
    }
    let light = (!pivoted).then(|| base.inertia() / (base.rod_mass() * &l * &l));
    if light.is_some() {
        legend.push((
            Swatch::Line(Stroke::dashed(PALETTE[2], 1.8)),
            "light-rod limit a* → r_{G}".into(),
        ));
    }
    if mark {
        legend.push((
            Swatch::Marker(Shape::Star, "#000000", true),
            "this scene".into(),
        ));
    }
    let subtitle = vec![format!(
        "{}{}; {star} depends on neither e nor v_{{0}}",
        rod(base),
        if pivoted {
            format!(
                ", on a pivot at p = {}, struck on the longer arm",
                multiple(&(pivot_of(base).expect("pivoted") / &l), "l")
            )
        } else {
            ", free on the table".into()
        }
    )];
    let mut chart = Chart::new(
        SIZE.0,
        SIZE.1,
        "Where to strike for the fastest spin, against the mass ratio",
        &subtitle,
        Axis {
            scale: x_scale,
            title: "mass ratio M/m (rod / projectile)".into(),
        },
        Axis {
            scale: y_scale,
            title: if pivoted {
                "distance from the pivot / l".into()
            } else {
                "distance from the centre / l".into()
            },
        },
        &legend,
    );
    let (x_lo, x_hi) = x_scale.range();
    let (_, y_hi) = y_scale.range();
    chart.svg.open("best");
    chart.curve(&best_curve, &Stroke::solid(PALETTE[4], 7.0));
    chart.svg.close();
    chart.svg.open("a-star");
    chart.curve(&star_curve, &Stroke::solid(PALETTE[0], 2.2));
    chart.svg.close();
    chart.svg.open("rod-end");
    chart.rule((x_lo, arm), (x_hi, arm), &Stroke::solid("#000000", 1.6));
    chart.svg.close();
    let mut labels = Vec::new();
    if let Some(k) = &light {
        let r = f(&decimal::sqrt_bounds(k, 17).0);
        chart.svg.open("light-rod-limit");
        chart.rule((x_lo, r), (x_hi, r), &Stroke::dashed(PALETTE[2], 1.8));
        chart.svg.close();
        labels.push((
            format!("light rod: a* → r_{{G}} = {}", root_multiple(k, "l")),
            (x_lo * 3.0, r),
            PALETTE[2],
        ));
    }
    if let Some(t) = &threshold {
        let x = f(t);
        chart.svg.open("threshold");
        chart.rule((x, 0.0), (x, y_hi), &Stroke::dashed(PALETTE[1], 1.8));
        chart.svg.close();
        labels.push((
            format!("M = {}: {star} reaches the end", multiple(t, "m")),
            (x, 0.7 * y_hi),
            PALETTE[1],
        ));
    }
    let end_text = if pivoted {
        format!(
            "end of the longer arm: {} from the pivot",
            multiple(&(&probe_optimum.arm / &l), "l")
        )
    } else {
        "end of the rod: a = l".into()
    };
    labels.push((end_text, (x_lo * 3.0, arm), "#000000"));
    if mark {
        let o = optimum_of(&probe);
        let best = best_squared(&o);
        let at = chart.marker(
            (
                f(&own),
                f(&decimal::sqrt_bounds(&(&best / (&l * &l)), 17).0),
            ),
            Shape::Star,
            "#000000",
            true,
        );
        let where_ = if o.within_rod {
            "on the rod".to_string()
        } else {
            "beyond the end: strike the end".to_string()
        };
        let name = if pivoted { "d*" } else { "a*" };
        let label = format!(
            "M/m = {}: {name} = {} l, {where_}",
            signed(&own),
            decimal::decimal_sqrt(&(&o.squared / (&l * &l)), 3)
        );
        chart.label_px(&label, at, "#000000");
    }
    for (markup, at, color) in labels {
        chart.label(&markup, at, color);
    }
    Ok(Figure {
        svg: chart.finish()?,
        data: Some(data),
    })
}

/// min(a*, arm)^2: where omega is largest on the rod.
fn best_squared(o: &Optimum) -> Q {
    best_of(&o.squared, &(&o.arm * &o.arm))
}

/// The square of the best point on the rod, min(a*, arm)^2.
fn best_of(squared: &Q, arm_squared: &Q) -> Q {
    squared.min(arm_squared).clone()
}

/// The paper's figure: a*/l against M/m for this rod, free and unmarked.
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
    let base = Scene::builder(Q::one(), Q::one())
        .rod(rod.clone())
        .build()?;
    Ok(optimum_figure(&base, false)?.svg)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    #[test]
    fn powers_of_ten_are_close_rationals() {
        assert_eq!(ten_power_hundredths(0), q(1, 1));
        assert_eq!(ten_power_hundredths(-200), q(1, 100));
        assert_eq!(ten_power_hundredths(300), q(1000, 1));
        let x = f(&ten_power_hundredths(-750));
        assert!((x / 10f64.powf(-7.5) - 1.0).abs() < 1e-5, "{x}");
    }

    #[test]
    fn gyration_radii_read_as_written_by_hand() {
        assert_eq!(root_multiple(&q(1, 3), "l"), "l/√3");
        assert_eq!(root_multiple(&q(1, 100), "l"), "l/10");
        assert_eq!(root_multiple(&q(4, 5), "l"), "2l/√5");
        assert_eq!(root_multiple(&q(2, 5), "l"), "√(2/5) l");
    }
}
