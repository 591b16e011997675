//! Symbolic scenes and claims: every scene quantity not given is a free symbol, and a claimed
//! formula is decided as an identity over the scene's domain with [`RatFn`] arithmetic; when it
//! is not one, a concrete valid scene where it fails is found by search.
//!
//! `L` stands for `2*l`; `d`, the distance of the impact from the nearer end, for `l - a`
//! (`l - |a|` when `a` is a number). A formula with `sqrt` is decided by squares, exactly, and
//! its sign at a valid sample scene (the rest of the domain is assumed to keep that sign).

use super::expr::{self, Radical};
use super::units::{Dimension, Measured};
use super::verdict::{Decision, Report, Verdict, radical_matches, rel_error};
use super::{Claim, ClaimValue, Exact, Quantity};
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, RatFn, Sym};
use crate::scene::{Params, RodInertia, Scene, SceneInput, Support};
use crate::solve::solve;
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;

/// The numeric scene fields with their names (as errors print them) and dimensions.
fn fields(input: &SceneInput) -> [(&'static str, &Option<String>, Dimension); 9] {
    [
        ("m", &input.m, Dimension::Mass),
        ("M", &input.rod_mass, Dimension::Mass),
        ("l", &input.l, Dimension::Length),
        ("length", &input.length, Dimension::Length),
        ("a", &input.a, Dimension::Length),
        ("from-end", &input.from_end, Dimension::Length),
        ("v0", &input.v0, Dimension::Speed),
        ("e", &input.e, Dimension::Pure),
        ("pivot", &input.pivot, Dimension::Length),
    ]
}

/// Whether some scene field is a formula rather than a number with a unit.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::symbolic::any_symbolic};
/// let s = SceneInput { rod_mass: Some("4*m".into()), ..Default::default() };
/// assert!(any_symbolic(&s));
/// ```
pub fn any_symbolic(input: &SceneInput) -> bool {
    fields(input).iter().any(|(name, text, dim)| {
        text.as_deref().is_some_and(|t| {
            Measured::parse(name, t, *dim).is_err() && expr::parse(name, t).is_ok()
        })
    })
}

/// The scene with every unit converted to exact SI numbers (for [`SceneInput::build`]).
///
/// # Errors
/// A number or unit that does not parse, naming the field.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::symbolic::si_input};
/// let s = SceneInput { m: Some("100 g".into()), v0: Some("36 km/h".into()), ..Default::default() };
/// let si = si_input(&s).unwrap();
/// assert_eq!((si.m.unwrap(), si.v0.unwrap()), ("1/10".to_string(), "10".to_string()));
/// ```
pub fn si_input(input: &SceneInput) -> Result<SceneInput, Error> {
    let convert = |name: &str, text: &Option<String>, dim| -> Result<Option<String>, Error> {
        text.as_deref()
            .map(|t| Ok(si_value(name, t, dim)?.to_string()))
            .transpose()
    };
    Ok(SceneInput {
        m: convert("m", &input.m, Dimension::Mass)?,
        rod_mass: convert("M", &input.rod_mass, Dimension::Mass)?,
        l: convert("l", &input.l, Dimension::Length)?,
        length: convert("length", &input.length, Dimension::Length)?,
        a: convert("a", &input.a, Dimension::Length)?,
        from_end: convert("from-end", &input.from_end, Dimension::Length)?,
        v0: convert("v0", &input.v0, Dimension::Speed)?,
        rod: input.rod.clone(),
        e: convert("e", &input.e, Dimension::Pure)?,
        pivot: convert("pivot", &input.pivot, Dimension::Length)?,
    })
}

fn si_value(name: &str, text: &str, dim: Dimension) -> Result<Q, Error> {
    Measured::parse(name, text, dim)?.si().ok_or_else(|| {
        Error::new(
            name,
            ErrorKind::Invalid("rpm is not a unit of a scene quantity".into()),
        )
    })
}

/// A scene in free symbols.
#[derive(Debug, Clone)]
pub struct SymbolicScene {
    /// The solver's parameters, each a rational function of the free symbols.
    pub params: Params<RatFn>,
    /// The free symbols, in the order m, M, l, a, v0, e, p.
    pub free: Vec<Sym>,
    /// What each claim symbol stands for (m M l L a d v0 e, and p on a pivot).
    meaning: Vec<(Sym, RatFn)>,
}

fn sym(name: &str) -> Sym {
    Sym::new(name)
}

fn value_of(name: &str, text: &str, dim: Dimension) -> Result<RatFn, Error> {
    if Measured::parse(name, text, dim).is_ok() {
        return Ok(RatFn::from_rational(&si_value(name, text, dim)?));
    }
    let r = expr::parse(name, text)?;
    if !r.is_rational() {
        return Err(Error::new(
            name,
            ErrorKind::Invalid("a scene quantity cannot contain a square root".into()),
        ));
    }
    // L = 2l and d = l - a in terms of the base symbols.
    let (l, a) = (RatFn::symbol("l"), RatFn::symbol("a"));
    r.coeff
        .subs_all(&[(sym("L"), RatFn::from(2) * &l), (sym("d"), l - &a)])
        .ok_or_else(|| Error::new(name, ErrorKind::DivisionByZero))
}

impl SymbolicScene {
    /// Builds the symbolic scene: given fields are numbers (with units) or formulas, the rest
    /// free symbols; `rod` is `uniform` (default), `dumbbell`, `rg=F` or `I=F`.
    ///
    /// # Errors
    /// A field that does not parse, conflicting alternatives, circular definitions, a
    /// numeric value outside the domain.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::symbolic::SymbolicScene};
    /// let s = SceneInput { rod_mass: Some("4*m".into()), length: Some("L".into()), ..Default::default() };
    /// let scene = SymbolicScene::build(&s).unwrap();
    /// let free: Vec<_> = scene.free.iter().map(|s| s.name()).collect();
    /// assert_eq!(free, ["m", "l", "a", "v0", "e"]);
    /// assert_eq!(scene.params.rod_mass.to_string(), "4*m");
    /// ```
    pub fn build(input: &SceneInput) -> Result<SymbolicScene, Error> {
        let given = |name: &str, text: &Option<String>, dim| {
            text.as_deref().map(|t| value_of(name, t, dim)).transpose()
        };
        let mut defs: BTreeMap<&'static str, RatFn> = BTreeMap::new();
        let mut put = |key: &'static str, v: Option<RatFn>| {
            if let Some(v) = v
                && v != RatFn::symbol(key)
            {
                defs.insert(key, v);
            }
        };
        put("m", given("m", &input.m, Dimension::Mass)?);
        put("M", given("M", &input.rod_mass, Dimension::Mass)?);
        let l = given("l", &input.l, Dimension::Length)?;
        let length = given("length", &input.length, Dimension::Length)?;
        if l.is_some() && length.is_some() {
            return Err(conflict("length", "give either --l or --length, not both"));
        }
        put("l", l.or(length.map(|x| x / RatFn::from(2))));
        let a = given("a", &input.a, Dimension::Length)?;
        let from_end = given("from-end", &input.from_end, Dimension::Length)?;
        if a.is_some() && from_end.is_some() {
            return Err(conflict(
                "from-end",
                "give either --a or --from-end, not both",
            ));
        }
        put("a", a.or(from_end.map(|d| RatFn::symbol("l") - &d)));
        put("v0", given("v0", &input.v0, Dimension::Speed)?);
        put("e", given("e", &input.e, Dimension::Pure)?);
        let pivot = given("pivot", &input.pivot, Dimension::Length)?;
        let has_pivot = pivot.is_some();
        put("p", pivot);
        let defs = resolve(defs)?;
        let mut names = vec!["m", "M", "l", "a", "v0", "e"];
        if has_pivot {
            names.push("p");
        }
        let value = |n: &str| defs.get(n).cloned().unwrap_or_else(|| RatFn::symbol(n));
        for (name, v) in &defs {
            if !names.contains(name) {
                return Err(Error::new(
                    "pivot",
                    ErrorKind::Invalid("p is used but the rod has no pivot".into()),
                ));
            }
            if v.symbols().contains(&sym("p")) && !has_pivot {
                return Err(Error::new(
                    *name,
                    ErrorKind::Invalid("p is used but the rod has no pivot (--pivot)".into()),
                ));
            }
            check_constant(name, v)?;
        }
        let (big_m, half) = (value("M"), value("l"));
        let inertia = match input.rod.as_deref().map(str::trim) {
            None | Some("uniform") => big_m.clone() * &half * &half / RatFn::from(3),
            Some("dumbbell") => big_m.clone() * &half * &half,
            Some(other) => {
                let substitute = |f: RatFn| {
                    f.subs_all(
                        &defs
                            .iter()
                            .map(|(k, v)| (sym(k), v.clone()))
                            .collect::<Vec<_>>(),
                    )
                    .ok_or_else(|| Error::new("rod", ErrorKind::DivisionByZero))
                };
                if let Some(r) = other.strip_prefix("rg=") {
                    let r = substitute(value_of("rod", r, Dimension::Length)?)?;
                    big_m.clone() * &r * &r
                } else if let Some(i) = other.strip_prefix("I=") {
                    substitute(value_of("rod", i, Dimension::Pure)?)?
                } else {
                    return Err(RodInertia::parse(other).err().unwrap_or_else(|| {
                        Error::new("rod", ErrorKind::Invalid("unknown rod".into()))
                    }));
                }
            }
        };
        let a = value("a");
        let mut free: Vec<Sym> = Vec::new();
        let mentioned = names
            .iter()
            .flat_map(|n| value(n).symbols())
            .chain(inertia.symbols())
            .collect::<std::collections::BTreeSet<_>>();
        for n in &names {
            if mentioned.contains(&sym(n)) {
                free.push(sym(n));
            }
        }
        let d = match a.as_constant() {
            Some(c) => half.clone() - &RatFn::from_rational(&c.abs()),
            None => half.clone() - &a,
        };
        let mut meaning: Vec<(Sym, RatFn)> = names.iter().map(|n| (sym(n), value(n))).collect();
        meaning.push((sym("L"), RatFn::from(2) * &half));
        meaning.push((sym("d"), d));
        let params = Params {
            m: value("m"),
            rod_mass: big_m,
            half_length: half,
            inertia,
            a,
            v0: value("v0"),
            e: value("e"),
            support: if has_pivot {
                Support::Pivot(value("p"))
            } else {
                Support::Free
            },
        };
        Ok(SymbolicScene {
            params,
            free,
            meaning,
        })
    }

    /// A claimed formula in the scene's free symbols.
    ///
    /// # Errors
    /// `p` on a free rod, or a denominator that vanishes in this scene.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::{expr::parse, symbolic::SymbolicScene}};
    /// let s = SceneInput { length: Some("L".into()), a: Some("L/4".into()), ..Default::default() };
    /// let scene = SymbolicScene::build(&s).unwrap();
    /// assert_eq!(scene.resolve("claim", &parse("x", "d").unwrap()).unwrap().to_string(), "1/2*l");
    /// ```
    pub fn resolve(&self, field: &str, claim: &Radical) -> Result<Radical, Error> {
        if claim.mentions(sym("p")) && !self.meaning.iter().any(|(s, _)| s.name() == "p") {
            return Err(Error::new(
                field,
                ErrorKind::Invalid("p is used but the rod has no pivot (--pivot)".into()),
            ));
        }
        claim
            .map(|f| f.subs_all(&self.meaning))
            .ok_or_else(|| Error::new(field, ErrorKind::DivisionByZero))
    }

    /// Deterministic sample points of the free symbols that make a valid scene (at most
    /// `limit` tried).
    fn samples(&self, limit: usize) -> impl Iterator<Item = BTreeMap<Sym, Q>> + '_ {
        let lists: Vec<(Sym, Vec<Q>)> = self
            .free
            .iter()
            .map(|s| (*s, candidates(s.name())))
            .collect();
        (0..limit).filter_map(move |k| {
            let mut rest = k;
            let mut point = BTreeMap::new();
            for (s, list) in &lists {
                point.insert(*s, list[rest % list.len()].clone());
                rest /= list.len();
            }
            if k > 0 && rest > 0 {
                return None;
            }
            self.scene_at(&point).map(|_| point)
        })
    }

    /// The numeric scene at a point, if valid.
    fn scene_at(&self, point: &BTreeMap<Sym, Q>) -> Option<Scene> {
        let at = |f: &RatFn| f.eval::<Q>(&|s| point.get(&s).cloned());
        let p = &self.params;
        let mut b = Scene::builder(at(&p.m)?, at(&p.rod_mass)?)
            .half_length(at(&p.half_length)?)
            .a(at(&p.a)?)
            .v0(at(&p.v0)?)
            .e(at(&p.e)?)
            .rod(RodInertia::Moment(at(&p.inertia)?));
        if let Support::Pivot(pv) = &p.support {
            b = b.pivot(at(pv)?);
        }
        b.build().ok()
    }
}

