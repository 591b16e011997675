//! The paper's missing Figure 1, to scale for a scene (top view: the rod, its mass distribution,
//! the pivot, the projectile and the impact point), and the before/after velocity diagram: the
//! same view just after the impact, with the velocity of each body and the rod's instantaneous
//! rest point y0 = -r_G^2/a.

use super::PALETTE;
use super::chart::{LABEL, Obstacles, SUBTITLE, TITLE};
use super::describe::{multiple, pivot_of, scene_line, signed};
use super::svg::{Anchor, Point, Rect, Shape, Stroke, Svg, Text};
use crate::error::Error;
use crate::field::Q;
use crate::sampling::{f, outcome_at};
use crate::scene::{RodInertia, Scene};
use crate::solve::Outcome;
use num_traits::Zero;

const TABLE: &str = "#efe6d2";
const ROD: &str = "#6b4423";
const PROJECTILE: &str = PALETTE[0];
const IMPACT: &str = PALETTE[1];
const VELOCITY: &str = PALETTE[2];
/// Pixels per l in every panel.
const SCALE: f64 = 200.0;

/// A panel: world coordinates in units of l (y up) mapped to pixels.
struct Panel {
    /// World x and y ranges.
    x: (f64, f64),
    y: (f64, f64),
    /// Pixel position of the world's top-left corner.
    origin: Point,
    obstacles: Obstacles,
    /// Labels to place once everything else is drawn: text, world point, colour.
    labels: Vec<(String, (f64, f64), &'static str)>,
}

impl Panel {
    fn new(x: (f64, f64), y: (f64, f64), origin: Point) -> Panel {
        Panel {
            x,
            y,
            origin,
            obstacles: Obstacles::default(),
            labels: Vec::new(),
        }
    }
    fn px(&self, p: (f64, f64)) -> Point {
        (
            self.origin.0 + (p.0 - self.x.0) * SCALE,
            self.origin.1 + (self.y.1 - p.1) * SCALE,
        )
    }
    fn frame(&self) -> Rect {
        let (a, b) = (self.px((self.x.0, self.y.1)), self.px((self.x.1, self.y.0)));
        Rect::new(a.0, a.1, b.0, b.1)
    }
    fn line(&mut self, svg: &mut Svg, p: (f64, f64), q: (f64, f64), stroke: &Stroke) {
        let (p, q) = (self.px(p), self.px(q));
        svg.line(p, q, stroke);
        self.obstacles.add_segment(p, q);
    }
    fn arrow(&mut self, svg: &mut Svg, p: (f64, f64), q: (f64, f64), color: &'static str) {
        let (p, q) = (self.px(p), self.px(q));
        svg.arrow(p, q, &Stroke::solid(color, 3.0), 14.0);
        self.obstacles.add_segment(p, q);
    }
    fn dot(&mut self, svg: &mut Svg, p: (f64, f64), r: f64, color: &'static str) {
        let c = self.px(p);
        svg.circle(c, r, Some(color), None);
        self.obstacles.add_box(Rect::around(c, r + 1.0));
    }
    /// A label near a world point, placed by [`Panel::place_labels`].
    fn label(&mut self, markup: &str, at: (f64, f64), color: &'static str) {
        self.labels.push((markup.to_string(), at, color));
    }
    /// Places the labels, in the order given, where each covers nothing drawn in the panel
    /// nor an earlier label.
    fn place_labels(&mut self, svg: &mut Svg) {
        for (markup, at, color) in std::mem::take(&mut self.labels) {
            let target = self.px(at);
            let text = Text::new(markup, target, LABEL).color(color);
            let (placed, _) = self
                .obstacles
                .place(&text, target, &self.frame().grow(-4.0));
            self.obstacles.add_box(placed.bounds());
            svg.text(&placed);
        }
    }
}

/// The table, the rod as its mass distribution makes it look, the centre, the pivot.
fn draw_rod(svg: &mut Svg, panel: &mut Panel, scene: &Scene) {
    svg.rect(panel.frame(), Some(TABLE), None);
    let l = f(scene.half_length());
    svg.open("rod");
    match scene.rod() {
        RodInertia::Dumbbell => {
            panel.line(svg, (0.0, -1.0), (0.0, 1.0), &Stroke::solid(ROD, 3.0));
            svg.open("end-masses");
            for y in [-1.0, 1.0] {
                panel.dot(svg, (0.0, y), 13.0, ROD);
            }
            svg.close();
            panel.label("end masses M/2 each", (0.0, 1.0), ROD);
        }
        other => {
            panel.line(svg, (0.0, -1.0), (0.0, 1.0), &Stroke::solid(ROD, 10.0));
            let (top, bottom) = (panel.px((0.0, 1.0)), panel.px((0.0, -1.0)));
            panel.obstacles.add_box(Rect::new(
                top.0 - 6.0,
                top.1 - 6.0,
                bottom.0 + 6.0,
                bottom.1 + 6.0,
            ));
            if !matches!(other, RodInertia::Uniform) {
                let r = (f(&scene.inertia()) / f(scene.rod_mass())).sqrt() / l;
                svg.open("gyration");
                for y in [-r, r] {
                    panel.line(svg, (-0.07, y), (0.07, y), &Stroke::solid("#f2c14e", 3.0));
                }
                svg.close();
                panel.label("±r_{G}", (0.07, r), ROD);
            }
        }
    }
    svg.close();
    panel.dot(svg, (0.0, 0.0), 5.0, "#000000");
    panel.label("centre G", (0.0, 0.0), "#000000");
    if let Some(p) = pivot_of(scene) {
        let y = f(p) / l;
        let c = panel.px((0.0, y));
        svg.open("pivot");
        svg.circle(
            c,
            10.0,
            Some("#ffffff"),
            Some(&Stroke::solid("#000000", 2.5)),
        );
        svg.line(
            (c.0 - 6.0, c.1 - 6.0),
            (c.0 + 6.0, c.1 + 6.0),
            &Stroke::solid("#000000", 2.0),
        );
        svg.line(
            (c.0 - 6.0, c.1 + 6.0),
            (c.0 + 6.0, c.1 - 6.0),
            &Stroke::solid("#000000", 2.0),
        );
        svg.close();
        panel.obstacles.add_box(Rect::around(c, 12.0));
        let text = format!(
            "fixed pivot, p = {}",
            multiple(&(p / scene.half_length()), "l")
        );
        panel.label(&text, (0.0, y), "#000000");
    }
}

/// The projectile's disc at `x` (units of l), level with the impact point, and its velocity
/// arrow of length `length` (units of l; none when zero).
fn draw_projectile(svg: &mut Svg, panel: &mut Panel, at: (f64, f64), length: f64, label: &str) {
    svg.open("projectile");
    panel.dot(svg, at, 10.0, PROJECTILE);
    if length.abs() > 1e-9 {
        let start = (at.0 + length.signum() * 0.06, at.1);
        panel.arrow(svg, start, (start.0 + length, at.1), PROJECTILE);
    }
    svg.close();
    panel.label(label, at, PROJECTILE);
}

fn header(svg: &mut Svg, width: f64, title: &str, lines: &[String]) {
    svg.open("title");
    svg.text(
        &Text::new(title, (width / 2.0, 30.0), TITLE)
            .anchor(Anchor::Middle)
            .bold(),
    );
    for (k, line) in lines.iter().enumerate() {
        svg.text(
            &Text::new(
                line.as_str(),
                (width / 2.0, 54.0 + 19.0 * k as f64),
                SUBTITLE,
            )
            .anchor(Anchor::Middle)
            .color("#555555"),
        );
    }
    svg.close();
}

/// The small x-y axes glyph at a panel's lower-left corner.
fn draw_axes_glyph(svg: &mut Svg, panel: &mut Panel) {
    let o = (panel.x.0 + 0.15, panel.y.0 + 0.15);
    svg.open("axes");
    for (tip, name) in [((o.0 + 0.35, o.1), "x"), ((o.0, o.1 + 0.35), "y")] {
        panel.arrow(svg, o, tip, "#000000");
        let p = panel.px(tip);
        svg.text(&Text::new(name, (p.0 + 4.0, p.1 - 4.0), LABEL));
    }
    svg.close();
}

/// The paper's missing Figure 1, to scale: the table seen from above, the rod of length 2l at
/// rest (a dumbbell with its end masses, a rod with given r_G with ±r_G marked, the pivot when
/// there is one), the projectile m moving at v0 towards the impact point at distance a.
///
/// # Errors
/// None for a valid scene (kept for the uniform signature of the figures).
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).pivot(q(-1, 2)).build().unwrap();
/// let svg = rodimpact::report::plot_figure1(&s).unwrap();
/// assert!(svg.contains("2l = 2") && svg.contains(r#"class="pivot""#));
/// ```
pub fn plot_figure1(scene: &Scene) -> Result<String, Error> {
    let (width, height) = (860.0, 720.0);
    let mut svg = Svg::new(width, height);
    header(
        &mut svg,
        width,
        "A projectile strikes a rod at rest on a smooth table (top view)",
        &[scene_line(scene)],
    );
    let mut panel = Panel::new((-2.4, 1.45), (-1.5, 1.5), (45.0, 80.0));
    draw_rod(&mut svg, &mut panel, scene);
    let l = f(scene.half_length());
    let a = f(scene.a()) / l;
    // The length 2l, dimensioned on the right.
    svg.open("dimensions");
    let dim = 0.8;
    panel.line(
        &mut svg,
        (dim, -1.0),
        (dim, 1.0),
        &Stroke::solid("#000000", 1.0),
    );
    for y in [-1.0, 1.0] {
        panel.line(
            &mut svg,
            (0.12, y),
            (dim + 0.08, y),
            &Stroke::solid("#000000", 1.0),
        );
    }
    let two_l = format!(
        "2l = {}",
        signed(&(scene.half_length() * Q::from_integer(2.into())))
    );
    panel.label(&two_l, (dim, 0.0), "#000000");
    // The impact distance a, dimensioned left of the rod.
    let ax = -0.3;
    if a != 0.0 {
        panel.line(&mut svg, (ax, 0.0), (ax, a), &Stroke::solid(IMPACT, 2.0));
        panel.line(
            &mut svg,
            (ax - 0.06, 0.0),
            (-0.02, 0.0),
            &Stroke::solid(IMPACT, 1.0),
        );
    }
    svg.close();
    panel.dot(&mut svg, (0.0, a), 5.5, IMPACT);
    let v0_length = 1.3;
    let start = -0.14 - v0_length - 0.06;
    draw_projectile(
        &mut svg,
        &mut panel,
        (start, a),
        v0_length,
        &format!(
            "m = {}, v_{{0}} = {}",
            signed(scene.m()),
            signed(scene.v0())
        ),
    );
    panel.label(&format!("a = {}", signed(scene.a())), (ax, a / 2.0), IMPACT);
    panel.label("impact point", (0.0, a), "#000000");
    let mass = format!("rod: M = {}", signed(scene.rod_mass()));
    panel.label(&mass, (0.0, 1.0), ROD);
    draw_axes_glyph(&mut svg, &mut panel);
    panel.place_labels(&mut svg);
    svg.finish()
}

