//! `rodimpact formula` rendered: text, Markdown, LaTeX and JSON, with a LaTeX writer for
//! rational functions (`\frac`, juxtaposed products, `v_0`, `r_G`).

use crate::field::poly::Monomial;
use crate::field::{Poly, Q, RatFn};
use crate::textbook::expr::Radical;
use crate::textbook::formula::{AnswerFormula, Condition, Formulas};
use num_bigint::BigInt;
use num_traits::{One, Signed};
use serde_json::{Map, Value, json};

/// What each key means, for the text and Markdown renderings.
pub(super) fn meaning(key: &str) -> &'static str {
    match key {
        "v" => "projectile's velocity after the impact",
        "V" => "velocity of the rod's centre after the impact",
        "omega" => "rod's angular velocity after the impact",
        "impulse" => "impulse of the projectile on the rod, J = m (v0 - v)",
        "energy_lost" => "kinetic energy lost in the impact",
        "pivot_impulse" => "impulse of the pivot on the rod",
        "a_star_squared" => {
            "a*^2, the impact point of fastest spin (squared; from the pivot on a pivoted rod)"
        }
        "omega_max" => "largest omega over the impact points",
        "vt" => "projectile's velocity along the rod after the impact",
        "Vt" => "velocity of the rod's centre along the rod after the impact",
        "spin" => "disc's spin after the impact (counterclockwise seen from above)",
        "tangential_impulse" => "impulse of the projectile on the rod along the rod, Jt",
        "energy_lost_restitution" => {
            "the part lost to restitution, (1 - e^2) u_n^2/(2 k_n), however the contact ends"
        }
        "energy_lost_friction" => {
            "the part lost to friction: u_t^2/(2 k_t) sticking, mu J (|u_t| - mu J k_t/2) sliding"
        }
        "mu_star" => {
            "friction coefficient that just stops the slip, mu* = |u_t|/(J k_t): the contact sticks when mu >= mu*"
        }
        _ => "",
    }
}

/// The scene line: free symbols and defaults.
fn preamble(f: &Formulas) -> Vec<String> {
    let mut lines = vec![format!(
        "free symbols: {}",
        if f.free.is_empty() {
            "none".to_string()
        } else {
            f.free.join(", ")
        }
    )];
    if !f.defaults.is_empty() {
        lines.push(format!("defaults: {}", f.defaults.join("; ")));
    }
    lines
}

/// Plain text: one `key = formula` per line, with its condition below.
///
/// # Examples
/// ```
/// use rodimpact::{report::formula_text, scene::SceneInput, textbook::formula::formulas};
/// let f = formulas(&SceneInput { rod_mass: Some("m".into()), ..Default::default() })?;
/// assert!(formula_text(&f).contains("omega = 6*a*v0/(3*a^2 + 2*l^2)"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn formula_text(f: &Formulas) -> String {
    let mut out = String::new();
    for line in preamble(f) {
        out.push_str(&format!("{line}\n"));
    }
    let entries = |out: &mut String, list: &[AnswerFormula], indent: &str| {
        for x in list {
            out.push_str(&format!("\n{indent}{} = {}\n", x.key, x.value));
            out.push_str(&format!("{indent}    {}\n", meaning(x.key)));
            if let Some(c) = &x.condition {
                out.push_str(&format!("{indent}    {c}\n"));
            }
        }
    };
    entries(&mut out, &f.formulas, "");
    if let Some(contact) = f.contact {
        out.push_str(&format!("\ncontact: {contact}\n"));
    }
    for case in &f.cases {
        out.push_str(&format!(
            "\nif it {}s ({}):\n",
            case.contact, case.condition
        ));
        entries(&mut out, &case.formulas, "  ");
    }
    out
}

