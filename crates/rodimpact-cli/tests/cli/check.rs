//! The `check` command-line contract: the issue's done-when commands, exit codes, JSON, limits.

use crate::common::rodimpact;
use serde_json::Value;

#[test]
fn disc_and_stick_agrees() {
    // m=2, M=1, L=4 (l=2), a=2 = the end, v0=3, elastic: I = 4/3, effective mass at the end
    // 1/(1 + 4/(4/3)) = 1/4; v = 3 (2 - 1/4)/(2 + 1/4) = 7/3, J = 4/3, V = 4/3, omega = 2.
    let (code, out, err) = rodimpact(&[
        "check",
        "--m",
        "2.0",
        "--M",
        "1.0",
        "--length",
        "4.0",
        "--a",
        "2.0",
        "--v0",
        "3.0",
        "--claim",
        "v=2.3",
        "--claim",
        "V=1.3",
        "--claim",
        "omega=2.0",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("7/3") && out.contains("3 of 3 claims agree"),
        "{out}"
    );
}

const STICKING: [&str; 12] = [
    "check",
    "--m",
    "0.100",
    "--M",
    "1.50",
    "--length",
    "2.00",
    "--from-end",
    "0",
    "--v0",
    "12.0",
    "--inelastic",
];

#[test]
fn sticking_projectile_right_and_halved_omega() {
    // Effective mass at the end 1/(1/1.5 + 1/0.5) = 3/8; J = 0.1 (3/8) 12/(0.1 + 3/8) = 18/19;
    // omega = J l / I = (18/19)/(1/2) = 36/19 = 1.8947...
    let mut args = STICKING.to_vec();
    args.extend(["--claim", "omega=1.89"]);
    let (code, out, _) = rodimpact(&args);
    assert_eq!(code, 0, "{out}");
    let mut args = STICKING.to_vec();
    args.extend(["--claim", "omega=0.947"]);
    let (code, out, _) = rodimpact(&args);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("36/19") && out.contains("DISAGREES"), "{out}");
    let mut args = STICKING.to_vec();
    args.extend(["--claim", "omega=1.90", "--json"]);
    let (code, out, _) = rodimpact(&args);
    assert_eq!(code, 1);
    let j: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["claims"][0]["exact"], "36/19");
    assert_eq!(j["claims"][0]["verdict"], "last_digit_off_by_one");
    assert_eq!(j["summary"]["disagree"], 1);
}

#[test]
fn symbolic_end_hit_identity_and_counterexample() {
    let base = ["check", "--length", "L", "--a", "L/2", "--elastic"];
    let mut args = base.to_vec();
    args.extend(["--claim", "omega=12*m*v0/((M+4*m)*L)"]);
    let (code, out, err) = rodimpact(&args);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("identity in m, M, l, v0"), "{out}");
    let mut args = base.to_vec();
    args.extend(["--claim", "omega=6*m*v0/((M+4*m)*L)", "--json"]);
    let (code, out, _) = rodimpact(&args);
    assert_eq!(code, 1);
    let j: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["symbolic"], true);
    assert!(
        j["claims"][0]["notes"][0]
            .as_str()
            .unwrap()
            .contains("counterexample")
    );
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    // One argument may hold at most 128 KiB (Linux), so the 100,000-deep nest goes in a file.
    let deep = "(".repeat(60_000) + "m" + &")".repeat(60_000);
    let deep_claim = format!("omega={deep}");
    let file = crate::common::scratch("deep").join("deep.toml");
    let nest = "(".repeat(100_000) + "m" + &")".repeat(100_000);
    let toml = format!(
        "[[problem]]\nid = \"deep\"\nsource = \"test\"\n[problem.given]\nm = \"1\"\nM = \"1\"\n[problem.claims]\nomega = \"{nest}\"\n"
    );
    std::fs::write(&file, toml).unwrap();
    let file_arg = file.display().to_string();
    let nested = format!("omega={}m{}", "(".repeat(300), ")".repeat(300));
    let cases: Vec<Vec<&str>> = vec![
        vec!["check", "--m", "1", "--M", "1"],
        vec!["check", "--m", "1", "--M", "1", "--claim", "omega"],
        vec!["check", "--m", "1", "--M", "1", "--claim", "spin=2"],
        vec!["check", "--m", "1 kg", "--M", "1", "--claim", "omega=1.2 J"],
        vec!["check", "--m", "1", "--M", "1", "--claim", &deep_claim],
        vec!["check", "--m", "1", "--M", "1", "--claim", &nested],
        vec![
            "check",
            "--m",
            "1",
            "--M",
            "1",
            "--claim",
            "pivot_impulse=1",
        ],
        vec![
            "check", "--m", "1", "--M", "1", "--claim", "v=1", "--sig", "0",
        ],
        vec!["check", "no/such/file.toml"],
        vec!["check", &file_arg],
        vec!["check", "examples/textbook.toml", "--claim", "v=1"],
    ];
    for args in cases {
        let (code, out, err) = rodimpact(&args);
        assert_eq!(code, 2, "{:?}: {out}{err}", &args[..args.len().min(6)]);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(out.is_empty(), "{out}");
    }
    let _ = std::fs::remove_dir_all(file.parent().expect("in its scratch directory"));
}

