//! A chart: title, axes with ticks and labels, curves clipped to the plotting area, markers, a
//! legend, and labels placed where they collide with nothing already drawn (other labels,
//! markers, curves, the legend), with a leader line when a label had to move away.

use super::scale::{Scale, Tick};
use super::svg::{Anchor, Point, Rect, Shape, Stroke, Svg, Text};
use crate::error::Error;

/// Sizes of the texts, in px.
pub(crate) const TITLE: f64 = 20.0;
pub(crate) const SUBTITLE: f64 = 14.5;
pub(crate) const AXIS_TITLE: f64 = 16.0;
pub(crate) const TICK_LABEL: f64 = 14.0;
pub(crate) const LABEL: f64 = 14.0;

/// Grey of grid lines and secondary text.
const GRID: &str = "#e3e3e3";
const GREY: &str = "#555555";

/// One axis: its scale and its title (markup).
pub(crate) struct Axis {
    pub(crate) scale: Scale,
    pub(crate) title: String,
}

/// Bands below and above a y axis's scale, past a drawn axis break, for values the scale cannot
/// show (an error of exactly 0 on a log axis, an unbounded one): each with its tick label (`0`,
/// `∞`) and a caption written in the band.
#[derive(Debug, Clone, Default)]
pub(crate) struct OffScale {
    pub(crate) below: Option<(String, String)>,
    pub(crate) above: Option<(String, String)>,
}

/// Height of an off-scale band, in px.
const BAND: f64 = 46.0;

