//! The markup of report prose (table titles, notes, headings, the paper report's own sentences):
//! plain text with inline math between dollars, `$a^* < l$`, written once and printed three
//! ways:
//!
//! - [`latex`]: the text escaped for LaTeX, the math kept as math (`$a^* < l$`), so captions
//!   compile cleanly and typeset as math;
//! - [`unicode`]: the math spelled in Unicode for terminals and plain Markdown (`a* < l`,
//!   `ω_max`, `v0`, `|p|`, `√(2/3)`);
//! - [`github`]: GitHub Markdown math, `` $`a^* < l`$ `` (the backtick form, so that `*`
//!   and `_` inside the math are never read as emphasis), for `report.md`.
//!
//! The claims' own texts are written in ASCII math (`a*^2`, `sqrt(2/3)`, `omega`);
//! [`ascii_math`] spells them in Unicode and [`markdown_text`] makes any text safe inside
//! Markdown.
//!
//! The math is a small subset of LaTeX: letters, digits, operators, `^` and `_` (with one
//! character or a braced group), `\sqrt{..}`, `\mathrm{..}`, `\lvert ..\rvert`, `\,` and the
//! commands `\omega`, `\mu`, `\Delta`, `\pi`, `\approx`, `\le`, `\ge`, `\ne`, `\cdot`, `\times`,
//! `\infty`, `\to`, `\max`, `\min`.

/// `text` with its `$…$` math spelled in Unicode and the dollars removed.
///
/// # Examples
/// ```
/// use rodimpact::report::markup::unicode;
/// assert_eq!(unicode(r"$a^* < l$ when $M/m < (l/r_G)^2 - 1$"), "a* < l when M/m < (l/r_G)² - 1");
/// assert_eq!(unicode(r"$\omega_{\max}$, $v_0$, $\lvert p\rvert$, $\sqrt{2/3}$"), "ω_max, v0, |p|, √(2/3)");
/// ```
pub fn unicode(text: &str) -> String {
    let mut out = String::new();
    for (i, part) in text.split('$').enumerate() {
        if i % 2 == 1 {
            out.push_str(&math_unicode(part));
        } else {
            out.push_str(part);
        }
    }
    out
}

/// `text` for GitHub Markdown: each `$…$` span becomes `` $`…`$ ``, the plain parts are escaped
/// with [`markdown_text`].
///
/// # Examples
/// ```
/// use rodimpact::report::markup::github;
/// assert_eq!(github(r"where $a^* < l$ holds"), r"where $`a^* < l`$ holds");
/// ```
pub fn github(text: &str) -> String {
    let mut out = String::new();
    for (i, part) in text.split('$').enumerate() {
        if i % 2 == 1 {
            out.push_str("$`");
            out.push_str(part);
            out.push_str("`$");
        } else {
            out.push_str(&markdown_text(part));
        }
    }
    out
}

/// Plain text made safe inside Markdown (a table cell included): `\`, `*`, `_`, `|`, `$`, `<`,
/// `` ` ``, `[` and `]` escaped, newlines as spaces.
///
/// # Examples
/// ```
/// use rodimpact::report::markup::markdown_text;
/// assert_eq!(markdown_text("a* = |p|"), r"a\* = \|p\|");
/// ```
pub fn markdown_text(text: &str) -> String {
    let mut out = String::new();
    for ch in text.chars() {
        match ch {
            '\\' | '*' | '|' | '$' | '<' | '`' | '[' | ']' | '_' => {
                out.push('\\');
                out.push(ch);
            }
            '\n' => out.push(' '),
            _ => out.push(ch),
        }
    }
    out
}

