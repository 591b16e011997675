//! A verifier that cannot fail is worthless. Two kinds of mutation:
//!
//! - a wrong formula of the paper: the claims that rest on it must fail, and every other claim
//!   must still check (the lists are exact, over the whole registry);
//! - a tampered certificate: the checker must reject it.

use rodimpact::claims::certificate::{Positive, Witness};
use rodimpact::claims::{
    Certificate, Claim, Decision, Expected, Formula, Paper, PosExpr, Relation, decide, registry,
};
use rodimpact::field::{QSqrt, RatFn, q};

fn sym(name: &str) -> RatFn {
    RatFn::symbol(name)
}

fn k(n: i64, d: i64) -> RatFn {
    RatFn::constant(q(n, d))
}

/// The claims that fail under `paper`, in registry order.
fn failing(paper: &Paper) -> Vec<&'static str> {
    registry()
        .iter()
        .filter(|e| decide(e.id, paper).expect("registered").verdict.is_err())
        .map(|e| e.id)
        .collect()
}

/// The paper as printed with one formula replaced.
fn mutated(edit: impl FnOnce(&mut Paper)) -> Paper {
    let mut paper = Paper::as_printed();
    edit(&mut paper);
    paper
}

/// `D = 1 + m/M + m a^2/I`.
fn paper_d() -> RatFn {
    k(1, 1) + &(sym("m") / sym("M")) + &(sym("m") * &sym("a") * &sym("a") / sym("I"))
}

#[test]
fn the_paper_as_printed_checks_everywhere() {
    assert_eq!(failing(&Paper::as_printed()), Vec::<&str>::new());
}

#[test]
fn a_wrong_projectile_velocity_is_caught() {
    // The sign of Eq. (v) flipped.
    let paper = mutated(|p| p.v = -p.v.clone());
    assert_eq!(
        failing(&paper),
        ["C8", "C11", "C12", "C13", "C18", "X2", "X16", "X17", "X22"]
    );
    // v = -(1 - m/M)/D v0: the a-term dropped, wrong only for a != 0.
    let paper =
        mutated(|p| p.v = (-((k(1, 1) - &(sym("m") / sym("M"))) / paper_d()) * &sym("v0")).into());
    assert_eq!(
        failing(&paper),
        ["C11", "C12", "C13", "C18", "X2", "X16", "X17", "X22"]
    );
}

#[test]
fn a_wrong_rod_velocity_is_caught() {
    let paper = mutated(|p| p.big_v = p.big_v.clone() / k(2, 1));
    assert_eq!(failing(&paper), ["C14", "C17", "X2", "X14", "X16"]);
    // 3m/M instead of 2m/M.
    let paper = mutated(|p| p.big_v = p.big_v.clone() * &k(3, 2));
    assert_eq!(failing(&paper), ["C14", "C17", "X2", "X14", "X16"]);
}

#[test]
fn a_wrong_omega_is_caught() {
    // The classic halved omega.
    let paper = mutated(|p| p.omega = p.omega.clone() * &k(1, 2));
    assert_eq!(
        failing(&paper),
        ["C15", "C20", "X2", "X4", "X16", "X17", "X22"]
    );
    // An offset: wrong at a = 0 too.
    let paper = mutated(|p| p.omega = p.omega.clone() + &(sym("v0") / sym("l")));
    assert_eq!(
        failing(&paper),
        ["C15", "C16", "C18", "C20", "X2", "X4", "X16", "X17", "X22"]
    );
    // Eq. (omega) without the m/M term of D: right in the limit M -> oo (X17 still checks).
    let paper =
        mutated(|p| p.omega = p.omega.clone() * &paper_d() / (paper_d() - &(sym("m") / sym("M"))));
    assert_eq!(failing(&paper), ["C15", "C20", "X2", "X4", "X16", "X22"]);
}

#[test]
fn a_wrong_general_optimum_is_caught() {
    let paper = mutated(|p| p.a_star_squared = p.a_star_squared.clone() * &k(2, 1));
    assert_eq!(
        failing(&paper),
        [
            "C20", "C22", "C30", "C41", "X5", "X6", "X7", "X9", "X10", "X11", "X19", "X23", "X24",
            "X26", "X31"
        ]
    );
    let paper =
        mutated(|p| p.a_star_squared = (sym("I") * &(sym("M") + &sym("m")) / sym("m")).into());
    assert_eq!(
        failing(&paper),
        [
            "C20", "C22", "C30", "C41", "X5", "X6", "X7", "X9", "X10", "X11", "X19", "X23", "X24",
            "X26", "X31"
        ]
    );
    // (M - m) for (M + m).
    let paper = mutated(|p| {
        p.a_star_squared = (sym("I") * &(sym("M") - &sym("m")) / (sym("m") * &sym("M"))).into()
    });
    assert_eq!(
        failing(&paper),
        [
            "C20", "C22", "C30", "C41", "X5", "X6", "X7", "X9", "X10", "X11", "X19", "X23", "X24",
            "X26", "X31"
        ]
    );
}

