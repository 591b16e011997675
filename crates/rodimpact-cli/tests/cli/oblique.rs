//! Oblique and frictional scenes through `solve`: the README's two scenes checked against an
//! independent derivation, the keys that appear only when a scene needs them, and the refusals.
//!
//! The expected fractions were derived independently of rodimpact's solver: a SymPy script
//! solving the full two-dimensional impulse balance (vector impulse P at the contact, cross
//! products for both bodies' angular momentum, Newton's law on the normal relative velocity,
//! the stick candidate tested against the friction cone, else sliding with |Pt| = mu Pn). The
//! hand derivations below repeat it in the decoupled form the physics allows.

use crate::common;

use common::{rat, rodimpact, solve_json};
use num_traits::Signed;
use serde_json::Value;

fn exact(j: &Value, key: &str) -> String {
    j[key]["exact"]
        .as_str()
        .unwrap_or_else(|| panic!("{key} missing"))
        .to_string()
}

const OBLIQUE: &[&str] = &[
    "--m", "1", "--M", "2", "--a", "1/2", "--v0", "3", "--v0t", "2", "--e", "1/2", "--mu", "1/5",
];

/// README scene 1: m = 1, M = 2, l = 1 (I = 2/3), a = 1/2, v0 = 3, v0t = 2, e = 1/2, mu = 1/5.
/// By hand: k_n = 1/m + 1/M + a^2/I = 1 + 1/2 + 3/8 = 15/8, J = (1 + e) v0/k_n = 12/5.
/// k_t = 1/m + 1/M = 3/2; the stick impulse v0t/k_t = 4/3 exceeds mu J = 12/25: it slides,
/// Jt = 12/25. Then v = 3 - 12/5 = 3/5, V = 6/5, omega = J a/I = 9/5, vt = 2 - 12/25 = 38/25,
/// Vt = 6/25; friction loses mu J (v0t - mu J k_t/2) = 12/25 (2 - 9/25) = 492/625 and
/// restitution (1 - e^2) v0^2/(2 k_n) = 9/5, in all 1617/625.
#[test]
fn readme_oblique_frictional_scene() {
    let (m, big_m, i, a, v0, v0t, e, mu) = (
        rat("1"),
        rat("2"),
        rat("2/3"),
        rat("1/2"),
        rat("3"),
        rat("2"),
        rat("1/2"),
        rat("1/5"),
    );
    let one = rat("1");
    let k_n = &one / &m + &one / &big_m + &a * &a / &i;
    let j_n = (&one + &e) * &v0 / &k_n;
    let k_t = &one / &m + &one / &big_m;
    assert!(
        (&v0t / &k_t).abs() > &mu * &j_n,
        "the hand derivation slides"
    );
    let j_t = &mu * &j_n;
    let lost =
        &j_t * (&v0t - &j_t * &k_t / rat("2")) + (&one - &e * &e) * &v0 * &v0 / (rat("2") * &k_n);
    let hand = [
        ("v", &v0 - &j_n / &m),
        ("V", &j_n / &big_m),
        ("omega", &j_n * &a / &i),
        ("vt", &v0t - &j_t / &m),
        ("Vt", &j_t / &big_m),
        ("impulse", j_n.clone()),
        ("tangential_impulse", j_t.clone()),
    ];
    let written = ["3/5", "6/5", "9/5", "38/25", "6/25", "12/5", "12/25"];
    let j = solve_json(OBLIQUE);
    for ((key, value), want) in hand.iter().zip(written) {
        assert_eq!(value.to_string(), want, "hand {key}");
        assert_eq!(exact(&j, key), want, "solve {key}");
    }
    assert_eq!(lost, rat("1617/625"));
    assert_eq!(j["energy"]["lost"]["exact"], "1617/625");
    assert_eq!(j["energy"]["lost_friction"]["exact"], "492/625");
    assert_eq!(j["energy"]["lost_restitution"]["exact"], "9/5");
    assert_eq!(j["contact"], "slide");
    assert!(
        j.get("spin").is_none(),
        "a point projectile has no spin key"
    );
    for law in [
        "linear_momentum",
        "tangential_momentum",
        "angular_momentum",
        "energy_loss",
    ] {
        assert_eq!(j["residuals"][law], "0", "{law}");
    }
}

