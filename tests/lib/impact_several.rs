//! Several frictionless contacts under each model, against the independent oracle
//! (`tests/oracles/multi_contact.py`: exact Python fractions, its own LCP enumeration and its own
//! sequential and PGS loops): every frictionless scene of `examples/impacts/` with more than one
//! contact, the bodies after, the impulses and the ledger of simultaneous Newton, simultaneous
//! Poisson, every sequential order, and 1, 2, 3 and 10 sweeps of projected Gauss-Seidel, all
//! exactly the oracle's fixture; and the cradle and the flat box worked by hand.

use rodimpact::field::{Q, q};
use rodimpact::impact::{
    MAX_ENUMERATED, MAX_ORDERED, Model, ModelAnswer, ModelOutcome, orders, solve_several,
};
use rodimpact::model::{System, parse_toml};
use serde_json::Value;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn rational(v: &Value) -> Q {
    v.as_str().unwrap().parse().unwrap()
}

fn system(name: &str) -> System {
    let text =
        std::fs::read_to_string(root().join(format!("examples/impacts/{name}.toml"))).unwrap();
    parse_toml(name, &text).unwrap()
}

/// The frictionless scenes with several contacts, and their fixtures.
fn scenes() -> Vec<(String, System, Value)> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(root().join("examples/impacts")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let s = system(&name);
        if s.contacts.len() < 2 || s.contacts.iter().any(|c| c.mu != Q::from_integer(0.into())) {
            continue;
        }
        let fixture =
            std::fs::read_to_string(root().join(format!("tests/data/impacts/{name}.json")))
                .unwrap();
        out.push((name, s, serde_json::from_str(&fixture).unwrap()));
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn only(outcome: ModelOutcome<Q>, what: &str) -> ModelAnswer<Q> {
    match outcome {
        ModelOutcome::Answered(mut answers) if answers.len() == 1 => answers.remove(0),
        other => panic!("{what}: not one answer: {other:?}"),
    }
}

fn check(name: &str, system: &System, expected: &Value, got: &ModelAnswer<Q>) {
    let at = format!("{name}, {}", got.model);
    for (index, velocity, omega) in &got.bodies {
        let body = &expected["bodies"][&system.bodies[*index].name];
        assert_eq!(
            velocity.x,
            rational(&body["velocity"][0]),
            "{at}: {} vx",
            system.bodies[*index].name
        );
        assert_eq!(velocity.y, rational(&body["velocity"][1]), "{at}: vy");
        assert_eq!(*omega, rational(&body["omega"]), "{at}: omega");
    }
    for (k, impulse) in got.impulses.iter().enumerate() {
        assert_eq!(
            *impulse,
            rational(&expected["impulses"][k]["normal"]),
            "{at}: impulse {}",
            k + 1
        );
    }
    let ledger = &expected["ledger"];
    assert_eq!(
        got.ledger.energy.before,
        rational(&ledger["energy"]["before"]),
        "{at}: energy"
    );
    assert_eq!(
        got.ledger.energy.change,
        rational(&ledger["energy"]["change"]),
        "{at}: energy change"
    );
    assert_eq!(
        got.ledger.momentum_after.x,
        rational(&ledger["momentum"]["after"][0]),
        "{at}: momentum"
    );
    assert_eq!(
        got.ledger.angular_after,
        rational(&ledger["angular_momentum_origin"]["after"]),
        "{at}: L"
    );
    let sinking: Vec<u64> = got.ledger.sinking().iter().map(|i| *i as u64 + 1).collect();
    let expected_sinking: Vec<u64> = ledger["sinking_contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect();
    assert_eq!(sinking, expected_sinking, "{at}: sinking contacts");
}

#[test]
fn every_model_is_the_oracles_on_every_frictionless_scene() {
    let scenes = scenes();
    assert!(scenes.len() >= 9, "{} scenes", scenes.len());
    let mut checked = 0;
    for (name, system, fixture) in &scenes {
        let models = fixture["models"].as_array().unwrap();
        let find = |key: &str| models.iter().find(|m| m["model"] == key).unwrap();
        for (model, key) in [
            (Model::SimultaneousNewton, "simultaneous-newton"),
            (Model::SimultaneousPoisson, "simultaneous-poisson"),
            (Model::Pgs(1), "pgs:1"),
            (Model::Pgs(2), "pgs:2"),
            (Model::Pgs(3), "pgs:3"),
            (Model::Pgs(10), "pgs:10"),
        ] {
            let expected = find(key);
            if expected.get("status").is_some_and(|s| s != "unique") {
                continue;
            }
            check(
                name,
                system,
                expected,
                &only(solve_several::<Q>(system, &model), name),
            );
            checked += 1;
        }
        let Some(sequential) = models.iter().find(|m| m["model"] == "sequential") else {
            assert!(
                system.contacts.len() > MAX_ORDERED,
                "{name}: the oracle ran no sequential model"
            );
            continue;
        };
        for order in sequential["orders"].as_array().unwrap() {
            let order_0: Vec<usize> = order["order"]
                .as_array()
                .unwrap()
                .iter()
                .map(|i| i.as_u64().unwrap() as usize - 1)
                .collect();
            let got = only(
                solve_several::<Q>(system, &Model::Sequential(order_0)),
                name,
            );
            check(name, system, order, &got);
            let fired: Vec<(usize, Q)> = order["impacts"]
                .as_array()
                .unwrap()
                .iter()
                .map(|i| {
                    (
                        i["contact"].as_u64().unwrap() as usize - 1,
                        rational(&i["impulse"]),
                    )
                })
                .collect();
            assert_eq!(
                got.impacts, fired,
                "{name}, {}: the impacts fired",
                got.model
            );
            checked += 1;
        }
    }
    assert!(checked > 100, "{checked} answers compared");
}

/// Newton's cradle of three equal balls (mass 1) struck at 1, e = 1, by hand. Simultaneous
/// Newton: the two contacts push with l1, l2 and leave at 1 (-u0) and 0: ball velocities
/// (1 - l1, l1 - l2, l2), with u1 = (l1 - l2) - (1 - l1) = 1 and u2 = l2 - (l1 - l2) = 0 give
/// l1 = 4/3, l2 = 2/3: (-1/3, 2/3, 2/3); energy (1/9 + 4/9 + 4/9)/2 = 1/2, kept. Sequential
/// 1 then 2: ball 1 stops, ball 2 takes 1, then ball 3 takes 1: (0, 0, 1). One PGS sweep:
/// l1 = 1 (ball 2 at 1), then l2 = 1/2 (u2 = 1 - 0 - l2 ... = 0 after e u0^- = 0): (0, 1/2,
/// 1/2), energy 1/4: half is lost.
#[test]
fn the_cradle_by_hand() {
    let cradle = system("cradle-3");
    let v = |answer: &ModelAnswer<Q>| -> Vec<Q> {
        answer.bodies.iter().map(|(_, v, _)| v.x.clone()).collect()
    };
    let newton = only(solve_several(&cradle, &Model::SimultaneousNewton), "newton");
    assert_eq!(v(&newton), [q(-1, 3), q(2, 3), q(2, 3)]);
    assert_eq!(newton.impulses, [q(4, 3), q(2, 3)]);
    assert_eq!(newton.ledger.energy.change, q(0, 1));
    let poisson = only(
        solve_several(&cradle, &Model::SimultaneousPoisson),
        "poisson",
    );
    assert_eq!(v(&poisson), v(&newton));
    for order in orders(2) {
        let seq = only(
            solve_several(&cradle, &Model::Sequential(order)),
            "sequential",
        );
        assert_eq!(v(&seq), [q(0, 1), q(0, 1), q(1, 1)]);
        assert_eq!(seq.ledger.energy.change, q(0, 1));
    }
    let one_sweep = only(solve_several(&cradle, &Model::Pgs(1)), "pgs:1");
    assert_eq!(v(&one_sweep), [q(0, 1), q(1, 2), q(1, 2)]);
    assert_eq!(one_sweep.ledger.energy.after, q(1, 4));
}

/// K sweeps of PGS on the 3-cradle: the impulse error shrinks by exactly 1/4 a sweep, and the
/// energy after K sweeps is 1/2 - (1/3) 4^(1-K) + (1/12) 16^(1-K) (the oracle's derivation).
/// Newton's cradle of N equal balls (mass 1) struck at 1, e = 1, by hand: with every contact
/// pushing, the first ball leaves at -(N-2)/N and the others together at 2/N, which keeps the
/// momentum (-(N-2) + 2(N-1))/N = 1 and the energy ((N-2)^2 + 4(N-1))/(2N^2) = 1/2; the contact
/// velocities after are 1, 0, ..., 0 (contact k, 2 <= k, joins two balls at 2/N), and the
/// impulse at contact k is 2(N-k)/N > 0, so the complementarity conditions hold. Twenty balls:
/// nineteen contacts, solved by Lemke's method.
#[test]
fn a_long_cradle_by_hand_through_lemke() {
    let n = 20;
    assert!(n - 1 > MAX_ENUMERATED);
    let mut text = String::new();
    for i in 0..n {
        let v = if i == 0 { 1 } else { 0 };
        text.push_str(&format!(
            "[[body]]\nname = \"ball{i}\"\nmass = \"1\"\nshape = \"disc\"\nradius = \"1/2\"\nposition = [\"{i}\", \"0\"]\nvelocity = [\"{v}\", \"0\"]\n"
        ));
    }
    for i in 1..n {
        text.push_str(&format!(
            "[[contact]]\nbodies = [\"ball{i}\", \"ball{}\"]\npoint = [\"{}/2\", \"0\"]\nnormal = [\"1\", \"0\"]\ne = \"1\"\n",
            i - 1,
            2 * i - 1
        ));
    }
    let system = parse_toml("cradle-20", &text).unwrap();
    for model in [Model::SimultaneousNewton, Model::SimultaneousPoisson] {
        let got = only(solve_several::<Q>(&system, &model), "cradle-20");
        let velocities: Vec<Q> = got.bodies.iter().map(|(_, v, _)| v.x.clone()).collect();
        let mut expected = vec![q(2, n as i64); n];
        expected[0] = q(-(n as i64 - 2), n as i64);
        assert_eq!(velocities, expected, "{model}");
        let impulses: Vec<Q> = (1..n as i64)
            .map(|k| q(2 * (n as i64 - k), n as i64))
            .collect();
        assert_eq!(got.impulses, impulses, "{model}");
        assert_eq!(got.ledger.energy.change, q(0, 1), "{model}");
    }
}

#[test]
fn pgs_converges_on_the_cradle_at_a_quarter_a_sweep() {
    let cradle = system("cradle-3");
    let newton = only(solve_several(&cradle, &Model::SimultaneousNewton), "newton");
    let mut previous: Option<Vec<Q>> = None;
    for k in 1..=8u32 {
        let swept = only(solve_several(&cradle, &Model::Pgs(k)), "pgs");
        let error: Vec<Q> = (0..2)
            .map(|i| &swept.impulses[i] - &newton.impulses[i])
            .collect();
        if let Some(before) = &previous {
            for i in 0..2 {
                assert_eq!(
                    &error[i] * q(4, 1),
                    before[i],
                    "sweep {k}, contact {}",
                    i + 1
                );
            }
        }
        let four = Q::from_integer(4.into()).pow(1 - k as i32);
        let sixteen = Q::from_integer(16.into()).pow(1 - k as i32);
        assert_eq!(
            swept.ledger.energy.after,
            q(1, 2) - q(1, 3) * four + q(1, 12) * sixteen,
            "sweep {k}"
        );
        previous = Some(error);
    }
}

/// Two frictional contacts under simultaneous Newton and simultaneous Poisson (Coulomb's law
/// in each phase, every mode of both contacts tried): the flat box sliding sideways (both
/// corners slide; at mu = 3/4 they stick in expansion, where only the sum of the two friction
/// impulses is determined) and the box on two pegs where Poisson's law GAINS energy, all the
/// oracle's motion and energy exactly, each answer unique.
#[test]
fn two_frictional_contacts_are_the_oracles() {
    for name in [
        "box-lands-flat-friction",
        "box-lands-flat-friction-stick",
        "two-contact-poisson-energy",
    ] {
        let s = system(name);
        let fixture: Value = serde_json::from_str(
            &std::fs::read_to_string(root().join(format!("tests/data/impacts/{name}.json")))
                .unwrap(),
        )
        .unwrap();
        for (model, key) in [
            (Model::SimultaneousNewton, "simultaneous-newton"),
            (Model::SimultaneousPoisson, "simultaneous-poisson"),
        ] {
            let expected = fixture["models"]
                .as_array()
                .unwrap()
                .iter()
                .find(|m| m["model"] == key)
                .unwrap();
            let got = only(solve_several::<Q>(&s, &model), name);
            for (index, velocity, omega) in &got.bodies {
                let body = &expected["bodies"][&s.bodies[*index].name];
                assert_eq!(
                    velocity.x,
                    rational(&body["velocity"][0]),
                    "{name}, {key}: vx"
                );
                assert_eq!(
                    velocity.y,
                    rational(&body["velocity"][1]),
                    "{name}, {key}: vy"
                );
                assert_eq!(*omega, rational(&body["omega"]), "{name}, {key}: omega");
            }
            assert_eq!(
                got.ledger.energy.change,
                rational(&expected["ledger"]["energy"]["change"]),
                "{name}, {key}"
            );
            assert_eq!(
                got.split_indeterminate,
                expected["tangential_split_indeterminate"] == true,
                "{name}, {key}: split"
            );
        }
    }
    let gain = only(
        solve_several::<Q>(
            &system("two-contact-poisson-energy"),
            &Model::SimultaneousPoisson,
        ),
        "gain",
    );
    assert!(gain.ledger.energy.gain());
    assert_eq!(gain.ledger.energy.change, q(989587, 25088000));
    // Sequential single-contact impacts take no friction; projected Gauss-Seidel does (a
    // friction row after each normal row: tests/lib/engine_laws.rs holds it to the oracle).
    assert!(matches!(
        solve_several::<Q>(
            &system("box-lands-flat-friction"),
            &Model::Sequential(vec![0, 1])
        ),
        ModelOutcome::FrictionlessOnly
    ));
    assert!(matches!(
        solve_several::<Q>(&system("box-lands-flat-friction"), &Model::Pgs(1)),
        ModelOutcome::Answered(_)
    ));
}
