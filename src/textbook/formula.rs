//! The exact answer of a scene as formulas (`rodimpact formula`): v, V, omega, the impulse, the
//! energy lost, a*^2 and omega_max, as rational functions of the scene's free symbols, computed
//! by the same symbolic scene as `check` ([`SymbolicScene`]) and the same generic solver as the
//! numbers.
//!
//! omega_max needs no square root of a rational function beyond a*'s: omega(a) has the form
//! `(1 + e) v0 m a/(J + m a^2)` (J the moment of inertia about the centre or the pivot, a the
//! lever arm), largest at `a*^2 = J/m` (free rod: `I (M + m)/(m M)`) with the value
//! `(1 + e) v0/(2 a*)`, when a* lies on the rod; at the end otherwise.

use super::expr::OBLIQUE_SYMBOLS;
use super::expr::{Budget, Radical};
use super::symbolic::{GivenScene, SymbolicScene, contact_endings, heaviest_field, oblique_params};
use crate::error::Error;
use crate::field::{Field, Poly, RatFn};
use crate::scene::{ObliqueParams, Params, SceneInput, Support};
use crate::solve::fast::linear::solve;
use crate::solve::fast::oblique::{ObliqueOutcome, normal_params};
use crate::solve::optimum::a_star_squared;
use num_traits::{One, Signed, Zero};

/// One formula of the answer.
#[derive(Debug, Clone, PartialEq)]
pub struct AnswerFormula {
    /// The JSON key: `v`, `V`, `omega`, `impulse`, `energy_lost`, `pivot_impulse`,
    /// `a_star_squared`, `omega_max`; in an oblique scene also `vt`, `Vt`, `spin`,
    /// `tangential_impulse`, `mu_star`, `energy_lost_restitution` and `energy_lost_friction`.
    pub key: &'static str,
    /// The value, `coeff * sqrt(radicand)` (radicand 1 for a rational function).
    pub value: Radical,
    /// When the formula holds (omega_max's case split), if it does not hold everywhere.
    pub condition: Option<String>,
    /// The same case split, structured for typesetting: when the formula holds, and the value
    /// otherwise.
    pub piecewise: Option<Piecewise>,
}

/// A formula that holds under a condition, and what holds otherwise (omega_max: at a* when a*
/// lies on the rod, else at the end).
#[derive(Debug, Clone, PartialEq)]
pub struct Piecewise {
    /// When the formula holds: an inequality in the symbols, or words (`None`: never).
    pub when: Option<Condition>,
    /// The value otherwise, when it has a formula (omega at the end of a free rod).
    pub otherwise: Option<RatFn>,
}

/// A condition of a case split.
#[derive(Debug, Clone, PartialEq)]
pub enum Condition {
    /// An inequality between the symbols.
    Inequality(Inequality),
    /// A condition said in words.
    Words(&'static str),
}

/// The formulas of one scene, with its free symbols and the defaults applied.
#[derive(Debug, Clone, PartialEq)]
pub struct Formulas {
    /// The free symbols, in the order m, M, l, a, v0, e, p, I, r, then the oblique ones.
    pub free: Vec<String>,
    /// The defaults applied to quantities not given (`e = 1 (elastic)`, `uniform rod ...`), and
    /// any assumption a case split rests on.
    pub defaults: Vec<String>,
    /// The formulas, in the order of the keys above (those that apply to the scene only); for
    /// an oblique scene also `vt`, `Vt`, `spin`, `tangential_impulse` and `mu_star` when the
    /// contact is decided, or `mu_star` alone when it is split into [`Formulas::cases`]; with
    /// friction and e != 1, the loss to restitution `energy_lost_restitution` (the same in
    /// either case).
    pub formulas: Vec<AnswerFormula>,
    /// How a frictional contact ends when the scene decides it: `stick` or `slide`.
    pub contact: Option<&'static str>,
    /// A frictional contact the symbols leave open: its answer when it sticks and when it
    /// slides (empty otherwise).
    pub cases: Vec<ContactCase>,
}

/// The answer in one way a frictional contact can end.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactCase {
    /// `stick` or `slide`.
    pub contact: &'static str,
    /// When this case is the answer: `mu >= mu_star` (the slip stops) or `mu < mu_star` (it
    /// slides throughout, Jt = mu J); `mu = 1/4 >= mu_star` for a given number.
    pub condition: String,
    /// The formulas of the case: `vt`, `Vt`, `spin` (a disc), `tangential_impulse`,
    /// `energy_lost`, and its part lost to friction `energy_lost_friction` when e != 1 (with
    /// e = 1 friction takes all of it).
    pub formulas: Vec<AnswerFormula>,
}

