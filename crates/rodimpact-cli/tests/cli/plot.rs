//! `rodimpact plot`: every figure honours the scene flags it accepts or refuses them (exit 2),
//! the figures carry what the review found missing (NEWCOMER.md #6, #16, #17, #19), and the
//! `--data` CSV holds the exact values at the sample points, checked here against independent
//! closed forms.

use rodimpact::field::Q;
use std::path::{Path, PathBuf};

use crate::common;
use common::rat;

/// `rodimpact ARGS`: (exit code, stderr).
fn rodimpact(args: &[&str]) -> (i32, String) {
    let (code, _, stderr) = common::rodimpact(args);
    (code, stderr)
}

struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Dir {
        let dir = crate::common::scratch(name);
        std::fs::create_dir_all(&dir).unwrap();
        Dir(dir)
    }
    fn path(&self, file: &str) -> PathBuf {
        self.0.join(file)
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs `plot FIGURE ARGS --out DIR/FIGURE.svg [--data DIR/FIGURE.csv]`; the SVG and CSV text.
fn plot(dir: &Dir, figure: &str, args: &[&str], data: bool) -> (String, Option<String>) {
    let svg = dir.path(&format!("{figure}.svg"));
    let csv = dir.path(&format!("{figure}.csv"));
    let mut all = vec!["plot", figure, "--out", svg.to_str().unwrap()];
    if data {
        all.extend(["--data", csv.to_str().unwrap()]);
    }
    all.extend(args);
    let (code, stderr) = rodimpact(&all);
    assert_eq!(code, 0, "plot {figure} {args:?}: {stderr}");
    let svg = std::fs::read_to_string(&svg).unwrap();
    let csv = data.then(|| std::fs::read_to_string(&csv).unwrap());
    (svg, csv)
}

/// The CSV as (header, rows).
fn table(csv: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

/// The exact value of `column` in the row where column `a` equals `a`.
fn at(csv: &str, a: &str, column: &str) -> Q {
    let (header, rows) = table(csv);
    let ia = header.iter().position(|h| h == "a").unwrap();
    let ic = header.iter().position(|h| h == column).unwrap();
    let row = rows
        .iter()
        .find(|r| rat(&r[ia]) == rat(a))
        .unwrap_or_else(|| panic!("no row a = {a}"));
    rat(&row[ic])
}

fn refused(args: &[&str], message: &str) {
    let (code, stderr) = rodimpact(args);
    assert_eq!(code, 2, "{args:?}");
    assert!(stderr.contains(message), "{args:?}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
}

/// NEWCOMER #6: `plot figure1 --pivot 1/2` drew no pivot and the dumbbell as a uniform bar.
#[test]
fn figure1_draws_the_pivot_and_the_dumbbell() {
    let dir = Dir::new("plot-fig1");
    let (svg, _) = plot(&dir, "figure1", &["--pivot", "-1/2", "--a", "1/2"], false);
    assert!(svg.contains(r#"<g class="pivot">"#));
    assert!(svg.contains("fixed pivot, p = −l/2"));
    assert!(svg.contains("on a fixed pivot at p = −l/2"));
    let (svg, _) = plot(&dir, "figure1", &["--rod", "dumbbell"], false);
    let masses = svg.split(r#"<g class="end-masses">"#).nth(1).unwrap();
    let masses = masses.split("</g>").next().unwrap();
    assert_eq!(masses.matches("<circle").count(), 2, "two end masses");
    assert!(svg.contains("dumbbell: all the mass at the two ends"));
    let (svg, _) = plot(&dir, "figure1", &[], false);
    assert!(!svg.contains(r#"class="pivot""#) && !svg.contains("end-masses"));
}

/// omega for a pivoted rod with e < 1: the sampled data is the fixed-axis formula
/// omega = (1 + e) m d v0/(I_p + m d^2), d = a - p, at every sample point.
#[test]
fn omega_for_a_pivoted_rod_and_partial_restitution_is_exact() {
    let dir = Dir::new("plot-omega-pivot");
    let flags = [
        "--m", "1", "--M", "2", "--pivot", "-1", "--e", "1/2", "--v0", "3",
    ];
    let (svg, csv) = plot(&dir, "omega", &flags, true);
    let csv = csv.unwrap();
    assert!(svg.contains("on a fixed pivot at p = −l, partly elastic (e = 1/2)"));
    assert!(!svg.contains("elastic (e = 1)"));
    let (m, big_m, p, e, v0) = (rat("1"), rat("2"), rat("-1"), rat("1/2"), rat("3"));
    let inertia_p = &big_m / rat("3") + &big_m * &p * &p;
    let (_, rows) = table(&csv);
    assert_eq!(rows.len(), 401, "a = -l..l in steps of l/200");
    for a in ["-1", "-1/2", "0", "1/4", "37/200", "1"] {
        let d = rat(a) - &p;
        let want = (rat("1") + &e) * &m * &d * &v0 / (&inertia_p + &m * &d * &d);
        assert_eq!(at(&csv, a, "omega"), want, "a = {a}");
    }
}

/// NEWCOMER #6: `plot omega --m 1 --M 1` was byte-identical to the default, and `--e 0` was
/// titled "elastic".
#[test]
fn omega_uses_the_scene_and_names_the_collision_law() {
    let dir = Dir::new("plot-omega-scene");
    let (default, _) = plot(&dir, "omega", &[], false);
    let (own, csv) = plot(&dir, "omega", &["--m", "1", "--M", "1", "--e", "0"], true);
    assert_ne!(default, own);
    assert!(own.contains("sticking, totally inelastic (e = 0)"));
    assert!(!own.contains("elastic (e = 1)"));
    assert!(own.contains("M/m = 1<") && !own.contains("M/m = 10<"));
    // Sticking halves the elastic spin: omega(l) = (1 + e) 3/5 = 3/5 for M = m, e = 0.
    let csv = csv.unwrap();
    assert_eq!(at(&csv, "1", "omega"), rat("3/5"));
    assert!(default.contains("elastic (e = 1)"));
}

/// NEWCOMER #17: integer pixel coordinates, no legend for the dashed continuation, ASCII
/// "omega_max", off-chart a* unmarked.
#[test]
fn omega_figure_quality() {
    let dir = Dir::new("plot-omega-quality");
    let (svg, _) = plot(&dir, "omega", &[], false);
    let curve = svg.split(r#"<g class="curve">"#).nth(1).unwrap();
    let points = curve.split("<polyline points=\"").nth(1).unwrap();
    let points = points.split('"').next().unwrap();
    assert!(
        points.split(' ').filter(|p| p.contains('.')).count() > 100,
        "sub-pixel coordinates"
    );
    assert!(svg.contains("off the rod, |a| &gt; l"));
    assert!(svg.contains(r#"ω l / v<tspan"#));
    assert!(svg.contains("fastest spin on the rod, ω<tspan"));
    assert!(!svg.contains("omega_max") && !svg.contains("omega(a)"));
    // M/m = 10: a* = sqrt(11/3) l = 1.91 l is beyond the 1.2 l of the chart: marked.
    assert!(svg.contains(r#"<g class="a-star-off-chart">"#));
    assert!(svg.contains("a* beyond this chart"));
}

/// NEWCOMER #16: `plot optimum --rod rg=1/10` clipped its threshold M = 99m, named the rod
/// "rg=1/10", and the log axis read "1.0, 10.0, 100.0" with 0.01 unlabelled.
#[test]
fn optimum_axes_adapt_to_the_threshold() {
    let dir = Dir::new("plot-optimum");
    let (svg, csv) = plot(&dir, "optimum", &["--rod", "rg=1/10"], true);
    assert!(svg.contains("r<tspan"), "r_G with a subscript");
    assert!(svg.contains("= l/10 (I = Ml"));
    assert!(!svg.contains("rg=1/10"));
    let label = svg
        .lines()
        .find(|l| l.contains("M = 99m: a* reaches the end"))
        .expect("the threshold labelled");
    let x: f64 = label
        .split("x=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        x > 0.0 && x + 200.0 < 1060.0,
        "label inside the figure: x = {x}"
    );
    for tick in ["0.01", "0.1", "1", "10", "100", "1000"] {
        assert!(svg.contains(&format!(">{tick}</text>")), "tick {tick}");
    }
    assert!(!svg.contains(">100.0<") && !svg.contains(">10.0<"));
    assert!(svg.contains(r#"<g class="best">"#), "min(a*, l) drawn");
    assert!(svg.contains("best point on the rod: min(a*, l)"));
    // Data: a* = r_G sqrt(1 + M/m) at every sampled ratio (17 correct digits).
    let (header, rows) = table(&csv.unwrap());
    let ia = header.iter().position(|h| h == "a_star_decimal").unwrap();
    assert_eq!(rows.len(), 501, "M/m = 10^-2 .. 10^3, 100 samples a decade");
    for row in rows.iter().step_by(37) {
        let ratio: f64 = row[1].parse().unwrap();
        let want = 0.1 * (1.0 + ratio).sqrt();
        let got: f64 = row[ia].parse().unwrap();
        assert!((got / want - 1.0).abs() < 1e-14, "{row:?}");
    }
}

#[test]
fn optimum_marks_the_given_scene() {
    let dir = Dir::new("plot-optimum-mark");
    let (svg, _) = plot(&dir, "optimum", &["--M", "3"], false);
    assert!(svg.contains("M/m = 3: a* = 1.15 l, beyond the end: strike the end"));
    let (plain, _) = plot(&dir, "optimum", &[], false);
    assert!(!plain.contains("this scene"));
}

/// NEWCOMER #19: `plot omega --out fig.png` wrote SVG text into fig.png; it now writes a PNG
/// (see `figures_as_png_twice_the_svg_size`), and another picture format is refused with
/// nothing written.
#[test]
fn another_picture_format_is_refused_and_nothing_written() {
    let dir = Dir::new("plot-jpg");
    let jpg = dir.path("fig.jpg");
    refused(
        &["plot", "omega", "--out", jpg.to_str().unwrap()],
        "out: the file name must end in .svg, got",
    );
    assert!(!Path::new(&jpg).exists());
}

/// Flags a figure cannot honour are refused with the figure's reason, before anything is
/// written.
#[test]
fn flags_a_figure_cannot_use_are_refused() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["plot", "optimum", "--e", "0", "--out", "x.svg"],
            "e: plot optimum: a* does not depend on the collision law",
        ),
        (
            &["plot", "optimum", "--inelastic", "--out", "x.svg"],
            "e: plot optimum",
        ),
        (
            &["plot", "optimum", "--v0", "2", "--out", "x.svg"],
            "v0: plot optimum: a* does not depend on v0",
        ),
        (
            &["plot", "omega", "--a", "1/2", "--out", "x.svg"],
            "a: plot omega varies the impact point itself",
        ),
        (
            &["plot", "energy", "--from-end", "0", "--out", "x.svg"],
            "from-end: plot energy varies the impact point",
        ),
        (
            &["plot", "figure1", "--ratios", "1,2", "--out", "x.svg"],
            "ratios: plot figure1 draws one scene",
        ),
        (
            &[
                "plot", "omega", "--M", "2", "--ratios", "1,2", "--out", "x.svg",
            ],
            "ratios: give either --M",
        ),
        (
            &["plot", "velocities", "--data", "v.csv", "--out", "x.svg"],
            "data: plot velocities draws one scene",
        ),
        (
            &["plot", "quantities", "--data", "v.txt", "--out", "x.svg"],
            "data: the file name must end in .csv",
        ),
    ];
    for (args, message) in cases {
        refused(args, message);
    }
    assert!(!Path::new(crate::ROOT).join("x.svg").exists());
}

/// Issue 16 item 5: v, V, omega, J and a·J along the rod, exact, against the paper's closed
/// forms (q = m/M + m a^2/I, D = 1 + q): v = (q - e)/D v0, V = (1 + e)(m/M)/D v0,
/// omega = (1 + e)(m a/I)/D v0, J = m (v0 - v), and a·J = I omega.
#[test]
fn quantities_data_are_the_closed_forms() {
    let dir = Dir::new("plot-quantities");
    let flags = [
        "--m", "2", "--M", "3", "--l", "2", "--v0", "5", "--e", "1/3", "--rod", "rg=1",
    ];
    let (svg, csv) = plot(&dir, "quantities", &flags, true);
    assert!(svg.contains("lever arm × impulse"));
    assert!(svg.contains(r#"<g class="a-star">"#));
    let csv = csv.unwrap();
    let (m, big_m, inertia, v0, e) = (rat("2"), rat("3"), rat("3"), rat("5"), rat("1/3"));
    for a in ["0", "1/100", "1/2", "1", "3/2", "2"] {
        let a_q = rat(a);
        let q = &m / &big_m + &m * &a_q * &a_q / &inertia;
        let d = rat("1") + &q;
        let v = (&q - &e) / &d * &v0;
        let omega = (rat("1") + &e) * (&m * &a_q / &inertia) / &d * &v0;
        assert_eq!(at(&csv, a, "v"), v, "v at a = {a}");
        assert_eq!(at(&csv, a, "V"), (rat("1") + &e) * (&m / &big_m) / &d * &v0);
        assert_eq!(at(&csv, a, "omega"), omega);
        assert_eq!(at(&csv, a, "J"), &m * (&v0 - &v));
        assert_eq!(at(&csv, a, "lever_times_J"), &inertia * &omega);
    }
}

/// The energy partition adds up to the energy before, exactly; for e = 1 nothing is lost, so the
/// figure has no loss band, legend entry or column (it showed an empty "lost" band before).
#[test]
fn energy_partition_adds_up() {
    let dir = Dir::new("plot-energy");
    for (e, lossless) in [("1", true), ("1/2", false)] {
        let (svg, csv) = plot(&dir, "energy", &["--m", "1", "--M", "2", "--e", e], true);
        assert_eq!(svg.contains("lost in the impact"), !lossless);
        let (header, rows) = table(&csv.unwrap());
        assert_eq!(
            header.contains(&"lost".to_string()),
            !lossless,
            "{header:?}"
        );
        let columns: &[usize] = if lossless { &[2, 4, 6] } else { &[2, 4, 6, 8] };
        for row in &rows {
            let parts: Q = columns.iter().map(|&i| rat(&row[i])).sum();
            assert_eq!(parts, rat("1/2"), "{row:?}");
            if !lossless {
                assert!(rat(&row[8]) > rat("0"), "{row:?}");
            }
        }
    }
}

/// Issue 16 item 5: the before/after diagram with the rest point y0 = -r_G^2/a.
#[test]
fn velocities_show_the_rest_point() {
    let dir = Dir::new("plot-velocities");
    // Uniform rod, l = 1, a = 1/2: y0 = -(1/3)/(1/2) = -2/3 l.
    let (svg, _) = plot(
        &dir,
        "velocities",
        &["--m", "1", "--M", "1", "--a", "1/2"],
        false,
    );
    assert!(svg.contains("/a = −2l/3"), "rest point");
    assert!(svg.contains(r#"<g class="rest-point">"#));
    assert!(svg.contains("v = 3/11") && svg.contains("V = 8/11"));
    let (svg, _) = plot(&dir, "velocities", &["--pivot", "-1/2"], false);
    assert!(svg.contains("at rest: the pivot"));
}

/// Whether `svg` holds a number printed from a float that is not finite.
fn holds_non_finite(svg: &str) -> bool {
    ["inf", "NaN"].iter().any(|token| {
        svg.match_indices(token).any(|(i, _)| {
            let before = svg[..i].chars().next_back();
            let after = svg[i + token.len()..].chars().next();
            !before.is_some_and(char::is_alphanumeric) && !after.is_some_and(char::is_alphanumeric)
        })
    })
}

/// Regression (G5): beyond the f64 range `plot` wrote `inf`/`NaN` coordinates into the SVG and
/// exited 0 (`plot optimum --M 1e400`: `<polygon points="inf,317.73 ...`; `plot velocities` on a
/// rod of 1e-10000: 13 lines with NaN). Now such a scene is refused, exit 2 and one line, with
/// nothing written (not the SVG, not the data); scenes that can be drawn are drawn finitely.
#[test]
fn no_figure_holds_inf_or_nan() {
    let dir = common::scratch("g5");
    let (svg, csv) = (dir.join("f.svg"), dir.join("f.csv"));
    let beyond: [&[&str]; 8] = [
        &["optimum", "--m", "1", "--M", "1e400"],
        &["optimum", "--M", "1e10000"],
        &["optimum", "--m", "1e-400", "--M", "1"],
        &["optimum", "--rod", "I=1e-10000"],
        &[
            "velocities",
            "--m",
            "1",
            "--M",
            "1",
            "--l",
            "1e-10000",
            "--a",
            "1e-10000",
        ],
        &[
            "figure1", "--m", "1", "--M", "1", "--l", "1e-10000", "--a", "1e-10000",
        ],
        &["omega", "--m", "1", "--M", "1", "--l", "1e-10000"],
        &["energy", "--l", "1e-400"],
    ];
    for args in beyond {
        let mut all = vec!["plot"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", svg.to_str().unwrap()]);
        if !["velocities", "figure1"].contains(&args[0]) {
            all.extend_from_slice(&["--data", csv.to_str().unwrap()]);
        }
        let (code, stderr) = rodimpact(&all);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        // Refused as beyond the f64 range, or first, before any sampling, as numbers too large
        // to sample exactly in seconds (G4).
        assert!(
            stderr.starts_with("error: scene: beyond what the figure can draw: ")
                || stderr.contains("more than 700 (limit for figures)"),
            "{args:?}: {stderr}"
        );
        assert!(
            !svg.exists() && !csv.exists(),
            "{args:?}: a file was written"
        );
    }
    let drawable: [&[&str]; 5] = [
        &[
            "velocities",
            "--m",
            "1",
            "--M",
            "1",
            "--l",
            "1e-300",
            "--a",
            "1e-300",
        ],
        &["figure1", "--m", "1e-400", "--M", "1"],
        &["velocities", "--m", "1e400", "--M", "1"],
        &["quantities", "--v0", "1e-400"],
        &["omega", "--m", "1e200", "--M", "1e200"],
    ];
    for args in drawable {
        let mut all = vec!["plot"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", svg.to_str().unwrap()]);
        let (code, stderr) = rodimpact(&all);
        assert_eq!(code, 0, "{args:?}: {stderr}");
        let text = std::fs::read_to_string(&svg).unwrap();
        assert!(!holds_non_finite(&text), "{args:?}");
        std::fs::remove_file(&svg).unwrap();
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// NEWCOMER capability 1: the figures as PNG, for slides, drawn in the program: a PNG twice
/// the SVG's size, the same bytes every time, written whole; another extension refused.
#[test]
fn figures_as_png_twice_the_svg_size() {
    let dir = Dir::new("plot-png");
    let (svg, _) = plot(&dir, "omega", &[], false);
    let size = |attr: &str| -> u32 {
        let at = svg.find(&format!("{attr}=\"")).unwrap() + attr.len() + 2;
        svg[at..at + svg[at..].find('"').unwrap()]
            .parse::<f64>()
            .unwrap() as u32
    };
    let (width, height) = (size("width"), size("height"));
    for name in ["a.png", "b.PNG"] {
        let path = dir.path(name);
        let (code, err) = rodimpact(&["plot", "omega", "--out", path.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
    }
    let png = std::fs::read(dir.path("a.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |at: usize| u32::from_be_bytes(png[at..at + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (2 * width, 2 * height), "the IHDR's size");
    assert!(
        png.len() > 100_000,
        "a drawn chart, not a blank page: {} bytes",
        png.len()
    );
    assert_eq!(
        std::fs::read(dir.path("b.PNG")).unwrap(),
        png,
        "deterministic"
    );
    refused(
        &["plot", "omega", "--out", "x.jpg"],
        "error: out: the file name must end in .svg, got 'x.jpg' (or .png, the figure as a picture)",
    );
    assert!(!png.starts_with(b"<svg"));
}
