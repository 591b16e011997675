//! `rodimpact impact` as users run it: the three laws side by side, Newton's energy gain said
//! plainly, JSON with exact values, published answers decided, and every bad input refused with
//! one line naming its field (exit 2).

use crate::common::{rodimpact, scratch};
use serde_json::Value;

const GAIN: &str = "examples/impacts/newton-gains-energy.toml";
/// The same scene by name, for the batch lines.
const GAIN_NAME: &str = "newton-gains-energy";

#[test]
fn newtons_gain_is_said_plainly_and_the_others_lose() {
    let (code, text, stderr) = rodimpact(&["impact", GAIN]);
    assert_eq!(code, 0, "{stderr}");
    // Only Newton's section says it creates energy; the summary gives the exact gain.
    assert_eq!(text.matches("THIS LAW CREATES ENERGY").count(), 1, "{text}");
    assert!(
        text.contains("energy: 1 -> 11/10 = 1.1 J, change 1/10 = 0.1 J: THIS LAW CREATES ENERGY")
    );
    assert!(text.contains("energy: 1 -> 121/146 ≈ 0.828767 J, change -25/146 ≈ -0.171233 J\n"));
    assert!(text.contains("change -25/218 ≈ -0.114679 J\n"));
    assert!(text.contains("Newton's law gains 1/10 = 0.1 J (10.0 % of the energy before)"));
    assert!(text.contains("W = [52/25, 36/25; 36/25, 73/25]: coupled"));
}

#[test]
fn json_holds_every_law_exactly() {
    let (code, out, stderr) = rodimpact(&["impact", GAIN, "--format", "json"]);
    assert_eq!(code, 0, "{stderr}");
    let j: Value = serde_json::from_str(&out).unwrap();
    let laws = j["laws"].as_array().unwrap();
    let names: Vec<&str> = laws.iter().map(|l| l["law"].as_str().unwrap()).collect();
    assert_eq!(names, ["newton", "poisson", "energetic"]);
    let gains: Vec<bool> = laws
        .iter()
        .map(|l| l["energy_gain"].as_bool().unwrap())
        .collect();
    assert_eq!(gains, [true, false, false]);
    // The oracle's witness, by hand: the rod leaves with v = (6/5, 1/10), omega = -3/2.
    let rod = &laws[0]["bodies"]["rod"];
    assert_eq!(rod["velocity"][0]["exact"], "6/5");
    assert_eq!(rod["velocity"][1]["exact"], "1/10");
    assert_eq!(rod["omega"]["exact"], "-3/2");
    assert_eq!(laws[0]["energy"]["change"]["exact"], "1/10");
    assert_eq!(laws[0]["phases"][1]["mode"], "stick");
    assert_eq!(laws[0]["contact_velocity"]["after"][1]["exact"], "1");
    assert_eq!(j["scene"]["contact_matrix"]["coupled"], true);
    // The energetic law's answer is a surd in the canonical form, with 30 digits.
    let lam = laws[2]["impulse_coefficients"]["normal"]["exact"]
        .as_str()
        .unwrap();
    assert_eq!(lam, "37/100 + sqrt(26075089)/10900");
    assert!(
        laws[2]["impulse_coefficients"]["normal"]["decimal"]
            .as_str()
            .unwrap()
            .len()
            >= 31
    );
    for law in laws {
        assert!(
            law["laws_hold"]
                .as_object()
                .unwrap()
                .values()
                .all(|v| v != false),
            "{law}"
        );
    }
}

#[test]
fn one_law_alone() {
    let (code, text, _) = rodimpact(&["impact", GAIN, "--law", "energetic"]);
    assert_eq!(code, 0);
    assert!(text.contains("Stronge (energetic") && !text.contains("Newton (kinematic"));
    assert!(text.contains("No law creates energy in this impact."));
}

#[test]
fn published_answers_are_decided() {
    for (file, code, summary) in [
        ("tutorbin-bar-wall", 0, "2 of 2 claims agree"),
        ("bj-crate-corner", 0, "2 of 2 claims agree"),
        ("jee-disk-hurdle", 0, "1 claim, it agrees"),
        ("fenggao-sliding-cube", 1, "1 claim, it disagrees"),
        ("assignmentexpert-disc-step", 1, "1 claim, it disagrees"),
        (
            "byjus-rod-37deg-floor",
            1,
            "0 of 2 claims agree; 2 disagree",
        ),
    ] {
        let path = format!("examples/impacts/published/{file}.toml");
        let (got, text, stderr) = rodimpact(&["impact", &path]);
        assert_eq!(got, code, "{file}: {stderr}");
        assert!(text.contains(summary), "{file}:\n{text}");
    }
}

/// A valid scene; each bad input below is one edit of it.
const BASE: &str = r#"
[[body]]
name = "rod"
mass = "1"
shape = "rod"
length = "2"
axis = ["3", "4"]
position = ["0", "4/5"]
velocity = ["1", "-1"]

[[body]]
name = "floor"
fixed = true

