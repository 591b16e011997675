//! A planar impact answered under the restitution laws, as `rodimpact impact` prints it: the
//! laws side by side in JSON (DESIGN §6) and a text report that says plainly where a law
//! creates energy.

use super::{surd_json, value_json};
use crate::field::decimal::{self, COMPACT_CHARS};
use crate::field::{Q, QSqrt};
use crate::mechanics::planar::Vec2;
use crate::model::{Mobility, Shape, System};
use crate::solve::impact::{ContactMatrix, LawAnswer};
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
/// use rodimpact::{field::{q, QSqrt}, model::paper_system, report::impact_json, scene::Scene};
/// use rodimpact::solve::impact::{solve_contact, Law};
/// let system = paper_system(&Scene::builder(q(1, 1), q(1, 1)).build()?);
/// let answer = solve_contact::<QSqrt>(&system, Law::Poisson).expect("answered");
/// let json = impact_json(&system, &[answer], 30);
/// assert_eq!(json["laws"][0]["bodies"]["rod"]["omega"]["exact"], "-6/5");
/// assert_eq!(json["laws"][0]["energy_gain"], false);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_json(system: &System, answers: &[LawAnswer<QSqrt>], digits: usize) -> Value {
    let digits = digits.max(30);
    let surd = |x: &QSqrt| surd_json(x, digits);
    let vector = |v: &Vec2<QSqrt>| json!([surd(&v.x), surd(&v.y)]);
    let c = &system.contacts[0];
    let (w, _) = crate::solve::impact::contact_matrix::<Q>(system);
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
            json!({
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
                "energy_gain": a.energy_gain,
                "laws_hold": {
                    "momentum": a.laws_hold.momentum,
                    "angular_momentum": a.laws_hold.angular_momentum,
                    "total_angular_momentum": a.laws_hold.total_angular_momentum,
                    "restitution": a.laws_hold.restitution,
                    "coulomb": a.laws_hold.coulomb,
                    "energy_equals_work": a.laws_hold.energy,
                },
            })
        })
        .collect();
    json!({
        "scene": scene_json(system, &w, digits),
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

fn scene_json(system: &System, w: &ContactMatrix<Q>, digits: usize) -> Value {
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
fn show(x: &QSqrt, digits: usize) -> String {
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
/// use rodimpact::{field::{q, QSqrt}, model::paper_system, report::impact_text, scene::Scene};
/// use rodimpact::solve::impact::{solve_contact, Law};
/// let system = paper_system(&Scene::builder(q(1, 1), q(1, 1)).build()?);
/// let answers: Vec<_> = Law::ALL.iter().map(|&l| solve_contact::<QSqrt>(&system, l).expect("answered")).collect();
/// let text = impact_text(&system, &answers, 6);
/// assert!(text.contains("W is diagonal"));
/// assert!(text.contains("No law creates energy"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn impact_text(system: &System, answers: &[LawAnswer<QSqrt>], digits: usize) -> String {
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
    let (w, u0) = crate::solve::impact::contact_matrix::<Q>(system);
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
        out.push_str(&format!("\n{}\n", law_heading(a.law)));
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
            if a.energy_gain {
                ": THIS LAW CREATES ENERGY"
            } else {
                ""
            }
        ));
        out.push_str(&format!(
            "  laws: {}\n",
            if a.laws_hold.all() {
                "momentum, angular momentum, the restitution law, Coulomb's cone and energy = work all hold exactly".to_string()
            } else {
                format!("NOT ALL HOLD: {:?}", a.laws_hold)
            }
        ));
    }
    let gains: Vec<String> = answers
        .iter()
        .filter(|a| a.energy_gain)
        .map(|a| {
            let hundred = QSqrt::rational(Q::from_integer(100.into()));
            let share = (a.energy.change.clone() * &hundred / &a.energy.before).decimal(3);
            format!(
                "{}'s law gains {} J ({share} % of the energy before)",
                law_name(a.law),
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

fn law_name(law: crate::solve::impact::Law) -> &'static str {
    use crate::solve::impact::Law;
    match law {
        Law::Newton => "Newton",
        Law::Poisson => "Poisson",
        Law::Energetic => "Stronge",
    }
}

fn law_heading(law: crate::solve::impact::Law) -> &'static str {
    use crate::solve::impact::Law;
    match law {
        Law::Newton => "Newton (kinematic: u_n after = -e u_n before)",
        Law::Poisson => "Poisson (kinetic: restitution impulse = e x compression impulse)",
        Law::Energetic => "Stronge (energetic: restitution work = -e^2 x compression work)",
    }
}
