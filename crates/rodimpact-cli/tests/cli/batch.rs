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
    assert!(err.contains("omega: 2 claims, 1 wrong (d)"), "{err}");
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

/// NEWCOMER m17: the wrong claims are listed by id, a repeated id once with its count; a claim
/// that is not a finite number is `non-finite` (summary: "not a finite number"); an engine that
/// counts the spin the other way is told so (`omega-sign`, beside the angular momentum it breaks).
#[test]
fn wrong_claims_by_id_a_flipped_spin_and_a_nan() {
    let dir = scratch("ids");
    let file = dir.join("log.csv");
    std::fs::write(
        &file,
        "id,m,M,a,v,V,omega,J\nend,1,1,1,0.7,0.3,0.9,\nend,1,1,1,0.8,0.3,0.9,\n\
         flip,1,1,1/2,3/11,8/11,-12/11,\nnan,1,1,1/2,NaN,8/11,12/11,\nj,1,1,1/2,3/11,8/11,12/11,inf\n",
    )
    .unwrap();
    let (code, out, err) = rodimpact(&["batch", file.to_str().unwrap()]);
    assert_eq!(code, 1);
    let diagnoses: Vec<&str> = out
        .lines()
        .skip(1)
        .map(|l| l.rsplit(',').next().unwrap())
        .collect();
    assert_eq!(
        diagnoses,
        [
            "energy-loss",
            "momentum;angular-momentum",
            "angular-momentum;omega-sign",
            "non-finite",
            "non-finite"
        ]
    );
    for line in [
        "v: 5 claims, 3 wrong (end ×2, nan), max rel error inf (1 not a finite number), median 1.7e-1\n",
        "omega: 5 claims, 3 wrong (end ×2, flip), max rel error 2.00, median 2.5e-1\n",
        "J: 1 claim, 1 wrong (j), max rel error inf (1 not a finite number), median inf\n",
        "  omega-sign: 1 (flip)\n",
        "  non-finite: 2 (nan, j)\n",
    ] {
        assert!(err.contains(line), "{line}{err}");
    }
}