[[contact]]
bodies = ["rod", "floor"]
point = ["-3/5", "0"]
normal = ["0", "1"]
e = "1"
mu = "1/3"
"#;

#[test]
fn bad_inputs_are_refused_naming_the_field() {
    let dir = scratch("impact-bad");
    let cases: [(&str, &str, &str, &str); 17] = [
        (
            "no approach",
            r#"velocity = ["1", "-1"]"#,
            r#"velocity = ["1", "1"]"#,
            "contact[1]: no approach",
        ),
        (
            "zero normal",
            r#"normal = ["0", "1"]"#,
            r#"normal = ["0", "0"]"#,
            "contact[1].normal: the normal is zero",
        ),
        (
            "point off the rod",
            r#"point = ["-3/5", "0"]"#,
            r#"point = ["-1/2", "0"]"#,
            "contact[1].point: (-1/2, 0) is not on the boundary of the shape of body 'rod'",
        ),
        (
            "negative mass",
            r#"mass = "1""#,
            r#"mass = "-1""#,
            "body[1].mass: must be > 0, got -1",
        ),
        (
            "negative mu",
            r#"mu = "1/3""#,
            r#"mu = "-1/3""#,
            "contact[1].mu: friction coefficient must be >= 0",
        ),
        (
            "e above 1",
            r#"e = "1""#,
            r#"e = "3/2""#,
            "contact[1].e: coefficient of restitution must lie in [0, 1]",
        ),
        (
            "unknown body",
            r#"bodies = ["rod", "floor"]"#,
            r#"bodies = ["rod", "ground"]"#,
            "contact[1].bodies: no body is named 'ground'",
        ),
        (
            "duplicate name",
            r#"name = "floor""#,
            r#"name = "rod""#,
            "body[2].name: 'rod' names two bodies",
        ),
        (
            "float literal",
            r#"mass = "1""#,
            "mass = 1.5",
            "body[1].mass: a floating-point literal is not read exactly",
        ),
        (
            "unknown key",
            r#"mu = "1/3""#,
            "mu = \"1/3\"\nfriction = \"1\"",
            "contact[1].friction: unknown key",
        ),
        (
            "wrong unit",
            r#"mass = "1""#,
            r#"mass = "1 m/s""#,
            "body[1].mass",
        ),
        (
            "both fixed",
            r#"name = "rod""#,
            "name = \"rod\"\nfixed = true",
            "body[1].mass: a fixed body never moves",
        ),
        (
            "a contact on one body",
            r#"bodies = ["rod", "floor"]"#,
            r#"bodies = ["rod", "rod"]"#,
            "contact[1].bodies: a contact joins two bodies",
        ),
        (
            "no bodies",
            "[[body]]\nname = \"rod\"",
            "[[bogus]]\nname = \"rod\"",
            "unknown key",
        ),
        (
            "bad shape",
            r#"shape = "rod""#,
            r#"shape = "sphere""#,
            "body[1].shape: expected point, disc, rod, box or polygon, got 'sphere'",
        ),
        (
            "a dimension the shape lacks",
            r#"length = "2""#,
            "length = \"2\"\nradius = \"1\"",
            "body[1].radius: a rod has no radius",
        ),
        ("syntax", r#"mu = "1/3""#, "mu = ", "line 20"),
    ];
    for (what, from, to, expected) in cases {
        assert!(BASE.contains(from), "{what}: the base has no {from}");
        let path = dir.join("scene.toml");
        std::fs::write(&path, BASE.replacen(from, to, 1)).unwrap();
        let (code, stdout, stderr) = rodimpact(&["impact", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{what}: {stdout}{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{what}: {stderr}");
        assert!(stderr.contains(expected), "{what}: {stderr}");
        assert!(stdout.is_empty(), "{what}: nothing is printed: {stdout}");
    }
    // The base itself is fine, and a file too large is refused before it is read.
    std::fs::write(dir.join("ok.toml"), BASE).unwrap();
    assert_eq!(
        rodimpact(&["impact", dir.join("ok.toml").to_str().unwrap()]).0,
        0
    );
    let big = format!("{BASE}\n# {}\n", "x".repeat(1 << 20));
    std::fs::write(dir.join("big.toml"), big).unwrap();
    let (code, _, stderr) = rodimpact(&["impact", dir.join("big.toml").to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("larger than 1048576 bytes (limit)"),
        "{stderr}"
    );
    // Too many contacts: 65, or 5 with friction (6^5 modes a phase), refused by count.
    let contact = &BASE[BASE.find("[[contact]]").unwrap()..];
    for (copies, expected) in [
        (65, "contact: more than 64 contacts (limit)"),
        (
            5,
            "contact: 5 contacts with friction: at most 4 when any has mu > 0 (limit)",
        ),
    ] {
        let path = dir.join("many.toml");
        std::fs::write(&path, format!("{BASE}{}", contact.repeat(copies - 1))).unwrap();
        let (code, stdout, stderr) = rodimpact(&["impact", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{copies}: {stdout}{stderr}");
        assert!(stderr.contains(expected), "{copies}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A normal given the wrong way round (the engineer's likeliest sign slip, NEWCOMER m3) is
/// named as a possibility beside "no approach".
#[test]
fn a_normal_the_wrong_way_round_is_named() {
    let dir = scratch("impact-wrong-way");
    let path = dir.join("scene.toml");
    assert!(BASE.contains(r#"normal = ["0", "1"]"#));
    std::fs::write(
        &path,
        BASE.replacen(r#"normal = ["0", "1"]"#, r#"normal = ["0", "-1"]"#, 1),
    )
    .unwrap();
    let path = path.to_str().unwrap();
    let (code, out, err) = rodimpact(&["impact", path]);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.starts_with(&format!("error: {path}: contact[1]: no approach: "))
            && err.ends_with(", not < 0; if the bodies do approach, the normal points the wrong way: it must point from the second body into the first\n"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `impact --batch`: each line a scene and an engine's claimed bodies, audited exactly: which
/// law or model the claim matches, the closest, and a diagnosis; exit 1 when one matches none.
#[test]
fn batch_audits_engine_claims() {
    let dir = scratch("impact-batch");
    let scene = |file: &str| -> serde_json::Map<String, Value> {
        let text = std::fs::read_to_string(format!("{}/examples/impacts/{file}.toml", crate::ROOT))
            .unwrap();
        let table: toml::Table = toml::from_str(&text).unwrap();
        serde_json::to_value(table)
            .unwrap()
            .as_object()
            .unwrap()
            .clone()
    };
    let line = |file: &str, id: &str, claimed: Value| {
        let mut s = scene(file);
        s.insert("id".into(), Value::String(id.into()));
        if !claimed.is_null() {
            s.insert("claimed".into(), claimed);
        }
        serde_json::to_string(&s).unwrap()
    };
    let rod = |vx: &str, vy: &str, w: &str| serde_json::json!({"engine": "test 1.0", "bodies": {"rod": {"velocity": [vx, vy], "omega": w}}});
    let lines = [
        line(GAIN_NAME, "newton-exact", rod("1.2", "0.1", "-1.5")),
        line(
            GAIN_NAME,
            "poisson-exact",
            rod("1866/1825", "-13/50", "-933/730"),
        ),
        line(GAIN_NAME, "no-contact", rod("1", "-1", "0")),
        line(GAIN_NAME, "nan", rod("nan", "0", "0")),
        line(
            "cradle-3",
            "cradle-one-sweep",
            serde_json::json!({"bodies": {
            "ball1": {"velocity": ["0", "0"], "omega": "0"},
            "ball2": {"velocity": ["0.5", "0"], "omega": "0"},
            "ball3": {"velocity": ["0.5", "0"], "omega": "0"}}}),
        ),
        line("box-corner", "unclaimed", Value::Null),
    ];
    let path = dir.join("log.jsonl");
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    let (code, out, err) = rodimpact(&["impact", "--batch", path.to_str().unwrap()]);
    assert_eq!(code, 1, "{err}");
    let rows: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(rows.len(), 6);
    assert_eq!(rows[0]["matches"], serde_json::json!(["newton"]));
    assert_eq!(rows[0]["diagnosis"], "ok");
    assert_eq!(rows[1]["matches"], serde_json::json!(["poisson"]));
    assert_eq!(rows[2]["diagnosis"], "no-contact");
    assert_eq!(rows[3]["diagnosis"], "off");
    assert_eq!(rows[4]["matches"], serde_json::json!(["pgs:1"]));
    assert_eq!(
        rows[4]["exact"]["simultaneous-newton"]["ball1"]["velocity"][0],
        "-1/3"
    );
    assert!(rows[5].get("diagnosis").is_none());
    assert!(err.contains("6 scenes, 5 with a claimed state"), "{err}");
    assert!(err.contains("no-contact: 1 (no-contact)"), "{err}");
    // Bad input names the line.
    std::fs::write(&path, "{\"body\": []}\n").unwrap();
    let (code, _, err) = rodimpact(&["impact", "--batch", path.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 1: body"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A misspelt key or body name gets a "did you mean" (NEWCOMER m7).
#[test]
fn a_misspelt_key_or_body_gets_a_suggestion() {
    let dir = scratch("impact-did-you-mean");
    for (from, to, expected) in [
        (
            r#"velocity = ["1", "-1"]"#,
            r#"velocty = ["1", "-1"]"#,
            "body[1].velocty: unknown key: did you mean 'velocity'? (expected one of ",
        ),
        (
            r#"bodies = ["rod", "floor"]"#,
            r#"bodies = ["rod", "flor"]"#,
            "contact[1].bodies: no body is named 'flor'; did you mean 'floor'?\n",
        ),
    ] {
        assert!(BASE.contains(from), "{from}");
        let path = dir.join("scene.toml");
        std::fs::write(&path, BASE.replacen(from, to, 1)).unwrap();
        let (code, out, err) = rodimpact(&["impact", path.to_str().unwrap()]);
        assert_eq!((code, out.as_str()), (2, ""));
        assert!(err.contains(expected), "{err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
