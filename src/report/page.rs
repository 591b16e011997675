//! The shell every rodimpact web page shares (`paper --format html`, `explore`, `handout`): one complete
//! HTML5 document that needs nothing beyond itself. Style, scripts, data and figures all go
//! inline and nothing is fetched (no font, stylesheet, script or image from the network), so
//! the file opens from disk, offline, and prints.
//!
//! A page builds its body with [`escape`] for any text, [`inline_svg`] for a figure and
//! [`json_script`] for data its script reads; [`document`] wraps the body with the title, the
//! style (after [`BASE_STYLE`], the print rules every page shares) and the script.

pub use super::mathml::escape;
use crate::Error;
use crate::error::ErrorKind;

/// The rules every page starts from: in print, no controls (buttons, sliders, anything marked
/// `no-print`) and links as plain text. A page's own style comes after and may add to them.
pub const BASE_STYLE: &str = "@media print {\n  button, input[type=range], .no-print { display: none !important; }\n  a { color: inherit; text-decoration: none; }\n}\n";

/// The parts of a page; [`document`] puts them together.
#[derive(Debug, Clone, Copy)]
pub struct Page<'a> {
    /// The document's title, plain text (escaped by [`document`]).
    pub title: &'a str,
    /// The page's CSS, inlined after [`BASE_STYLE`]; it must not contain `</style`.
    pub style: &'a str,
    /// The inside of `<body>`, HTML, complete: every text in it already escaped.
    pub body: &'a str,
    /// JavaScript run at the end of the body (empty: no script); it must not contain `</script`.
    pub script: &'a str,
}

/// The whole page: doctype, `<head>` (charset, viewport, the generator's version, the escaped
/// title, the inline style) and `<body>` with the script last.
///
/// # Panics
/// **Panics if the style contains `</style` or the script `</script`** (they would end their
/// element early; a programming error: every style and script is the program's own).
///
/// # Examples
/// ```
/// use rodimpact::report::page::{Page, document};
/// let html = document(&Page {
///     title: "a < b",
///     style: "p { margin: 0; }\n",
///     body: "<p>Hello</p>\n",
///     script: "",
/// });
/// assert!(html.starts_with("<!DOCTYPE html>\n<html lang=\"en\">"));
/// assert!(html.contains("<title>a &lt; b</title>"));
/// assert!(html.contains("@media print") && html.contains("p { margin: 0; }"));
/// assert!(html.contains("<body>\n<p>Hello</p>\n</body>") && !html.contains("<script"));
/// ```
pub fn document(page: &Page<'_>) -> String {
    assert!(
        !page.style.contains("</style"),
        "a style that ends its element"
    );
    assert!(
        !page.script.contains("</script"),
        "a script that ends its element"
    );
    let script = if page.script.is_empty() {
        String::new()
    } else {
        format!("<script>\n{}</script>\n", page.script)
    };
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"rodimpact {}\">\n<title>{}</title>\n\
         <style>\n{BASE_STYLE}{}</style>\n</head>\n<body>\n{}{script}</body>\n</html>\n",
        env!("CARGO_PKG_VERSION"),
        escape(page.title),
        page.style,
        page.body,
    )
}

/// An SVG document (rodimpact's own plots) as an element of the page: any XML declaration
/// before `<svg` dropped, and `role="img"` with `label` (plain text, escaped) as its accessible
/// name.
///
/// # Examples
/// ```
/// use rodimpact::report::page::inline_svg;
/// let svg = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4\"/>";
/// assert_eq!(
///     inline_svg(svg, "omega & a"),
///     "<svg role=\"img\" aria-label=\"omega &amp; a\" xmlns=\"http://www.w3.org/2000/svg\" width=\"4\"/>"
/// );
/// ```
pub fn inline_svg(svg: &str, label: &str) -> String {
    let start = svg.find("<svg").unwrap_or(0);
    svg[start..].replacen(
        "<svg ",
        &format!("<svg role=\"img\" aria-label=\"{}\" ", escape(label)),
        1,
    )
}

