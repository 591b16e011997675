//! The physics of a scene as hypotheses in the statement language: the domain, the moment of
//! inertia, and for each impact the balance equations and the contact law in its own unknowns.
//! Nothing here comes from rodimpact's solver.

use super::statement::{
    BalanceForm, ExportLaw, Friction, ObliqueSetting, Rod, Setting, Statement, StrikePoint,
};

/// A hypothesis: what it says in words and the proposition.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Hypothesis {
    /// In words (`linear momentum`).
    pub label: String,
    /// In the statement language.
    pub text: String,
}

fn hyp(label: impl Into<String>, text: impl Into<String>) -> Hypothesis {
    Hypothesis {
        label: label.into(),
        text: text.into(),
    }
}

/// The unknowns of an impact: `v`, `V`, `omega`, and `J` (and `P` for a pivot) with the
/// impulses; for an oblique impact also `vt`, `Vt` (not on a pivot), the disc's `spin` after
/// and the tangential impulse `Jt`.
///
/// # Examples
/// ```
/// use rodimpact::claims::export::{Friction, StrikePoint, Setting, Rod, ExportLaw, AT_A, unknowns};
/// let scene = Setting::new(Rod::Uniform, ExportLaw::Elastic);
/// assert_eq!(unknowns(&scene, &StrikePoint { at: "l", tag: "1" }), ["v_1", "V_1", "omega_1"]);
/// let oblique = Setting::new(Rod::Free, ExportLaw::Elastic).oblique(Friction::Stick);
/// assert_eq!(unknowns(&oblique, &AT_A[0]), ["v", "V", "omega", "J", "vt", "Vt", "spin", "Jt"]);
/// ```
pub fn unknowns(scene: &Setting, impact: &StrikePoint) -> Vec<String> {
    let mut names = match scene.rod {
        Rod::Nothing => vec![],
        Rod::Pivot => vec!["v", "omega"],
        _ => vec!["v", "V", "omega"],
    };
    if scene.balance == BalanceForm::Impulses && scene.rod != Rod::Nothing {
        names.push("J");
        if scene.rod == Rod::Pivot {
            names.push("P");
        }
    }
    if scene.oblique.is_some() && scene.rod != Rod::Nothing {
        names.push("vt");
        if scene.rod != Rod::Pivot {
            names.push("Vt");
        }
        names.extend(["spin", "Jt"]);
    }
    names.iter().map(|n| tagged(n, impact.tag)).collect()
}

fn tagged(name: &str, tag: &str) -> String {
    if tag.is_empty() {
        name.to_string()
    } else {
        format!("{name}_{tag}")
    }
}

/// The domain and the moment of inertia of the scene.
fn domain(scene: &Setting) -> Vec<Hypothesis> {
    let mut out = Vec::new();
    if scene.rod == Rod::Nothing {
        return out;
    }
    out.push(hyp("projectile mass and speed", "m > 0 and v0 > 0"));
    match scene.rod {
        Rod::Free => out.push(hyp(
            "rod mass, moment of inertia about its centre",
            "M > 0 and I > 0",
        )),
        Rod::Uniform => {
            out.push(hyp("rod mass, half-length", "M > 0 and l > 0"));
            out.push(hyp("uniform rod of length 2l", "I = M*l^2/3"));
        }
        Rod::Gyration => {
            out.push(hyp("rod mass, radius of gyration", "M > 0 and r > 0"));
            out.push(hyp("moment of inertia about the centre", "I = M*r^2"));
        }
        Rod::Dumbbell => {
            out.push(hyp("rod mass, half-length", "M > 0 and l > 0"));
            out.push(hyp("ideal dumbbell, all mass at the ends", "I = M*l^2"));
        }
        Rod::Pivot => out.push(hyp("rod mass, moment about the pivot", "M > 0 and Ip > 0")),
        Rod::Nothing => {}
    }
    if scene.law == ExportLaw::Restitution {
        out.push(hyp("restitution coefficient", "0 <= e <= 1"));
    }
    if let Some(oblique) = scene.oblique {
        out.push(hyp(
            "the projectile a solid disc of radius rd (rd = 0: a point), moment m*rd^2/2 about its centre",
            "rd >= 0",
        ));
        out.push(hyp(
            "the rod struck on its axis: the contact point is (d, a) from the centre, d = 0 (a thin rod)",
            "d = 0",
        ));
        if oblique.friction == Friction::Slide {
            out.push(hyp("Coulomb friction coefficient", "mu_f >= 0"));
        }
    }
    out
}