/// Markdown: a table of the formulas in LaTeX math (`$...$`).
///
/// # Examples
/// ```
/// use rodimpact::{report::formula_markdown, scene::SceneInput, textbook::formula::formulas};
/// let f = formulas(&SceneInput::default())?;
/// assert!(formula_markdown(&f).contains("| `omega` |"));
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn formula_markdown(f: &Formulas) -> String {
    let mut out = String::new();
    for line in preamble(f) {
        out.push_str(&format!("{line}  \n"));
    }
    let table = |out: &mut String, list: &[AnswerFormula]| {
        out.push_str("\n| quantity | formula | meaning |\n|---|---|---|\n");
        for x in list {
            let mut what = meaning(x.key).to_string();
            if let Some(c) = &x.condition {
                what.push_str(&format!("; {c}"));
            }
            out.push_str(&format!(
                "| `{}` | ${}$ | {} |\n",
                x.key,
                radical_latex(&x.value),
                what.replace('|', "\\|")
            ));
        }
    };
    table(&mut out, &f.formulas);
    if let Some(contact) = f.contact {
        out.push_str(&format!("\nThe contact: **{contact}**.\n"));
    }
    for case in &f.cases {
        out.push_str(&format!(
            "\nIf it {}s ({}):\n",
            case.contact, case.condition
        ));
        table(&mut out, &case.formulas);
    }
    out
}

/// LaTeX: a document fragment (compiles with amsmath): the free symbols and the defaults as
/// text, then one `align*` with a row per formula; a case split typeset as `cases` beside its
/// formula (omega_max: at a* when a* lies on the rod, at the end otherwise), and a contact the
/// symbols leave open as an `\intertext` heading before each case's rows.
///
/// # Examples
/// ```
/// use rodimpact::{report::formula_latex, scene::SceneInput, textbook::formula::formulas};
/// let f = formulas(&SceneInput::default())?;
/// let latex = formula_latex(&f);
/// assert!(latex.contains(r"\omega &= \frac{6 a m v_0}{"));
/// assert!(latex.contains(r"& \text{if } M \le 2 m"), "{latex}");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn formula_latex(f: &Formulas) -> String {
    let mut out = String::new();
    for line in preamble(f) {
        out.push_str(&format!("\\noindent {}\\par\n", text_latex(&line)));
    }
    let row = |x: &AnswerFormula| {
        let value = radical_latex(&x.value);
        let value = match &x.piecewise {
            None => value,
            Some(p) => {
                let when = match &p.when {
                    None => "\\text{never}".to_string(),
                    Some(Condition::Inequality(c)) => {
                        format!(
                            "\\text{{if }} {} \\le {}",
                            poly_latex(&c.lhs),
                            poly_latex(&c.rhs)
                        )
                    }
                    Some(Condition::Words(w)) => format!("\\text{{if {}}}", text_latex(w)),
                };
                let otherwise = match &p.otherwise {
                    Some(end) => format!("{} & \\text{{otherwise (at the end)}}", ratfn_latex(end)),
                    None => "\\text{largest at the end of the rod} & \\text{otherwise}".to_string(),
                };
                format!(
                    "\\begin{{cases}} \\displaystyle {value} & {when} \\\\ \\displaystyle {otherwise} \\end{{cases}}"
                )
            }
        };
        format!("  {} &= {value}", key_latex(x.key))
    };
    // Rows of the align: formulas (Ok) and \intertext headings (Err), which amsmath takes
    // right after a line break and which need none after them.
    let mut rows: Vec<Result<String, String>> = Vec::new();
    for x in &f.formulas {
        rows.push(Ok(row(x)));
        if x.key == "mu_star"
            && let Some(contact) = f.contact
        {
            rows.push(Err(format!("The contact {}s:", text_latex(contact))));
        }
    }
    for case in &f.cases {
        rows.push(Err(format!(
            "If it {}s (${}$):",
            case.contact,
            condition_latex(&case.condition)
        )));
        rows.extend(case.formulas.iter().map(|x| Ok(row(x))));
    }
    let mut out_rows = String::new();
    for (k, r) in rows.iter().enumerate() {
        match r {
            Ok(formula) => {
                out_rows.push_str(formula);
                if k + 1 < rows.len() {
                    out_rows.push_str(" \\\\");
                }
            }
            Err(heading) => out_rows.push_str(&format!("  \\intertext{{{heading}}}")),
        }
        out_rows.push('\n');
    }
    out.push_str("\\begin{align*}\n");
    out.push_str(&out_rows);
    out.push_str("\\end{align*}\n");
    out
}

