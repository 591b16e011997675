//! The `table` command-line contract: options, formats, and the defects users met.

use crate::common;

use common::rodimpact;

/// Regression (NEWCOMER, issue 12): `--help` says `--rod I=X` is in units of M l^2, but X was
/// taken as the absolute I of the unit scene (m = l = 1, M = M/m), so `I=1/3` failed for
/// every mass ratio below 1/3 and meant a different rod for every row. I = (1/3) M l^2 is the
/// uniform rod: the tables must then be the uniform rod's, row for row.
#[test]
fn rod_moment_is_in_units_of_m_l_squared() {
    let (code, uniform, stderr) = rodimpact(&["table", "--format", "csv"]);
    assert_eq!(code, 0, "{stderr}");
    let (code, relative, stderr) = rodimpact(&["table", "--format", "csv", "--rod", "I=1/3"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(relative, uniform);
    let (code, md, _) = rodimpact(&["table", "--only", "T1", "--rod", "I=1/3"]);
    assert_eq!(code, 0);
    assert!(md.contains("Rod: I = 1/3 M l²; e = 1."), "{md}");
    // The dumbbell is I = M l^2.
    let (_, dumbbell, _) = rodimpact(&[
        "table", "--format", "csv", "--only", "T1", "--rod", "dumbbell",
    ]);
    let (_, one, _) = rodimpact(&["table", "--format", "csv", "--only", "T1", "--rod", "I=1"]);
    assert_eq!(one, dumbbell);

    for bad in ["I=2", "I=0", "I=-1/2"] {
        let (code, stdout, stderr) = rodimpact(&["table", "--rod", bad]);
        assert_eq!((code, stdout.as_str()), (2, ""), "{bad}");
        assert!(
            stderr.starts_with("error: rod: I=X means I = X M l^2 and needs 0 < X <= 1"),
            "{stderr}"
        );
    }
}

/// Regression: with a* at the end (M = 2m), T2 printed the a/l = 1 row twice, once as the
/// listed point and once as a*.
#[test]
fn t2_lists_a_star_once_when_it_is_a_listed_point() {
    let (code, stdout, _) =
        rodimpact(&["table", "--only", "T2", "--ratio", "2", "--format", "csv"]);
    assert_eq!(code, 0);
    let a_column: Vec<&str> = stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(a_column, ["0", "1/4", "1/2", "3/4", "1"]);
    let (_, md, _) = rodimpact(&["table", "--only", "T2", "--ratio", "2"]);
    assert!(md.contains("the row a/l = 1 is the optimum a*"), "{md}");
    // M = m: a* = sqrt(6)/3 sits between 3/4 and 1, in its simplified form.
    let (_, md, _) = rodimpact(&["table", "--only", "T2"]);
    let rows: Vec<&str> = md.lines().filter(|l| l.starts_with("| ")).skip(1).collect();
    assert_eq!(rows.len(), 6);
    assert!(
        rows[4].starts_with("| √6/3 | 1/2 | 1/2 | √6/2 | 1.22474487139 |"),
        "{}",
        rows[4]
    );
}

/// Regression: `table --help` printed `[default: md] [default: md]`.
#[test]
fn help_states_each_default_once() {
    let (code, help, _) = rodimpact(&["table", "--help"]);
    assert_eq!(code, 0);
    assert_eq!(help.matches("[default: md]").count(), 1, "{help}");
    assert!(help.contains("I=X (I = X M l^2)"), "{help}");
}

/// Regression (NEWCOMER #15): `table --format csv` printed five tables in one file separated by
/// `# T1` comment lines, rows of 1-7 fields, no decimals for T3, `v` for what is v/v0. Several
/// tables now make one rectangular file with a `table` column; every number has its decimal.
#[test]
fn several_tables_make_one_rectangular_csv() {
    let (code, stdout, _) = rodimpact(&["table", "--format", "csv"]);
    assert_eq!(code, 0);
    let lines: Vec<&str> = stdout.lines().collect();
    let header: Vec<&str> = lines[0].split(',').collect();
    assert_eq!(header[0], "table");
    assert!(lines.iter().all(|l| !l.starts_with('#')));
    for line in &lines {
        assert_eq!(line.split(',').count(), header.len(), "{line}");
    }
    let ids: std::collections::BTreeSet<&str> = lines[1..]
        .iter()
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(
        ids.into_iter().collect::<Vec<_>>(),
        ["T1", "T2", "T3", "T4", "T5"]
    );
    for name in [
        "v/v0",
        "V/v0",
        "omega*l/v0",
        "energy_lost/K0",
        "M/m",
        "d_star/l",
    ] {
        assert!(header.contains(&name), "{name}");
        assert!(
            header.contains(&format!("{name}_decimal").as_str()),
            "{name}_decimal"
        );
    }
    // T3's sticking row: every exact value with its decimal.
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let sticking: Vec<&str> = lines
        .iter()
        .filter(|l| l.starts_with("T3,"))
        .nth(2)
        .unwrap()
        .split(',')
        .collect();
    assert_eq!(sticking[col("e")], "0");
    assert_eq!(sticking[col("omega*l/v0")], "sqrt(6)/4");
    assert_eq!(sticking[col("omega*l/v0_decimal")], "0.61237243569579452");
    assert_eq!(sticking[col("energy_lost/K0")], "1/4");
    assert_eq!(
        sticking[col("energy_lost/K0_decimal")],
        "0.25000000000000000"
    );
}

/// T6 against the impulse balance worked by hand for M = 3m struck at the end (I = M l^2/3 =
/// m l^2, so a^2/I = 1/m), e = 1/2, v0t = v0/2: k_n = 1 + 1/3 + 1 = 7/3, J = (3/2)/(7/3) = 9/14;
/// k_t = 1 + 1/3 = 4/3, so sticking takes Jt = (1/2)/(4/3) = 3/8 and mu* = (3/8)/(9/14) = 7/12.
/// At mu = 1/10 it slides: Jt = 9/140, vt = 1/2 - 9/140 = 61/140, Vt = 3/140, and friction
/// takes mu J (u_t - mu J k_t/2) = 36/1225; omega = a J/I = 9/14 in every row.
/// `table --only T6 ARGS --format csv` as its rows, each a map from column name to cell, and
/// the whole text (for messages).
fn t6_csv(args: &[&str]) -> (Vec<std::collections::BTreeMap<String, String>>, String) {
    let (code, text, stderr) =
        rodimpact(&[&["table", "--only", "T6", "--format", "csv"], args].concat());
    assert_eq!(code, 0, "{stderr}");
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let rows = text
        .lines()
        .skip(1)
        .map(|l| {
            header
                .iter()
                .zip(l.split(','))
                .map(|(h, c)| (h.to_string(), c.to_string()))
                .collect()
        })
        .collect();
    (rows, text)
}

#[test]
fn t6_against_the_impulse_balance_by_hand() {
    let (rows, text) = t6_csv(&["--ratio", "3", "--e", "1/2", "--v0t", "1/2"]);
    let cell = |mu: &str, name: &str| {
        let r = rows
            .iter()
            .find(|r| r["mu"] == mu)
            .unwrap_or_else(|| panic!("{text}"));
        r[name].clone()
    };
    let names = [
        "contact",
        "Jt/(m*v0)",
        "vt/v0",
        "Vt/v0",
        "omega*l/v0",
        "friction_loss/(m*v0^2)",
    ];
    assert_eq!(
        names.map(|n| cell("1/10", n)),
        ["slide", "9/140", "61/140", "3/140", "9/14", "36/1225"]
    );
    assert_eq!(
        [cell("7/12", "contact"), cell("7/12", "Jt/(m*v0)")],
        ["stick", "3/8"]
    );
    assert_eq!(cell("1/2", "contact"), "slide");
    assert_eq!(cell("0", "contact"), "frictionless");
    assert!(
        rows.iter().all(|r| r["omega*l/v0"] == "9/14"),
        "omega changes with mu: {text}"
    );
    // T6 is not one of the paper's tables: the default is T1-T5.
    let (_, all, _) = rodimpact(&["table"]);
    assert!(all.contains("### T5.") && !all.contains("### T6."));
}

/// T6 with a spinning disc struck off the end, by hand: M = m, l = 1 (I = 1/3), a = 1/2,
/// e = 1/2; a disc r = 1/10 spinning at 5 with v0t = 1/2. k_n = 1 + 1 + (1/4)/(1/3) = 11/4,
/// J = (3/2)/(11/4) = 6/11, omega = a J/I = 9/11; the rim slips at u_t = 1/2 + 5/10 = 1,
/// k_t = 1/m + r^2/(m r^2/2) + 1/M = 4, mu* = 1/((6/11) 4) = 11/24. At mu = 1/4 it slides:
/// Jt = 3/22, vt = 1/2 - 3/22 = 4/11, Vt = 3/22, spin = 5 - 2 (3/22)/(1/10) = 25/11, friction
/// takes (3/22)(1 - (3/22) 4/2) = 12/121. From mu* on it sticks: Jt = u_t/k_t = 1/4,
/// vt = Vt = 1/4, the disc stops turning (5 - 2 (1/4) 10 = 0), friction takes 1/(2 4) = 1/8.
#[test]
fn t6_with_a_spinning_disc_off_the_end_by_hand() {
    let (rows, text) = t6_csv(&[
        "--a", "1/2", "--e", "1/2", "--v0t", "1/2", "--radius", "1/10", "--spin", "5",
    ]);
    let mus: Vec<&str> = rows.iter().map(|r| r["mu"].as_str()).collect();
    assert_eq!(
        mus,
        ["0", "1/10", "1/4", "11/24", "1/2", "1", "2"],
        "{text}"
    );
    let names = [
        "contact",
        "Jt/(m*v0)",
        "vt/v0",
        "Vt/v0",
        "spin*l/v0",
        "omega*l/v0",
        "friction_loss/(m*v0^2)",
    ];
    let row = |mu: &str| {
        let r = rows.iter().find(|r| r["mu"] == mu).unwrap();
        names.map(|n| r[n].clone())
    };
    assert_eq!(
        row("0"),
        ["frictionless", "0", "1/2", "0", "5", "9/11", "0"]
    );
    assert_eq!(
        row("1/4"),
        ["slide", "3/22", "4/11", "3/22", "25/11", "9/11", "12/121"]
    );
    for mu in ["11/24", "2"] {
        assert_eq!(
            row(mu),
            ["stick", "1/4", "1/4", "1/4", "0", "9/11", "1/8"],
            "{mu}"
        );
    }
    let (_, md, _) = rodimpact(&[
        "table", "--only", "T6", "--a", "1/2", "--radius", "1/10", "--spin", "5",
    ]);
    assert!(
        md.starts_with("### T6. Oblique impact with friction at a = 1/2 l\n"),
        "{md}"
    );
    assert!(
        md.contains("a solid disc of radius r = 1/10 l (I = m r²/2) spinning at ω_d0 = 5 v0/l"),
        "{md}"
    );
    // Ten columns: narrower gaps keep the LaTeX table within the page.
    let (_, latex, _) = rodimpact(&[
        "table", "--only", "T6", "--radius", "1/10", "--format", "latex",
    ]);
    assert!(latex.contains("\\setlength{\\tabcolsep}{4pt}"));
}

/// T6 runs past mu* even when mu* is beyond the listed values (v0t = 3 v0: mu* = 15/4, and a
/// row at 2 mu*); a scene with nothing sliding, a spin without a disc and an impact off the rod
/// are refused.
#[test]
fn t6_runs_past_the_threshold_and_refuses_what_has_no_friction() {
    let (rows, text) = t6_csv(&["--v0t", "3"]);
    let last: Vec<[&str; 2]> = rows[rows.len() - 2..]
        .iter()
        .map(|r| [r["mu"].as_str(), r["contact"].as_str()])
        .collect();
    assert_eq!(last, [["15/4", "stick"], ["15/2", "stick"]], "{text}");
    for (args, message) in [
        (
            &["--v0t", "0"][..],
            "error: v0t: nothing slides at the contact before the impact (v0t + spin r = 0), so friction has nothing to do: give a --v0t or a disc's --spin\n",
        ),
        (
            &["--v0t", "-1/2", "--radius", "1/10", "--spin", "5"],
            "error: v0t: nothing slides at the contact before the impact (v0t + spin r = 0), so friction has nothing to do: give a --v0t or a disc's --spin\n",
        ),
        (
            &["--spin", "1"],
            "error: spin: a point projectile has no spin: give the disc's --radius too\n",
        ),
        (
            &["--a", "3/2"],
            "error: a: must lie on the rod, |a| <= l = 1, got 3/2\n",
        ),
        (&["--radius", "0"], "error: radius: must be > 0, got 0\n"),
    ] {
        let (code, stdout, stderr) = rodimpact(&[&["table", "--only", "T6"], args].concat());
        assert_eq!(
            (code, stdout.as_str(), stderr.as_str()),
            (2, "", message),
            "{args:?}"
        );
    }
}

/// Regression (G14): `table --only T6 --pivot P` printed T6 unchanged (even with `--pivot 7`,
/// off the rod), though `--pivot` is for T1: a flag that changes none of the tables asked for
/// is now refused by name, as `plot` refuses flags that change nothing in its figure.
#[test]
fn a_flag_that_changes_none_of_the_tables_asked_for_is_refused() {
    for (args, want) in [
        (
            &["--only", "T6", "--pivot", "0"][..],
            "error: pivot: changes only T1, which --only T6 leaves out; leave --pivot out\n",
        ),
        (
            &["--only", "T6", "--pivot", "7"][..],
            "error: pivot: changes only T1, which --only T6 leaves out; leave --pivot out\n",
        ),
        (
            &["--v0t", "1"][..],
            "error: v0t: changes only T6, which the default T1-T5 leaves out; leave --v0t out\n",
        ),
        (
            &["--only", "T4", "--rod", "dumbbell"][..],
            "error: rod: changes only T1, T2, T3, T5, T6, which --only T4 leaves out; leave --rod out\n",
        ),
        (
            &["--only", "t2,T3", "--ratios", "1,2"][..],
            "error: ratios: changes only T1, T5, which --only t2,T3 leaves out; leave --ratios out\n",
        ),
    ] {
        let (code, stdout, stderr) = rodimpact(&[&["table"], args].concat());
        assert_eq!((code, stdout.as_str()), (2, ""), "{args:?}");
        assert_eq!(stderr, want, "{args:?}");
    }
    // A flag that changes one of the tables asked for is honoured as before.
    let (code, stdout, stderr) = rodimpact(&["table", "--only", "T1,T6", "--pivot", "0"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("### T6."), "{stdout}");
}

/// NEWCOMER m4: the caption above each LaTeX table keeps a gap to the rule below it (it sat on
/// `\toprule`): the caption package, with captions on top, 6 pt. Compiled with pdflatex and
/// looked at.
#[test]
fn latex_captions_keep_a_gap_to_the_rule() {
    let (code, out, _) = crate::common::rodimpact(&["table", "--format", "latex", "--only", "T3"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("\\usepackage[tableposition=top,skip=6pt]{caption}\n"),
        "{out}"
    );
    assert!(out.find("{caption}").unwrap() < out.find("\\begin{document}").unwrap());
}
