//! A minimal SVG writer: shapes and text with sub-pixel coordinates (two decimals), Unicode text
//! with sub- and superscripts, and text widths estimated from DejaVu Sans's advance widths so
//! labels can be laid out without a font library.

use crate::error::Error;
use std::fmt::Write;

/// A point in pixels (y down).
pub(crate) type Point = (f64, f64);

/// The typeface of every text: DejaVu Sans when installed (the widths below are its own), else
/// any sans-serif.
const FONT: &str = "DejaVu Sans, Verdana, sans-serif";

/// Advance widths of DejaVu Sans for ASCII 32..=126, in thousandths of an em.
const ASCII_WIDTHS: [u16; 95] = [
    318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636, 636,
    636, 636, 636, 636, 636, 636, 636, 337, 337, 838, 838, 838, 531, 1000, 684, 686, 698, 770, 632,
    575, 775, 752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695, 635, 611, 732, 684, 989, 685,
    611, 685, 390, 337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635, 634, 278, 278, 579,
    278, 974, 634, 612, 635, 635, 411, 521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838,
];

/// Width of one character in ems (DejaVu Sans; symbols outside ASCII at their own widths).
fn char_width(c: char) -> f64 {
    let thousandths = match c {
        ' '..='~' => ASCII_WIDTHS[c as usize - 32],
        '²' | '³' | '¹' | '⁰'..='⁹' => 401,
        '⁻' => 528,
        '·' => 318,
        '–' => 500,
        '—' => 1000,
        '√' => 637,
        '′' => 227,
        '▸' | '◂' => 502,
        _ => 838, // ω, ×, −, ≤, ≥, arrows: all 837-838
    };
    f64::from(thousandths) / 1000.0
}

/// A run of text: normal, subscript (`_{...}`) or superscript (`^{...}`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Shift {
    Normal,
    Sub,
    Sup,
}

/// Relative size of a sub- or superscript.
const SCRIPT: f64 = 0.72;

/// Splits the markup `ω_{max} = 10^{-3}` into runs.
fn runs(markup: &str) -> Vec<(Shift, String)> {
    let mut out: Vec<(Shift, String)> = Vec::new();
    let mut rest = markup;
    while !rest.is_empty() {
        let next = rest
            .find(['_', '^'])
            .filter(|&i| rest[i + 1..].starts_with('{'));
        match next {
            Some(i) => {
                let shift = if rest.as_bytes()[i] == b'_' {
                    Shift::Sub
                } else {
                    Shift::Sup
                };
                let close = rest[i..].find('}').map_or(rest.len(), |j| i + j);
                if i > 0 {
                    out.push((Shift::Normal, rest[..i].to_string()));
                }
                out.push((shift, rest[i + 2..close].to_string()));
                rest = rest.get(close + 1..).unwrap_or("");
            }
            None => {
                out.push((Shift::Normal, rest.to_string()));
                rest = "";
            }
        }
    }
    out
}

/// The width in pixels of `markup` set at `size` px.
pub(crate) fn text_width(markup: &str, size: f64) -> f64 {
    runs(markup)
        .iter()
        .map(|(shift, s)| {
            let scale = if *shift == Shift::Normal { 1.0 } else { SCRIPT };
            s.chars().map(char_width).sum::<f64>() * size * scale
        })
        .sum()
}

/// A coordinate with at most two decimals, no trailing zeros, no `-0`.
pub(crate) fn num(x: f64) -> String {
    let rounded = (x * 100.0).round() / 100.0;
    let text = format!("{:.2}", if rounded == 0.0 { 0.0 } else { rounded });
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stroke {
    /// Colour, `#rrggbb`.
    pub(crate) color: &'static str,
    /// Width in px.
    pub(crate) width: f64,
    /// Dash pattern (`"6 4"`), or solid.
    pub(crate) dash: Option<&'static str>,
}

impl Stroke {
    pub(crate) const fn solid(color: &'static str, width: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: None,
        }
    }
    pub(crate) const fn dashed(color: &'static str, width: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: Some("7 5"),
        }
    }
    pub(crate) const fn dotted(color: &'static str, width: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: Some("2 4"),
        }
    }
    fn attributes(&self) -> String {
        let mut out = format!(
            r#" stroke="{}" stroke-width="{}""#,
            self.color,
            num(self.width)
        );
        if let Some(dash) = self.dash {
            let _ = write!(out, r#" stroke-dasharray="{dash}""#);
        }
        out
    }
}

