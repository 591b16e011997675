//! A SymPy script per claim: it solves the balance equations for the unknowns, substitutes the
//! claim's definitions, and asserts each check by cancelling (an identity) or by exact
//! evaluation (a counterexample or witness at given values). Exit status 0 when confirmed.
//!
//! Only identities and checks at given values go to SymPy; an inequality over a domain is
//! z3's, and the script says so (see [`supported`]).

use super::expr::{Expr, Prop, parse};
use super::physics::{hypotheses, unknowns};
use super::statement::{Expect, Statement};
use super::{Exported, header};
use crate::claims::Entry;
use crate::claims::certificate::Relation;
use std::collections::BTreeSet;

fn expr(e: &Expr) -> String {
    match e {
        Expr::Int(n) => format!("Integer({n})"),
        Expr::Name(n) => n.clone(),
        Expr::Neg(x) => format!("(-{})", expr(x)),
        Expr::Add(x, y) => format!("({} + {})", expr(x), expr(y)),
        Expr::Sub(x, y) => format!("({} - {})", expr(x), expr(y)),
        Expr::Mul(x, y) => format!("({} * {})", expr(x), expr(y)),
        Expr::Div(x, y) => format!("({} / {})", expr(x), expr(y)),
        Expr::Pow(x, n) => format!("({} ** {n})", expr(x)),
    }
}

fn prop(p: &Prop) -> String {
    match p {
        Prop::Relation(op, x, y) => {
            let f = match op {
                Relation::Eq => "EQ",
                Relation::Ne => "NE",
                Relation::Lt => "LT",
                Relation::Le => "LE",
                Relation::Gt => "GT",
                Relation::Ge => "GE",
            };
            format!("{f}(at({}), at({}))", expr(x), expr(y))
        }
        Prop::Not(q) => format!("(not {})", prop(q)),
        Prop::And(qs) => format!("all([{}])", list(qs)),
        Prop::Or(qs) => format!("any([{}])", list(qs)),
        Prop::Implies(q, r) => format!("((not {}) or {})", prop(q), prop(r)),
    }
}

fn list(ps: &[Prop]) -> String {
    ps.iter().map(prop).collect::<Vec<_>>().join(", ")
}

fn parsed(text: &str) -> Prop {
    parse(text).unwrap_or_else(|e| panic!("a claim's statement: {e}"))
}

/// A hypothesis as SymPy uses it.
enum Use {
    /// `name = expr` (or `name^2 = expr`, the positive root): substituted.
    Define(String, String),
    /// About the unknowns: a solution must satisfy it.
    Filter(String),
    /// A domain condition on the parameters (an inequality): SymPy's symbols are positive.
    Domain,
    /// Any other equation between parameters: SymPy cannot substitute it.
    Unusable,
}

fn classify(p: &Prop, unknown: &BTreeSet<String>) -> Use {
    if !p.names().is_disjoint(unknown) {
        return Use::Filter(prop(p));
    }
    match p {
        Prop::Relation(Relation::Eq, Expr::Name(n), e) => Use::Define(n.clone(), expr(e)),
        Prop::Relation(Relation::Eq, Expr::Pow(b, 2), e) if matches!(**b, Expr::Name(_)) => {
            let Expr::Name(n) = &**b else { unreachable!() };
            Use::Define(n.clone(), format!("sqrt({})", expr(e)))
        }
        Prop::Relation(Relation::Eq, ..) => Use::Unusable,
        Prop::And(ps)
            if ps
                .iter()
                .any(|q| matches!(q, Prop::Relation(Relation::Eq, ..))) =>
        {
            Use::Unusable
        }
        _ => Use::Domain,
    }
}

fn all_unknowns(statement: &Statement) -> BTreeSet<String> {
    statement
        .impacts
        .iter()
        .flat_map(|i| unknowns(&statement.scene, i))
        .collect()
}

