//! A planar impact answered under the restitution laws, as `rodimpact impact` prints it: the
//! laws side by side in JSON (DESIGN §6) and a text report that says plainly where a law
//! creates energy.

use super::{surd_json, value_json};
use crate::field::decimal::{self, COMPACT_CHARS};
use crate::field::{Q, QSqrt};
use crate::impact::{Balance, ContactMatrix, LawAnswer};
use crate::mechanics::planar::Vec2;
use crate::model::{Mobility, Shape, System};
use num_traits::Zero;
use serde_json::{Map, Value, json};

/// The JSON of `rodimpact impact`: `scene` (bodies, the contact, its matrix W) and `laws`,
/// one object per law with `bodies` (each moving body's `velocity` and `omega` after, a pinned
/// body's `pin_impulse`), `impulse` (P on A, world), `impulse_coefficients` (`normal` lam and
/// `tangential` tau, P = lam n + tau t), `lam_c`, `phases`, `contact_velocity` (`before`,
/// `after`: world vectors, and their `normal` and `tangential` components), `work`, `energy`
/// (`before`, `after`, `change` = after - before), `energy_gain` and `laws_hold`. Every number
/// is `{"exact", "decimal"}` with at least 30 significant digits (`digits` more if asked); a
/// surd in the canonical form x + y*sqrt(d).
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, Q, QSqrt}, report::impact_json, scene::Scene};
/// use rodimpact::impact::{contact_matrix, solve_contact, Law};
/// let system = Scene::builder(q(1, 1), q(1, 1)).build()?.system();
/// let answer = solve_contact::<QSqrt>(&system, Law::Poisson).expect("answered");
/// let (w, _) = contact_matrix::<Q>(&system);
/// let json = impact_json(&system, &w, &[answer], 30);
/// assert_eq!(json["laws"][0]["bodies"]["rod"]["omega"]["exact"], "-6/5");
/// assert_eq!(json["laws"][0]["energy_gain"], false);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_json(
    system: &System,
    w: &ContactMatrix<Q>,
    answers: &[LawAnswer<QSqrt>],
    digits: usize,
) -> Value {
    let digits = digits.max(30);
    let surd = |x: &QSqrt| surd_json(x, digits);
    let vector = |v: &Vec2<QSqrt>| json!([surd(&v.x), surd(&v.y)]);
    let c = &system.contacts[0];
    let laws: Vec<Value> = answers
        .iter()
        .map(|a| {
            let mut bodies = Map::new();
            for b in &a.bodies {
                let mut body = Map::new();
                body.insert("velocity".into(), vector(&b.velocity));
                body.insert("omega".into(), surd(&b.omega));
                if let Some(p) = &b.pin_impulse {
                    body.insert("pin_impulse".into(), vector(p));
                }
                bodies.insert(system.bodies[b.index].name.clone(), Value::Object(body));
            }
            let world = |u: &[QSqrt; 2]| world_vector(u, &c.normal);
            let mut entry = json!({
                "law": a.law.name(),
                "bodies": bodies,
                "impulse": vector(&a.impulse),
                "impulse_coefficients": {"normal": surd(&a.lam), "tangential": surd(&a.tau)},
                "lam_c": surd(&a.lam_c),
                "phases": a.phases.iter().map(|p| json!({
                    "mode": p.mode.name(), "from": surd(&p.from), "to": surd(&p.to)
                })).collect::<Vec<_>>(),
                "contact_velocity": {
                    "before": vector(&world(&a.contact_before)),
                    "after": vector(&world(&a.contact_after)),
                    "normal": {"before": surd(&a.contact_before[0]), "after": surd(&a.contact_after[0])},
                    "tangential": {"before": surd(&a.contact_before[1]), "after": surd(&a.contact_after[1])},
                },
                "work": {
                    "normal_compression": surd(&a.work[0]),
                    "normal_restitution": surd(&a.work[1]),
                    "friction": surd(&a.work[2]),
                },
                "energy": {
                    "before": surd(&a.energy.before),
                    "after": surd(&a.energy.after),
                    "change": surd(&a.energy.change),
                },
                "energy_gain": a.energy.gain(),
                "laws_hold": {
                    "momentum": a.balances.holds(Balance::Momentum),
                    "angular_momentum": a.balances.holds(Balance::AngularMomentum),
                    "total_angular_momentum": a.balances.checked(Balance::TotalAngularMomentum),
                    "restitution": a.balances.holds(Balance::Restitution),
                    "coulomb": a.balances.holds(Balance::Coulomb),
                    "energy_equals_work": a.balances.holds(Balance::EnergyEqualsWork),
                },
            });
            if let Some(profile) = &a.engine {
                entry["engine"] = json!(profile.to_string());
            }
            entry
        })
        .collect();
    json!({
        "scene": scene_json(system, w, digits),
        "laws": laws,
    })
}

