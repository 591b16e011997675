//! `rodimpact::textbook`: significant figures, units, formulas, identities, problem files.
//! Expected values are derived by hand (see the comments), not by the code under test.

use rodimpact::field::q;
use rodimpact::scene::SceneInput;
use rodimpact::textbook::problems::parse_problems;
use rodimpact::textbook::sigfig::{Precision, Printed, Tie, round_sig};
use rodimpact::textbook::units::{Dimension, Measured, pi_bounds};
use rodimpact::textbook::{
    AnswerAgreement, ClaimedAnswer, Exact, check_scene, expr, numeric::decide,
};

fn rat(text: &str) -> rodimpact::field::Q {
    rodimpact::number::parse(text).unwrap()
}

#[test]
fn significant_figures_as_printed() {
    // (written, figures, ambiguous range)
    type Case = (&'static str, u32, Option<(u32, u32)>);
    let cases: [Case; 16] = [
        ("2.0", 2, None),
        ("2", 1, None),
        ("0.0500", 3, None),
        ("1.50e3", 3, None),
        ("1.5E-3", 2, None),
        ("1e3", 1, None),
        ("1500", 2, Some((2, 4))),
        ("1500.", 4, None),
        ("100", 1, Some((1, 3))),
        ("12", 2, None),
        ("-0.143", 3, None),
        (".8992", 4, None),
        ("350.", 3, None),
        ("007", 1, None),
        ("10e3", 1, Some((1, 2))),
        ("1071.43", 6, None),
    ];
    for (text, figures, ambiguous) in cases {
        let p = Printed::parse("x", text).unwrap();
        assert_eq!(
            p.precision,
            Precision::Figures { figures, ambiguous },
            "{text}"
        );
    }
    assert_eq!(
        Printed::parse("x", "36/19").unwrap().precision,
        Precision::Exact
    );
    assert_eq!(
        Printed::parse("x", "0").unwrap().precision,
        Precision::Exact
    );
    assert_eq!(
        Printed::parse("x", "0.00").unwrap().precision,
        Precision::ZeroAt { place: -2 }
    );
    assert_eq!(
        Printed::parse("x", "1500")
            .unwrap()
            .with_sig(3)
            .unwrap()
            .precision,
        Precision::Figures {
            figures: 3,
            ambiguous: None
        }
    );
}

#[test]
fn rounding_to_significant_figures() {
    // (exact, figures, half-up result)
    let cases = [
        ("36/19", 3, "1.89"),   // 1.894736...
        ("7/3", 2, "2.3"),      // 2.333...
        ("45/22", 3, "2.05"),   // 2.04545...
        ("9996/1000", 3, "10"), // carries into a new decade
        ("-1/7", 3, "-0.143"),
        ("1449/1", 2, "1400"),
        ("1450/1", 2, "1500"), // a tie: up
    ];
    for (x, n, expected) in cases {
        assert_eq!(round_sig(&rat(x), n, Tie::Up), rat(expected), "{x} to {n}");
    }
    assert_eq!(round_sig(&rat("1450"), 2, Tie::Down), rat("1400"));
}

fn agreement(claim: &str, exact: &str) -> AnswerAgreement {
    decide(
        &ClaimedAnswer::parse(claim).unwrap(),
        &Exact::Rational(rat(exact)),
        None,
    )
    .agreement
}

#[test]
fn verdicts_by_significant_figures() {
    let cases = [
        ("omega=1.89", "36/19", AnswerAgreement::Agrees),
        ("omega=1.90", "36/19", AnswerAgreement::LastDigit),
        // 1.88 is one unit off the rounded 1.89 but 1.5 units from 1.8947...: not a slip.
        ("omega=1.88", "36/19", AnswerAgreement::Disagrees),
        ("omega=1.87", "36/19", AnswerAgreement::Disagrees),
        ("omega=0.947", "36/19", AnswerAgreement::Disagrees),
        ("omega=-1.89", "36/19", AnswerAgreement::Agrees), // by magnitude
        ("v=-1.89", "36/19", AnswerAgreement::Disagrees),  // only omega ignores the sign
        ("omega=36/19", "36/19", AnswerAgreement::Agrees),
        ("omega=1.8947", "36/19", AnswerAgreement::Agrees),
        ("omega=1.895", "36/19", AnswerAgreement::Agrees), // 1.894736... to 4 figures
        ("omega=1.896", "36/19", AnswerAgreement::Disagrees), // 1.26 units from 1.894736...
        ("omega=1.894", "36/19", AnswerAgreement::LastDigit), // 0.74 units: a rounding slip
        ("v=2.2", "9/4", AnswerAgreement::Agrees), // exact tie 2.25: either rounding is right
        ("v=2.3", "9/4", AnswerAgreement::Agrees),
        ("v=1500", "1549", AnswerAgreement::Agrees), // ambiguous: read with 2 figures
        ("v=1500", "1551", AnswerAgreement::LastDigit),
        ("v=0.0", "1/50", AnswerAgreement::Agrees), // 0.02 rounds to 0.0
        ("v=0.0", "1/10", AnswerAgreement::Disagrees), // a zero carries no figure: -100 %
        ("v=0", "1/1000", AnswerAgreement::Disagrees), // an integer zero is exact
        ("v=37/19", "36/19", AnswerAgreement::Disagrees),
    ];
    for (claim, exact, expected) in cases {
        assert_eq!(agreement(claim, exact), expected, "{claim} vs {exact}");
    }
    // --sig overrides the printed figures: 1500 read with 4 figures disagrees with 1549.
    let d = decide(
        &ClaimedAnswer::parse("v=1500").unwrap(),
        &Exact::Rational(rat("1549")),
        Some(4),
    );
    assert_eq!(d.agreement, AnswerAgreement::Disagrees);
    let d = decide(
        &ClaimedAnswer::parse("v=1500").unwrap(),
        &Exact::Rational(rat("1549")),
        None,
    );
    assert!(d.notes[0].contains("ambiguous"), "{:?}", d.notes);
}

#[test]
fn units_convert_exactly_to_si() {
    let cases = [
        ("100 g", Dimension::Mass, "1/10"),
        ("1.50 kg", Dimension::Mass, "3/2"),
        ("2.5 mm", Dimension::Length, "1/400"),
        ("60.0 cm", Dimension::Length, "3/5"),
        ("4 m", Dimension::Length, "4"),
        ("300 cm/s", Dimension::Speed, "3"),
        ("36 km/h", Dimension::Speed, "10"),
        ("12.0m/s", Dimension::Speed, "12"),
        ("2.0 rad/s", Dimension::AngularSpeed, "2"),
        ("22.5 J", Dimension::Energy, "45/2"),
        ("1.50 kg m/s", Dimension::Impulse, "3/2"),
        ("3 N*s", Dimension::Impulse, "3"),
    ];
    for (text, dim, si) in cases {
        let m = Measured::parse("x", text, dim).unwrap();
        assert_eq!(m.si().unwrap(), rat(si), "{text}");
    }
    let err = |text, dim| Measured::parse("v0", text, dim).unwrap_err().to_string();
    assert_eq!(
        err("3 kg", Dimension::Speed),
        "v0: unit 'kg' is a mass, expected a speed"
    );
    assert!(err("3 furlongs", Dimension::Speed).contains("unknown unit 'furlongs'"));
    // Sig figs are those of the written number, in its own unit: "60.0 cm" has 3.
    let m = Measured::parse("x", "60.0 cm", Dimension::Length).unwrap();
    assert_eq!(
        m.printed.precision,
        Precision::Figures {
            figures: 3,
            ambiguous: None
        }
    );
}

#[test]
fn rpm_is_decided_with_bounds_on_pi() {
    let (lo, hi) = pi_bounds(30);
    assert!(lo < hi && hi.clone() - &lo == rat("1e-30"));
    assert!(rat("3.14159265358979") < lo && hi < rat("355/113")); // 355/113 = 3.14159292 > pi
    // omega = 36/19 rad/s = 18.0931... rpm.
    assert_eq!(
        agreement("omega=18.1 rpm", "36/19"),
        AnswerAgreement::Agrees
    );
    assert_eq!(
        agreement("omega=18.09 rpm", "36/19"),
        AnswerAgreement::Agrees
    );
    assert_eq!(
        agreement("omega=18.2 rpm", "36/19"),
        AnswerAgreement::Disagrees
    ); // 0.107 rpm off
    assert_eq!(
        agreement("omega=18.0 rpm", "36/19"),
        AnswerAgreement::LastDigit
    ); // 0.093 rpm off
    assert_eq!(agreement("omega=18 rpm", "36/19"), AnswerAgreement::Agrees);
    // A fraction in rpm can never equal a rational omega (pi is irrational).
    assert_eq!(
        agreement("omega=18/1 rpm", "36/19"),
        AnswerAgreement::Disagrees
    );
}

#[test]
fn expressions_parse_with_limits() {
    let r = expr::parse("c", "12*m*v0/((M+4*m)*L)").unwrap();
    assert!(r.is_rational());
    assert_eq!(
        expr::parse("c", "2^-1 + (m/m)^3").unwrap().constant(),
        Some((q(3, 2), q(1, 1)))
    );
    assert_eq!(
        expr::parse("c", "sqrt(8)/2").unwrap().constant(),
        Some((q(1, 1), q(2, 1)))
    );
    assert_eq!(
        expr::parse("c", "sqrt(2)*sqrt(2)").unwrap().constant(),
        Some((q(2, 1), q(1, 1)))
    );
    for (bad, why) in [
        ("2m", "expected an operator"),
        ("m+", "expected a number"),
        ("(m", "expected ')'"),
        ("x*m", "unknown symbol 'x'"),
        ("1/0", "division by zero"),
        ("m/(M-M)", "division by zero"),
        ("m^1000", "exponent beyond"),
        ("sqrt(2)+sqrt(3)", "sums of different square roots"),
        ("sqrt(sqrt(2))", "nested square roots"),
        ("sqrt(-4)", "negative"),
        ("((m+M+l+a+v0+e+p)^8)^8", "too large"),
    ] {
        let err = expr::parse("claim omega", bad).unwrap_err().to_string();
        assert!(
            err.starts_with("claim omega: ") && err.contains(why),
            "{bad}: {err}"
        );
    }
    let deep = "(".repeat(100_000) + "m" + &")".repeat(100_000);
    let err = expr::parse("c", &deep).unwrap_err().to_string();
    assert!(err.contains("longer than 10000"), "{err}");
    let deep = "(".repeat(4_000) + "m" + &")".repeat(4_000);
    let err = expr::parse("c", &deep).unwrap_err().to_string();
    assert!(err.contains("nested deeper than 200"), "{err}");
    let minus = "-".repeat(9_000) + "m";
    assert!(
        expr::parse("c", &minus)
            .unwrap_err()
            .to_string()
            .contains("nested deeper")
    );
}

fn symbolic(input: SceneInput, claims: &[&str]) -> Vec<(AnswerAgreement, Vec<String>)> {
    let claims: Vec<ClaimedAnswer> = claims
        .iter()
        .map(|c| ClaimedAnswer::parse(c).unwrap())
        .collect();
    let check = check_scene(&input, &claims, None).unwrap();
    assert!(check.symbolic.is_some());
    check
        .answers
        .into_iter()
        .map(|d| (d.agreement, d.notes))
        .collect()
}

fn end_hit_elastic() -> SceneInput {
    SceneInput {
        length: Some("L".into()),
        a: Some("L/2".into()),
        e: Some("1".into()),
        ..Default::default()
    }
}

#[test]
fn symbolic_identities_true_and_false() {
    // Elastic end hit of a free uniform rod: effective mass M/4 at the end, so
    // J = 2 m (M/4) v0 / (m + M/4), V = J/M = 2 m v0/(M + 4m), omega = J l / (M l^2/3).
    let r = symbolic(
        end_hit_elastic(),
        &[
            "omega=12*m*v0/((M+4*m)*L)",
            "omega=6*m*v0/((M+4*m)*L)",
            "V=2*m*v0/(M+4*m)",
            "v=v0*(4*m-M)/(4*m+M)",
            "omega=-6*m*v0/((M+4*m)*l)",
            "energy_lost=0",
            "V_cm=m*v0/(m+M)",
        ],
    );
    let verdicts: Vec<AnswerAgreement> = r.iter().map(|(v, _)| *v).collect();
    use AnswerAgreement::*;
    assert_eq!(
        verdicts,
        [Agrees, Disagrees, Agrees, Agrees, Agrees, Agrees, Agrees]
    );
    assert!(r[0].1[0].starts_with("identity in"), "{:?}", r[0].1);
    // The counterexample is a concrete valid scene with the two values.
    let note = &r[1].1[0];
    assert!(
        note.contains("counterexample") && note.contains("m=1"),
        "{note}"
    );
    assert!(r[4].1.iter().any(|n| n.contains("opposite sign")));
}

#[test]
fn symbolic_scene_flags_and_free_symbols() {
    // M = 4m, end hit, elastic: the projectile stops (equal effective masses).
    let s = SceneInput {
        rod_mass: Some("4*m".into()),
        from_end: Some("0".into()),
        e: Some("1".into()),
        ..Default::default()
    };
    let r = symbolic(
        s,
        &["v=0", "omega=3*v0/(4*l)", "omega=3*v0/(2*L)", "V=v0/4"],
    );
    assert!(
        r.iter().all(|(v, _)| *v == AnswerAgreement::Agrees),
        "{r:?}"
    );
    // Sticking at a = L/4 on a free rod with m = M: the claim with d (= l - a = l/2).
    // Exact: 1/M_eff = 1/M + a^2/I = (1 + 3/4)/M, M_eff = 4M/7; J = m M_eff v0/(m + M_eff)
    // = 4 m v0/11 (M = m); omega = J a / I = (4 m v0/11)(l/2)/(m l^2/3) = 6 v0/(11 l).
    let s = SceneInput {
        rod_mass: Some("m".into()),
        length: Some("L".into()),
        a: Some("L/4".into()),
        e: Some("0".into()),
        ..Default::default()
    };
    let r = symbolic(
        s,
        &[
            "omega=6*v0/(11*l)",
            "omega=3*v0/(11*d)",
            "omega=6*v0/(11*d)",
        ],
    );
    let verdicts: Vec<AnswerAgreement> = r.iter().map(|(v, _)| *v).collect();
    assert_eq!(
        verdicts,
        [
            AnswerAgreement::Agrees,
            AnswerAgreement::Agrees,
            AnswerAgreement::Disagrees
        ]
    );
    // Every quantity not given is free except e (elastic) and the rod (uniform), as in solve.
    let s = SceneInput {
        length: Some("L".into()),
        ..Default::default()
    };
    let r = symbolic(s, &["V_cm=m*v0/(m+M)", "v=v0"]);
    assert_eq!(r[0].0, AnswerAgreement::Agrees);
    assert_eq!(r[1].0, AnswerAgreement::Disagrees);
}

#[test]
fn symbolic_input_errors_name_the_field() {
    let run = |input: SceneInput, claim: &str| {
        check_scene(&input, &[ClaimedAnswer::parse(claim).unwrap()], None)
            .unwrap_err()
            .to_string()
    };
    let s = SceneInput {
        m: Some("2*M".into()),
        rod_mass: Some("m+m".into()),
        ..Default::default()
    };
    assert!(run(s, "v=m").contains("circular"));
    assert_eq!(
        run(end_hit_elastic(), "omega=p*m"),
        "claim omega: p is used but the rod has no pivot (--pivot)"
    );
    let s = SceneInput {
        m: Some("-1".into()),
        ..end_hit_elastic()
    };
    assert!(run(s, "v=m").starts_with("m: -1 is outside the domain"));
    assert!(
        run(end_hit_elastic(), "omega_max=l")
            .contains("omega(a*) when M <= 2*m and omega(l) otherwise, two formulas")
    );
    assert!(run(end_hit_elastic(), "omega=30 rpm").contains("rpm cannot be compared"));
}

const GOOD: &str = r#"
[[problem]]
id = "p1"
source = "test"
[problem.given]
m = "1 kg"
M = "1 kg"
collision = "elastic"
[problem.claims]
omega = "6/5"
"#;

fn file_error(text: &str) -> String {
    parse_problems("t.toml", text).unwrap_err().to_string()
}

#[test]
fn every_problem_file_error_is_one_line_naming_the_key() {
    assert_eq!(parse_problems("t.toml", GOOD).unwrap().len(), 1);
    let cases = [
        (
            GOOD.replace("source", "sorce"),
            "t.toml: line 4: unknown field `sorce`",
        ),
        (
            GOOD.replace("[[problem]]", "[[problems]]"),
            "t.toml: line 2: unknown field `problems`",
        ),
        (
            GOOD.replace("M = \"1 kg\"", "mass = \"1 kg\""),
            "unknown field `mass`",
        ),
        (
            GOOD.replace("omega = \"6/5\"", "omega = 1.2"),
            "claims.omega: write the value as a string",
        ),
        (
            GOOD.replace("omega = \"6/5\"", "omegaa = \"1.2\""),
            "claims.omegaa: unknown name 'omegaa'",
        ),
        (
            GOOD.replace("omega = \"6/5\"", ""),
            "problem 'p1': claims: give 1 to 100 claims",
        ),
        (
            GOOD.replace("\"elastic\"", "\"bouncy\""),
            "given.collision: expected elastic, inelastic or sticking",
        ),
        (
            GOOD.replace(
                "collision = \"elastic\"",
                "collision = \"elastic\"\ne = \"1\"",
            ),
            "given.collision: give either e or collision",
        ),
        (GOOD.replace("id = \"p1\"", ""), "missing field `id`"),
        (
            GOOD.replace("m = \"1 kg\"", "m = 1"),
            "line 6: invalid type: integer `1`, expected a string",
        ),
        (
            GOOD.replace("source = \"test\"", "source = \"test\"\nsig = 0"),
            "problem 'p1': sig: must be a whole number",
        ),
        (
            GOOD.replace("[problem.given]", "[problem.given"),
            "t.toml: line",
        ),
        ("".to_string(), "missing field `problem`"),
    ];
    for (text, expected) in cases {
        let err = file_error(&text);
        assert!(err.contains(expected), "expected {expected:?} in {err:?}");
        assert!(!err.contains('\n'), "one line: {err:?}");
        assert!(err.starts_with("t.toml"), "{err}");
    }
    let huge = "#".repeat(rodimpact::textbook::problems::MAX_FILE_BYTES + 1);
    assert!(file_error(&huge).contains("limit"));
    // Scene errors and claimed values surface when checking, naming the problem and the field.
    let checked = |text: &str| {
        let problems = parse_problems("t.toml", text).unwrap();
        rodimpact::textbook::problems::check_problems("t.toml", &problems, None)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        checked(&GOOD.replace("m = \"1 kg\"", "m = \"1 m/s\"")),
        "t.toml: problem 'p1': m: unit 'm/s' is a speed, expected a mass"
    );
    assert_eq!(
        checked(&GOOD.replace("omega = \"6/5\"", "omega = \"1.2 kg\"")),
        "t.toml: problem 'p1': claims.omega: unit 'kg' is a mass, expected an angular speed"
    );
    assert!(
        checked(&GOOD.replace("omega = \"6/5\"", "omega = \"2*m)\""))
            .starts_with("t.toml: problem 'p1': claims.omega: expected an operator")
    );
}

/// RELIABILITY F8: one budget for every formula of a run. A budget that holds one heavy
/// claim refuses the second, naming it, whether the claims share a scene or not; the same
/// claims under a fresh budget each pass.
#[test]
fn the_work_budget_is_shared_by_every_claim_of_a_run() {
    use rodimpact::textbook::{check_scene_within, expr::Budget};
    let heavy = format!("V=(m+{})^8", "7".repeat(200));
    let mut probe = Budget::run();
    let one = ClaimedAnswer::parse_within(&heavy, &mut probe).unwrap();
    let scene = SceneInput {
        m: Some("1".into()),
        rod_mass: Some("1".into()),
        ..Default::default()
    };
    check_scene_within(&scene, &[one], None, &mut probe).unwrap();
    let cost = probe.spent();
    assert!(cost > 100_000, "a heavy claim: {cost}");
    let mut budget = Budget::new(cost + cost / 2);
    let first = ClaimedAnswer::parse_within(&heavy, &mut budget).unwrap();
    check_scene_within(&scene, &[first], None, &mut budget).unwrap();
    let err = ClaimedAnswer::parse_within(&heavy.replace("V=", "v="), &mut budget)
        .unwrap_err()
        .to_string();
    assert!(
        err.starts_with("claim v: the claims of this run together cost more than"),
        "{err}"
    );
}

/// NEWCOMER #3/#4 at the library level: a scene of formulas takes e = 1 and a uniform rod
/// unless told otherwise; `--e e` keeps e a symbol.
#[test]
fn symbolic_defaults_and_an_explicit_symbol_e() {
    let s = SceneInput {
        rod_mass: Some("4*m".into()),
        a: Some("l".into()),
        ..Default::default()
    };
    let r = check_scene(&s, &[ClaimedAnswer::parse("v=0").unwrap()], None).unwrap();
    assert!(r.all_agree());
    let summary = r.symbolic.unwrap();
    assert_eq!(summary.free, ["m", "l", "v0"]);
    assert_eq!(
        summary.defaults,
        ["e = 1 (elastic)", "uniform rod (I = M l^2/3)"]
    );
    // With e a symbol, v = (1 - e) v0/2 at the end of M = 4m (effective mass m).
    let s = SceneInput {
        e: Some("e".into()),
        ..s
    };
    let r = check_scene(
        &s,
        &[
            ClaimedAnswer::parse("v=(1-e)*v0/2").unwrap(),
            ClaimedAnswer::parse("v=0").unwrap(),
        ],
        None,
    )
    .unwrap();
    assert_eq!(r.answers[0].agreement, AnswerAgreement::Agrees);
    assert_eq!(r.answers[1].agreement, AnswerAgreement::Disagrees);
    assert_eq!(r.symbolic.unwrap().defaults, ["uniform rod (I = M l^2/3)"]);
}