/// The exact answer of `input` as formulas: every quantity not given is its own symbol, except
/// the collision law (e = 1) and the rod (uniform), as in `solve` and `check`.
///
/// # Errors
/// Bad or contradictory scene flags (as `check`), a scene whose formulas leave no valid scene.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::formula::formulas};
/// let f = formulas(&SceneInput { rod_mass: Some("m".into()), ..Default::default() })?;
/// let text = |key: &str| f.formulas.iter().find(|x| x.key == key).unwrap().value.to_string();
/// assert_eq!(text("omega"), "6*a*v0/(3*a^2 + 2*l^2)");
/// assert_eq!(text("a_star_squared"), "2/3*l^2");
/// assert!(f.formulas.iter().all(|x| x.key != "energy_lost")); // elastic: nothing lost
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn formulas(input: &SceneInput) -> Result<Formulas, Error> {
    let mut budget = Budget::run();
    let given = GivenScene::read(input, &mut budget)?;
    let heaviest = heaviest_field(input).unwrap_or("scene");
    budget.metered(heaviest, |budget| solved_formulas(&given, input, budget))
}

/// [`formulas`] once the scene is read, on what is left of the run's budget.
fn solved_formulas(
    given: &GivenScene,
    input: &SceneInput,
    budget: &mut Budget,
) -> Result<Formulas, Error> {
    let scene = SymbolicScene::build(given)?;
    if let Some(o) = oblique_params(&scene, input, budget)? {
        return Ok(oblique_formulas(&scene, &o));
    }
    let p = &scene.params;
    let out = solve(p).expect("the impulse equations of a valid scene are nonsingular");
    let mut list = vec![
        rational("v", out.after.v.clone()),
        rational("V", out.after.rod_v.clone()),
        rational("omega", out.after.omega.clone()),
        rational("impulse", out.impulse(p)),
    ];
    if !p.e.is_one() {
        list.push(rational("energy_lost", out.energy.lost()));
    }
    if let Some(j) = &out.pivot_impulse {
        list.push(rational("pivot_impulse", j.clone()));
    }
    let squared = a_star_squared(p);
    list.push(rational("a_star_squared", squared.clone()));
    list.push(omega_max(p, &out.after.omega, &squared));
    Ok(Formulas {
        free: scene.free.iter().map(|s| s.name().to_string()).collect(),
        defaults: scene.defaults.clone(),
        formulas: list,
        contact: None,
        cases: Vec::new(),
    })
}

fn rational(key: &'static str, x: RatFn) -> AnswerFormula {
    AnswerFormula {
        key,
        value: Radical::rational(x),
        condition: None,
        piecewise: None,
    }
}

