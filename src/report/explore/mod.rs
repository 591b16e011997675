//! `rodimpact explore`: one self-contained interactive page on which a student finds the
//! paper's surprise: sliders for M/m, a, e, the rod and the pivot; the exact answer (fractions
//! and surds, computed in the page by this library compiled to WebAssembly, `crate::app::pages`);
//! |omega| along the rod with a* and the end marked; a* against M/m with the threshold; an animation of the impact and of the second
//! impact that follows a hit beyond the stop point (X19), with energy bars; a predict-first
//! mode; and a second tab, the oblique impact (the puck sliding along the rod, friction, a
//! disc): does sliding change the spin?
//!
//! The impact point may be a* itself (the a field takes `a*`, `-a*`, `p+a*`, `p-a*`): the page's
//! numbers are `x + y*sqrt(r)`, so a scene struck at a* is exact too (X19's v = V and
//! omega a* = v0, not their decimals).
//!
//! The page carries rodimpact's own exact answers for a set of reference scenes (computed
//! natively when the page is written, `rodimpact::app::pages::explore_page`), and checks its
//! WebAssembly module against them each time it opens.

use super::page::{Page, document, json_script, module_element, page_script};
use crate::Error;
use serde_json::Value;

/// The page's body, with `{{VERSION}}` and `{{REFERENCE}}` (the reference answers) to fill.
const BODY: &str = include_str!("page.html");
const STYLE: &str = include_str!("page.css");
/// The page's script: reads the controls, asks the library (compiled to WebAssembly) and draws.
const UI: &str = include_str!("ui.js");

/// The page, complete: its body with the `reference` answers it checks its module against
/// and the `preset` it opens with (a link's text after `#`, which a link's own `#...` still
/// overrides), its style and scripts, in the shared shell ([`document`]). `module` is the
/// WebAssembly module the page computes with (compressed, in base64: the command-line tool's
/// build makes it). `rodimpact::app::pages::explore_page` computes the reference answers.
///
/// # Errors
/// When `module` is empty ([`module_element`]).
///
/// # Examples
/// ```
/// use rodimpact::report::explore::explore_html;
/// let reference = serde_json::json!([{"a_star": "sqrt(6)/3"}]);
/// let page = explore_html("", &reference, "eJwDAAAAAAE=")?;
/// assert!(page.starts_with("<!DOCTYPE html>"));
/// assert!(page.contains("\"a_star\":\"sqrt(6)/3\""));
/// assert!(page.contains("<script type=\"application/json\" id=\"preset\">\"\"</script>"));
/// assert!(!page.contains("{{"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn explore_html(preset: &str, reference: &Value, module: &str) -> Result<String, Error> {
    let reference = serde_json::to_string(reference).expect("JSON of strings");
    let preset = serde_json::to_string(preset).expect("JSON of a string");
    let body = BODY
        .replace("{{VERSION}}", env!("CARGO_PKG_VERSION"))
        .replace("{{REFERENCE}}", &json_script("reference", &reference))
        .replace("{{PRESET}}", &json_script("preset", &preset))
        + &module_element(module)?;
    Ok(document(&Page {
        title: "Where should you hit the rod? An exact explorer",
        style: STYLE,
        body: &body,
        script: &page_script(UI),
    }))
}
