//! The oblique and frictional part of a symbolic scene (`formula --v0t ... --mu ...`): each
//! flag given is a number (with a unit) or a formula in the scene's symbols and the oblique ones
//! ([`OBLIQUE_SYMBOLS`]); a flag not given takes `solve`'s default (no slide along the rod, no
//! friction, a point projectile, the rod at rest).

use super::SymbolicScene;
use super::given::value_of;
use crate::error::{Error, ErrorKind};
use crate::field::{Field, RatFn};
use crate::impact::Mode;
use crate::scene::{
    Disc, ObliqueParams, RodMotion, SceneInput, Support, dimension_of, no_approach,
    spin_without_disc,
};
use crate::solve::fast::linear;
use crate::solve::fast::oblique::{self, ObliqueOutcome, normal_params};
use crate::textbook::expr::{Budget, OBLIQUE_SYMBOLS, Radical};
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// Whether `input` gives any oblique flag.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::symbolic::has_oblique};
/// assert!(has_oblique(&SceneInput { mu: Some("mu".into()), ..Default::default() }));
/// assert!(!has_oblique(&SceneInput::default()));
/// ```
pub fn has_oblique(input: &SceneInput) -> bool {
    input.first_oblique().is_some()
}

/// The oblique part of `input` over `scene`'s symbols, or `None` when no oblique flag is
/// given. A flag's formula may use the scene's symbols (replaced by what they stand for in the
/// scene, `--v0t v0` with `--v0 2*m` is `2*m`) and the oblique symbols.
///
/// # Errors
/// A flag that does not parse, `--spin` without `--radius`, a negative `mu` or a radius that
/// is not positive (as numbers, or as formulas positive in no sample scene), a pivoted rod whose centre is given a motion of its own, a rod
/// moving away from the projectile (no approach at the contact, as a number or in every sample
/// scene), or a symbol that does not belong in the scene (`p` without a pivot).
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{expr::Budget, symbolic::{GivenScene, SymbolicScene, oblique_params}}};
/// let input = SceneInput { rod_mass: Some("m".into()), v0t: Some("v0".into()), mu: Some("mu".into()), ..Default::default() };
/// let mut budget = Budget::run();
/// let scene = SymbolicScene::build(&GivenScene::read(&input, &mut budget)?)?;
/// let o = oblique_params(&scene, &input, &mut budget)?.unwrap();
/// assert_eq!((o.v0t.to_string(), o.mu.to_string()), ("v0".to_string(), "mu".to_string()));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn oblique_params(
    scene: &SymbolicScene,
    input: &SceneInput,
    budget: &mut Budget,
) -> Result<Option<ObliqueParams<RatFn>>, Error> {
    if !has_oblique(input) {
        return Ok(None);
    }
    let mut values = [None, None, None, None, None, None, None];
    for ((field, text), slot) in input.oblique_inputs().zip(&mut values) {
        let Some(text) = text else { continue };
        let (value, _) = value_of(field, text, dimension_of(field), budget)?;
        let value = scene
            .substitute(field, &Radical::rational(value), budget)?
            .coeff;
        *slot = Some(value);
    }
    let [v0t, mu, radius, spin, rod_v, rod_vt, rod_omega] = values;
    let or_zero = |x: Option<RatFn>| x.unwrap_or_else(RatFn::zero);
    if let Some(c) = mu.as_ref().and_then(RatFn::as_constant)
        && c.is_negative()
    {
        return Err(Error::out_of_range(
            "mu",
            format!("friction coefficient must be >= 0, got {c}"),
        ));
    }
    if let Some(c) = radius.as_ref().and_then(RatFn::as_constant)
        && !c.is_positive()
    {
        return Err(Error::out_of_range(
            "radius",
            format!("must be > 0, got {c}"),
        ));
    }
    // A formula is refused where it can never be valid, as the scene's own are (`--M -m`):
    // a friction coefficient positive in no sample scene is negative (or 0 wherever it is
    // valid, no friction at all); a radius positive in none is never a disc's.
    for (field, value, text, rule) in [
        ("mu", &mu, &input.mu, "friction coefficient must be >= 0"),
        ("radius", &radius, &input.radius, "must be > 0"),
    ] {
        if let Some(value) = value
            && value.as_constant().is_none()
            && !scene.sign_somewhere(value, Ordering::Greater)
        {
            return Err(Error::out_of_range(
                field,
                format!(
                    "{rule}, but {field} = {} is <= 0 in every sample scene of the free symbols",
                    crate::echo::echo(text.as_deref().unwrap_or_default())
                ),
            ));
        }
    }
    let disc = match (radius, spin) {
        (Some(radius), spin) => Some(Disc {
            radius,
            spin: or_zero(spin),
        }),
        (None, Some(_)) => return Err(spin_without_disc()),
        (None, None) => None,
    };
    if let Support::Pivot(_) = scene.params.support {
        for (field, x) in [("rod-v", &rod_v), ("rod-vt", &rod_vt)] {
            if x.as_ref().is_some_and(|x| !x.is_zero()) {
                return Err(Error::new(
                    field,
                    ErrorKind::Conflict(
                        "a pivoted rod's centre moves only by turning about the pivot; give --rod-omega only".into(),
                    ),
                ));
            }
        }
    }
    let o = ObliqueParams {
        v0t: or_zero(v0t),
        mu: or_zero(mu),
        disc,
        rod_before: RodMotion {
            v: or_zero(rod_v),
            vt: or_zero(rod_vt),
            omega: or_zero(rod_omega),
        },
    };
    let approach = normal_params(&scene.params, &o).v0;
    match approach.as_constant() {
        Some(c) if !c.is_positive() => return Err(no_approach(&format!("is {c}, not > 0"))),
        None if !scene.sign_somewhere(&approach, Ordering::Greater) => {
            return Err(no_approach(&format!(
                "= {approach}, is > 0 in no sample scene of the free symbols"
            )));
        }
        _ => {}
    }
    Ok(Some(o))
}