/// The formulas of an oblique scene: the normal problem's v, V, omega, impulse (and the
/// pivot's impulse across the rod) for every contact; a* and omega_max when the rod is at rest
/// (they are the paper's: the slide along the rod and friction never change them, X27-X31);
/// then the tangential answers, decided, or split into stick and slide with the threshold
/// `mu_star = |u_t|/(J k_t)`, the friction that just stops the slip.
fn oblique_formulas(scene: &SymbolicScene, o: &ObliqueParams<RatFn>) -> Formulas {
    let p = &scene.params;
    let endings = contact_endings(scene, o);
    let stick = &endings.stick;
    let mut list = vec![
        rational("v", stick.after.v.clone()),
        rational("V", stick.after.rod.v.clone()),
        rational("omega", stick.after.rod.omega.clone()),
        rational("impulse", stick.impulse.clone()),
    ];
    if let Some((across, _)) = &stick.pivot_impulse {
        list.push(rational("pivot_impulse", across.clone()));
    }
    if o.rod_before.omega.is_zero() {
        // Drift along either axis leaves a* where it is (X31); omega_max scales with the
        // approach speed, which is the normal problem's v0.
        let normal_problem = normal_params(p, o);
        let squared = a_star_squared(&normal_problem);
        list.push(rational("a_star_squared", squared.clone()));
        list.push(omega_max(&normal_problem, &stick.after.rod.omega, &squared));
    }
    let mut defaults = scene.defaults.clone();
    let approach = normal_params(p, o).v0;
    if approach != p.v0 && approach.as_constant().is_none() {
        defaults.push(format!(
            "the approach at the contact point, u_n = {approach}, taken > 0 (no impact otherwise)"
        ));
    }
    let friction = !o.mu.is_zero();
    // The loss has two parts when both act: restitution (the normal problem's, the same
    // however the contact ends) and friction.
    let parts = friction && !p.e.is_one();
    if parts {
        list.push(rational(
            "energy_lost_restitution",
            stick.lost_restitution.clone(),
        ));
    }
    let tangential = |out: &ObliqueOutcome<RatFn>| {
        let mut part = vec![
            rational("vt", out.after.vt.clone()),
            rational("Vt", out.after.rod.vt.clone()),
        ];
        if let Some(spin) = &out.after.spin {
            part.push(rational("spin", spin.clone()));
        }
        if friction {
            part.push(rational(
                "tangential_impulse",
                out.tangential_impulse.clone(),
            ));
        }
        if friction || !p.e.is_one() {
            part.push(rational("energy_lost", out.energy.lost()));
        }
        if parts {
            part.push(rational("energy_lost_friction", out.lost_friction.clone()));
        }
        part
    };
    defaults.extend(endings.slip_taken.clone());
    if let Some(mu_star) = &endings.mu_star {
        list.push(rational("mu_star", mu_star.clone()));
    }
    let (mut contact, mut cases) = (None, Vec::new());
    match endings.endings.as_slice() {
        [one] => {
            contact = friction.then_some(one.contact);
            list.extend(tangential(&one.outcome));
        }
        both => {
            cases = both
                .iter()
                .map(|e| ContactCase {
                    contact: e.contact,
                    condition: e.condition.clone().unwrap_or_default(),
                    formulas: tangential(&e.outcome),
                })
                .collect();
        }
    }
    Formulas {
        free: free_symbols(scene, o),
        defaults,
        formulas: list,
        contact,
        cases,
    }
}

/// The scene's free symbols, then the oblique ones the formulas use.
pub(crate) fn free_symbols(scene: &SymbolicScene, o: &ObliqueParams<RatFn>) -> Vec<String> {
    let mut free: Vec<String> = scene.free.iter().map(|s| s.name().to_string()).collect();
    let used: Vec<&RatFn> = [
        &o.v0t,
        &o.mu,
        &o.rod_before.v,
        &o.rod_before.vt,
        &o.rod_before.omega,
    ]
    .into_iter()
    .chain(o.disc.iter().flat_map(|d| [&d.radius, &d.spin]))
    .collect();
    for name in OBLIQUE_SYMBOLS {
        if used
            .iter()
            .any(|f| f.symbols().iter().any(|s| s.name() == name))
        {
            free.push(name.to_string());
        }
    }
    free
}