#[test]
fn bundled_collection_runs_and_reports_the_wrong_answers() {
    let (code, out, err) = rodimpact(&["check", "examples/textbook.toml"]);
    assert_eq!(code, 1, "{err}");
    assert!(out.contains("12 problems"), "{out}");
    let (_, out, _) = rodimpact(&["check", "examples/textbook.toml", "--json"]);
    let j: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["problems"].as_array().unwrap().len(), 12);
}

/// Runs `check` and returns (exit code, stdout, stderr), asserting the one-line contract for
/// input errors.
fn check(args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["check"];
    all.extend_from_slice(args);
    let (code, out, err) = rodimpact(&all);
    if code == 2 {
        assert_eq!(err.lines().count(), 1, "one line: {err}");
        assert!(out.is_empty(), "nothing on stdout on bad input: {out}");
    }
    (code, out, err)
}

/// Regression (NEWCOMER #3): in symbolic mode every flag left out became a free symbol, e
/// included, so the paper's own Eq. (omega) for the elastic uniform rod was "refuted" with a
/// counterexample at e = 1/2. e and the rod now take solve's defaults (elastic, uniform), the
/// other quantities stay free, and the report says which are free and which defaults it used.
#[test]
fn symbolic_check_takes_the_defaults_of_solve_and_names_the_free_symbols() {
    let (code, out, err) = check(&["--claim", "omega=6*m*a*v0/(M*l^2*(1+m/M+3*m*a^2/(M*l^2)))"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("  free symbols: m, M, l, a, v0\n"), "{out}");
    assert!(
        out.contains("  defaults: e = 1 (elastic); uniform rod (I = M l^2/3)\n"),
        "{out}"
    );
    assert!(
        out.contains("agrees") && out.ends_with("1 claim, it agrees\n"),
        "{out}"
    );
    // The end-hit formula needs the end: a is free unless given, and the report shows it.
    let (code, out, _) = check(&["--elastic", "--claim", "omega=6*m*v0/((M+4*m)*l)"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("free symbols: m, M, l, a, v0"), "{out}");
    let (code, out, _) = check(&[
        "--elastic",
        "--a",
        "l",
        "--claim",
        "omega=6*m*v0/((M+4*m)*l)",
    ]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("free symbols: m, M, l, v0\n"), "{out}");
    assert!(!out.contains("defaults: e = 1"), "e was given: {out}");
    // JSON says the same.
    let (_, out, _) = check(&["--M", "m", "--claim", "V=1/2*v0", "--json"]);
    let j: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["symbolic"], true);
    assert_eq!(j["free_symbols"], serde_json::json!(["m", "l", "a", "v0"]));
    assert_eq!(j["defaults"][0], "e = 1 (elastic)");
}

/// Regression (NEWCOMER #4): `check --M 4*m --elastic --claim v=0` was refused ("a number
/// cannot be checked against the formula ...") because a was free; a constant claim is now
/// decided as an identity (refuted with a counterexample while a is free), and agrees once the
/// end is given: M = 4m struck at the end stops the projectile (equal effective masses).
#[test]
fn a_constant_claim_is_decided_against_a_formula() {
    let (code, out, err) = check(&["--M", "4*m", "--a", "l", "--claim", "v=0"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("  v      0      0        -           agrees"),
        "{out}"
    );
    let (code, out, err) = check(&["--M", "4*m", "--elastic", "--claim", "v=0", "--json"]);
    assert_eq!(code, 1, "a disagreement, not bad input: {err}");
    let j: Value = serde_json::from_str(&out).unwrap();
    let c = &j["claims"][0];
    assert_eq!(c["verdict"], "disagrees");
    assert_eq!(
        c["notes"][0],
        "a number against a formula: decided as an identity in the free symbols"
    );
    // At m = l = v0 = 1, a = 1/2: v = (3/4 - 3)/(3/4 + 5) = -9/23.
    assert_eq!(
        c["counterexample"],
        serde_json::json!({
            "at": {"a": "1/2", "l": "1", "m": "1", "v0": "1"},
            "exact": "-9/23",
            "claimed": "0"
        })
    );
}

/// Regression (NEWCOMER #5): `check --rod rg=r ...` said "m: required, but not given" because
/// a rod given by a formula did not make the scene symbolic (and `r` was no symbol). The
/// paper's general-I formula, and its a* = sqrt((M+m) I/(m M)), are now decided with I and r.
#[test]
fn rod_formulas_make_the_check_symbolic_with_i_and_r() {
    let (code, out, err) = check(&[
        "--rod",
        "rg=r",
        "--claim",
        "omega=2*m*a*v0/(I*(1+m/M+m*a^2/I))",
        "--claim",
        "a_star=sqrt((M+m)*I/(m*M))",
        "--claim",
        "a_star=r",
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("free symbols: m, M, l, a, v0, r"), "{out}");
    let verdicts: Vec<&str> = out
        .lines()
        .filter(|l| l.starts_with("  omega") || l.starts_with("  a_star"))
        .map(|l| l.split_whitespace().last().unwrap())
        .collect();
    assert_eq!(verdicts, ["agrees", "agrees", "DISAGREES"], "{out}");
    // Uniform rod by default: I = M l^2/3 in a claim; M = m puts a* at sqrt(2/3) l.
    let (code, out, _) = check(&["--M", "m", "--claim", "a_star=sqrt(2/3)*l"]);
    assert_eq!(code, 0, "{out}");
    // omega_max where the symbols leave the case open is named, with what to claim instead.
    let (code, _, err) = check(&["--claim", "omega_max=v0/l"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("omega_max is omega(a*) when M <= 2*m and omega(l) otherwise")
            && err.contains("claim a_star or omega"),
        "{err}"
    );
    let (code, _, err) = check(&["--claim", "a_star=r"]);
    assert_eq!(code, 2);
    assert!(err.contains("give --rod rg=r"), "{err}");
}

/// Regression (NEWCOMER #11): an impulse claimed as 0.1 N s against 480/2437 = 0.197 N s
/// (49 % off) was labelled "last digit off by one", and large errors printed as `3.0e2%`.
/// "Last digit off by one" now needs a true near-miss (the claim within one unit of its last
/// place of the exact value, with two figures or more); large errors read as a factor.
#[test]
fn near_misses_and_large_errors_are_worded_for_what_they_are() {
    let scene = [
        "--m",
        "10g",
        "--M",
        "2kg",
        "--length",
        "120cm",
        "--v0",
        "36km/h",
        "--from-end",
        "10cm",
    ];
    let mut args = scene.to_vec();
    args.extend([
        "--claim",
        "impulse=0.1 N*s",
        "--claim",
        "impulse=0.196 N*s",
        "--claim",
        "omega=1.62",
        "--claim",
        "omega=0.410",
    ]);
    // J = 480/2437 = 0.19696 N s; omega = J (a)/I = 1000/2437 = 0.41034 rad/s.
    let (code, out, _) = check(&args);
    assert_eq!(code, 1, "{out}");
    let rows: Vec<&str> = out.lines().skip(1).collect();
    assert!(
        rows[0].contains("-49 %") && rows[0].ends_with("DISAGREES"),
        "{out}"
    );
    assert!(
        rows[1].contains("-0.49 %") && rows[1].ends_with("DISAGREES (last digit off by one)"),
        "{out}"
    );
    assert!(
        rows[2].contains("×3.95") && rows[2].ends_with("DISAGREES"),
        "{out}"
    );
    assert!(
        rows[3].contains("-0.083 %") && rows[3].ends_with("agrees"),
        "{out}"
    );
    assert!(!out.contains("e2%") && !out.contains("e1%"), "{out}");
}

/// Regression (NEWCOMER #26): `check --json` gave 6-digit decimals, `rel_error` as a string
/// with "%", and the counterexample only as free text in `notes`.
#[test]
fn check_json_is_machine_readable() {
    let (_, out, _) = check(&[
        "--m",
        "0.100",
        "--M",
        "1.50",
        "--length",
        "2.00",
        "--v0",
        "12.0",
        "--inelastic",
        "--claim",
        "omega=0.947",
        "--claim",
        "a_star=sqrt(1/2)",
        "--json",
    ]);
    let j: Value = serde_json::from_str(&out).unwrap();
    let omega = &j["claims"][0];
    // omega = 36/19, correctly rounded to 30 significant digits.
    assert_eq!(omega["decimal"], "1.89473684210526315789473684211");
    // (0.947 - 36/19)/(36/19) = -0.50019444...
    let rel = omega["rel_error"].as_f64().expect("a number");
    assert!((rel + 0.500_194_444_444_444_4).abs() < 1e-15, "{rel}");
    assert_eq!(omega["rel_error_at_counterexample"], false);
    // a*^2 = I (M + m)/(m M) = (1/2)(1.6)/(0.15) = 16/3: a* = 4/sqrt(3), to 30 digits
    // 2.30940107675850305803659512201 (2.309401076758503058036595122007... by Python decimal).
    assert_eq!(j["claims"][1]["decimal"], "2.30940107675850305803659512201");
    let (_, out, _) = check(&[
        "--length",
        "L",
        "--a",
        "L/2",
        "--claim",
        "omega=6*m*v0/((M+4*m)*L)",
        "--json",
    ]);
    let j: Value = serde_json::from_str(&out).unwrap();
    let c = &j["claims"][0];
    // At M = 3, l = 1, m = 1, v0 = 1: exact 6/7, claimed 3/7: -50 %.
    assert_eq!(
        c["counterexample"]["at"],
        serde_json::json!({"M": "3", "l": "1", "m": "1", "v0": "1"})
    );
    assert_eq!(c["counterexample"]["exact"], "6/7");
    assert_eq!(c["counterexample"]["claimed"], "3/7");
    assert_eq!(c["rel_error"], -0.5);
    assert_eq!(c["rel_error_at_counterexample"], true);
}

/// Regression (NEWCOMER #25): summaries said "1 problems", "1 claims" and "0 of 1 claims
/// agree"; `check --m 10 g ...` blamed the problem file, and `check --claim omega=1.2`
/// answered "m: required, but not given" without saying why a number needs a numeric scene.
#[test]
fn check_wording_for_one_claim_and_for_stray_arguments() {
    let (code, out, _) = check(&["--m", "1", "--M", "1", "--claim", "omega=6/5"]);
    assert_eq!(code, 0);
    assert!(out.ends_with("\n1 claim, it agrees\n"), "{out}");
    let (_, out, _) = check(&[
        "--m", "1", "--M", "1", "--claim", "v=6/5", "--claim", "V=2/5",
    ]);
    assert!(
        out.ends_with("\n1 of 2 claims agrees; 1 disagrees\n"),
        "{out}"
    );
    let file = crate::common::scratch("one").join("one.toml");
    std::fs::write(
        &file,
        "[[problem]]\nid = \"p\"\nsource = \"s\"\n[problem.given]\nm = \"1\"\nM = \"1\"\n[problem.claims]\nomega = \"6/5\"\n",
    )
    .unwrap();
    let (code, out, _) = check(&[file.to_str().unwrap()]);
    let _ = std::fs::remove_dir_all(file.parent().expect("in its scratch directory"));
    assert_eq!(code, 0);
    assert!(out.ends_with("\n1 problem; 1 claim, it agrees\n"), "{out}");
    let (code, _, err) = check(&["--m", "10", "g", "--M", "1", "--claim", "v=1"]);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: check: unexpected argument 'g': a unit goes with its number in one argument (--m \"10 g\" or --m 10g)\n"
    );
    let (code, _, err) = check(&["--claim", "omega=1.2"]);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: m: not given; a numeric claim (omega=1.2) needs a numeric scene: give m and M as numbers (--m, --M), or claim a formula in the scene's symbols\n"
    );
}

/// Regression (RELIABILITY F14): scene formulas skipped the physical domain: `--a 2*l`
/// "agreed" (exit 0) for an impact off the rod, and `--M -m` or `--pivot 2*l` gave UNDECIDED
/// (exit 1). A scene whose formulas leave no valid sample scene is now bad input (exit 2),
/// naming the field and the constraint.
#[test]
fn scene_formulas_outside_the_domain_are_refused() {
    let cases: [(&[&str], &str); 5] = [
        (
            &[
                "--a",
                "2*l",
                "--claim",
                "omega=(6*e*m*v0 + 6*m*v0)/(M*l + 13*l*m)",
            ],
            "error: a: must lie on the rod, |a| <= l, but a = 2*l is off the rod in every sample scene of the free symbols\n",
        ),
        (
            &["--M", "-m", "--claim", "omega=v0"],
            "error: M: must be > 0, but M = -m is <= 0 in every sample scene of the free symbols\n",
        ),
        (
            &["--M", "m", "--pivot", "2*l", "--claim", "omega=v0"],
            "error: pivot: must lie on the rod, |p| <= l, but pivot = 2*l is off the rod in every sample scene of the free symbols\n",
        ),
        (
            &["--e", "1+m/m", "--claim", "omega=v0"],
            "error: e: 2 is outside the domain of e\n",
        ),
        (
            &["--rod", "rg=2*l", "--claim", "omega=v0"],
            "error: rod: the radius of gyration must satisfy 0 < r_G <= l, and it does in no sample scene of the free symbols\n",
        ),
    ];
    for (args, expected) in cases {
        let (code, out, err) = check(args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert_eq!(err, expected, "{args:?}");
    }
    // A formula valid on part of the domain is checked there: a = l - 1 is on the rod for l >= 1/2.
    let (code, out, err) = check(&["--a", "l-1", "--claim", "V_cm=m*v0/(m+M)"]);
    assert_eq!(code, 0, "{out}{err}");
}

/// Regression (RELIABILITY F8): each formula was bounded by MAX_WORK but nothing bounded
/// their sum: 100 claims of about a second each ran 106 s, and 1,000 problems 69 s with
/// 916 MB. Every formula of a run (scene flags, claims, identity decisions), on the command
/// line or in a file, is now charged to one budget of 10 x MAX_WORK, refused past it with
/// exit 2 naming the claim (and the problem); a file's problems are checked one at a time.
#[test]
fn a_run_has_one_work_budget() {
    // (m + 99...9)^12 with a 300-digit constant costs 2.4 million work units: 17 of them pass
    // the budget of 40 million, while each alone is well within MAX_WORK.
    let heavy = format!("omega=(m+{})^12", "9".repeat(300));
    let mut args = vec!["--m", "1", "--M", "1"];
    for _ in 0..20 {
        args.extend(["--claim", heavy.as_str()]);
    }
    let (code, _, err) = check(&args);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: claim omega: the claims of this run together cost more than 40000000 work units (limit); check them in smaller runs\n"
    );
    let (code, out, _) = check(&args[..8]);
    assert_eq!(code, 1, "two heavy claims fit: {out}");
    let problem = |k: usize| {
        format!(
            "[[problem]]\nid = \"p{k}\"\nsource = \"s\"\n[problem.given]\nm = \"1\"\nM = \"1\"\n[problem.claims]\n{}\n",
            heavy.replacen('=', " = \"", 1) + "\""
        )
    };
    let text: String = (1..=20).map(problem).collect();
    let file = crate::common::scratch("budget").join("budget.toml");
    std::fs::write(&file, text).unwrap();
    let (code, _, err) = check(&[file.to_str().unwrap()]);
    let _ = std::fs::remove_dir_all(file.parent().expect("in its scratch directory"));
    assert_eq!(code, 2);
    assert!(
        err.contains(": problem 'p17': claims.omega: the claims of this run together cost more than 40000000 work units (limit)"),
        "{err}"
    );
}

/// Regression (NEWCOMER #25): `rodimpact slove` lost clap's "a similar subcommand exists" tip
/// in the one-line rewrite of usage errors.
#[test]
fn a_mistyped_subcommand_suggests_the_right_one() {
    let (code, out, err) = rodimpact(&["slove", "--m", "1"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: unrecognized subcommand 'slove'; tip: ") && err.contains("'solve'"),
        "{err}"
    );
}

/// NEWCOMER M7: a velocity claimed with the right magnitude and the wrong sign disagrees (the
/// sign of v says whether the projectile rebounds), and the note says so. By hand: m = 0.05,
/// M = 0.3, l = 0.4, a = 0.3, v0 = 4, uniform rod, elastic: D = 1 + m/M + m a^2/I with I = M
/// l^2/3 = 0.016, so D = 1 + 1/6 + 0.0045/0.016 = 139/96 and v = -(1 - 1/6 - 9/32)/D v0 =
/// -(53/96)(96/139) 4 = -212/139 ~ -1.525.
#[test]
fn a_rebound_claimed_forward_is_named_as_a_sign_error() {
    let scene = [
        "--m",
        "50g",
        "--M",
        "0.30kg",
        "--length",
        "80cm",
        "--from-end",
        "10cm",
        "--v0",
        "4.0m/s",
    ];
    let note = "note: the magnitude agrees, only the sign differs: v < 0, the projectile rebounds (it moves back after the impact)";
    for claim in ["v=1.5 m/s", "v=212/139"] {
        let (code, out, _) = check(&[&scene[..], &["--claim", claim]].concat());
        assert_eq!(code, 1, "{out}");
        assert!(
            out.contains("-212/139") && out.contains("DISAGREES"),
            "{out}"
        );
        assert!(out.contains(note), "{claim}: {out}");
    }
    // A wrong magnitude gets no such note, and the right signed value agrees.
    let (_, out, _) = check(&[&scene[..], &["--claim", "v=1.2"]].concat());
    assert!(!out.contains("only the sign differs"), "{out}");
    let (code, out, _) = check(&[&scene[..], &["--claim", "v=-1.5"]].concat());
    assert_eq!(code, 0, "{out}");
}

/// NEWCOMER m16: a symbolic a* is shown canonically (an integer free of squares under the
/// root, l outside it: for M = m, a*^2 = 2 l^2/3, a* = sqrt(6) l/3), under a header without
/// "(SI)" (the scene has symbols, not units), and the note on the sign says what it means.
#[test]
fn a_symbolic_a_star_is_shown_canonically() {
    let (code, out, _) = check(&["--M", "m", "--claim", "a_star=sqrt(2/3)*l"]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("  claim   exact            claimed      rel. error  verdict\n"),
        "{out}"
    );
    assert!(
        out.contains("  a_star  (1/3*l)*sqrt(6)  sqrt(2/3)*l  -           agrees\n"),
        "{out}"
    );
    assert!(out.contains("note: the squares agree identically, and both sides have the same sign (checked at a sample scene)"), "{out}");
}

/// NEWCOMER m20 and m15: a product written without `*` is named with the fix, a misspelt
/// symbol gets a suggestion, `check` with nothing to check says what to give, and a formula
/// refuted only because a is free (check does not assume the end) says how to hit the end.
#[test]
fn authors_mistakes_in_writing_are_named_with_their_fix() {
    for (args, message) in [
        (
            &["--a", "l", "--claim", "omega=6*m*v0/((M+4m)*l)"][..],
            "error: claim omega: expected ')' at character 13 (found 'm') in expression: write 4*m... (a product needs '*')\n",
        ),
        (
            &["--a", "l", "--claim", "omega=6*m*v_0/((M+4*m)*l)"],
            "error: claim omega: unknown symbol 'v_0' at character 5 (did you mean v0? symbols: m M l L a d v0 e p I r, oblique v0t mu rd w V0 Vt0 omega0, function sqrt)\n",
        ),
        (
            &[],
            "error: claim: nothing to check: give --claim NAME=VALUE (with the scene's flags), or a problems .toml file (rodimpact check examples/textbook.toml)\n",
        ),
    ] {
        let (code, out, err) = check(args);
        assert_eq!(
            (code, out.as_str(), err.as_str()),
            (2, "", message),
            "{args:?}"
        );
    }
    let end_hit = "omega=6*m*v0/((M+4*m)*l)";
    let (code, out, _) = check(&["--elastic", "--claim", end_hit]);
    assert_eq!(code, 1);
    assert!(
        out.contains("note: a is a free symbol here (not the end, solve's default): add --a l for a hit at the end"),
        "{out}"
    );
    let (code, out, _) = check(&["--elastic", "--a", "l", "--claim", end_hit]);
    assert_eq!(code, 0, "{out}");
    let help = crate::common::output(vec!["check", "--help"]).stdout;
    assert!(
        String::from_utf8(help)
            .unwrap()
            .contains("a free symbol a for formulas")
    );
}

/// NEWCOMER capability 3: a disagreeing claim is tried against the usual mistakes, each solved
/// exactly, and the note names the one that reproduces it. By hand, for m = M = l = v0 = 1,
/// a = 1/2, e = 1 (I = 1/3): omega = (1 + e) m v0 a/(I (1 + m/M) + m a^2) = 12/11; with e = 0
/// it is 6/11 = 0.5455; with I about the end (4/3) it is 1/(8/3 + 1/4) = 12/35 = 0.343; twice
/// 12/11 is 2.18. The author's 50 g taken as 50 kg (l = 0.4, a = 0.3, I = 0.016, e = 1/2,
/// v0 = 4): 1.5*50*4*0.3/(0.016 (1 + 50/0.3) + 50*0.09) = 12.53. An oblique impact that slides
/// (mu = 1/5) claimed with its sticking answer vt = 2/3 (the stick impulse does not depend on
/// mu: `solve ... --mu 10` sticks with vt = 2/3).
#[test]
fn the_usual_mistake_that_reproduces_a_claim_is_named() {
    let cases: [(&[&str], &str); 5] = [
        (
            &[
                "--m",
                "1",
                "--M",
                "1",
                "--a",
                "1/2",
                "--claim",
                "omega=0.5455",
            ],
            "note: a usual mistake reproduces the claim: e = 0 (a sticking impact) instead of e = 1; or a factor 1/2 (the exact value times 1/2)",
        ),
        (
            &[
                "--m",
                "1",
                "--M",
                "1",
                "--a",
                "1/2",
                "--claim",
                "omega=0.343",
            ],
            "note: a usual mistake reproduces the claim: the moment of inertia about the rod's end (I + M l^2) instead of its centre",
        ),
        (
            &[
                "--m",
                "1",
                "--M",
                "1",
                "--a",
                "1/2",
                "--claim",
                "omega=2.18",
            ],
            "note: a usual mistake reproduces the claim: a factor 2 (the exact value times 2)",
        ),
        (
            &[
                "--m",
                "50g",
                "--M",
                "0.30kg",
                "--length",
                "80cm",
                "--from-end",
                "10cm",
                "--v0",
                "4.0m/s",
                "--e",
                "1/2",
                "--claim",
                "omega=12.53",
            ],
            "note: a usual mistake reproduces the claim: the projectile's mass in grams read as kilograms",
        ),
        (
            &[
                "--m", "1", "--M", "2", "--a", "1/2", "--v0", "3", "--v0t", "2", "--mu", "1/5",
                "--claim", "vt=0.667",
            ],
            "note: a usual mistake reproduces the claim: sticking taken for sliding",
        ),
    ];
    for (flags, note) in cases {
        let mut args = vec!["check"];
        args.extend_from_slice(flags);
        let (code, stdout, stderr) = rodimpact(&args);
        assert_eq!(code, 1, "{args:?}: {stderr}");
        assert!(stdout.contains("DISAGREES"), "{stdout}");
        assert!(stdout.contains(note), "{args:?}:\n{stdout}");
    }
    // A claim no usual mistake gives has no such note.
    let (_, stdout, _) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "1/2",
        "--claim",
        "omega=0.9",
    ]);
    assert!(!stdout.contains("usual mistake"), "{stdout}");
}

/// NEWCOMER m13 and M6: `--a a*` strikes the scene exactly at its optimum, solved in Q(sqrt d).
/// By hand, m = M = l = v0 = 1, e = 1, uniform rod: a*^2 = (M + m) I/(m M) = 2/3; there omega
/// is omega_max = (1 + e) v0/(2 a*) = sqrt(6)/2 and the two leave together, v = V = 1/2 (X19);
/// on the other side omega is negative. A pivot at the end -1: d*^2 = I_p/m = 1/3 + 1 = 4/3,
/// omega = 2/(2 d*) = sqrt(3)/2. M = 3m puts a*^2 = 4/3 beyond the end: refused, naming the
/// end. `solve` says where a* is taken.
#[test]
fn a_star_is_an_impact_point() {
    let (code, stdout, stderr) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "a*",
        "--claim",
        "omega=1.22",
        "--claim",
        "omega=sqrt(6)/2",
        "--claim",
        "v=1/2",
        "--claim",
        "V=0.5",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains("omega  sqrt(6)/2 ≈ 1.22474  sqrt(6)/2  0 %"),
        "{stdout}"
    );
    assert!(stdout.contains("4 of 4 claims agree"), "{stdout}");
    let (code, stdout, _) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "-a*",
        "--claim",
        "omega=-1.22",
    ]);
    assert_eq!(code, 0, "{stdout}");
    let (code, stdout, _) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--pivot",
        "-1",
        "--a",
        "a*",
        "--claim",
        "omega=sqrt(3)/2",
    ]);
    assert_eq!(code, 0, "{stdout}");
    let (code, _, stderr) = rodimpact(&[
        "check", "--m", "1", "--M", "3", "--a", "a*", "--claim", "omega=1",
    ]);
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "error: a: a* = sqrt(4/3) from the centre lies beyond the rod's end on that side: the end is the best point there (--a 1)\n"
    );
    let (code, _, stderr) = rodimpact(&["solve", "--m", "1", "--M", "1", "--a", "a*"]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("error: a: a* is not a number here"),
        "{stderr}"
    );
}

