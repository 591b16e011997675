//! The exact answers an engine's claimed impact is compared with: the physical laws (one
//! contact) or models (several), the laws engines converge to, and the engine's own step,
//! replayed exactly; answers that are equal are one, named by the first and listing the others.

use crate::echo::echo;
use crate::error::{Error, ErrorKind};
use crate::field::{Q, QSqrt};
use crate::impact::{
    Engine, Law, Model, ModelOutcome, Profile, Stopped, orders, solve_engine_exact, solve_exact,
    solve_several_sharing,
};
use crate::mechanics::planar::Vec2;
use crate::model::System;
use serde_json::Value;

/// What an answer is: a physical law or model, a law engines converge to, or an engine's step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Newton's, Poisson's or Stronge's law (one contact); the simultaneous models and
    /// sequential impacts (several).
    Physical,
    /// lcp-newton, lcp-poisson, split, sweeps of projected Gauss-Seidel.
    EngineLaw,
    /// An engine's step, replayed exactly ([`Profile`]).
    Profile,
}

/// One exact answer the claimed state is compared with: its name (and the names of the answers
/// equal to it), what it is, and every moving body's (index, velocity, spin).
#[derive(Debug, Clone, PartialEq)]
pub struct EngineReference {
    /// `newton`, `lcp-newton`, `simultaneous-newton`, `pgs:4`, `pymunk-7`, ...
    pub name: String,
    /// The other answers exactly equal to it, in the order they are tried.
    pub equal: Vec<String>,
    /// What the first is.
    pub kind: Kind,
    /// The moving bodies after.
    pub bodies: Vec<(usize, Vec2<QSqrt>, QSqrt)>,
}

impl EngineReference {
    /// Whether `name` names this answer (its own name, or one of the equal answers').
    pub fn is(&self, name: &str) -> bool {
        self.name == name || self.equal.iter().any(|e| e == name)
    }
}

/// The engine profile of a line whose `claimed.engine` names an engine rodimpact replays, by
/// its name and the major version rodimpact follows (`pymunk 7.3.1`, `box2d 2.3.10` with
/// `settings.scale`, `box2d v3.1`, `pybullet 3.2.7` with `settings.plane`, `rapier2d-f64
/// 0.36.1`); `None` for another engine or version (MuJoCo's compliant contact has no such step;
/// `pymunk 99` is not pymunk 7), or none named. Nothing is guessed from a prefix.
///
/// # Errors
/// `claimed.engine: expected a string`; a setting that the named engine's step takes but that
/// does not parse (`claimed.settings.scale: ...`, `claimed.settings.plane: expected xz or xy`).
///
/// # Examples
/// ```
/// use rodimpact::batch::profile_of_claim;
/// let claim = |text: &str| serde_json::from_str::<serde_json::Value>(text).unwrap();
/// let box2d = claim(r#"{"engine": "box2d 2.3.10", "settings": {"scale": "16.0"}}"#);
/// assert_eq!(profile_of_claim(&box2d)?.unwrap().to_string(), "box2d-2.3:scale=16");
/// assert_eq!(profile_of_claim(&claim(r#"{"engine": "Box2D v3.1"}"#))?.unwrap().to_string(), "box2d-3");
/// assert!(profile_of_claim(&claim(r#"{"engine": "pymunk 99"}"#))?.is_none());
/// assert!(profile_of_claim(&claim(r#"{"engine": "bulletproof-sim 1.0"}"#))?.is_none());
/// let bad = claim(r#"{"engine": "box2d 2.3.10", "settings": {"scale": "-16"}}"#);
/// assert!(profile_of_claim(&bad).unwrap_err().to_string().starts_with("claimed.settings.scale"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn profile_of_claim(claimed: &Value) -> Result<Option<Profile>, Error> {
    let Some(engine) = claimed.get("engine") else {
        return Ok(None);
    };
    let engine = engine
        .as_str()
        .ok_or_else(|| {
            Error::new(
                "claimed.engine",
                ErrorKind::Invalid("expected a string".into()),
            )
        })?
        .to_lowercase();
    let mut words = engine.split_whitespace();
    let name = words.next().unwrap_or("");
    let version = words
        .next()
        .map(|v| v.trim_start_matches('v'))
        .unwrap_or("");
    let major_minor: Vec<&str> = version.split('.').take(2).collect();
    let setting = |key: &str| -> Option<String> {
        claimed
            .get("settings")
            .and_then(|s| s.get(key))
            .map(|v| match v {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            })
    };
    let refused = |key: &str, why: String| {
        Error::new(format!("claimed.settings.{key}"), ErrorKind::Invalid(why))
    };
    let text = match (name, major_minor.as_slice()) {
        ("pymunk" | "chipmunk", ["7", ..]) => "pymunk-7".to_string(),
        ("box2d" | "pybox2d", ["3", ..]) => "box2d-3".to_string(),
        ("box2d" | "pybox2d", ["2", "3"]) => match setting("scale") {
            None => "box2d-2.3".to_string(),
            Some(text) => {
                let scale = crate::number::parse(&text)
                    .map_err(|kind| Error::new("claimed.settings.scale", kind))?;
                if !num_traits::Signed::is_positive(&scale) {
                    return Err(refused(
                        "scale",
                        format!("must be > 0, got {}", echo(&text)),
                    ));
                }
                format!("box2d-2.3:scale={scale}")
            }
        },
        ("pybullet" | "bullet", ["3", ..]) => match setting("plane").as_deref() {
            None | Some("xz") => "bullet-3".to_string(),
            Some("xy") => "bullet-3:plane=xy".to_string(),
            Some(other) => {
                return Err(refused(
                    "plane",
                    format!("expected xz or xy, got '{}'", echo(other)),
                ));
            }
        },
        ("rapier" | "rapier2d" | "rapier2d-f64", ["0", "36"]) => "rapier-0.36".to_string(),
        _ => return Ok(None),
    };
    Profile::parse(&text)
        .map(Some)
        .map_err(|why| Error::new("claimed.settings", ErrorKind::Invalid(why)))
}