/// The world vector whose components along n and t are `u` (u_n = u.n, u_t = u.t, |t| = |n|).
fn world_vector(u: &[QSqrt; 2], normal: &Vec2<Q>) -> Vec2<QSqrt> {
    let lift = |x: &Q| QSqrt::rational(x.clone());
    let (n, t) = (normal, normal.perp());
    let size = lift(&n.dot(n));
    Vec2::new(
        (u[0].clone() * &lift(&n.x) + &(u[1].clone() * &lift(&t.x))) / &size,
        (u[0].clone() * &lift(&n.y) + &(u[1].clone() * &lift(&t.y))) / &size,
    )
}

pub(super) fn scene_json(system: &System, w: &ContactMatrix<Q>, digits: usize) -> Value {
    let value = |x: &Q| value_json(x, digits);
    let vector = |v: &Vec2<Q>| json!([value(&v.x), value(&v.y)]);
    let bodies: Vec<Value> = system
        .bodies
        .iter()
        .map(|b| {
            let mut out = Map::new();
            out.insert("name".into(), json!(b.name));
            match &b.mobility {
                Mobility::Fixed => {
                    out.insert("fixed".into(), json!(true));
                    out.insert("position".into(), vector(&b.position));
                }
                mobility => {
                    out.insert("mass".into(), value(&b.mass));
                    out.insert("inertia".into(), value(&b.inertia));
                    out.insert("position".into(), vector(&b.position));
                    out.insert("velocity".into(), vector(&b.velocity));
                    out.insert("omega".into(), value(&b.omega));
                    if let Mobility::Pinned(pin) = mobility {
                        out.insert("pin".into(), vector(pin));
                    }
                }
            }
            if let Some(shape) = &b.shape {
                out.insert("shape".into(), json!(shape_name(shape)));
            }
            Value::Object(out)
        })
        .collect();
    let contacts: Vec<Value> = system
        .contacts
        .iter()
        .map(|c| {
            json!({
                "bodies": [system.bodies[c.a].name, system.bodies[c.b].name],
                "point": vector(&c.point),
                "normal": vector(&c.normal),
                "tangent": vector(&c.tangent()),
                "e": value(&c.e),
                "mu": value(&c.mu),
            })
        })
        .collect();
    let mut out = Map::new();
    if let Some(title) = &system.title {
        out.insert("title".into(), json!(title));
    }
    out.insert("bodies".into(), json!(bodies));
    out.insert("contacts".into(), json!(contacts));
    out.insert(
        "contact_matrix".into(),
        json!({"nn": value(&w.nn), "nt": value(&w.nt), "tt": value(&w.tt), "coupled": !w.nt.is_zero()}),
    );
    Value::Object(out)
}

fn shape_name(shape: &Shape) -> &'static str {
    match shape {
        Shape::Point => "point",
        Shape::Disc { .. } => "disc",
        Shape::Rod { .. } => "rod",
        Shape::Box { .. } => "box",
        Shape::Polygon { .. } => "polygon",
    }
}

/// `x` for a reader: exact when short, with its decimal when it is not an integer; a long
/// exact value as its decimal only.
pub(super) fn show(x: &QSqrt, digits: usize) -> String {
    let exact = x.to_string();
    let decimal = x.decimal(digits);
    if exact.chars().count() > COMPACT_CHARS {
        return format!("≈ {decimal}");
    }
    if x.y().is_zero() && x.x().is_integer() {
        return exact;
    }
    // A fraction whose decimal ends within the digits shown: exactly that decimal.
    let trimmed = match decimal.split_once('e') {
        None if decimal.contains('.') => decimal
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string(),
        _ => decimal.clone(),
    };
    let terminates =
        x.y().is_zero() && crate::number::parse(&trimmed).is_ok_and(|back| &back == x.x());
    if terminates {
        format!("{exact} = {trimmed}")
    } else {
        format!("{exact} ≈ {decimal}")
    }
}

