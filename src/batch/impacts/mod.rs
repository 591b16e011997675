//! An engine's planar impacts audited: `rodimpact impact --batch FILE.jsonl`.
//!
//! Each line is a scene in its JSON form (the structure of a scene file) with an optional
//! `"claimed"` object, what an engine produced: `{"engine": "...", "bodies": {"rod":
//! {"velocity": ["x", "y"], "omega": "w"}, ...}}`, every number a decimal or fraction string
//! read exactly (a float's shortest text is its exact value's nearest decimal). The line is
//! answered exactly under every physical law (one contact) or model (several contacts), every
//! law engines converge to (lcp-newton, lcp-poisson, split, sweeps of projected Gauss-Seidel)
//! and the engine's own step where rodimpact replays it ([`profile_of_claim`], or one given);
//! equal answers are one. The claimed state is compared with each: its error in energy,
//! `sqrt(K(claim - exact)/K(before))` (K the kinetic energy of the velocity differences), which
//! answers it matches within a tolerance, which it is closest to, the split of its error into
//! the engine's law, its iterations and its rounding, and a diagnosis as `batch` gives (`ok`;
//! or `energy-gain`, `energy-loss`, `restitution-ignored`, `no-contact`, `momentum`,
//! `angular-momentum`, `off`).
//!
//! | file | what it does |
//! |---|---|
//! | `mod.rs` | one line audited: the claim read, its errors, matches, diagnosis and error split |
//! | `references.rs` | the exact answers a claim is compared with, equal ones grouped |
//! | `summary.rs` | what the lines said, together |

mod line;
mod references;
mod summary;

pub use line::parse_line;
pub use references::{EngineReference, Kind, profile_of_claim};
pub use summary::{ImpactBatchSummary, MAX_NAMED_SCENES, Scenes};

use crate::batch::FloatFormat;
use crate::echo::echo;
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, QSqrt};
use crate::impact::Profile;
use crate::mechanics::planar::{
    PlanarBody, Vec2, angular_momentum, kinetic_energy, linear_momentum,
};
use crate::model::{Mobility, System, from_value};
use num_traits::{Signed, Zero};
use references::{every_replayed_profile, exact_answers, law_name};
use serde_json::Value;
use std::cmp::Ordering;

/// When a claim matches an exact answer: its error in energy within `rtol`, or every component
/// within `atol` (m/s, rad/s), or every component within `ulps` floats of the exact value
/// correctly rounded.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactTolerance {
    /// The relative error in energy, `sqrt(K(claim - exact)/K(before))`, at most this.
    pub rtol: Q,
    /// Or every component within this absolute error.
    pub atol: Option<Q>,
    /// Or every component within this many floats of the format.
    pub ulps: Option<(u64, FloatFormat)>,
}

impl Default for ImpactTolerance {
    /// `rtol` 1e-9, no `atol`, no `ulps`.
    fn default() -> Self {
        ImpactTolerance {
            rtol: Q::new(1.into(), 1_000_000_000.into()),
            atol: None,
            ulps: None,
        }
    }
}

/// Which engine steps a line is compared with.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum EngineChoice {
    /// The step of the engine the line's `claimed.engine` names ([`profile_of_claim`]).
    #[default]
    FromClaim,
    /// This engine's, for every line.
    This(Profile),
    /// Every replayed engine's (pymunk-7, box2d-2.3, bullet-3, their defaults).
    Every,
}

/// An engine's error split: the distance of its converged law from the nearest physical law
/// (its LAW), of its step from that law (its ITERATIONS), and of its claim from its step (its
/// ROUNDING), each in energy relative to the energy before, squared (as
/// [`ImpactAudit::errors`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorSplit {
    /// The engine's profile.
    pub profile: Profile,
    /// Its converged law's answer, and the physical law or model nearest it.
    pub law: String,
    /// The nearest physical law or model.
    pub nearest: String,
    /// The law's distance from it.
    pub of_law: QSqrt,
    /// The step's distance from its law.
    pub of_iterations: QSqrt,
    /// The claim's distance from the step (`None`: a claimed component not finite).
    pub of_rounding: Option<QSqrt>,
}