/// Every moving body after an impact: its index, velocity and angular velocity.
type BodiesAfter = Vec<(usize, Vec2<QSqrt>, QSqrt)>;

/// Every answer of `system`, equal ones grouped: one contact, the three laws, the engines'
/// laws, 1 and 10 sweeps of projected Gauss-Seidel and `profiles`' steps; several, the
/// simultaneous models, sequential impacts in every order (up to 4 contacts), split, 1, 4 and
/// 10 sweeps and the profiles' steps. With `physical_only`, the physical laws or the
/// simultaneous models alone.
pub(super) fn exact_answers(
    system: &System,
    profiles: &[Profile],
    physical_only: bool,
) -> Result<Vec<EngineReference>, Error> {
    let mut all: Vec<(String, Kind, BodiesAfter)> = Vec::new();
    let lift = |v: &Vec2<Q>| Vec2::new(QSqrt::rational(v.x.clone()), QSqrt::rational(v.y.clone()));
    let invalid =
        |e: crate::impact::ImpactError| Error::new("scene", ErrorKind::Invalid(e.to_string()));
    let push_models = |all: &mut Vec<_>, models: Vec<(Model, Kind)>| -> Result<(), Error> {
        let named: Vec<Model> = models.iter().map(|(m, _)| m.clone()).collect();
        for (model, kind) in models {
            let outcome = solve_several_sharing::<Q>(system, &model, model.share_among(&named));
            if outcome == ModelOutcome::Stopped(Stopped::Interrupted) {
                return Err(Error::new("impact", ErrorKind::Interrupted));
            }
            if let ModelOutcome::Answered(answers) = outcome {
                for (k, a) in answers.into_iter().enumerate() {
                    let name = if k == 0 {
                        model.to_string()
                    } else {
                        format!("{model} (answer {})", k + 1)
                    };
                    let bodies = a
                        .bodies
                        .iter()
                        .map(|(i, v, w)| (*i, lift(v), QSqrt::rational(w.clone())))
                        .collect();
                    all.push((name, kind, bodies));
                }
            }
        }
        Ok(())
    };
    let n = system.contacts.len();
    if n == 1 {
        let laws: Vec<(Law, Kind)> = Law::ALL
            .into_iter()
            .map(|l| (l, Kind::Physical))
            .chain(
                Law::ENGINES
                    .into_iter()
                    .map(|l| (l, Kind::EngineLaw))
                    .filter(|_| !physical_only),
            )
            .collect();
        for (law, kind) in laws {
            let answer = solve_exact(system, law).map_err(invalid)?;
            let bodies = answer
                .bodies
                .into_iter()
                .map(|b| (b.index, b.velocity, b.omega))
                .collect();
            all.push((law.name().into(), kind, bodies));
        }
        if !physical_only {
            push_models(
                &mut all,
                vec![
                    (Model::Pgs(1), Kind::EngineLaw),
                    (Model::Pgs(10), Kind::EngineLaw),
                ],
            )?;
            for profile in profiles {
                // A step that does not stop has no answer to compare with.
                if let Ok(answer) = solve_engine_exact(system, profile) {
                    let bodies = answer
                        .bodies
                        .into_iter()
                        .map(|b| (b.index, b.velocity, b.omega))
                        .collect();
                    all.push((profile.to_string(), Kind::Profile, bodies));
                }
            }
        }
    } else {
        let mut models = vec![
            (Model::SimultaneousNewton, Kind::Physical),
            (Model::SimultaneousPoisson, Kind::Physical),
        ];
        if !physical_only {
            if n <= 4 {
                models.extend(
                    orders(n)
                        .into_iter()
                        .map(|o| (Model::Sequential(o), Kind::Physical)),
                );
            }
            models.push((Model::Split, Kind::EngineLaw));
            models.extend([1, 4, 10].map(|k| (Model::Pgs(k), Kind::EngineLaw)));
            models.extend(
                profiles
                    .iter()
                    .map(|p| (Model::Engine(p.clone()), Kind::Profile)),
            );
        }
        push_models(&mut all, models)?;
    }
    let mut grouped: Vec<EngineReference> = Vec::new();
    for (name, kind, bodies) in all {
        match grouped.iter_mut().find(|r| r.bodies == bodies) {
            Some(r) => r.equal.push(name),
            None => grouped.push(EngineReference {
                name,
                equal: Vec::new(),
                kind,
                bodies,
            }),
        }
    }
    Ok(grouped)
}

/// The name of the answer an engine's law is among the references: for several contacts,
/// lcp-newton is the simultaneous Newton model, lcp-poisson the simultaneous Poisson model.
pub(super) fn law_name(law: Law, contacts: usize) -> String {
    match (contacts, Model::of_law(law)) {
        (1, _) | (_, None) => law.name().to_string(),
        (_, Some(model)) => model.to_string(),
    }
}

/// The engines whose steps rodimpact replays, with their defaults: the profiles a line is
/// compared with when `--engine all` asks for every one.
pub(super) fn every_replayed_profile() -> Vec<Profile> {
    Engine::ALL
        .into_iter()
        .filter(|e| e.replayed())
        .map(Profile::of)
        .collect()
}
