//! The `solve` command-line contract: JSON keys and value forms, exit codes, one-line errors.

use crate::common;

use common::{rodimpact, solve_json};

#[test]
fn paper_example_m_equals_m_hit_at_the_end() {
    let j = solve_json(&["--m", "1", "--M", "1", "--a", "1"]);
    assert_eq!(j["v"]["exact"], "3/5");
    assert_eq!(j["V"]["exact"], "2/5");
    assert_eq!(j["omega"]["exact"], "6/5");
    assert_eq!(j["v"]["decimal"], "0.600000000000000000000000000000");
    for law in ["linear_momentum", "angular_momentum", "energy"] {
        assert_eq!(j["residuals"][law], "0", "{law}");
    }
    assert_eq!(j["a_star"]["squared"], "2/3");
    // Surds in the one canonical form: square factors out, no denominator under the root.
    assert_eq!(j["a_star"]["exact"], "sqrt(6)/3");
    assert_eq!(j["a_star"]["decimal"], "0.816496580927726032732428024902");
    assert_eq!(j["a_star"]["within_rod"], true);
    assert_eq!(j["argmax"], "a_star");
    assert_eq!(j["omega_max"]["exact"], "sqrt(6)/2");
    assert_eq!(j["omega_max"]["decimal"], "1.22474487139158904909864203735");
    assert_eq!(j["energy"]["before"]["exact"], "1/2");
    assert_eq!(j["energy"]["lost"]["exact"], "0");
    assert!(j.get("pivot_impulse").is_none());
    // Beyond the contract: placement, threshold, the end-hit ratio and the paper's f(x) form.
    assert_eq!(j["a_star"]["placement"], "inside");
    assert_eq!(j["a_star"]["threshold_M"], "2");
    assert_eq!(j["end_over_max"]["exact"], "2*sqrt(6)/5");
    assert_eq!(j["gain"]["exact"], "-1 + 5*sqrt(6)/12");
    assert_eq!(j["paper_form"]["b_squared"], "2/3");
    assert_eq!(j["paper_form"]["verified"], true);
}

#[test]
fn a_star_bounds_enclose_and_meet_the_precision() {
    use rodimpact::number::parse;
    let j = solve_json(&["--m", "1", "--M", "1", "--digits", "40"]);
    let lower = parse(j["a_star"]["lower"].as_str().unwrap()).unwrap();
    let upper = parse(j["a_star"]["upper"].as_str().unwrap()).unwrap();
    let two_thirds = rodimpact::field::q(2, 3);
    assert!(&lower * &lower <= two_thirds && two_thirds <= &upper * &upper);
    // upper - lower <= 10^-40 a*, and a* < 1 here.
    let tolerance = rodimpact::field::Q::new(1.into(), num_bigint::BigInt::from(10).pow(40));
    assert!(upper - lower <= tolerance);
}

#[test]
fn pivoted_sticking_scene_reports_the_pivot_impulse_not_momentum() {
    let j = solve_json(&[
        "--m",
        "1",
        "--M",
        "3",
        "--a",
        "1",
        "--pivot",
        "0",
        "--inelastic",
    ]);
    assert_eq!(j["v"]["exact"], "1/2");
    assert_eq!(j["V"]["exact"], "0");
    assert_eq!(j["omega"]["exact"], "1/2");
    assert_eq!(j["pivot_impulse"]["exact"], "-1/2");
    assert_eq!(j["energy"]["lost"]["exact"], "1/4");
    let residuals = j["residuals"].as_object().unwrap();
    assert_eq!(residuals.keys().collect::<Vec<_>>(), ["angular_momentum"]);
    assert_eq!(j["residuals"]["angular_momentum"], "0");
    // I_p = I + M p^2 = 1, d*^2 = I_p/m = 1: the optimum is the end (distance 1 from the pivot).
    assert_eq!(j["a_star"]["squared"], "1");
    assert_eq!(j["a_star"]["within_rod"], true);
}