fn show_vector(v: &Vec2<QSqrt>, digits: usize) -> String {
    format!("({}, {})", show(&v.x, digits), show(&v.y, digits))
}

fn compact_vector(v: &Vec2<Q>) -> String {
    format!("({}, {})", decimal::compact(&v.x), decimal::compact(&v.y))
}

/// The text report of `rodimpact impact`: the scene, the contact matrix (and whether the
/// normal and tangential problems are coupled), then each law's answer, and a last paragraph
/// that says which laws create energy, if any.
///
/// # Examples
/// ```
/// use rodimpact::{field::{q, Q, QSqrt}, report::impact_text, scene::Scene};
/// use rodimpact::impact::{contact_matrix, solve_contact, Law};
/// let system = Scene::builder(q(1, 1), q(1, 1)).build()?.system();
/// let answers: Vec<_> = Law::ALL.iter().map(|&l| solve_contact::<QSqrt>(&system, l).expect("answered")).collect();
/// let text = impact_text(&system, &contact_matrix::<Q>(&system), &answers, 6);
/// assert!(text.contains("W is diagonal"));
/// assert!(text.contains("No law creates energy"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_text(
    system: &System,
    (w, u0): &(ContactMatrix<Q>, [Q; 2]),
    answers: &[LawAnswer<QSqrt>],
    digits: usize,
) -> String {
    let mut out = String::new();
    if let Some(title) = &system.title {
        out.push_str(&format!("{title}\n\n"));
    }
    out.push_str("Bodies (SI units; spins counterclockwise)\n");
    for b in &system.bodies {
        let what = match &b.mobility {
            Mobility::Fixed => format!("fixed, at {} m", compact_vector(&b.position)),
            mobility => {
                let pin = match mobility {
                    Mobility::Pinned(p) => format!(", pinned at {} m", compact_vector(p)),
                    _ => String::new(),
                };
                format!(
                    "m = {} kg, I = {} kg m^2, centre {} m, v = {} m/s, omega = {} rad/s{pin}",
                    decimal::compact(&b.mass),
                    decimal::compact(&b.inertia),
                    compact_vector(&b.position),
                    compact_vector(&b.velocity),
                    decimal::compact(&b.omega)
                )
            }
        };
        let shape = b
            .shape
            .as_ref()
            .map(|s| format!(" (shape: {})", shape_name(s)))
            .unwrap_or_default();
        out.push_str(&format!("  {}{shape}: {what}\n", b.name));
    }
    let c = &system.contacts[0];
    out.push_str(&format!(
        "Contact: {} on {} at {} m, normal {} (into {}), e = {}, mu = {}\n",
        system.bodies[c.a].name,
        system.bodies[c.b].name,
        compact_vector(&c.point),
        compact_vector(&c.normal),
        system.bodies[c.a].name,
        decimal::compact(&c.e),
        decimal::compact(&c.mu)
    ));
    out.push_str(&format!(
        "  before: u_n = {}, u_t = {} (the relative velocity along the normal and the tangent, scaled by |n|)\n",
        decimal::compact(&u0[0]),
        decimal::compact(&u0[1])
    ));
    out.push_str(&format!(
        "  W = [{}, {}; {}, {}]: {}\n",
        decimal::compact(&w.nn),
        decimal::compact(&w.nt),
        decimal::compact(&w.nt),
        decimal::compact(&w.tt),
        if w.nt.is_zero() {
            "W is diagonal, so the normal and tangential problems separate and the three laws agree"
        } else {
            "coupled (W_nt != 0): an impulse along one direction changes the velocity along the other, and the laws may part"
        }
    ));
    for a in answers {
        let heading = match &a.engine {
            Some(profile) => engine_heading(profile),
            None => law_heading(a.law).to_string(),
        };
        out.push_str(&format!("\n{heading}\n"));
        for b in &a.bodies {
            let pin = b
                .pin_impulse
                .as_ref()
                .map(|p| format!(", pin impulse {} N s", show_vector(p, digits)))
                .unwrap_or_default();
            out.push_str(&format!(
                "  {}: v = {} m/s, omega = {} rad/s{pin}\n",
                system.bodies[b.index].name,
                show_vector(&b.velocity, digits),
                show(&b.omega, digits)
            ));
        }
        out.push_str(&format!(
            "  impulse on {}: P = {} N s (lam = {}, tau = {})\n",
            system.bodies[c.a].name,
            show_vector(&a.impulse, digits),
            show(&a.lam, digits),
            show(&a.tau, digits)
        ));
        let phases: Vec<String> = a
            .phases
            .iter()
            .map(|p| format!("{} to lam = {}", p.mode.name(), show(&p.to, digits)))
            .collect();
        out.push_str(&format!(
            "  phases: {}; compression ends at lam = {}\n",
            phases.join(", then "),
            show(&a.lam_c, digits)
        ));
        out.push_str(&format!(
            "  contact: u_n {} -> {}, u_t {} -> {}\n",
            show(&a.contact_before[0], digits),
            show(&a.contact_after[0], digits),
            show(&a.contact_before[1], digits),
            show(&a.contact_after[1], digits)
        ));
        out.push_str(&format!(
            "  energy: {} -> {} J, change {} J{}\n",
            show(&a.energy.before, digits),
            show(&a.energy.after, digits),
            show(&a.energy.change, digits),
            if a.energy.gain() {
                ": THIS LAW CREATES ENERGY"
            } else {
                ""
            }
        ));
        let laws = if a.balances.all_zero() {
            "momentum, angular momentum, the restitution law, Coulomb's cone and energy = work all hold exactly".to_string()
        } else if let Some(profile) = &a.engine {
            format!(
                "momentum and angular momentum {}; after the step's {} iterations not yet {}'s: {} left over",
                if a.balances.holds(Balance::Momentum) && a.balances.holds(Balance::AngularMomentum)
                {
                    "hold exactly"
                } else {
                    "FAIL"
                },
                profile.engine.iterations(),
                a.law.name(),
                a.balances.failing().join(", ")
            )
        } else {
            format!("NOT ALL HOLD: {} fail", a.balances.failing().join(", "))
        };
        out.push_str(&format!("  laws: {laws}\n"));
    }
    let gains: Vec<String> = answers
        .iter()
        .filter(|a| a.energy.gain())
        .map(|a| {
            let hundred = QSqrt::rational(Q::from_integer(100.into()));
            let share = (a.energy.change.clone() * &hundred / &a.energy.before).decimal(3);
            let who = match &a.engine {
                Some(profile) => format!("{profile}'s step"),
                None => format!("{}'s law", law_name(a.law)),
            };
            format!(
                "{who} gains {} J ({share} % of the energy before)",
                show(&a.energy.change, digits)
            )
        })
        .collect();
    out.push('\n');
    if gains.is_empty() {
        out.push_str("No law creates energy in this impact.\n");
    } else {
        out.push_str(&format!(
            "Energy is created, decided exactly: {}. With a coupled W and a slip that stops or reverses, Newton's law imposes the final normal velocity whatever happened during the impact, and the normal impulse can do net positive work (Kane and Levinson 1985; Stronge 1991).\n",
            gains.join("; ")
        ));
    }
    out
}