/// Whether `f` mentions an oblique symbol (they belong in the oblique flags only).
pub(super) fn mentions_oblique(f: &RatFn) -> Option<&'static str> {
    OBLIQUE_SYMBOLS
        .iter()
        .copied()
        .find(|name| f.symbols().iter().any(|s| s.name() == *name))
}

/// How a frictional contact of a symbolic scene ends: one [`Ending`] when the scene decides it
/// (also without friction: the contact then keeps its slip), or one when it sticks and one when
/// it slides when the symbols leave it open.
#[derive(Debug, Clone)]
pub struct ContactEndings {
    /// The answer when the contact sticks (also the frictionless answer, and the normal
    /// problem's v, V, omega and impulse, which no ending changes).
    pub stick: ObliqueOutcome<RatFn>,
    /// The ways it ends, in that order (stick before slide).
    pub endings: Vec<Ending>,
    /// The friction that just stops the slip, mu* = |Jt_stick|/J, with friction (the slip's
    /// sign taken as [`ContactEndings::slip_taken`] says when the symbols leave it open).
    pub mu_star: Option<RatFn>,
    /// `u_t = ..., taken > 0 ...` when the slip's sign is open and was taken (a default to say).
    pub slip_taken: Option<String>,
}

/// One way a frictional contact ends.
#[derive(Debug, Clone)]
pub struct Ending {
    /// `stick` or `slide`.
    pub contact: &'static str,
    /// When it is the answer, as `mu >= mu_star` or `mu < mu_star`; `None` when the scene
    /// decides the contact.
    pub condition: Option<String>,
    /// The impact's answer ending this way.
    pub outcome: ObliqueOutcome<RatFn>,
}

