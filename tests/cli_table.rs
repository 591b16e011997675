//! The `table` command-line contract: options, formats, and the defects users met.

mod common;

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
#[test]
fn t6_against_the_impulse_balance_by_hand() {
    let out = rodimpact(&[
        "table", "--only", "T6", "--ratio", "3", "--e", "1/2", "--v0t", "1/2", "--format", "csv",
    ]);
    let (code, text, _) = out;
    assert_eq!(code, 0);
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let cell = |mu: &str, name: &str| {
        let r = rows
            .iter()
            .find(|r| r[0] == mu)
            .unwrap_or_else(|| panic!("{text}"));
        r[column(name)]
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
    assert_eq!(cell("0", "contact"), "none (frictionless)");
    let omega = column("omega*l/v0");
    assert!(
        rows.iter().all(|r| r[omega] == "9/14"),
        "omega changes with mu: {text}"
    );
    // T6 is not one of the paper's tables: the default is T1-T5.
    let (_, all, _) = rodimpact(&["table"]);
    assert!(all.contains("### T5.") && !all.contains("### T6."));
}

/// The README shows T6 as `table --only T6` prints it.
#[test]
fn readme_shows_t6_as_printed() {
    let (_, t6, _) = rodimpact(&["table", "--only", "T6"]);
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    assert!(readme.contains(&format!("$ rodimpact table --only T6\n{t6}```")));
}
