//! Units wherever numbers are (NEWCOMER #20): `check` accepted `100 g` but `solve`, `plot`,
//! `simulate` and `batch` refused it ("m: not a number: unexpected character 'g'"), so a
//! teacher copying a problem was surprised. Every scene number is now read by one parser
//! (`SceneInput::build`) that converts a unit exactly to SI; each test compares a run with
//! units against the same run in plain SI numbers.

use crate::common;

use common::rodimpact;
use serde_json::Value;

fn ok(args: &[&str]) -> String {
    let (code, out, err) = rodimpact(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

/// 100 g = 0.1 kg, 1.5 kg, 120 cm = 2 x 0.6 m, 10 cm from the end = a 0.5 m, 36 km/h = 10 m/s.
const WITH_UNITS: [&str; 10] = [
    "--m",
    "100 g",
    "--M",
    "1.5kg",
    "--length",
    "120cm",
    "--from-end",
    "10 cm",
    "--v0",
    "36 km/h",
];
const IN_SI: [&str; 10] = [
    "--m", "0.1", "--M", "1.5", "--l", "0.6", "--a", "0.5", "--v0", "10",
];

fn with(base: &[&str], flags: &[&str]) -> Vec<String> {
    base.iter().chain(flags).map(|s| s.to_string()).collect()
}

fn run(args: &[String]) -> String {
    ok(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

#[test]
fn solve_reads_units_exactly() {
    let units: Value =
        serde_json::from_str(&run(&with(&["solve", "--json"], &WITH_UNITS))).unwrap();
    let si: Value = serde_json::from_str(&run(&with(&["solve", "--json"], &IN_SI))).unwrap();
    assert_eq!(units, si);
    assert_eq!(units["scene"]["m"], "1/10");
    assert_eq!(units["scene"]["l"], "3/5");
    assert_eq!(units["scene"]["a"], "1/2");
    assert_eq!(units["scene"]["v0"], "10");
    // The rod's radius of gyration takes a length unit: 30 cm = 3/10 m.
    let rg: Value = serde_json::from_str(&ok(&[
        "solve", "--json", "--m", "1", "--M", "1", "--rod", "rg=30 cm",
    ]))
    .unwrap();
    assert_eq!(rg["scene"]["rod"], "rg=3/10");
}

#[test]
fn plot_and_simulate_read_units_exactly() {
    let dir = crate::common::scratch("units");
    std::fs::create_dir_all(&dir).unwrap();
    let (a, b) = (dir.join("units.svg"), dir.join("si.svg"));
    run(&with(
        &["plot", "figure1", "--out", a.to_str().unwrap()],
        &WITH_UNITS,
    ));
    run(&with(
        &["plot", "figure1", "--out", b.to_str().unwrap()],
        &IN_SI,
    ));
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    std::fs::remove_dir_all(&dir).unwrap();
    let sim = |base: &[&str]| -> Value {
        let args = with(&["simulate", "--json", "--stiffness", "1e8"], base);
        serde_json::from_str(&run(&args)).unwrap()
    };
    assert_eq!(sim(&WITH_UNITS)["exact"], sim(&IN_SI)["exact"]);
}

#[test]
fn batch_cells_read_units_exactly() {
    let dir = crate::common::scratch("units-batch");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("units.csv");
    // I = M l^2/3 = 0.18; 1/M_eff = 1/M + a^2/I = 37/18; J = 2 m M_eff v0/(m + M_eff) =
    // 360/217; v = v0 - J/m = -1430/217, V = J/M = 240/217, omega = J a/I = 1000/217.
    std::fs::write(
        &file,
        "m,M,l,a,v0,omega\n100 g,1.5kg,60cm,50 cm,36 km/h,1000/217 rad/s\n0.1,1.5,0.6,0.5,10,1000/217\n",
    )
    .unwrap();
    let out = ok(&["batch", file.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    let rows: Vec<&str> = out.lines().skip(1).collect();
    let tail = |row: &str| row.split(',').skip(6).collect::<Vec<_>>().join(",");
    assert_eq!(tail(rows[0]), tail(rows[1]), "{out}");
    assert!(
        tail(rows[0]).starts_with("-1430/217,240/217,1000/217,true,true,"),
        "{out}"
    );
}

#[test]
fn a_wrong_unit_is_named_on_one_line() {
    for (args, expected) in [
        (
            &["solve", "--m", "2 m/s", "--M", "1"][..],
            "error: m: unit 'm/s' is a speed, expected a mass\n",
        ),
        (
            &["solve", "--m", "3 oz", "--M", "1"][..],
            "error: m: unknown unit 'oz' (a mass takes kg, lb, g)\n",
        ),
        // Written against the number, an unknown unit is named the same way (NEWCOMER m14:
        // it was "not a number: unexpected character 'o'").
        (
            &["solve", "--m", "3oz", "--M", "1"][..],
            "error: m: unknown unit 'oz' (a mass takes kg, lb, g)\n",
        ),
        (
            &[
                "plot", "figure1", "--m", "1", "--M", "1", "--e", "1 J", "--out", "x.svg",
            ][..],
            "error: e: unit 'J' is an energy, expected a pure number\n",
        ),
    ] {
        let (code, out, err) = rodimpact(args);
        assert_eq!(
            (code, out.as_str(), err.as_str()),
            (2, "", expected),
            "{args:?}"
        );
    }
}

/// `solve`'s text report carries the units (it printed bare numbers while `check` said "SI").
#[test]
fn solve_text_prints_si_units() {
    let out = run(&with(&["solve"], &WITH_UNITS));
    for needle in [
        "  m = 1/10 kg, M = 3/2 kg, l = 3/5 m (rod length 6/5 m), a = 1/2 m, v0 = 10 m/s\n",
        "(SI units; a number given without a unit is read in SI)",
        "-1430/217 m/s",
        "1000/217 rad/s",
        "360/217 N s",
        "N s",
        " J ",
        "m^2",
    ] {
        assert!(out.contains(needle), "{needle:?} in\n{out}");
    }
}

/// NEWCOMER m14: the common textbook units, exact by definition: 1 lb = 0.45359237 kg,
/// 1 ft = 0.3048 m, 1 mph = 0.44704 m/s, 1 kJ = 1000 J; angular speeds in deg/s (pi/180
/// rad/s), rev/s (2 pi) and 1/s, decided in claims with exact bounds on pi.
#[test]
fn textbook_units_are_read_exactly() {
    let (code, out, err) = rodimpact(&[
        "solve", "--m", "2lb", "--M", "1 kg", "--length", "6 ft", "--v0", "10 mph", "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["scene"]["m"], "45359237/50000000");
    assert_eq!(j["scene"]["l"], "1143/1250");
    assert_eq!(j["scene"]["v0"], "2794/625");
    // m = M = l = v0 = 1, a = 1/2: omega = 12/11 rad/s = 62.50... deg/s = 0.17362... rev/s.
    let (code, out, _) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "1/2",
        "--claim",
        "omega=62.5 deg/s",
        "--claim",
        "omega=0.174 rev/s",
        "--claim",
        "omega=1.09 1/s",
        "--claim",
        "energy_lost=0 kJ",
    ]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("note: deg/s = pi/180 rad/s: decided with exact rational bounds on pi"),
        "{out}"
    );
    assert!(
        out.contains("note: rev/s = 2 pi rad/s: decided with exact rational bounds on pi"),
        "{out}"
    );
    assert!(out.ends_with("4 of 4 claims agree\n"), "{out}");
    let (code, _, err) = rodimpact(&[
        "solve", "--m", "1", "--M", "1", "--v0t", "1", "--mu", "1", "--radius", "1/10", "--spin",
        "10 rpm",
    ]);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: spin: rpm is not a rational multiple of rad/s: give it in rad/s\n"
    );
}
