//! What the web pages compute (`app::pages`, the functions their WebAssembly module
//! answers): the explore page's answer against `solve`'s for random scenes, its a* scenes
//! against the hand results, its motion against X19, its field errors; the tilted-rod page
//! against the independent oracle's fixtures, and its energy map.

use proptest::prelude::*;
use rodimpact::app::pages::{call, call_json, explore, explore_motion, tilted, tilted_map};
use rodimpact::field::{Q, QSqrt, q};
use rodimpact::report::solution_json;
use rodimpact::scene::SceneInput;
use rodimpact::solve::Answer;
use serde_json::{Value, json};

/// The explore page's request for a scene in its fields.
fn fields(ratio: &str, a: &str, e: &str, rod: &str, pivot: Option<&str>) -> Value {
    let gyration = rod.strip_prefix("rg=");
    json!({
        "ratio": ratio, "a": a, "e": e,
        "kind": if gyration.is_some() { "gyration" } else { rod },
        "rg": gyration.unwrap_or(""),
        "pivoted": pivot.is_some(), "pivot": pivot.unwrap_or(""),
    })
}

/// `solve --json`'s exact strings for the same scene (m = l = v0 = 1).
fn cli(ratio: &str, a: &str, e: &str, rod: &str, pivot: Option<&str>) -> Value {
    let scene = SceneInput {
        m: Some("1".into()),
        rod_mass: Some(ratio.into()),
        a: Some(a.into()),
        e: Some(e.into()),
        rod: Some(rod.into()),
        pivot: pivot.map(Into::into),
        ..Default::default()
    }
    .build()
    .expect("a valid scene");
    solution_json(&Answer::of(&scene), 6)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Every value the page's table shows is `solve`'s, exactly, on random rational scenes:
    /// free or pivoted, every rod kind, elastic to sticking.
    #[test]
    fn the_explore_page_answers_as_solve_does(
        ratio in (1u32..60, 1u32..12),
        a in (-12i32..=12, 1u32..=12),
        e in (0u32..=6, 6u32..=9),
        kind in 0usize..3,
        rg in 1u32..=10,
        pivot in proptest::option::of((-8i32..=8, 8u32..=8)),
    ) {
        let ratio = format!("{}/{}", ratio.0, ratio.1);
        let a = format!("{}/{}", a.0.clamp(-(a.1 as i32), a.1 as i32), a.1);
        let e = format!("{}/{}", e.0, e.1);
        let rod = match kind { 0 => "uniform".to_string(), 1 => "dumbbell".to_string(), _ => format!("rg={rg}/10") };
        let pivot = pivot.map(|(n, d)| format!("{n}/{d}"));
        let page = explore(&fields(&ratio, &a, &e, &rod, pivot.as_deref()));
        let solved = cli(&ratio, &a, &e, &rod, pivot.as_deref());
        let mut keys = vec![("v", &solved["v"]["exact"]), ("V", &solved["V"]["exact"]), ("omega", &solved["omega"]["exact"]),
            ("energy_lost", &solved["energy"]["lost"]["exact"]), ("a_star", &solved["a_star"]["exact"]),
            ("omega_max", &solved["omega_max"]["exact"])];
        if pivot.is_some() {
            keys.push(("pivot_impulse", &solved["pivot_impulse"]["exact"]));
        }
        for (key, exact) in keys {
            prop_assert_eq!(&page["values"][key]["text"], exact, "{} for {} {} {} {} {:?}", key, ratio, a, e, rod, pivot);
        }
    }
}

/// Struck at a* (M = m, elastic, free): v = V = 1/2 and omega = sqrt(6)/2 exactly, omega a* = 1
/// (X19), and the rod meets the puck again half a turn later, at t = pi a* = pi sqrt(6)/3.
#[test]
fn explore_at_a_star_is_x19() {
    let page = explore(&fields("1", "a*", "1", "uniform", None));
    let text = |key: &str| page["values"][key]["text"].as_str().unwrap().to_string();
    assert_eq!(
        [text("v"), text("V"), text("omega"), text("omega_lever")],
        ["1/2", "1/2", "sqrt(6)/2", "1"]
    );
    assert_eq!(
        (&page["at_a_star"], &page["inside"]),
        (&json!(true), &json!(true))
    );
    let second = page["motion"]["second"].as_f64().unwrap();
    let expected = std::f64::consts::PI * (2.0f64 / 3.0).sqrt();
    assert!(
        (second - expected).abs() < 1e-9,
        "{second} against {expected}"
    );
    // At that time the puck is where the rod's other arm is: its distance from the rod's line is 0.
    let states = explore_motion(
        &json!({"ratio": "1", "a": "a*", "e": "1", "kind": "uniform", "times": [second]}),
    );
    let s = &states["states"][0];
    let (ball, centre, phi) = (&s["ball"], &s["centre"], s["phi"].as_f64().unwrap());
    let dx = ball[0].as_f64().unwrap() - centre[0].as_f64().unwrap();
    let dy = ball[1].as_f64().unwrap() - centre[1].as_f64().unwrap();
    assert!((dx * phi.cos() + dy * phi.sin()).abs() < 1e-9);
}