/// README scene 2: a solid disc m = 1, r = 1/4, spinning counterclockwise at 8 rad/s, strikes a
/// uniform rod M = 3, l = 1 (I = 1) at a = 1/2 with v0 = 2, elastic, mu = 1/2.
/// By hand: k_n = 1 + 1/3 + 1/4 = 19/12, J = 2 v0/k_n = 48/19. The rim slips along the rod with
/// u_t = spin r = 2; k_t = 1/m + r^2/(m r^2/2) + 1/M = 1 + 2 + 1/3 = 10/3, so the stick impulse is
/// 3/5 <= mu J = 24/19: it sticks. Then vt = -3/5, spin = 8 - 2 (3/5)/(1/4) = 16/5, Vt = 1/5, and
/// the rim moves with vt + spin r = 1/5 = Vt. Across: v = 2 - 48/19 = -10/19, V = 16/19,
/// omega = J a/I = 24/19 (the spin does not enter the normal problem). Loss: u_t^2/(2 k_t) = 3/5.
#[test]
fn readme_spinning_disc() {
    let j = solve_json(&[
        "--m", "1", "--M", "3", "--a", "1/2", "--v0", "2", "--mu", "1/2", "--radius", "1/4",
        "--spin", "8",
    ]);
    let want = [
        ("v", "-10/19"),
        ("V", "16/19"),
        ("omega", "24/19"),
        ("vt", "-3/5"),
        ("Vt", "1/5"),
        ("spin", "16/5"),
        ("impulse", "48/19"),
        ("tangential_impulse", "3/5"),
    ];
    // The hand derivation, step by step.
    let (m, big_m, i, a, v0, r, spin, mu) = (
        rat("1"),
        rat("3"),
        rat("1"),
        rat("1/2"),
        rat("2"),
        rat("1/4"),
        rat("8"),
        rat("1/2"),
    );
    let one = rat("1");
    let k_n = &one / &m + &one / &big_m + &a * &a / &i;
    let j_n = rat("2") * &v0 / &k_n;
    let slip = &spin * &r;
    let k_t = &one / &m + &r * &r / (&m * &r * &r / rat("2")) + &one / &big_m;
    let j_t = &slip / &k_t;
    assert!(j_t.abs() <= &mu * &j_n, "the hand derivation sticks");
    let hand = [
        &v0 - &j_n / &m,
        &j_n / &big_m,
        &j_n * &a / &i,
        -(&j_t / &m),
        &j_t / &big_m,
        &spin - rat("2") * &j_t / (&m * &r),
        j_n.clone(),
        j_t.clone(),
    ];
    for ((key, value), by_hand) in want.into_iter().zip(hand) {
        assert_eq!(by_hand.to_string(), value, "hand {key}");
        assert_eq!(exact(&j, key), value, "solve {key}");
    }
    assert_eq!(
        &slip * &slip / (rat("2") * &k_t),
        rat("3/5"),
        "u_t^2/(2 k_t)"
    );
    assert_eq!(j["contact"], "stick");
    // mu* = (3/5)/(48/19) = 19/80 <= 1/2.
    assert_eq!(exact(&j, "mu_star"), "19/80");
    assert_eq!(j["energy"]["lost"]["exact"], "3/5");
    assert_eq!(j["energy"]["lost_friction"]["exact"], "3/5");
    assert_eq!(j["energy"]["lost_restitution"]["exact"], "0");
    // Rim velocity after equals the rod's along-axis velocity: the slip stopped.
    let rim = rat("-3/5") + rat("16/5") * rat("1/4");
    assert_eq!(rim, rat("1/5"));
}

/// The same oblique scene seen from a frame moving with (1, -1) (the rod's velocity there):
/// every velocity shifts by the frame's, omega, the impulses and the contact do not.
#[test]
fn a_moving_rod_is_the_rest_scene_in_its_frame() {
    let rest = solve_json(OBLIQUE);
    let mut moving_args = vec![
        "--m", "1", "--M", "2", "--a", "1/2", "--v0", "4", "--v0t", "1", "--e", "1/2", "--mu",
        "1/5", "--rod-v", "1", "--rod-vt", "-1",
    ];
    let moving = solve_json(&moving_args);
    for (key, shift) in [("v", "1"), ("V", "1"), ("vt", "-1"), ("Vt", "-1")] {
        assert_eq!(
            rat(&exact(&moving, key)),
            rat(&exact(&rest, key)) + rat(shift),
            "{key}"
        );
    }
    for key in ["omega", "impulse", "tangential_impulse"] {
        assert_eq!(exact(&moving, key), exact(&rest, key), "{key}");
    }
    assert_eq!(moving["contact"], rest["contact"]);
    // Turning the rod before the impact: the fastest-spin section no longer applies.
    moving_args.extend(["--rod-omega", "1/2"]);
    let turning = solve_json(&moving_args);
    assert!(turning.get("a_star").is_none() && rest.get("a_star").is_some());
}