/// Horizontal alignment of a text on its anchor point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Anchor {
    Start,
    Middle,
    End,
}

/// A text: markup (`_{}` subscripts, `^{}` superscripts), baseline anchor point, size in px.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Text {
    pub(crate) markup: String,
    pub(crate) at: Point,
    pub(crate) size: f64,
    pub(crate) anchor: Anchor,
    pub(crate) color: &'static str,
    pub(crate) bold: bool,
    /// Turned a quarter anticlockwise (a y-axis title).
    pub(crate) vertical: bool,
}

impl Text {
    pub(crate) fn new(markup: impl Into<String>, at: Point, size: f64) -> Text {
        Text {
            markup: markup.into(),
            at,
            size,
            anchor: Anchor::Start,
            color: "#000000",
            bold: false,
            vertical: false,
        }
    }
    pub(crate) fn anchor(mut self, anchor: Anchor) -> Text {
        self.anchor = anchor;
        self
    }
    pub(crate) fn color(mut self, color: &'static str) -> Text {
        self.color = color;
        self
    }
    pub(crate) fn bold(mut self) -> Text {
        self.bold = true;
        self
    }
    pub(crate) fn vertical(mut self) -> Text {
        self.vertical = true;
        self
    }
    pub(crate) fn width(&self) -> f64 {
        text_width(&self.markup, self.size) * if self.bold { 1.1 } else { 1.0 }
    }

    /// The box the text covers (ascent 0.8 em above the baseline, descent 0.25 em below).
    pub(crate) fn bounds(&self) -> Rect {
        let w = self.width();
        let (x, y) = self.at;
        let start = match self.anchor {
            Anchor::Start => 0.0,
            Anchor::Middle => -w / 2.0,
            Anchor::End => -w,
        };
        if self.vertical {
            Rect::new(
                x - 0.8 * self.size,
                y - start - w,
                x + 0.25 * self.size,
                y - start,
            )
        } else {
            Rect::new(
                x + start,
                y - 0.8 * self.size,
                x + start + w,
                y + 0.25 * self.size,
            )
        }
    }
}

/// An axis-aligned rectangle in pixels, `x0 <= x1`, `y0 <= y1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rect {
    pub(crate) x0: f64,
    pub(crate) y0: f64,
    pub(crate) x1: f64,
    pub(crate) y1: f64,
}

impl Rect {
    pub(crate) fn new(x0: f64, y0: f64, x1: f64, y1: f64) -> Rect {
        Rect {
            x0: x0.min(x1),
            y0: y0.min(y1),
            x1: x0.max(x1),
            y1: y0.max(y1),
        }
    }
    pub(crate) fn around(center: Point, half: f64) -> Rect {
        Rect::new(
            center.0 - half,
            center.1 - half,
            center.0 + half,
            center.1 + half,
        )
    }
    pub(crate) fn overlaps(&self, other: &Rect) -> bool {
        self.x0 < other.x1 && other.x0 < self.x1 && self.y0 < other.y1 && other.y0 < self.y1
    }
    pub(crate) fn contains(&self, other: &Rect) -> bool {
        self.x0 <= other.x0 && other.x1 <= self.x1 && self.y0 <= other.y0 && other.y1 <= self.y1
    }
    pub(crate) fn grow(&self, by: f64) -> Rect {
        Rect::new(self.x0 - by, self.y0 - by, self.x1 + by, self.y1 + by)
    }
    pub(crate) fn width(&self) -> f64 {
        self.x1 - self.x0
    }
    pub(crate) fn height(&self) -> f64 {
        self.y1 - self.y0
    }
    pub(crate) fn center(&self) -> Point {
        ((self.x0 + self.x1) / 2.0, (self.y0 + self.y1) / 2.0)
    }

