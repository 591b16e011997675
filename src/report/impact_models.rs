//! The report of several contacts under each model (`rodimpact impact` on a scene with more
//! than one contact): every model's answers with their ledgers, as text and JSON, equal
//! sequential orders named together.

use super::impact::{scene_json, show};
use super::value_json;
use crate::field::decimal;
use crate::field::{Q, QSqrt};
use crate::impact::{ContactMatrix, Model, ModelOutcome, Stopped};
use crate::mechanics::planar::Vec2;
use crate::model::System;
use num_traits::Zero;
use serde_json::{Map, Value, json};

/// The JSON of `rodimpact impact` for a scene with several contacts: `scene` and `models`, one
/// object per model (`model`, `status`: `unique`, `several` or why there is none; `answers`,
/// each with `bodies`, per-contact `impulses` (`normal`, `tangential`), the ledger
/// (`momentum`, `angular_momentum_origin`, `energy` with `change`, `energy_gain`,
/// `normal_velocity_after`, `sinking_contacts`, 1-based) and, for a sequential model, the
/// `impacts` it fired).
///
/// # Examples
/// ```
/// use rodimpact::{field::Q, model::parse_toml, report::models_json};
/// use rodimpact::impact::{Model, contact_matrix, solve_several};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
/// let system = parse_toml("cradle-3", &text)?;
/// let model = Model::SimultaneousNewton;
/// let w = contact_matrix::<Q>(&system).0;
/// let json = models_json(&system, &w, &[(model.clone(), solve_several::<Q>(&system, &model))], 30);
/// assert_eq!(json["models"][0]["answers"][0]["bodies"]["ball1"]["velocity"][0]["exact"], "-1/3");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn models_json(
    system: &System,
    w: &ContactMatrix<Q>,
    outcomes: &[(Model, ModelOutcome<Q>)],
    digits: usize,
) -> Value {
    let digits = digits.max(30);
    let value = |x: &Q| value_json(x, digits);
    let vector = |v: &Vec2<Q>| json!([value(&v.x), value(&v.y)]);
    let models: Vec<Value> = outcomes
        .iter()
        .map(|(model, outcome)| {
            let (status, answers) = match outcome {
                ModelOutcome::Answered(answers) if answers.len() == 1 => ("unique", answers.as_slice()),
                ModelOutcome::Answered(answers) => ("several", answers.as_slice()),
                ModelOutcome::NoSolution => ("no solution", &[][..]),
                ModelOutcome::DoesNotStop => ("does not stop", &[][..]),
                ModelOutcome::FrictionlessOnly => ("frictionless only", &[][..]),
                ModelOutcome::Stopped(Stopped::OverBudget(_)) => ("over the work limit", &[][..]),
                ModelOutcome::Stopped(Stopped::Interrupted) => ("interrupted", &[][..]),
            };
            let answers: Vec<Value> = answers
                .iter()
                .map(|a| {
                    let mut bodies = Map::new();
                    for (index, velocity, omega) in &a.bodies {
                        bodies.insert(
                            system.bodies[*index].name.clone(),
                            json!({"velocity": vector(velocity), "omega": value(omega)}),
                        );
                    }
                    let l = &a.ledger;
                    let mut out = json!({
                        "bodies": bodies,
                        "impulses": a.impulses.iter().zip(&a.tangential).enumerate().map(|(k, (n, t))| json!({
                            "contact": k + 1, "normal": value(n), "tangential": value(t)
                        })).collect::<Vec<_>>(),
                        "split_indeterminate": a.split_indeterminate,
                        "ledger": {
                            "momentum": {"before": vector(&l.momentum_before), "after": vector(&l.momentum_after)},
                            "angular_momentum_origin": {"before": value(&l.angular_before), "after": value(&l.angular_after)},
                            "energy": {"before": value(&l.energy.before), "after": value(&l.energy.after), "change": value(&l.energy.change)},
                            "energy_gain": l.energy.gain(),
                            "normal_velocity_after": l.normal_after.iter().map(&value).collect::<Vec<_>>(),
                            "sinking_contacts": l.sinking().iter().map(|i| i + 1).collect::<Vec<_>>(),
                        },
                    });
                    if !a.impacts.is_empty() {
                        out["impacts"] = json!(a.impacts.iter().map(|(k, x)| json!({"contact": k + 1, "impulse": value(x)})).collect::<Vec<_>>());
                    }
                    out
                })
                .collect();
            let mut entry = json!({"model": model.to_string(), "status": status, "answers": answers});
            if let Model::Engine(profile) = model {
                entry["engine"] = json!(profile.to_string());
            }
            if let ModelOutcome::Stopped(stopped) = outcome {
                entry["why"] = json!(stopped.to_string());
            }
            entry
        })
        .collect();
    json!({"scene": scene_json(system, w, digits), "models": models})
}

