//! The general one-contact solver against the independent oracle (`tests/oracles/planar_impact.py`,
//! exact Python fractions, Routh's construction written separately): every scene of
//! `examples/impacts/` with one contact, under the three laws, every number exactly as the
//! oracle's fixture in `tests/data/impacts/` (velocities and spins after, the impulse and its
//! coefficients, lam_c and lam_f, the phases with friction, the works, the energies and
//! whether energy is gained), and every balance law holding exactly.

use rodimpact::field::{Q, QSqrt};
use rodimpact::impact::{Law, LawAnswer, solve_contact};
use rodimpact::model::{System, parse_toml};
use serde_json::Value;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A fixture number: "p/q", or {"x", "y", "d"} for x + y sqrt(d).
fn number(v: &Value) -> QSqrt {
    let rational = |s: &Value| -> Q { s.as_str().unwrap().parse().unwrap() };
    match v {
        Value::String(_) => QSqrt::rational(rational(v)),
        Value::Object(o) => QSqrt::new(rational(&o["x"]), rational(&o["y"]), rational(&o["d"])),
        other => panic!("not a fixture number: {other}"),
    }
}

fn pair(v: &Value) -> [QSqrt; 2] {
    [number(&v[0]), number(&v[1])]
}

/// The scenes with one contact and their fixtures.
fn one_contact_scenes() -> Vec<(String, System, Value)> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(root().join("examples/impacts")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&path).unwrap();
        let system = parse_toml(&name, &text).unwrap_or_else(|e| panic!("{name}: {e}"));
        if system.contacts.len() != 1 {
            continue;
        }
        let fixture = root().join(format!("tests/data/impacts/{name}.json"));
        let fixture: Value =
            serde_json::from_str(&std::fs::read_to_string(fixture).unwrap()).unwrap();
        out.push((name, system, fixture));
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn check(name: &str, system: &System, expected: &Value, got: &LawAnswer<QSqrt>) {
    let law = got.law.name();
    let at = |what: &str| format!("{name}, {law}: {what}");
    for body in &got.bodies {
        let body_name = &system.bodies[body.index].name;
        let e = &expected["bodies"][body_name];
        assert_eq!(
            [body.velocity.x.clone(), body.velocity.y.clone()],
            pair(&e["velocity"]),
            "{}",
            at(body_name)
        );
        assert_eq!(
            body.omega,
            number(&e["omega"]),
            "{}",
            at(&format!("{body_name}.omega"))
        );
    }
    assert_eq!(
        [got.impulse.x.clone(), got.impulse.y.clone()],
        pair(&expected["impulse"]),
        "{}",
        at("impulse")
    );
    assert_eq!(
        got.lam,
        number(&expected["impulse_coefficients"]["lam"]),
        "{}",
        at("lam")
    );
    assert_eq!(
        got.tau,
        number(&expected["impulse_coefficients"]["tau"]),
        "{}",
        at("tau")
    );
    assert_eq!(got.lam_c, number(&expected["lam_c"]), "{}", at("lam_c"));
    assert_eq!(
        got.contact_after[0],
        number(&expected["contact_velocity"]["after"]["n"]),
        "{}",
        at("u_n after")
    );
    assert_eq!(
        got.contact_after[1],
        number(&expected["contact_velocity"]["after"]["t"]),
        "{}",
        at("u_t after")
    );
    let work = &expected["work"];
    assert_eq!(
        got.work,
        [
            number(&work["normal_compression"]),
            number(&work["normal_restitution"]),
            number(&work["friction"])
        ],
        "{}",
        at("work")
    );
    let energy = &expected["energy"];
    assert_eq!(
        got.energy.before,
        number(&energy["before"]),
        "{}",
        at("energy before")
    );
    assert_eq!(
        got.energy.after,
        number(&energy["after"]),
        "{}",
        at("energy after")
    );
    assert_eq!(
        got.energy.change,
        number(&energy["change"]),
        "{}",
        at("energy change")
    );
    assert_eq!(
        Value::Bool(got.energy.gain()),
        expected["energy_gain"],
        "{}",
        at("energy_gain")
    );
    if !system.contacts[0].mu.eq(&Q::from_integer(0.into())) {
        let phases: Vec<(String, QSqrt, QSqrt)> = expected["phases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                (
                    p["mode"].as_str().unwrap().to_string(),
                    number(&p["from"]),
                    number(&p["to"]),
                )
            })
            .collect();
        let got_phases: Vec<(String, QSqrt, QSqrt)> = got
            .phases
            .iter()
            .map(|p| (p.mode.name().to_string(), p.from.clone(), p.to.clone()))
            .collect();
        assert_eq!(got_phases, phases, "{}", at("phases"));
    }
    assert!(
        got.balances.all_zero(),
        "{}: {:?}",
        at("laws"),
        got.balances.failing()
    );
}

#[test]
fn every_one_contact_scene_is_the_oracles_under_every_law() {
    let scenes = one_contact_scenes();
    assert!(scenes.len() >= 8, "{} scenes", scenes.len());
    for (name, system, fixture) in &scenes {
        let laws = fixture["laws"].as_array().unwrap();
        for law in Law::ALL {
            let expected = laws.iter().find(|l| l["law"] == law.name()).unwrap();
            let got = solve_contact::<QSqrt>(system, law)
                .unwrap_or_else(|e| panic!("{name}, {law}: {e}"));
            check(name, system, expected, &got);
        }
    }
}
