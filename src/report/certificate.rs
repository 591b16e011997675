//! One certificate in Markdown: what it says, its data, and what the checker verified (the body
//! of each certificate in `proofs/<ID>.md`).

use crate::claims::certificate::{
    Expected, Identity, Integral, Limit, Positive, Witness, point_name,
};
use crate::claims::{Certificate, Formula};
use crate::field::{RatFn, Sym};
use std::fmt::Write as _;

/// The certificate in Markdown: its kind, its data in a `text` block, and what the checker
/// verified.
///
/// # Examples
/// ```
/// use rodimpact::claims::{Certificate, Formula};
/// use rodimpact::field::RatFn;
/// use rodimpact::report::certificate_markdown;
/// let x = Formula::sym("x");
/// let one = Formula::int(1);
/// let c = Certificate::identity("(x+1)^2 expands", (x.clone() + &one).pow(2),
///     x.pow(2) + &(Formula::int(2) * &x) + &one);
/// assert!(certificate_markdown(&c).contains("lhs     = (x + 1)^2\nrhs     = x^2 + 2*x + 1\n"));
/// let a = Formula::sym("a");
/// let c = Certificate::identity_at("a^2 = 4 at a = 2", a.pow(2), Formula::int(4),
///     &[("a", RatFn::from(2))]);
/// assert!(certificate_markdown(&c).contains("at        a = 2\n"));
/// ```
pub fn certificate_markdown(c: &Certificate) -> String {
    match c {
        Certificate::Identity(c) => identity(c),
        Certificate::Positive(c) => positive(c),
        Certificate::Limit(c) => limit(c),
        Certificate::Witness(c) => witness(c),
        Certificate::Integral(c) => integral(c),
    }
}

fn identity(c: &Identity) -> String {
    let (lhs, rhs, at) = (&c.lhs, &c.rhs, &c.at);
    let mut block = format!("lhs     = {lhs}\nrhs     = {rhs}\n");
    let mut names: Vec<&(String, Formula)> = lhs.names().iter().collect();
    for n in rhs.names() {
        if !names.iter().any(|(k, _)| *k == n.0) {
            names.push(n);
        }
    }
    for (i, (name, value)) in names.iter().enumerate() {
        let head = if i == 0 { "where" } else { "" };
        let _ = writeln!(block, "{head:<9} {name} = {value}");
    }
    if !at.is_empty() {
        let _ = writeln!(block, "at        {}", substitution_text(at));
    }
    let checked = match c.reduced_sides() {
        Ok((l, r)) if l == r => {
            let _ = writeln!(block, "reduced = {l}   (both sides)");
            "the numerator of lhs - rhs expands to the zero polynomial"
        }
        Ok((l, r)) => {
            let _ = writeln!(block, "reduced : lhs = {l}, rhs = {r}");
            "lhs - rhs is compared with 0"
        }
        Err(_) => "the substitution makes a denominator vanish",
    };
    let at_words = if at.is_empty() {
        ""
    } else {
        "after the substitution in both sides, "
    };
    format!(
        "*Identity certificate.*\n\n```text\n{block}```\n\nChecked: {at_words}{checked}; the sides are shown as they were built.\n"
    )
}

fn positive(c: &Positive) -> String {
    let subs = if c.substitutions.is_empty() {
        "(none)".to_string()
    } else {
        substitution_text(&c.substitutions)
    };
    let names = |v: &[Sym]| {
        if v.is_empty() {
            "(none)".to_string()
        } else {
            v.iter().map(|s| s.name()).collect::<Vec<_>>().join(", ")
        }
    };
    format!(
        "*Positivity certificate.*\n\n```text\nexpression   = {}\nclaim        = expression {} 0\ndomain       : positive {}; nonnegative {}\nsubstitution : {subs}\nform         = {}\n```\n\nChecked: after the substitution the expression equals the form identically, and the form is built only from positive symbols and constants, sums, products, quotients by positive terms and squares, so it is {}.\n",
        c.expr,
        if c.strict { ">" } else { ">=" },
        names(&c.positive),
        names(&c.nonnegative),
        c.form,
        if c.strict { "> 0" } else { ">= 0" }
    )
}

fn limit(c: &Limit) -> String {
    let sym = c.sym;
    let target = match &c.expected {
        Expected::Finite(x) => x.to_string(),
        Expected::Infinite { coefficient, order } => {
            format!("~ ({coefficient}) * {sym}^{order}")
        }
    };
    format!(
        "*Limit certificate.*\n\n```text\nexpression = {}\n{sym} -> {}\nlimit      = {target}\n```\n\nChecked: exact leading terms in {sym} of numerator and denominator.\n",
        c.expr,
        point_name(c.at)
    )
}

fn witness(c: &Witness) -> String {
    let inst = c
        .instance
        .iter()
        .map(|(s, v)| format!("{s} = {v}"))
        .collect::<Vec<_>>()
        .join(", ");
    let show = |x: &RatFn| {
        c.evaluate(x)
            .map(|v| format!("{v} (~ {})", v.decimal(12)))
            .unwrap_or_else(|| "undefined".into())
    };
    format!(
        "*Witness certificate.*\n\n```text\ninstance : {inst}\nlhs      = {}\n         = {}\nrhs      = {}\n         = {}\nrelation : lhs {} rhs\n```\n\nChecked: both sides evaluated exactly in Q(sqrt d); the sign of lhs - rhs decided exactly.\n",
        c.lhs,
        show(&c.lhs),
        c.rhs,
        show(&c.rhs),
        c.relation.symbol()
    )
}

fn integral(c: &Integral) -> String {
    format!(
        "*Integral certificate.*\n\n```text\nintegral from {} to {} of ({}) * {var}^{} d{var}\n  = {}\n```\n\nChecked: exact polynomial antiderivative in {var}, evaluated at the limits.\n",
        c.lower,
        c.upper,
        c.density,
        c.power,
        c.expected,
        var = c.var
    )
}

/// `I = m*M*a^2/(M + m), e = 1`.
fn substitution_text(at: &[(Sym, RatFn)]) -> String {
    at.iter()
        .map(|(s, v)| format!("{s} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}