pub(crate) fn law_name(law: crate::impact::Law) -> &'static str {
    use crate::impact::Law;
    match law {
        Law::Newton => "Newton",
        Law::Poisson => "Poisson",
        Law::Energetic => "Stronge",
        Law::LcpNewton => "LCP-Newton",
        Law::LcpPoisson => "LCP-Poisson",
        Law::Split => "Split",
    }
}

/// The heading of an engine's answer: its name, what rodimpact computes of it, its settings.
fn engine_heading(profile: &crate::impact::Profile) -> String {
    let engine = profile.engine;
    let what = if engine.replayed() {
        format!(
            "one step of its solver replayed exactly, {} iterations; it converges to {}",
            engine.iterations(),
            engine.law().name()
        )
    } else {
        format!(
            "its soft substeps have no rational replay: the law they converge to, {}",
            engine.law().name()
        )
    };
    let (e, mu) = engine.combine();
    format!(
        "{profile} (engine: {what}; {}; combines e by {}, mu by {})",
        if profile.threshold.is_zero() {
            "no restitution threshold".to_string()
        } else {
            format!(
                "restitution threshold {} in the scene's units",
                decimal::compact(&profile.threshold)
            )
        },
        e.name(),
        mu.name()
    )
}

pub(crate) fn law_heading(law: crate::impact::Law) -> &'static str {
    use crate::impact::Law;
    match law {
        Law::Newton => "Newton (kinematic: u_n after = -e u_n before)",
        Law::Poisson => "Poisson (kinetic: restitution impulse = e x compression impulse)",
        Law::Energetic => "Stronge (energetic: restitution work = -e^2 x compression work)",
        Law::LcpNewton => {
            "LCP-Newton (engines' one phase: u_n after = -e u_n before and Coulomb's law on the final slip)"
        }
        Law::LcpPoisson => {
            "LCP-Poisson (engines' two phases: a compression with Coulomb's law, then e x its impulse)"
        }
        Law::Split => {
            "Split (friction without restitution, then restitution without friction: Rapier, Box2D v3)"
        }
    }
}

