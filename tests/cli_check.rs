//! The `check` command-line contract: the done-when commands, exit codes, JSON, limits.

use serde_json::Value;
use std::process::Command;

fn rodimpact(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

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
    let file = std::env::temp_dir().join(format!("rodimpact-deep-{}.toml", std::process::id()));
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
    let _ = std::fs::remove_file(&file);
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
