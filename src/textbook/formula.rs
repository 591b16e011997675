//! The exact answer of a scene as formulas (`rodimpact formula`): v, V, omega, the impulse, the
//! energy lost, a*^2 and omega_max, as rational functions of the scene's free symbols, computed
//! by the same symbolic scene as `check` ([`SymbolicScene`]) and the same generic solver as the
//! numbers.
//!
//! omega_max needs no square root of a rational function beyond a*'s: omega(a) has the form
//! `(1 + e) v0 m a/(J + m a^2)` (J the moment of inertia about the centre or the pivot, a the
//! lever arm), largest at `a*^2 = J/m` (free rod: `I (M + m)/(m M)`) with the value
//! `(1 + e) v0/(2 a*)`, when a* lies on the rod; at the end otherwise.

use super::expr::{Budget, Radical};
use super::symbolic::{GivenScene, SymbolicScene};
use crate::error::Error;
use crate::field::poly::Monomial;
use crate::field::{Field, Poly, RatFn, TrySqrt};
use crate::optimum::a_star_squared;
use crate::scene::{Params, SceneInput, Support};
use crate::solve::linear::solve;
use num_traits::{One, Signed, Zero};

/// One formula of the answer.
#[derive(Debug, Clone, PartialEq)]
pub struct AnswerFormula {
    /// The JSON key: `v`, `V`, `omega`, `impulse`, `energy_lost`, `pivot_impulse`,
    /// `a_star_squared`, `omega_max`.
    pub key: &'static str,
    /// The value, `coeff * sqrt(radicand)` (radicand 1 for a rational function).
    pub value: Radical,
    /// When the formula holds (omega_max's case split), if it does not hold everywhere.
    pub condition: Option<String>,
}

/// The formulas of one scene, with its free symbols and the defaults applied.
#[derive(Debug, Clone, PartialEq)]
pub struct Formulas {
    /// The free symbols, in the order m, M, l, a, v0, e, p, I, r.
    pub free: Vec<String>,
    /// The defaults applied to quantities not given (`e = 1 (elastic)`, `uniform rod ...`).
    pub defaults: Vec<String>,
    /// The formulas, in the order of the keys above (those that apply to the scene only).
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
    let scene = SymbolicScene::build(&given)?;
    let p = &scene.params;
    let out = solve(p).expect("the impulse equations of a valid scene are nonsingular");
    let rational = |key, x: RatFn| AnswerFormula {
        key,
        value: Radical::rational(x),
        condition: None,
    };
    let mut list = vec![
        rational("v", out.after.v.clone()),
        rational("V", out.after.rod_v.clone()),
        rational("omega", out.after.omega.clone()),
        rational("impulse", out.impulse(p)),
    ];
    if !p.e.is_one() {
        list.push(rational("energy_lost", out.energy.lost.clone()));
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
    })
}

/// omega_max: `(1 + e) v0/(2 a*)` where a* lies on the rod, with the condition; omega at the
/// end (a = l, or the end farther from the pivot) stated for the other case.
fn omega_max(p: &Params<RatFn>, omega: &RatFn, squared: &RatFn) -> AnswerFormula {
    let two = RatFn::from_i64(2);
    let coeff = (RatFn::one() + &p.e) * &p.v0 / two;
    let inverse = RatFn::one() / squared.clone();
    let value = match square_root(&inverse) {
        Some(root) => Radical::rational(coeff * &root),
        None => Radical {
            coeff,
            radicand: inverse,
        },
    };
    let at_end = end_omega(p, omega);
    let otherwise = match &at_end {
        Some(w) => format!("otherwise omega_max = omega(end) = {w}"),
        None => "otherwise omega is largest at the end of the rod".to_string(),
    };
    let condition = match &p.support {
        Support::Free => match on_rod(squared, &p.half_length) {
            OnRod::Always => None,
            OnRod::Never => Some(format!(
                "never: a* lies beyond the end for every value of the symbols; {otherwise}"
            )),
            OnRod::When(c) => Some(format!("when {c} (a* on the rod); {otherwise}")),
        },
        Support::Pivot(_) => Some(format!(
            "when a* (measured from the pivot) reaches no farther than the end of the rod; {otherwise}"
        )),
    };
    AnswerFormula {
        key: "omega_max",
        value,
        condition,
    }
}

/// The square root of a quotient of two monomials whose exponents are even and whose
/// coefficient is a rational square (`1/l^2` -> `1/l`; the symbols are positive quantities);
/// `None` otherwise.
fn square_root(f: &RatFn) -> Option<RatFn> {
    let root = |p: &Poly| -> Option<Poly> {
        let mut terms = p.terms();
        let (monomial, c) = terms.next()?;
        if terms.next().is_some() {
            return None;
        }
        let mut half = Monomial::one();
        for &(sym, e) in monomial.factors() {
            if e % 2 != 0 {
                return None;
            }
            half = half.mul(&Monomial::var(sym, e / 2));
        }
        Some(Poly::monomial(c.try_sqrt()?, half))
    };
    RatFn::new(root(f.num())?, root(f.den())?)
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
    /// When the condition (written `lhs <= rhs`) holds.
    When(String),
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
        return OnRod::When(format!("{excess} <= 0"));
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
        OnRod::When(format!("{lhs} <= {rhs}"))
    }
}