#[test]
fn a_wrong_uniform_optimum_is_caught() {
    // The natural slip: (M + m)/m instead of (M + m)/(3m).
    let paper = mutated(|p| p.a_star_uniform_squared = p.a_star_uniform_squared.clone() * &k(3, 1));
    assert_eq!(
        failing(&paper),
        ["C4", "C22", "C26", "C27", "C28", "C29", "X6", "X8", "X15"]
    );
    // (M + m)/(2m).
    let paper = mutated(|p| p.a_star_uniform_squared = p.a_star_uniform_squared.clone() * &k(3, 2));
    assert_eq!(
        failing(&paper),
        ["C4", "C22", "C26", "C27", "C28", "C29", "X6", "X8", "X15"]
    );
}

#[test]
fn a_wrong_gyration_optimum_is_caught() {
    // (M + m)/M instead of (M + m)/m.
    let paper = mutated(|p| {
        p.a_star_gyration_squared =
            ((sym("M") + &sym("m")) / sym("M") * &sym("r_G") * &sym("r_G")).into()
    });
    assert_eq!(
        failing(&paper),
        ["C41", "C42", "C43", "C44", "C45", "X8", "X12", "X16"]
    );
    // (M + 2m)/m: X1 does not use a*, and still checks.
    let paper = mutated(|p| {
        p.a_star_gyration_squared = p.a_star_gyration_squared.clone() + &(sym("r_G") * &sym("r_G"))
    });
    assert_eq!(
        failing(&paper),
        ["C41", "C42", "C43", "C44", "C45", "X8", "X12", "X16"]
    );
}

#[test]
fn a_wrong_inertia_is_caught() {
    // I = M l^2/12: the length l taken for 2l.
    let paper =
        mutated(|p| p.uniform_inertia = (sym("M") * &sym("l") * &sym("l") / k(12, 1)).into());
    assert_eq!(failing(&paper), ["C21", "C22", "C37", "X14", "X18", "X25"]);
}

#[test]
fn a_wrong_threshold_is_caught() {
    // "M > m implies a* > l": false.
    let paper = mutated(|p| p.threshold = k(1, 1).into());
    assert_eq!(
        failing(&paper),
        ["C23", "C24", "C25", "C26", "C27", "C30", "C39"]
    );
    let paper = mutated(|p| p.threshold = k(3, 1).into());
    assert_eq!(
        failing(&paper),
        ["C23", "C24", "C25", "C26", "C27", "C30", "C39"]
    );
}

#[test]
fn a_wrong_impulse_formula_is_caught() {
    // 3 m a^2/(M l^2) printed as m a^2/(M l^2).
    let (m, big_m, a, l) = (sym("m"), sym("M"), sym("a"), sym("l"));
    let paper = mutated(|p| {
        p.impulse_linear = (k(2, 1) * &m * &sym("v0")
            / (k(1, 1) + &(m.clone() / big_m.clone()) + &(m * &a * &a / (big_m * &l * &l))))
            .into()
    });
    assert_eq!(failing(&paper), ["C35", "C36", "C37"]);
}

/// The certificate with its claim altered: another right-hand side, a shifted form, the
/// opposite relation, another limit, another integral.
fn corrupted(c: &Certificate) -> Certificate {
    let mut c = c.clone();
    match &mut c {
        Certificate::Identity(c) => c.rhs = c.rhs.clone() + &sym("m"),
        Certificate::Positive(c) => {
            c.form = PosExpr::sum([c.form.clone(), PosExpr::constant(1, 1)])
        }
        Certificate::Witness(c) => {
            c.relation = match c.relation {
                Relation::Eq => Relation::Ne,
                Relation::Ne => Relation::Eq,
                Relation::Lt => Relation::Ge,
                Relation::Ge => Relation::Lt,
                Relation::Gt => Relation::Le,
                Relation::Le => Relation::Gt,
            }
        }
        Certificate::Limit(c) => {
            c.expected = match &c.expected {
                Expected::Finite(x) => Expected::Finite(x.clone() + &k(1, 1)),
                Expected::Infinite { coefficient, order } => Expected::Infinite {
                    coefficient: coefficient.clone(),
                    order: *order - 1,
                },
            }
        }
        Certificate::Integral(c) => c.expected = c.expected.clone() + &k(1, 1),
    }
    c
}

/// Every certificate carries weight: it checks as built, and fails once what it claims is
/// altered.
#[test]
fn every_certificate_can_fail() {
    let paper = Paper::as_printed();
    for e in registry() {
        let claim = decide(e.id, &paper).expect("registered").claim;
        for cert in claim.certificates() {
            assert!(cert.check().is_ok(), "{}: {}", e.id, cert.title());
            assert!(
                corrupted(cert).check().is_err(),
                "{}: {} cannot fail",
                e.id,
                cert.title()
            );
        }
    }
}

/// Claim `id` as decided from the paper as printed.
fn claim(id: &str) -> Claim {
    decide(id, &Paper::as_printed()).expect("registered").claim
}

/// The `index`-th certificate of a claim, counterexamples first.
fn certificate(claim: &mut Claim, index: usize) -> &mut Certificate {
    claim
        .certificates_mut()
        .into_iter()
        .nth(index)
        .expect("the claim has that certificate")
}