/// On a pivot at p = -l (M = m, e = 1/3) struck at p + a*: the pivot's impulse is -2/3 +
/// sqrt(3)/3 (I_p = 4/3, a* = 2 sqrt(3)/3, J = 2/3); beyond the end a* is struck at the end,
/// with a note.
#[test]
fn explore_on_a_pivot_and_beyond_the_end() {
    let page = explore(&fields("1", "p+a*", "1/3", "uniform", Some("-1")));
    assert_eq!(page["values"]["pivot_impulse"]["text"], "-2/3 + sqrt(3)/3");
    assert_eq!(page["values"]["ratio_to_max"]["text"], "1");
    let heavy = explore(&fields("3", "a*", "1", "uniform", None));
    assert_eq!(heavy["scene"]["a"]["text"], "1");
    assert_eq!(
        heavy["note"],
        "a* = 2√3/3 ≈ 1.155 lies beyond the end of the rod: struck at the end, a/l = 1, where the spin is fastest on that side."
    );
    assert_eq!(heavy["values"]["omega"]["text"], "6/7");
    // The guess's share of the best spin: at the end of the M = m rod, 2 sqrt(6)/5.
    let guessed =
        explore(&json!({"ratio": "1", "a": "1/2", "e": "1", "kind": "uniform", "guess": "1"}));
    assert_eq!(guessed["guess"]["share"]["text"], "2*sqrt(6)/5");
}

/// A wrong field is named with the page's name for it and its reason; nothing else is answered.
#[test]
fn explore_names_each_wrong_field() {
    let wrong = explore(
        &json!({"ratio": "0", "a": "3/2", "e": "1.5", "kind": "gyration", "rg": "2", "pivoted": true, "pivot": "x"}),
    );
    assert_eq!(
        wrong,
        json!({"errors": {
            "ratio": "M/m: must be > 0",
            "e": "e: must lie in 0 ≤ e ≤ 1",
            "rg": "r_G/l: must lie in 0 < r_G/l ≤ 1",
            "pivot": "p/l: not a number: unexpected character 'x' at position 1 in \"x\"",
        }})
    );
    let off_rod = explore(&json!({"ratio": "1", "a": "3/2", "e": "1"}));
    assert_eq!(
        off_rod["errors"]["a"],
        "a/l: must lie on the rod, −1 ≤ a/l ≤ 1"
    );
    let long = explore(&json!({"ratio": "1".repeat(31), "a": "1", "e": "1"}));
    assert_eq!(long["errors"]["ratio"], "M/m: more than 30 digits");
    let free_p = explore(&json!({"ratio": "1", "a": "p+a*", "e": "1"}));
    assert_eq!(free_p["errors"]["a"], "a/l: 'p' only on a pivot");
}

/// The module's entry point: JSON in, JSON out, an unknown function or bad JSON an error.
#[test]
fn call_json_dispatches_by_name() {
    let answer: Value = serde_json::from_str(&call_json(
        r#"{"name": "number", "request": {"text": "1.5e-3"}}"#,
    ))
    .unwrap();
    assert_eq!(answer["value"]["text"], "3/2000");
    assert_eq!(
        call("number", &json!({"text": ""}))["error"]["field"],
        "number"
    );
    let bad: Value = serde_json::from_str(&call_json("not json")).unwrap();
    assert_eq!(bad["error"]["field"], "request");
}

/// An exact fixture number ("p/q", or {"x", "y", "d"} for x + y sqrt(d)) as rodimpact spells it.
fn spelled(v: &Value) -> String {
    let rational = |s: &Value| -> Q { s.as_str().unwrap().parse().unwrap() };
    match v {
        Value::String(_) => QSqrt::rational(rational(v)).to_string(),
        _ => QSqrt::new(rational(&v["x"]), rational(&v["y"]), rational(&v["d"])).to_string(),
    }
}