/// NEWCOMER M6: omega_max in symbols where the scene decides the case. By hand, a uniform rod
/// (I = M l^2/3) with M = m: a*^2 = (M + m) I/(m M) = 2 l^2/3 < l^2 always, so omega_max =
/// (1 + e) v0/(2 a*) = sqrt(6)/2 v0/l at e = 1 and (3/8) sqrt(6) v0/l at e = 1/2. With M = 3m,
/// a*^2 = 4 l^2/3 > l^2 always: omega_max is omega at the end, 2 m v0 l/(I (1 + m/M) + m l^2)
/// = 6/7 v0/l. With M free the case depends on M <= 2m: refused, naming the condition.
#[test]
fn omega_max_in_symbols_where_the_case_is_decided() {
    for (flags, claim) in [
        (&["--M", "m"][..], "omega_max=sqrt(6)/2*v0/l"),
        (
            &["--M", "m", "--e", "1/2"][..],
            "omega_max=3/8*sqrt(6)*v0/l",
        ),
        (&["--M", "3*m"][..], "omega_max=6*m*v0/((M+4*m)*l)"),
    ] {
        let mut args = vec!["check"];
        args.extend_from_slice(flags);
        args.extend(["--claim", claim]);
        let (code, stdout, stderr) = rodimpact(&args);
        assert_eq!(code, 0, "{args:?}: {stdout}{stderr}");
        assert!(stdout.contains("1 claim, it agrees"), "{stdout}");
    }
    let (code, stdout, _) = rodimpact(&["check", "--M", "m", "--claim", "omega_max=v0/l"]);
    assert_eq!(code, 1);
    assert!(
        stdout.contains("counterexample") && !stdout.contains("add --a l"),
        "{stdout}"
    );
    let (code, _, stderr) = rodimpact(&["check", "--claim", "omega_max=v0/l"]);
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "error: claim omega_max: omega_max is omega(a*) when M <= 2*m and omega(l) otherwise, two formulas: fix the case in the scene (--M 2*m, ...) or claim a_star or omega\n"
    );
}