/// Which checks of the statement SymPy decides: an identity (a conclusion of equations) or a
/// check at values fixed by definitions, every hypothesis being a definition, a domain
/// condition or about the unknowns.
///
/// # Examples
/// ```
/// use rodimpact::claims::export::{Check, ExportLaw, Rod, Setting, Statement, sympy_supported};
/// const CHECKS: &[Check] = &[
///     Check::holds("V", "V = 2*m*v0/(M + m)").given(&["a = 0"]),
///     Check::holds("V > 0", "V > 0"),
/// ];
/// let scene = Setting::new(Rod::Free, ExportLaw::Elastic);
/// assert_eq!(sympy_supported(&Statement::new(scene, CHECKS)), [true, false]);
/// ```
pub fn supported(statement: &Statement) -> Vec<bool> {
    let unknown = all_unknowns(statement);
    let shared: Vec<Prop> = hypotheses(statement)
        .iter()
        .map(|h| parsed(&h.text))
        .collect();
    statement
        .checks
        .iter()
        .map(|c| {
            let given: Vec<Prop> = shared
                .iter()
                .cloned()
                .chain(c.given.iter().map(|g| parsed(g)))
                .collect();
            let mut defined = BTreeSet::new();
            for g in &given {
                match classify(g, &unknown) {
                    Use::Unusable => return false,
                    Use::Define(n, _) => {
                        defined.insert(n);
                    }
                    Use::Filter(_) | Use::Domain => {}
                }
            }
            let claim = parsed(c.claim);
            // An equation about the unknowns would constrain the parameters, not pick a solution.
            let constrains = c
                .given
                .iter()
                .map(|g| parsed(g))
                .any(|g| matches!(classify(&g, &unknown), Use::Filter(_)) && g.is_equational());
            match c.expect {
                Expect::Holds => claim.is_equational() && !constrains,
                Expect::Fails | Expect::Exists => given
                    .iter()
                    .chain([&claim])
                    .flat_map(Prop::names)
                    .all(|n| unknown.contains(&n) || defined.contains(&n)),
            }
        })
        .collect()
}

const PRELUDE: &str = r#"import sys
from sympy import Integer, Symbol, simplify, solve, sqrt


def zero(x):
    return simplify(x) == 0


def sign(x):
    """The exact sign of x, or exit 1 when SymPy cannot decide it."""
    x = simplify(x)
    if x.is_zero:
        return 0
    if x.is_positive:
        return 1
    if x.is_negative:
        return -1
    sys.exit(f"undecided sign: {x}")


def EQ(x, y):
    return zero(x - y)


def NE(x, y):
    return not zero(x - y)


def LT(x, y):
    return sign(y - x) > 0


def LE(x, y):
    return sign(y - x) >= 0


def GT(x, y):
    return sign(x - y) > 0


def GE(x, y):
    return sign(x - y) >= 0


def substitute(x, definitions):
    """x with every definition applied, until none applies (a definition may use another)."""
    for _ in range(len(definitions) + 1):
        for name, value in definitions:
            x = x.subs(name, value)
    return x


def solutions(balance, unknowns, definitions, filters):
    """The solutions of the balance equations after the definitions, those meeting the filters."""
    equations = [substitute(b, definitions) for b in balance]
    found = solve(equations, unknowns, dict=True) if unknowns else [{}]
    kept = [s for s in found if all(f(lambda x: substitute(x, definitions).subs(s)) for f in filters)]
    if not kept:
        sys.exit("the balance equations have no solution")
    return kept


def confirm(what, expect, holds, found):
    results = [holds(lambda x: substitute(x, found[1]).subs(s)) for s in found[0]]
    ok = all(results) if expect == "holds" else (not all(results) if expect == "fails" else any(results))
    print(("confirmed: " if ok else "NOT confirmed: ") + what)
    return ok
"#;