#[test]
fn oblique_keys_appear_only_when_needed() {
    let plain = solve_json(&["--m", "1", "--M", "1"]);
    for key in ["vt", "Vt", "spin", "tangential_impulse", "contact"] {
        assert!(plain.get(key).is_none(), "plain scene has {key}");
    }
    // The normal impulse J = m (v0 - v) is every scene's (NEWCOMER m18): 2/5 at the end.
    assert_eq!(plain["impulse"]["exact"], "2/5");
    let explicit_zeros = solve_json(&["--m", "1", "--M", "1", "--v0t", "0", "--mu", "0"]);
    assert_eq!(
        plain, explicit_zeros,
        "zero oblique inputs are the paper's scene"
    );
    let no_friction = solve_json(&["--m", "1", "--M", "1", "--v0t", "1"]);
    assert_eq!(exact(&no_friction, "vt"), "1");
    assert_eq!(exact(&no_friction, "tangential_impulse"), "0");
    assert!(
        no_friction.get("contact").is_none(),
        "no friction, no contact"
    );
}

#[test]
fn refusals_are_one_line_exit_2() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--rod-v", "2"],
            "error: v0: no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), is -1, not > 0\n",
        ),
        (
            &["--rod-omega", "1"],
            "error: v0: no approach at the contact point: the projectile's normal velocity minus the struck point's, v0 - (V0 + omega0 a), is 0, not > 0\n",
        ),
        (
            &["--spin", "1"],
            "error: spin: a point projectile has no spin: give the disc's --radius too\n",
        ),
        (
            &["--mu", "-1/2"],
            "error: mu: friction coefficient must be >= 0, got -1/2\n",
        ),
        (&["--radius", "0"], "error: radius: must be > 0, got 0\n"),
        (
            &["--pivot", "-1", "--rod-vt", "1"],
            "error: rod-vt: a pivoted rod's centre moves only by turning about the pivot; give --rod-omega only\n",
        ),
        (
            &["--mu", "1", "--backend", "f64"],
            "error: backend: the float and interval backends solve the paper's scene only; an oblique or frictional scene is solved exactly\n",
        ),
    ];
    for (extra, want) in cases {
        let mut args = vec!["solve", "--m", "1", "--M", "1"];
        args.extend_from_slice(extra);
        let (code, stdout, stderr) = rodimpact(&args);
        assert_eq!((code, stdout.as_str()), (2, ""), "{extra:?}");
        assert_eq!(stderr, *want, "{extra:?}");
    }
}

/// `check` decides claims on the new quantities against the exact oblique answer (the README
/// scene above: vt = 38/25, Vt = 6/25, Jt = 12/25), and refuses what does not apply.
#[test]
fn check_claims_on_oblique_quantities() {
    let mut args = vec!["check"];
    args.extend_from_slice(OBLIQUE);
    args.extend([
        "--claim",
        "vt=1.52 m/s",
        "--claim",
        "Vt=0.24",
        "--claim",
        "tangential_impulse=0.48",
        "--claim",
        "omega=1.8",
        "--json",
    ]);
    let (code, stdout, stderr) = rodimpact(&args);
    assert_eq!(code, 0, "{stderr}");
    let j: Value = serde_json::from_str(&stdout).expect("JSON");
    let text = j.to_string();
    assert!(
        text.contains("38/25") && text.contains("6/25") && text.contains("12/25"),
        "{text}"
    );
    args.extend(["--claim", "Vt=0.3"]);
    let (code, _, _) = rodimpact(&args);
    assert_eq!(code, 1, "a wrong Vt disagrees");
    for (extra, want) in [
        (
            vec!["--claim", "vt=1"],
            "error: claim vt: only an oblique scene has it: give --v0t, --mu, --radius or the rod's motion before the impact\n",
        ),
        (
            vec!["--v0t", "1", "--claim", "spin=1"],
            "error: claim spin: the projectile is a point (no --radius)\n",
        ),
    ] {
        let mut args = vec!["check", "--m", "1", "--M", "1"];
        args.extend(extra);
        let (code, _, stderr) = rodimpact(&args);
        assert_eq!((code, stderr.as_str()), (2, want));
    }
}

