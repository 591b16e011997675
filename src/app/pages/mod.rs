//! The web pages' computing core: what the pages ask of the library, answered in JSON (the
//! WebAssembly module of the pages calls [`call_json`]), and the pages themselves written with
//! what they carry computed ([`explore_page`], [`tilted_page`]).
//!
//! The pages (`explore`, and `explore --scene tilted-rod`) compute every number they show with
//! this library compiled to WebAssembly (`wasm/`, built by the command-line tool's `build.rs`
//! and handed to the page writers, which inline it compressed in each page), never with a second implementation of the physics in JavaScript. The page's
//! script calls [`call`] through the module (`api.call(name, request)`); the same function
//! answers here natively, so `cargo test` checks what the pages compute.
//!
//! | name | answers |
//! |---|---|
//! | `number` | a field's text read as an exact number (or its error) |
//! | `explore` | the paper's scene on the explore page: the exact answer, a*, omega_max, the curves |
//! | `explore_motion` | the rod and puck after the impact at given times, for the animation |
//! | `oblique` | the explore page's oblique tab: the puck also sliding along the rod, with friction |
//! | `tilted` | a tilted rod on a rough floor under the three laws, with Routh's path |
//! | `tilted_map` | where each law creates energy, over a grid of tilted-rod scenes |

mod explore;
mod explore_api;
mod oblique;
mod tilted;
mod tilted_page;
mod value;

pub use explore::{Frame, Preset, REFERENCE_SCENES, explore_page, reference_answers};
pub use explore_api::{PAGE_DIGITS, explore, explore_motion, is_a_star};
pub use oblique::oblique;
pub use tilted::{tilted, tilted_map};
pub use tilted_page::{TiltedPreset, tilted_page};
pub use value::exact;

use crate::Error;
use crate::error::ErrorKind;
use serde_json::{Value, json};

/// Answers one request of a page: `name` is the function, `request` its argument.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::call;
/// use serde_json::json;
/// let answer = call("number", &json!({"text": "0.25"}));
/// assert_eq!(answer["value"]["text"], "1/4");
/// assert_eq!(call("nothing", &json!({}))["error"]["message"], "no page function 'nothing'");
/// ```
pub fn call(name: &str, request: &Value) -> Value {
    match name {
        "number" => number(request),
        "explore" => explore(request),
        "explore_motion" => explore_motion(request),
        "oblique" => oblique(request),
        "tilted" => tilted(request),
        "tilted_map" => tilted_map(request),
        _ => field_error(
            "name",
            format!("no page function '{}'", crate::echo::echo(name)),
        ),
    }
}

/// [`call`] on the text the WebAssembly module receives: `{"name": ..., "request": ...}`; the
/// answer as JSON text.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::call_json;
/// assert!(call_json(r#"{"name": "number", "request": {"text": "3/6"}}"#).contains(r#""text":"1/2""#));
/// assert!(call_json("{").contains("error"));
/// ```
pub fn call_json(text: &str) -> String {
    let answer = match serde_json::from_str::<Value>(text) {
        Ok(message) => call(
            message["name"].as_str().unwrap_or_default(),
            &message["request"],
        ),
        Err(e) => field_error("request", format!("not JSON: {e}")),
    };
    answer.to_string()
}

/// `number`: `{"text": "0.25"}` read as an exact number: `{"value": X}` or an error.
fn number(request: &Value) -> Value {
    match read(request, "text", "number") {
        Ok(q) => json!({ "value": exact(&crate::field::QSqrt::rational(q)) }),
        Err(e) => e,
    }
}

/// The text of `request[key]` read as an exact rational, or the error object naming `field`.
fn read(request: &Value, key: &str, field: &str) -> Result<crate::field::Q, Value> {
    let text = request[key].as_str().unwrap_or_default();
    crate::number::parse(text).map_err(|kind| field_error(field, kind_message(&kind)))
}

/// An error's reason as the pages show it (without the field's name, which the page shows).
fn kind_message(kind: &ErrorKind) -> String {
    Error::new("x", kind.clone())
        .to_string()
        .trim_start_matches("x: ")
        .to_string()
}

/// `{"error": {"field": field, "message": message}}`.
fn field_error(field: &str, message: String) -> Value {
    json!({ "error": { "field": field, "message": message } })
}
