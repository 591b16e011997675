//! The `prove` and `paper` command-line contract.

use serde_json::Value;
use std::io::Read;
use std::process::{Command, Stdio};

fn rodimpact(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn prove_json_lists_all_72_claims_in_order_with_the_contract_keys() {
    let (code, stdout, stderr) = rodimpact(&["prove", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let list: Vec<Value> = serde_json::from_str(&stdout).expect("a JSON list");
    let ids: Vec<&str> = list.iter().map(|c| c["id"].as_str().unwrap()).collect();
    let expected: Vec<String> = (1..=46)
        .map(|i| format!("C{i}"))
        .chain((1..=26).map(|i| format!("X{i}")))
        .collect();
    assert_eq!(ids, expected);
    for c in &list {
        let verdict = c["verdict"].as_str().unwrap();
        assert!(["PROVED", "REFUTED", "QUALIFIED"].contains(&verdict), "{c}");
        assert!(c["statement"].is_string() && c["method"].is_string() && c["seconds"].is_number());
        assert_eq!(
            c.get("qualification").is_some(),
            verdict == "QUALIFIED",
            "{c}"
        );
    }
}

#[test]
fn paper_prints_every_decision_and_exits_0() {
    let (code, stdout, stderr) = rodimpact(&["paper"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("72 claims:"));
    let decisions = stdout
        .lines()
        .filter(|l| {
            let t = l.trim_start();
            (t.starts_with('C') || t.starts_with('X'))
                && ["PROVED", "REFUTED", "QUALIFIED"]
                    .iter()
                    .any(|v| t.contains(v))
        })
        .count();
    assert_eq!(decisions, 72);
    assert!(stdout.contains("T1. Where the rod spins fastest"));
}

#[test]
fn prove_write_reproduces_the_committed_certificates() {
    let dir = std::env::temp_dir().join(format!("rodimpact-proofs-{}", std::process::id()));
    let (code, _, stderr) = rodimpact(&["prove", "--write", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let committed = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("proofs");
    let mut count = 0;
    for entry in std::fs::read_dir(&committed).unwrap() {
        let name = entry.unwrap().file_name();
        let written = std::fs::read_to_string(dir.join(&name)).expect("written");
        assert_eq!(
            written,
            std::fs::read_to_string(committed.join(&name)).unwrap(),
            "{name:?}"
        );
        count += 1;
    }
    assert_eq!(count, 73);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unknown_claims_and_unwritable_directories_exit_2() {
    let (code, stdout, stderr) = rodimpact(&["prove", "C99"]);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert_eq!(
        stderr.trim(),
        "error: id: unknown claim 'C99'; the ids are C1-C46 and X1-X26"
    );
    let (code, _, stderr) = rodimpact(&["prove", "C1", "--write", "/proc/rodimpact-cannot-write"]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("error: write: cannot create"),
        "{stderr}"
    );
    assert_eq!(stderr.trim_end().lines().count(), 1);
}

#[test]
fn a_closed_pipe_ends_the_program_quietly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .arg("paper")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap(); // then the pipe closes
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
}
