//! `solve --explain`: the working for one scene as a student would write it: the balance
//! equations with the scene's numbers, the elimination, D, the result, and the a* step
//! (f(x) = x/(b^2 + c^2 x^2) is largest at x = b/c), with whether a* lies on the rod. One list
//! of steps, rendered as text, Markdown or LaTeX.

use super::{markup, mathml};
use crate::field::notation::{Notation, surd};
use crate::field::{Q, QSqrt};
use crate::scene::Groups;
use crate::scene::{Scene, Support};
use crate::solve::optimum::{Arm, Placement, struck_end};
use crate::solve::working::Working;
use num_traits::{One, Signed, Zero};

/// The output format of [`explain`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExplainFormat {
    /// Plain text.
    Text,
    /// Markdown (equations in `$...$`).
    Markdown,
    /// A LaTeX fragment (equations in `align*`).
    Latex,
    /// An HTML fragment for a web page: each step an `<h3>` and paragraphs, the math in MathML
    /// (no script or font needed).
    Html,
}

/// A step: a heading, sentences, and equations written in the crate's ASCII math (`*`, `/`,
/// `omega`, `v0`, `a*`), which the LaTeX rendering spells in TeX.
struct Step {
    title: &'static str,
    prose: Vec<String>,
    equations: Vec<String>,
}

/// A number in an equation: negative ones in parentheses.
fn n(x: &Q) -> String {
    if x.is_negative() {
        format!("({x})")
    } else {
        x.to_string()
    }
}

/// The working of a scene, written out from its solved `working` ([`Working::of`]).
///
/// # Examples
/// ```
/// use rodimpact::{field::q, scene::Scene, report::{explain, ExplainFormat}};
/// use rodimpact::solve::working::Working;
/// let s = Working::of(&Scene::builder(q(1, 1), q(1, 1)).a(q(1, 1)).build()?);
/// let text = explain(&s, ExplainFormat::Text);
/// assert!(text.contains("1*1 = 1*v + 1*V"));
/// assert!(text.contains("D = 1 + q = 5"));
/// assert!(text.contains("omega = (1 + e)*(m*a/I)/D*v0 = 6/5"));
/// assert!(text.contains("a*^2 = b^2/c^2 = 2/3"));
/// let html = explain(&s, ExplainFormat::Html);
/// assert!(html.starts_with("<h3>1. The scene</h3>\n<p><math>"));
/// assert!(html.contains("<h3>5. Where ω is largest</h3>"));
/// assert!(html.contains("<math display=\"block\">") && !html.contains("merror"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn explain(working: &Working, format: ExplainFormat) -> String {
    let steps = steps(working);
    match format {
        ExplainFormat::Text => render(
            &steps,
            |t| format!("{t}\n"),
            |e| format!("    {e}\n"),
            |p| format!("{}\n", prose(p, str::to_string, |m| m.to_string())),
        ),
        ExplainFormat::Markdown => render(
            &steps,
            |t| format!("### {t}\n\n"),
            |e| format!("$$ {} $$\n\n", latex(e)),
            |p| {
                format!(
                    "{}\n\n",
                    prose(p, str::to_string, |m| format!("${}$", latex(m)))
                )
            },
        ),
        ExplainFormat::Latex => render(
            &steps,
            |t| format!("\\paragraph{{{t}}}\n"),
            |e| format!("\\[ {} \\]\n", latex(e)),
            |p| {
                format!(
                    "{}\n\n",
                    prose(p, str::to_string, |m| format!("${}$", latex(m)))
                )
            },
        ),
        ExplainFormat::Html => render(
            &steps,
            |t| format!("<h3>{}</h3>\n", words_html(t)),
            |e| format!("{}\n", mathml::math(&latex(e), true)),
            |p| {
                let html = prose(p, words_html, |m| mathml::math(&latex(m), false));
                format!("<p>{html}</p>\n")
            },
        ),
    }
}

/// Words for a web page: the ASCII math among them in Unicode (`omega` is `ω`), escaped.
fn words_html(words: &str) -> String {
    mathml::escape(&markup::ascii_math(words))
}

/// A sentence whose math is marked with backticks: the words written by `words`, the math by
/// `math`.
fn prose(p: &str, words: impl Fn(&str) -> String, math: impl Fn(&str) -> String) -> String {
    p.split('`')
        .enumerate()
        .map(
            |(i, part)| {
                if i % 2 == 1 { math(part) } else { words(part) }
            },
        )
        .collect()
}

