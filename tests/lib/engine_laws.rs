//! The engines' laws and profiles against the independent oracle (`tests/oracles/engine_laws.py`,
//! exact Python fractions, written without reading the Rust): every scene of
//! `examples/impacts/`, the three witnesses of `tests/oracles/witnesses/` and the 60 scenes of
//! `engines/impacts.jsonl`, under lcp-newton, lcp-poisson, split, pgs:1 and pgs:10 with
//! friction, and the exact replays of pymunk-7, box2d-2.3 (also at scale 16) and bullet-3: the
//! status (answered, several, no solution, does not stop) and every moving body's velocity and
//! spin after, exactly as the fixtures of `tests/data/impacts-engines/` hold them.

use rodimpact::field::{Q, QSqrt};
use rodimpact::impact::{
    Law, Model, ModelOutcome, Profile, solve_engine_exact, solve_exact, solve_several,
};
use rodimpact::mechanics::planar::Vec2;
use rodimpact::model::{System, from_value, parse_toml};
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rational(v: &Value) -> Q {
    v.as_str().expect("an exact string").parse().expect("p/q")
}

/// Every moving body's (name, velocity, spin) after, sorted by name, as text: a state.
type State = BTreeSet<(String, String, String, String)>;

fn fixture_state(bodies: &Value) -> State {
    bodies
        .as_object()
        .expect("bodies")
        .iter()
        .map(|(name, b)| {
            let [x, y] = [&b["velocity"][0], &b["velocity"][1]].map(rational);
            (
                name.clone(),
                x.to_string(),
                y.to_string(),
                rational(&b["omega"]).to_string(),
            )
        })
        .collect()
}

fn state<F: ToString>(system: &System, bodies: &[(usize, Vec2<F>, F)]) -> State {
    bodies
        .iter()
        .map(|(i, v, w)| {
            (
                system.bodies[*i].name.clone(),
                v.x.to_string(),
                v.y.to_string(),
                w.to_string(),
            )
        })
        .collect()
}

/// What the library says of `system` under the fixture's `name`: its status and its states.
fn library(system: &System, name: &str) -> (&'static str, Vec<State>) {
    let n = system.contacts.len();
    let one_contact_law = Law::parse(name).filter(|_| n == 1);
    let profile = Profile::parse(name).ok();
    let lifted = |a: rodimpact::impact::LawAnswer<QSqrt>| {
        let bodies: Vec<(usize, Vec2<QSqrt>, QSqrt)> = a
            .bodies
            .into_iter()
            .map(|b| (b.index, b.velocity, b.omega))
            .collect();
        ("answered", vec![state(system, &bodies)])
    };
    if let Some(law) = one_contact_law {
        return match solve_exact(system, law) {
            Ok(a) => lifted(a),
            Err(e) => panic!("{name}: {e}"),
        };
    }
    if let (Some(profile), 1) = (&profile, n) {
        return match solve_engine_exact(system, profile) {
            Ok(a) => lifted(a),
            Err(rodimpact::impact::ImpactError::Unanswered(..)) => ("does-not-stop", Vec::new()),
            Err(e) => panic!("{name}: {e}"),
        };
    }
    let model = Model::parse(name, n).unwrap_or_else(|why| panic!("{name}: {why}"));
    match solve_several::<Q>(system, &model) {
        ModelOutcome::Answered(answers) => {
            let states: Vec<State> = answers.iter().map(|a| state(system, &a.bodies)).collect();
            (
                if states.len() == 1 {
                    "answered"
                } else {
                    "several"
                },
                states,
            )
        }
        ModelOutcome::NoSolution => ("no-solution", Vec::new()),
        ModelOutcome::DoesNotStop => ("does-not-stop", Vec::new()),
        ModelOutcome::FrictionlessOnly => ("frictionless-only", Vec::new()),
        ModelOutcome::Stopped(why) => panic!("{name}: stopped: {why}"),
    }
}

/// Every answer of one fixture against the library.
fn agrees(label: &str, system: &System, fixture: &Value) -> usize {
    let mut checked = 0;
    for answer in fixture["answers"].as_array().expect("answers") {
        let name = answer["law"].as_str().expect("law");
        let status = answer["status"].as_str().expect("status");
        let (got_status, got) = library(system, name);
        assert_eq!(got_status, status, "{label} {name}");
        let mut want: Vec<State> = match status {
            "answered" => vec![fixture_state(&answer["bodies"])],
            "several" => answer["solutions"]
                .as_array()
                .expect("solutions")
                .iter()
                .map(|s| fixture_state(&s["bodies"]))
                .collect(),
            _ => Vec::new(),
        };
        let mut got = got;
        want.sort();
        got.sort();
        assert_eq!(got, want, "{label} {name}");
        checked += 1;
    }
    checked
}

#[test]
fn every_example_under_every_engine_law_is_the_oracles() {
    let mut checked = 0;
    for (dir, prefix) in [
        ("examples/impacts", ""),
        ("tests/oracles/witnesses", "witness-"),
    ] {
        for entry in std::fs::read_dir(root().join(dir)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "toml") {
                continue;
            }
            let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
            let fixture_path =
                root().join(format!("tests/data/impacts-engines/{prefix}{stem}.json"));
            let fixture: Value =
                serde_json::from_str(&std::fs::read_to_string(&fixture_path).unwrap()).unwrap();
            let text = std::fs::read_to_string(&path).unwrap();
            let system = parse_toml(&stem, &text).unwrap();
            checked += agrees(&stem, &system, &fixture);
        }
    }
    assert!(checked >= 24 * 9, "{checked} answers checked");
}

#[test]
fn the_engine_suite_under_every_engine_law_is_the_oracles() {
    let scenes = std::fs::read_to_string(root().join("engines/impacts.jsonl")).unwrap();
    let fixtures =
        std::fs::read_to_string(root().join("tests/data/impacts-engines/engines-impacts.jsonl"))
            .unwrap();
    let mut checked = 0;
    for (scene, fixture) in scenes.lines().zip(fixtures.lines()) {
        let mut scene: Value = serde_json::from_str(scene).unwrap();
        let fixture: Value = serde_json::from_str(fixture).unwrap();
        let id = scene["id"].as_str().unwrap().to_string();
        assert_eq!(fixture["scene"]["id"], scene["id"]);
        for key in ["id", "class"] {
            scene.as_object_mut().unwrap().remove(key);
        }
        let system = from_value(&scene).unwrap();
        checked += agrees(&id, &system, &fixture);
    }
    assert!(checked >= 60 * 9, "{checked} answers checked");
}