/// A contact case's condition (`mu >= mu_star`, `mu = 1/4 >= mu_star`) in LaTeX math.
fn condition_latex(condition: &str) -> String {
    condition
        .replace(">=", "\\ge")
        .replace("mu_star", "\\mu^{*}")
        .replace("mu", "\\mu")
        .replace("\\\\mu^{*}", "\\mu^{*}")
}

/// Plain text for LaTeX's text mode: its special characters escaped.
fn text_latex(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '_' | '&' | '%' | '$' | '#' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str("\\^{}"),
            // OT1 text fonts print < and > as inverted punctuation.
            '<' => out.push_str("$<$"),
            '>' => out.push_str("$>$"),
            '~' => out.push_str("\\~{}"),
            _ => out.push(c),
        }
    }
    out
}

/// JSON: `free_symbols`, `defaults`, and per key `{"text", "latex"}` (plus `condition`).
///
/// # Examples
/// ```
/// use rodimpact::{report::formula_json, scene::SceneInput, textbook::formula::formulas};
/// let f = formulas(&SceneInput::default())?;
/// let j = formula_json(&f);
/// assert_eq!(j["a_star_squared"]["text"], "(1/3*M*l^2 + 1/3*l^2*m)/m");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn formula_json(f: &Formulas) -> Value {
    let mut map = Map::new();
    map.insert("free_symbols".into(), json!(f.free));
    map.insert("defaults".into(), json!(f.defaults));
    let entries = |map: &mut Map<String, Value>, list: &[AnswerFormula]| {
        for x in list {
            let mut entry = Map::new();
            entry.insert("text".into(), json!(x.value.to_string()));
            entry.insert("latex".into(), json!(radical_latex(&x.value)));
            if let Some(c) = &x.condition {
                entry.insert("condition".into(), json!(c));
            }
            map.insert(x.key.into(), Value::Object(entry));
        }
    };
    entries(&mut map, &f.formulas);
    if let Some(contact) = f.contact {
        map.insert("contact".into(), json!(contact));
    }
    if !f.cases.is_empty() {
        let mut cases = Map::new();
        for case in &f.cases {
            let mut entry = Map::new();
            entry.insert("condition".into(), json!(case.condition));
            entries(&mut entry, &case.formulas);
            cases.insert(case.contact.into(), Value::Object(entry));
        }
        map.insert("cases".into(), Value::Object(cases));
    }
    Value::Object(map)
}

pub(super) fn key_latex(key: &str) -> &'static str {
    match key {
        "v" => "v",
        "V" => "V",
        "omega" => "\\omega",
        "impulse" => "J",
        "energy_lost" => "\\Delta E",
        "pivot_impulse" => "J_p",
        "a_star_squared" => "a^{*2}",
        "omega_max" => "\\omega_{\\max}",
        "vt" => "v_t",
        "Vt" => "V_t",
        "spin" => "\\omega_{\\mathrm{disc}}",
        "tangential_impulse" => "J_t",
        "mu_star" => "\\mu^{*}",
        "energy_lost_restitution" => "\\Delta E_{e}",
        "energy_lost_friction" => "\\Delta E_{\\mu}",
        _ => "?",
    }
}

fn symbol_latex(name: &str) -> String {
    match name {
        "v0" => "v_0".into(),
        "r" => "r_G".into(),
        "v0t" => "v_{0t}".into(),
        "mu" => "\\mu".into(),
        "rd" => "r_d".into(),
        "V0" => "V_0".into(),
        "Vt0" => "V_{t0}".into(),
        "omega0" => "\\omega_0".into(),
        other => other.into(),
    }
}

/// A rational number in LaTeX (`\frac{p}{q}` or an integer), without sign.
fn rational_latex(c: &Q) -> String {
    if c.is_integer() {
        c.numer().to_string()
    } else {
        format!("\\frac{{{}}}{{{}}}", c.numer(), c.denom())
    }
}