fn render(
    steps: &[Step],
    title: impl Fn(&str) -> String,
    equation: impl Fn(&str) -> String,
    prose: impl Fn(&str) -> String,
) -> String {
    let mut out = String::new();
    for (i, s) in steps.iter().enumerate() {
        out.push_str(&title(&format!("{}. {}", i + 1, s.title)));
        for p in &s.prose {
            out.push_str(&prose(p));
        }
        for e in &s.equations {
            out.push_str(&equation(e));
        }
        out.push('\n');
    }
    out
}

/// ASCII math in TeX: `omega` -> `\omega`, `v0` -> `v_0`, `a*` -> `a^*`, `*` -> `\cdot`,
/// `sqrt(x)` -> `\sqrt{x}`, `<=` -> `\le`, `=>` -> `\Rightarrow`, wide gaps -> `\qquad`.
fn latex(e: &str) -> String {
    // Names first, into placeholders that the operator rules below cannot touch.
    const NAMES: [(&str, &str); 17] = [
        ("omega_max", "\\omega_{\\max}"),
        ("Jt_stick", "J_t^{\\text{stick}}"),
        ("Jt", "J_t"),
        ("v0t", "v_{0t}"),
        ("vt", "v_t"),
        ("Vt", "V_t"),
        ("mu* ", "\\mu^{*} "),
        ("mu", "\\mu"),
        ("spin", "\\text{spin}"),
        ("max |omega| over the rod", "\\max_{\\text{rod}} |\\omega|"),
        ("omega", "\\omega"),
        ("v0", "v_0"),
        ("a*^2", "a^{*2}"),
        ("a* ", "a^{*} "),
        ("d*^2", "d^{*2}"),
        ("d* ", "d^{*} "),
        ("≈", "\\approx"),
    ];
    let mut s = e.to_string();
    for (k, (from, _)) in NAMES.iter().enumerate() {
        s = s.replace(from, &format!("\u{1}{k}\u{2}"));
    }
    s = s
        .replace("   ", " \\qquad ")
        .replace("=>", "\\Rightarrow")
        .replace("<=", "\\le")
        .replace(">=", "\\ge")
        .replace('*', " \\cdot ");
    while let Some(i) = s.find("sqrt(") {
        let rest = &s[i + 5..];
        let mut depth = 1;
        let close = rest
            .char_indices()
            .find(|&(_, c)| {
                depth += match c {
                    '(' => 1,
                    ')' => -1,
                    _ => 0,
                };
                depth == 0
            })
            .map_or(rest.len(), |(k, _)| k);
        let after = &rest[(close + 1).min(rest.len())..];
        s = format!("{}\\sqrt{{{}}}{after}", &s[..i], &rest[..close]);
    }
    for (k, (_, to)) in NAMES.iter().enumerate() {
        s = s.replace(&format!("\u{1}{k}\u{2}"), &format!("{to} "));
    }
    s
}

fn steps(working: &Working) -> Vec<Step> {
    // An oblique scene: the normal problem's working (a rod at rest meets the projectile's
    // normal speed v0), then the step along the rod.
    let mut steps = normal_steps(working);
    if let (Some(o), Some(out)) = (working.scene.oblique(), &working.oblique) {
        steps.insert(steps.len() - 1, along_the_rod(&working.scene, o, out));
    }
    steps
}

/// The working of the paper's scene: the balances, their solution, and where omega is largest.
fn normal_steps(working: &Working) -> Vec<Step> {
    let scene = &working.normal;
    let (m, big_m, a, v0, e) = numbers(scene);
    let inertia = scene.inertia();
    let x = &working.outcome.after;
    let mut steps = vec![Step {
        title: "The scene",
        prose: vec![format!(
            "`m = {m}`, `M = {big_m}`, `l = {}`, `a = {a}`, `v0 = {v0}`, `e = {e}`; {} rod, `I = {inertia}` (about its centre); {}.",
            scene.half_length(),
            scene.rod(),
            match scene.support() {
                Support::Free => "free on the table".to_string(),
                Support::Pivot(p) => format!("on a fixed pivot at `p = {p}`"),
            }
        )],
        equations: vec![],
    }];
    match scene.support() {
        Support::Free => free_rod_steps(scene, &inertia, x, &mut steps),
        Support::Pivot(p) => pivot_steps(scene, p, &inertia, x, &mut steps),
    }
    steps.push(a_star_step(scene, &working.optimum));
    steps
}

