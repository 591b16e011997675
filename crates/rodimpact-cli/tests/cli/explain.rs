//! `solve --explain`: the working with the scene's numbers, checked against values derived by
//! hand. Free uniform rod, m = M = 1, l = 1, a = 1/2, e = 1/2: I = 1/3, r = 1, s = m a^2/I = 3/4,
//! q = 7/4, D = 11/4; v = (q - e)/D v0 = 5/11, V = (1 + e) r/D v0 = 6/11,
//! omega = (1 + e)(m a/I)/D v0 = (3/2)(3/2)/(11/4) = 9/11; a*^2 = I (M + m)/(m M) = 2/3.
//! Pivot at p = 1/2, M = 3, a = 1, sticking: I = 1, d = 1/2, I + M p^2 = 7/4, q = m d^2/(7/4) = 1/7,
//! D = 8/7, v = q/D = 1/8, omega = (m d/(7/4))/D = 1/4, V = -p omega = -1/8.

use crate::common::rodimpact;

/// `rodimpact solve ARGS`: (exit code, stdout, stderr).
fn run(args: &[&str]) -> (i32, String, String) {
    rodimpact(&[&["solve"], args].concat())
}

#[test]
fn free_rod_working_with_its_numbers() {
    let (code, text, _) = run(&[
        "--m",
        "1",
        "--M",
        "1",
        "--a",
        "1/2",
        "--e",
        "1/2",
        "--explain",
    ]);
    assert_eq!(code, 0);
    for line in [
        "m*v0 = m*v + M*V:   1*1 = 1*v + 1*V",
        "m*a*v0 = m*a*v + I*omega:   1*1/2*1 = 1*1/2*v + 1/3*omega",
        "V + a*omega - v = e*v0:   V + 1/2*omega - v = 1/2*1",
        "r = m/M = 1,   s = m*a^2/I = 3/4,   q = 7/4",
        "D = 1 + q = 11/4",
        "v = (q - e)/D*v0 = 5/11",
        "V = (1 + e)*r/D*v0 = 6/11",
        "omega = (1 + e)*(m*a/I)/D*v0 = 9/11",
        "a*^2 = b^2/c^2 = 2/3",
        "a* = sqrt(6)/3 ≈ 0.816497 < 1: a* lies on the rod",
    ] {
        assert!(text.contains(line), "missing {line:?} in\n{text}");
    }
}

#[test]
fn pivot_working_replaces_linear_momentum() {
    let (code, text, _) = run(&[
        "--m",
        "1",
        "--M",
        "3",
        "--a",
        "1",
        "--pivot",
        "1/2",
        "--inelastic",
        "--explain",
    ]);
    assert_eq!(code, 0);
    assert!(!text.contains("m*v0 = m*v + M*V"), "{text}");
    for line in [
        "angular momentum about the pivot replaces it",
        "m*d*v0 = m*d*v + (I + M*p^2)*omega:   1*1/2*1 = 1*1/2*v + 7/4*omega",
        "q = 1/7,   D = 1 + q = 8/7",
        "v = (q - e)/D*v0 = 1/8",
        "omega = (1 + e)*(m*d/(I + M*p^2))/D*v0 = 1/4",
        "V = -p*omega = -1/8",
    ] {
        assert!(text.contains(line), "missing {line:?} in\n{text}");
    }
}

#[test]
fn markdown_and_latex_and_refusals() {
    let (_, md, _) = run(&["--m", "1", "--M", "1", "--explain", "markdown"]);
    assert!(md.contains("### 2. The three balance equations") && md.contains("$$ "));
    let (_, tex, _) = run(&["--m", "1", "--M", "1", "--explain", "latex"]);
    assert!(tex.contains(r"\paragraph{4. The result}"));
    assert!(tex.contains(r"\omega_{\max}") && !tex.contains('≈') && !tex.contains('`'));
    for (args, message) in [
        (
            &["--m", "1", "--M", "1", "--explain", "pdf"][..],
            "error: explain: expected text, markdown or latex, got 'pdf'\n",
        ),
        (
            &["--m", "1", "--M", "1", "--explain", "--json"][..],
            "error: explain: the working is written exactly: not with --json or --backend\n",
        ),
        (
            &[
                "--m",
                "1",
                "--M",
                "1",
                "--v0t",
                "1",
                "--rod-vt",
                "1",
                "--explain",
            ][..],
            "error: explain: the working is written for a rod at rest before the impact: not with --rod-v, --rod-vt or --rod-omega\n",
        ),
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, 2);
        assert_eq!(err, message);
    }
}

