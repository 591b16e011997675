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