/// The tilted-rod page's two example scenes answer as the independent oracle's fixtures say:
/// every law's end, phases, contact velocity, rod after, works and energy.
#[test]
fn the_tilted_page_agrees_with_the_oracle() {
    for (file, mu, e) in [
        ("tilted-rod-rough-floor", "1/3", "1"),
        ("tilted-rod-sticks", "1/2", "1/2"),
    ] {
        let path = format!(
            "{}/tests/data/impacts/{file}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let fixture: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let page = tilted(&json!({"tan_half": "1/2", "slip": "1", "mu": mu, "e": e}));
        assert_eq!(page["lam_c"]["text"], spelled(&fixture["lam_c"]), "{file}");
        for (ours, theirs) in page["laws"]
            .as_array()
            .unwrap()
            .iter()
            .zip(fixture["laws"].as_array().unwrap())
        {
            assert_eq!(ours["law"], theirs["law"]);
            let text = |v: &Value| v["text"].as_str().unwrap().to_string();
            assert_eq!(
                text(&ours["lam"]),
                spelled(&theirs["impulse_coefficients"]["lam"]),
                "{file} {}",
                theirs["law"]
            );
            assert_eq!(
                text(&ours["tau"]),
                spelled(&theirs["impulse_coefficients"]["tau"])
            );
            assert_eq!(
                text(&ours["rod"]["vx"]),
                spelled(&theirs["bodies"]["rod"]["velocity"][0])
            );
            assert_eq!(
                text(&ours["rod"]["vy"]),
                spelled(&theirs["bodies"]["rod"]["velocity"][1])
            );
            assert_eq!(
                text(&ours["rod"]["omega"]),
                spelled(&theirs["bodies"]["rod"]["omega"])
            );
            assert_eq!(
                text(&ours["u_after"][0]),
                spelled(&theirs["contact_velocity"]["after"]["n"])
            );
            assert_eq!(
                text(&ours["u_after"][1]),
                spelled(&theirs["contact_velocity"]["after"]["t"])
            );
            assert_eq!(
                text(&ours["work"]["compression"]),
                spelled(&theirs["work"]["normal_compression"])
            );
            assert_eq!(
                text(&ours["work"]["restitution"]),
                spelled(&theirs["work"]["normal_restitution"])
            );
            assert_eq!(
                text(&ours["work"]["friction"]),
                spelled(&theirs["work"]["friction"])
            );
            assert_eq!(
                text(&ours["energy_change"]),
                spelled(&theirs["energy"]["change"])
            );
            assert_eq!(ours["energy_gain"], theirs["energy_gain"]);
            let phases: Vec<(String, String, String)> = ours["phases"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    (
                        p["mode"].as_str().unwrap().into(),
                        text(&p["from"]),
                        text(&p["to"]),
                    )
                })
                .collect();
            let expected: Vec<(String, String, String)> = theirs["phases"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    (
                        p["mode"].as_str().unwrap().into(),
                        spelled(&p["from"]),
                        spelled(&p["to"]),
                    )
                })
                .collect();
            assert_eq!(phases, expected);
        }
    }
}

/// Routh's path of the default scene: the slip stops at lam = 75/181 (u_t = 0) and reverses; the
/// path runs to the last law's end, Newton's 725/724, where u_n = 1 = -e u_n before.
#[test]
fn the_tilted_path_breaks_where_the_slip_stops() {
    let page = tilted(&json!({"tan_half": "1/2", "slip": "1", "mu": "1/3", "e": "1"}));
    let at = |i: usize, key: &str| page["path"][i][key]["text"].as_str().unwrap().to_string();
    assert_eq!(
        [at(0, "lam"), at(1, "lam"), at(2, "lam")],
        ["0", "75/181", "725/724"]
    );
    assert_eq!(
        [at(0, "u_n"), at(0, "u_t"), at(1, "u_t"), at(2, "u_n")],
        ["-1", "-1", "0", "1"]
    );
    assert_eq!(page["scene"]["mu_stick"]["text"], "36/73");
    assert_eq!(
        (&page["scene"]["cos"]["text"], &page["scene"]["sin"]["text"]),
        (&json!("3/5"), &json!("4/5"))
    );
    assert_eq!(page["laws"][0]["energy_percent"]["text"], "4928125/2358792");
    assert_eq!(
        tilted(&json!({"tan_half": "1", "slip": "1", "mu": "0", "e": "1"}))["error"]["field"],
        "tan_half"
    );
}

