//! Quantities along the rod for one scene, the teacher's figures: v, V, omega, the impulse J
//! and the lever arm times the impulse a·J against the impact point (the paper's competition
//! between a growing lever arm and a shrinking impulse), and the partition of the kinetic
//! energy (projectile, rod translation, rod rotation, lost). Every value is the library
//! solver's exact answer at a rational impact point.

use super::chart::{Axis, Chart, Swatch};
use super::data::{PlotData, Value};
use super::describe::{numbers, pivot_of, scene_line};
use super::scale::Scale;
use super::svg::Stroke;
use super::{Figure, PALETTE, SIZE};
use crate::error::Error;
use crate::field::Q;
use crate::sampling::{PER_L, arm_optima, check_sampling_cost, f, outcome_at, point};
use crate::scene::{Params, Scene};
use crate::solve::Outcome;
use crate::solve::optimum::Argmax;
use num_traits::Zero;

/// One sample: the impact point and the exact outcome there.
struct Sample {
    a: Q,
    out: Outcome<Q>,
}

/// The solver's outcome at every a = k l/200 on the rod (a >= 0 for a free rod, whose
/// quantities are even or odd in a; the whole rod on a pivot).
fn samples(scene: &Scene) -> Result<Vec<Sample>, Error> {
    let first = if pivot_of(scene).is_some() { -PER_L } else { 0 };
    (first..=PER_L)
        .map(|k| {
            let a = point(scene, k);
            let out = outcome_at(scene, &a)?;
            Ok(Sample { a, out })
        })
        .collect()
}

/// The x axis and range for a scene: a/l over the struck half, or the whole rod on a pivot.
fn x_axis(scene: &Scene) -> Axis {
    let pivoted = pivot_of(scene).is_some();
    Axis {
        scale: Scale::Linear {
            lo: if pivoted { -1.0 } else { 0.0 },
            hi: 1.0,
        },
        title: if pivoted {
            "impact point a/l (signed distance from the centre)".into()
        } else {
            "impact point a/l (distance from the centre)".into()
        },
    }
}

/// Vertical dotted lines where omega peaks on the rod (a*, or d* either side of the pivot).
fn mark_optima(chart: &mut Chart, scene: &Scene, y: (f64, f64)) -> Result<(), Error> {
    for arm in arm_optima(scene)? {
        if arm.optimum.argmax == Argmax::AStar {
            let x = arm.peak_at;
            chart.svg.open("a-star");
            chart.rule((x, y.0), (x, y.1), &Stroke::dotted("#000000", 1.6));
            chart.svg.close();
            let name = if pivot_of(scene).is_some() {
                "d*"
            } else {
                "a*"
            };
            chart.label(
                &format!("{name}: fastest spin"),
                (x, y.0 + 0.9 * (y.1 - y.0)),
                "#000000",
            );
        }
    }
    Ok(())
}

