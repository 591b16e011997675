//! `rodimpact batch`: the reference batches confirmed exactly, a wrong claim reported with its
//! row, bad cells named by row and column, nothing half-written.

use crate::common;
use common::scratch;

use common::{data_file, rodimpact};
use std::path::Path;

fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

#[test]
fn every_claim_of_the_1e6_batch_is_confirmed_in_order() {
    let dir = scratch("confirm");
    let out = dir.join("out.csv");
    let (code, stdout, stderr) = rodimpact(&[
        "batch",
        &data_file("bench-1e6.csv"),
        "--jobs",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.is_empty());
    for name in ["v", "V", "omega"] {
        assert!(
            stderr.contains(&format!(
                "{name}: 10000 claims, 0 wrong, max rel error 0, median 0"
            )),
            "{stderr}"
        );
    }
    let input = std::fs::read_to_string(data_file("bench-1e6.csv")).unwrap();
    let output = std::fs::read_to_string(&out).unwrap();
    let (inputs, outputs): (Vec<_>, Vec<_>) = (input.lines().collect(), output.lines().collect());
    assert_eq!(outputs.len(), inputs.len());
    assert!(
        outputs[0].starts_with("m,M,l,a,v0,v,V,omega,v_exact,V_exact,omega_exact,laws_held,v_ok,")
    );
    for (i, o) in inputs.iter().zip(&outputs).skip(1) {
        // Same row, in order; the exact columns repeat the file's claims.
        let claims: Vec<&str> = i.split(',').skip(5).collect();
        let cells: Vec<&str> = o.split(',').collect();
        assert!(o.starts_with(&format!("{i},")), "row order");
        assert_eq!(&cells[8..11], &claims[..], "{o}");
        // Every claim exact: the claimed state is the exact one, so its audit is `ok`.
        assert_eq!(
            &cells[11..],
            ["true", "true", "0", "true", "0", "true", "0", "0", "ok"]
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_altered_value_is_reported_with_its_row_and_exit_1() {
    let dir = scratch("altered");
    let input = std::fs::read_to_string(data_file("bench-textbook.csv")).unwrap();
    let mut lines: Vec<String> = input.lines().take(101).map(String::from).collect();
    // Row 17 (line 18): omega off by 1 in the last digit of the numerator.
    let mut cells: Vec<String> = lines[17].split(',').map(String::from).collect();
    let (n, d) = cells[7].split_once('/').unwrap();
    let n: i64 = n.parse().unwrap();
    cells[7] = format!("{}/{d}", n + 1);
    lines[17] = cells.join(",");
    let file = dir.join("in.csv");
    std::fs::write(&file, lines.join("\n")).unwrap();
    let (code, stdout, stderr) = rodimpact(&["batch", file.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("omega: 100 claims, 1 wrong (row 17)"),
        "{stderr}"
    );
    let row17 = stdout.lines().nth(17).unwrap();
    assert!(row17.starts_with(&lines[17]));
    assert!(row17.contains(",true,0,true,0,false,"), "{row17}");
    assert_eq!(stdout.lines().filter(|l| l.contains(",false,")).count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_bad_cell_names_row_and_column_and_writes_nothing() {
    let dir = scratch("bad");
    let mut text = String::from("m,M,a,e,rod,pivot\n");
    for _ in 0..20_000 {
        text.push_str("1,2,1/2,1,uniform,\n");
    }
    let file = dir.join("in.csv");
    let out = dir.join("out.csv");
    for (row, cell, want) in [
        (
            "1,-1,0,1,uniform,",
            17,
            "error: row 17, column M: must be > 0, got -1",
        ),
        (
            "1,1,0,1,steel,",
            9000,
            "error: row 9000, column rod: expected uniform",
        ),
        (
            "1,1,x,1,uniform,",
            20_000,
            "error: row 20000, column a: not a number",
        ),
        ("1,1,1", 3, "error: row 3: expected 6 cells, got 3"),
    ] {
        let mut lines: Vec<&str> = text.lines().collect();
        lines[cell] = row;
        std::fs::write(&file, lines.join("\n")).unwrap();
        let (code, _, stderr) = rodimpact(&[
            "batch",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 2, "{stderr}");
        assert!(stderr.starts_with(want), "{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert_eq!(leftovers(&dir), ["in.csv"], "no output, no temporary file");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn usage_errors_exit_2() {
    let dir = scratch("usage");
    let file = dir.join("in.csv");
    std::fs::write(&file, "m,M,M\n1,1,1\n").unwrap();
    let f = file.to_str().unwrap();
    let empty = dir.join("empty.csv");
    std::fs::write(&empty, "").unwrap();
    let e = empty.to_str().unwrap();
    for (args, want) in [
        (vec!["batch", f], "error: header: column 'M' given twice"),
        (vec!["batch", e], "error: FILE: "),
        (
            vec!["batch", "/nonexistent/x.csv"],
            "error: FILE: cannot read /nonexistent/x.csv",
        ),
        (
            vec!["batch", f, "--jobs", "0"],
            "error: jobs: must be a whole number from 1 to 1024",
        ),
        (
            vec!["batch", f, "--backend", "f16"],
            "error: invalid value 'f16'",
        ),
    ] {
        let (code, _, stderr) = rodimpact(&args);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(stderr.starts_with(want), "{args:?}: {stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mixed_scenes_and_the_f64_backend() {
    let dir = scratch("mixed");
    let file = dir.join("in.csv");
    std::fs::write(
        &file,
        "m,M,a,e,rod,pivot,omega\n1,1,1,,,,6/5\n1,3,1,0,,0,1/2\n1,2,1/2,,dumbbell,,4/13\n",
    )
    .unwrap();
    let (code, stdout, stderr) = rodimpact(&["batch", file.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(
        stdout,
        "m,M,a,e,rod,pivot,omega,v,V,omega_exact,laws_held,omega_ok,omega_rel_error\n\
         1,1,1,,,,6/5,3/5,2/5,6/5,true,true,0\n\
         1,3,1,0,,0,1/2,1/2,0,1/2,true,true,0\n\
         1,2,1/2,,dumbbell,,4/13,-3/13,8/13,4/13,true,true,0\n"
    );
    let (code, stdout, stderr) = rodimpact(&["batch", file.to_str().unwrap(), "--backend", "f64"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("1,1,1,,,,6/5,0.6,0.4,1.2"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Regression (G6): an engine log with its own `v_exact`, `v_ok`, `laws_held` columns had them
/// passed through beside rodimpact's, and the forged `v_ok = true` of a wrong row came first.
/// Now the header is refused (exit 2, one line naming the column) and nothing is written, to
/// standard output or to `--out`.
#[test]
fn a_log_that_names_rodimpacts_own_columns_is_refused() {
    let dir = scratch("g6");
    let file = dir.join("in.csv");
    let out = dir.join("out.csv");
    std::fs::write(
        &file,
        "m,M,v,v_exact,v_ok,laws_held\n1,1,3/5,3/5,true,true\n1,1,1/2,3/5,true,true\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    for args in [
        vec!["batch", path],
        vec!["batch", path, "--out", out.to_str().unwrap()],
    ] {
        let (code, stdout, stderr) = rodimpact(&args);
        assert_eq!((code, stdout.as_str()), (2, ""), "{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(
            stderr.starts_with("error: header: column 'v_exact' is a name rodimpact writes"),
            "{stderr}"
        );
    }
    assert_eq!(leftovers(&dir), ["in.csv"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Regression (G12): `--rtol 1e-10000` (or `1e-400`) was stated as "claims agree within a
/// relative 0": the summary went through f64, which underflows. The check was always exact
/// (a claim off by 1.7e-34 is wrong); now the statement is too.
#[test]
fn a_tiny_rtol_is_stated_exactly() {
    let dir = scratch("g12");
    let file = dir.join("in.csv");
    std::fs::write(
        &file,
        "m,M,v\n1,1,3/5\n1,1,0.6000000000000000000000000000000001\n",
    )
    .unwrap();
    for (rtol, stated) in [
        ("1e-10000", "1e-10000"),
        ("1e-400", "1e-400"),
        ("1/3", "1/3"),
        ("1e-6", "0.000001"),
    ] {
        let (code, _, stderr) = rodimpact(&["batch", file.to_str().unwrap(), "--rtol", rtol]);
        assert!(
            stderr.starts_with(&format!("claims agree within a relative {stated}\n")),
            "{rtol}: {stderr}"
        );
        let wrong = code == 1;
        assert_eq!(
            wrong,
            rtol.starts_with("1e-4") || rtol.starts_with("1e-1"),
            "{rtol}: {stderr}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The same sweep written in decimals and in fractions (tests/data/README.md) has the same
/// answers, row by row, exact and f64: the decimal cells are read as the fractions they are
/// (the word row reads `0.05` as 5/100), whichever row takes them.
#[test]
fn a_sweep_in_decimals_is_answered_as_in_fractions() {
    for backend in ["exact", "f64"] {
        let answers = |file: &str| -> Vec<String> {
            let (code, stdout, stderr) =
                rodimpact(&["batch", &data_file(file), "--backend", backend]);
            assert_eq!(code, 0, "{stderr}");
            stdout
                .lines()
                .map(|line| line.splitn(7, ',').nth(6).unwrap_or_default().to_string())
                .collect()
        };
        let (decimals, fractions) = (
            answers("sweep-decimals.csv"),
            answers("sweep-fractions.csv"),
        );
        assert_eq!(decimals.len(), 2001);
        assert_eq!(decimals, fractions, "{backend}");
    }
}

/// NEWCOMER m17 and m18: one row and one claim are counted in the singular, and a file
/// separated by semicolons is named as such instead of "column 'm' is required".
#[test]
fn counts_read_as_english_and_a_semicolon_file_is_named() {
    let dir = scratch("plural");
    let one = dir.join("one.csv");
    std::fs::write(&one, "m,M,v\n1,1,3/5\n").unwrap();
    let (code, _, stderr) = rodimpact(&["batch", one.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert_eq!(
        stderr,
        "1 row, laws held exactly on 1\nv: 1 claim, 0 wrong, max rel error 0, median 0\n"
    );
    let semi = dir.join("semi.csv");
    std::fs::write(&semi, "m;M;a\n1;1;1\n").unwrap();
    let (code, _, stderr) = rodimpact(&["batch", semi.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(
        stderr,
        "error: header: the header has no commas (it is separated by ';'): rodimpact reads comma-separated files\n"
    );
}

/// NEWCOMER M3: an engine returns round-off (1e-17) for a quantity that vanishes exactly (omega
/// for a centre hit: m = M = l = v0 = 1, a = 0 gives v = 0, V = 1, omega = 0). No ulp count
/// accepts it (exit 1, diagnosis `off`); `--atol 1e-12` accepts it in the scene's own units
/// (here v0/l = 1), and still refuses 1e-11.
#[test]
fn an_absolute_floor_accepts_round_off_where_the_exact_value_vanishes() {
    let dir = scratch("atol");
    let file = dir.join("zero.csv");
    std::fs::write(
        &file,
        "id,m,M,a,v,V,omega\nc,1,1,0,0,1,1e-17\nd,1,1,0,0,1,1e-11\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    let (code, out, _) = rodimpact(&["batch", path, "--ulps", "16"]);
    assert_eq!(code, 1);
    assert!(
        out.contains("\nc,1,1,0,0,1,1e-17,0,1,0,true,true,0,0,true,0,0,false,inf,"),
        "{out}"
    );
    let (code, out, err) = rodimpact(&["batch", path, "--ulps", "16", "--atol", "1e-12"]);
    assert_eq!(code, 1, "row d is still wrong: {err}");
    assert!(out.contains(",omega_ok,"), "{out}");
    assert!(out.contains("\nc,1,1,0,0,1,1e-17,0,1,0,true,true,0,0,true,0,0,true,inf,4352464011485697175,+3.33e-35,ok\n"), "{out}");
    assert!(
        out.contains("\nd,1,1,0,0,1,1e-11,0,1,0,true,true,0,0,true,0,0,false,inf,"),
        "{out}"
    );
    assert!(
        err.contains(
            "claims also agree within 1e-12 of the scene's units (v0, v0/l, m v0, m v0^2/2)\n"
        ),
        "{err}"
    );
    assert!(err.contains("omega: 2 claims, 1 wrong (row 2)"), "{err}");
    let (code, _, err) = rodimpact(&["batch", path, "--atol", "2"]);
    assert_eq!(code, 2);
    assert_eq!(err, "error: atol: must be a number from 0 to 1, got 2\n");
}

/// NEWCOMER m19: `batch --help` lists every scene column the engine suite writes (the oblique
/// ones too), from the one table of scene keys.
#[test]
fn the_help_lists_every_scene_column() {
    let (code, help, _) = rodimpact(&["batch", "--help"]);
    assert_eq!(code, 0);
    assert!(
        help.contains("header among m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega (m and M required)"),
        "{help}"
    );
    let (_, suite, _) = rodimpact(&["scenes", "--suite", "engines"]);
    let header = suite.lines().next().unwrap();
    for column in header.split(',').filter(|c| !["id", "class"].contains(c)) {
        assert!(help.contains(column), "{column} missing from batch --help");
    }
}
