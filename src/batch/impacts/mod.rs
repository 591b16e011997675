//! An engine's planar impacts audited: `rodimpact impact --batch FILE.jsonl`.
//!
//! Each line is a scene in its JSON form (the structure of a scene file) with an optional
//! `"claimed"` object, what an engine produced: `{"engine": "...", "bodies": {"rod":
//! {"velocity": ["x", "y"], "omega": "w"}, ...}}`, every number a decimal or fraction string
//! read exactly (a float's shortest text is its exact value's nearest decimal). The line is
//! answered exactly under every law (one contact) or model (several contacts), and the claimed
//! state is compared with each: its error in energy, `sqrt(K(claim - exact)/K(before))` (K the
//! kinetic energy of the velocity differences), which answers it matches within a tolerance,
//! which it is closest to, and a diagnosis as `batch` gives (`ok`; or `energy-gain`, `energy-loss`,
//! `restitution-ignored`, `no-contact`, `momentum`, `angular-momentum`, `off`).

use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt};
use crate::impact::{Law, Model, ModelOutcome, orders, solve_exact, solve_several};
use crate::mechanics::planar::{
    PlanarBody, Vec2, angular_momentum, kinetic_energy, linear_momentum,
};
use crate::model::{Mobility, System, from_value};
use num_traits::{Signed, Zero};
use serde_json::Value;
use std::cmp::Ordering;

/// One exact answer the claimed state is compared with: a law's or a model's name and every
/// moving body's (index, velocity, spin).
#[derive(Debug, Clone, PartialEq)]
pub struct EngineReference {
    /// `newton`, `poisson`, `energetic`, or a model (`simultaneous-newton`, `pgs:4`, ...).
    pub name: String,
    /// The moving bodies after.
    pub bodies: Vec<(usize, Vec2<QSqrt>, QSqrt)>,
}

/// One line audited.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactAudit {
    /// The line's `id` (its number when it has none).
    pub id: String,
    /// The scene.
    pub system: System,
    /// The exact answers, under every law or model.
    pub references: Vec<EngineReference>,
    /// The claimed state, when the line has one: every moving body's (index, velocity, spin).
    pub claimed: Option<Vec<(usize, Vec2<Q>, Q)>>,
    /// The engine's name, as the line gives it.
    pub engine: Option<String>,
    /// For each reference, the square of the claim's error in energy,
    /// `K(claim - exact)/K(before)` (`None`: a claimed component not finite).
    pub errors: Vec<Option<QSqrt>>,
    /// The references the claim matches within the tolerance.
    pub matches: Vec<String>,
    /// What is wrong with the claim (empty: it matches).
    pub findings: Vec<&'static str>,
}

/// The references a system is answered by: the three laws (one contact), or the simultaneous
/// models and, unless `simultaneous_only`, sequential impacts in every order (up to 4 contacts)
/// and 1, 4 and 10 sweeps of projected Gauss-Seidel (several).
fn answers(system: &System, simultaneous_only: bool) -> Result<Vec<EngineReference>, Error> {
    let lift = |v: &Vec2<Q>| Vec2::new(QSqrt::rational(v.x.clone()), QSqrt::rational(v.y.clone()));
    if system.contacts.len() == 1 {
        return Law::ALL
            .iter()
            .map(|&law| {
                let answer = solve_exact(system, law)
                    .map_err(|e| Error::new("scene", ErrorKind::Invalid(e.to_string())))?;
                Ok(EngineReference {
                    name: law.name().into(),
                    bodies: answer
                        .bodies
                        .into_iter()
                        .map(|b| (b.index, b.velocity, b.omega))
                        .collect(),
                })
            })
            .collect();
    }
    let n = system.contacts.len();
    let mut models = vec![Model::SimultaneousNewton, Model::SimultaneousPoisson];
    if !simultaneous_only {
        if n <= 4 {
            models.extend(orders(n).into_iter().map(Model::Sequential));
        }
        models.extend([Model::Pgs(1), Model::Pgs(4), Model::Pgs(10)]);
    }
    let mut out = Vec::new();
    for model in models {
        if let ModelOutcome::Answered(answers) = solve_several::<Q>(system, &model) {
            for (k, a) in answers.into_iter().enumerate() {
                let name = if k == 0 {
                    model.to_string()
                } else {
                    format!("{model} (answer {})", k + 1)
                };
                out.push(EngineReference {
                    name,
                    bodies: a
                        .bodies
                        .iter()
                        .map(|(i, v, w)| (*i, lift(v), QSqrt::rational(w.clone())))
                        .collect(),
                });
            }
        }
    }
    Ok(out)
}

