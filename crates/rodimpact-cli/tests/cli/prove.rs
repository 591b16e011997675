//! The `prove` and `paper` command-line contract.

use crate::common;
use common::scratch;

use common::rodimpact;
use rodimpact::claims::{beyond_ids, paper_ids, registry};
use serde_json::Value;
use std::io::Read;
use std::process::{Command, Stdio};

/// The registered ids, in order.
fn ids() -> Vec<&'static str> {
    registry().iter().map(|e| e.id).collect()
}

#[test]
fn prove_json_lists_every_claim_in_order_with_the_contract_keys() {
    let (code, stdout, stderr) = rodimpact(&["prove", "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let list: Vec<Value> = serde_json::from_str(&stdout).expect("a JSON list");
    let listed: Vec<&str> = list.iter().map(|c| c["id"].as_str().unwrap()).collect();
    assert_eq!(listed, ids());
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
    assert!(stdout.contains(&format!("{} claims:", registry().len())));
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
    assert_eq!(decisions, registry().len());
    assert!(stdout.contains("T1. Where the rod spins fastest"));
}

/// Every file of `committed` (not its subdirectories) was written into `dir` with the same
/// text; returns how many.
fn assert_written_as_committed(dir: &std::path::Path, committed: &std::path::Path) -> usize {
    let mut count = 0;
    for entry in std::fs::read_dir(committed).unwrap() {
        let entry = entry.unwrap();
        if entry.path().is_dir() {
            continue;
        }
        let name = entry.file_name();
        let written = std::fs::read_to_string(dir.join(&name)).expect("written");
        assert_eq!(
            written,
            std::fs::read_to_string(committed.join(&name)).unwrap(),
            "{name:?}"
        );
        count += 1;
    }
    count
}

#[test]
fn prove_write_reproduces_the_committed_certificates() {
    let dir = crate::common::scratch("proofs");
    let (code, _, stderr) = rodimpact(&["prove", "--write", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let committed = std::path::Path::new(crate::ROOT).join("proofs");
    // The subdirectories are the exports for independent checkers (proofs/smt2, proofs/sympy).
    let count = assert_written_as_committed(&dir, &committed);
    assert_eq!(
        count,
        registry().len() + 1,
        "a certificate per claim and the index"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unknown_claims_and_unwritable_directories_exit_2() {
    let (code, stdout, stderr) = rodimpact(&["prove", "C99"]);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert_eq!(
        stderr.trim(),
        format!(
            "error: id: unknown claim 'C99'; the ids are {} and {}",
            paper_ids(),
            beyond_ids()
        )
    );
    let (code, _, stderr) = rodimpact(&["prove", "C1", "--write", "/proc/rodimpact-cannot-write"]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with("error: write: cannot write /proc/rodimpact-cannot-write: "),
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

/// Every file under `dir` (recursively) with its contents, and the names of hidden entries
/// beside it: a snapshot to compare before and after a run.
fn snapshot(dir: &std::path::Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let name = path.strip_prefix(dir).unwrap().display().to_string();
            if path.is_dir() {
                out.push((format!("{name}/"), String::new()));
                stack.push(path);
            } else {
                out.push((name, std::fs::read_to_string(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

/// Regression (RELIABILITY F6): `paper --out DIR` wrote the certificates and README.md one by
/// one, so when `DIR/report.md` could not be written (here it is a directory) the run failed
/// after 73 files had already replaced the previous ones: an old report beside new
/// certificates. Now every file is staged in DIR and renamed in only when all are complete;
/// a target in the way is refused before anything is written.
#[test]
fn a_failing_paper_out_leaves_the_previous_directory_untouched() {
    let root = scratch("paper-f6");
    let dir = root.join("out");
    std::fs::create_dir_all(dir.join("report.md")).unwrap();
    std::fs::write(dir.join("report.md/kept.txt"), "inside the way").unwrap();
    std::fs::write(dir.join("C1.md"), "the previous run's C1\n").unwrap();
    let before = snapshot(&root);

    let (code, _, stderr) = rodimpact(&["paper", "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("error: out: cannot write ") && stderr.contains("report.md"),
        "{stderr}"
    );
    // DIR as it was, and nothing new beside it (no staging directory left over).
    assert_eq!(snapshot(&root), before);
    std::fs::remove_dir_all(&root).unwrap();
}

/// Regression (RELIABILITY F6): `prove C1 C2 C3 --write W` with `W/C2.md` unwritable wrote
/// `C1.md`, then failed. Now nothing is written.
#[test]
fn a_failing_prove_write_writes_nothing() {
    let root = scratch("prove-f6");
    let dir = root.join("w");
    std::fs::create_dir_all(dir.join("C2.md")).unwrap();
    let before = snapshot(&root);
    let (code, _, stderr) =
        rodimpact(&["prove", "C1", "C2", "C3", "--write", dir.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("C2.md"), "{stderr}");
    assert_eq!(snapshot(&root), before);
    std::fs::remove_dir_all(&root).unwrap();
}

/// What `paper --help` promises is exactly what `paper --out` writes, and a re-run replaces
/// its own files while keeping the user's.
#[test]
fn paper_out_writes_what_its_help_lists_and_keeps_other_files() {
    let root = scratch("paper-out");
    let dir = root.join("report dir");
    let (code, _, stderr) = rodimpact(&["paper", "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let certificates = ids().into_iter().map(|id| format!("{id}.md"));
    let others = [
        "README.md",
        "report.md",
        "tables.md",
        "tables.tex",
        "T1.csv",
        "T2.csv",
        "T3.csv",
        "T4.csv",
        "T5.csv",
        "omega.svg",
        "optimum.svg",
        "figure1.svg",
    ];
    let mut expected: Vec<String> = certificates
        .chain(others.iter().map(|s| s.to_string()))
        .collect();
    expected.sort();
    assert_eq!(names, expected);

    let (_, help, _) = rodimpact(&["paper", "--help"]);
    for name in others.iter().filter(|n| !n.ends_with(".csv")) {
        assert!(help.contains(name), "--help does not list {name}:\n{help}");
    }
    assert!(help.contains("T1.csv ... T5.csv"), "{help}");
    let (paper, beyond) = (paper_ids(), beyond_ids());
    let claims = format!(
        "{}.md ... {}.md, {}.md ... {}.md",
        paper.first, paper.last, beyond.first, beyond.last
    );
    assert!(help.contains(&claims), "{help}");

    // report.md embeds the figures and every table; the index describes this directory.
    let report = std::fs::read_to_string(dir.join("report.md")).unwrap();
    for svg in ["omega.svg", "optimum.svg", "figure1.svg"] {
        assert!(
            report.contains(&format!("]({svg})\n")),
            "{svg} not embedded"
        );
    }
    for t in ["T1", "T2", "T3", "T4", "T5"] {
        assert!(report.contains(&format!("### {t}. ")), "{t} missing");
    }
    let index = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(index.contains("Written by `rodimpact paper --out DIR`"));
    assert!(!index.contains("prove --write proofs"));
    for name in others.iter().filter(|n| **n != "README.md") {
        assert!(index.contains(&format!("[{name}]({name})")), "{name}");
    }
    let t2 = std::fs::read_to_string(dir.join("T2.csv")).unwrap();
    assert!(t2.starts_with("a/l,a/l_decimal,v/v0,v/v0_decimal,V/v0,V/v0_decimal,"));

    // A re-run: the user's file stays, a stale copy of ours is replaced.
    std::fs::write(dir.join("notes.txt"), "mine\n").unwrap();
    std::fs::write(dir.join("report.md"), "stale\n").unwrap();
    let (code, _, stderr) = rodimpact(&["paper", "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
        "mine\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("report.md")).unwrap(),
        report
    );
    let beside: Vec<_> = std::fs::read_dir(&root).unwrap().collect();
    assert_eq!(
        beside.len(),
        1,
        "staging or backup directories left beside DIR"
    );
    std::fs::remove_dir_all(&root).unwrap();
}

/// `paper --out .` was refused while directory outputs replaced DIR as a whole (a shell inside
/// would have been left in a removed directory). DIR is now written in place, so the current
/// directory is an output directory like any other: its own files stay, nothing is left hidden.
#[test]
fn the_current_directory_is_an_output_directory_like_any_other() {
    let root = scratch("paper-dot");
    std::fs::write(root.join("notes.txt"), "mine\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(["paper", "--out", "."])
        .current_dir(&root)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let written = snapshot(&root);
    assert!(written.contains(&("notes.txt".into(), "mine\n".into())));
    assert!(written.iter().any(|(name, _)| name == "report.md"));
    assert!(
        written.iter().all(|(name, _)| !name.starts_with('.')),
        "{written:?}"
    );
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn prove_export_reproduces_the_committed_exports() {
    for format in ["smt2", "sympy"] {
        let dir = crate::common::scratch(&format!("export-{format}"));
        let (code, _, stderr) = rodimpact(&["prove", "--export", format, dir.to_str().unwrap()]);
        assert_eq!(code, 0, "{stderr}");
        let committed = std::path::Path::new(crate::ROOT)
            .join("proofs")
            .join(format);
        let count = assert_written_as_committed(&dir, &committed);
        assert_eq!(count, std::fs::read_dir(&dir).unwrap().count());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// An unknown export format is bad usage: exit 2, the field and the formats named, nothing
/// written.
#[test]
fn an_unknown_export_format_exits_2() {
    let dir = crate::common::scratch("export-coq").join("proofs");
    let (code, _, stderr) = rodimpact(&["prove", "C1", "--export", "coq", dir.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("export") && stderr.contains("smt2 and sympy"),
        "{stderr}"
    );
    assert!(!dir.exists());
    std::fs::remove_dir_all(dir.parent().expect("in its scratch directory")).unwrap();
}
