//! `batch --backend f64`: what the output says about a float run.
//!
//! Regression (F9 of the hostile-input review, NEWCOMER #9): the f64 backend decides no
//! conservation law (every `laws_held` cell is `-`), yet the summary said
//! `1 rows, laws held exactly on 1`, even for rows whose f64 results were NaN. Its appended
//! columns were named `v_exact, V_exact, omega_exact` beside claims although they hold f64
//! values, and a zero was written `-0.0`. The summary now says the laws were not checked, the
//! columns are `v_f64, V_f64, omega_f64`, and a zero is `0.0`. Since the engine audit (issue
//! 15) the f64 output has no `laws_held` column at all: a column of `-` said nothing.

use std::process::Command;

#[test]
fn the_f64_backend_says_what_it_checked() {
    let dir = crate::common::scratch("f64");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("in.csv");
    // Row 1: M = 3m on a pivot at the centre, hit at the end: v = 0, V = 0, omega = 1; f64
    // computes V = -(p omega) = -0.0. Row 2: the paper's M = m end hit.
    std::fs::write(&file, "m,M,a,pivot,V\n1,3,1,0,0\n1,1,1,,0.4\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(["batch", file.to_str().unwrap(), "--backend", "f64"])
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    );
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(
        stdout,
        "m,M,a,pivot,V,v_f64,V_f64,omega_f64,V_ok,V_rel_error\n\
         1,3,1,0,0,0.0,0.0,1.0,true,0\n\
         1,1,1,,0.4,0.6,0.4,1.2,true,5.55e-17\n"
    );
    assert!(!stdout.contains("-0.0"), "{stdout}");
    assert!(
        stderr.starts_with("2 rows (f64: conservation laws and diagnoses not checked)\n"),
        "{stderr}"
    );
    assert!(!stderr.contains("held"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}
