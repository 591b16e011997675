//! Symbolic scenes and claims: a scene quantity not given is a free symbol, except the
//! collision law (elastic, e = 1) and the rod (uniform), which take the defaults of `solve`;
//! a claimed formula is decided as an identity over the scene's domain with [`RatFn`]
//! arithmetic and, when it is not one, refuted by a concrete valid scene found by search.
//!
//! `L` stands for `2*l`; `d`, the distance of the impact from the nearer end, for `l - a`
//! (`l - |a|` when `a` is a number); `I` for the rod's moment of inertia about its centre and
//! `r` for its radius of gyration. A formula with `sqrt` is decided by squares, exactly, and
//! its sign at a valid sample scene (the rest of the domain is assumed to keep that sign).
//!
//! A scene whose formulas leave no valid sample scene (`--a 2*l`, `--M -m`) is refused,
//! naming the field, before any claim is decided.

use super::expr::{Budget, Radical, size, size_of, words};
use super::verdict::{Counterexample, Decision, Report, SceneSummary, Verdict, radical_matches};
use super::{Claim, ClaimValue, Exact, Quantity, read_value};
use crate::error::{Error, ErrorKind};
use crate::field::{Field, Poly, Q, RatFn, Sym};
use crate::optimum::a_star_squared;
use crate::scene::{Params, RodInertia, SceneInput, Support, dimension_of};
use crate::solve::linear::solve;
use crate::units::Dimension;
use num_traits::{One, Signed};
use std::collections::{BTreeMap, BTreeSet};

/// The numeric scene inputs in the order they are read: (key, text).
fn numeric_fields(input: &SceneInput) -> [(&'static str, &Option<String>); 9] {
    [
        ("m", &input.m),
        ("M", &input.rod_mass),
        ("l", &input.l),
        ("length", &input.length),
        ("a", &input.a),
        ("from-end", &input.from_end),
        ("v0", &input.v0),
        ("e", &input.e),
        ("pivot", &input.pivot),
    ]
}

/// How the rod was given.
#[derive(Debug, Clone)]
enum RodGiven {
    /// Not given: uniform, the default.
    Default,
    /// `uniform` or `dumbbell`.
    Named(RodInertia),
    /// `rg=F`: the radius of gyration.
    Gyration(RatFn),
    /// `I=F`: the moment of inertia about the centre.
    Moment(RatFn),
}

/// A scene as given, every value read once: numbers (in SI) as constant rational functions,
/// formulas in the scene's symbols (`L` and `d` already expanded).
#[derive(Debug, Clone)]
pub struct GivenScene {
    values: Vec<(&'static str, String, RatFn)>,
    rod: RodGiven,
    formula: bool,
}

impl GivenScene {
    /// Reads every field of `input`: a number with an optional unit, or a formula (charged to
    /// `budget`).
    ///
    /// # Errors
    /// A field that is neither, naming it; a square root in a scene quantity; an unknown rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::{expr::Budget, symbolic::GivenScene}};
    /// let s = SceneInput { m: Some("100 g".into()), rod_mass: Some("4*m".into()), ..Default::default() };
    /// assert!(GivenScene::read(&s, &mut Budget::run()).unwrap().has_formula());
    /// let s = SceneInput { m: Some("100 g".into()), ..Default::default() };
    /// assert!(!GivenScene::read(&s, &mut Budget::run()).unwrap().has_formula());
    /// ```
    pub fn read(input: &SceneInput, budget: &mut Budget) -> Result<GivenScene, Error> {
        let mut values = Vec::new();
        let mut formula = false;
        for (key, text) in numeric_fields(input) {
            if let Some(text) = text {
                let (value, is_formula) = value_of(key, text, dimension_of(key), budget)?;
                formula |= is_formula;
                values.push((key, text.trim().to_string(), value));
            }
        }
        let rod = match input.rod.as_deref().map(str::trim) {
            None => RodGiven::Default,
            Some(text) => {
                let read = |body: &str, dimension, budget: &mut Budget| {
                    value_of("rod", body, dimension, budget)
                };
                if let Some(body) = text.strip_prefix("rg=") {
                    let (r, is_formula) = read(body, Dimension::Length, budget)?;
                    formula |= is_formula;
                    RodGiven::Gyration(r)
                } else if let Some(body) = text.strip_prefix("I=") {
                    let (i, is_formula) = read(body, Dimension::MomentOfInertia, budget)?;
                    formula |= is_formula;
                    RodGiven::Moment(i)
                } else {
                    RodGiven::Named(RodInertia::parse(text)?)
                }
            }
        };
        Ok(GivenScene {
            values,
            rod,
            formula,
        })
    }

    /// Whether some field is a formula rather than a number.
    pub fn has_formula(&self) -> bool {
        self.formula
    }

    fn get(&self, key: &str) -> Option<&RatFn> {
        self.values
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|(_, _, v)| v)
    }

    fn text(&self, key: &str) -> Option<&str> {
        self.values
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|(_, t, _)| t.as_str())
    }
}