/// One line audited.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactAudit {
    /// The line's `id` (its number when it has none).
    pub id: String,
    /// The scene.
    pub system: System,
    /// The exact answers, equal ones grouped.
    pub references: Vec<EngineReference>,
    /// The claimed state, when the line has one: every moving body's (index, velocity, spin).
    pub claimed: Option<Vec<(usize, Vec2<Q>, Q)>>,
    /// The engine's name, as the line gives it.
    pub engine: Option<String>,
    /// For each reference, the square of the claim's error in energy,
    /// `K(claim - exact)/K(before)` (`None`: a claimed component not finite).
    pub errors: Vec<Option<QSqrt>>,
    /// The references the claim matches within the tolerance (the first name of each: its
    /// equal answers match too).
    pub matches: Vec<String>,
    /// The reference nearest the claim (its first name).
    pub closest: Option<String>,
    /// The engine's error split, when its step is compared with.
    pub split: Option<ErrorSplit>,
    /// What is wrong with the claim (empty: it matches).
    pub findings: Vec<&'static str>,
}

/// Every moving body's (index, velocity, spin), as claimed.
type Bodies = Vec<(usize, Vec2<Q>, Q)>;

/// The engine named and the claimed state of `value["claimed"]`, exactly.
fn claimed(value: &Value, system: &System) -> Result<(Option<String>, Option<Bodies>), Error> {
    let Some(c) = value.get("claimed") else {
        return Ok((None, None));
    };
    let unknown = |field: String, expected: &str| {
        Error::new(
            field,
            ErrorKind::Invalid(format!("unknown key (expected {expected})")),
        )
    };
    let c = c
        .as_object()
        .ok_or_else(|| Error::new("claimed", ErrorKind::Invalid("expected an object".into())))?;
    if let Some(key) = c
        .keys()
        .find(|k| !["engine", "settings", "bodies"].contains(&k.as_str()))
    {
        return Err(unknown(
            format!("claimed.{}", echo(key)),
            "engine, settings, bodies",
        ));
    }
    let engine = c.get("engine").and_then(Value::as_str).map(String::from);
    let bodies = c
        .get("bodies")
        .and_then(Value::as_object)
        .ok_or_else(|| Error::new("claimed.bodies", ErrorKind::Missing))?;
    // Every claimed body is a moving body of the scene, with its velocity and spin only.
    for (name, body) in bodies {
        let field = format!("claimed.bodies.{}", echo(name));
        if !system.bodies.iter().any(|b| b.moves() && &b.name == name) {
            return Err(Error::new(
                field,
                ErrorKind::Invalid("no moving body of the scene has this name".into()),
            ));
        }
        if let Some(key) = body.as_object().and_then(|b| {
            b.keys()
                .find(|k| !["velocity", "omega"].contains(&k.as_str()))
        }) {
            return Err(unknown(format!("{field}.{}", echo(key)), "velocity, omega"));
        }
    }
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

/// The bodies of a claim, lifted into Q(sqrt d) to meet the exact answers.
fn lifted(claims: &[(usize, Vec2<Q>, Q)]) -> Vec<(usize, Vec2<QSqrt>, QSqrt)> {
    let lift = |x: &Q| QSqrt::rational(x.clone());
    claims
        .iter()
        .map(|(i, v, w)| (*i, Vec2::new(lift(&v.x), lift(&v.y)), lift(w)))
        .collect()
}

/// The distance between two states of the moving bodies, measured in energy: the square of
/// `sqrt(K(a - b)/K(before))`, K the kinetic energy of the velocity differences (each body's
/// mass and inertia weighing its own), so every component counts in proportion to the motion
/// it carries and an exact zero is no special case. `None` when `a` is empty (a claimed
/// component not finite), or nothing moves before.
fn distance(
    system: &System,
    a: &[(usize, Vec2<QSqrt>, QSqrt)],
    b: &[(usize, Vec2<QSqrt>, QSqrt)],
) -> Option<QSqrt> {
    if a.is_empty() {
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
    let difference = bodies(&mut a.iter().zip(b).map(|((i, v, w), (_, rv, rw))| {
        (
            &system.bodies[*i],
            Vec2::new(v.x.clone() - &rv.x, v.y.clone() - &rv.y),
            w.clone() - rw,
        )
    }));
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

/// Whether every claimed component lies within `tolerance`'s `atol` or `ulps` of the
/// reference's (false when neither is given).
fn within_components(
    claims: &[(usize, Vec2<Q>, Q)],
    reference: &EngineReference,
    tolerance: &ImpactTolerance,
) -> bool {
    let pairs = || {
        claims
            .iter()
            .zip(&reference.bodies)
            .flat_map(|((_, v, w), (_, rv, rw))| [(&v.x, &rv.x), (&v.y, &rv.y), (w, rw)])
    };
    let near = |claim: &Q, exact: &QSqrt| -> bool {
        let by_atol = tolerance.atol.as_ref().is_some_and(|atol| {
            let d = QSqrt::rational(claim.clone()) - exact;
            let atol = QSqrt::rational(atol.clone());
            d.cmp_exact(&atol) != Ordering::Greater && d.cmp_exact(&-atol) != Ordering::Less
        });
        let by_ulps = tolerance.ulps.is_some_and(|(n, format)| {
            let (lo, hi) = if exact.d().is_none() {
                (exact.x().clone(), exact.x().clone())
            } else {
                exact.bounds(40)
            };
            crate::batch::ulp_distance(claim, &lo, format)
                .min(crate::batch::ulp_distance(claim, &hi, format))
                <= n
        });
        by_atol || by_ulps
    };
    (tolerance.atol.is_some() || tolerance.ulps.is_some()) && pairs().all(|(c, x)| near(c, x))
}

/// Audits one line of `impact --batch` (the `number`-th): its claim against every exact answer
/// (with the engine steps `engines` chooses), matching within `tolerance`.
///
/// # Errors
/// The line's JSON or scene is bad input, naming the field.
///
/// # Examples
/// An engine that ignored the restitution of a wall: the claim matches no law, and the
/// diagnosis says what happened.
/// ```
/// use rodimpact::batch::{EngineChoice, ImpactTolerance, audit_impact};
/// let line = r#"{"id": "puck", "body": [{"name": "puck", "mass": "1", "velocity": ["1", "0"]},
///   {"name": "wall", "fixed": true}], "contact": [{"bodies": ["puck", "wall"], "point": ["0", "0"],
///   "normal": ["-1", "0"], "e": "1/2"}],
///   "claimed": {"engine": "test", "bodies": {"puck": {"velocity": ["0", "0"], "omega": "0"}}}}"#;
/// let (tolerance, engines) = (ImpactTolerance::default(), EngineChoice::FromClaim);
/// let audit = audit_impact(line, 1, &tolerance, &engines)?;
/// assert_eq!(audit.findings, ["restitution-ignored", "energy-loss"]);
/// let right = line.replace(r#"["0", "0"], "omega"#, r#"["-0.5", "0"], "omega"#);
/// let audit = audit_impact(&right, 1, &tolerance, &engines)?;
/// assert_eq!(audit.closest.as_deref(), Some("newton")); // every law agrees without friction
/// assert_eq!(audit.matches, ["newton"]); // the laws are one answer here: poisson, energetic, ... equal it
/// assert!(audit.references[0].equal.contains(&"energetic".to_string()));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn audit_impact(
    line: &str,
    number: usize,
    tolerance: &ImpactTolerance,
    engines: &EngineChoice,
) -> Result<ImpactAudit, Error> {
    let at = |e: Error| Error::new(format!("line {number}: {}", e.field), e.kind);
    let value = parse_line(line).map_err(|e| match e.field.as_str() {
        "line" => Error::new(format!("line {number}"), e.kind),
        _ => at(e),
    })?;
    if value.get("claim").is_some() {
        return Err(at(Error::new(
            "claim",
            ErrorKind::Invalid(
                "published answers ([[claim]]) belong in a scene file (rodimpact impact FILE.toml); an engine's bodies after go in \"claimed\"".into(),
            ),
        )));
    }
    let mut scene = value.clone();
    if let Value::Object(map) = &mut scene {
        for key in ["id", "class", "claimed"] {
            map.remove(key);
        }
    }
    let system = from_value(&scene).map_err(at)?;
    let id = match value.get("id") {
        None => number.to_string(),
        Some(Value::String(id)) => id.clone(),
        Some(_) => {
            return Err(at(Error::new(
                "id",
                ErrorKind::Invalid("expected a string".into()),
            )));
        }
    };
    let profiles: Vec<Profile> = match engines {
        EngineChoice::FromClaim => match value.get("claimed") {
            Some(claimed) => profile_of_claim(claimed).map_err(at)?.into_iter().collect(),
            None => Vec::new(),
        },
        EngineChoice::This(profile) => vec![profile.clone()],
        EngineChoice::Every => every_replayed_profile(),
    };
    let references = exact_answers(&system, &profiles, false).map_err(at)?;
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
            closest: None,
            split: None,
            findings: Vec::new(),
        });
    };
    let claim = lifted(&claims);
    let errors: Vec<Option<QSqrt>> = references
        .iter()
        .map(|r| distance(&system, &claim, &r.bodies))
        .collect();
    let squared = QSqrt::rational(tolerance.rtol.clone() * &tolerance.rtol);
    let matched = |r: &EngineReference, e: &Option<QSqrt>| {
        e.as_ref()
            .is_some_and(|e| e.cmp_exact(&squared) != Ordering::Greater)
            || (!claims.is_empty() && within_components(&claims, r, tolerance))
    };
    let matches: Vec<String> = references
        .iter()
        .zip(&errors)
        .filter(|(r, e)| matched(r, e))
        .map(|(r, _)| r.name.clone())
        .collect();
    let closest = references
        .iter()
        .zip(&errors)
        .filter_map(|(r, e)| e.as_ref().map(|e| (r, e)))
        .min_by(|a, b| a.1.cmp_exact(b.1))
        .map(|(r, _)| r.name.clone());
    let split = profiles
        .first()
        .and_then(|p| error_split(&system, &references, &claim, p));
    let findings = if matches.is_empty() {
        diagnose(&system, &claims, &references, &tolerance.rtol)
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
        closest,
        split,
        findings,
    })
}