/// The step along the rod of an oblique impact (a rod at rest): the slip, the impulse that
/// would stop it, Coulomb's bound, stick or slide, and the velocities along the rod after.
fn along_the_rod(
    scene: &Scene,
    o: &crate::scene::Oblique,
    out: &crate::solve::fast::oblique::ObliqueOutcome<Q>,
) -> Step {
    let (p, op) = (scene.params::<Q>(), o.params::<Q>());
    let slip = op.slip(&p.support);
    let free = matches!(p.support, Support::Free);
    let (m, big_m) = (scene.m(), scene.rod_mass());
    let one = Q::one();
    let mut terms = vec![("1/m".to_string(), &one / m)];
    if o.disc.is_some() {
        terms.push(("2/m".into(), Q::from_integer(2.into()) / m));
    }
    if free {
        terms.push(("1/M".into(), &one / big_m));
    }
    let k_t: Q = terms.iter().map(|(_, x)| x.clone()).sum();
    let names: Vec<&str> = terms.iter().map(|(t, _)| t.as_str()).collect();
    let mut prose = vec![format!(
        "Along the rod the projectile slips at `u_t = {slip}` before the impact{}. A tangential impulse `Jt` changes that slip by `-k_t*Jt`, `k_t = {}`{}{}, so stopping it takes `Jt_stick = u_t/k_t`. Coulomb's law allows at most `mu` times the normal impulse `J = m*(v0 - v)`.",
        if o.disc.is_some() {
            " (the disc's rim turning with it)"
        } else {
            ""
        },
        names.join(" + "),
        if o.disc.is_some() {
            " (2/m: the solid disc's rim, r^2/I_disc = 2/m)"
        } else {
            ""
        },
        if free {
            ""
        } else {
            " (the pivot holds the rod along its length)"
        },
    )];
    let mut equations = vec![
        format!("J = m*(v0 - v) = {}", out.impulse),
        format!("k_t = {} = {k_t}", names.join(" + ")),
        format!("Jt_stick = u_t/k_t = {}", out.stick_impulse),
    ];
    let jt = &out.tangential_impulse;
    if op.mu.is_zero() {
        prose.push("Without friction (`mu = 0`) nothing acts along the rod: `Jt = 0`.".into());
    } else {
        let mu_star = out.stick_impulse.abs() / &out.impulse;
        equations.push(format!(
            "mu* = |Jt_stick|/J = ({})/({}) = {mu_star}",
            out.stick_impulse.abs(),
            out.impulse
        ));
        prose.push(if matches!(out.contact, Some(crate::impact::Mode::Stick)) {
            format!(
                "`mu = {} >= mu* = {mu_star}`: the slip stops, and `Jt = Jt_stick = {jt}`.",
                op.mu
            )
        } else {
            format!(
                "`mu = {} < mu* = {mu_star}`: the projectile slides throughout, and friction gives `|Jt| = mu*J = {}`, against the slip.",
                op.mu,
                jt.abs()
            )
        });
    }
    equations.push(format!("vt = v0t - Jt/m = {}", out.after.vt));
    if free {
        equations.push(format!("Vt = Jt/M = {}", out.after.rod.vt));
    }
    if let Some(spin) = &out.after.spin {
        equations.push(format!("spin after = {spin}"));
    }
    Step {
        title: "Along the rod: stick or slide",
        prose,
        equations,
    }
}

/// m, M, a, v0 and e of `scene`, the numbers every equation is written with.
fn numbers(scene: &Scene) -> (&Q, &Q, &Q, &Q, &Q) {
    (
        scene.m(),
        scene.rod_mass(),
        scene.a(),
        scene.v0(),
        scene.e(),
    )
}

fn free_rod_steps(scene: &Scene, inertia: &Q, x: &crate::scene::Motion<Q>, steps: &mut Vec<Step>) {
    let (m, big_m, a, v0, e) = numbers(scene);
    steps.push(Step {
        title: "The three balance equations",
        prose: vec![
            "Linear momentum, angular momentum about the rod's centre (the table is frictionless and the rod free), and the restitution law at the contact point (its velocity after the impact is `V + a*omega`):".into(),
        ],
        equations: vec![
            format!("m*v0 = m*v + M*V:   {}*{} = {}*v + {}*V", n(m), n(v0), n(m), n(big_m)),
            format!(
                "m*a*v0 = m*a*v + I*omega:   {}*{}*{} = {}*{}*v + {}*omega",
                n(m), n(a), n(v0), n(m), n(a), n(inertia)
            ),
            format!("V + a*omega - v = e*v0:   V + {}*omega - v = {}*{}", n(a), n(e), n(v0)),
        ],
    });
    let g = Groups::of(m, big_m, inertia, a);
    steps.push(Step {
        title: "Elimination",
        prose: vec![
            "The first two give V and omega in terms of v; the third then gives v. With `r = m/M`, `s = m*a^2/I`, `q = r + s` and `D = 1 + q`:".into(),
        ],
        equations: vec![
            "V = (m/M)*(v0 - v),   omega = (m*a/I)*(v0 - v)".into(),
            "(v0 - v)*q = v + e*v0   =>   v = (q - e)/D*v0".into(),
            format!("r = m/M = {},   s = m*a^2/I = {},   q = {}", g.r, g.s, g.q),
            format!("D = 1 + q = {}", g.d),
        ],
    });
    steps.push(Step {
        title: "The result",
        prose: vec![],
        equations: vec![
            format!("v = (q - e)/D*v0 = {}", x.v),
            format!("V = (1 + e)*r/D*v0 = {}", x.rod_v),
            format!("omega = (1 + e)*(m*a/I)/D*v0 = {}", x.omega),
        ],
    });
}

