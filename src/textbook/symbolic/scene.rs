//! A scene in free symbols: given fields are numbers or formulas, the rest symbols, with the
//! defaults of `solve` for the collision law and the rod; its domain is checked on a grid of
//! sample scenes, which also serve to refute claimed formulas.

use super::given::{GivenScene, RodGiven};
use super::oblique::mentions_oblique;
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Q, RatFn, Sym};
use crate::scene::{Params, RodInertia, Support, gyration_moment};
use crate::textbook::expr::{Budget, OBLIQUE_SYMBOLS, Radical, size, size_of};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BTreeSet};

fn sym(name: &str) -> Sym {
    Sym::new(name)
}

/// The physical constraints of a scene, in the order they are checked and named.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Constraint {
    ProjectileMass,
    RodMass,
    HalfLength,
    Speed,
    Inertia,
    OnTheRod,
    Restitution,
    PivotOnTheRod,
}

const CONSTRAINTS: [Constraint; 8] = [
    Constraint::ProjectileMass,
    Constraint::RodMass,
    Constraint::HalfLength,
    Constraint::Speed,
    Constraint::Inertia,
    Constraint::OnTheRod,
    Constraint::Restitution,
    Constraint::PivotOnTheRod,
];

/// A scene in free symbols.
#[derive(Debug, Clone)]
pub struct SymbolicScene {
    /// The solver's parameters, each a rational function of the free symbols.
    pub params: Params<RatFn>,
    /// The free symbols, in the order m, M, l, a, v0, e, p, I, r.
    pub free: Vec<Sym>,
    /// The defaults applied to quantities not given.
    pub defaults: Vec<String>,
    /// The radius of gyration when the rod gives one (`rg=F`, or `l` for a dumbbell).
    gyration: Option<RatFn>,
    /// What each claim symbol stands for (m M l L a d v0 e I, r when known, p on a pivot).
    meaning: Vec<(Sym, RatFn)>,
    /// The given texts of the fields a constraint names (for messages).
    texts: BTreeMap<&'static str, (String, String)>,
}