/// The exact state just after the impact, and where the rod is momentarily at rest.
struct After {
    out: Outcome<Q>,
    /// y0 = -V/omega (the pivot itself for a pivoted rod); `None` when omega = 0.
    rest: Option<Q>,
}

fn after(scene: &Scene) -> Result<After, Error> {
    let out = outcome_at(scene, scene.a())?;
    let rest = (!out.after.omega.is_zero()).then(|| -(&out.after.rod_v / &out.after.omega));
    Ok(After { out, rest })
}

/// The velocities before and after the impact, side by side and to scale: the projectile's
/// velocity, the velocity V + omega y of the rod's points, and the instantaneous rest point
/// y0 = -r_G^2/a of the rod (the pivot itself when there is one).
///
/// # Errors
/// None for a valid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).a(q(1, 2)).build().unwrap();
/// let svg = rodimpact::report::velocity_figure(&s).unwrap();
/// assert!(svg.contains("y₀ = −r_{G}") || svg.contains("rest point"));
/// ```
pub fn velocity_figure(scene: &Scene) -> Result<String, Error> {
    let state = after(scene)?;
    let motion = &state.out.after;
    let (l, v0) = (f(scene.half_length()), f(scene.v0()));
    let a = f(scene.a()) / l;
    let (v, big_v, omega) = (f(&motion.v), f(&motion.rod_v), f(&motion.omega));
    let fastest = [
        v0,
        v.abs(),
        (big_v + omega * l).abs(),
        (big_v - omega * l).abs(),
    ]
    .into_iter()
    .fold(0.0, f64::max);
    // World length of an arrow per unit of velocity: the fastest arrow is 1.2 l long.
    let per = 1.2 / fastest;
    let (width, height) = (1220.0, 760.0);
    let mut svg = Svg::new(width, height);
    let value = |x: &Q, unit: &str| format!("{}{unit}", signed(x));
    header(
        &mut svg,
        width,
        "Velocities just before and just after the impact (top view, to scale)",
        &[
            scene_line(scene),
            format!(
                "m = {}, M = {}, l = {}, a = {}, v_{{0}} = {}: after, v = {}, V = {}, ω = {}",
                signed(scene.m()),
                signed(scene.rod_mass()),
                signed(scene.half_length()),
                signed(scene.a()),
                signed(scene.v0()),
                value(&motion.v, ""),
                value(&motion.rod_v, ""),
                value(&motion.omega, ""),
            ),
        ],
    );
    let y_range = (-1.55, 1.55);
    let mut before = Panel::new((-1.75, 1.1), y_range, (20.0, 110.0));
    let mut later = Panel::new((-1.75, 1.55), y_range, (20.0 + 2.85 * SCALE + 20.0, 110.0));
    for (panel, name) in [(&mut before, "just before"), (&mut later, "just after")] {
        draw_rod(&mut svg, panel, scene);
        let corner = panel.px((panel.x.0, panel.y.1));
        let title = Text::new(name, (corner.0 + 10.0, corner.1 + 24.0), LABEL + 2.0).bold();
        panel.obstacles.add_box(title.bounds());
        svg.text(&title);
        panel.dot(&mut svg, (0.0, a), 5.5, IMPACT);
    }
    let v0_length = v0 * per;
    draw_projectile(
        &mut svg,
        &mut before,
        (-0.14 - v0_length - 0.06, a),
        v0_length,
        &format!("v_{{0}} = {}", signed(scene.v0())),
    );
    before.label("rod at rest", (0.0, -1.0), ROD);
    draw_axes_glyph(&mut svg, &mut before);
    // After: the rod's velocity field, arrows every l/4 and the line through their tips.
    svg.open("rod-velocities");
    let mut tips = Vec::new();
    for k in -4..=4 {
        let y = f64::from(k) / 4.0;
        let u = (big_v + omega * y * l) * per;
        tips.push((u, y));
        if u.abs() * SCALE > 3.0 {
            later.arrow(&mut svg, (0.0, y), (u, y), VELOCITY);
        }
    }
    let (p, q) = (later.px(tips[0]), later.px(tips[8]));
    svg.line(p, q, &Stroke::dotted(VELOCITY, 1.5));
    later.obstacles.add_segment(p, q);
    svg.close();
    later.label("rod point at y: V + ω y", tips[8], VELOCITY);
    if big_v != 0.0 {
        later.label(
            &format!("V = {}", signed(&motion.rod_v)),
            (big_v * per, 0.0),
            VELOCITY,
        );
    }
    // The projectile, just separated: its arrow ends left of the rod.
    let v_length = v * per;
    let x = if v > 0.0 { -0.3 - v_length } else { -0.3 };
    let text = if motion.v.is_zero() {
        "v = 0: the projectile stops".to_string()
    } else {
        format!("v = {}", signed(&motion.v))
    };
    draw_projectile(&mut svg, &mut later, (x, a), v_length, &text);
    // The instantaneous rest point.
    match &state.rest {
        Some(rest) => {
            let y = f(rest) / l;
            let name = match pivot_of(scene) {
                Some(_) => "at rest: the pivot".to_string(),
                None => format!(
                    "instantaneous rest point y_{{0}} = −r_{{G}}^{{2}}/a = {}",
                    multiple(&(rest / scene.half_length()), "l")
                ),
            };
            if y.abs() <= 1.45 {
                svg.open("rest-point");
                if y.abs() > 1.0 {
                    let end = y.signum();
                    later.line(&mut svg, (0.0, end), (0.0, y), &Stroke::dashed(ROD, 2.0));
                }
                let c = later.px((0.0, y));
                svg.marker(Shape::Circle, c, 8.0, "#000000", false);
                svg.line(
                    (c.0 - 5.0, c.1 - 5.0),
                    (c.0 + 5.0, c.1 + 5.0),
                    &Stroke::solid("#000000", 2.0),
                );
                svg.line(
                    (c.0 - 5.0, c.1 + 5.0),
                    (c.0 + 5.0, c.1 - 5.0),
                    &Stroke::solid("#000000", 2.0),
                );
                later.obstacles.add_box(Rect::around(c, 10.0));
                svg.close();
                later.label(&name, (0.0, y), "#000000");
            } else {
                let edge = 1.45 * y.signum();
                later.label(
                    &format!("{name} (beyond this view)"),
                    (0.0, edge),
                    "#000000",
                );
            }
        }
        None => later.label(
            "ω = 0: the rod translates, no rest point",
            (0.0, -1.0),
            "#000000",
        ),
    }
    before.place_labels(&mut svg);
    later.place_labels(&mut svg);
    // The scale of the arrows.
    svg.text(
        &Text::new(
            format!(
                "Arrows to scale: v_{{0}} is drawn {:.2} l long. Every point of the rod moves along x; the dotted line joins the arrow tips.",
                v0_length
            ),
            (width / 2.0, height - 18.0),
            LABEL,
        )
        .anchor(Anchor::Middle)
        .color("#555555"),
    );
    svg.finish()
}