/// The ASCII math of the claims' texts spelled in Unicode: `omega` → `ω`, `sqrt(6)` → `√6`,
/// `sqrt(2/3)` → `√(2/3)`, `^2` → `²`, `pi` → `π`, `oo` → `∞`, `->` → `→`, `<=` → `≤`,
/// `>=` → `≥`, `!=` → `≠`, `<<` → `≪`, `>>` → `≫`. Words are matched whole (`omega_max` →
/// `ω_max`, `a0` stays, `tau1` → `τ₁`); anything else is left as written.
///
/// # Examples
/// ```
/// use rodimpact::report::markup::ascii_math;
/// assert_eq!(
///     ascii_math("omega(sqrt(2/3) l) = sqrt(6)/2 v0/l; a*^2 -> oo, M >= 2m"),
///     "ω(√(2/3) l) = √6/2 v0/l; a*² → ∞, M ≥ 2m"
/// );
/// // An indexed Greek name takes a subscript; a coefficient does not stop a Greek letter.
/// assert_eq!(ascii_math("tau1 in (pi/2, 3pi/2), pie"), "τ₁ in (π/2, 3π/2), pie");
/// ```
pub fn ascii_math(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric()) {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let joined_before = start > 0 && chars[start - 1].is_ascii_alphanumeric();
            if word == "sqrt" && !joined_before && chars.get(i) == Some(&' ') {
                // `sqrt 6`, `Q(sqrt d)`: the root of the next word.
                let start = i + 1;
                let mut end = start;
                while end < chars.len() && chars[end].is_ascii_alphanumeric() {
                    end += 1;
                }
                if end > start {
                    out.push('√');
                    out.extend(&chars[start..end]);
                    i = end;
                    continue;
                }
            }
            if word == "sqrt" && !joined_before && chars.get(i) == Some(&'(') {
                let (arg, next) = balanced(&chars, i);
                let inner = ascii_math(&arg);
                if inner.chars().all(|c| c.is_alphanumeric()) {
                    out.push_str(&format!("√{inner}"));
                } else {
                    out.push_str(&format!("√({inner})"));
                }
                i = next;
                continue;
            }
            // A Greek name with a numeric index (`tau1`) takes the index as a subscript.
            let stem = word.trim_end_matches(|c: char| c.is_ascii_digit());
            let index: String = word[stem.len()..]
                .chars()
                .map(|d| char::from_u32(0x2080 + d.to_digit(10).unwrap_or(0)).unwrap_or(d))
                .collect();
            let greek = match stem {
                "omega" => Some("ω"),
                "pi" => Some("π"),
                "mu" => Some("μ"),
                "tau" => Some("τ"),
                "kappa" => Some("κ"),
                "oo" => Some("∞"),
                _ => None,
            };
            // `sqrt3`, `2sqrt6`: a root of digits, also right after a coefficient.
            let after_letter = start > 0 && chars[start - 1].is_ascii_alphabetic();
            if let Some(digits) = word
                .strip_prefix("sqrt")
                .filter(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()))
                && !after_letter
            {
                out.push('√');
                out.push_str(digits);
                continue;
            }
            // After a coefficient (`3pi`) it is still a Greek letter; inside a word it is not.
            match greek {
                Some(g) if !after_letter && !stem.is_empty() => {
                    out.push_str(g);
                    out.push_str(&index);
                }
                _ => out.push_str(&word),
            }
            continue;
        }
        let next = chars.get(i + 1).copied();
        let pair = match (c, next) {
            ('-', Some('>')) => Some("→"),
            ('<', Some('=')) => Some("≤"),
            ('>', Some('=')) => Some("≥"),
            ('!', Some('=')) => Some("≠"),
            ('<', Some('<')) => Some("≪"),
            ('>', Some('>')) => Some("≫"),
            _ => None,
        };
        if let Some(p) = pair {
            out.push_str(p);
            i += 2;
            continue;
        }
        if c == '^' {
            let digit = next.filter(char::is_ascii_digit);
            let after = chars.get(i + 2).copied();
            if let Some(d) = digit.filter(|_| !after.is_some_and(|a| a.is_ascii_alphanumeric())) {
                out.push_str(&superscript(&d.to_string()));
                i += 2;
                continue;
            }
        }
        out.push(c);
        i += 1;
    }
    out
}

/// The parenthesised group opening at `i` (without its parentheses) and the index after it.
fn balanced(chars: &[char], i: usize) -> (String, usize) {
    let mut depth = 0;
    for (j, &c) in chars.iter().enumerate().skip(i) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return (chars[i + 1..j].iter().collect(), j + 1);
                }
            }
            _ => {}
        }
    }
    (chars[i + 1..].iter().collect(), chars.len())
}

/// `text` for LaTeX: the plain parts escaped (`&`, `%`, `#`, `_`, `{`, `}`, `~`, `^`, `\`, `<`,
/// `>`, `|` and the Unicode symbols as math), the `$…$` math kept verbatim.
///
/// # Examples
/// ```
/// use rodimpact::report::markup::latex;
/// assert_eq!(latex(r"T1_a: $a^* < l$ & 50%"), r"T1\_a: $a^* < l$ \& 50\%");
/// ```
pub fn latex(text: &str) -> String {
    let mut out = String::new();
    for (i, part) in text.split('$').enumerate() {
        if i % 2 == 1 {
            out.push('$');
            out.push_str(part);
            out.push('$');
        } else {
            out.push_str(&latex_text(part));
        }
    }
    out
}