/// The balance equations and the contact law of one impact.
fn impact_physics(scene: &Setting, impact: &StrikePoint) -> Vec<Hypothesis> {
    let [v, big_v, w, j, p] = ["v", "V", "omega", "J", "P"].map(|n| tagged(n, impact.tag));
    let a = format!("({})", impact.at);
    let at = if impact.tag.is_empty() {
        String::new()
    } else {
        format!(" (impact {}, at {})", impact.tag, impact.at)
    };
    let mut out = Vec::new();
    let pivot = scene.rod == Rod::Pivot;
    let inertia = if pivot { "Ip" } else { "I" };
    let moving = scene.oblique.is_some_and(|o| o.moving);
    // The rod's velocity change across the rod, and the approach speed.
    let (gained, approach) = if moving {
        (format!("({big_v} - V0)"), "(v0 - V0)")
    } else {
        (big_v.clone(), "v0")
    };
    let moment = if scene.oblique.is_some() {
        format!("{a}*{j} - d*Jt")
    } else {
        format!("{j}*{a}")
    };
    match (scene.balance, pivot) {
        (BalanceForm::Momentum, false) => {
            out.push(hyp(
                format!("linear momentum{at}"),
                format!("m*v0 = m*{v} + M*{big_v}"),
            ));
            out.push(hyp(
                format!("angular momentum about the fixed point at the rod's centre{at}"),
                format!("m*v0*{a} = m*{v}*{a} + I*{w}"),
            ));
        }
        (BalanceForm::Momentum, true) => out.push(hyp(
            format!("angular momentum about the pivot{at}"),
            format!("m*v0*{a} = m*{v}*{a} + Ip*{w}"),
        )),
        (BalanceForm::Impulses, _) => {
            out.push(hyp(
                format!("projectile: impulse -J{at}"),
                format!("m*{v} - m*v0 = -{j}"),
            ));
            if pivot {
                out.push(hyp(
                    format!("rod, linear: impulses J and the pivot's P{at}"),
                    format!("M*h*{w} = {j} + {p}"),
                ));
            } else {
                out.push(hyp(
                    format!("rod, linear: impulse J{at}"),
                    format!("M*{gained} = {j}"),
                ));
            }
            let about = if scene.oblique.is_some() {
                "moment of (J, Jt) applied at (d, a)"
            } else {
                "moment of J"
            };
            out.push(hyp(
                format!("rod, angular: {about}{at}"),
                format!("{inertia}*{w} = {moment}"),
            ));
        }
    }
    let struck = if pivot {
        format!("{w}*{a}")
    } else {
        format!("{big_v} + {w}*{a}")
    };
    match scene.law {
        ExportLaw::Elastic => out.push(hyp(
            format!("Newton's law, e = 1{at}"),
            format!("{struck} - {v} = {approach}"),
        )),
        ExportLaw::Restitution => out.push(hyp(
            format!("Newton's law, restitution e{at}"),
            format!("{struck} - {v} = e*{approach}"),
        )),
        ExportLaw::Sticking => out.push(hyp(
            format!("sticking: the projectile moves with the struck point{at}"),
            format!("{v} = {struck}"),
        )),
        ExportLaw::Energy => {
            let rod = if pivot {
                format!("Ip*{w}^2")
            } else {
                format!("M*{big_v}^2 + I*{w}^2")
            };
            out.push(hyp(
                format!("kinetic energy conserved{at}"),
                format!("m*v0^2 = m*{v}^2 + {rod}"),
            ));
        }
    }
    if let Some(oblique) = scene.oblique {
        out.extend(along_the_rod(oblique, pivot));
    }
    out
}

/// The motion along the rod in an oblique impact: the tangential impulse `Jt` on the rod (`-Jt`
/// on the disc at its contact point, `rd` from its centre), and the friction law. The rod's
/// point `(d, a)` moves along the rod at `Vt - omega*d` (`-omega*d` on a pivot, which holds the
/// rod along its axis); the disc's contact point at `vt + spin*rd`.
fn along_the_rod(oblique: ObliqueSetting, pivot: bool) -> Vec<Hypothesis> {
    let mut out = vec![hyp(
        "projectile, along the rod: impulse -Jt",
        "m*vt - m*v0t = -Jt",
    )];
    let rod_point = if pivot {
        "-omega*d".to_string()
    } else {
        let drift = if oblique.moving { "(Vt - Vt0)" } else { "Vt" };
        out.push(hyp(
            "rod, along its axis: impulse Jt",
            format!("M*{drift} = Jt"),
        ));
        "Vt - omega*d".to_string()
    };
    out.push(hyp(
        "disc, angular about its centre: moment of -Jt at its rim",
        "m*rd^2*(spin - w) = -2*rd*Jt",
    ));
    match oblique.friction {
        Friction::Any => {}
        Friction::Stick => out.push(hyp(
            "sticking: the disc's contact point ends moving with the rod's, along the rod",
            format!("vt + spin*rd = {rod_point}"),
        )),
        Friction::Slide => out.push(hyp(
            "sliding forward: Coulomb's law, Jt = mu_f J",
            "Jt = mu_f*J",
        )),
    }
    out
}

/// Every hypothesis of a statement shared by its checks: the domain, the physics of each impact,
/// then the statement's own.
///
/// # Examples
/// ```
/// use rodimpact::claims::export::{Check, ExportLaw, Rod, Setting, Statement, hypotheses};
/// const CHECKS: &[Check] = &[Check::holds("V > 0", "V > 0")];
/// let s = Statement::new(Setting::new(Rod::Free, ExportLaw::Elastic), CHECKS);
/// let texts: Vec<String> = hypotheses(&s).into_iter().map(|h| h.text).collect();
/// assert!(texts.contains(&"m*v0 = m*v + M*V".to_string()));
/// assert!(texts.contains(&"V + omega*(a) - v = v0".to_string()));
/// ```
pub fn hypotheses(statement: &Statement) -> Vec<Hypothesis> {
    let mut out = domain(&statement.scene);
    if statement.scene.rod != Rod::Nothing {
        for impact in statement.impacts {
            out.extend(impact_physics(&statement.scene, impact));
        }
    }
    out.extend(
        statement
            .given
            .iter()
            .map(|g| hyp("hypothesis of the claim", *g)),
    );
    out
}