/// Every moving body's (index, velocity, spin), as claimed.
type Bodies = Vec<(usize, Vec2<Q>, Q)>;

/// The engine named and the claimed state of `value["claimed"]`, exactly.
fn claimed(value: &Value, system: &System) -> Result<(Option<String>, Option<Bodies>), Error> {
    let Some(c) = value.get("claimed") else {
        return Ok((None, None));
    };
    let engine = c.get("engine").and_then(Value::as_str).map(String::from);
    let bodies = c
        .get("bodies")
        .and_then(Value::as_object)
        .ok_or_else(|| Error::new("claimed.bodies", ErrorKind::Missing))?;
    let number = |v: &Value, field: &str| -> Result<Option<Q>, Error> {
        let text = match v {
            Value::String(s) => s.clone(),
            Value::Number(n) => n.to_string(),
            _ => {
                return Err(Error::new(
                    field,
                    ErrorKind::Invalid("expected a number".into()),
                ));
            }
        };
        // NaN and infinities are wrong claims, not bad input.
        if ["nan", "inf", "-inf", "infinity", "-infinity"]
            .contains(&text.trim().to_lowercase().as_str())
        {
            return Ok(None);
        }
        crate::number::parse(&text)
            .map(Some)
            .map_err(|kind| Error::new(field, kind))
    };
    let mut out = Vec::new();
    for (index, body) in system.bodies.iter().enumerate().filter(|(_, b)| b.moves()) {
        let field = format!("claimed.bodies.{}", body.name);
        let b = bodies
            .get(&body.name)
            .ok_or_else(|| Error::new(field.clone(), ErrorKind::Missing))?;
        let v = b
            .get("velocity")
            .and_then(Value::as_array)
            .filter(|v| v.len() == 2)
            .ok_or_else(|| {
                Error::new(
                    format!("{field}.velocity"),
                    ErrorKind::Invalid("expected [x, y]".into()),
                )
            })?;
        let (x, y) = (
            number(&v[0], &format!("{field}.velocity[1]"))?,
            number(&v[1], &format!("{field}.velocity[2]"))?,
        );
        let w = number(
            b.get("omega")
                .ok_or_else(|| Error::new(format!("{field}.omega"), ErrorKind::Missing))?,
            &format!("{field}.omega"),
        )?;
        match (x, y, w) {
            (Some(x), Some(y), Some(w)) => out.push((index, Vec2::new(x, y), w)),
            // A non-finite component: the claim is wrong whatever the rest.
            _ => return Ok((engine, Some(Vec::new()))),
        }
    }
    Ok((engine, Some(out)))
}

