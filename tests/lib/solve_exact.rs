//! The exact solver against independent derivations, the closed forms, the reference batch
//! and the conservation laws.

use crate::common;

use common::{any_scene, rat, reference_rows, scene};
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use rodimpact::field::big::{RBig, to_q};
use rodimpact::field::{Q, QSqrt};
use rodimpact::impact::Balance;
use rodimpact::scene::Support;
use rodimpact::solve::fast::{closed_form::closed_form, linear::solve};
use rodimpact::solve::optimum::{omega_max_squared, optimum};

/// (scene, v, V, omega, pivot impulse or "-", energy lost), each worked by hand.
const CASES: &[(&str, &str, &str, &str, &str, &str)] = &[
    // The paper, M = m, uniform rod hit at the end: D = 1 + 1 + 3 = 5.
    ("m=1 M=1 a=1", "3/5", "2/5", "6/5", "-", "0"),
    // Case (i): a = 0 gives omega = 0 and V = 2 m v0/(M + m).
    ("m=1 M=3 a=0", "-1/2", "1/2", "0", "-", "0"),
    // Case (ii): a = 0, m = M: the projectile stops and the rod takes v0.
    ("m=2 M=2 a=0 v0=7/2", "0", "7/2", "0", "-", "0"),
    // e = 1/2, M = m: q = 4, v = (q - e)/(1 + q), V = (1 + e) r/(1 + q), omega = (1 + e)(m a/I)/(1 + q).
    ("m=1 M=1 a=1 e=1/2", "7/10", "3/10", "9/10", "-", "3/40"),
    // Sticking, M = m: the struck point moves with the projectile, V + omega = v.
    ("m=1 M=1 a=1 e=0", "4/5", "1/5", "3/5", "-", "1/10"),
    // Dumbbell M = 2, hit halfway: I = 2, q = 1/2 + 1/8.
    (
        "m=1 M=2 a=1/2 rod=dumbbell",
        "-3/13",
        "8/13",
        "4/13",
        "-",
        "0",
    ),
    // Pivot at the centre, sticking: I_p = 1, omega = m d v0/(I_p + m d^2) = 1/2, pivot takes -1/2.
    ("m=1 M=3 a=1 pivot=0 e=0", "1/2", "0", "1/2", "-1/2", "1/4"),
    // A door (pivot at an end), elastic, hit at the far edge d = 2: I_p = 4, omega = 1/2, v = 0.
    ("m=1 M=3 a=1 pivot=-1", "0", "1/2", "1/2", "1/2", "0"),
    // The same door hit at its centre of percussion d = I_p/(M h) = 4/3: no pivot impulse.
    ("m=1 M=3 a=1/3 pivot=-1", "-5/13", "6/13", "6/13", "0", "0"),
];

#[test]
fn hand_worked_scenes_are_reproduced_exactly() {
    for &(text, v, big_v, omega, pivot, lost) in CASES {
        let s = scene(text);
        let out = solve(&s.params::<Q>()).expect("nonsingular");
        assert_eq!(out.after.v, rat(v), "v for {text}");
        assert_eq!(out.after.rod_v, rat(big_v), "V for {text}");
        assert_eq!(out.after.omega, rat(omega), "omega for {text}");
        match pivot {
            "-" => assert!(out.pivot_impulse.is_none(), "{text}"),
            p => assert_eq!(out.pivot_impulse, Some(rat(p)), "pivot impulse for {text}"),
        }
        assert_eq!(out.energy.lost(), rat(lost), "energy lost for {text}");
        assert!(
            out.residuals.all_zero(),
            "residuals for {text}: {:?}",
            out.residuals
        );
    }
}