/// NEWCOMER M6: claims about an oblique, frictional scene in symbols. The end hit on an
/// equal-mass rod by a puck sliding at v0t with friction mu: Jt = (2/5) mu m v0 is the sliding
/// answer (mu < mu* = 5 v0t/(4 v0)), Jt = m v0t/2 the sticking one; omega = (6/5) v0/l whatever
/// the contact does; vt = v0t/3 is neither, refuted at a sample scene.
#[test]
fn symbolic_oblique_claims_name_the_contact_they_hold_for() {
    let (code, out, err) = rodimpact(&[
        "check",
        "--M",
        "m",
        "--a",
        "l",
        "--v0t",
        "v0t",
        "--mu",
        "mu",
        "--claim",
        "tangential_impulse=2/5*mu*m*v0",
        "--claim",
        "tangential_impulse=1/2*m*v0t",
        "--claim",
        "omega=6/5*v0/l",
        "--claim",
        "vt=v0t/3",
        "--json",
    ]);
    assert_eq!(code, 1, "{err}");
    let report: Value = serde_json::from_str(&out).unwrap();
    let answers = report["claims"].as_array().expect("claims");
    let verdicts: Vec<&str> = answers
        .iter()
        .map(|a| a["verdict"].as_str().unwrap())
        .collect();
    assert_eq!(
        verdicts,
        ["agrees", "agrees", "agrees", "disagrees"],
        "{out}"
    );
    assert_eq!(
        report["free_symbols"],
        serde_json::json!(["m", "l", "v0", "v0t", "mu"])
    );
    let notes = |i: usize| answers[i]["notes"].to_string();
    assert!(
        notes(0)
            .contains("the answer when the contact slides (mu < mu_star, mu_star = 5/4*v0t/v0)"),
        "{}",
        notes(0)
    );
    assert!(
        notes(1).contains("the answer when the contact sticks (mu >= mu_star"),
        "{}",
        notes(1)
    );
    assert!(
        notes(2).contains("the same however the contact ends"),
        "{}",
        notes(2)
    );
    assert!(
        notes(3).contains("nor the answer when it slides: -2/5*mu*v0 + v0t"),
        "{}",
        notes(3)
    );
    // Decided by the numbers: mu = 2 >= mu* = 5/4 when v0t = v0, the contact sticks.
    let (code, out, err) = rodimpact(&[
        "check", "--M", "m", "--a", "l", "--v0t", "v0", "--mu", "2", "--claim", "vt=v0/2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("the contact sticks for every value of the symbols, mu_star = 5/4"),
        "{out}"
    );
}