/// Regression (oracle finding of issue 33): on a pivot, the maximum was reported over the struck
/// arm only, unnamed. m = M = l = 1, pivot p = 1/2, I_p = 1/3 + 1/4 = 7/12 = m d*^2, so
/// d* = sqrt(21)/6 ~ 0.764. Struck at a = 3/4, the struck arm is 1/2 long and omega(d) =
/// 2 d/(7/12 + d^2) peaks at its end, 1/(5/6) = 6/5; the other arm (3/2 long) holds d*, where
/// omega = 1/d* = 2 sqrt(21)/7 ~ 1.309 (striking a = -1/4 gives 72/55 ~ 1.30909, just below).
#[test]
fn a_pivoted_rod_reports_the_struck_arm_and_the_whole_rod() {
    let j = solve_json(&["--m", "1", "--M", "1", "--pivot", "1/2", "--a", "3/4"]);
    assert_eq!(j["a_star"]["squared"], "7/12");
    assert_eq!(j["argmax"], "end");
    assert_eq!(j["omega_max"]["exact"], "6/5");
    assert_eq!(j["rod_omega_max"]["exact"], "2*sqrt(21)/7");
    assert_eq!(j["rod_omega_max"]["arm"], "other");
    assert_eq!(j["rod_omega_max"]["argmax"], "a_star");
    assert_eq!(j["rod_omega_max"]["other_arm"], "3/2");
    let (code, text, _) = rodimpact(&[
        "solve", "--m", "1", "--M", "1", "--pivot", "1/2", "--a", "3/4",
    ]);
    assert_eq!(code, 0);
    assert!(
        text.contains("max |omega| on the struck arm, reached at the end"),
        "{text}"
    );
    assert!(
        text.contains("max |omega| over the rod, at d* on the other arm"),
        "{text}"
    );
    // Struck on the long arm, the struck arm's maximum is the rod's.
    let j = solve_json(&["--m", "1", "--M", "1", "--pivot", "1/2", "--a", "-1/4"]);
    assert_eq!(j["omega_max"]["exact"], "2*sqrt(21)/7");
    assert_eq!(j["rod_omega_max"]["arm"], "struck");
    // A pivot at an end leaves one arm, and a free rod's halves mirror each other.
    assert!(
        solve_json(&["--m", "1", "--M", "1", "--pivot", "1"])
            .get("rod_omega_max")
            .is_none()
    );
    assert!(
        solve_json(&["--m", "1", "--M", "1"])
            .get("rod_omega_max")
            .is_none()
    );
}

#[test]
fn heavy_rod_peaks_at_the_end() {
    let j = solve_json(&["--m", "1", "--M", "3"]);
    assert_eq!(j["a_star"]["squared"], "4/3");
    assert_eq!(j["a_star"]["within_rod"], false);
    assert_eq!(j["argmax"], "end");
    assert_eq!(j["omega_max"]["exact"], j["omega"]["exact"]);
}

#[test]
fn textbook_inputs_convert_exactly() {
    let j = solve_json(&[
        "--m",
        "0.05",
        "--M",
        "1.2",
        "--length",
        "1.5",
        "--from-end",
        "0.25",
        "--v0",
        "75/9.8",
        "--e",
        "1/2",
        "--rod",
        "dumbbell",
    ]);
    assert_eq!(j["scene"]["l"], "3/4");
    assert_eq!(j["scene"]["a"], "1/2");
    assert_eq!(j["scene"]["v0"], "375/49");
    assert_eq!(j["scene"]["I"], "27/40");
    assert!(
        j["residuals"].get("energy").is_none(),
        "no energy residual for e < 1"
    );
}

#[test]
fn text_report_is_readable() {
    let (code, stdout, _) = rodimpact(&["solve", "--m", "1", "--M", "1"]);
    assert_eq!(code, 0);
    for needle in [
        "free rod",
        "uniform rod",
        "elastic",
        "3/5",
        "6/5",
        "sqrt(6)/3",
        "on the rod",
    ] {
        assert!(stdout.contains(needle), "missing {needle} in\n{stdout}");
    }
}