/// The SymPy script of a stated claim: its [`supported`] checks (at least one).
pub(super) fn write(entry: &Entry, statement: &Statement) -> Exported {
    let unknown = all_unknowns(statement);
    let hyps = hypotheses(statement);
    let mut names = BTreeSet::new();
    for h in &hyps {
        names.extend(parsed(&h.text).names());
    }
    for c in statement.checks {
        for g in c.given.iter().chain([&c.claim]) {
            names.extend(parsed(g).names());
        }
    }
    let mut out = String::from("#!/usr/bin/env python3\n");
    out.push_str(&header(entry, statement, "# "));
    out.push_str(
        "# Re-derived with SymPy from the balance equations (not from rodimpact's solution): solve\n\
         # them for the unknowns, substitute, and check each conclusion exactly. Exit status 0 when\n\
         # every check is confirmed. Run: python3 FILE\n",
    );
    out.push_str(PRELUDE);
    out.push('\n');
    for n in &names {
        let kind = if unknown.contains(n) {
            "real=True"
        } else {
            "positive=True"
        };
        out.push_str(&format!("{n} = Symbol(\"{n}\", {kind})\n"));
    }
    // Shared hypotheses: balance equations (as expressions equal to zero), definitions, filters.
    let (mut balance, mut definitions, mut filters) = (Vec::new(), Vec::new(), Vec::new());
    for h in &hyps {
        let p = parsed(&h.text);
        match (&p, classify(&p, &unknown)) {
            (Prop::Relation(Relation::Eq, x, y), Use::Filter(_)) => {
                balance.push(format!("    {} - ({}),  # {}", expr(x), expr(y), h.label));
            }
            (_, Use::Filter(f)) => filters.push(f),
            (_, Use::Define(n, e)) => definitions.push(format!("    ({n}, {e}),  # {}", h.label)),
            _ => {}
        }
    }
    let list = |name: &str, items: &[String]| {
        format!(
            "{name} = [\n{}]\n",
            items.iter().map(|i| format!("{i}\n")).collect::<String>()
        )
    };
    out.push_str(&list("balance", &balance));
    out.push_str(&format!(
        "unknowns = [{}]\n",
        unknown.iter().cloned().collect::<Vec<_>>().join(", ")
    ));
    out.push_str(&list("definitions", &definitions));
    let lambda = |p: &str| format!("    lambda at: {p},");
    out.push_str(&list(
        "filters",
        &filters.iter().map(|f| lambda(f)).collect::<Vec<_>>(),
    ));
    out.push_str("\nok = True\n");
    for (i, (c, decided)) in statement
        .checks
        .iter()
        .zip(supported(statement))
        .enumerate()
    {
        if !decided {
            out.push_str(&format!(
                "\n# check {}: {}\nprint({:?})\n",
                i + 1,
                c.what,
                format!(
                    "left to z3 (not an identity or a check at given values): {}",
                    c.what
                )
            ));
            continue;
        }
        let (mut defs, mut own_filters) = (Vec::new(), Vec::new());
        for g in c.given {
            match classify(&parsed(g), &unknown) {
                Use::Define(n, e) => defs.push(format!("({n}, {e})")),
                Use::Filter(f) => own_filters.push(lambda(&f)),
                _ => {}
            }
        }
        let expect = match c.expect {
            Expect::Holds => "holds",
            Expect::Fails => "fails",
            Expect::Exists => "exists",
        };
        out.push_str(&format!("\n# check {}: {}\n", i + 1, c.what));
        out.push_str(&format!(
            "defs = definitions + [{}]\nfound = (solutions(balance, unknowns, defs, filters + [\n{}]), defs)\n",
            defs.join(", "),
            own_filters.iter().map(|f| format!("{f}\n")).collect::<String>()
        ));
        out.push_str(&format!(
            "ok = confirm({:?}, \"{expect}\", lambda at: {}, found) and ok\n",
            c.what,
            prop(&parsed(c.claim))
        ));
    }
    out.push_str("\nsys.exit(0 if ok else 1)\n");
    Exported {
        name: format!("{}.py", entry.id),
        text: out,
    }
}