/// The claim's error against a reference, measured in energy: the square of
/// `sqrt(K(claim - exact)/K(before))`, K the kinetic energy of the velocity differences (each
/// body's mass and inertia weighing its own), so every component counts in proportion to the
/// motion it carries and an exact zero is no special case. `None` when a claimed component is
/// not finite, or nothing moves before.
fn error(
    system: &System,
    claimed: &[(usize, Vec2<Q>, Q)],
    reference: &EngineReference,
) -> Option<QSqrt> {
    if claimed.is_empty() {
        return None;
    }
    let lift = |x: &Q| QSqrt::rational(x.clone());
    let bodies = |pairs: &mut dyn Iterator<Item = (&crate::model::Body, Vec2<QSqrt>, QSqrt)>| {
        pairs
            .map(|(b, velocity, omega)| PlanarBody {
                mass: lift(&b.mass),
                inertia: lift(&b.inertia),
                centre: Vec2::new(lift(&b.position.x), lift(&b.position.y)),
                velocity,
                omega,
            })
            .collect::<Vec<_>>()
    };
    let difference = bodies(&mut claimed.iter().zip(&reference.bodies).map(
        |((i, v, w), (_, rv, rw))| {
            (
                &system.bodies[*i],
                Vec2::new(lift(&v.x) - &rv.x, lift(&v.y) - &rv.y),
                lift(w) - rw,
            )
        },
    ));
    let before = bodies(&mut system.bodies.iter().filter(|b| b.moves()).map(|b| {
        (
            b,
            Vec2::new(lift(&b.velocity.x), lift(&b.velocity.y)),
            lift(&b.omega),
        )
    }));
    let k0 = kinetic_energy(&before);
    (k0.sign() == Some(Ordering::Greater)).then(|| kinetic_energy(&difference) / &k0)
}

/// Audits one line of `impact --batch` (the `number`-th), with claims agreeing within the
/// relative tolerance `rtol`.
///
/// # Errors
/// The line's JSON or scene is bad input, naming the field.
///
/// # Examples
/// An engine that ignored the restitution of a wall: the claim matches no law, and the
/// diagnosis says what happened.
/// ```
/// use rodimpact::batch::audit_impact;
/// use rodimpact::field::q;
/// let line = r#"{"id": "puck", "body": [{"name": "puck", "mass": "1", "velocity": ["1", "0"]},
///   {"name": "wall", "fixed": true}], "contact": [{"bodies": ["puck", "wall"], "point": ["0", "0"],
///   "normal": ["-1", "0"], "e": "1/2"}],
///   "claimed": {"engine": "test", "bodies": {"puck": {"velocity": ["0", "0"], "omega": "0"}}}}"#;
/// let audit = audit_impact(line, 1, &q(1, 1_000_000_000))?;
/// assert_eq!(audit.findings, ["restitution-ignored", "energy-loss"]);
/// let right = line.replace(r#"["0", "0"], "omega"#, r#"["-0.5", "0"], "omega"#);
/// assert_eq!(audit_impact(&right, 1, &q(1, 1_000_000_000))?.matches, ["newton", "poisson", "energetic"]);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn audit_impact(line: &str, number: usize, rtol: &Q) -> Result<ImpactAudit, Error> {
    let at = |e: Error| Error::new(format!("line {number}: {}", e.field), e.kind);
    let value: Value = serde_json::from_str(line).map_err(|e| {
        Error::new(
            format!("line {number}"),
            ErrorKind::Invalid(format!("not JSON: {e}")),
        )
    })?;
    let mut scene = value.clone();
    if let Value::Object(map) = &mut scene {
        for key in ["id", "class", "claimed"] {
            map.remove(key);
        }
    }
    let system = from_value(&scene).map_err(at)?;
    let id = value
        .get("id")
        .and_then(Value::as_str)
        .map_or_else(|| number.to_string(), String::from);
    let references = answers(&system, false).map_err(at)?;
    let (engine, claimed) = claimed(&value, &system).map_err(at)?;
    let Some(claims) = claimed.clone() else {
        return Ok(ImpactAudit {
            id,
            system,
            references,
            claimed: None,
            engine,
            errors: Vec::new(),
            matches: Vec::new(),
            findings: Vec::new(),
        });
    };
    let errors: Vec<Option<QSqrt>> = references
        .iter()
        .map(|r| error(&system, &claims, r))
        .collect();
    let tolerance = QSqrt::rational(rtol * rtol);
    let within = |e: &QSqrt| e.cmp_exact(&tolerance) != Ordering::Greater;
    let matches: Vec<String> = references
        .iter()
        .zip(&errors)
        .filter(|(_, e)| e.as_ref().is_some_and(within))
        .map(|(r, _)| r.name.clone())
        .collect();
    let findings = if matches.is_empty() {
        diagnose(&system, &claims, &references, rtol)
    } else {
        Vec::new()
    };
    Ok(ImpactAudit {
        id,
        system,
        references,
        claimed,
        engine,
        errors,
        matches,
        findings,
    })
}