/// The engine's error split: its law against the nearest physical answer, its step against its
/// law, the claim against its step. `None` when the step has no answer (its steps do not stop).
fn error_split(
    system: &System,
    references: &[EngineReference],
    claim: &[(usize, Vec2<QSqrt>, QSqrt)],
    profile: &Profile,
) -> Option<ErrorSplit> {
    let step = references.iter().find(|r| r.is(&profile.to_string()))?;
    let law_answer_name = law_name(profile.engine.law(), system.contacts.len());
    let law = references.iter().find(|r| r.is(&law_answer_name))?;
    let (nearest, of_law) = references
        .iter()
        .filter(|r| r.kind == Kind::Physical)
        .filter_map(|r| distance(system, &law.bodies, &r.bodies).map(|d| (r, d)))
        .min_by(|a, b| a.1.cmp_exact(&b.1))
        .map(|(r, d)| (r.name.clone(), d))?;
    Some(ErrorSplit {
        profile: profile.clone(),
        law: law_answer_name,
        nearest,
        of_law,
        of_iterations: distance(system, &step.bodies, &law.bodies)?,
        of_rounding: distance(system, claim, &step.bodies),
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
    if let Ok(plastic) = exact_answers(&sticking, &[], true)
        && plastic.iter().any(|r| {
            distance(system, &lifted(claims), &r.bodies)
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
