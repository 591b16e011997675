//! `rodimpact explore --scene tilted-rod`: one self-contained interactive page on the general
//! one-contact solver: a rod tilted above a rough floor, its lower end landing while it slides;
//! sliders for the tilt, the slip, mu and e; Newton's, Poisson's and Stronge's laws side by side
//! with Routh's path (the slip's phases along the normal impulse) and the energy change; and a
//! map of the scenes where each law creates energy, each decided exactly. Every number is
//! computed in the page by this library compiled to WebAssembly ([`super::pages::tilted`],
//! [`super::pages::tilted_map`]).

use super::page::{Page, document, json_script};
use super::pages;
use crate::Error;
use serde_json::json;

/// The page's body, with `{{VERSION}}` and `{{PRESET}}` to fill.
const BODY: &str = include_str!("page.html");
const STYLE: &str = include_str!("page.css");
/// The page's script: reads the controls, asks the library and draws.
const UI: &str = include_str!("ui.js");

/// The scene the page opens on: tan(theta/2), the slip, mu and e, as the page's link spells
/// them (`tan_half=1/2&slip=1&mu=1/3&e=1`); a value not given keeps the page's default (the
/// example `examples/impacts/tilted-rod-rough-floor.toml`: 1/2, 1, 1/3, 1).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TiltedPreset {
    fields: Vec<(&'static str, String)>,
}

impl TiltedPreset {
    /// The preset of the given values (each as typed), checked as the page checks them.
    ///
    /// # Errors
    /// The first wrong value, naming its flag (`tilt`, `slip`, `mu`, `e`) and the reason.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::report::tilted::TiltedPreset;
    /// let preset = TiltedPreset::of(Some("1/4"), None, Some("0.5"), None)?;
    /// assert_eq!(preset.link(), "tan_half=1/4&mu=1/2");
    /// let wrong = TiltedPreset::of(Some("2"), None, None, None).unwrap_err();
    /// assert_eq!(wrong.to_string(), "tilt: must lie in 0 < tan(θ/2) < 1 (a tilt between 0 and 90 degrees)");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn of(
        tilt: Option<&str>,
        slip: Option<&str>,
        mu: Option<&str>,
        e: Option<&str>,
    ) -> Result<TiltedPreset, Error> {
        let given = [
            ("tan_half", "tilt", tilt),
            ("slip", "slip", slip),
            ("mu", "mu", mu),
            ("e", "e", e),
        ];
        let default = |key: &str| match key {
            "tan_half" => "1/2",
            "mu" => "1/3",
            _ => "1",
        };
        let request = json!({
            "tan_half": tilt.unwrap_or(default("tan_half")),
            "slip": slip.unwrap_or(default("slip")),
            "mu": mu.unwrap_or(default("mu")),
            "e": e.unwrap_or(default("e")),
        });
        let answer = pages::tilted(&request);
        if let Some(error) = answer.get("error") {
            let key = error["field"].as_str().unwrap_or_default();
            let (_, flag, _) = given
                .iter()
                .find(|(k, _, _)| *k == key)
                .copied()
                .unwrap_or((key, key, None));
            let message = error["message"].as_str().unwrap_or_default();
            let reason = message.split_once(": ").map_or(message, |(_, why)| why);
            return Err(Error::new(
                flag,
                crate::error::ErrorKind::Invalid(reason.to_string()),
            ));
        }
        let fields = given
            .iter()
            .filter_map(|&(key, _, value)| {
                value.map(|_| {
                    (
                        key,
                        answer["input"][key]["text"]
                            .as_str()
                            .unwrap_or_default()
                            .to_string(),
                    )
                })
            })
            .collect();
        Ok(TiltedPreset { fields })
    }

    /// The preset as the page's link spells it after `#` (empty: nothing preset).
    pub fn link(&self) -> String {
        pages::link_of(&self.fields)
    }
}

/// The page, complete, opening on `preset` (a link's `#...` still overrides it).
///
/// # Errors
/// When `module` (the WebAssembly module, compressed, in base64) is empty
/// ([`pages::module_element`]).
///
/// # Examples
/// ```
/// use rodimpact::report::tilted::{TiltedPreset, tilted_html};
/// let page = tilted_html(&TiltedPreset::default(), "eJwDAAAAAAE=")?;
/// assert!(page.starts_with("<!DOCTYPE html>") && page.contains("Routh"));
/// assert!(!page.contains("{{"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn tilted_html(preset: &TiltedPreset, module: &str) -> Result<String, Error> {
    let preset = serde_json::to_string(&preset.link()).expect("JSON of a string");
    let body = BODY
        .replace("{{VERSION}}", env!("CARGO_PKG_VERSION"))
        .replace("{{PRESET}}", &json_script("preset", &preset))
        + &pages::module_element(module)?;
    Ok(document(&Page {
        title: "Can a bounce create energy? A tilted rod on a rough floor, under three laws",
        style: STYLE,
        body: &body,
        script: &pages::page_script(UI),
    }))
}