/// The endings of the contact of `scene` with its oblique part `o`: decided by the symbols
/// where they can (no slip, no friction, Coulomb's law decided in every scene, or mu - mu* a
/// number), else both, each with its condition.
///
/// # Examples
/// The M = m rod struck at its end by a puck sliding at v0t, mu free: it sticks when
/// mu >= mu* = 5 v0t/(4 v0), and slides otherwise.
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{expr::Budget, symbolic::{GivenScene, SymbolicScene, contact_endings, oblique_params}}};
/// let input = SceneInput { rod_mass: Some("m".into()), a: Some("l".into()), v0t: Some("v0t".into()), mu: Some("mu".into()), ..Default::default() };
/// let mut budget = Budget::run();
/// let scene = SymbolicScene::build(&GivenScene::read(&input, &mut budget)?)?;
/// let o = oblique_params(&scene, &input, &mut budget)?.unwrap();
/// let endings = contact_endings(&scene, &o);
/// assert_eq!(endings.mu_star.unwrap().to_string(), "5/4*v0t/v0");
/// let cases: Vec<_> = endings.endings.iter().map(|e| (e.contact, e.condition.clone().unwrap())).collect();
/// assert_eq!(cases, [("stick", "mu >= mu_star".to_string()), ("slide", "mu < mu_star".to_string())]);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn contact_endings(scene: &SymbolicScene, o: &ObliqueParams<RatFn>) -> ContactEndings {
    let p = &scene.params;
    let normal = linear::solve(&normal_params(p, o))
        .expect("the impulse equations of a valid scene are nonsingular")
        .after;
    let with = |given: Option<Mode>| oblique::complete(p, o, normal.clone(), given);
    let stick = with(Some(Mode::Stick)).expect("a valid scene's masses are positive");
    let decided = |contact: &'static str, outcome: ObliqueOutcome<RatFn>| Ending {
        contact,
        condition: None,
        outcome,
    };
    if o.mu.is_zero() {
        return ContactEndings {
            endings: vec![decided("slide", stick.clone())],
            stick,
            mu_star: None,
            slip_taken: None,
        };
    }
    // mu* = |u_t|/(J k_t) = |stick impulse|/J. A slip of open sign is taken with the sign it
    // has in some valid sample scene (> 0 when it has both): the other sign mirrors mu* and
    // the sliding answers; the sticking ones hold for either.
    let slip = o.slip(&p.support);
    let (forward, slip_taken) = match slip.sign() {
        Some(sign) => (sign != Ordering::Less, None),
        None => {
            let forward = scene.sign_somewhere(&slip, Ordering::Greater)
                || !scene.sign_somewhere(&slip, Ordering::Less);
            let (taken, other) = if forward { (">", "<") } else { ("<", ">") };
            let note = format!(
                "the slip before the impact, u_t = {slip}, taken {taken} 0 (for u_t {other} 0: mu_star is minus the formula below, and the slide formulas hold with -mu for mu)"
            );
            (forward, Some(note))
        }
    };
    let speed = if forward {
        stick.stick_impulse.clone()
    } else {
        -stick.stick_impulse.clone()
    };
    let mu_star = speed / &stick.impulse;
    let done = |endings| ContactEndings {
        endings,
        stick: stick.clone(),
        mu_star: Some(mu_star.clone()),
        slip_taken: slip_taken.clone(),
    };
    if slip.is_zero() {
        // No slip before the impact: nothing to stop, the contact holds (Jt = 0).
        return done(vec![decided("stick", stick.clone())]);
    }
    if let Ok(out) = with(None) {
        let contact = out.contact.map_or("stick", Mode::kind);
        return done(vec![decided(contact, out)]);
    }
    let slide = with(Some(Mode::Slide { forward })).expect("a valid scene's masses are positive");
    // The symbols may leave the slip's course open while mu - mu* is a number (mu given, mu*
    // free of symbols): that number decides the contact.
    match (o.mu.clone() - &mu_star).as_constant() {
        Some(margin) if margin.is_negative() => done(vec![decided("slide", slide)]),
        Some(_) => done(vec![decided("stick", stick.clone())]),
        None => {
            let mu = match o.mu.as_constant() {
                Some(c) => format!("mu = {c}"),
                None => "mu".to_string(),
            };
            done(vec![
                Ending {
                    contact: "stick",
                    condition: Some(format!("{mu} >= mu_star")),
                    outcome: stick.clone(),
                },
                Ending {
                    contact: "slide",
                    condition: Some(format!("{mu} < mu_star")),
                    outcome: slide,
                },
            ])
        }
    }
}
