//! The engines' laws and profiles on the command line: `impact --law lcp-newton|lcp-poisson|split`
//! and `impact --engine NAME` answer as the independent oracle's fixtures
//! (`tests/data/impacts-engines/`, `tests/oracles/engine_laws.py`) say, on every example, and
//! `impact --batch`'s CI flags (`--expect`, `--summary-json`, `--atol`, `--ulps`, `--engine`).

use crate::common::{assert_refused, rodimpact, scratch};
use serde_json::Value;

const TILTED: &str = "examples/impacts/tilted-rod-rough-floor.toml";
const CRADLE: &str = "examples/impacts/cradle-3.toml";
const PYMUNK: &str = "tests/data/engines/impacts/pymunk-7.3.1.jsonl";

/// The oracle's answer named `name` for the example `stem`.
fn oracle(stem: &str, name: &str) -> Value {
    let path = format!("{}/tests/data/impacts-engines/{stem}.json", crate::ROOT);
    let fixture: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    fixture["answers"]
        .as_array()
        .unwrap()
        .iter()
        .find(|a| a["law"] == name)
        .unwrap_or_else(|| panic!("{stem}: no oracle answer {name}"))
        .clone()
}

/// `impact FILE ARGS --format json`, which must not be refused.
fn impact_json(file: &str, args: &[&str]) -> Value {
    let mut all = vec!["impact", file, "--format", "json"];
    all.extend_from_slice(args);
    let (code, out, err) = rodimpact(&all);
    assert!(code == 0 || code == 1, "{all:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// The exact velocity and angular velocity of `body` in a JSON answer.
fn state(answer: &Value, body: &str) -> [String; 3] {
    let b = &answer["bodies"][body];
    let exact = |v: &Value| {
        v["exact"]
            .as_str()
            .unwrap_or_else(|| v.as_str().unwrap())
            .to_string()
    };
    [
        exact(&b["velocity"][0]),
        exact(&b["velocity"][1]),
        exact(&b["omega"]),
    ]
}

#[test]
fn lcp_newton_on_the_tilted_rod_sticks_and_gains_a_tenth() {
    let (code, text, err) = rodimpact(&["impact", TILTED, "--law", "lcp-newton"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.contains("rod: v = (6/5 = 1.2, 1/10 = 0.1) m/s, omega = -3/2 = -1.5 rad/s"),
        "{text}"
    );
    assert!(
        text.contains("energy: 1 -> 11/10 = 1.1 J, change 1/10 = 0.1 J: THIS LAW CREATES ENERGY")
    );
    assert!(text.contains("contact: u_n -1 -> 1, u_t -1 -> 0"));
    // The three engine laws each equal the oracle's.
    for law in ["lcp-newton", "lcp-poisson", "split"] {
        let j = impact_json(TILTED, &["--law", law]);
        assert_eq!(j["laws"][0]["law"], law);
        let want = oracle("tilted-rod-rough-floor", law);
        assert_eq!(state(&j["laws"][0], "rod"), state(&want, "rod"), "{law}");
        assert_eq!(
            j["laws"][0]["energy"]["change"]["exact"], want["energy"]["change"],
            "{law}"
        );
    }
}

#[test]
fn an_engines_step_is_its_replay_beside_the_laws() {
    for (engine, name) in [
        ("pymunk-7", "pymunk-7"),
        ("box2d-2.3", "box2d-2.3"),
        ("box2d-2.3:scale=16", "box2d-2.3:scale=16"),
        ("bullet-3", "bullet-3"),
    ] {
        let j = impact_json(TILTED, &["--engine", engine]);
        let laws = j["laws"].as_array().unwrap();
        // The three physical laws, then the engine's step.
        assert_eq!(laws.len(), 4, "{engine}");
        assert_eq!(laws[3]["engine"], engine);
        assert_eq!(laws[3]["law"], "lcp-newton");
        assert_eq!(
            state(&laws[3], "rod"),
            state(&oracle("tilted-rod-rough-floor", name), "rod"),
            "{engine}"
        );
    }
    // Box2D's threshold: an approach at exactly 1 m/s is not above it, so no bounce at all.
    let j = impact_json(TILTED, &["--law", "newton", "--engine", "box2d-2.3"]);
    assert_eq!(
        j["laws"][1]["contact_velocity"]["normal"]["after"]["exact"],
        "0"
    );
    let (_, text, _) = rodimpact(&["impact", TILTED, "--law", "newton", "--engine", "box2d-2.3"]);
    assert!(
        text.contains(
            "restitution threshold 1 in the scene's units; combines e by max, mu by sqrt of product"
        ),
        "{text}"
    );
    // The soft-contact engines answer with the law they converge to.
    let j = impact_json(TILTED, &["--law", "split", "--engine", "rapier-0.36"]);
    assert_eq!(state(&j["laws"][1], "rod"), state(&j["laws"][0], "rod"));
}

#[test]
fn every_example_answers_under_every_engine_law_and_profile() {
    let dir = format!("{}/examples/impacts", crate::ROOT);
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .map(|p| {
            format!(
                "examples/impacts/{}",
                p.file_name().unwrap().to_str().unwrap()
            )
        })
        .collect();
    files.sort();
    assert!(files.len() >= 20);
    for file in &files {
        for args in [
            ["--law", "lcp-newton"],
            ["--law", "lcp-poisson"],
            ["--law", "split"],
            ["--engine", "pymunk-7"],
            ["--engine", "box2d-2.3"],
            ["--engine", "box2d-3"],
            ["--engine", "rapier-0.36"],
            ["--engine", "bullet-3"],
        ] {
            let (code, out, err) = rodimpact(&["impact", file, args[0], args[1]]);
            assert!(code == 0 || code == 1, "{file} {args:?}: {err}");
            assert!(!out.is_empty(), "{file} {args:?}");
        }
    }
}

#[test]
fn several_contacts_take_the_engines_laws_not_the_physical_ones() {
    // split and lcp-newton on a cradle are the simultaneous answer: -1/3, 2/3, 2/3.
    for law in ["split", "lcp-newton"] {
        let j = impact_json(CRADLE, &["--law", law]);
        let models = j["models"].as_array().unwrap();
        assert_eq!(models.len(), 1, "{law}");
        let answer = &models[0]["answers"][0];
        assert_eq!(state(answer, "ball1")[0], "-1/3", "{law}");
        assert_eq!(state(answer, "ball3")[0], "2/3", "{law}");
    }
    // pymunk's step on the touching cradle: it does not collide touching circles, so one pair.
    let j = impact_json(CRADLE, &["--engine", "pymunk-7"]);
    let step = j["models"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(step["engine"], "pymunk-7");
    let want = oracle("cradle-3", "pymunk-7");
    assert_eq!(state(&step["answers"][0], "ball1"), state(&want, "ball1"));
    assert_refused(
        &["impact", CRADLE, "--law", "newton"],
        "error: law: several contacts: their models (--model) say how the contacts act together \
         (of the laws, only the engines' lcp-newton, lcp-poisson and split apply)\n",
    );
    assert_refused(
        &["impact", CRADLE, "--law", "split", "--model", "pgs:1"],
        "error: law: several contacts: give the law or the model (--model), not both\n",
    );
    let (code, _, err) = rodimpact(&["impact", TILTED, "--engine", "havok"]);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("error: engine: ") && err.lines().count() == 1,
        "{err}"
    );
}

#[test]
fn the_audits_ci_flags() {
    let dir = scratch("impact-batch-ci");
    // --summary-json: the summary a dashboard reads, with the same counts as the text.
    let summary = dir.join("summary.json");
    let (code, _, err) = rodimpact(&[
        "impact",
        "--batch",
        PYMUNK,
        "--rtol",
        "1e-2",
        "--summary-json",
        summary.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    let s: Value = serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap();
    assert_eq!(
        (s["scenes"].as_u64(), s["passed"].as_bool()),
        (Some(61), Some(false))
    );
    assert_eq!(s["closest"]["pymunk-7"], 18);
    assert_eq!(
        s["findings"]["off"]["scenes"],
        serde_json::json!(["ball-on-column", "cradle-12-two-balls"])
    );
    // --expect: the two known findings allowed, the job passes; one left out, it fails on it.
    let known = dir.join("known.csv");
    std::fs::write(&known, "id,finding\nball-on-column,off\ncradle-12-*,off\n").unwrap();
    let (code, _, err) = rodimpact(&[
        "impact",
        "--batch",
        PYMUNK,
        "--rtol",
        "1e-2",
        "--expect",
        known.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    std::fs::write(&known, "id,finding\nball-on-column,off\n").unwrap();
    let (code, _, err) = rodimpact(&[
        "impact",
        "--batch",
        PYMUNK,
        "--rtol",
        "1e-2",
        "--expect",
        known.to_str().unwrap(),
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("cradle-12-two-balls"), "{err}");
    // --ulps, --atol: a looser rule matches more claims; never fewer.
    let matched = |args: &[&str]| -> usize {
        let mut all = vec!["impact", "--batch", PYMUNK];
        all.extend_from_slice(args);
        let (_, out, _) = rodimpact(&all);
        out.lines()
            .filter(|l| {
                let v: Value = serde_json::from_str(l).unwrap();
                !v["matches"].as_array().unwrap().is_empty()
            })
            .count()
    };
    let strict = matched(&[]);
    assert!(matched(&["--ulps", "1000000"]) >= strict);
    assert!(matched(&["--atol", "1e-3"]) > strict);
    // --engine all: every replayed engine's step is an answer of every line.
    let (_, out, _) = rodimpact(&["impact", "--batch", PYMUNK, "--engine", "all"]);
    let first: Value = serde_json::from_str(out.lines().nth(2).unwrap()).unwrap();
    let names: Vec<String> = first["rel_error"]
        .as_object()
        .unwrap()
        .keys()
        .cloned()
        .collect();
    for engine in ["pymunk-7", "box2d-2.3", "bullet-3"] {
        let equal = first["equal"].to_string();
        assert!(
            names.iter().any(|n| n == engine) || equal.contains(engine),
            "{engine}: {first}"
        );
    }
    // Bad options: one line naming the flag, exit 2.
    for (args, field) in [
        (vec!["--rtol", "-1"], "rtol"),
        (vec!["--rtol", "1e10000"], "rtol"),
        (vec!["--atol", "x"], "atol"),
        (vec!["--ulps", "-1"], "ulps"),
        (vec!["--engine", "havok"], "engine"),
    ] {
        let mut all = vec!["impact", "--batch", PYMUNK];
        all.extend_from_slice(&args);
        let (code, out, err) = rodimpact(&all);
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}");
        assert!(
            err.starts_with(&format!("error: {field}: ")) && err.lines().count() == 1,
            "{err}"
        );
    }
    // The audit's options without --batch are refused, not ignored; one scene's options with it too.
    assert_refused(
        &["impact", TILTED, "--rtol", "1"],
        "error: rtol: only with --batch (it says when an engine's claim matches)\n",
    );
    let (code, _, err) = rodimpact(&["impact", "--batch", PYMUNK, "--law", "newton"]);
    assert_eq!(code, 2, "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Box2D's restitution threshold applies in both its profiles (hostile-46 F1): a disc landing at
/// 1/2 m/s with e = 1 does not bounce under box2d-2.3 or box2d-3 (threshold 1 m/s), bounces to
/// 1/2 under box2d-3:threshold=1/4 and under the engines without a threshold; a threshold for an
/// engine that has none, a setting given twice, or scale with threshold is refused (F2, F3).
#[test]
fn the_restitution_threshold_is_applied_where_an_engine_has_one() {
    let dir = scratch("engine-threshold");
    let path = dir.join("slow-disc.toml");
    std::fs::write(
        &path,
        r#"
[[body]]
name = "disc"
mass = "1"
shape = "disc"
radius = "1"
position = ["0", "1"]
velocity = ["0", "-1/2"]
[[body]]
name = "floor"
fixed = true
[[contact]]
bodies = ["disc", "floor"]
point = ["0", "0"]
normal = ["0", "1"]
e = "1"
"#,
    )
    .unwrap();
    let path = path.to_str().unwrap();
    for (engine, vy) in [
        ("box2d-2.3", "0"),
        ("box2d-3", "0"),
        ("box2d-3:threshold=1/4", "1/2"),
        ("box2d-3:scale=4", "1/2"),
        ("rapier-0.36", "1/2"),
        ("pymunk-7", "1/2"),
    ] {
        let (code, out, err) = rodimpact(&["impact", path, "--engine", engine, "--format", "json"]);
        assert_eq!(code, 0, "{engine}: {err}");
        let json: Value = serde_json::from_str(&out).unwrap();
        let step = json["laws"]
            .as_array()
            .unwrap()
            .iter()
            .find(|l| l["engine"] == engine)
            .unwrap_or_else(|| panic!("{engine}: {out}"));
        assert_eq!(
            step["bodies"]["disc"]["velocity"][1]["exact"], vy,
            "{engine}"
        );
    }
    for (engine, why) in [
        (
            "pymunk-7:threshold=5",
            "pymunk-7 has no restitution threshold (threshold= and scale= apply to box2d-2.3 and box2d-3)",
        ),
        (
            "box2d-2.3:scale=2,threshold=5",
            "threshold= and scale= both set the threshold: give one",
        ),
        ("box2d-2.3:scale=2,scale=3", "scale is given twice"),
        (
            "rapier-0.36:plane=xy",
            "rapier-0.36 takes no settings, got 'plane'",
        ),
    ] {
        assert_refused(
            &["impact", path, "--engine", engine],
            &format!("error: engine: {why}\n"),
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
