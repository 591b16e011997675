//! The float-backend values of `solve --backend` as JSON: each of v, V, omega as
//! `{"float", "exact", "rel_error", "cond", "reliable"}`, plus `"because"` saying why when it is
//! not reliable, or for the interval backend `{"lower", "upper", "exact", "encloses"}`, from
//! the values [`crate::stability::judge`] solved and judged.

use crate::field::{Q, decimal};
use crate::stability::Judged;
use serde_json::{Map, Value, json};

/// The `v`, `V`, `omega` entries of the judged values.
///
/// # Examples
/// ```
/// use rodimpact::{report::backend_json, scene::Scene, field::q, stability::{Backend, judge}};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build()?;
/// let j = backend_json(&judge(&s, Backend::Interval)?);
/// assert_eq!(j["omega"]["exact"], "12/11");
/// assert_eq!(j["omega"]["encloses"], true);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn backend_json(judged: &Judged) -> Map<String, Value> {
    let mut out = Map::new();
    match judged {
        Judged::Interval(values) => {
            for x in values {
                out.insert(
                    x.name.to_string(),
                    json!({
                        "lower": x.lower,
                        "upper": x.upper,
                        "exact": x.exact.to_string(),
                        "encloses": x.encloses,
                    }),
                );
            }
        }
        Judged::Float(values) => {
            let text = |x: Option<&Q>| x.map_or("inf".to_string(), |x| decimal::decimal(x, 3));
            for x in values {
                let mut entry = json!({
                    "float": x.float,
                    "exact": x.exact.to_string(),
                    "rel_error": text(x.rel_error.as_ref()),
                    "cond": text(x.cond.as_ref()),
                    "reliable": x.doubts.is_empty(),
                });
                if !x.doubts.is_empty() {
                    entry["because"] = Value::String(x.doubts.join("; "));
                }
                out.insert(x.name.to_string(), entry);
            }
        }
    }
    out
}
