//! The float-backend values of `solve --backend`: each of v, V, omega as
//! `{"float", "exact", "rel_error", "cond", "reliable"}` (DESIGN.md §3), or for the interval
//! backend `{"lower", "upper", "exact", "encloses"}`.

use crate::error::{Error, ErrorKind};
use crate::field::{Interval, Q};
use crate::float::Real;
use crate::number;
use crate::scene::Scene;
use crate::solve::closed_form;
use crate::stability::{Backend, Measured, Reference};
use serde_json::{Map, Value, json};

/// The `v`, `V`, `omega` entries of `scene` solved in `backend` (`solve --backend` passes the
/// library's stable formula, [`crate::float::Formula::DEFAULT`]; the interval runs the closed
/// form).
///
/// # Errors
/// A pivoted rod with a float backend (the float formulas and condition numbers cover the free
/// rod), or the exact backend (nothing to compare).
///
/// # Examples
/// ```
/// use rodimpact::{report::backend_values, scene::Scene, field::q, stability::Backend};
/// use rodimpact::float::Formula;
/// let s = Scene::builder(q(4, 7), q(1, 1)).a(q(1, 2)).build()?; // v = 0 exactly
/// let j = backend_values(&s, Backend::F64(Formula::Sq))?;
/// assert_eq!(j["v"]["exact"], "0");
/// assert_eq!(j["v"]["reliable"], false);
/// assert_eq!(j["V"]["reliable"], true);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn backend_values(scene: &Scene, backend: Backend) -> Result<Map<String, Value>, Error> {
    let refuse = |why: &str| Error::new("backend", ErrorKind::Invalid(why.into()));
    if backend == Backend::Exact {
        return Err(refuse("the exact backend has no float values"));
    }
    let Some(reference) = Reference::of(scene) else {
        return Err(refuse(
            "the float backends cover the free rod; drop --pivot or use --backend exact",
        ));
    };
    let names = ["v", "V", "omega"];
    let exact = &reference.motion;
    let exacts = [&exact.v, &exact.rod_v, &exact.omega];
    let mut out = Map::new();
    if backend == Backend::Interval {
        let x = closed_form(&scene.params::<Interval>()).expect("a free rod's closed form");
        for (i, x) in [x.v, x.rod_v, x.omega].iter().enumerate() {
            out.insert(
                names[i].into(),
                json!({
                    "lower": x.lower().shortest(),
                    "upper": x.upper().shortest(),
                    "exact": exacts[i].to_string(),
                    "encloses": x.contains(exacts[i]),
                }),
            );
        }
        return Ok(out);
    }
    let (measured, _) = backend
        .measure(scene, &reference)
        .expect("a free rod is measured");
    let floats: [String; 3] = match backend {
        Backend::F32(f) => motion_strings(f.eval(&scene.params::<f32>())),
        Backend::F64(f) => motion_strings(f.eval(&scene.params::<f64>())),
        Backend::Interval | Backend::Exact => unreachable!("handled above"),
    };
    let cond = backend.condition(&reference);
    let conds = [&cond.v, &cond.rod_v, &cond.omega];
    let measures = [&measured.v, &measured.rod_v, &measured.omega];
    let u = backend.unit_roundoff();
    for i in 0..3 {
        let text = |x: Option<&Q>| x.map_or("inf".to_string(), |x| number::decimal(x, 3));
        out.insert(
            names[i].into(),
            json!({
                "float": floats[i],
                "exact": exacts[i].to_string(),
                "rel_error": text(measures[i].rel_error.as_ref()),
                "cond": text(conds[i].as_ref()),
                "reliable": Measured::reliable(conds[i].as_ref(), &u),
            }),
        );
    }
    Ok(out)
}

fn motion_strings<T: Real>(x: Option<crate::mechanics::Motion<T>>) -> [String; 3] {
    let x = x.expect("a free rod");
    [x.v.shortest(), x.rod_v.shortest(), x.omega.shortest()]
}