/// v/v0, V/v0, omega l/v0, J/(m v0) and (a - p) J/(m v0 l) against a/l for one scene, with
/// the exact samples (scene units) as data.
///
/// # Errors
/// None for a valid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// let fig = rodimpact::report::quantities_figure(&s).unwrap();
/// let csv = fig.data.unwrap().to_csv();
/// // a = l: v = 3/5, V = 2/5, omega = 6/5, J = 2/5, a J = 2/5.
/// assert!(csv.lines().last().unwrap().starts_with("1,1.0000000000000000,3/5,"));
/// ```
pub fn quantities_figure(scene: &Scene) -> Result<Figure, Error> {
    check_sampling_cost(std::slice::from_ref(scene))?;
    let samples = samples(scene)?;
    let params = scene.params::<Q>();
    let pivot = pivot_of(scene).cloned().unwrap_or_default();
    let (m, l, v0) = (scene.m(), scene.half_length(), scene.v0());
    let lever = if pivot_of(scene).is_some() {
        "(a − p)·J"
    } else {
        "a·J"
    };
    let mut data = PlotData::new(&["a", "v", "V", "omega", "J", "lever_times_J"]);
    let mut curves: Vec<Vec<(f64, f64)>> = vec![Vec::new(); 5];
    for s in &samples {
        let j = s.out.impulse(&Params {
            a: s.a.clone(),
            ..params.clone()
        });
        let moment = (&s.a - &pivot) * &j;
        let x = f(&(&s.a / l));
        let ys = [
            &s.out.after.v / v0,
            &s.out.after.rod_v / v0,
            &s.out.after.omega * l / v0,
            &j / (m * v0),
            &moment / (m * v0 * l),
        ];
        for (curve, y) in curves.iter_mut().zip(&ys) {
            curve.push((x, f(y)));
        }
        data.rows.push(
            [
                s.a.clone(),
                s.out.after.v.clone(),
                s.out.after.rod_v.clone(),
                s.out.after.omega.clone(),
                j,
                moment,
            ]
            .into_iter()
            .map(Value::Exact)
            .collect(),
        );
    }
    let names = [
        "v/v_{0}: projectile".to_string(),
        "V/v_{0}: rod centre".to_string(),
        "ω l/v_{0}: spin".to_string(),
        "J/(m v_{0}): impulse on the rod".to_string(),
        format!("{lever}/(m v_{{0}} l): lever arm × impulse"),
    ];
    let colors = [PALETTE[0], PALETTE[2], PALETTE[1], PALETTE[4], PALETTE[3]];
    // V is wide and J dashed, so both show where they coincide (M = m: V = J/M = J/m).
    let strokes = [
        Stroke::solid(colors[0], 2.6),
        Stroke::solid(colors[1], 5.0),
        Stroke::solid(colors[2], 2.6),
        Stroke::dashed(colors[3], 2.6),
        Stroke::dotted(colors[4], 3.0),
    ];
    let legend: Vec<(Swatch, String)> = strokes
        .iter()
        .zip(&names)
        .map(|(s, n)| (Swatch::Line(*s), n.clone()))
        .collect();
    let (lo, hi) = curves
        .iter()
        .flatten()
        .fold((0.0f64, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let y_scale = Scale::linear_nice(lo, hi * 1.05);
    let law_note = if pivot_of(scene).is_some() {
        "ω = (a − p)·J / I_{p}"
    } else {
        "ω = a·J / I"
    };
    let mut chart = Chart::new(
        SIZE.0,
        SIZE.1,
        "What the impact gives, against the impact point",
        &[
            scene_line(scene),
            format!(
                "{}; {law_note}: the lever arm grows while the impulse shrinks",
                numbers(scene, true)
            ),
        ],
        x_axis(scene),
        Axis {
            scale: y_scale,
            title: "in units of v_{0}, v_{0}/l, m v_{0}, m v_{0} l".into(),
        },
        &legend,
    );
    let range = y_scale.range();
    if range.0 < 0.0 {
        chart.rule((-1.0, 0.0), (1.0, 0.0), &Stroke::solid("#888888", 1.0));
    }
    for (curve, stroke) in curves.iter().zip(&strokes) {
        chart.svg.open("curve");
        chart.curve(curve, stroke);
        chart.svg.close();
    }
    mark_optima(&mut chart, scene, range)?;
    Ok(Figure {
        svg: chart.finish()?,
        data: Some(data),
    })
}

/// The kinetic energy after the impact split into the projectile's, the rod's translation and
/// rotation, and the loss, as fractions of m v0^2/2, stacked against a/l.
///
/// # Errors
/// None for a valid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).e(q(0, 1)).build().unwrap();
/// let fig = rodimpact::report::energy_figure(&s).unwrap();
/// assert!(fig.svg.contains("lost"));
/// // Elastic: nothing is lost anywhere, so no band says so.
/// let elastic = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// assert!(!rodimpact::report::energy_figure(&elastic).unwrap().svg.contains("lost"));
/// ```
pub fn energy_figure(scene: &Scene) -> Result<Figure, Error> {
    check_sampling_cost(std::slice::from_ref(scene))?;
    let samples = samples(scene)?;
    let two = Q::from_integer(2.into());
    let (m, big_m, inertia) = (scene.m(), scene.rod_mass(), scene.inertia());
    let before = m * scene.v0() * scene.v0() / &two;
    // An elastic impact loses nothing at any point: no band, legend entry or column for a loss.
    let lossy = samples.iter().any(|s| !s.out.energy.lost().is_zero());
    let columns = ["a", "projectile", "rod_translation", "rod_rotation", "lost"];
    let mut data = PlotData::new(&columns[..if lossy { 5 } else { 4 }]);
    // Cumulative fractions: rotation, + translation, + projectile, + lost (= 1).
    let n_bands = if lossy { 4 } else { 3 };
    let mut bands: Vec<Vec<(f64, f64)>> = vec![Vec::new(); n_bands];
    let l = scene.half_length();
    for s in &samples {
        let x = &s.out.after;
        let parts = [
            &inertia * &x.omega * &x.omega / &two,
            big_m * &x.rod_v * &x.rod_v / &two,
            m * &x.v * &x.v / &two,
            s.out.energy.lost(),
        ];
        let mut total = Q::from_integer(0.into());
        for (band, part) in bands.iter_mut().zip(&parts) {
            total += part / &before;
            band.push((f(&(&s.a / l)), f(&total)));
        }
        let mut row = vec![
            Value::Exact(s.a.clone()),
            Value::Exact(parts[2].clone()),
            Value::Exact(parts[1].clone()),
            Value::Exact(parts[0].clone()),
        ];
        if lossy {
            row.push(Value::Exact(parts[3].clone()));
        }
        data.rows.push(row);
    }
    let fills = ["#9ecae9", "#f4b183", "#a8dcc9", "#d0d0d0"];
    let lines = [PALETTE[0], PALETTE[1], PALETTE[2], "#777777"];
    let names = [
        "rod rotation, I ω^{2}/2",
        "rod translation, M V^{2}/2",
        "projectile, m v^{2}/2",
        "lost in the impact",
    ];
    let legend: Vec<(Swatch, String)> = fills
        .iter()
        .zip(&names)
        .take(n_bands)
        .rev()
        .map(|(c, n)| (Swatch::Area(c), n.to_string()))
        .collect();
    let mut chart = Chart::new(
        SIZE.0,
        SIZE.1,
        "Where the kinetic energy goes, against the impact point",
        &[
            scene_line(scene),
            format!(
                "{}; fractions of the energy before, m v_{{0}}^{{2}}/2",
                numbers(scene, true)
            ),
        ],
        x_axis(scene),
        Axis {
            scale: Scale::Linear { lo: 0.0, hi: 1.0 },
            title: "fraction of the kinetic energy before the impact".into(),
        },
        &legend,
    );
    let mut floor: Vec<(f64, f64)> = bands[0].iter().map(|p| (p.0, 0.0)).collect();
    for ((band, fill), line) in bands.iter().zip(fills).zip(lines) {
        let outline: Vec<_> = band
            .iter()
            .chain(floor.iter().rev())
            .map(|p| chart.px(*p))
            .collect();
        chart.svg.open("band");
        chart.svg.polygon(&outline, Some(fill), None);
        chart.curve(band, &Stroke::solid(line, 1.4));
        chart.svg.close();
        floor.clone_from(band);
    }
    mark_optima(&mut chart, scene, (0.0, 1.0))?;
    Ok(Figure {
        svg: chart.finish()?,
        data: Some(data),
    })
}