/// A frictional scene in symbols is checked too (it was refused before NEWCOMER M6): with no
/// slide along the rod there is nothing to stop, the contact holds, and omega is the paper's.
#[test]
fn a_symbolic_frictional_scene_is_checked() {
    let (code, out, err) = rodimpact(&[
        "check",
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "l",
        "--mu",
        "1",
        "--claim",
        "omega=6/5*v0/l",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("the contact sticks for every value of the symbols, mu_star = 0"),
        "{out}"
    );
}

/// The published problem's scene: the printed 1.3 x 10^3 m/s at 60 degrees to the rod, split.
const HALLIDAY: &[&str] = &[
    "--m",
    "3 g",
    "--M",
    "4 kg",
    "--length",
    "0.5 m",
    "--from-end",
    "0",
    "--pivot",
    "0",
    "--v0",
    "1125.833 m/s",
    "--v0t",
    "650 m/s",
    "--mu",
    "1",
    "--inelastic",
];

/// The oblique problem collection checks through the TOML path: units, a disc, a pivot, a
/// sliding rod. Its four problems written in the textbook style (not published: see the file's
/// header) have answers from an independent two-dimensional impulse balance, rounded to three
/// figures. The two published ones (Halliday's bullet at 60 degrees to a rod on a central axis,
/// run forward from the printed speed) are checked against angular momentum about the axis, by
/// hand: m v0 r = (M L^2/12 + m r^2) omega with r = L/2 (the axis takes the impulse along the
/// rod). Book: m = 3/1000, v0 = 1125833/1000, L = 1/2: omega = (3377499/4000000)/(16036/192000)
/// = 10132497/1002250. Variant: m = 31/10000, v0 = 1248809/1000, L = 21/50: omega =
/// 38713079/3226510. Lodging stops the slip: mu* = m v0t/J with J = v0/(1/m + r^2/I) =
/// 1302925/2251666 for the book, below the files' mu = 1.
#[test]
fn oblique_problem_collection_agrees() {
    let (code, out, err) = rodimpact(&["check", "examples/oblique.toml"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.ends_with("6 problems; 22 of 22 claims agree\n"),
        "{out}"
    );
    assert!(
        out.contains("2010/167 ≈ 12.0359"),
        "the disc's spin after: {out}"
    );
    for omega in ["10132497/1002250 ≈ 10.1098", "38713079/3226510 ≈ 11.9984"] {
        assert!(
            out.contains(omega),
            "the published problems' omega {omega}: {out}"
        );
    }
    let j = solve_json(HALLIDAY);
    assert_eq!(exact(&j, "omega"), "10132497/1002250");
    assert_eq!(
        exact(&j, "vt"),
        "0",
        "the bullet lodges: its slip along the rod stops"
    );
    assert_eq!(j["contact"], "stick");
    assert_eq!(exact(&j, "mu_star"), "1302925/2251666");
}

/// `{"exact": ...}` of `key` in `json`, or `None` when the key is absent.
fn exact_of(json: &Value, key: &str) -> Option<String> {
    json.get(key)
        .map(|v| v["exact"].as_str().unwrap().to_string())
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 48, ..Default::default() })]

    /// The front door: `solve::Answer::of` is the whole answer, and `solve --json` prints
    /// exactly it (both axes, the disc's spin, the impulses, the contact, mu*, the optimum), on
    /// random oblique, frictional, spinning-disc, pivoted and moving-rod scenes.
    #[test]
    fn the_library_answer_is_what_solve_json_prints(scene in common::oblique_scene()) {
        let Some(scene) = scene else { return Ok(()) };
        let answer = rodimpact::solve::Answer::of(&scene);
        let mut args = vec!["--m".to_string(), scene.m().to_string(), "--M".into(), scene.rod_mass().to_string(),
            "--a".into(), scene.a().to_string(), "--e".into(), scene.e().to_string(), "--v0".into(), scene.v0().to_string()];
        if let rodimpact::scene::Support::Pivot(p) = scene.support() {
            args.extend(["--pivot".to_string(), p.to_string()]);
        }
        let o = scene.oblique().cloned().unwrap_or_default();
        for (flag, value) in [("--v0t", &o.v0t), ("--mu", &o.mu), ("--rod-omega", &o.rod_before.omega)] {
            args.extend([flag.to_string(), value.to_string()]);
        }
        if !matches!(scene.support(), rodimpact::scene::Support::Pivot(_)) {
            args.extend(["--rod-v".to_string(), o.rod_before.v.to_string(), "--rod-vt".into(), o.rod_before.vt.to_string()]);
        }
        if let Some(d) = &o.disc {
            args.extend(["--radius".to_string(), d.radius.to_string(), "--spin".into(), d.spin.to_string()]);
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let json = solve_json(&args);
        let text = |x: &rodimpact::field::Q| Some(x.to_string());
        match &answer.impact.oblique {
            Some(done) => {
                proptest::prop_assert_eq!(exact_of(&json, "v"), text(&done.after.v));
                proptest::prop_assert_eq!(exact_of(&json, "V"), text(&done.after.rod.v));
                proptest::prop_assert_eq!(exact_of(&json, "omega"), text(&done.after.rod.omega));
                proptest::prop_assert_eq!(exact_of(&json, "vt"), text(&done.after.vt));
                proptest::prop_assert_eq!(exact_of(&json, "Vt"), text(&done.after.rod.vt));
                proptest::prop_assert_eq!(exact_of(&json, "spin"), done.after.spin.as_ref().and_then(text));
                proptest::prop_assert_eq!(exact_of(&json, "impulse"), text(&answer.impulse));
                proptest::prop_assert_eq!(exact_of(&json, "tangential_impulse"), text(&done.tangential_impulse));
                proptest::prop_assert_eq!(json.get("contact").and_then(Value::as_str), done.contact.map(|c| c.kind()));
                proptest::prop_assert_eq!(exact_of(&json, "mu_star"), answer.mu_star().as_ref().and_then(text));
            }
            None => {
                let after = &answer.impact.outcome.after;
                proptest::prop_assert_eq!(exact_of(&json, "v"), text(&after.v));
                proptest::prop_assert_eq!(exact_of(&json, "omega"), text(&after.omega));
            }
        }
        proptest::prop_assert_eq!(json["a_star"]["squared"].as_str().map(String::from), answer.optimum.as_ref().map(|o| o.squared.to_string()));
        proptest::prop_assert!(answer.laws_hold());
    }

    /// X29: a free rod drifting with (V0, Vt0) before the impact, not turning, answers what the
    /// rod at rest answers at the approach speed v0 - V0, shifted by the drift: v + V0, V + V0,
    /// omega the same (and the slip along the rod counted relative to the rod).
    #[test]
    fn a_drifting_rod_is_the_rod_at_rest_shifted(
        (m, big_m, a, e) in (common::positive(), common::positive(), common::signed_unit(), common::unit_interval()),
        (v0, drift) in (common::positive(), common::signed_unit()),
    ) {
        use rodimpact::scene::Scene;
        let v0 = v0 + rat("1");
        let moving = Scene::builder(m.clone(), big_m.clone()).a(a.clone()).e(e.clone()).v0(v0.clone())
            .rod_before(drift.clone(), rat("0"), rat("0")).build().unwrap();
        let at_rest = Scene::builder(m, big_m).a(a).e(e).v0(&v0 - &drift).build().unwrap();
        let moved = rodimpact::solve::Answer::of(&moving);
        let rest = rodimpact::solve::Answer::of(&at_rest);
        // A zero drift is the paper's scene itself, answered without the along-the-rod part.
        let (v, rod_v, omega) = match &moved.impact.oblique {
            Some(o) => (&o.after.v, &o.after.rod.v, &o.after.rod.omega),
            None => {
                let after = &moved.impact.outcome.after;
                (&after.v, &after.rod_v, &after.omega)
            }
        };
        let still = &rest.impact.outcome.after;
        proptest::prop_assert_eq!(v, &(&still.v + &drift));
        proptest::prop_assert_eq!(rod_v, &(&still.rod_v + &drift));
        proptest::prop_assert_eq!(omega, &still.omega);
        proptest::prop_assert_eq!(&moved.impulse, &rest.impulse);
        proptest::prop_assert_eq!(moved.optimum.map(|o| o.squared), rest.optimum.map(|o| o.squared));
    }
}