#[test]
fn bad_inputs_exit_2_with_one_line_naming_the_field() {
    let long = "1".repeat(20_000);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--m", "-1", "--M", "1"], "m: must be > 0"),
        (vec!["--m", "1/0", "--M", "1"], "m: division by zero"),
        (vec!["--m", "NaN", "--M", "1"], "m: "),
        (vec!["--m", "inf", "--M", "1"], "m: "),
        (vec!["--m", "", "--M", "1"], "m: empty"),
        (vec!["--m", "abc", "--M", "1"], "m: "),
        (
            vec!["--m", "1", "--M", "1", "--a", "2"],
            "a: must lie on the rod",
        ),
        (vec!["--m", "1e999999999", "--M", "1"], "m: exponent"),
        (
            vec!["--m", long.as_str(), "--M", "1"],
            "m: more than 10000 digits",
        ),
        (vec!["--m", "1", "--M", "1", "--e", "2"], "e: "),
        (vec!["--m", "1", "--M", "1", "--pivot", "3"], "pivot: "),
        (vec!["--m", "1", "--M", "1", "--rod", "rg=2"], "rod: "),
        (vec!["--m", "1", "--M", "1", "--rod", "I=7"], "rod: "),
        (vec!["--m", "1", "--M", "1", "--rod", "glass"], "rod: "),
        (vec!["--M", "1"], "m: required"),
        (vec!["--m", "1", "--M", "1", "--digits", "0"], "digits: "),
        (
            vec!["--m", "1", "--M", "1", "--l", "1", "--length", "2"],
            "length: ",
        ),
        (
            vec!["--m", "1", "--M", "1", "--e", "1", "--inelastic"],
            "--inelastic",
        ),
        (vec!["--m", "1", "--M", "1", "--bogus", "1"], "--bogus"),
    ];
    for (args, needle) in cases {
        let mut all = vec!["solve"];
        all.extend_from_slice(&args);
        let (code, stdout, stderr) = rodimpact(&all);
        assert_eq!(code, 2, "exit code for {args:?}; stderr {stderr}");
        assert!(stdout.is_empty(), "nothing on stdout for {args:?}");
        assert_eq!(
            stderr.trim_end().lines().count(),
            1,
            "one line for {args:?}: {stderr}"
        );
        assert!(
            stderr.contains(needle),
            "{needle:?} in {stderr:?} for {args:?}"
        );
        assert!(!stderr.contains("panicked"), "{args:?}");
    }
}

/// The CSV of one table is a rectangular file whose header names each column with its units;
/// every exact value has its decimal beside it.
#[test]
fn table_csv_gives_the_paper_case_exactly() {
    let (code, stdout, stderr) =
        rodimpact(&["table", "--format", "csv", "--only", "T1", "--ratios", "1"]);
    assert_eq!(code, 0, "{stderr}");
    let mut lines = stdout.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        header,
        [
            "M/m",
            "M/m_decimal",
            "a_star^2/l^2",
            "a_star^2/l^2_decimal",
            "a_star/l",
            "a_star/l_decimal",
            "a_star_position",
            "omega_end/omega_max",
            "omega_end/omega_max_decimal"
        ]
    );
    let row: Vec<&str> = lines.next().expect("the M/m = 1 row").split(',').collect();
    assert_eq!(
        row,
        [
            "1",
            "1.0000000000000000",
            "2/3",
            "0.66666666666666667",
            "sqrt(6)/3",
            "0.81649658092772603",
            "inside",
            "2*sqrt(6)/5",
            "0.97979589711327124"
        ]
    );
    assert_eq!(lines.next(), None);
}

#[test]
fn a_star_bounds_are_fifty_digits_tight_when_asked() {
    let j = solve_json(&["--m", "1", "--M", "1", "--digits", "50"]);
    let lower = j["a_star"]["lower"].as_str().unwrap();
    let upper = j["a_star"]["upper"].as_str().unwrap();
    // sqrt(2/3) = 0.81649658092772603273242802490196379732198249355222337614423...
    assert!(
        lower.starts_with("0.8164965809277260327324280249019637973219824935522"),
        "{lower}"
    );
    assert!(
        upper.starts_with("0.8164965809277260327324280249019637973219824935522"),
        "{upper}"
    );
}

