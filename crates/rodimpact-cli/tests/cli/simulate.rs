//! `rodimpact simulate`: one k with every integrator, the pivoted and sticking cases, the k
//! sweep with its slopes, exact values printed exactly, the refusals and the exit code of a
//! miss.

use crate::common;
use common::rodimpact;

/// `simulate --m 1 --M 1` plus `args`.
fn simulate(args: &[&str]) -> (i32, String, String) {
    let mut full = vec!["simulate", "--m", "1", "--M", "1"];
    full.extend(args);
    rodimpact(&full)
}

fn json(out: &str) -> serde_json::Value {
    serde_json::from_str(out).unwrap_or_else(|e| panic!("{e}: {out}"))
}

#[test]
fn one_stiffness_runs_every_integrator() {
    let (code, out, _) = simulate(&["--a", "1/2", "--stiffness", "1e6", "--json"]);
    assert_eq!(code, 0);
    let doc = json(&out);
    // NEWCOMER #22: the exact values as exact strings, their f64 roundings beside.
    assert_eq!(doc["exact"]["v"], "3/11");
    assert_eq!(doc["exact"]["V"], "8/11");
    assert_eq!(doc["exact"]["omega"], "12/11");
    assert_eq!(doc["exact"]["energy_change"], "0");
    assert_eq!(doc["exact_f64"]["omega"], 12.0 / 11.0);
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
    assert_eq!(event["ending"], "separated");
    assert_eq!(doc["ok"], true);
}

/// NEWCOMER #22: the text report prints 3/11 (not 2.727272727272727e-1) and defines its columns
/// and step counts. Nothing here reads the last column, the run's wall time, which load changes
/// (a slow run once printed `1.2e-1 |` there and failed the old whole-text check).
#[test]
fn text_prints_exact_values_and_defines_its_columns() {
    let (code, out, _) = simulate(&["--a", "1/2", "--stiffness", "1e6"]);
    assert_eq!(code, 0, "{out}");
    let exact_section = out.split("| integrator").next().unwrap();
    assert!(exact_section.contains("3/11"), "{out}");
    assert!(!exact_section.contains("e-1"), "{out}");
    for line in [
        "  v      projectile velocity          3/11   ~ 0.272727272727273",
        "  omega  rod angular velocity         12/11  ~ 1.09090909090909",
        "  dE/E   energy change, -lost/before  0",
        "| event-rk4 | 0.031 | 100 |",
        "  h Omega     the step h times Omega",
        "  steps       fixed-step methods run from rest through the approach (l/10 at v0) and the \
         contact, to the first step after separation; event-rk4 integrates only the contact",
        "  err X       relative error |X_sim - X_exact| / |X_exact|",
        "  lateral/v0  the projectile's velocity along the rod afterwards, over v0",
        "  tolerance   the largest error accepted: the model's O(1/k) floor 4.3e-5",
        "All 5 runs reproduce the exact values within their tolerances.",
    ] {
        assert!(out.contains(line), "missing {line:?} in\n{out}");
    }
}

/// NEWCOMER #21: `--pivot` works: the pivot impulse is integrated over the contact and compared
/// with the exact one (-8/7 for a centre pivot hit at l/2).
#[test]
fn pivoted_rod_is_simulated_with_its_pivot_impulse() {
    let args = ["--a", "1/2", "--pivot", "0", "--stiffness", "1e8", "--json"];
    let (code, out, _) = simulate(&args);
    assert_eq!(code, 0, "{out}");
    let doc = json(&out);
    assert_eq!(doc["exact"]["v"], "-1/7");
    assert_eq!(doc["exact"]["omega"], "12/7");
    assert_eq!(doc["exact"]["P"], "-8/7");
    for run in doc["runs"].as_array().unwrap() {
        assert_eq!(run["ok"], true, "{run}");
    }
    let event = &doc["runs"][4];
    assert!(
        (event["P"].as_f64().unwrap() + 8.0 / 7.0).abs() < 1e-7,
        "{event}"
    );
    assert!(event["rel_err"]["P"].as_f64().unwrap() < 1e-7, "{event}");
    let (_, text, _) = simulate(&args[..6]);
    assert!(text.contains("  P      impulse of the pivot on the rod  -8/7  ~ -1.14285714285714"));
    assert!(text.contains("| err P |"), "{text}");
}

/// NEWCOMER #21: `--inelastic` works: the glued contact reproduces the sticking values.
#[test]
fn sticking_case_is_simulated() {
    let (code, out, _) = simulate(&["--a", "1/2", "--inelastic", "--stiffness", "1e8", "--json"]);
    assert_eq!(code, 0, "{out}");
    let doc = json(&out);
    assert_eq!(doc["contact"], "sticking");
    assert_eq!(doc["exact"]["v"], "7/11");
    assert_eq!(doc["exact"]["energy_change"], "-4/11");
    let event = &doc["runs"][4];
    assert_eq!(event["ending"], "settled");
    // The default step is h Omega = pi/100 for every law; the settle time is T_s = 34.1/Omega,
    // hence ceil(100 * 34.1 / pi) = 1087 steps.
    assert!((event["h_omega"].as_f64().unwrap() - std::f64::consts::PI / 100.0).abs() < 1e-3);
    assert_eq!(event["steps"], 1087);
    assert!(event["rel_err"]["v"].as_f64().unwrap() < 1e-6, "{event}");
    assert!(
        event["rel_err"]["omega"].as_f64().unwrap() < 1e-6,
        "{event}"
    );
}

