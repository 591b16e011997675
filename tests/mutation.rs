//! A verifier that cannot fail is worthless: feed the claims a wrong formula and the claims that
//! rest on it must fail, while the others still check.

use rodimpact::claims::model::{k, sym};
use rodimpact::claims::{Paper, decide, registry};

fn failing(paper: &Paper) -> Vec<&'static str> {
    registry()
        .iter()
        .map(|e| (e.id, decide(e.id, paper).expect("registered")))
        .filter(|(_, d)| d.verdict.is_err())
        .map(|(id, _)| id)
        .collect()
}

#[test]
fn the_paper_as_printed_checks_everywhere() {
    assert_eq!(failing(&Paper::as_printed()), Vec::<&str>::new());
}

#[test]
fn a_wrong_omega_is_caught() {
    let mut paper = Paper::as_printed();
    paper.omega = paper.omega.clone() * &k(1, 2); // the classic halved omega
    let failed = failing(&paper);
    assert!(failed.contains(&"C15"), "{failed:?}");
    assert!(
        !failed.contains(&"C21"),
        "an unrelated claim still checks: {failed:?}"
    );
}

#[test]
fn a_wrong_rod_velocity_is_caught() {
    let mut paper = Paper::as_printed();
    paper.big_v = paper.big_v.clone() * &k(3, 2); // 3m/M instead of 2m/M
    let failed = failing(&paper);
    assert!(failed.contains(&"C14"), "{failed:?}");
}

#[test]
fn a_wrong_threshold_is_caught() {
    let mut paper = Paper::as_printed();
    paper.threshold = k(1, 1).into(); // "M > m implies a* > l": false
    let failed = failing(&paper);
    assert!(failed.contains(&"C23"), "{failed:?}");
}

#[test]
fn a_wrong_inertia_is_caught() {
    let mut paper = Paper::as_printed();
    paper.uniform_inertia = (sym("M") * &sym("l") * &sym("l") / k(12, 1)).into(); // length l taken for 2l
    let failed = failing(&paper);
    assert!(failed.contains(&"C21"), "{failed:?}");
}
