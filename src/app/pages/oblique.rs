//! The explore page's oblique tab: the paper's scene with the puck also sliding along the rod
//! (v0t) and Coulomb friction mu at the contact, the puck a point or a solid disc that may
//! spin. Its lesson: on a thin rod the friction impulse acts along the rod's axis, so the rod's
//! spin is exactly the frictionless one; friction costs energy and the contact sticks from mu*
//! on.

use super::exact;
use super::explore_api::{FieldErrors, page_scene_with, params_at, read_field};
use crate::field::{Field, Q, QSqrt, q};
use crate::scene::{Oblique, Params};
use crate::solve::fast::oblique::{ObliqueOutcome, solve};
use num_traits::{Signed, Zero};
use serde_json::{Value, json};

/// The points of the loss curve.
const CURVE_POINTS: i64 = 100;

/// `oblique`: the explore page's fields (see [`super::explore`]) and `v0t`, `mu`, and for a
/// disc `radius` (r/l) and `spin`; answered with `values` (v, V, omega, vt, Vt, J, Jt, the
/// disc's `spin_after`, `mu_star`, the energies and `omega_frictionless`), `contact` (`stick`,
/// `slide` or `frictionless`), `same_spin` (omega equals the frictionless omega, exactly),
/// `pivot_impulse` (across and along, on a pivot) and `loss_curve` (the energy lost to
/// friction, and in all, as shares of the energy before, against mu, in floats); or `errors`
/// by field.
///
/// # Examples
/// The M = m rod struck at l/2 by a puck sliding along it at v0: the contact slides (mu* =
/// 11/16), yet omega = 12/11 as without friction.
/// ```
/// use serde_json::json;
/// let answer = rodimpact::app::pages::oblique(&json!({
///     "ratio": "1", "a": "1/2", "e": "1", "kind": "uniform", "v0t": "1", "mu": "1/4"
/// }));
/// assert_eq!(answer["values"]["omega"]["text"], "12/11");
/// assert_eq!(answer["values"]["mu_star"]["text"], "11/16");
/// assert_eq!((answer["contact"].as_str(), answer["same_spin"].as_bool()), (Some("slide"), Some(true)));
/// assert_eq!(answer["values"]["lost_friction"]["text"], "18/121");
/// ```
pub fn oblique(request: &Value) -> Value {
    let mut errors = FieldErrors::new();
    let v0t = read_field(request, "v0t", &|_| None, &mut errors);
    let mu = read_field(
        request,
        "mu",
        &|m| m.is_negative().then_some("must be ≥ 0"),
        &mut errors,
    );
    let disc = match request["radius"]
        .as_str()
        .map(str::trim)
        .filter(|t| !t.is_empty())
    {
        None => None,
        Some(_) => {
            let radius = read_field(
                request,
                "radius",
                &|r| (!r.is_positive()).then_some("must be > 0"),
                &mut errors,
            );
            let spin = match request["spin"]
                .as_str()
                .map(str::trim)
                .filter(|t| !t.is_empty())
            {
                Some(_) => read_field(request, "spin", &|_| None, &mut errors),
                None => Some(Q::zero()),
            };
            Some((radius, spin))
        }
    };
    let extension = (v0t.clone(), mu.clone(), disc.clone());
    let s = match page_scene_with(request, errors, &|b| {
        let (v0t, mu, disc) = &extension;
        let b = b
            .v0t(v0t.clone().unwrap_or_default())
            .mu(mu.clone().unwrap_or_default());
        match disc {
            Some((Some(r), Some(w))) => b.disc(r.clone(), w.clone()),
            _ => b,
        }
    }) {
        Ok(s) => s,
        Err(errors) => return json!({ "errors": errors }),
    };
    let scene = &s.scene;
    let oblique = scene.oblique().cloned().unwrap_or_default();
    let params: Params<QSqrt> = params_at(scene, s.a.clone());
    let out = solve(&params, &oblique.params::<QSqrt>(), None).expect("a valid scene solves");
    let frictionless = Oblique {
        mu: Q::zero(),
        ..oblique.clone()
    };
    let without =
        solve(&params, &frictionless.params::<QSqrt>(), None).expect("a valid scene solves");
    let mu_star = (!out.stick_impulse.is_zero()).then(|| out.stick_impulse.abs() / &out.impulse);
    let mut values = json!({
        "v": exact(&out.after.v),
        "V": exact(&out.after.rod.v),
        "omega": exact(&out.after.rod.omega),
        "vt": exact(&out.after.vt),
        "Vt": exact(&out.after.rod.vt),
        "J": exact(&out.impulse),
        "Jt": exact(&out.tangential_impulse),
        "energy_before": exact(&out.energy.before),
        "energy_lost": exact(&out.energy.lost()),
        "lost_restitution": exact(&out.lost_restitution),
        "lost_friction": exact(&out.lost_friction),
        "omega_frictionless": exact(&without.after.rod.omega),
    });
    if let Some(spin) = &out.after.spin {
        values["spin_after"] = exact(spin);
    }
    if let Some(m) = &mu_star {
        values["mu_star"] = exact(m);
    }
    json!({
        "values": values,
        "contact": out.contact.map_or("frictionless", |c| c.kind()),
        "same_spin": out.after.rod.omega == without.after.rod.omega,
        "pivot_impulse": out.pivot_impulse.as_ref().map(|(x, t)| [exact(x), exact(t)]),
        "loss_curve": match s.a.d() {
            // Struck at a rational point (as a slider strikes): the curve in Q, several times faster.
            None => loss_curve(&params_at::<Q>(scene, s.a.x().clone()), &oblique, mu_star.as_ref()),
            Some(_) => loss_curve(&params, &oblique, mu_star.as_ref()),
        },
    })
}

/// The energy lost to friction, and in all, as shares of the energy before, at 101 values of mu
/// from 0 to mu_max = 3/2 mu* (at least 1, in tenths), each solved exactly, as floats.
fn loss_curve<F: Field>(params: &Params<F>, oblique: &Oblique, mu_star: Option<&QSqrt>) -> Value {
    let star = mu_star.map(Field::nearest_f64);
    // mu_max in tenths, so that the samples are short fractions.
    let tenths = star.map_or(10, |m| ((m * 15.0).ceil() as i64).clamp(10, 1000));
    let mu_max = q(tenths, 10);
    let (mut mus, mut friction, mut total) = (Vec::new(), Vec::new(), Vec::new());
    for k in 0..=CURVE_POINTS {
        let mu = mu_max.clone() * &q(k, CURVE_POINTS);
        let at = Oblique {
            mu: mu.clone(),
            ..oblique.clone()
        };
        let out: ObliqueOutcome<F> =
            solve(params, &at.params::<F>(), None).expect("a valid scene solves");
        mus.push(mu.nearest_f64());
        friction.push((out.lost_friction.clone() / &out.energy.before).nearest_f64());
        total.push((out.energy.lost() / &out.energy.before).nearest_f64());
    }
    json!({ "mu": mus, "friction": friction, "total": total, "mu_star": star, "mu_max": mu_max.nearest_f64() })
}