/// Plain text made safe for LaTeX's text mode.
fn latex_text(text: &str) -> String {
    let mut out = String::new();
    for ch in text.chars() {
        match ch {
            '&' | '%' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(ch);
            }
            '~' => out.push_str("\\textasciitilde{}"),
            '^' => out.push_str("\\textasciicircum{}"),
            '\\' => out.push_str("\\textbackslash{}"),
            '<' => out.push_str("$<$"),
            '>' => out.push_str("$>$"),
            '|' => out.push_str("$\\vert$"),
            '√' => out.push_str("$\\surd$"),
            '≤' => out.push_str("$\\le$"),
            '≥' => out.push_str("$\\ge$"),
            '·' => out.push_str("$\\cdot$"),
            '≈' => out.push_str("$\\approx$"),
            'ω' => out.push_str("$\\omega$"),
            'Δ' => out.push_str("$\\Delta$"),
            '²' => out.push_str("$^2$"),
            _ => out.push(ch),
        }
    }
    out
}

/// The Unicode spelling of a LaTeX command without arguments, `None` for an unknown one.
fn command(name: &str) -> Option<&'static str> {
    Some(match name {
        "omega" => "ω",
        "mu" => "μ",
        "Delta" => "Δ",
        "pi" => "π",
        "approx" => "≈",
        "le" | "leq" => "≤",
        "ge" | "geq" => "≥",
        "ne" => "≠",
        "cdot" => "·",
        "times" => "×",
        "infty" => "∞",
        "to" => "→",
        "lvert" | "rvert" | "vert" => "|",
        "max" => "max",
        "min" => "min",
        "," | ";" | " " => " ",
        _ => return None,
    })
}

/// One math span in Unicode.
fn math_unicode(math: &str) -> String {
    let chars: Vec<char> = math.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '\\' => {
                let start = i + 1;
                let mut end = start;
                while end < chars.len() && chars[end].is_ascii_alphabetic() {
                    end += 1;
                }
                if end == start && end < chars.len() {
                    end += 1; // a one-character command such as `\,`
                }
                let name: String = chars[start..end].iter().collect();
                i = end;
                let relation = matches!(
                    command(&name),
                    Some("≈" | "≤" | "≥" | "≠" | "·" | "×" | "→")
                );
                if !relation && chars[start..end].iter().all(char::is_ascii_alphabetic) {
                    // As in LaTeX, spaces after a control word only end its name (`\Delta K`
                    // is `ΔK`); around a relation they stay, for reading.
                    while chars.get(i) == Some(&' ') {
                        i += 1;
                    }
                }
                match name.as_str() {
                    "frac" => {
                        let (num, next) = group(&chars, i);
                        let (den, next) = group(&chars, next);
                        out.push_str(&format!(
                            "{}/{}",
                            operand(&math_unicode(&num)),
                            operand(&math_unicode(&den))
                        ));
                        i = next;
                    }
                    "sqrt" => {
                        let (arg, next) = group(&chars, i);
                        let inner = math_unicode(&arg);
                        if inner.chars().all(|c| c.is_alphanumeric()) {
                            out.push_str(&format!("√{inner}"));
                        } else {
                            out.push_str(&format!("√({inner})"));
                        }
                        i = next;
                    }
                    "mathrm" | "text" | "mathit" => {
                        let (arg, next) = group(&chars, i);
                        out.push_str(&math_unicode(&arg));
                        i = next;
                    }
                    _ => out.push_str(command(&name).unwrap_or(&name)),
                }
            }
            '^' => {
                let (arg, next) = group(&chars, i + 1);
                out.push_str(&superscript(&math_unicode(&arg)));
                i = next;
            }
            '_' => {
                let (arg, next) = group(&chars, i + 1);
                let inner = math_unicode(&arg);
                if !inner.chars().all(|c| c.is_ascii_digit()) {
                    out.push('_');
                }
                out.push_str(&inner);
                i = next;
            }
            '{' | '}' => i += 1,
            c => {
                out.push(c);
                i += 1;
            }
        }
    }
    // `\, ` and the like: one space is enough.
    while out.contains("  ") {
        out = out.replace("  ", " ");
    }
    out
}

