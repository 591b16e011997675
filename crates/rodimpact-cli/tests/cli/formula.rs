//! `rodimpact formula` against formulas derived by hand, independently of the solver:
//! free rod, elastic, omega = (1 + e) m a v0/(I (1 + m/M) + m a^2); V = (1 + e) (m/M) v0/D';
//! pivoted rod, omega = (1 + e) m d v0/(I + M p^2 + m d^2) with d = a - p; the energy lost
//! (1 - e^2) v0^2/(2 (1/m + 1/M + a^2/I)); a*^2 = I (M + m)/(m M); omega_max = (1 + e) v0/(2 a*).
//! Each printed formula is parsed back and compared as an exact rational function (so the test
//! does not depend on the order the terms are printed in).

use rodimpact::textbook::expr::{Radical, parse};
use std::process::Command;

fn formula_json(args: &[&str]) -> serde_json::Value {
    let out = crate::common::output([&["formula"], args, &["--format", "json"]].concat());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// `rodimpact formula ARGS` as it ran (any exit code).
fn run(args: &[&str]) -> std::process::Output {
    crate::common::output([&["formula"], args].concat())
}

fn value(text: &str) -> Radical {
    parse("test", text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// `coeff^2 * radicand`, to compare roots written with different factors outside the root.
fn square(r: &Radical) -> rodimpact::field::RatFn {
    r.coeff.clone() * &r.coeff * &r.radicand
}

fn assert_formula(j: &serde_json::Value, key: &str, expected: &str) {
    let got = j[key]["text"]
        .as_str()
        .unwrap_or_else(|| panic!("no {key} in {j}"));
    assert_eq!(
        square(&value(got)),
        square(&value(expected)),
        "{key}: got {got}, expected {expected}"
    );
}

#[test]
fn free_uniform_rod_elastic_the_paper() {
    let j = formula_json(&[]);
    assert_eq!(
        j["free_symbols"],
        serde_json::json!(["m", "M", "l", "a", "v0"])
    );
    let d = "(M*l^2/3*(1+m/M) + m*a^2)";
    assert_formula(&j, "omega", &format!("2*m*a*v0/{d}"));
    assert_formula(&j, "V", &format!("2*(m/M)*v0*(M*l^2/3)/{d}"));
    assert_formula(
        &j,
        "v",
        "-(1-m/M-3*m*a^2/(M*l^2))/(1+m/M+3*m*a^2/(M*l^2))*v0",
    );
    assert_formula(&j, "impulse", &format!("2*m*(M*l^2/3)*v0/{d}"));
    assert_formula(&j, "a_star_squared", "(M+m)*l^2/(3*m)");
    assert_formula(&j, "omega_max", "v0/sqrt((M+m)*l^2/(3*m))");
    assert!(j.get("energy_lost").is_none(), "elastic: nothing lost");
    assert!(j.get("pivot_impulse").is_none(), "free rod: no pivot");
    assert_eq!(
        j["omega_max"]["condition"],
        "when M <= 2*m (a* on the rod); otherwise omega_max = omega(end) = 6*m*v0/(M*l + 4*l*m)"
    );
    assert_eq!(
        j["omega"]["latex"],
        r"\frac{6 a m v_0}{M l^{2} + 3 a^{2} m + l^{2} m}"
    );
}

#[test]
fn dumbbell_gyration_and_threshold_mass() {
    let dumbbell = formula_json(&["--rod", "dumbbell"]);
    assert_formula(&dumbbell, "omega", "2*m*a*v0/(M*l^2 + m*l^2 + m*a^2)");
    assert!(
        dumbbell["omega_max"]["condition"]
            .as_str()
            .unwrap()
            .starts_with("never")
    );
    let rg = formula_json(&["--rod", "rg=r"]);
    assert_formula(&rg, "omega", "2*m*a*v0/(M*r^2 + m*r^2 + m*a^2)");
    assert_formula(&rg, "a_star_squared", "(M+m)*r^2/m");
    // M = 2m: a* is the end exactly, for every m and l: no condition left.
    let threshold = formula_json(&["--M", "2*m"]);
    assert_formula(&threshold, "a_star_squared", "l^2");
    assert!(threshold["omega_max"].get("condition").is_none());
}

#[test]
fn restitution_sticking_and_pivot() {
    let e = formula_json(&["--rod", "rg=r", "--e", "e"]);
    assert_formula(&e, "omega", "(1+e)*m*a*v0/(M*r^2 + m*r^2 + m*a^2)");
    assert_formula(
        &e,
        "energy_lost",
        "(1-e^2)*v0^2/(2*(1/m + 1/M + a^2/(M*r^2)))",
    );
    assert_formula(&e, "omega_max", "(1+e)*v0/(2*sqrt((M+m)*r^2/m))");
    let half = formula_json(&["--e", "1/2", "--M", "m", "--a", "l"]);
    assert_formula(&half, "omega", "(3/2)*m*l*v0/(m*l^2/3*2 + m*l^2)");
    // Sticking on a pivot at p: omega = m d v0/(I + M p^2 + m d^2), d = a - p.
    let pivot = formula_json(&["--pivot", "p", "--e", "0"]);
    assert_formula(&pivot, "omega", "m*(a-p)*v0/(M*l^2/3 + M*p^2 + m*(a-p)^2)");
    assert_formula(&pivot, "a_star_squared", "(M*l^2/3 + M*p^2)/m");
    assert_formula(&pivot, "omega_max", "v0/(2*sqrt((M*l^2/3 + M*p^2)/m))");
    assert!(pivot.get("pivot_impulse").is_some() && pivot.get("energy_lost").is_some());
}

#[test]
fn every_format_renders_and_bad_input_is_refused() {
    let text = String::from_utf8(run(&[]).stdout).unwrap();
    assert!(
        text.contains("omega = 6*a*m*v0/(M*l^2 + 3*a^2*m + l^2*m)"),
        "{text}"
    );
    let latex = String::from_utf8(run(&["--format", "latex"]).stdout).unwrap();
    assert!(
        latex.contains(r"\begin{align*}")
            && latex.contains(r"\omega_{\max} &= \begin{cases} \displaystyle \frac{v_0}{l} \sqrt{")
    );
    let md = String::from_utf8(run(&["--format", "markdown"]).stdout).unwrap();
    assert!(md.contains("| `a_star_squared` |"));
    for (args, message) in [
        (
            &["--format", "pdf"][..],
            "error: format: expected text, latex, markdown or json, got 'pdf'\n",
        ),
        (
            &["--M", "2*q"][..],
            "error: M: unknown symbol 'q' at character 3 (symbols: m M l L a d v0 e p I r, oblique v0t mu rd w V0 Vt0 omega0, function sqrt)\n",
        ),
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2));
        assert_eq!(String::from_utf8(out.stderr).unwrap(), message);
    }
}

/// A rational omega_max where a* = l: `sqrt(1/l^2)` is written `1/l` (the README's example;
/// the console test holds the whole transcript).
#[test]
fn omega_max_at_the_threshold_is_rational() {
    let out = run(&["--M", "2*m", "--e", "e"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("omega_max = (1/2*e*v0 + 1/2*v0)/l"), "{text}");
}

/// An oblique frictional scene in symbols, against the impulse balance worked by hand: the
/// tangential impulse acts along the rod through its centre, so omega is the frictionless one;
/// sticking takes Jt = u_t/k_t with u_t = v0t and k_t = 1/m + 1/M, sliding takes Jt = mu J; the
/// threshold is mu* = u_t/(J k_t) with J = (1 + e) v0/(1/m + 1/M + a^2/I), I = M l^2/3.
#[test]
fn oblique_friction_in_symbols() {
    let j = formula_json(&["--v0t", "v0t", "--mu", "mu", "--e", "e"]);
    let paper = formula_json(&["--e", "e"]);
    for key in ["v", "V", "omega", "impulse", "a_star_squared"] {
        assert_eq!(j[key], paper[key], "{key} changed by v0t and mu");
    }
    let k_n = "(1/m + 1/M + 3*a^2/(M*l^2))";
    let big_j = format!("((1+e)*v0/{k_n})");
    assert_formula(&j, "mu_star", &format!("v0t/({big_j}*(1/m + 1/M))"));
    let stick = &j["cases"]["stick"];
    assert_formula(stick, "tangential_impulse", "v0t/(1/m + 1/M)");
    assert_formula(stick, "vt", "v0t - v0t/(1/m + 1/M)/m");
    assert_formula(stick, "Vt", "v0t/(1/m + 1/M)/M");
    // Lost: (1 - e^2) v0^2/(2 k_n) to restitution, u_t^2/(2 k_t) to friction.
    assert_formula(
        stick,
        "energy_lost",
        &format!("(1 - e^2)*v0^2/(2*{k_n}) + v0t^2/(2*(1/m + 1/M))"),
    );
    let slide = &j["cases"]["slide"];
    assert_formula(slide, "tangential_impulse", &format!("mu*{big_j}"));
    assert_formula(slide, "vt", &format!("v0t - mu*{big_j}/m"));
    assert_formula(slide, "Vt", &format!("mu*{big_j}/M"));
    assert_formula(
        slide,
        "energy_lost",
        &format!("(1 - e^2)*v0^2/(2*{k_n}) + mu*{big_j}*(v0t - mu*{big_j}*(1/m + 1/M)/2)"),
    );
    // The two parts of the loss: restitution once (the normal problem's), friction per case.
    assert_formula(
        &j,
        "energy_lost_restitution",
        &format!("(1 - e^2)*v0^2/(2*{k_n})"),
    );
    assert_formula(stick, "energy_lost_friction", "v0t^2/(2*(1/m + 1/M))");
    assert_formula(
        slide,
        "energy_lost_friction",
        &format!("mu*{big_j}*(v0t - mu*{big_j}*(1/m + 1/M)/2)"),
    );
    assert_eq!(stick["condition"], "mu >= mu_star");
    assert_eq!(slide["condition"], "mu < mu_star");
    let defaults = j["defaults"].as_array().unwrap();
    assert!(
        defaults.iter().any(|d| d
            .as_str()
            .unwrap()
            .starts_with("the slip before the impact, u_t = v0t, taken > 0")),
        "{j}"
    );
}

/// A spinning solid disc (I = m rd^2/2) struck on the paper's scene, by hand: the rim slips
/// with u_t = w rd, k_t = 1/m + rd^2/(m rd^2/2) + 1/M = 3/m + 1/M; sticking takes
/// Jt = w rd/k_t, and the spin drops by 2 Jt/(m rd) to w (M + m)/(3M + m).
#[test]
fn spinning_disc_in_symbols() {
    let j = formula_json(&["--radius", "rd", "--spin", "w", "--mu", "mu"]);
    let stick = &j["cases"]["stick"];
    assert_formula(stick, "spin", "w*(M + m)/(3*M + m)");
    assert_formula(stick, "tangential_impulse", "w*rd/(3/m + 1/M)");
    assert_formula(stick, "vt", "-w*rd/(3/m + 1/M)/m");
    assert_formula(stick, "energy_lost", "(w*rd)^2/(2*(3/m + 1/M))");
    assert_formula(&j, "omega", "2*m*a*v0/(M*l^2/3*(1+m/M) + m*a^2)");
}

/// X27 for every projectile: omega (and v, V, J) of the paper's scene, whatever the slide along
/// the rod, the friction and the disc's spin; a disc's spin is the only new answer besides the
/// tangential ones.
#[test]
fn omega_is_the_papers_whatever_the_slide_and_the_friction() {
    let paper = formula_json(&["--e", "e"]);
    for oblique in [
        &["--v0t", "v0t", "--mu", "mu"][..],
        &["--v0t", "v0t", "--mu", "1/3"],
        &[
            "--radius", "rd", "--spin", "w", "--v0t", "v0t", "--mu", "mu",
        ],
    ] {
        let j = formula_json(&[&["--e", "e"][..], oblique].concat());
        for key in ["v", "V", "omega", "impulse", "a_star_squared", "omega_max"] {
            assert_eq!(j[key], paper[key], "{key} changed by {oblique:?}");
        }
        for case in ["stick", "slide"] {
            for key in ["v", "V", "omega", "impulse"] {
                assert!(j["cases"][case].get(key).is_none(), "{key} split by {case}");
            }
        }
    }
}

/// A slip the symbols make negative (`--v0t -v0`) is taken < 0, not > 0: mu* = v0/(J k_t) is
/// positive and a sliding contact pushes the rod backwards, Jt = -mu J (J = (1 + e) v0/k_n, here
/// e = 1); sticking takes Jt = u_t/k_t = -v0/k_t as for either sign.
#[test]
fn a_negative_slip_is_taken_negative() {
    let j = formula_json(&["--v0t", "-v0", "--mu", "mu"]);
    let k_n = "(1/m + 1/M + 3*a^2/(M*l^2))";
    let big_j = format!("(2*v0/{k_n})");
    assert_formula(&j, "mu_star", &format!("v0/({big_j}*(1/m + 1/M))"));
    assert_formula(
        &j["cases"]["slide"],
        "tangential_impulse",
        &format!("-mu*{big_j}"),
    );
    assert_formula(
        &j["cases"]["stick"],
        "tangential_impulse",
        "-v0/(1/m + 1/M)",
    );
    let defaults = j["defaults"].to_string();
    assert!(
        defaults.contains("the slip before the impact, u_t = -v0, taken < 0"),
        "{defaults}"
    );
}

/// A rod moving before the impact: its approach at the contact, u_n = v0 - V0 (a centre hit),
/// is said to be taken > 0 when it is a formula, and a rod that never meets the projectile is
/// refused as `solve` refuses it, in numbers and in symbols.
#[test]
fn the_approach_of_a_moving_rod() {
    let j = formula_json(&["--a", "0", "--rod-v", "V0"]);
    assert_formula(&j, "impulse", "2*(v0 - V0)/(1/m + 1/M)");
    let defaults = j["defaults"].to_string();
    assert!(
        defaults.contains("the approach at the contact point, u_n = -V0 + v0, taken > 0"),
        "{defaults}"
    );
    let numbers = ["--m", "1", "--M", "1", "--v0", "1", "--rod-v", "2"];
    let out = run(&numbers);
    assert_eq!(out.status.code(), Some(2));
    let message = "error: v0: no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), is -1, not > 0\n";
    assert_eq!(String::from_utf8(out.stderr).unwrap(), message);
    let solved = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .arg("solve")
        .args(numbers)
        .output()
        .unwrap();
    assert_eq!(String::from_utf8(solved.stderr).unwrap(), message);
    let out = run(&["--rod-v", "2*v0"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "error: v0: no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), = -v0, is > 0 in no sample scene of the free symbols\n"
    );
}

/// Every quantity of a numeric oblique scene as `solve` gives it, and as worked by hand: m = 1,
/// M = 2, l = 1 (I = 2/3), a = 1/2, v0 = 3, e = 1/2; a disc r = 1/10 spinning at 4 with
/// v0t = 1; the rod moving with V0 = 1/2, Vt0 = 1/4, omega0 = 1. u_n = 3 - (1/2 + 1/2) = 2,
/// k_n = 1 + 1/2 + (1/4)/(2/3) = 15/8, J = (3/2) 2/(15/8) = 8/5; restitution loses
/// (3/4) 4/(2 15/8) = 4/5. u_t = 1 + 4/10 - 1/4 = 23/20, k_t = 3/m + 1/M = 7/2,
/// mu* = (23/20)/((8/5)(7/2)) = 23/112 > mu = 1/5: it slides, Jt = 8/25, vt = 17/25,
/// Vt = 1/4 + 4/25 = 41/100, spin = 4 - 2 (8/25)/(1/10) = -12/5, friction loses
/// (8/25)(23/20 - (8/25)(7/4)) = 118/625; v = 3 - 8/5, V = 1/2 + 4/5, omega = 1 + (1/2)(8/5)/(2/3).
#[test]
fn a_numeric_oblique_scene_as_solve_and_by_hand() {
    let scene = [
        "--m",
        "1",
        "--M",
        "2",
        "--l",
        "1",
        "--a",
        "1/2",
        "--v0",
        "3",
        "--e",
        "1/2",
        "--v0t",
        "1",
        "--mu",
        "1/5",
        "--radius",
        "1/10",
        "--spin",
        "4",
        "--rod-v",
        "1/2",
        "--rod-vt",
        "1/4",
        "--rod-omega",
        "1",
    ];
    let f = formula_json(&scene);
    let solved = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .arg("solve")
        .args(scene)
        .arg("--json")
        .output()
        .unwrap();
    let solved: serde_json::Value = serde_json::from_slice(&solved.stdout).unwrap();
    for (key, by_hand) in [
        ("v", "7/5"),
        ("V", "13/10"),
        ("omega", "11/5"),
        ("impulse", "8/5"),
        ("mu_star", "23/112"),
        ("vt", "17/25"),
        ("Vt", "41/100"),
        ("spin", "-12/5"),
        ("tangential_impulse", "8/25"),
    ] {
        assert_eq!(f[key]["text"], by_hand, "{key}");
        assert_eq!(solved[key]["exact"], by_hand, "{key}");
    }
    for (key, solve_key, by_hand) in [
        ("energy_lost", "lost", "618/625"),
        ("energy_lost_restitution", "lost_restitution", "4/5"),
        ("energy_lost_friction", "lost_friction", "118/625"),
    ] {
        assert_eq!(f[key]["text"], by_hand, "{key}");
        assert_eq!(solved["energy"][solve_key]["exact"], by_hand, "{key}");
    }
    assert_eq!(
        (&f["contact"], &solved["contact"]),
        (&"slide".into(), &"slide".into())
    );
}

/// Numbers decide the contact: equal masses, a centre hit at v0 = 1 with v0t = 1 and
/// mu = 1/4 slides (mu* = 1/2), as `solve` says; with mu = 1 it sticks.
#[test]
fn numbers_decide_the_contact_as_solve_does() {
    let scene = [
        "--m", "1", "--M", "1", "--a", "0", "--v0", "1", "--v0t", "1",
    ];
    let slide = formula_json(&[&scene[..], &["--mu", "1/4"]].concat());
    assert_eq!(slide["contact"], "slide");
    assert!(slide["cases"].is_null());
    let solved = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .arg("solve")
        .args(scene)
        .args(["--mu", "1/4", "--json"])
        .output()
        .unwrap();
    let solved: serde_json::Value = serde_json::from_slice(&solved.stdout).unwrap();
    for key in ["v", "V", "omega", "vt", "Vt", "tangential_impulse"] {
        assert_eq!(slide[key]["text"], solved[key]["exact"], "{key}");
    }
    assert_formula(&slide, "mu_star", "1/2");
    let stick = formula_json(&[&scene[..], &["--mu", "1"]].concat());
    assert_eq!(stick["contact"], "stick");
    assert_formula(&stick, "tangential_impulse", "1/2");
}

/// The oblique symbols belong in the oblique flags; a claim of `check` refuses them.
#[test]
fn oblique_symbols_stay_in_their_flags() {
    let out = run(&["--M", "2*mu"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "error: M: mu may appear only in the oblique flags (--v0t, --mu, --radius, --spin, --rod-v, --rod-vt, --rod-omega)\n"
    );
    let out = run(&["--spin", "w"]);
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "error: spin: a point projectile has no spin: give the disc's --radius too\n"
    );
    let out = run(&["--mu", "-1/2"]);
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "error: mu: friction coefficient must be >= 0, got -1/2\n"
    );
}

/// Regression (G11): `--mu -mu` and `--radius -rd` were accepted (slide formulas with a negative
/// friction coefficient, a disc of negative radius), though they are negative in every sample
/// scene, while `--M -m` and the numbers `--mu -1`, `--radius -1` were refused. Now a formula
/// positive in no sample scene is refused, naming the flag; one positive somewhere is not.
#[test]
fn symbolic_negative_friction_and_radius_are_refused() {
    for (args, want) in [
        (
            &["--v0t", "v0t", "--mu", "-mu"][..],
            "error: mu: friction coefficient must be >= 0, but mu = -mu is <= 0 in every sample scene of the free symbols\n",
        ),
        (
            &["--v0t", "v0t", "--mu", "-mu^2"][..],
            "error: mu: friction coefficient must be >= 0, but mu = -mu^2 is <= 0 in every sample scene of the free symbols\n",
        ),
        (
            &["--radius", "-rd", "--spin", "w", "--mu", "mu"][..],
            "error: radius: must be > 0, but radius = -rd is <= 0 in every sample scene of the free symbols\n",
        ),
        (
            &["--radius", "-l", "--spin", "w"][..],
            "error: radius: must be > 0, but radius = -l is <= 0 in every sample scene of the free symbols\n",
        ),
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8(out.stderr).unwrap(), want, "{args:?}");
        assert!(out.stdout.is_empty());
    }
    for args in [
        &["--v0t", "v0t", "--mu", "mu"][..],
        &["--v0t", "v0t", "--mu", "mu-1/2"][..],
        &["--v0t", "v0t", "--mu", "m-M"][..],
        &["--radius", "rd", "--spin", "w"][..],
        &["--radius", "l/2", "--spin", "w"][..],
    ] {
        let out = run(args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// Regression (G13): `formula --v0 -v0` said `error: e: circular definitions among e, v0`,
/// naming the default e, which the user never gave.
#[test]
fn a_circular_flag_is_named_itself() {
    let out = run(&["--v0", "-v0"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8(out.stderr).unwrap(),
        "error: v0: circular definitions among v0\n"
    );
}

/// Regression (oracle finding of issue 33): a rod drifting before the impact without turning
/// lost a*^2 and omega_max, though drift leaves a* where it is (X31). By hand: the approach is
/// u_n = v0 - V0 for every a, so omega(a) is the paper's curve with v0 - V0 for v0:
/// a*^2 = I (M + m)/(m M) = (M + m) l^2/(3 m), omega_max = 2 (v0 - V0)/(2 a*) = (v0 - V0)/a*.
/// Drift along the rod (`--rod-vt`) does not touch the normal problem at all.
#[test]
fn a_drifting_rod_keeps_its_optimum() {
    let j = formula_json(&["--rod-v", "V0"]);
    assert_formula(&j, "a_star_squared", "(M + m)*l^2/(3*m)");
    assert_formula(&j, "omega_max", "(v0 - V0)/sqrt((M + m)*l^2/(3*m))");
    let along = formula_json(&["--rod-vt", "1"]);
    assert_formula(&along, "a_star_squared", "(M + m)*l^2/(3*m)");
    assert_formula(&along, "omega_max", "v0/sqrt((M + m)*l^2/(3*m))");
    // A turning rod has no such optimum: the approach depends on a.
    let turning = formula_json(&["--rod-omega", "w"]);
    assert!(turning.get("a_star_squared").is_none(), "{turning}");
}

/// Regression (oracle finding of issue 33): `--M m --a l --v0t v0 --mu 2` printed mu* = 5/4
/// and then both a sticking and a sliding answer. On the paper's end hit with M = m, J =
/// (2/5) m v0 and sticking takes Jt = u_t/k_t = v0/(2/m) = m v0/2, so mu* = (1/2)/(2/5) = 5/4
/// for every m and v0: mu = 2 sticks (vt = Vt = v0/2), mu = 1 slides (Jt = mu J = (2/5) m v0,
/// vt = v0 - 2/5 v0 = 3/5 v0), and mu = 5/4 just sticks.
#[test]
fn a_numeric_margin_over_mu_star_decides_the_contact() {
    for (mu, contact, vt) in [
        ("2", "stick", "v0/2"),
        ("5/4", "stick", "v0/2"),
        ("1", "slide", "3*v0/5"),
    ] {
        let j = formula_json(&["--M", "m", "--a", "l", "--v0t", "v0", "--mu", mu]);
        assert_formula(&j, "mu_star", "5/4");
        assert_eq!(j["contact"], contact, "mu = {mu}: {j}");
        assert!(
            j.get("cases")
                .is_none_or(|c| c.as_object().is_none_or(|o| o.is_empty())),
            "mu = {mu}: {j}"
        );
        assert_formula(&j, "vt", vt);
    }
}

/// The canonical surd (oracle finding of issue 33): an integer free of squares under the root,
/// positive symbols' even powers outside: omega_max = v0/a* with a*^2 = 2 l^2/3 is
/// v0 sqrt(3/2)/l = sqrt(6) v0/(2 l), printed `(1/2*v0/l)*sqrt(6)`, not `(v0)*sqrt(3/2/l^2)`.
#[test]
fn omega_max_is_printed_as_a_canonical_surd() {
    let text = String::from_utf8(run(&["--M", "m"]).stdout).unwrap();
    assert!(text.contains("omega_max = (1/2*v0/l)*sqrt(6)\n"), "{text}");
    let j = formula_json(&["--M", "m"]);
    assert_formula(&j, "omega_max", "v0*sqrt(3/2)/l");
    let latex = String::from_utf8(run(&["--M", "m", "--format", "latex"]).stdout).unwrap();
    assert!(
        latex.contains(r"\omega_{\max} &= \frac{v_0}{2 l} \sqrt{6}"),
        "{latex}"
    );
}

/// The oracle finding of issue 33: `r` was refused in `--a`. Struck at its own radius of
/// gyration r (I = M r^2), a free rod spins at, by hand, omega = (1 + e) m a v0/(I (1 + m/M) +
/// m a^2) with a = r: 2 m v0/((M + 2m) r); a*^2 = I (M + m)/(m M) = (M + m) r^2/m.
#[test]
fn the_impact_point_may_be_the_radius_of_gyration() {
    let j = formula_json(&["--rod", "rg=r", "--a", "r"]);
    assert_formula(&j, "omega", "2*m*v0/((M + 2*m)*r)");
    assert_formula(&j, "a_star_squared", "(M + m)*r^2/m");
    // A dumbbell's r is l: struck at r is struck at the end.
    let dumbbell = formula_json(&["--rod", "dumbbell", "--a", "r"]);
    let end = formula_json(&["--rod", "dumbbell", "--a", "l"]);
    assert_eq!(dumbbell["omega"], end["omega"]);
    for (args, message) in [
        (
            &["--a", "r"][..],
            "error: a: r stands for the rod's radius of gyration, which is not rational for this rod (uniform: l/sqrt(3)); give it with --rod rg=...\n",
        ),
        (
            &["--rod", "rg=a/2", "--a", "r"],
            "error: a: circular definitions: a uses r, which the rod defines through a\n",
        ),
        (
            &["--v0", "r"],
            "error: v0: r may appear only in --rod, --a, --from-end, --pivot and in claims\n",
        ),
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(String::from_utf8(out.stderr).unwrap(), message, "{args:?}");
    }
}

/// NEWCOMER m3 and m21: the format names have the same aliases everywhere (`md`, `tex`,
/// `txt`), and `formula`'s summary in `rodimpact --help` is one line.
#[test]
fn format_aliases_are_the_same_everywhere() {
    let md = run(&["--format", "md"]);
    assert_eq!(md.stdout, run(&["--format", "markdown"]).stdout);
    assert_eq!(
        run(&["--format", "tex"]).stdout,
        run(&["--format", "latex"]).stdout
    );
    let explain = |format: &str| {
        crate::common::output(vec!["solve", "--m", "1", "--M", "1", "--explain", format]).stdout
    };
    assert_eq!(explain("md"), explain("markdown"));
    let stability = crate::common::output(vec!["stability", "--format", "markdown"]);
    assert!(stability.status.success());
    let help = String::from_utf8(crate::common::output(vec!["--help"]).stdout).unwrap();
    let line = help
        .lines()
        .find(|l| l.trim_start().starts_with("formula"))
        .unwrap();
    assert_eq!(
        line.trim(),
        "formula    The exact answer as formulas in the scene's free symbols (--M 2*m, --v0t v0t)"
    );
}

/// NEWCOMER M1: the case conditions are typeset with the formulas, not left in `%` comments:
/// omega_max as `cases` (v0/a* when M <= 2m, omega at the end 6 m v0/((M + 4m) l) otherwise),
/// and each contact case under an `\intertext` heading, so the LaTeX pasted into a handout
/// states when each block holds. (`pdflatex` compiles all three outputs with amsmath.)
#[test]
fn latex_typesets_the_case_conditions() {
    let latex = |args: &[&str]| {
        String::from_utf8(run(&[args, &["--format", "latex"]].concat()).stdout).unwrap()
    };
    let paper = latex(&[]);
    assert!(
        paper.contains(r"\omega_{\max} &= \begin{cases} \displaystyle \frac{v_0}{l} \sqrt{\frac{3 m}{M + m}} & \text{if } M \le 2 m \\ \displaystyle \frac{6 m v_0}{l \left(M + 4 m\right)} & \text{otherwise (at the end)} \end{cases}"),
        "{paper}"
    );
    // NEWCOMER m1: factored as a textbook prints it, the common monomial in front.
    assert!(
        paper.contains(r"a^{*2} &= \frac{l^{2} \left(M + m\right)}{3 m}"),
        "{paper}"
    );
    assert!(paper.contains(r"v &= \frac{v_0 \left(-M l^{2} + 3 a^{2} m + l^{2} m\right)}{M l^{2} + 3 a^{2} m + l^{2} m}"), "{paper}");
    assert!(
        !paper.contains("\n%"),
        "no condition left in a comment: {paper}"
    );
    let open = latex(&["--M", "m", "--a", "l", "--v0t", "v0t", "--mu", "mu"]);
    assert!(
        open.contains("\\\\\n  \\intertext{If it sticks ($\\mu \\ge \\mu^{*}$):}\n"),
        "{open}"
    );
    assert!(
        open.contains("\\\\\n  \\intertext{If it slides ($\\mu < \\mu^{*}$):}\n"),
        "{open}"
    );
    assert!(
        open.contains("taken $>$ 0"),
        "the default slip sign is printed: {open}"
    );
    // The energy lost while sliding, its common factor (2/25 m mu v0) in front.
    assert!(
        open.contains(r"\Delta E &= \frac{2}{25} m \mu v_0 \left(-2 \mu v_0 + 5 v_{0t}\right)"),
        "{open}"
    );
    let decided = latex(&["--M", "m", "--a", "l", "--v0t", "v0", "--mu", "2"]);
    assert!(
        decided.contains("\\intertext{The contact sticks:}"),
        "{decided}"
    );
}

/// NEWCOMER m2: `--standalone` makes `formula --format latex` and `solve --explain latex` a
/// complete document (pdflatex compiles both as they are), as `table --format latex` is;
/// without LaTeX it is refused.
#[test]
fn standalone_latex_is_a_complete_document() {
    let doc = String::from_utf8(run(&["--format", "latex", "--standalone"]).stdout).unwrap();
    assert!(
        doc.starts_with("\\documentclass{article}\n\\usepackage{amsmath}\n"),
        "{doc}"
    );
    assert!(
        doc.contains("\\begin{document}\n\n") && doc.ends_with("\\end{align*}\n\\end{document}\n"),
        "{doc}"
    );
    let working = crate::common::output(vec![
        "solve",
        "--m",
        "1",
        "--M",
        "1",
        "--explain",
        "latex",
        "--standalone",
    ]);
    let working = String::from_utf8(working.stdout).unwrap();
    assert!(
        working.starts_with("\\documentclass{article}") && working.ends_with("\\end{document}\n"),
        "{working}"
    );
    let refused = run(&["--standalone"]);
    assert_eq!(refused.status.code(), Some(2));
    assert_eq!(
        String::from_utf8(refused.stderr).unwrap(),
        "error: standalone: a complete document is LaTeX: add --format latex\n"
    );
}