/// The energy map at the page's defaults (mu = 1/3, e = 1) over its grid (tan(theta/2) = k/40,
/// 21 slips from -2 to 2): each cell is the tilted scene's own decision, Newton's law gains
/// energy in 117 of the 819 scenes, and Stronge's energetic law, which never creates energy,
/// in none.
#[test]
fn the_energy_map_marks_where_newton_gains() {
    let tan_halves: Vec<String> = (1..=39).map(|k| format!("{k}/40")).collect();
    let slips: Vec<String> = (-10..=10).map(|i| q(i, 5).to_string()).collect();
    let map = tilted_map(&json!({"mu": "1/3", "e": "1", "tan_halves": tan_halves, "slips": slips}));
    let count = |law: &str| {
        map[law]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|row| row.as_array().unwrap())
            .filter(|c| **c == json!(true))
            .count()
    };
    assert_eq!((count("newton"), count("energetic")), (117, 0));
    // Spot checks against the scene's own answer.
    for (row, column) in [(15, 19), (0, 0), (20, 38), (10, 5)] {
        let scene = tilted(
            &json!({"tan_half": tan_halves[column], "slip": slips[row], "mu": "1/3", "e": "1"}),
        );
        for (i, law) in ["newton", "poisson", "energetic"].into_iter().enumerate() {
            assert_eq!(
                map[law][row][column], scene["laws"][i]["energy_gain"],
                "{law} at {row},{column}"
            );
        }
    }
    let too_big = tilted_map(
        &json!({"mu": "0", "e": "1", "tan_halves": vec!["1/2"; 41], "slips": vec!["1"; 40]}),
    );
    assert_eq!(
        too_big["error"]["message"],
        "the map takes at most 1600 scenes, got 40 x 41"
    );
}

/// The oblique tab answers as `solve --v0t --mu` does: sliding at mu = 1/4 (mu* = 11/16),
/// sticking at mu = 1, and with a spinning disc; omega is the frictionless one every time (the
/// friction impulse acts along the rod's axis).
#[test]
fn the_oblique_tab_answers_as_solve_does() {
    use rodimpact::app::pages::oblique;
    let slide = oblique(
        &json!({"ratio": "1", "a": "1/2", "e": "1", "kind": "uniform", "v0t": "1", "mu": "1/4"}),
    );
    let text =
        |answer: &Value, key: &str| answer["values"][key]["text"].as_str().unwrap().to_string();
    assert_eq!(
        [
            "v",
            "V",
            "omega",
            "vt",
            "Vt",
            "Jt",
            "mu_star",
            "energy_lost",
            "lost_friction"
        ]
        .map(|k| text(&slide, k)),
        [
            "3/11", "8/11", "12/11", "9/11", "2/11", "2/11", "11/16", "18/121", "18/121"
        ]
    );
    assert_eq!(
        (&slide["contact"], &slide["same_spin"]),
        (&json!("slide"), &json!(true))
    );
    let stick = oblique(
        &json!({"ratio": "1", "a": "1/2", "e": "1", "kind": "uniform", "v0t": "1", "mu": "1"}),
    );
    assert_eq!(
        ["vt", "Vt", "Jt"].map(|k| text(&stick, k)),
        ["1/2", "1/2", "1/2"]
    );
    assert_eq!(stick["contact"], "stick");
    // M = 2m, a = l/3, e = 1/2, v0t = -1/2, mu = 1/5, a disc of radius l/10 spinning at 3 v0/l.
    let disc = oblique(
        &json!({"ratio": "2", "a": "1/3", "e": "1/2", "kind": "uniform", "v0t": "-1/2",
        "mu": "1/5", "radius": "1/10", "spin": "3"}),
    );
    assert_eq!(
        ["v", "V", "omega", "vt", "Vt", "spin_after", "Jt", "mu_star"].map(|k| text(&disc, k)),
        [
            "1/10", "9/20", "9/20", "-31/70", "-1/35", "29/7", "-2/35", "4/63"
        ]
    );
    assert_eq!(
        (&disc["contact"], &disc["same_spin"]),
        (&json!("stick"), &json!(true))
    );
    // The loss curve: no loss to friction at mu = 0; from mu* on, the sticking loss.
    let curve = &slide["loss_curve"];
    let friction = curve["friction"].as_array().unwrap();
    assert_eq!((friction.len(), friction[0].as_f64()), (101, Some(0.0)));
    assert_eq!(curve["mu_max"], 1.1);
    let stuck_share = friction[100].as_f64().unwrap();
    assert!(
        friction[70..]
            .iter()
            .all(|f| f.as_f64() == Some(stuck_share)),
        "constant once it sticks"
    );
    // Errors by field, the disc's too; a spin without a disc is not a field the tab sends.
    let wrong = oblique(
        &json!({"ratio": "1", "a": "1/2", "e": "1", "v0t": "x", "mu": "-1", "radius": "0"}),
    );
    assert_eq!(wrong["errors"]["mu"], "μ: must be ≥ 0");
    assert_eq!(wrong["errors"]["radius"], "r/l: must be > 0");
    assert!(
        wrong["errors"]["v0t"]
            .as_str()
            .unwrap()
            .starts_with("v0t: not a number")
    );
}