/// What is wrong with a claim that matches no answer.
fn diagnose(
    system: &System,
    claims: &[(usize, Vec2<Q>, Q)],
    references: &[EngineReference],
    rtol: &Q,
) -> Vec<&'static str> {
    if claims.is_empty() {
        return vec!["off"];
    }
    let before: Vec<PlanarBody<Q>> = system
        .bodies
        .iter()
        .filter(|b| b.moves())
        .map(|b| b.planar())
        .collect();
    let after: Vec<PlanarBody<Q>> = before
        .iter()
        .zip(claims)
        .map(|(b, (_, v, w))| PlanarBody {
            velocity: v.clone(),
            omega: w.clone(),
            ..b.clone()
        })
        .collect();
    let within = |x: &Q, y: &Q| {
        let scale = if y.is_zero() { x.abs() } else { y.abs() };
        (x - y).abs() <= scale * rtol
    };
    let mut findings = Vec::new();
    let unchanged = before.iter().zip(&after).all(|(b, a)| {
        within(&a.velocity.x, &b.velocity.x)
            && within(&a.velocity.y, &b.velocity.y)
            && within(&a.omega, &b.omega)
    });
    if unchanged {
        findings.push("no-contact");
    }
    // The same scene with e = 0: an engine that ignored restitution.
    let sticking = System {
        contacts: system
            .contacts
            .iter()
            .map(|c| crate::model::Contact {
                e: Q::zero(),
                ..c.clone()
            })
            .collect(),
        ..system.clone()
    };
    if let Ok(plastic) = answers(&sticking, true)
        && plastic.iter().any(|r| {
            error(system, claims, r)
                .is_some_and(|e| e.cmp_exact(&QSqrt::rational(rtol * rtol)) != Ordering::Greater)
        })
        && system.contacts.iter().any(|c| c.e.is_positive())
    {
        findings.push("restitution-ignored");
    }
    let (k0, k1) = (kinetic_energy(&before), kinetic_energy(&after));
    if k1 > &k0 * (Q::from_integer(1.into()) + rtol) {
        findings.push("energy-gain");
    }
    let lowest = references
        .iter()
        .map(|r| {
            let bodies: Vec<PlanarBody<QSqrt>> = before
                .iter()
                .zip(&r.bodies)
                .map(|(b, (_, v, w))| PlanarBody {
                    mass: QSqrt::rational(b.mass.clone()),
                    inertia: QSqrt::rational(b.inertia.clone()),
                    centre: Vec2::new(
                        QSqrt::rational(b.centre.x.clone()),
                        QSqrt::rational(b.centre.y.clone()),
                    ),
                    velocity: v.clone(),
                    omega: w.clone(),
                })
                .collect();
            kinetic_energy(&bodies)
        })
        .min_by(|a, b| a.cmp_exact(b));
    if let Some(lowest) = lowest {
        let floor = lowest * &QSqrt::rational(Q::from_integer(1.into()) - rtol);
        if QSqrt::rational(k1.clone()).cmp_exact(&floor) == Ordering::Less && !unchanged {
            findings.push("energy-loss");
        }
    }
    if system.bodies.iter().all(|b| b.mobility == Mobility::Free) {
        let (p0, p1) = (linear_momentum(&before), linear_momentum(&after));
        if !within(&p1.x, &p0.x) || !within(&p1.y, &p0.y) {
            findings.push("momentum");
        }
        let origin = Vec2::zero();
        if !within(
            &angular_momentum(&after, &origin),
            &angular_momentum(&before, &origin),
        ) {
            findings.push("angular-momentum");
        }
    }
    if findings.is_empty() {
        findings.push("off");
    }
    findings
}