impl SymbolicScene {
    /// Builds the symbolic scene: given fields are numbers (with units) or formulas, the rest
    /// free symbols, except e (1, elastic) and the rod (uniform) which take `solve`'s defaults.
    ///
    /// # Errors
    /// Conflicting alternatives, circular definitions, a numeric value outside the domain,
    /// `I` or `r` outside `--rod` and the claims, or formulas that leave no valid sample scene.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::{expr::Budget, symbolic::{GivenScene, SymbolicScene}}};
    /// let s = SceneInput { rod_mass: Some("4*m".into()), length: Some("L".into()), ..Default::default() };
    /// let scene = SymbolicScene::build(&GivenScene::read(&s, &mut Budget::run()).unwrap()).unwrap();
    /// let free: Vec<_> = scene.free.iter().map(|s| s.name()).collect();
    /// assert_eq!(free, ["m", "l", "a", "v0"]);
    /// assert_eq!(scene.params.rod_mass.to_string(), "4*m");
    /// assert_eq!(scene.params.e.to_string(), "1");
    /// ```
    pub fn build(given: &GivenScene) -> Result<SymbolicScene, Error> {
        let mut defs: BTreeMap<&'static str, RatFn> = BTreeMap::new();
        let mut put = |key: &'static str, v: Option<RatFn>| {
            if let Some(v) = v
                && v != RatFn::symbol(key)
            {
                defs.insert(key, v);
            }
        };
        put("m", given.get("m").cloned());
        put("M", given.get("M").cloned());
        let (l, length) = (given.get("l"), given.get("length"));
        if l.is_some() && length.is_some() {
            return Err(conflict("length", "give either --l or --length, not both"));
        }
        put(
            "l",
            l.cloned()
                .or_else(|| length.map(|x| x.clone() / RatFn::from(2))),
        );
        let (a, from_end) = (given.get("a"), given.get("from-end"));
        if a.is_some() && from_end.is_some() {
            return Err(conflict(
                "from-end",
                "give either --a or --from-end, not both",
            ));
        }
        put(
            "a",
            a.cloned()
                .or_else(|| from_end.map(|d| RatFn::symbol("l") - d)),
        );
        put("v0", given.get("v0").cloned());
        let mut defaults = Vec::new();
        let e = given.get("e").cloned().unwrap_or_else(|| {
            defaults.push("e = 1 (elastic)".to_string());
            RatFn::one()
        });
        put("e", Some(e));
        let pivot = given.get("pivot").cloned();
        let has_pivot = pivot.is_some();
        put("p", pivot);
        for (key, v) in &defs {
            if let Some(name) = mentions_oblique(v) {
                return Err(Error::new(
                    *key,
                    ErrorKind::Invalid(format!(
                        "{name} may appear only in the oblique flags (--v0t, --mu, --radius, --spin, --rod-v, --rod-vt, --rod-omega)"
                    )),
                ));
            }
            // The impact point and the pivot may be placed by the rod's own lengths (`--a r`:
            // struck at the radius of gyration); every other flag defines what the rod uses.
            let placed_on_rod = ["a", "p"].contains(key);
            if let Some(s) = v
                .symbols()
                .iter()
                .find(|s| ["I", "r"].contains(&s.name()) && !placed_on_rod)
            {
                return Err(Error::new(
                    *key,
                    ErrorKind::Invalid(format!(
                        "{} may appear only in --rod, --a, --from-end, --pivot and in claims",
                        s.name()
                    )),
                ));
            }
        }
        let mut defs = resolve(defs)?;
        let mut names = vec!["m", "M", "l", "a", "v0", "e"];
        if has_pivot {
            names.push("p");
        }
        let value = |n: &str| defs.get(n).cloned().unwrap_or_else(|| RatFn::symbol(n));
        for (name, v) in &defs {
            if v.symbols().contains(&sym("p")) && !has_pivot {
                return Err(Error::new(
                    *name,
                    ErrorKind::Invalid("p is used but the rod has no pivot (--pivot)".into()),
                ));
            }
            check_constant(name, v)?;
        }
        let substitute = |f: &RatFn| {
            let subs: Vec<(Sym, RatFn)> = defs.iter().map(|(k, v)| (sym(k), v.clone())).collect();
            f.subs_all(&subs)
                .ok_or_else(|| Error::new("rod", ErrorKind::DivisionByZero))
        };
        let (big_m, half) = (value("M"), value("l"));
        let (inertia, gyration) = match &given.rod {
            RodGiven::Default | RodGiven::Named(RodInertia::Uniform) => {
                if matches!(given.rod, RodGiven::Default) {
                    defaults.push("uniform rod (I = M l^2/3)".to_string());
                }
                (RodInertia::Uniform.moment(&big_m, &half), None)
            }
            RodGiven::Named(rod) => (rod.moment(&big_m, &half), Some(half.clone())),
            RodGiven::Gyration(r) => {
                let r = substitute(r)?;
                (gyration_moment(&big_m, &r), Some(r))
            }
            RodGiven::Moment(i) => (substitute(i)?, None),
        };
        for (key, field) in [("a", "a"), ("p", "pivot")] {
            if let Some(placed) = defs.get(key) {
                let placed = on_the_rod(field, placed, &inertia, gyration.as_ref())?;
                defs.insert(key, placed);
            }
        }
        let value = |n: &str| defs.get(n).cloned().unwrap_or_else(|| RatFn::symbol(n));
        let a = value("a");
        let mentioned: BTreeSet<Sym> = names
            .iter()
            .flat_map(|n| value(n).symbols())
            .chain(inertia.symbols())
            .collect();
        let free: Vec<Sym> = ["m", "M", "l", "a", "v0", "e", "p", "I", "r"]
            .iter()
            .map(|n| sym(n))
            .filter(|s| mentioned.contains(s))
            .collect();
        let d = match a.as_constant() {
            Some(c) => half.clone() - &RatFn::from_rational(&c.abs()),
            None => half.clone() - &a,
        };
        let mut meaning: Vec<(Sym, RatFn)> = names.iter().map(|n| (sym(n), value(n))).collect();
        meaning.push((sym("L"), RatFn::from(2) * &half));
        meaning.push((sym("d"), d));
        meaning.push((sym("I"), inertia.clone()));
        if let Some(r) = &gyration {
            meaning.push((sym("r"), r.clone()));
        }
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
        // The field a constraint names: the flag given (`length` for l, `from-end` for a).
        let mut texts = BTreeMap::new();
        for (key, keys) in [
            ("m", &["m"][..]),
            ("M", &["M"]),
            ("l", &["l", "length"]),
            ("v0", &["v0"]),
            ("a", &["a", "from-end"]),
            ("e", &["e"]),
            ("pivot", &["pivot"]),
        ] {
            if let Some(named) = keys
                .iter()
                .find_map(|k| given.text(k).map(|t| (k.to_string(), t.to_string())))
            {
                texts.insert(key, named);
            }
        }
        let scene = SymbolicScene {
            params,
            free,
            defaults,
            gyration: if matches!(given.rod, RodGiven::Gyration(_)) {
                gyration
            } else {
                None
            },
            meaning,
            texts,
        };
        scene.check_domain()?;
        Ok(scene)
    }

    /// A claimed formula in the scene's free symbols: every symbol the claim uses is replaced
    /// by what it stands for in this scene (work charged to `budget`).
    ///
    /// # Errors
    /// `p` on a free rod, `r` where the rod gives no rational radius of gyration, a
    /// denominator that vanishes in this scene, or an exhausted budget.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::{expr::{parse, Budget}, symbolic::{GivenScene, SymbolicScene}}};
    /// let s = SceneInput { length: Some("L".into()), a: Some("L/4".into()), ..Default::default() };
    /// let mut budget = Budget::run();
    /// let scene = SymbolicScene::build(&GivenScene::read(&s, &mut budget).unwrap()).unwrap();
    /// let d = scene.resolve("claim", &parse("x", "d").unwrap(), &mut budget).unwrap();
    /// assert_eq!(d.to_string(), "1/2*l");
    /// let i = scene.resolve("claim", &parse("x", "I").unwrap(), &mut budget).unwrap();
    /// assert_eq!(i.to_string(), "1/3*M*l^2");
    /// ```
    pub fn resolve(
        &self,
        field: &str,
        claim: &Radical,
        budget: &mut Budget,
    ) -> Result<Radical, Error> {
        if let Some(name) = OBLIQUE_SYMBOLS.iter().find(|n| claim.mentions(sym(n))) {
            return Err(Error::new(
                field,
                ErrorKind::Invalid(format!(
                    "{name} is a symbol of an oblique scene: check an oblique scene with numbers, or see its formulas with `rodimpact formula`"
                )),
            ));
        }
        self.substitute(field, claim, budget)
    }

    /// `formula` in the scene's free symbols: every scene symbol it uses replaced by what it
    /// stands for (an oblique symbol stays itself); work charged to `budget`.
    ///
    /// # Errors
    /// As [`SymbolicScene::resolve`], except for the oblique symbols.
    pub(crate) fn substitute(
        &self,
        field: &str,
        claim: &Radical,
        budget: &mut Budget,
    ) -> Result<Radical, Error> {
        if claim.mentions(sym("p")) && !self.meaning.iter().any(|(s, _)| s.name() == "p") {
            return Err(Error::new(
                field,
                ErrorKind::Invalid("p is used but the rod has no pivot (--pivot)".into()),
            ));
        }
        if claim.mentions(sym("r")) && !self.meaning.iter().any(|(s, _)| s.name() == "r") {
            return Err(Error::new(
                field,
                ErrorKind::Invalid(
                    "r is used but this rod's radius of gyration is not a rational function (a uniform rod has r = l/sqrt(3)): write it with l, or give --rod rg=r".into(),
                ),
            ));
        }
        // Only the symbols the claim uses and that stand for something else.
        let subs: Vec<(Sym, RatFn)> = self
            .meaning
            .iter()
            .filter(|(s, v)| claim.mentions(*s) && *v != RatFn::symbol(s.name()))
            .cloned()
            .collect();
        if subs.is_empty() {
            return Ok(claim.clone());
        }
        let cost = subs
            .iter()
            .map(|(_, v)| size_of(v))
            .sum::<u64>()
            .saturating_mul(size(claim));
        budget.charge(field, cost)?;
        claim
            .map(|f| f.subs_all(&subs))
            .ok_or_else(|| Error::new(field, ErrorKind::DivisionByZero))
    }

    /// The grid of sample points of the free symbols and the `extra` ones, which vary fastest
    /// (at most `limit` points), valid or not.
    fn grid(&self, extra: &[Sym], limit: usize) -> impl Iterator<Item = BTreeMap<Sym, Q>> + '_ {
        let lists: Vec<(Sym, Vec<Q>)> = extra
            .iter()
            .chain(&self.free)
            .map(|s| (*s, candidates(s.name())))
            .collect();
        (0..limit).map_while(move |k| {
            let mut rest = k;
            let mut point = BTreeMap::new();
            for (s, list) in &lists {
                point.insert(*s, list[rest % list.len()].clone());
                rest /= list.len();
            }
            (k == 0 || rest == 0).then_some(point)
        })
    }

    /// The valid sample scenes (at most `limit` points of the free symbols' sample grid where
    /// every constraint holds), with the `extra` symbols (the oblique ones) sampled too.
    pub(super) fn samples_with(
        &self,
        extra: &[Sym],
        limit: usize,
    ) -> impl Iterator<Item = BTreeMap<Sym, Q>> + '_ {
        self.grid(extra, limit).filter(|point| {
            self.constraints_at(point)
                .is_some_and(|ok| ok.iter().all(|&b| b))
        })
    }

    /// Whether `f`, in the free symbols and the oblique ones, has the sign `sign` in some valid
    /// sample scene (the oblique symbols from their own sample lists: `mu` and `rd` not
    /// negative): a sign assumed for `f` is then not a contradiction.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{field::RatFn, scene::SceneInput, textbook::{expr::Budget, symbolic::{GivenScene, SymbolicScene}}};
    /// use std::cmp::Ordering;
    /// let scene = SymbolicScene::build(&GivenScene::read(&SceneInput::default(), &mut Budget::run())?)?;
    /// let minus_v0 = -RatFn::symbol("v0");
    /// assert!(scene.sign_somewhere(&minus_v0, Ordering::Less));
    /// assert!(!scene.sign_somewhere(&minus_v0, Ordering::Greater)); // v0 > 0
    /// let v0t = RatFn::symbol("v0t");
    /// assert!(scene.sign_somewhere(&v0t, Ordering::Greater) && scene.sign_somewhere(&v0t, Ordering::Less));
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn sign_somewhere(&self, f: &RatFn, sign: Ordering) -> bool {
        let extra: Vec<Sym> = OBLIQUE_SYMBOLS
            .iter()
            .map(|n| sym(n))
            .filter(|s| f.symbols().contains(s))
            .collect();
        self.samples_with(&extra, SAMPLES).any(|point| {
            f.eval::<Q>(&|s| point.get(&s).cloned())
                .is_some_and(|x| x.cmp(&Q::zero()) == sign)
        })
    }

    /// Which constraints hold at a point (in [`CONSTRAINTS`] order); `None` where a value is
    /// undefined (a vanishing denominator).
    fn constraints_at(&self, point: &BTreeMap<Sym, Q>) -> Option<[bool; 8]> {
        let at = |f: &RatFn| f.eval::<Q>(&|s| point.get(&s).cloned());
        let p = &self.params;
        let (m, big_m, l, v0) = (at(&p.m)?, at(&p.rod_mass)?, at(&p.half_length)?, at(&p.v0)?);
        let (inertia, a, e) = (at(&p.inertia)?, at(&p.a)?, at(&p.e)?);
        let inertia_ok = match &self.gyration {
            Some(r) => {
                let r = at(r)?;
                r.is_positive() && r <= l
            }
            None => inertia.is_positive() && inertia <= &big_m * &l * &l,
        };
        let pivot_ok = match &p.support {
            Support::Free => true,
            Support::Pivot(pv) => at(pv)?.abs() <= l,
        };
        Some([
            m.is_positive(),
            big_m.is_positive(),
            l.is_positive(),
            v0.is_positive(),
            inertia_ok,
            a.abs() <= l,
            !e.is_negative() && e <= Q::one(),
            pivot_ok,
        ])
    }

    /// Refuses a scene with no valid sample point, naming the first constraint that fails at
    /// every point (or the scene, when each holds somewhere but never all together).
    fn check_domain(&self) -> Result<(), Error> {
        let mut ever = [false; 8];
        for point in self.grid(&[], SAMPLES) {
            let Some(ok) = self.constraints_at(&point) else {
                continue;
            };
            if ok.iter().all(|&b| b) {
                return Ok(());
            }
            for (seen, holds) in ever.iter_mut().zip(ok) {
                *seen |= holds;
            }
        }
        let failing = CONSTRAINTS
            .iter()
            .zip(ever)
            .find(|(_, seen)| !seen)
            .map(|(c, _)| *c);
        Err(match failing {
            Some(c) => self.domain_error(c),
            None => Error::out_of_range(
                "scene",
                "no sample scene satisfies every constraint at once (m, M, l, v0 > 0, 0 < I <= M l^2, |a| <= l, 0 <= e <= 1, |p| <= l)",
            ),
        })
    }

    fn domain_error(&self, c: Constraint) -> Error {
        let (key, rule, failure) = match c {
            Constraint::ProjectileMass => ("m", "must be > 0", "is <= 0"),
            Constraint::RodMass => ("M", "must be > 0", "is <= 0"),
            Constraint::HalfLength => ("l", "must be > 0", "is <= 0"),
            Constraint::Speed => ("v0", "must be > 0", "is <= 0"),
            Constraint::Inertia => {
                let rule = if self.gyration.is_some() {
                    "the radius of gyration must satisfy 0 < r_G <= l"
                } else {
                    "the moment of inertia must satisfy 0 < I <= M l^2"
                };
                return Error::out_of_range(
                    "rod",
                    format!("{rule}, and it does in no sample scene of the free symbols"),
                );
            }
            Constraint::OnTheRod => ("a", "must lie on the rod, |a| <= l", "is off the rod"),
            Constraint::Restitution => ("e", "must lie in [0, 1]", "lies outside [0, 1]"),
            Constraint::PivotOnTheRod => {
                ("pivot", "must lie on the rod, |p| <= l", "is off the rod")
            }
        };
        match self.texts.get(key) {
            Some((field, text)) => Error::out_of_range(
                field.as_str(),
                format!(
                    "{rule}, but {field} = {text} {failure} in every sample scene of the free symbols"
                ),
            ),
            None => Error::out_of_range(
                key,
                format!("{rule}, and it holds in no sample scene of the free symbols"),
            ),
        }
    }
}

