//! `rodimpact explore --scene tilted-rod`, written: its preset checked as the page checks it
//! (by the page's own [`super::tilted`]), rendered by [`crate::report::tilted::tilted_html`].

use crate::Error;
use crate::report::page::link_of;
use serde_json::json;

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
    /// use rodimpact::app::pages::TiltedPreset;
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
        let answer = super::tilted(&request);
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
        link_of(&self.fields)
    }
}

/// The page, complete, opening on `preset`, with the WebAssembly `module` (compressed, in
/// base64: the command-line tool's build makes it).
///
/// # Errors
/// When `module` is empty.
///
/// # Examples
/// ```
/// use rodimpact::app::pages::{TiltedPreset, tilted_page};
/// let page = tilted_page(&TiltedPreset::of(Some("1/4"), None, None, None)?, "eJwDAAAAAAE=")?;
/// assert!(page.contains("tan_half=1/4"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn tilted_page(preset: &TiltedPreset, module: &str) -> Result<String, Error> {
    crate::report::tilted::tilted_html(&preset.link(), module)
}