#[test]
fn plots_are_written_and_bad_figures_refused() {
    let dir = crate::common::scratch("plot");
    std::fs::create_dir_all(&dir).unwrap();
    for figure in ["omega", "optimum", "figure1"] {
        let out = dir.join(format!("{figure}.svg"));
        let (code, _, stderr) = rodimpact(&["plot", figure, "--out", out.to_str().unwrap()]);
        assert_eq!(code, 0, "{stderr}");
        assert!(std::fs::read_to_string(&out).unwrap().starts_with("<svg"));
    }
    let (code, _, stderr) = rodimpact(&["plot", "omega", "--ratios", "1,-2", "--out", "x.svg"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("ratios: "), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// docs/stability.md: v = 0 exactly (q = e), so the f64 v is flagged unreliable while V
/// and omega stay reliable; every value carries float, exact, rel_error and cond.
#[test]
fn backend_f64_flags_the_stopping_projectile_as_unreliable() {
    let j = solve_json(&[
        "--backend",
        "f64",
        "--m",
        "4/7",
        "--M",
        "1",
        "--l",
        "1",
        "--a",
        "1/2",
    ]);
    assert_eq!(j["backend"], "f64/sq");
    assert_eq!(j["v"]["exact"], "0");
    assert_eq!(j["v"]["cond"], "inf");
    assert_eq!(j["v"]["reliable"], false);
    assert_eq!(j["V"]["exact"], "4/7");
    assert_eq!(j["V"]["float"], "0.5714285714285714");
    assert_eq!(j["V"]["reliable"], true);
    assert_eq!(j["omega"]["reliable"], true);
    assert!(j["a_star"]["squared"].is_string(), "the exact keys stay");
}

#[test]
fn backend_interval_encloses_and_pivot_with_a_float_backend_is_refused() {
    let j = solve_json(&[
        "--backend",
        "interval",
        "--m",
        "1/3",
        "--M",
        "1",
        "--a",
        "1/2",
    ]);
    for key in ["v", "V", "omega"] {
        assert_eq!(j[key]["encloses"], true, "{key}");
    }
    let (code, stdout, stderr) = rodimpact(&[
        "solve",
        "--backend",
        "f32",
        "--m",
        "1",
        "--M",
        "1",
        "--pivot",
        "0",
    ]);
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1);
    assert!(stderr.starts_with("error: backend:"), "{stderr}");
}

/// Regression (NEWCOMER #23): the text report said "on the rod when (this I/M)  M <= 2, i.e.
/// M/m <= 2", printed the verifier's internals (`K  omega = K x/(b^2 + c^2 x^2)`, `b^2  c = 1;
/// identity in x: checked`) and named the float formula only as "f64/sq".
#[test]
fn text_report_speaks_to_students() {
    let (code, out, _) = rodimpact(&["solve", "--m", "1", "--M", "1"]);
    assert_eq!(code, 0);
    let line = |start: &str| {
        out.lines()
            .find(|l| l.trim_start().starts_with(start))
            .unwrap_or_else(|| panic!("no line {start:?} in\n{out}"))
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
    };
    assert_eq!(
        line("a* is on the rod when"),
        "a* is on the rod when M ≤ 2m (here M = m)"
    );
    assert_eq!(line("on the rod"), "on the rod inside: a* < l = 1 m");
    assert!(!out.contains("b^2") && !out.contains("K x/") && !out.contains("identity in x"));
    // r_G = l/2: a*^2 = r_G^2 (M + m)/m <= l^2 iff M <= m (l^2 - r_G^2)/r_G^2 = 3m.
    let (_, out, _) = rodimpact(&["solve", "--m", "2", "--M", "3", "--rod", "rg=1/2"]);
    assert!(out.contains("M ≤ 3m (here M = (3/2)m)"), "{out}");
    let (_, out, _) = rodimpact(&["solve", "--m", "1", "--M", "1", "--rod", "dumbbell"]);
    assert!(
        out.contains("never: with r_G = l, a* lies beyond the end for every M"),
        "{out}"
    );
    let (_, out, _) = rodimpact(&["solve", "--backend", "f64", "--m", "4/7", "--M", "1"]);
    assert!(
        out.contains("Backend f64: IEEE binary64 with the stable formula \"sq\" (the closed form with exact power-of-two rescaling"),
        "{out}"
    );
}

/// Regression (NEWCOMER #26): `solve --m 1e400` printed the 401-digit integer in the scene
/// line (and fractions of hundreds of digits in the table); the text now shows compact forms
/// and the JSON keeps every exact digit.
#[test]
fn huge_numbers_are_compact_in_text_and_exact_in_json() {
    let (code, out, _) = rodimpact(&["solve", "--m", "1e400", "--M", "1"]);
    assert_eq!(code, 0);
    assert!(out.contains("  m = 1e400 kg, M = 1 kg,"), "{out}");
    assert!(out.lines().all(|l| l.chars().count() < 120), "{out}");
    // v = (m - M/4)/(m + M/4) for an elastic end hit: just below 1, shown as a decimal.
    assert!(out.contains("≈ 1.00000000000000 m/s"), "{out}");
    let j = solve_json(&["--m", "1e400", "--M", "1"]);
    assert_eq!(j["scene"]["m"], format!("1{}", "0".repeat(400)));
    assert_eq!(
        j["v"]["exact"],
        // (m - M/4)/(m + M/4) = (4e400 - 1)/(4e400 + 1)
        format!("3{}/4{}1", "9".repeat(400), "0".repeat(399))
    );
}
