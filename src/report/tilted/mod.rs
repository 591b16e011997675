//! `rodimpact explore --scene tilted-rod`: one self-contained interactive page on the general
//! one-contact solver: a rod tilted above a rough floor, its lower end landing while it slides;
//! sliders for the tilt, the slip, mu and e; Newton's, Poisson's and Stronge's laws side by side
//! with Routh's path (the slip's phases along the normal impulse) and the energy change; and a
//! map of the scenes where each law creates energy, each decided exactly. Every number is
//! computed in the page by this library compiled to WebAssembly (`crate::app::pages::tilted`,
//! `crate::app::pages::tilted_map`).

use super::page::{Page, document, json_script, module_element, page_script};
use crate::Error;

/// The page's body, with `{{VERSION}}` and `{{PRESET}}` to fill.
const BODY: &str = include_str!("page.html");
const STYLE: &str = include_str!("page.css");
/// The page's script: reads the controls, asks the library and draws.
const UI: &str = include_str!("ui.js");

/// The page, complete, opening on `preset` (a link's text after `#`, which a link's own
/// `#...` still overrides), with the WebAssembly `module` (compressed, in base64).
///
/// # Errors
/// When `module` is empty ([`module_element`]).
///
/// # Examples
/// ```
/// use rodimpact::report::tilted::tilted_html;
/// let page = tilted_html("tan_half=1/4", "eJwDAAAAAAE=")?;
/// assert!(page.starts_with("<!DOCTYPE html>") && page.contains("Routh"));
/// assert!(!page.contains("{{"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn tilted_html(preset: &str, module: &str) -> Result<String, Error> {
    let preset = serde_json::to_string(preset).expect("JSON of a string");
    let body = BODY
        .replace("{{VERSION}}", env!("CARGO_PKG_VERSION"))
        .replace("{{PRESET}}", &json_script("preset", &preset))
        + &module_element(module)?;
    Ok(document(&Page {
        title: "Can a bounce create energy? A tilted rod on a rough floor, under three laws",
        style: STYLE,
        body: &body,
        script: &page_script(UI),
    }))
}