/// NEWCOMER m24: a CI job on an engine's log. pymunk 7.3.1's known differences
/// (`tests/data/engines/pymunk-7.3.1-f64-expected.csv`) let its log pass (exit 0), with the
/// summary as JSON; the same log with one spin flipped fails (exit 1) and names the new finding;
/// a baseline line that matches no row is told; bad baselines exit 2 and write nothing.
#[test]
fn a_baseline_lets_known_findings_pass_and_fails_new_ones() {
    let dir = scratch("expect");
    let log = std::path::PathBuf::from(data_file("engines/pymunk-7.3.1-f64.csv"));
    let baseline = std::path::PathBuf::from(data_file("engines/pymunk-7.3.1-f64-expected.csv"));
    let json = dir.join("summary.json");
    let run = |log: &str, baseline: &str| {
        rodimpact(&[
            "batch",
            log,
            "--ulps",
            "16",
            "--atol",
            "1e-12",
            "--expect",
            baseline,
            "--summary-json",
            json.to_str().unwrap(),
        ])
    };
    let (code, _, err) = run(log.to_str().unwrap(), baseline.to_str().unwrap());
    assert_eq!(code, 0, "{err}");
    // The baseline's path as the summary shows it (its tail, for a long one).
    assert!(
        err.ends_with(
            "pymunk-7.3.1-f64-expected.csv: 150 rows with known findings only, 0 with new ones\n"
        ),
        "{err}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(summary["rows"], 264);
    assert_eq!(summary["passed"], true);
    assert_eq!(summary["diagnosis"]["no-contact"]["rows"], 84);
    assert_eq!(summary["expected"]["rows_unexpected"], 0);
    assert_eq!(summary["claims"]["omega"]["wrong"], 141);

    // One row's spin flipped, and a stale line in the baseline.
    let text = std::fs::read_to_string(&log).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let omega = lines[0].split(',').position(|c| c == "omega").unwrap();
    let row = lines
        .iter()
        .position(|l| l.starts_with("free-inside-1,"))
        .unwrap();
    let mut cells: Vec<String> = lines[row].split(',').map(str::to_string).collect();
    cells[omega] = format!("-{}", cells[omega]);
    lines[row] = cells.join(",");
    let flipped = dir.join("flipped.csv");
    std::fs::write(&flipped, lines.join("\n") + "\n").unwrap();
    let stale = dir.join("stale.csv");
    std::fs::write(
        &stale,
        std::fs::read_to_string(&baseline).unwrap() + "gone-*,energy-gain\n",
    )
    .unwrap();
    let (code, _, err) = run(flipped.to_str().unwrap(), stale.to_str().unwrap());
    assert_eq!(code, 1);
    assert!(err.contains(": 150 rows with known findings only, 1 with new ones: free-inside-1 (angular-momentum, omega-sign)\n"), "{err}");
    assert!(
        err.ends_with("stale.csv lines that matched no row: 15 (gone-*,energy-gain)\n"),
        "{err}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(summary["passed"], false);
    assert_eq!(
        summary["expected"]["unexpected"],
        serde_json::json!([{"id": "free-inside-1", "findings": ["angular-momentum", "omega-sign"]}])
    );
    assert_eq!(
        summary["expected"]["unmatched_lines"],
        serde_json::json!([{"line": 15, "id": "gone-*", "finding": "energy-gain"}])
    );

    // Bad baselines and a log without ids: exit 2, one line, no summary written.
    std::fs::remove_file(&json).unwrap();
    let bad = dir.join("bad.csv");
    for (text, expected) in [
        (
            "id,finding\nend,energy-loose\n",
            "line 2: unknown finding 'energy-loose'",
        ),
        (
            "id;finding\n",
            "line 1: the header is 'id;finding', expected 'id,finding'",
        ),
    ] {
        std::fs::write(&bad, text).unwrap();
        let (code, out, err) = run(log.to_str().unwrap(), bad.to_str().unwrap());
        assert_eq!((code, out.as_str()), (2, ""), "{err}");
        assert!(
            err.starts_with("error: expect: ") && err.contains(expected),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1);
    }
    let untagged = dir.join("untagged.csv");
    std::fs::write(&untagged, "m,M,v\n1,1,1\n").unwrap();
    let (code, _, err) = run(untagged.to_str().unwrap(), baseline.to_str().unwrap());
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: expect: the batch has no id column to match the baseline's ids against\n"
    );
    assert!(!json.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// NEWCOMER M2: an oblique log that claims `vt, Vt, tangential_impulse` in `check`'s words has
/// them checked (before, they passed through, and the output named them twice). By hand, m = M
/// = l = 1, a = 1/2, v0 = v0t = 3, mu = 1/10: the normal problem gives v = 9/11, so J = 24/11; the
/// contact slides (the stick impulse 3/2 is more than mu J), Jt = mu J = 12/55, vt = 3 - 12/55 =
/// 153/55, Vt = 12/55. A wrong Jt = 0.5 fails (exit 1); a claim along the rod needs an oblique
/// column.
#[test]
fn friction_claims_are_checked() {
    let dir = scratch("friction-claims");
    let file = dir.join("oblique.csv");
    std::fs::write(
        &file,
        "id,m,M,l,a,v0,v0t,mu,v,V,omega,vt,Vt,tangential_impulse\n\
         right,1,1,1,1/2,3,3,1/10,9/11,24/11,36/11,153/55,12/55,12/55\n\
         wrong,1,1,1,1/2,3,3,1/10,9/11,24/11,36/11,153/55,12/55,0.5\n",
    )
    .unwrap();
    let (code, out, err) = rodimpact(&["batch", file.to_str().unwrap()]);
    assert_eq!(code, 1, "{err}");
    let header: Vec<&str> = out.lines().next().unwrap().split(',').collect();
    let mut names = header.clone();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), header.len(), "a name twice: {header:?}");
    assert!(header.contains(&"tangential_impulse_exact") && header.contains(&"vt_ok"));
    assert!(
        out.contains(
            "\nwrong,1,1,1,1/2,3,3,1/10,9/11,24/11,36/11,153/55,12/55,0.5,9/11,24/11,36/11,153/55,12/55,,12/55,slide,true,"
        ),
        "{out}"
    );
    assert!(out.contains(",false,1.29\n"), "{out}");
    assert!(
        err.contains("tangential_impulse: 2 claims, 1 wrong (wrong), max rel error 1.29"),
        "{err}"
    );
    assert!(err.contains("vt: 2 claims, 0 wrong"), "{err}");
    let paper = dir.join("paper.csv");
    std::fs::write(&paper, "m,M,vt\n1,1,1\n").unwrap();
    let (code, _, err) = rodimpact(&["batch", paper.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "error: header: claim column 'vt' is an oblique scene's output: it needs a column among v0t, mu, radius, spin, rod-v, rod-vt, rod-omega\n"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// NEWCOMER m24: tolerances per class of rows. A pivot held by a relative 1e-6 accepts V within
/// 1.3e-7 of 3/4; free rows held to 2 ulps accept v one float from 3/5 and refuse three; the
/// report names the rules, and a row under a relative rule has no ulps count.
#[test]
fn tolerances_per_class_of_rows() {
    let dir = scratch("tolerance");
    let file = dir.join("log.csv");
    std::fs::write(
        &file,
        "id,m,M,a,pivot,v,V,omega\n\
         free-1,1,1,1,,0.6000000000000001,0.4,1.2\n\
         piv-1,1,1,1,-1,0.5,0.7500001,0.75\n\
         free-2,1,1,1,,0.6000000000000003,0.4,1.2\n",
    )
    .unwrap();
    let path = file.to_str().unwrap();
    let rules = [
        "--tolerance",
        "pivot=rtol:1e-6",
        "--tolerance",
        "free=ulps:2",
    ];
    let (code, out, err) = rodimpact(&[&["batch", path][..], &rules[..]].concat());
    assert_eq!(code, 1, "{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert!(
        lines[1].ends_with(",true,1.67e-16,1,true,0,0,true,0,0,+1.20e-16,ok"),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].ends_with(",true,0,,true,0.000000133,,true,0,,+0.000000150,ok"),
        "{}",
        lines[2]
    );
    assert!(lines[3].contains(",false,5.00e-16,3,"), "{}", lines[3]);
    assert!(err.contains(
        "claims agree, on pivot rows: within a relative 0.000001\n\
         claims agree, on free-rod rows: within 2 f64 ulps of the exact value\n"
    ));
    assert!(err.contains("v: 3 claims, 1 wrong (free-2)"), "{err}");
    // An id pattern, first rule wins: free-2 now passes too.
    let (code, _, err) = rodimpact(&[
        "batch",
        path,
        "--tolerance",
        "id:free-2=rtol:1e-15",
        "--tolerance",
        "free=ulps:2",
        "--tolerance",
        "pivot=rtol:1e-6",
    ]);
    assert_eq!(code, 0, "{err}");
    // Without the rules, every float claim must be exact.
    let (code, _, err) = rodimpact(&["batch", path]);
    assert_eq!(code, 1);
    assert!(
        err.contains("v: 3 claims, 2 wrong (free-1, free-2)"),
        "{err}"
    );
    for (args, message) in [
        (
            vec!["--tolerance", "joint=rtol:1"],
            "error: tolerance: 'joint' is not a class: free, pivot, oblique or id:PATTERN\n",
        ),
        (
            vec!["--tolerance", "pivot"],
            "error: tolerance: 'pivot' is not CLASS=RULE (e.g. pivot=rtol:1e-6)\n",
        ),
        (
            vec!["--tolerance", "pivot=rtol:2"],
            "error: rtol: must be a number from 0 to 1, got 2\n",
        ),
        (
            vec!["--float", "f32"],
            "error: float: the float format of an ulps count: give --ulps N or a --tolerance CLASS=ulps:N\n",
        ),
        (
            vec!["--backend", "f64", "--tolerance", "free=ulps:3"],
            "error: tolerance: an ulps rule needs the exact backend (the distance is to the correctly rounded exact value); use rtol:R with --backend f64\n",
        ),
    ] {
        common::assert_refused(&[&["batch", path][..], &args[..]].concat(), message);
    }
}