/// One line of `impact --batch`'s output for an audited scene: `id`, `engine`, `contacts`,
/// `exact` (every distinct answer's bodies, exact strings, under its first name: the physical
/// laws or models, the engines' laws, the engine's replayed step), `equal` (for an answer that
/// others equal, their names), `rel_error` (the claim's error in energy against each,
/// `sqrt(K(claim - exact)/K(before))`, three digits, `nan` for a claim that is not finite),
/// `matches` (the answers within the tolerance, by their first names), `closest`, `error_split` (where the engine's
/// step is replayed: the distance of its law from the nearest physical one, of its step from
/// its law, of the claim from its step) and `diagnosis` (`ok`, or `;`-joined findings).
///
/// # Examples
/// ```
/// use rodimpact::{batch::{EngineChoice, ImpactTolerance, audit_impact}, report::impact_audit_json};
/// let line = r#"{"id": "p", "body": [{"name": "p", "mass": "1", "velocity": ["1", "0"]},
///   {"name": "wall", "fixed": true}], "contact": [{"bodies": ["p", "wall"], "point": ["0", "0"], "normal": ["-1", "0"]}],
///   "claimed": {"bodies": {"p": {"velocity": ["-1", "0"], "omega": "0"}}}}"#;
/// let audit = audit_impact(line, 1, &ImpactTolerance::default(), &EngineChoice::FromClaim)?;
/// let json = impact_audit_json(&audit);
/// assert_eq!(json["diagnosis"], "ok");
/// assert_eq!(json["exact"]["newton"]["p"]["velocity"][0], "-1");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_audit_json(audit: &crate::batch::ImpactAudit) -> Value {
    let system = &audit.system;
    let mut exact = Map::new();
    let mut equal = Map::new();
    for r in &audit.references {
        let mut bodies = Map::new();
        for (index, v, w) in &r.bodies {
            bodies.insert(
                system.bodies[*index].name.clone(),
                json!({"velocity": [v.x.to_string(), v.y.to_string()], "omega": w.to_string()}),
            );
        }
        exact.insert(r.name.clone(), Value::Object(bodies));
        if !r.equal.is_empty() {
            equal.insert(r.name.clone(), json!(r.equal));
        }
    }
    // The square root of an energy ratio's upper bound: 3 digits.
    let error = |e: &QSqrt| QSqrt::sqrt_of(&e.bounds(20).1).decimal(3);
    let mut out = Map::new();
    out.insert("id".into(), json!(audit.id));
    if let Some(engine) = &audit.engine {
        out.insert("engine".into(), json!(engine));
    }
    out.insert("contacts".into(), json!(system.contacts.len()));
    out.insert("exact".into(), Value::Object(exact));
    if !equal.is_empty() {
        out.insert("equal".into(), Value::Object(equal));
    }
    if audit.claimed.is_some() {
        let mut errors = Map::new();
        for (r, e) in audit.references.iter().zip(&audit.errors) {
            errors.insert(
                r.name.clone(),
                json!(e.as_ref().map_or_else(|| "nan".to_string(), error)),
            );
        }
        out.insert("rel_error".into(), Value::Object(errors));
        out.insert("matches".into(), json!(audit.matches));
        out.insert("closest".into(), json!(audit.closest));
        if let Some(split) = &audit.split {
            out.insert(
                "error_split".into(),
                json!({
                    "profile": split.profile.to_string(),
                    "law": split.law,
                    "nearest_physical": split.nearest,
                    "of_law": error(&split.of_law),
                    "of_iterations": error(&split.of_iterations),
                    "of_rounding": split.of_rounding.as_ref().map_or_else(|| "nan".to_string(), error),
                }),
            );
        }
        let diagnosis = if audit.findings.is_empty() {
            "ok".to_string()
        } else {
            audit.findings.join(";")
        };
        out.insert("diagnosis".into(), json!(diagnosis));
    }
    Value::Object(out)
}