/// NEWCOMER m11: on a pivot the working's step 5 speaks of d*, the distance from the pivot
/// (not a*, which is measured from the centre), says where the struck arm ends, and gives the
/// rod's maximum when the other arm spins it faster. m = 1, M = 3, l = 1, p = -1, uniform:
/// I_p = 1 + 3 = 4, d*^2 = I_p/m = 4, d* = 2, the far end a = 1. m = M = l = 1, p = 1/2,
/// a = 3/4: d*^2 = 7/12, the struck arm is 1/2 long, the other 3/2, where |omega| reaches
/// 1/d* = 2 sqrt(21)/7.
#[test]
fn a_pivots_working_speaks_of_d_star() {
    let run = |args: &[&str]| {
        let (code, out, err) = crate::common::rodimpact(args);
        assert_eq!(code, 0, "{err}");
        out
    };
    let end = run(&[
        "solve",
        "--m",
        "1",
        "--M",
        "3",
        "--a",
        "1/2",
        "--pivot",
        "-1",
        "--inelastic",
        "--explain",
    ]);
    assert!(
        end.contains("d* = 2 from the pivot (the struck arm ends at a = 1, 2 from the pivot): exactly the end of the rod."),
        "{end}"
    );
    assert!(
        end.contains("    d*^2 = b^2/c^2 = 4\n") && !end.contains("a*"),
        "{end}"
    );
    let other = run(&[
        "solve",
        "--m",
        "1",
        "--M",
        "1",
        "--pivot",
        "1/2",
        "--a",
        "3/4",
        "--explain",
    ]);
    assert!(other.contains("The other arm, 3/2 long beyond the pivot, gives more: |omega| reaches 2*sqrt(21)/7 there."), "{other}");
    assert!(
        other.contains("    max |omega| over the rod = 2*sqrt(21)/7\n"),
        "{other}"
    );
}

/// NEWCOMER m12: the working of an oblique impact: the normal problem as for the paper's scene,
/// then the step along the rod. By hand, m = 1, M = 2, l = 1, a = 1/2, v0 = 3, v0t = 2: the
/// normal problem gives v = -1/5, so J = m (v0 - v) = 16/5; k_t = 1/m + 1/M = 3/2, the slip 2
/// is stopped by Jt = 2/(3/2) = 4/3, so mu* = (4/3)/(16/5) = 5/12. With mu = 1/5 it slides:
/// |Jt| = mu J = 16/25, vt = 2 - 16/25 = 34/25, Vt = 16/50 = 8/25. With mu = 10 it sticks:
/// Jt = 4/3, vt = 2/3, Vt = 2/3.
#[test]
fn the_working_along_the_rod() {
    let scene = [
        "--m", "1", "--M", "2", "--a", "1/2", "--v0", "3", "--v0t", "2",
    ];
    let with = |mu: &str, format: &str| {
        let mut args = scene.to_vec();
        args.extend(["--mu", mu, "--explain", format]);
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{err}");
        out
    };
    let slide = with("1/5", "text");
    for line in [
        "5. Along the rod: stick or slide",
        "mu = 1/5 < mu* = 5/12: the projectile slides throughout, and friction gives |Jt| = mu*J = 16/25, against the slip.",
        "    J = m*(v0 - v) = 16/5",
        "    mu* = |Jt_stick|/J = (4/3)/(16/5) = 5/12",
        "    vt = v0t - Jt/m = 34/25",
        "    Vt = Jt/M = 8/25",
        "6. Where omega is largest",
    ] {
        assert!(slide.contains(line), "{line}\n{slide}");
    }
    let stick = with("10", "text");
    assert!(
        stick.contains("mu = 10 >= mu* = 5/12: the slip stops, and Jt = Jt_stick = 4/3."),
        "{stick}"
    );
    assert!(stick.contains("    vt = v0t - Jt/m = 2/3") && stick.contains("    Vt = Jt/M = 2/3"));
    let tex = with("10", "latex");
    assert!(
        tex.contains(r"\mu  = 10 \ge \mu^{*}") && tex.contains(r"J_t^{\text{stick}}"),
        "{tex}"
    );
}