fn candidates(name: &str) -> Vec<Q> {
    let list: &[(i64, i64)] = match name {
        "m" => &[(1, 1), (2, 1), (1, 3), (5, 2)],
        "M" => &[(3, 1), (1, 1), (7, 2), (1, 5)],
        "l" => &[(1, 1), (2, 1), (3, 2)],
        "a" => &[(1, 2), (1, 3), (1, 1), (3, 4)],
        "v0" => &[(1, 1), (3, 1)],
        "e" => &[(1, 2), (1, 1), (0, 1), (1, 3)],
        _ => &[(-1, 2), (0, 1), (1, 4), (-1, 1)],
    };
    list.iter()
        .map(|(n, d)| Q::new((*n).into(), (*d).into()))
        .collect()
}

fn conflict(field: &str, why: &str) -> Error {
    Error::new(field, ErrorKind::Conflict(why.into()))
}

/// Substitutes definitions into each other until none mentions a defined symbol.
fn resolve(
    mut defs: BTreeMap<&'static str, RatFn>,
) -> Result<BTreeMap<&'static str, RatFn>, Error> {
    for _ in 0..=defs.len() {
        let subs: Vec<(Sym, RatFn)> = defs.iter().map(|(k, v)| (sym(k), v.clone())).collect();
        let defined = |v: &RatFn| v.symbols().iter().any(|s| defs.contains_key(s.name()));
        if !defs.values().any(defined) {
            return Ok(defs);
        }
        let mut next = BTreeMap::new();
        for (k, v) in &defs {
            let v = v
                .subs_all(&subs)
                .ok_or_else(|| Error::new(*k, ErrorKind::DivisionByZero))?;
            next.insert(*k, v);
        }
        defs = next;
    }
    let names: Vec<&str> = defs.keys().copied().collect();
    Err(conflict(
        names.first().copied().unwrap_or("scene"),
        &format!("circular definitions among {}", names.join(", ")),
    ))
}