/// The text report of `rodimpact impact` for several contacts: each model's answer (or why it
/// has none), the bodies after, the impulses, and the ledger: momentum, angular momentum about
/// the origin, the energy change, and the contacts the model lets sink.
///
/// # Examples
/// ```
/// use rodimpact::{field::Q, model::parse_toml, report::models_text};
/// use rodimpact::impact::{Model, solve_several};
/// let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/impacts/cradle-3.toml")).unwrap();
/// let system = parse_toml("cradle-3", &text)?;
/// let model = Model::Pgs(1);
/// let report = models_text(&system, &[(model.clone(), solve_several::<Q>(&system, &model))], 6);
/// assert!(report.contains("energy 1/2 = 0.5 -> 1/4 = 0.25 J, change -1/4 = -0.25 J"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn models_text(
    system: &System,
    outcomes: &[(Model, ModelOutcome<Q>)],
    digits: usize,
) -> String {
    let show = |x: &Q| show(&QSqrt::rational(x.clone()), digits);
    let show_vector = |v: &Vec2<Q>| format!("({}, {})", show(&v.x), show(&v.y));
    let mut out = String::new();
    if let Some(title) = &system.title {
        out.push_str(&format!("{title}\n\n"));
    }
    out.push_str(&format!(
        "{} bodies, {} contacts (normal velocities before: {})\n",
        system.bodies.len(),
        system.contacts.len(),
        system
            .contacts
            .iter()
            .map(|c| decimal::compact(&system.relative_velocity(c).dot(&c.normal)))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    let rough = system.contacts.iter().any(|c| !c.mu.is_zero());
    let mut shown = vec![false; outcomes.len()];
    for (k, (model, outcome)) in outcomes.iter().enumerate() {
        if shown[k] {
            continue;
        }
        out.push_str(&format!("\n{} ({})\n", model, model_meaning(model, rough)));
        // The other sequential orders with the same outcome, named here rather than repeated.
        if matches!(model, Model::Sequential(_)) {
            let same: Vec<String> = (k + 1..outcomes.len())
                .filter(|&j| {
                    matches!(outcomes[j].0, Model::Sequential(_))
                        && same_outcome(outcome, &outcomes[j].1)
                })
                .map(|j| {
                    shown[j] = true;
                    outcomes[j].0.to_string()
                })
                .collect();
            if !same.is_empty() {
                out.push_str(&format!(
                    "  the same in the orders {}\n",
                    same.join("; ").replace("sequential:", "")
                ));
            }
        }
        let answers = match outcome {
            ModelOutcome::Answered(answers) => answers,
            ModelOutcome::NoSolution => {
                out.push_str("  no impulses satisfy this model\n");
                continue;
            }
            ModelOutcome::DoesNotStop => {
                out.push_str(&format!("  {}\n", model.why_it_does_not_stop(system)));
                continue;
            }
            ModelOutcome::FrictionlessOnly => {
                out.push_str("  run without friction only here, and this scene has friction\n");
                continue;
            }
            ModelOutcome::Stopped(stopped) => {
                out.push_str(&format!("  not answered: {stopped}\n"));
                continue;
            }
        };
        if answers.len() > 1 {
            let why = match model {
                Model::SimultaneousPoisson => {
                    "the compression's split among the contacts is open and, with unequal e, \
                     each split pushes differently in the expansion: these are the ends of a set \
                     of answers"
                }
                _ => "the model does not decide",
            };
            out.push_str(&format!("  {} answers: {why}\n", answers.len()));
        }
        for (k, a) in answers.iter().enumerate() {
            if answers.len() > 1 {
                out.push_str(&format!("  answer {}:\n", k + 1));
            }
            for (index, velocity, omega) in &a.bodies {
                out.push_str(&format!(
                    "  {}: v = {} m/s, omega = {} rad/s\n",
                    system.bodies[*index].name,
                    show_vector(velocity),
                    show(omega)
                ));
            }
            let impulses: Vec<String> = a
                .impulses
                .iter()
                .zip(&a.tangential)
                .map(|(n, t)| {
                    if t.is_zero() {
                        show(n)
                    } else {
                        format!("{} (tangential {})", show(n), show(t))
                    }
                })
                .collect();
            out.push_str(&format!(
                "  impulses (normal, per contact): {}\n",
                impulses.join("; ")
            ));
            if a.split_indeterminate {
                out.push_str("  these impulses are one split of several that give the same velocities (only their combined effect is determined)\n");
            }
            if !a.impacts.is_empty() {
                out.push_str(&format!("  impacts fired: {}\n", a.impacts.len()));
            }
            let l = &a.ledger;
            out.push_str(&format!(
                "  momentum {} -> {}, angular momentum about the origin {} -> {}\n",
                show_vector(&l.momentum_before),
                show_vector(&l.momentum_after),
                show(&l.angular_before),
                show(&l.angular_after)
            ));
            out.push_str(&format!(
                "  energy {} -> {} J, change {} J{}\n",
                show(&l.energy.before),
                show(&l.energy.after),
                show(&l.energy.change),
                if l.energy.gain() {
                    ": THIS MODEL CREATES ENERGY"
                } else {
                    ""
                }
            ));
            let sinking = l.sinking();
            out.push_str(&format!(
                "  normal velocity after: {}{}\n",
                l.normal_after
                    .iter()
                    .map(&show)
                    .collect::<Vec<_>>()
                    .join(", "),
                if sinking.is_empty() {
                    String::new()
                } else {
                    format!(
                        "; contact{} {} SINK{}",
                        if sinking.len() == 1 { "" } else { "s" },
                        sinking
                            .iter()
                            .map(|i| (i + 1).to_string())
                            .collect::<Vec<_>>()
                            .join(", "),
                        if sinking.len() == 1 { "S" } else { "" }
                    )
                }
            ));
        }
    }
    out
}

/// Whether two models' outcomes say the same: the same velocities after, or the same reason
/// for no answer.
fn same_outcome(a: &ModelOutcome<Q>, b: &ModelOutcome<Q>) -> bool {
    match (a, b) {
        (ModelOutcome::Answered(x), ModelOutcome::Answered(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p.bodies == q.bodies)
        }
        (ModelOutcome::Answered(_), _) | (_, ModelOutcome::Answered(_)) => false,
        _ => a == b,
    }
}

/// What `model` is, in words; `rough`: some contact has friction.
fn model_meaning(model: &Model, rough: bool) -> &'static str {
    match model {
        Model::SimultaneousNewton => {
            "every contact at once, Newton's law: a complementarity problem"
        }
        Model::SimultaneousPoisson => {
            "every contact at once, compression then expansion by Poisson's law"
        }
        Model::Sequential(_) => {
            "one contact at a time, in this order, in passes until none approaches"
        }
        Model::Pgs(_) if rough => {
            "sweeps of projected Gauss-Seidel from zero impulses, as engines run them: a \
             friction row after each rough contact's normal row"
        }
        Model::Pgs(_) => "sweeps of projected Gauss-Seidel from zero impulses, as engines run them",
        Model::Split => {
            "friction without restitution, then restitution without friction, as Rapier and Box2D v3 converge to"
        }
        Model::Engine(profile) if profile.engine.replayed() => {
            "one step of the engine's solver, replayed exactly from its source"
        }
        Model::Engine(_) => {
            "the law the engine's substeps converge to (its soft contact is not rational)"
        }
    }
}