/// What a legend entry shows beside its text.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Swatch {
    Line(Stroke),
    Marker(Shape, &'static str, bool),
    Area(&'static str),
}

/// Everything drawn so far that a label must not cover.
#[derive(Default)]
pub(crate) struct Obstacles {
    boxes: Vec<Rect>,
    segments: Vec<(Point, Point)>,
}

impl Obstacles {
    pub(crate) fn add_box(&mut self, r: Rect) {
        self.boxes.push(r);
    }
    pub(crate) fn add_segment(&mut self, p: Point, q: Point) {
        self.segments.push((p, q));
    }

    /// How many obstacles `r` touches.
    pub(crate) fn hits(&self, r: &Rect) -> usize {
        self.boxes.iter().filter(|b| b.overlaps(r)).count()
            + self
                .segments
                .iter()
                .filter(|(p, q)| r.clip(*p, *q).is_some())
                .count()
    }

    /// Places `text` (its `at` ignored) near `target` inside `within`: the first position,
    /// trying every side at growing distances, that touches nothing; else the one touching
    /// least. Returns the positioned text and whether it moved away (a leader line helps).
    pub(crate) fn place(&self, text: &Text, target: Point, within: &Rect) -> (Text, bool) {
        let (w, size) = (text.width(), text.size);
        let h = 1.05 * size;
        let mut best: Option<(usize, Text, bool)> = None;
        for (ring, gap) in [6.0, 14.0, 28.0, 48.0, 80.0, 130.0].into_iter().enumerate() {
            let (x, y) = target;
            // Top-left corners of the box: right, above, left, below, then the diagonals.
            let corners = [
                (x + gap, y - h / 2.0),
                (x - w / 2.0, y - gap - h),
                (x - gap - w, y - h / 2.0),
                (x - w / 2.0, y + gap),
                (x + gap * 0.7, y - gap * 0.7 - h),
                (x - gap * 0.7 - w, y - gap * 0.7 - h),
                (x + gap * 0.7, y + gap * 0.7),
                (x - gap * 0.7 - w, y + gap * 0.7),
            ];
            for (x0, y0) in corners {
                let mut placed = text.clone();
                placed.anchor = Anchor::Start;
                placed.at = (x0, y0 + 0.8 * size);
                let bounds = placed.bounds();
                if !within.contains(&bounds) {
                    continue;
                }
                let hits = self.hits(&bounds.grow(2.0));
                if hits == 0 {
                    return (placed, ring >= 2);
                }
                if best.as_ref().is_none_or(|(b, _, _)| hits < *b) {
                    best = Some((hits, placed, ring >= 2));
                }
            }
        }
        best.map_or_else(|| (text.clone(), false), |(_, t, moved)| (t, moved))
    }
}

/// Width of a legend's box: swatch, longest text, padding.
fn legend_width(entries: &[(Swatch, String)]) -> f64 {
    entries
        .iter()
        .map(|(_, m)| Text::new(m.as_str(), (0.0, 0.0), LABEL).width())
        .fold(0.0, f64::max)
        + LEGEND_SWATCH
        + 20.0
}

const LEGEND_ROW: f64 = 23.0;
const LEGEND_SWATCH: f64 = 36.0;

/// The legend beside the plotting area, top-left corner at `at`: one row per entry.
fn draw_legend(svg: &mut Svg, at: Point, entries: &[(Swatch, String)]) {
    let (x0, y0) = at;
    let frame = Rect::new(
        x0,
        y0,
        x0 + legend_width(entries),
        y0 + LEGEND_ROW * entries.len() as f64 + 12.0,
    );
    svg.open("legend");
    svg.rect(frame, Some("#ffffff"), Some(&Stroke::solid("#999999", 1.0)));
    for (k, (kind, markup)) in entries.iter().enumerate() {
        let y = y0 + 6.0 + LEGEND_ROW * (k as f64 + 0.5);
        let (sx0, sx1) = (x0 + 9.0, x0 + LEGEND_SWATCH - 1.0);
        match kind {
            Swatch::Line(stroke) => svg.line((sx0, y), (sx1, y), stroke),
            Swatch::Marker(shape, color, filled) => {
                svg.marker(*shape, ((sx0 + sx1) / 2.0, y), 6.0, color, *filled)
            }
            Swatch::Area(color) => svg.rect(
                Rect::new(sx0, y - 7.0, sx1, y + 7.0),
                Some(color),
                Some(&Stroke::solid("#666666", 0.6)),
            ),
        }
        svg.text(&Text::new(
            markup.as_str(),
            (x0 + LEGEND_SWATCH + 8.0, y + 5.0),
            LABEL,
        ));
    }
    svg.close();
}

/// A chart under construction.
pub(crate) struct Chart {
    pub(crate) svg: Svg,
    /// The plotting area in px.
    pub(crate) area: Rect,
    /// The part of the area the y scale maps to (all of it unless there are off-scale bands).
    inner: Rect,
    x: Scale,
    y: Scale,
    pub(crate) obstacles: Obstacles,
    /// Captions of the off-scale bands, placed last (around the markers in them).
    captions: Vec<(String, Point)>,
}

impl Chart {
    /// A `width` x `height` chart with a title, subtitle lines, two axes and the legend drawn.
    pub(crate) fn new(
        width: f64,
        height: f64,
        title: &str,
        subtitle: &[String],
        x: Axis,
        y: Axis,
        legend: &[(Swatch, String)],
    ) -> Chart {
        Chart::with_bands(
            width,
            height,
            title,
            subtitle,
            x,
            y,
            legend,
            &OffScale::default(),
        )
    }

    /// As [`Chart::new`], with off-scale bands on the y axis.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn with_bands(
        width: f64,
        height: f64,
        title: &str,
        subtitle: &[String],
        x: Axis,
        y: Axis,
        legend: &[(Swatch, String)],
        bands: &OffScale,
    ) -> Chart {
        let mut svg = Svg::new(width, height);
        svg.open("title");
        svg.text(
            &Text::new(title, (width / 2.0, 30.0), TITLE)
                .anchor(Anchor::Middle)
                .bold(),
        );
        for (k, line) in subtitle.iter().enumerate() {
            svg.text(
                &Text::new(
                    line.as_str(),
                    (width / 2.0, 54.0 + 19.0 * k as f64),
                    SUBTITLE,
                )
                .anchor(Anchor::Middle)
                .color(GREY),
            );
        }
        svg.close();
        let top = 48.0 + 19.0 * subtitle.len() as f64 + 14.0;
        let legend_width = legend_width(legend);
        let right = if legend.is_empty() {
            width - 28.0
        } else {
            width - 24.0 - legend_width - 18.0
        };
        let area = Rect::new(88.0, top, right, height - 68.0);
        if !legend.is_empty() {
            draw_legend(&mut svg, (right + 18.0, top), legend);
        }
        let inner = Rect::new(
            area.x0,
            area.y0 + if bands.above.is_some() { BAND } else { 0.0 },
            area.x1,
            area.y1 - if bands.below.is_some() { BAND } else { 0.0 },
        );
        let mut chart = Chart {
            svg,
            area,
            inner,
            captions: Vec::new(),
            x: x.scale,
            y: y.scale,
            obstacles: Obstacles::default(),
        };
        chart.axes(&x.title, &y.title);
        chart.bands(bands);
        chart
    }

    /// The off-scale bands: shaded, labelled at the axis, with a break mark where they meet
    /// the scale.
    fn bands(&mut self, bands: &OffScale) {
        let (a, inner) = (self.area, self.inner);
        for (label, band, edge) in [
            (
                &bands.below,
                Rect::new(a.x0, inner.y1, a.x1, a.y1),
                inner.y1,
            ),
            (
                &bands.above,
                Rect::new(a.x0, a.y0, a.x1, inner.y0),
                inner.y0,
            ),
        ] {
            let Some((label, caption)) = label else {
                continue;
            };
            self.svg.open("off-scale");
            self.svg.rect(band, Some("#f1f1f1"), None);
            let cy = band.center().1 + 5.0;
            self.svg.text(
                &Text::new(label.as_str(), (a.x0 - 11.0, cy), TICK_LABEL).anchor(Anchor::End),
            );
            self.captions
                .push((caption.clone(), (a.x0 + 4.0, cy - 5.0)));
            // The break: a white gap in the axis between two slanted strokes.
            let x = a.x0;
            self.svg.rect(
                Rect::new(x - 8.0, edge - 3.0, x + 8.0, edge + 3.0),
                Some("#ffffff"),
                None,
            );
            for dy in [-3.0, 3.0] {
                self.svg.line(
                    (x - 8.0, edge + dy + 3.0),
                    (x + 8.0, edge + dy - 3.0),
                    &Stroke::solid("#000000", 1.5),
                );
            }
            self.svg
                .line((a.x0, edge), (a.x1, edge), &Stroke::dashed("#999999", 1.0));
            self.svg.close();
        }
    }

    /// The px height of the middle of an off-scale band (`above` or below).
    pub(crate) fn band_y(&self, above: bool) -> f64 {
        if above {
            (self.area.y0 + self.inner.y0) / 2.0
        } else {
            (self.inner.y1 + self.area.y1) / 2.0
        }
    }

    fn axes(&mut self, x_title: &str, y_title: &str) {
        let a = self.area;
        let (x_ticks, y_ticks) = (self.x.ticks(), self.y.ticks());
        self.svg.open("grid");
        for t in x_ticks.iter().filter(|t| t.label.is_some()) {
            let px = self.px_x(t.value);
            self.svg
                .line((px, a.y0), (px, a.y1), &Stroke::solid(GRID, 1.0));
        }
        for t in y_ticks.iter().filter(|t| t.label.is_some()) {
            let py = self.px_y(t.value);
            self.svg
                .line((a.x0, py), (a.x1, py), &Stroke::solid(GRID, 1.0));
        }
        self.svg.close();
        self.svg.open("axes");
        let axis = Stroke::solid("#000000", 1.5);
        self.svg.line((a.x0, a.y1), (a.x1, a.y1), &axis);
        self.svg.line((a.x0, a.y0), (a.x0, a.y1), &axis);
        let tick_line = |t: &Tick| if t.label.is_some() { 7.0 } else { 4.0 };
        for t in &x_ticks {
            let px = self.px_x(t.value);
            self.svg.line((px, a.y1), (px, a.y1 + tick_line(t)), &axis);
            if let Some(label) = &t.label {
                self.svg.text(
                    &Text::new(label.as_str(), (px, a.y1 + 24.0), TICK_LABEL)
                        .anchor(Anchor::Middle),
                );
            }
        }
        for t in &y_ticks {
            let py = self.px_y(t.value);
            self.svg.line((a.x0 - tick_line(t), py), (a.x0, py), &axis);
            if let Some(label) = &t.label {
                self.svg.text(
                    &Text::new(label.as_str(), (a.x0 - 11.0, py + 5.0), TICK_LABEL)
                        .anchor(Anchor::End),
                );
            }
        }
        self.svg.text(
            &Text::new(x_title, ((a.x0 + a.x1) / 2.0, a.y1 + 52.0), AXIS_TITLE)
                .anchor(Anchor::Middle),
        );
        self.svg.text(
            &Text::new(y_title, (26.0, (a.y0 + a.y1) / 2.0), AXIS_TITLE)
                .anchor(Anchor::Middle)
                .vertical(),
        );
        self.svg.close();
    }

    pub(crate) fn px_x(&self, x: f64) -> f64 {
        self.area.x0 + self.x.fraction(x) * self.area.width()
    }
    pub(crate) fn px_y(&self, y: f64) -> f64 {
        self.inner.y1 - self.y.fraction(y) * self.inner.height()
    }
    /// A data point in px.
    pub(crate) fn px(&self, p: (f64, f64)) -> Point {
        (self.px_x(p.0), self.px_y(p.1))
    }
    /// A curve through data points, clipped to the area; a label avoids it afterwards.
    pub(crate) fn curve(&mut self, data: &[(f64, f64)], stroke: &Stroke) {
        let mut runs: Vec<Vec<Point>> = Vec::new();
        let mut open = false;
        for pair in data.windows(2) {
            let (p, q) = (self.px(pair[0]), self.px(pair[1]));
            let finite = [p.0, p.1, q.0, q.1].iter().all(|v| v.is_finite());
            match finite.then(|| self.area.clip(p, q)).flatten() {
                Some((from, to)) => {
                    if !open || from != p {
                        runs.push(vec![from]);
                    }
                    runs.last_mut().expect("a run was opened").push(to);
                    open = to == q;
                    self.obstacles.add_segment(from, to);
                }
                None => open = false,
            }
        }
        for run in runs {
            self.svg.polyline(&run, stroke);
        }
    }

    /// A straight line between data points (clipped), an obstacle for labels.
    pub(crate) fn rule(&mut self, from: (f64, f64), to: (f64, f64), stroke: &Stroke) {
        self.curve(&[from, to], stroke);
    }

    /// A marker at a data point, an obstacle for labels.
    pub(crate) fn marker(
        &mut self,
        at: (f64, f64),
        shape: Shape,
        color: &'static str,
        filled: bool,
    ) -> Point {
        let p = self.px(at);
        self.marker_px(p, shape, color, filled);
        p
    }

    /// A marker at a point in px.
    pub(crate) fn marker_px(&mut self, p: Point, shape: Shape, color: &'static str, filled: bool) {
        self.svg.marker(shape, p, 6.5, color, filled);
        self.obstacles.add_box(Rect::around(p, 8.0));
    }

    /// A label near the px point `target`, placed where it covers nothing; joined to the point
    /// by a thin line when it had to move away.
    pub(crate) fn label_px(&mut self, markup: &str, target: Point, color: &'static str) {
        let text = Text::new(markup, target, LABEL).color(color);
        let (placed, moved) = self.obstacles.place(&text, target, &self.area.grow(-2.0));
        let bounds = placed.bounds();
        if moved {
            let (cx, cy) = bounds.center();
            let end = (
                cx.clamp(bounds.x0, bounds.x1),
                cy.clamp(bounds.y0, bounds.y1),
            );
            if let Some((p, q)) = bounds.grow(2.0).clip(target, end) {
                let start = if p == target { q } else { p };
                self.svg.line(target, start, &Stroke::solid(color, 0.8));
                self.obstacles.add_segment(target, start);
            }
        }
        self.svg.rect(bounds.grow(1.0), Some("#ffffff"), None);
        self.svg.text(&placed);
        self.obstacles.add_box(bounds);
    }

    /// A label near a data point.
    pub(crate) fn label(&mut self, markup: &str, at: (f64, f64), color: &'static str) {
        let p = self.px(at);
        self.label_px(markup, p, color);
    }

    /// The finished SVG (the band captions placed now, where they cover nothing).
    pub(crate) fn finish(mut self) -> Result<String, Error> {
        for (caption, at) in std::mem::take(&mut self.captions) {
            self.label_px(&caption, at, GREY);
        }
        self.svg.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_label_avoids_what_is_there() {
        let mut obstacles = Obstacles::default();
        let area = Rect::new(0.0, 0.0, 400.0, 300.0);
        // A horizontal curve through the target and a box to its right.
        obstacles.add_segment((0.0, 150.0), (400.0, 150.0));
        obstacles.add_box(Rect::new(205.0, 120.0, 300.0, 180.0));
        let text = Text::new("a*", (0.0, 0.0), 14.0);
        let (placed, _) = obstacles.place(&text, (200.0, 150.0), &area);
        let b = placed.bounds();
        assert_eq!(obstacles.hits(&b), 0, "{b:?}");
        assert!(area.contains(&b));
    }

    #[test]
    fn a_label_stays_inside_the_area() {
        let obstacles = Obstacles::default();
        let area = Rect::new(0.0, 0.0, 400.0, 300.0);
        let text = Text::new("M = 99m: a* reaches the end", (0.0, 0.0), 14.0);
        let (placed, _) = obstacles.place(&text, (399.0, 150.0), &area);
        assert!(area.contains(&placed.bounds()));
    }
}