/// The positivity certificate at `index`.
fn positivity(claim: &mut Claim, index: usize) -> &mut Positive {
    match certificate(claim, index) {
        Certificate::Positive(c) => c,
        other => panic!("{} is not a positivity certificate", other.title()),
    }
}

/// The witness certificate at `index`.
fn witness(claim: &mut Claim, index: usize) -> &mut Witness {
    match certificate(claim, index) {
        Certificate::Witness(c) => c,
        other => panic!("{} is not a witness certificate", other.title()),
    }
}

#[test]
fn a_form_showing_only_nonnegativity_does_not_prove_strictness() {
    // C8: omega >= 0 vanishes at the centre.
    let mut c8 = claim("C8");
    positivity(&mut c8, 3).strict = true;
    assert!(c8.check().is_err());
    // C25: l^2 - a*^2 is only >= 0 when M <= 2m.
    let mut c25 = claim("C25");
    positivity(&mut c25, 1).strict = true;
    assert!(c25.check().is_err());
    // C20: the gap to the peak is only >= 0 everywhere (it vanishes at the peak).
    let mut c20 = claim("C20");
    positivity(&mut c20, 2).strict = true;
    assert!(c20.check().is_err());
    // X14: every nonnegative form of the far end claimed strict.
    let mut x14 = claim("X14");
    for c in x14.certificates_mut() {
        if let Certificate::Positive(c) = c {
            c.strict = true;
        }
    }
    assert!(x14.check().is_err());
}

#[test]
fn a_form_without_a_visible_sign_is_rejected() {
    // C4: the form negated.
    let mut c4 = claim("C4");
    let form = &mut positivity(&mut c4, 0).form;
    *form = PosExpr::product([PosExpr::constant(-1, 1), form.clone()]);
    assert!(c4.check().is_err());
    // C39: the same value, but a negative constant in the shape.
    let mut c39 = claim("C39");
    let form = &mut positivity(&mut c39, 0).form;
    *form = PosExpr::sum([
        form.clone(),
        PosExpr::constant(1, 1),
        PosExpr::constant(-1, 1),
    ]);
    assert!(c39.check().is_err());
    // C24: a form that is not the expression (scale 6 replaced by 3).
    let mut c24 = claim("C24");
    let form = &mut positivity(&mut c24, 0).form;
    *form = PosExpr::product([PosExpr::constant(1, 2), form.clone()]);
    assert!(c24.check().is_err());
    // X20: the monotonicity reversed, share(a) - share(a + t) is not positive.
    let mut x20 = claim("X20");
    for c in x20.certificates_mut() {
        if let Certificate::Positive(c) = c {
            c.expr = -c.expr.clone();
        }
    }
    assert!(x20.check().is_err());
}

#[test]
fn a_domain_that_admits_the_boundary_is_rejected() {
    // C7: declaring t >= 0 admits e = 1, where nothing is lost.
    let mut c7 = claim("C7");
    let loss = positivity(&mut c7, 1);
    loss.positive.retain(|s| s.name() != "t");
    loss.nonnegative.push(rodimpact::field::Sym::new("t"));
    assert!(c7.check().is_err());
    // X8's 3/4 bound with the slack s of unknown sign.
    let mut x8 = claim("X8");
    let bound = x8
        .certificates_mut()
        .into_iter()
        .find(|c| c.title().starts_with("ratio^2 - 3/4"))
        .expect("the 3/4 certificate");
    if let Certificate::Positive(c) = bound {
        c.nonnegative.clear();
    }
    assert!(bound.check().is_err());
}

#[test]
fn a_witness_with_the_relation_reversed_fails() {
    // C1: omega(a*) > omega(l) at M = m, claimed <=.
    let mut c1 = claim("C1");
    witness(&mut c1, 1).relation = Relation::Le;
    assert!(c1.check().is_err());
    // C27: omega(a*) < omega(l).
    let mut c27 = claim("C27");
    let last = c27.certificates().len() - 1;
    witness(&mut c27, last).relation = Relation::Lt;
    assert!(c27.check().is_err());
    // X22: the asymmetric rod at c = 0 is no counterexample.
    let mut x22 = claim("X22");
    let Decision::Qualified { counterexample, .. } = &mut x22.decision else {
        panic!("X22 is qualified");
    };
    for c in counterexample.iter_mut() {
        if let Certificate::Witness(c) = c {
            for (s, v) in c.instance.iter_mut() {
                if s.name() == "c" {
                    *v = QSqrt::rational(q(0, 1));
                }
            }
        }
    }
    assert!(x22.check().is_err());
}

#[test]
fn the_composite_body_with_the_naive_inertia_is_no_counterexample() {
    // C31: compared with I + m a^2 in place of the composite's I_c.
    let mut c31 = claim("C31");
    let Certificate::Identity(c) = certificate(&mut c31, 0) else {
        panic!("C31's counterexample is an identity");
    };
    let naive = sym("I") + &(sym("m") * &sym("a") * &sym("a"));
    c.rhs = Formula::from(sym("m") * &sym("v0") * &sym("a") / naive);
    assert!(c31.check().is_err());
}