/// A polynomial in LaTeX, factored as a textbook prints it: the factor common to every term
/// (the largest monomial, with the rational content) in front of the sum in parentheses,
/// `l^{2} \left(M + m\right)`, `\frac{2}{25} m \mu v_0 \left(-2 \mu v_0 + 5 v_{0t}\right)`; a
/// sum with no common monomial, or a single term, as its terms.
pub(super) fn poly_latex(p: &Poly) -> String {
    let common = common_monomial(p);
    if common == Monomial::one() {
        return terms_latex(p);
    }
    let factor = Poly::monomial(p.content().abs(), common);
    let rest = p
        .div_exact(&factor)
        .expect("a common monomial and the content divide every term");
    format!(
        "{} \\left({}\\right)",
        terms_latex(&factor),
        terms_latex(&rest)
    )
}

/// The largest monomial that divides every term of `p` (1 for fewer than two terms).
fn common_monomial(p: &Poly) -> Monomial {
    let terms: Vec<&Monomial> = p.terms().map(|(m, _)| m).collect();
    if terms.len() < 2 {
        return Monomial::one();
    }
    p.symbols().into_iter().fold(Monomial::one(), |acc, s| {
        match terms.iter().map(|m| m.exponent(s)).min() {
            Some(e) if e > 0 => acc.mul(&Monomial::var(s, e)),
            _ => acc,
        }
    })
}

/// A polynomial in LaTeX: terms joined by + and -, products juxtaposed.
fn terms_latex(p: &Poly) -> String {
    let mut out = String::new();
    // Largest term first, as the text form prints them.
    let terms: Vec<_> = p.terms().collect();
    for (i, (monomial, c)) in terms.into_iter().rev().enumerate() {
        let negative = c.is_negative();
        let abs = c.abs();
        if i == 0 {
            if negative {
                out.push('-');
            }
        } else {
            out.push_str(if negative { " - " } else { " + " });
        }
        let factors: Vec<String> = monomial
            .factors()
            .iter()
            .map(|&(s, e)| {
                let s = symbol_latex(s.name());
                if e == 1 { s } else { format!("{s}^{{{e}}}") }
            })
            .collect();
        if factors.is_empty() {
            out.push_str(&rational_latex(&abs));
        } else {
            if !abs.is_one() {
                out.push_str(&rational_latex(&abs));
                out.push(' ');
            }
            out.push_str(&factors.join(" "));
        }
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

/// A rational function in LaTeX: `\frac{num}{den}`, or the numerator alone over 1.
pub(super) fn ratfn_latex(f: &RatFn) -> String {
    if f.den().is_one() {
        return poly_latex(f.num());
    }
    // The rational constant goes into the fraction as integers (\frac{v_0}{2 l}, not
    // \frac{\frac{1}{2} v_0}{l}).
    let (num_content, den_content) = (f.num().content(), f.den().content());
    let constant = &num_content / &den_content;
    let part = |p: &Poly, content: &Q, integer: &BigInt| {
        p.scale(&(Q::from_integer(integer.clone()) / content))
    };
    format!(
        "\\frac{{{}}}{{{}}}",
        poly_latex(&part(f.num(), &num_content, constant.numer())),
        poly_latex(&part(f.den(), &den_content, constant.denom()))
    )
}

/// `coeff \sqrt{radicand}` in LaTeX.
pub(super) fn radical_latex(r: &Radical) -> String {
    if r.is_rational() {
        return ratfn_latex(&r.coeff);
    }
    let root = format!("\\sqrt{{{}}}", ratfn_latex(&r.radicand));
    if r.coeff.is_one() {
        root
    } else if r.coeff.num().terms().count() > 1 && r.coeff.den().is_one() {
        format!("\\left({}\\right) {root}", ratfn_latex(&r.coeff))
    } else {
        format!("{} {root}", ratfn_latex(&r.coeff))
    }
}
