//! `rodimpact simulate`: one k with every integrator, the k sweep with its slopes, bad input.

mod common;
use common::rodimpact;

#[test]
fn one_stiffness_runs_every_integrator() {
    let (code, out, _) = rodimpact(&[
        "simulate",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "1/2",
        "--stiffness",
        "1e6",
        "--json",
    ]);
    assert_eq!(code, 0);
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(doc["exact"]["omega"], 12.0 / 11.0);
    let names: Vec<&str> = doc["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["integrator"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        ["verlet", "rk4", "midpoint", "backward-euler", "event-rk4"]
    );
    let event = &doc["runs"][4];
    assert_eq!(event["steps"], 100);
    assert!(event["rel_err"]["omega"].as_f64().unwrap() < 2e-7);
}

#[test]
fn sweep_prints_the_fitted_slopes() {
    let (code, out, _) = rodimpact(&[
        "simulate",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "1/2",
        "--sweep-k",
    ]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().filter(|l| l.starts_with("| 1e")).count(), 9);
    assert!(
        out.contains("v -1.000, V -1.000, omega -1.000, lateral -0.500"),
        "{out}"
    );
}

#[test]
fn bad_input_names_the_field() {
    for (args, field) in [
        (vec!["--stiffness", "0"], "stiffness"),
        (vec!["--stiffness", "1e6", "--pivot", "0"], "pivot"),
        (vec!["--stiffness", "1e6", "--inelastic"], "e"),
        (vec!["--stiffness", "1e12", "--steps", "1000000"], "steps"),
        (vec!["--stiffness", "1e6", "--dt", "-1"], "dt"),
    ] {
        let mut full = vec!["simulate", "--m", "1", "--M", "1"];
        full.extend(args);
        let (code, out, err) = rodimpact(&full);
        assert_eq!(code, 2, "{full:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1);
        assert!(err.starts_with(&format!("error: {field}: ")), "{err}");
    }
}