fn check_constant(name: &str, v: &RatFn) -> Result<(), Error> {
    let Some(c) = v.as_constant() else {
        return Ok(());
    };
    let bad = match name {
        "m" | "M" | "l" | "v0" => !c.is_positive(),
        "e" => c.is_negative() || c > Q::one(),
        _ => false,
    };
    if bad {
        Err(Error::out_of_range(
            name,
            format!("{c} is outside the domain of {name}"),
        ))
    } else {
        Ok(())
    }
}

/// Checks claims about a symbolic scene.
///
/// # Errors
/// Bad input; a printed number against a non-constant answer; `a_star`/`omega_max` (not
/// supported symbolically).
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{Claim, symbolic::check}};
/// let s = SceneInput { length: Some("L".into()), a: Some("L/2".into()), e: Some("1".into()), ..Default::default() };
/// let right = Claim::parse("omega=12*m*v0/((M+4*m)*L)").unwrap();
/// let wrong = Claim::parse("omega=6*m*v0/((M+4*m)*L)").unwrap();
/// let r = check(&s, &[right, wrong], None).unwrap();
/// assert!(r.decisions[0].agrees() && !r.decisions[1].agrees());
/// ```
pub fn check(input: &SceneInput, claims: &[Claim], sig: Option<u32>) -> Result<Report, Error> {
    let scene = SymbolicScene::build(input)?;
    let out = solve(&scene.params).ok_or_else(|| {
        Error::new(
            "scene",
            ErrorKind::Invalid("singular impulse equations".into()),
        )
    })?;
    let mut decisions = Vec::with_capacity(claims.len());
    for claim in claims {
        let field = format!("claim {}", claim.quantity.name());
        let exact = claim
            .quantity
            .motion_value(&scene.params, &out)?
            .ok_or_else(|| {
                Error::new(
                    field.as_str(),
                    ErrorKind::Invalid(
                        "a_star and omega_max are checked for numeric scenes only".into(),
                    ),
                )
            })?;
        let decision = match &claim.value {
            ClaimValue::Printed(_) => match exact.as_constant() {
                Some(x) => super::verdict::decide(claim, &Exact::Rational(x), sig),
                None => {
                    return Err(Error::new(
                        field.as_str(),
                        ErrorKind::Invalid(format!(
                            "a number cannot be checked against the formula {exact}: give every scene quantity a value"
                        )),
                    ));
                }
            },
            ClaimValue::Formula(r) => identity(claim, &scene.resolve(&field, r)?, &exact, &scene),
        };
        decisions.push(decision);
    }
    Ok(Report {
        symbolic: true,
        decisions,
    })
}