    /// The part of the segment `p`-`q` inside the rectangle (Liang-Barsky), if any.
    pub(crate) fn clip(&self, p: Point, q: Point) -> Option<(Point, Point)> {
        let (dx, dy) = (q.0 - p.0, q.1 - p.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (step, room) in [
            (-dx, p.0 - self.x0),
            (dx, self.x1 - p.0),
            (-dy, p.1 - self.y0),
            (dy, self.y1 - p.1),
        ] {
            if step == 0.0 {
                if room < 0.0 {
                    return None;
                }
            } else {
                let t = room / step;
                if step < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
        (t0 <= t1).then_some((
            (p.0 + t0 * dx, p.1 + t0 * dy),
            (p.0 + t1 * dx, p.1 + t1 * dy),
        ))
    }
}

/// Marker shapes, told apart without colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Shape {
    Circle,
    Square,
    Diamond,
    TriangleUp,
    TriangleRight,
    TriangleLeft,
    Star,
}

/// An SVG document under construction.
pub(crate) struct Svg {
    width: f64,
    height: f64,
    body: String,
}

impl Svg {
    /// A white page of `width` x `height` px.
    pub(crate) fn new(width: f64, height: f64) -> Svg {
        let mut svg = Svg {
            width,
            height,
            body: String::new(),
        };
        svg.rect(Rect::new(0.0, 0.0, width, height), Some("#ffffff"), None);
        svg
    }

    /// Opens a group with a class (tests and readers find the parts by it).
    pub(crate) fn open(&mut self, class: &str) {
        let _ = writeln!(self.body, r#"<g class="{class}">"#);
    }
    pub(crate) fn close(&mut self) {
        self.body.push_str("</g>\n");
    }

    pub(crate) fn line(&mut self, p: Point, q: Point, stroke: &Stroke) {
        let _ = writeln!(
            self.body,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}"{} stroke-linecap="round"/>"#,
            num(p.0),
            num(p.1),
            num(q.0),
            num(q.1),
            stroke.attributes()
        );
    }

    pub(crate) fn polyline(&mut self, points: &[Point], stroke: &Stroke) {
        if points.len() < 2 {
            return;
        }
        let coords: Vec<String> = points
            .iter()
            .map(|p| format!("{},{}", num(p.0), num(p.1)))
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{}" fill="none"{} stroke-linejoin="round" stroke-linecap="round"/>"#,
            coords.join(" "),
            stroke.attributes()
        );
    }

    /// A closed polygon, filled and/or outlined.
    pub(crate) fn polygon(
        &mut self,
        points: &[Point],
        fill: Option<&str>,
        stroke: Option<&Stroke>,
    ) {
        let coords: Vec<String> = points
            .iter()
            .map(|p| format!("{},{}", num(p.0), num(p.1)))
            .collect();
        let _ = writeln!(
            self.body,
            r#"<polygon points="{}" fill="{}"{} stroke-linejoin="round"/>"#,
            coords.join(" "),
            fill.unwrap_or("none"),
            stroke.map(Stroke::attributes).unwrap_or_default()
        );
    }

    pub(crate) fn rect(&mut self, r: Rect, fill: Option<&str>, stroke: Option<&Stroke>) {
        let _ = writeln!(
            self.body,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{}"{}/>"#,
            num(r.x0),
            num(r.y0),
            num(r.width()),
            num(r.height()),
            fill.unwrap_or("none"),
            stroke.map(Stroke::attributes).unwrap_or_default()
        );
    }

    pub(crate) fn circle(&mut self, c: Point, r: f64, fill: Option<&str>, stroke: Option<&Stroke>) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{}" cy="{}" r="{}" fill="{}"{}/>"#,
            num(c.0),
            num(c.1),
            num(r),
            fill.unwrap_or("none"),
            stroke.map(Stroke::attributes).unwrap_or_default()
        );
    }

    /// A marker of `shape` and size `r` (px, about its radius) at `c`: filled in `color`, or
    /// open (white inside, outlined) when `filled` is false.
    pub(crate) fn marker(
        &mut self,
        shape: Shape,
        c: Point,
        r: f64,
        color: &'static str,
        filled: bool,
    ) {
        let fill = if filled { color } else { "#ffffff" };
        let outline = Stroke::solid(color, if filled { 1.0 } else { 2.0 });
        let (x, y) = c;
        let polygon = |pts: &[(f64, f64)]| -> Vec<Point> {
            pts.iter()
                .map(|(dx, dy)| (x + dx * r, y + dy * r))
                .collect()
        };
        match shape {
            Shape::Circle => self.circle(c, r, Some(fill), Some(&outline)),
            Shape::Square => {
                let s = r * 0.85;
                self.rect(
                    Rect::new(x - s, y - s, x + s, y + s),
                    Some(fill),
                    Some(&outline),
                );
            }
            Shape::Diamond => {
                let pts = polygon(&[(0.0, -1.2), (1.2, 0.0), (0.0, 1.2), (-1.2, 0.0)]);
                self.polygon(&pts, Some(fill), Some(&outline));
            }
            Shape::TriangleUp => {
                let pts = polygon(&[(0.0, -1.2), (1.1, 0.8), (-1.1, 0.8)]);
                self.polygon(&pts, Some(fill), Some(&outline));
            }
            Shape::TriangleRight => {
                let pts = polygon(&[(1.2, 0.0), (-0.8, -1.1), (-0.8, 1.1)]);
                self.polygon(&pts, Some(fill), Some(&outline));
            }
            Shape::TriangleLeft => {
                let pts = polygon(&[(-1.2, 0.0), (0.8, -1.1), (0.8, 1.1)]);
                self.polygon(&pts, Some(fill), Some(&outline));
            }
            Shape::Star => {
                let pts: Vec<(f64, f64)> = (0..10)
                    .map(|k| {
                        let angle = std::f64::consts::PI * (f64::from(k) / 5.0 - 0.5);
                        let radius = if k % 2 == 0 { 1.35 } else { 0.55 };
                        (radius * angle.cos(), radius * angle.sin())
                    })
                    .collect();
                self.polygon(&polygon(&pts), Some(fill), Some(&outline));
            }
        }
    }

    /// An arrow from `from` to `to` with a filled head of length `head` px.
    pub(crate) fn arrow(&mut self, from: Point, to: Point, stroke: &Stroke, head: f64) {
        let (dx, dy) = (to.0 - from.0, to.1 - from.1);
        let length = dx.hypot(dy);
        if length < 1e-9 {
            return;
        }
        let (ux, uy) = (dx / length, dy / length);
        let head = head.min(length * 0.6);
        let base = (to.0 - ux * head, to.1 - uy * head);
        self.line(from, base, stroke);
        let half = head * 0.45;
        let pts = [
            to,
            (base.0 - uy * half, base.1 + ux * half),
            (base.0 + uy * half, base.1 - ux * half),
        ];
        self.polygon(&pts, Some(stroke.color), None);
    }

    pub(crate) fn text(&mut self, t: &Text) {
        let anchor = match t.anchor {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        };
        let mut attributes = format!(
            r#"x="{}" y="{}" xml:space="preserve" font-family="{FONT}" font-size="{}" fill="{}" text-anchor="{anchor}""#,
            num(t.at.0),
            num(t.at.1),
            num(t.size),
            t.color
        );
        if t.bold {
            attributes.push_str(r#" font-weight="bold""#);
        }
        if t.vertical {
            let _ = write!(
                attributes,
                r#" transform="rotate(-90 {} {})""#,
                num(t.at.0),
                num(t.at.1)
            );
        }
        // Each run moves the baseline from where the previous one left it (dy): baseline-shift
        // is not honoured by every renderer.
        let mut content = String::new();
        let mut offset = 0.0;
        for (shift, run) in runs(&t.markup) {
            let (target, size) = match shift {
                Shift::Normal => (0.0, t.size),
                Shift::Sub => (0.25 * t.size, SCRIPT * t.size),
                Shift::Sup => (-0.4 * t.size, SCRIPT * t.size),
            };
            if target == offset && shift == Shift::Normal {
                content.push_str(&escape(&run));
            } else {
                let _ = write!(content, r#"<tspan dy="{}""#, num(target - offset));
                if shift != Shift::Normal {
                    let _ = write!(content, r#" font-size="{}""#, num(size));
                }
                let _ = write!(content, ">{}</tspan>", escape(&run));
            }
            offset = target;
        }
        let _ = writeln!(self.body, "<text {attributes}>{content}</text>");
    }

    /// The finished document.
    ///
    /// # Errors
    /// `scene: beyond what the figure can draw ...` when a coordinate or a number in a label is
    /// not finite: an exact value beyond the f64 range (`M = 1e400`), or a ratio of two values
    /// that underflowed (`l = a = 1e-10000`). No figure ever holds `inf` or `NaN`.
    pub(crate) fn finish(self) -> Result<String, Error> {
        if holds_non_finite(&self.body) {
            return Err(beyond_drawing());
        }
        Ok(format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n{}</svg>\n",
            self.body,
            w = num(self.width),
            h = num(self.height),
        ))
    }
}

/// The refusal of a scene whose figure would need numbers beyond the f64 range.
pub(crate) fn beyond_drawing() -> Error {
    Error::out_of_range(
        "scene",
        "beyond what the figure can draw: its coordinates leave the f64 range (about \
         1e-308 to 1e308); `rodimpact solve` answers it exactly",
    )
}

/// Whether `text` holds a number Rust printed from a float that is not finite (`inf`, `-inf`,
/// `NaN`, as a word of its own: `infinite` is a word, not a number).
fn holds_non_finite(text: &str) -> bool {
    ["inf", "NaN"].iter().any(|token| {
        text.match_indices(token).any(|(i, _)| {
            let before = text[..i].chars().next_back();
            let after = text[i + token.len()..].chars().next();
            !before.is_some_and(|c| c.is_alphanumeric())
                && !after.is_some_and(|c| c.is_alphanumeric())
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_keep_two_decimals_and_no_negative_zero() {
        assert_eq!(num(12.0), "12");
        assert_eq!(num(12.345), "12.35");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-3.5), "-3.5");
    }

    #[test]
    fn markup_splits_into_scripts() {
        assert_eq!(
            runs("ω_{max} = 10^{-3}"),
            vec![
                (Shift::Normal, "ω".to_string()),
                (Shift::Sub, "max".to_string()),
                (Shift::Normal, " = 10".to_string()),
                (Shift::Sup, "-3".to_string()),
            ]
        );
        // An underscore not followed by a brace is text.
        assert_eq!(runs("a_b"), vec![(Shift::Normal, "a_b".to_string())]);
    }

    #[test]
    fn widths_follow_the_font() {
        // "M" is 863/1000 em, "i" 278/1000: at 10 px.
        assert!((text_width("Mi", 10.0) - 11.41).abs() < 1e-9);
        assert!(text_width("ω_{max}", 10.0) < text_width("ωmax", 10.0));
    }

    #[test]
    fn clipping_keeps_the_inside_part() {
        let r = Rect::new(0.0, 0.0, 10.0, 10.0);
        assert_eq!(
            r.clip((-5.0, 5.0), (5.0, 5.0)),
            Some(((0.0, 5.0), (5.0, 5.0)))
        );
        assert_eq!(r.clip((-5.0, -5.0), (-1.0, 20.0)), None);
    }

    /// Regression (G5): figures beyond the f64 range were written with `inf` and `NaN`
    /// coordinates (and exit 0). A document holding one is refused.
    #[test]
    fn a_document_with_a_non_finite_number_is_refused() {
        for bad in [f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            let mut svg = Svg::new(10.0, 10.0);
            svg.polyline(&[(0.0, 1.0), (bad, 2.0)], &Stroke::solid("#000000", 1.0));
            let err = svg.finish().unwrap_err().to_string();
            assert!(
                err.starts_with("scene: beyond what the figure can draw"),
                "{err}"
            );
        }
        let mut svg = Svg::new(10.0, 10.0);
        svg.text(&Text::new(
            "infinite NaNs? no: infinity, Inf, info",
            (1.0, 2.0),
            10.0,
        ));
        assert!(svg.finish().is_ok());
    }

    #[test]
    fn text_escapes_and_scripts() {
        let mut svg = Svg::new(10.0, 10.0);
        svg.text(&Text::new("a < b & ω_{max}", (1.0, 2.0), 10.0));
        let out = svg.finish().unwrap();
        assert!(out.contains("a &lt; b &amp; ω"));
        assert!(out.contains(r#"<tspan dy="2.5" font-size="7.2">max</tspan>"#));
    }
}