fn pivot_steps(
    scene: &Scene,
    p: &Q,
    inertia: &Q,
    x: &crate::scene::Motion<Q>,
    steps: &mut Vec<Step>,
) {
    let (m, big_m, a, v0, e) = numbers(scene);
    let d = a - p;
    let about_pivot = inertia + big_m * p * p;
    steps.push(Step {
        title: "The balance equations",
        prose: vec![
            "The pivot pushes on the rod during the impact, so linear momentum is not conserved: angular momentum about the pivot replaces it, and the rod turns about the pivot (its centre moves with `V = -p*omega`). The restitution law holds at the contact point, at distance `d = a - p` from the pivot:".into(),
        ],
        equations: vec![
            format!(
                "m*d*v0 = m*d*v + (I + M*p^2)*omega:   {}*{}*{} = {}*{}*v + {}*omega",
                n(m), n(&d), n(v0), n(m), n(&d), n(&about_pivot)
            ),
            format!("d*omega - v = e*v0:   {}*omega - v = {}*{}", n(&d), n(e), n(v0)),
        ],
    });
    let q = m * &d * &d / &about_pivot;
    steps.push(Step {
        title: "Elimination",
        prose: vec!["With `q = m*d^2/(I + M*p^2)` and `D = 1 + q`:".into()],
        equations: vec![
            "omega = m*d/(I + M*p^2)*(v0 - v),   (v0 - v)*q = v + e*v0".into(),
            format!("q = {q},   D = 1 + q = {}", Q::one() + &q),
        ],
    });
    steps.push(Step {
        title: "The result",
        prose: vec![],
        equations: vec![
            format!("v = (q - e)/D*v0 = {}", x.v),
            format!("omega = (1 + e)*(m*d/(I + M*p^2))/D*v0 = {}", x.omega),
            format!("V = -p*omega = {}", x.rod_v),
        ],
    });
}

fn a_star_step(scene: &Scene, o: &crate::solve::optimum::Optimum) -> Step {
    let root = surd(&QSqrt::sqrt_of(&o.squared), Notation::Ascii);
    let approx = QSqrt::sqrt_of(&o.squared).decimal(6);
    let (lever, moment, star, from) = match scene.support() {
        Support::Free => ("a", "I*(M + m)/M".to_string(), "a*", String::new()),
        Support::Pivot(_) => {
            let end = struck_end(scene);
            (
                "d",
                "I + M*p^2".to_string(),
                "d*",
                format!(
                    " from the pivot (the struck arm ends at a = {end}, {} from the pivot)",
                    o.arm
                ),
            )
        }
    };
    let placement = match o.placement {
        Placement::Inside => format!(
            "`{star} = {root} ≈ {approx} < {}`{from}: {star} lies on the rod, and hitting there spins the rod faster than hitting the end.",
            o.arm
        ),
        Placement::AtEnd => format!("`{star} = {root}`{from}: exactly the end of the rod."),
        Placement::Beyond => format!(
            "`{star} = {root} ≈ {approx} > {}`{from}: {star} lies beyond the end, so omega grows all the way to the end, which gives the fastest spin.",
            o.arm
        ),
    };
    let mut prose = vec![
        format!(
            "As a function of the lever arm `{lever}`, `omega` has the form `K*x/(b^2 + c^2*x^2)` with `x = {lever}`, `b^2 = {moment}` and `c^2 = m`; `f(x) = x/(b^2 + c^2*x^2)` is largest at `x = b/c`, so"
        ),
        placement,
    ];
    let mut equations = vec![
        format!("{star}^2 = b^2/c^2 = {}", o.squared),
        format!("omega_max = {}", surd(&o.omega_max, Notation::Ascii)),
    ];
    // On a pivot the same curve holds on the other arm, which may spin the rod faster.
    if let (Some(other), (max, Arm::Other)) = (&o.other_arm, o.rod_max()) {
        prose.push(format!(
            "The other arm, {} long beyond the pivot, gives more: |omega| reaches `{}` there.",
            other.arm,
            surd(max, Notation::Ascii)
        ));
        equations.push(format!(
            "max |omega| over the rod = {}",
            surd(max, Notation::Ascii)
        ));
    }
    Step {
        title: "Where omega is largest",
        prose,
        equations,
    }
}