/// The most sample scenes tried, to validate a scene or to refute a claim.
pub(super) const SAMPLES: usize = 4096;

fn candidates(name: &str) -> Vec<Q> {
    let list: &[(i64, i64)] = match name {
        "m" => &[(1, 1), (2, 1), (1, 3), (5, 2)],
        "M" => &[(3, 1), (1, 1), (7, 2), (1, 5)],
        "l" => &[(1, 1), (2, 1), (3, 2)],
        "a" => &[(1, 2), (1, 3), (1, 1), (3, 4)],
        "v0" => &[(1, 1), (3, 1)],
        "e" => &[(1, 2), (1, 1), (0, 1), (1, 3)],
        "I" => &[(1, 3), (1, 7), (1, 2), (1, 10)],
        "r" => &[(1, 2), (1, 3), (1, 1), (1, 4)],
        "mu" => &[(1, 4), (1, 2), (0, 1), (1, 1)],
        "rd" => &[(1, 4), (1, 2), (1, 1), (1, 10)],
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
    let cycle = in_cycles(&defs);
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
    // Named by their flags (the pivot's symbol is p), only those on a cycle: `--v0 -v0` is
    // about v0, not the defaults beside it.
    let flag = |key: &str| if key == "p" { "pivot" } else { key }.to_string();
    let names: Vec<String> = cycle.iter().map(|k| flag(k)).collect();
    Err(conflict(
        names.first().map_or("scene", String::as_str),
        &format!("circular definitions among {}", names.join(", ")),
    ))
}

/// The defined symbols that depend on themselves, through any chain of definitions.
fn in_cycles(defs: &BTreeMap<&'static str, RatFn>) -> Vec<&'static str> {
    let uses = |key: &str| -> Vec<&'static str> {
        let symbols = defs[key].symbols();
        defs.keys()
            .copied()
            .filter(|k| symbols.iter().any(|s| s.name() == *k))
            .collect()
    };
    defs.keys()
        .copied()
        .filter(|&start| {
            let (mut seen, mut stack) = (Vec::new(), uses(start));
            while let Some(k) = stack.pop() {
                if k == start {
                    return true;
                }
                if !seen.contains(&k) {
                    seen.push(k);
                    stack.extend(uses(k));
                }
            }
            false
        })
        .collect()
}

/// A position along the rod (`a`, the pivot) written with the rod's own `I` or `r`, in the
/// scene's symbols: `r` is the rod's radius of gyration, which must be rational (given with
/// `--rod rg=...`, or the dumbbell's l), `I` its moment of inertia about the centre. A rod
/// defined through the position it places is circular.
fn on_the_rod(
    field: &str,
    placed: &RatFn,
    inertia: &RatFn,
    gyration: Option<&RatFn>,
) -> Result<RatFn, Error> {
    let uses = |f: &RatFn, name: &str| f.symbols().iter().any(|s| s.name() == name);
    let mut out = placed.clone();
    for (name, meaning) in [("r", gyration), ("I", Some(inertia))] {
        if !uses(&out, name) {
            continue;
        }
        let meaning = meaning.ok_or_else(|| {
            Error::new(
                field,
                ErrorKind::Invalid(
                    "r stands for the rod's radius of gyration, which is not rational for this rod (uniform: l/sqrt(3)); give it with --rod rg=...".into(),
                ),
            )
        })?;
        if *meaning == RatFn::symbol(name) {
            // The rod's own free symbol (`--rod rg=r`): r stays r.
            continue;
        }
        if uses(meaning, "a") || uses(meaning, "p") || uses(meaning, name) {
            return Err(Error::new(
                field,
                ErrorKind::Invalid(format!(
                    "circular definitions: {field} uses {name}, which the rod defines through {field}"
                )),
            ));
        }
        out = out
            .subs(sym(name), meaning)
            .ok_or_else(|| Error::new(field, ErrorKind::DivisionByZero))?;
    }
    Ok(out)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::SceneInput;

    fn build(pairs: &[(&str, &str)]) -> Result<SymbolicScene, Error> {
        let mut s = SceneInput::default();
        for (k, v) in pairs {
            *s.slot(k).expect("a scene key") = Some(v.to_string());
        }
        SymbolicScene::build(&GivenScene::read(&s, &mut Budget::run())?)
    }

    #[test]
    fn circular_definitions_are_refused() {
        let err = build(&[("m", "2*M"), ("M", "m/2+m")])
            .unwrap_err()
            .to_string();
        assert!(err.contains("circular"), "{err}");
    }

    /// Regression (G13): `formula --v0 -v0` said `e: circular definitions among e, v0`,
    /// naming a default the user never gave. Now only the symbols on a cycle are named.
    #[test]
    fn circular_definitions_name_only_the_symbols_on_a_cycle() {
        let err = |pairs: &[(&str, &str)]| build(pairs).unwrap_err().to_string();
        assert_eq!(err(&[("v0", "-v0")]), "v0: circular definitions among v0");
        assert_eq!(
            err(&[("a", "v0/2"), ("v0", "2*v0+l")]),
            "v0: circular definitions among v0"
        );
        assert_eq!(
            err(&[("m", "2*M"), ("M", "m/2+m"), ("l", "1")]),
            "M: circular definitions among M, m"
        );
        assert_eq!(
            err(&[("pivot", "p/2"), ("a", "l/2")]),
            "pivot: circular definitions among pivot"
        );
    }

    #[test]
    fn rod_symbols_stay_out_of_the_scene_flags() {
        let err = build(&[("v0", "r")]).unwrap_err().to_string();
        assert_eq!(
            err,
            "v0: r may appear only in --rod, --a, --from-end, --pivot and in claims"
        );
        // The impact point may be the uniform rod's I-derived length, not its irrational r.
        let err = build(&[("a", "r")]).unwrap_err().to_string();
        assert!(
            err.starts_with("a: r stands for the rod's radius of gyration"),
            "{err}"
        );
        let scene = build(&[("a", "3*I/(M*l)")]).unwrap();
        assert_eq!(scene.params.a.to_string(), "l");
    }
}