fn sym(name: &str) -> Sym {
    Sym::new(name)
}

/// A field's value, and whether it was a formula; `L` and `d` are expanded to `2*l` and
/// `l - a`.
fn value_of(
    field: &str,
    text: &str,
    dimension: Dimension,
    budget: &mut Budget,
) -> Result<(RatFn, bool), Error> {
    let r = match read_value(field, text, dimension, budget)? {
        ClaimValue::Printed(m) => {
            let si = m.si().ok_or_else(|| {
                Error::new(
                    field,
                    ErrorKind::Invalid("rpm is not a unit of a scene quantity".into()),
                )
            })?;
            return Ok((RatFn::from_rational(&si), false));
        }
        ClaimValue::Formula(r) => r,
    };
    if !r.is_rational() {
        return Err(Error::new(
            field,
            ErrorKind::Invalid("a scene quantity cannot contain a square root".into()),
        ));
    }
    let (l, a) = (RatFn::symbol("l"), RatFn::symbol("a"));
    let value = r
        .coeff
        .subs_all(&[(sym("L"), RatFn::from(2) * &l), (sym("d"), l - &a)])
        .ok_or_else(|| Error::new(field, ErrorKind::DivisionByZero))?;
    Ok((value, true))
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
            if let Some(s) = v.symbols().iter().find(|s| ["I", "r"].contains(&s.name())) {
                return Err(Error::new(
                    *key,
                    ErrorKind::Invalid(format!(
                        "{} may appear only in --rod and in claims",
                        s.name()
                    )),
                ));
            }
        }
        let defs = resolve(defs)?;
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
                (big_m.clone() * &half * &half / RatFn::from(3), None)
            }
            RodGiven::Named(_) => (big_m.clone() * &half * &half, Some(half.clone())),
            RodGiven::Gyration(r) => {
                let r = substitute(r)?;
                (big_m.clone() * &r * &r, Some(r))
            }
            RodGiven::Moment(i) => (substitute(i)?, None),
        };
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

    /// The grid of sample points of the free symbols (at most `limit`), valid or not.
    fn grid(&self, limit: usize) -> impl Iterator<Item = BTreeMap<Sym, Q>> + '_ {
        let lists: Vec<(Sym, Vec<Q>)> = self
            .free
            .iter()
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

    /// Deterministic sample points that make a valid scene (at most `limit` tried).
    fn samples(&self, limit: usize) -> impl Iterator<Item = BTreeMap<Sym, Q>> + '_ {
        self.grid(limit).filter(|point| {
            self.constraints_at(point)
                .is_some_and(|ok| ok.iter().all(|&b| b))
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
        for point in self.grid(SAMPLES) {
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
const SAMPLES: usize = 4096;

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

/// The exact answer a claim is compared with, as `coeff * sqrt(radicand)`.
fn exact_value(
    quantity: Quantity,
    field: &str,
    scene: &SymbolicScene,
    out: &crate::solve::Outcome<RatFn>,
) -> Result<Radical, Error> {
    if let Some(x) = quantity.motion_value(&scene.params, out)? {
        return Ok(Radical::rational(x));
    }
    match quantity {
        Quantity::AStar => Ok(Radical {
            coeff: RatFn::one(),
            radicand: a_star_squared(&scene.params),
        }),
        _ => Err(Error::new(
            field,
            ErrorKind::Invalid(
                "omega_max is checked for numeric scenes only: it is omega(a*) when a* <= l and omega(l) otherwise, a different formula on each side; claim a_star or omega instead".into(),
            ),
        )),
    }
}

/// Checks claims about a symbolic scene; every formula's work is charged to `budget`.
///
/// # Errors
/// Bad input; `omega_max` (piecewise, not one formula); rpm against a formula; an exhausted
/// budget.
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::{Claim, expr::Budget, symbolic::{check, GivenScene}}};
/// let s = SceneInput { length: Some("L".into()), a: Some("L/2".into()), ..Default::default() };
/// let right = Claim::parse("omega=12*m*v0/((M+4*m)*L)").unwrap();
/// let wrong = Claim::parse("omega=6*m*v0/((M+4*m)*L)").unwrap();
/// let mut budget = Budget::run();
/// let given = GivenScene::read(&s, &mut budget).unwrap();
/// let r = check(&given, &[right, wrong], None, &mut budget).unwrap();
/// assert!(r.decisions[0].agrees() && !r.decisions[1].agrees());
/// assert_eq!(r.symbolic.unwrap().defaults, ["e = 1 (elastic)", "uniform rod (I = M l^2/3)"]);
/// ```
pub fn check(
    given: &GivenScene,
    claims: &[Claim],
    sig: Option<u32>,
    budget: &mut Budget,
) -> Result<Report, Error> {
    let scene = SymbolicScene::build(given)?;
    let out = solve(&scene.params).ok_or_else(|| {
        Error::new(
            "scene",
            ErrorKind::Invalid("singular impulse equations".into()),
        )
    })?;
    let mut decisions = Vec::with_capacity(claims.len());
    for claim in claims {
        let field = format!("claim {}", claim.quantity.name());
        let exact = exact_value(claim.quantity, &field, &scene, &out)?;
        let claimed = match &claim.value {
            ClaimValue::Printed(m) => {
                if let Some((c, r)) = exact.constant() {
                    decisions.push(super::verdict::decide(claim, &Exact::radical(c, r), sig));
                    continue;
                }
                let si = m.si().ok_or_else(|| {
                    Error::new(
                        field.as_str(),
                        ErrorKind::Invalid(
                            "a value in rpm cannot be compared with a formula: give it in rad/s"
                                .into(),
                        ),
                    )
                })?;
                Radical::rational(RatFn::from_rational(&si))
            }
            ClaimValue::Formula(r) => {
                let resolved = scene.resolve(&field, r, budget)?;
                if let (Some(_), Some((c, r))) = (resolved.constant(), exact.constant()) {
                    let numeric = Claim {
                        value: ClaimValue::Formula(resolved),
                        ..claim.clone()
                    };
                    decisions.push(super::verdict::decide(&numeric, &Exact::radical(c, r), sig));
                    continue;
                }
                resolved
            }
        };
        let mut decision = identity(claim, &claimed, &exact, &scene, budget, &field)?;
        if matches!(claim.value, ClaimValue::Printed(_)) {
            decision.notes.insert(
                0,
                "a number against a formula: decided as an identity in the free symbols".into(),
            );
        }
        decisions.push(decision);
    }
    Ok(Report {
        symbolic: Some(SceneSummary {
            free: scene.free.iter().map(|s| s.name().to_string()).collect(),
            defaults: scene.defaults.clone(),
        }),
        decisions,
    })
}

/// Decides `claim == exact` over the domain, both `coeff * sqrt(radicand)`.
fn identity(
    claim: &Claim,
    c: &Radical,
    exact: &Radical,
    scene: &SymbolicScene,
    budget: &mut Budget,
    field: &str,
) -> Result<Decision, Error> {
    let omega = claim.quantity == Quantity::Omega;
    let mut d = Decision::new(claim.quantity.name(), &claim.text, exact.to_string(), None);
    let mut squares_agree = false;
    if c.is_rational() && exact.is_rational() {
        let (claimed, value) = (Fraction::of(&c.coeff), Fraction::of(&exact.coeff));
        if claimed.equals(&value, false, budget, field)? {
            d.verdict = Verdict::Agrees;
            d.notes.push(identity_note(scene));
            return Ok(d);
        }
        if omega && claimed.equals(&value, true, budget, field)? {
            d.verdict = Verdict::Agrees;
            d.notes.push(identity_note(scene));
            d.notes
                .push("opposite sign: compared by magnitude (rotation conventions differ)".into());
            return Ok(d);
        }
    } else {
        let square = |x: &Radical, budget: &mut Budget| {
            let coeff = Fraction::of(&x.coeff);
            coeff
                .times(&coeff, budget, field)?
                .times(&Fraction::of(&x.radicand), budget, field)
        };
        let (claimed, value) = (square(c, budget)?, square(exact, budget)?);
        if claimed.equals(&value, false, budget, field)? {
            squares_agree = true;
            d.notes.push(
                "the squares agree identically; the sign is taken from a sample scene".into(),
            );
        }
    }
    // Search a valid scene where the values differ (or, for a root, fix the sign).
    let per_sample = eval_cost(c).saturating_add(eval_cost(exact));
    for point in scene.samples(SAMPLES) {
        budget.charge(field, per_sample)?;
        let at = |f: &RatFn| f.eval::<Q>(&|s| point.get(&s).cloned());
        let (Some(cc), Some(cr), Some(ec), Some(er)) = (
            at(&c.coeff),
            at(&c.radicand),
            at(&exact.coeff),
            at(&exact.radicand),
        ) else {
            continue;
        };
        if cr.is_negative() || er.is_negative() {
            continue;
        }
        let value = Exact::radical(ec, er);
        let (equal, same_sign) = radical_matches(&cc, &cr, &value);
        if equal && (same_sign || omega) && squares_agree {
            d.verdict = Verdict::Agrees;
            if !same_sign {
                d.notes.push("opposite sign: compared by magnitude".into());
            }
            return Ok(d);
        }
        if !(equal && (same_sign || omega)) {
            let counterexample = Counterexample {
                point: point
                    .iter()
                    .map(|(s, v)| (s.name().to_string(), v.clone()))
                    .collect(),
                exact: value,
                claimed: Exact::radical(cc, cr),
            };
            d.refute(counterexample, omega);
            return Ok(d);
        }
    }
    d.notes
        .push("no valid sample scene separates the claim from the exact value".into());
    Ok(d)
}

/// The work of evaluating `x` at a point: for each polynomial, its terms times its words (each
/// term is added to a sum that grows to the size of the whole).
fn eval_cost(x: &Radical) -> u64 {
    [
        x.coeff.num(),
        x.coeff.den(),
        x.radicand.num(),
        x.radicand.den(),
    ]
    .iter()
    .map(|p| (p.terms().count() as u64).saturating_mul(words(p)))
    .fold(0, u64::saturating_add)
}

/// A rational function as an unreduced quotient of polynomials: identities are decided by
/// cross-multiplying, without the GCDs that reducing would cost.
struct Fraction {
    num: Poly,
    den: Poly,
}

impl Fraction {
    fn of(f: &RatFn) -> Fraction {
        Fraction {
            num: f.num().clone(),
            den: f.den().clone(),
        }
    }

    /// The product, its work charged.
    fn times(&self, other: &Fraction, budget: &mut Budget, field: &str) -> Result<Fraction, Error> {
        let cost = words(&self.num).saturating_mul(words(&other.num))
            + words(&self.den).saturating_mul(words(&other.den));
        budget.charge(field, cost)?;
        Ok(Fraction {
            num: &self.num * &other.num,
            den: &self.den * &other.den,
        })
    }

    /// Whether `self == other` (or `self == -other` when `negated`) identically.
    fn equals(
        &self,
        other: &Fraction,
        negated: bool,
        budget: &mut Budget,
        field: &str,
    ) -> Result<bool, Error> {
        let cost = words(&self.num).saturating_mul(words(&other.den))
            + words(&other.num).saturating_mul(words(&self.den));
        budget.charge(field, cost)?;
        let (left, right) = (&self.num * &other.den, &other.num * &self.den);
        Ok(if negated {
            (left + &right).is_zero()
        } else {
            (left - &right).is_zero()
        })
    }
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

    #[test]
    fn rod_symbols_stay_out_of_the_scene_flags() {
        let err = build(&[("a", "r")]).unwrap_err().to_string();
        assert_eq!(err, "a: r may appear only in --rod and in claims");
    }
}