/// omega_max: `(1 + e) v0/(2 a*)` where a* lies on the rod, with the condition; omega at the
/// end (a = l, or the end farther from the pivot) stated for the other case.
fn omega_max(p: &Params<RatFn>, omega: &RatFn, squared: &RatFn) -> AnswerFormula {
    let two = RatFn::from_i64(2);
    let coeff = (RatFn::one() + &p.e) * &p.v0 / two;
    let value = Radical::normalized(coeff, RatFn::one() / squared.clone());
    let at_end = end_omega(p, omega);
    let otherwise = match &at_end {
        Some(w) => format!("otherwise omega_max = omega(end) = {w}"),
        None => "otherwise omega is largest at the end of the rod".to_string(),
    };
    let beyond_pivot = "a* (measured from the pivot) reaches no farther than the end of the rod";
    let (condition, when) = match &p.support {
        Support::Free => match on_rod(squared, &p.half_length) {
            OnRod::Always => (None, None),
            OnRod::Never => (
                Some(format!(
                    "never: a* lies beyond the end for every value of the symbols; {otherwise}"
                )),
                Some(None),
            ),
            OnRod::When(c) => (
                Some(format!("when {c} (a* on the rod); {otherwise}")),
                Some(Some(Condition::Inequality(c))),
            ),
        },
        Support::Pivot(_) => (
            Some(format!("when {beyond_pivot}; {otherwise}")),
            Some(Some(Condition::Words(
                "a* (from the pivot) lies on the rod",
            ))),
        ),
    };
    AnswerFormula {
        key: "omega_max",
        value,
        condition,
        piecewise: when.map(|when| Piecewise {
            when,
            otherwise: at_end,
        }),
    }
}

/// omega at the end the paper strikes: a = l for a free rod (a a symbol); `None` when a is
/// given, or for a pivoted rod (the far end depends on the pivot's side).
fn end_omega(p: &Params<RatFn>, omega: &RatFn) -> Option<RatFn> {
    if p.support != Support::Free || p.a.symbols().len() != 1 {
        return None;
    }
    let a = *p.a.symbols().iter().next()?;
    (p.a == RatFn::symbol(a.name()))
        .then(|| omega.subs(a, &p.half_length))
        .flatten()
}

/// Where a* lies, from the sign of `a*^2 - l^2`.
pub(crate) enum OnRod {
    /// For every value of the symbols.
    Always,
    /// For no value of the symbols.
    Never,
    /// When the condition holds.
    When(Inequality),
}

/// `lhs <= rhs` between two polynomials in the scene's symbols, with positive coefficients
/// (`M <= 2*m`).
#[derive(Debug, Clone, PartialEq)]
pub struct Inequality {
    /// The left side.
    pub lhs: Poly,
    /// The right side.
    pub rhs: Poly,
}

impl std::fmt::Display for Inequality {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} <= {}", self.lhs, self.rhs)
    }
}

/// Whether a* (squared: `squared`) lies on a rod of half-length `l`: the sign of `a*^2 - l^2`
/// with its positive factors (a monomial denominator, powers of symbols dividing every term,
/// all positive quantities, and the content) cleared, written `lhs <= rhs`: `M <= 2*m` for the
/// uniform rod. Used by `formula` and by `check`'s a* verdicts.
pub(crate) fn on_rod(squared: &RatFn, l: &RatFn) -> OnRod {
    let excess = squared.clone() - &(l.clone() * l);
    if let Some(c) = excess.as_constant() {
        return if c.is_positive() {
            OnRod::Never
        } else {
            OnRod::Always
        };
    }
    let den = excess.den();
    let positive_den = den.terms().count() == 1 && den.terms().all(|(_, c)| c.is_positive());
    if !positive_den {
        return OnRod::When(Inequality {
            lhs: excess.num().clone() * excess.den(),
            rhs: Poly::zero(),
        });
    }
    let mut num = excess.num().clone();
    for sym in num.symbols() {
        let k = num.low_degree_in(sym);
        if k > 0 {
            num = num
                .div_exact(&Poly::var(sym).pow(k))
                .expect("every term holds sym^k");
        }
    }
    let num = num.scale(&num.content().abs().recip());
    let (mut lhs, mut rhs) = (Poly::zero(), Poly::zero());
    for (monomial, c) in num.terms() {
        let term = Poly::monomial(c.abs(), monomial.clone());
        if c.is_positive() {
            lhs = lhs + &term;
        } else {
            rhs = rhs + &term;
        }
    }
    if rhs.is_zero() {
        OnRod::Never
    } else if lhs.is_zero() {
        OnRod::Always
    } else {
        OnRod::When(Inequality { lhs, rhs })
    }
}
