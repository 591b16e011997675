//! The figures as PNG, for slides: the SVG rasterised by resvg (a pure-Rust renderer), with the
//! figures' font, DejaVu Sans and DejaVu Sans Bold, carried in the program (subsets of Latin,
//! Greek and the mathematical symbols, `assets/fonts/`, Bitstream Vera licence): the same
//! picture on every machine, whatever fonts it has.

use crate::error::{Error, ErrorKind};
use resvg::{tiny_skia, usvg};
use std::sync::Arc;

/// The figures' regular and bold faces (subsets; see `assets/fonts/LICENSE-DejaVu.txt`).
const FONTS: [&[u8]; 2] = [
    include_bytes!("../../../assets/fonts/DejaVuSans-subset.ttf"),
    include_bytes!("../../../assets/fonts/DejaVuSans-Bold-subset.ttf"),
];

/// How many pixels a PNG has per SVG unit: twice the SVG's size, sharp on a projector.
pub const PNG_SCALE: f32 = 2.0;

/// `svg` rasterised to PNG at `scale` pixels per SVG unit, on a white background.
///
/// # Errors
/// An SVG that does not parse, or a picture of no size or more than 8,192 pixels a side
/// (`out`).
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene};
/// let s = Scene::builder(q(1, 1), q(2, 1)).build()?;
/// let png = rodimpact::report::svg_to_png(&rodimpact::report::energy_figure(&s)?.svg, 1.0)?;
/// assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn svg_to_png(svg: &str, scale: f32) -> Result<Vec<u8>, Error> {
    let invalid = |why: String| Error::new("out", ErrorKind::Invalid(why));
    let mut fonts = usvg::fontdb::Database::new();
    for face in FONTS {
        fonts.load_font_data(face.to_vec());
    }
    fonts.set_sans_serif_family("DejaVu Sans");
    let options = usvg::Options {
        fontdb: Arc::new(fonts),
        ..usvg::Options::default()
    };
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|why| invalid(format!("the figure's SVG does not parse: {why}")))?;
    let size = tree.size().to_int_size().scale_by(scale);
    let pixmap = size
        .filter(|s| s.width() <= 8192 && s.height() <= 8192)
        .and_then(|s| tiny_skia::Pixmap::new(s.width(), s.height()));
    let Some(mut pixmap) = pixmap else {
        return Err(invalid(format!(
            "the figure cannot be drawn {scale} times its size"
        )));
    };
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|why| invalid(format!("the PNG could not be encoded: {why}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixels darker than mid-grey in a decoded PNG.
    fn dark_pixels(png: &[u8]) -> usize {
        let pixmap = tiny_skia::Pixmap::decode_png(png).expect("a PNG");
        pixmap
            .pixels()
            .iter()
            .filter(|p| u32::from(p.red()) + u32::from(p.green()) + u32::from(p.blue()) < 3 * 128)
            .count()
    }

    /// Text is drawn with the carried font (no system font needed), Greek and bold included;
    /// the size is the SVG's times the scale; the same SVG gives the same bytes.
    #[test]
    fn text_is_drawn_with_the_carried_font() {
        let text = |body: &str| {
            format!(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"50\">\
                 <text x=\"10\" y=\"35\" font-family=\"DejaVu Sans, Verdana, sans-serif\" \
                 font-size=\"30\" {body}</text></svg>"
            )
        };
        let blank = svg_to_png(&text(">"), 2.0).unwrap();
        assert_eq!(dark_pixels(&blank), 0);
        let greek = svg_to_png(&text(">ω μ √ ≤"), 2.0).unwrap();
        let bold = svg_to_png(&text("font-weight=\"bold\">ω μ √ ≤"), 2.0).unwrap();
        let (regular, heavy) = (dark_pixels(&greek), dark_pixels(&bold));
        assert!(regular > 500, "{regular} dark pixels");
        assert!(heavy > regular, "bold {heavy} against regular {regular}");
        let pixmap = tiny_skia::Pixmap::decode_png(&greek).unwrap();
        assert_eq!((pixmap.width(), pixmap.height()), (400, 100));
        assert_eq!(svg_to_png(&text(">ω μ √ ≤"), 2.0).unwrap(), greek);
    }

    #[test]
    fn a_bad_svg_or_size_is_an_error() {
        assert!(
            svg_to_png("<svg", 1.0)
                .unwrap_err()
                .to_string()
                .starts_with("out: the figure's SVG does not parse")
        );
        let huge = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"5000\" height=\"10\"/>";
        assert_eq!(
            svg_to_png(huge, 2.0).unwrap_err().to_string(),
            "out: the figure cannot be drawn 2 times its size"
        );
    }
}