#[test]
fn sweep_prints_the_fitted_slopes() {
    let (code, out, _) = simulate(&["--a", "1/2", "--sweep-k"]);
    assert_eq!(code, 0, "{out}");
    assert_eq!(out.lines().filter(|l| l.starts_with("| 1e")).count(), 9);
    assert!(
        out.contains("v -1.000, V -1.000, omega -1.000, lateral -0.500"),
        "{out}"
    );
    // k = 1e2 is too soft to check (model floor 0.43), the other eight check.
    assert!(out.contains("| 4.3e-1 | loose |"), "{out}");
    assert!(out.contains(
        "The sweep passes: 8 of 9 stiffnesses reproduce the exact values within their \
         tolerances; 1 is too soft to check (loose)."
    ));
    let (code, out, _) = simulate(&["--a", "1/2", "--pivot", "-1", "--e", "1/2", "--sweep-k"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains(", P -1.000, lateral -0.500"), "{out}");
}

/// Refused before any work, exit 2 and one line naming the field: the scene flags, a step
/// longer than the contact (RELIABILITY F11: `--dt 1e300` printed inf/NaN errors and exited 0),
/// runs beyond the work limit (F12: one implicit run could take 100 s), and the default a = l
/// with the exact geometry (F11).
#[test]
fn bad_input_names_the_field() {
    for (args, field, says) in [
        (vec!["--a", "1/2", "--stiffness", "0"], "stiffness", "> 0"),
        (
            vec!["--a", "1/2", "--stiffness", "1e6", "--dt", "-1"],
            "dt",
            "> 0",
        ),
        (
            vec!["--a", "1/2", "--stiffness", "1e6", "--dt", "1e300"],
            "dt",
            "longer than the contact time T_c = 1.894e-3 s",
        ),
        (
            vec!["--a", "1/2", "--stiffness", "1e6", "--steps", "1000000"],
            "steps",
            "beyond the limit 3e8",
        ),
        (
            vec!["--a", "1/2", "--stiffness", "1e4", "--dt", "1.6e-9"],
            "dt",
            "force evaluations",
        ),
        (
            vec!["--a", "1/2", "--stiffness", "1e300"],
            "stiffness",
            "event-rk4, whose cost does not grow with k",
        ),
        (
            vec!["--stiffness", "1e6"],
            "a",
            "slides off the end as the rod turns, so the exact geometry transfers no impulse: \
             hit inside the rod (--a 999/1000) or use --geometry frozen",
        ),
        (vec!["--sweep-k", "--a", "-1"], "a", "(--a -999/1000)"),
        (
            vec!["--sweep-k", "--a", "1/2", "--integrator", "midpoint"],
            "sweep-k",
            "the runs would take 4.7e8 force evaluations, beyond the limit 3e8",
        ),
    ] {
        let (code, out, err) = simulate(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with(&format!("error: {field}: ")), "{err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    // The frozen geometry has no end to slide off: a = l runs.
    let (code, out, _) = simulate(&["--stiffness", "1e6", "--geometry", "frozen"]);
    assert_eq!(code, 0, "{out}");
}

/// RELIABILITY F11: a run that does not reproduce the exact values exits 1 with the reason,
/// instead of 0: a point sliding off near the end, an explicit method beyond its stability
/// limit, a step too coarse to check anything.
#[test]
fn a_miss_exits_one_with_the_reason() {
    for (args, reason) in [
        (
            vec![
                "--a",
                "0.9999",
                "--stiffness",
                "1e3",
                "--integrator",
                "event-rk4",
            ],
            "event-rk4: the point slid past the rod's end during the contact",
        ),
        (
            vec![
                "--a",
                "1/2",
                "--stiffness",
                "1e6",
                "--integrator",
                "verlet",
                "--dt",
                "1.5e-3",
            ],
            "verlet: h Omega = 2.487 is beyond the method's stability limit 2",
        ),
        (
            vec![
                "--a",
                "1/2",
                "--stiffness",
                "1e6",
                "--dt",
                "1e-3",
                "--integrator",
                "rk4",
            ],
            "rk4: the tolerance 8.8e-1 (the integrator's error) is above 0.1",
        ),
        (
            vec![
                "--a",
                "1/2",
                "--stiffness",
                "1e2",
                "--integrator",
                "event-rk4",
            ],
            "the tolerance 4.3e-1 (the model's distance from the impulse) is above 0.1, too \
             loose to check the impulse: raise --stiffness",
        ),
    ] {
        let (code, out, err) = simulate(&args);
        assert_eq!(code, 1, "{args:?}: {out}{err}");
        assert!(err.is_empty(), "{err}");
        assert!(
            out.contains("MISS: the run misses the exact values:"),
            "{out}"
        );
        assert!(out.contains(reason), "{args:?}: {out}");
    }
    let (code, out, _) = simulate(&["--a", "0.9999", "--stiffness", "1e3", "--json"]);
    assert_eq!(code, 1);
    let doc = json(&out);
    assert_eq!(doc["ok"], false);
    assert_eq!(doc["runs"][4]["ending"], "slid off the rod's end");
}

/// `simulate --help` advertises only what works: the scene flags (pivot and inelastic
/// included, both simulated now) and no flag that is refused outright.
#[test]
fn help_lists_the_flags_that_work() {
    let (code, out, _) = rodimpact(&["simulate", "--help"]);
    assert_eq!(code, 0);
    for flag in ["--pivot", "--inelastic", "--stiffness", "--sweep-k", "--dt"] {
        assert!(out.contains(flag), "{flag}");
    }
    assert!(out.contains("e = 0 glues"), "{out}");
}