#[test]
fn only_the_laws_that_apply_are_reported() {
    let free_elastic = solve(&scene("m=1 M=1").params::<Q>()).unwrap();
    assert!(
        free_elastic
            .residuals
            .get(Balance::LinearMomentum)
            .is_some()
    );
    assert!(free_elastic.residuals.get(Balance::Energy).is_some());
    let pivot_sticking = solve(&scene("m=1 M=1 pivot=0 e=0").params::<Q>()).unwrap();
    assert!(
        pivot_sticking
            .residuals
            .get(Balance::LinearMomentum)
            .is_none()
    );
    assert!(pivot_sticking.residuals.get(Balance::Energy).is_none());
    assert!(pivot_sticking.pivot_impulse.is_some());
}

#[test]
fn reference_batch_is_reproduced_exactly() {
    let mut rows = 0;
    for (line, s, f) in reference_rows("bench-textbook.csv", usize::MAX) {
        let out = solve(&s.params::<Q>()).unwrap();
        assert_eq!(
            (&out.after.v, &out.after.rod_v, &out.after.omega),
            (&f[0], &f[1], &f[2]),
            "row {line}"
        );
        assert!(out.residuals.all_zero());
        rows += 1;
    }
    assert_eq!(rows, 10_000);
}

#[test]
fn f64_agrees_with_q_on_ordinary_scenes() {
    // Bound: 1e-12 relative to the natural scale of each output (v0 for v and V, v0/l for
    // omega); measured worst case on the reference batches is about 1e-15 on this scale.
    for (line, s, _) in reference_rows("bench-1e6.csv", 2000) {
        let exact = solve(&s.params::<Q>()).unwrap().after;
        let float = solve(&s.params::<f64>()).unwrap().after;
        let v0 = rodimpact::field::Field::nearest_f64(s.v0());
        let l = rodimpact::field::Field::nearest_f64(s.half_length());
        for (name, x, fx, scale) in [
            ("v", &exact.v, float.v, v0),
            ("V", &exact.rod_v, float.rod_v, v0),
            ("omega", &exact.omega, float.omega, v0 / l),
        ] {
            let err = (rodimpact::field::Field::nearest_f64(x) - fx).abs();
            assert!(err <= 1e-12 * scale, "{name} in row {line}: error {err}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    /// Law: for every valid rational scene the applicable momentum balances hold exactly,
    /// energy is conserved exactly when e = 1 and never created otherwise.
    #[test]
    fn conservation_laws_hold_exactly(s in any_scene()) {
        let out = solve(&s.params::<Q>()).unwrap();
        prop_assert!(out.residuals.get(Balance::AngularMomentum).unwrap().is_zero());
        prop_assert!(out.residuals.all_zero());
        prop_assert!(!out.energy.lost().is_negative());
        prop_assert_eq!(out.residuals.get(Balance::LinearMomentum).is_some(), matches!(s.support(), Support::Free));
    }

    /// Law: omega_max squared without a root, over Q and over dashu's rationals, is the square
    /// of the optimum's omega_max in Q(sqrt d).
    #[test]
    fn omega_max_squared_is_the_optimums_squared(s in any_scene()) {
        let o = optimum(&s).unwrap();
        let squared = o.omega_max.clone() * &o.omega_max;
        let q: Q = omega_max_squared(&s).unwrap();
        prop_assert_eq!(QSqrt::rational(q.clone()), squared);
        let big: RBig = omega_max_squared(&s).unwrap();
        prop_assert_eq!(to_q(&big), q);
    }

    /// Law: the paper's closed forms (generalised to e, and the fixed-axis formula) equal the
    /// linear solve over Q.
    #[test]
    fn closed_forms_equal_the_linear_solve(s in any_scene()) {
        let p = s.params::<Q>();
        prop_assert_eq!(closed_form(&p).unwrap(), solve(&p).unwrap().after);
    }

    /// Law: Newton's restitution holds at the contact: the struck point separates at e v0.
    #[test]
    fn restitution_holds_at_the_contact(s in any_scene()) {
        let p = s.params::<Q>();
        let after = solve(&p).unwrap().after;
        let separation = after.rod_point_velocity(s.a()) - &after.v;
        prop_assert_eq!(separation, s.e() * s.v0());
    }
}