/// Data for the page's script: `json` in a `<script type="application/json">` element with
/// this `id` (the script reads it with `JSON.parse(document.getElementById(id).textContent)`).
/// Every `</` is written `<\/`, which JSON reads as `</` and which cannot end the element.
///
/// # Examples
/// ```
/// use rodimpact::report::page::json_script;
/// assert_eq!(
///     json_script("data", r#"{"note":"</script>"}"#),
///     "<script type=\"application/json\" id=\"data\">{\"note\":\"<\\/script>\"}</script>\n"
/// );
/// ```
pub fn json_script(id: &str, json: &str) -> String {
    format!(
        "<script type=\"application/json\" id=\"{}\">{}</script>\n",
        escape(id),
        json.replace("</", "<\\/")
    )
}

/// Unpacks the module in the page and runs the page's script with the API.
const LOADER: &str = include_str!("page_loader.js");

/// The element that carries the WebAssembly module in a page: `module` is the module
/// zlib-compressed and in base64, as the command-line tool's `build.rs` leaves it; part of the
/// page's body, read by the loader of [`page_script`].
///
/// # Errors
/// When `module` is empty (a build without the feature `pages`, without the
/// `wasm32-unknown-unknown` target, or with `RODIMPACT_PAGES_WASM=none`), naming the fix.
///
/// # Examples
/// ```
/// let element = rodimpact::report::page::module_element("eJwDAAAAAAE=")?;
/// assert!(element.starts_with("<script type=\"application/octet-stream\" id=\"rodimpact-wasm\">eJw"));
/// assert!(rodimpact::report::page::module_element("").is_err());
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn module_element(module: &str) -> Result<String, Error> {
    if module.is_empty() {
        return Err(Error::new(
            "explore",
            ErrorKind::Invalid(
                "this build has no WebAssembly module for the pages: install the target \
                 (rustup target add wasm32-unknown-unknown) and build again with the feature \
                 `pages` (on by default)"
                    .into(),
            ),
        ));
    }
    Ok(format!(
        "<script type=\"application/octet-stream\" id=\"rodimpact-wasm\">{module}</script>\n"
    ))
}

/// The script of a page that computes with the library: the loader, which unpacks the module
/// of [`module_element`] and then runs `ui` as the body of a function of `api`
/// (`api.call(name, request)` answers as [`crate::app::pages::call`] does).
///
/// # Examples
/// ```
/// let script = rodimpact::report::page::page_script("api.call('number', {text: '1'});");
/// assert!(script.contains("rodimpactPage(function (api) {"));
/// ```
pub fn page_script(ui: &str) -> String {
    format!("{LOADER}\nrodimpactPage(function (api) {{\n{ui}\n}});\n")
}

/// A page's preset as its link spells it after `#`: `key=value` joined by `&` (empty: nothing
/// preset). The values are the program's own (numbers, `/`, `-`, `.`, `=`, words): no escaping.
///
/// # Examples
/// ```
/// let fields = [("M", "1/2".to_string()), ("a", "1".to_string())];
/// assert_eq!(rodimpact::report::page::link_of(&fields), "M=1/2&a=1");
/// ```
pub fn link_of(fields: &[(&'static str, String)]) -> String {
    fields
        .iter()
        .map(|(key, value)| format!("{key}={value}"))
        .collect::<Vec<_>>()
        .join("&")
}

#[cfg(test)]
mod tests {
    use super::*;

    const EMPTY: Page<'static> = Page {
        title: "",
        style: "",
        body: "",
        script: "",
    };

    /// A style or script holding its own end tag would close its element early and spill the
    /// rest into the page as text or markup; the shell refuses it.
    #[test]
    #[should_panic(expected = "a script that ends its element")]
    fn a_script_that_would_end_its_element_is_refused() {
        document(&Page {
            script: "let s = '</script>';",
            ..EMPTY
        });
    }

    #[test]
    #[should_panic(expected = "a style that ends its element")]
    fn a_style_that_would_end_its_element_is_refused() {
        document(&Page {
            style: "</style><p>",
            ..EMPTY
        });
    }
}