/// Decides `claim == exact` over the domain.
fn identity(claim: &Claim, c: &Radical, exact: &RatFn, scene: &SymbolicScene) -> Decision {
    let omega = claim.quantity == Quantity::Omega;
    let mut d = Decision::new(claim.quantity.name(), &claim.text, exact.to_string(), None);
    let mut squares_agree = false;
    if c.is_rational() {
        if (c.coeff.clone() - exact).is_identically_zero() {
            d.verdict = Verdict::Agrees;
            d.notes.push(identity_note(scene));
            return d;
        }
        if omega && (c.coeff.clone() + exact).is_identically_zero() {
            d.verdict = Verdict::Agrees;
            d.notes.push(identity_note(scene));
            d.notes
                .push("opposite sign: compared by magnitude (rotation conventions differ)".into());
            return d;
        }
    } else if (c.coeff.clone() * &c.coeff * &c.radicand - exact.clone() * exact)
        .is_identically_zero()
    {
        squares_agree = true;
        d.notes
            .push("the squares agree identically; the sign is taken from a sample scene".into());
    }
    // Search a valid scene where the values differ (or, for a root, fix the sign).
    for point in scene.samples(4096) {
        let at = |f: &RatFn| f.eval::<Q>(&|s| point.get(&s).cloned());
        let (Some(cc), Some(cr), Some(x)) = (at(&c.coeff), at(&c.radicand), at(exact)) else {
            continue;
        };
        if cr.is_negative() {
            continue;
        }
        let (equal, same_sign) = radical_matches(&cc, &cr, &Exact::Rational(x.clone()));
        if equal && (same_sign || omega) && squares_agree {
            d.verdict = Verdict::Agrees;
            if !same_sign {
                d.notes.push("opposite sign: compared by magnitude".into());
            }
            return d;
        }
        if !(equal && (same_sign || omega)) {
            let claimed = crate::field::QSqrt::new(Q::zero(), cc, cr);
            let values: Vec<String> = point.iter().map(|(s, v)| format!("{s}={v}")).collect();
            d.verdict = Verdict::Disagrees;
            let (lo, hi) = claimed.bounds(20);
            let mid = (lo + hi) / Q::from_integer(2.into());
            d.rel_error =
                rel_error(&mid, &x, omega).map(|e| format!("{e} (at the counterexample)"));
            d.notes.push(format!(
                "not an identity; counterexample {}: exact {} = {x}, claimed {claimed}",
                if values.is_empty() {
                    "(no free symbols)".to_string()
                } else {
                    values.join(", ")
                },
                claim.quantity.name()
            ));
            return d;
        }
    }
    d.notes
        .push("no valid sample scene separates the claim from the exact value".into());
    d
}

fn identity_note(scene: &SymbolicScene) -> String {
    let free: Vec<&str> = scene.free.iter().map(|s| s.name()).collect();
    if free.is_empty() {
        "exact: equal as numbers".into()
    } else {
        format!(
            "identity in {} (exact rational-function arithmetic)",
            free.join(", ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circular_definitions_are_refused() {
        let s = SceneInput {
            m: Some("2*M".into()),
            rod_mass: Some("m/2+m".into()),
            ..Default::default()
        };
        let err = SymbolicScene::build(&s).unwrap_err().to_string();
        assert!(err.contains("circular"), "{err}");
    }
}