/// `x` as an operand of `/`: in parentheses when it is a sum or product with spaces.
fn operand(x: &str) -> String {
    if x.contains([' ', '+', '-']) {
        format!("({x})")
    } else {
        x.to_string()
    }
}

/// The argument at `i`: a braced group or one character; returns it and the index after it.
fn group(chars: &[char], i: usize) -> (String, usize) {
    match chars.get(i) {
        Some('{') => {
            let mut depth = 0;
            for (j, &c) in chars.iter().enumerate().skip(i) {
                match c {
                    '{' => depth += 1,
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            return (chars[i + 1..j].iter().collect(), j + 1);
                        }
                    }
                    _ => {}
                }
            }
            (chars[i + 1..].iter().collect(), chars.len())
        }
        Some(&c) => (c.to_string(), i + 1),
        None => (String::new(), i),
    }
}

/// An exponent in Unicode: digits as superscripts, `*` as is (`a^{*2}` is `a*²`), anything
/// else after a caret.
fn superscript(text: &str) -> String {
    let sup = |c: char| {
        Some(match c {
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            '-' => '⁻',
            '*' => '*',
            _ => return None,
        })
    };
    match text.chars().map(sup).collect::<Option<String>>() {
        Some(s) => s,
        None => format!("^({text})"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claim_texts_in_unicode() {
        let table = [
            ("omega_max and omega", "ω_max and ω"),
            ("a*^2 = (M + m) I/(m M)", "a*² = (M + m) I/(m M)"),
            ("x^n and x^10 and r_G^2", "x^n and x^10 and r_G²"),
            ("sqrt((M+m)/(3m)) l", "√((M+m)/(3m)) l"),
            ("l/sqrt3, t = pi a*/v0", "l/√3, t = π a*/v0"),
            ("exactly in Q(sqrt 6), Q(sqrt d)", "exactly in Q(√6), Q(√d)"),
            (
                "the ratio is 2sqrt6/5, not xsqrt6",
                "the ratio is 2√6/5, not xsqrt6",
            ),
            ("M << m, M >> m, M -> oo", "M ≪ m, M ≫ m, M → ∞"),
            (
                "a0, v0, epsilon, pivot, topic",
                "a0, v0, epsilon, pivot, topic",
            ),
        ];
        for (ascii, want) in table {
            assert_eq!(ascii_math(ascii), want, "{ascii}");
        }
    }

    #[test]
    fn math_in_unicode() {
        let table = [
            (r"$a^{*2}/l^2$", "a*²/l²"),
            (r"$\omega(\mathrm{end})/\omega_{\max}$", "ω(end)/ω_max"),
            (r"$\omega/\omega_{\mathrm{el}}$", "ω/ω_el"),
            (r"$\Delta K/K_0$", "ΔK/K0"),
            (r"$\omega\, l/v_0$", "ω l/v0"),
            (r"$\omega l$", "ωl"),
            (r"$M \le 2m$, $x \approx 1$", "M ≤ 2m, x ≈ 1"),
            (
                r"$\frac{\sqrt{6}}{3}$, $\frac{1 + e}{2}$",
                "√6/3, (1 + e)/2",
            ),
            (r"$I/(M l^2)$", "I/(M l²)"),
            (r"$d^* = \sqrt{I_p/m}$", "d* = √(I_p/m)"),
            (r"$\sqrt{6}/2$", "√6/2"),
            (
                r"$\omega_{\mathrm{el}} = 2\,\omega_{\mathrm{inel}}$",
                "ω_el = 2 ω_inel",
            ),
            (r"$x^{n+1}$", "x^(n+1)"),
            ("no math", "no math"),
        ];
        for (markup, want) in table {
            assert_eq!(unicode(markup), want, "{markup}");
        }
    }

    /// The review's broken caption: `<` and `|` in LaTeX's text mode print as `¡` and an em
    /// dash in OT1. Outside math they are now math symbols; inside math they stay as typed.
    #[test]
    fn text_mode_symbols_become_math() {
        assert_eq!(latex("a < b, |p|"), r"a $<$ b, $\vert$p$\vert$");
        assert_eq!(
            latex(r"$d = I_p/(M \lvert p\rvert)$"),
            r"$d = I_p/(M \lvert p\rvert)$"
        );
        assert_eq!(latex("r_G ≈ 1"), r"r\_G $\approx$ 1");
    }
}
