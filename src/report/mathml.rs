//! MathML for the web pages: the LaTeX math every other output already writes (the
//! [`markup`](super::markup) subset, the exact numbers of [`notation`](crate::field::notation),
//! the rational functions of `formula`) translated to presentation MathML, so a page shows the
//! same formulas as the LaTeX tables without a script or a font from the network.
//!
//! The LaTeX read is the subset those writers produce: letters (each an identifier), numbers,
//! operators, `^` and `_` with one character or a braced group (both on one base give
//! `msubsup`), `\frac{..}{..}`, `\sqrt{..}`, `\mathrm{..}`, `\left( .. \right)`,
//! `\lvert .. \rvert`, the spaces `\,` `\;` `\quad`, the Greek letters and the named operators
//! listed below (`\omega`, `\le`, `\max`, ...). Anything else is shown as written, in `<merror>`,
//! never dropped.

/// `latex` (math mode, without dollars) as a `<math>` element; `block` centres it on a line
/// of its own (`display="block"`).
///
/// # Examples
/// ```
/// use rodimpact::report::mathml::math;
/// assert_eq!(
///     math(r"a^* = \frac{\sqrt{6}}{3}", false),
///     "<math><mrow><msup><mi>a</mi><mo>*</mo></msup><mo>=</mo>\
///      <mfrac><msqrt><mn>6</mn></msqrt><mn>3</mn></mfrac></mrow></math>"
/// );
/// assert!(math(r"\omega_{\max}", true).starts_with("<math display=\"block\">"));
/// ```
pub fn math(latex: &str, block: bool) -> String {
    let chars: Vec<char> = latex.chars().collect();
    let mut reader = Reader { chars, at: 0 };
    let mut row = Vec::new();
    // A stray closing brace ends a group, not the formula: read on to the end.
    while reader.at < reader.chars.len() {
        row.extend(reader.row(None));
    }
    let open = if block {
        "<math display=\"block\">"
    } else {
        "<math>"
    };
    format!("{open}{}</math>", mrow(row))
}

/// Text with `$…$` math ([`markup`](super::markup)) as HTML: the plain parts escaped, each
/// math span a `<math>` element.
///
/// # Examples
/// ```
/// use rodimpact::report::mathml::text;
/// assert_eq!(
///     text("on the rod when $M < 2m$ & <b>"),
///     "on the rod when <math><mrow><mi>M</mi><mo>&lt;</mo><mn>2</mn><mi>m</mi></mrow></math> &amp; &lt;b&gt;"
/// );
/// ```
pub fn text(marked: &str) -> String {
    let mut out = String::new();
    for (i, part) in marked.split('$').enumerate() {
        if i % 2 == 1 {
            out.push_str(&math(part, false));
        } else {
            out.push_str(&escape(part));
        }
    }
    out
}

/// `text` escaped for HTML element content and attribute values: `&`, `<`, `>`, `"` and `'`.
///
/// # Examples
/// ```
/// use rodimpact::report::mathml::escape;
/// assert_eq!(escape(r#"a < "b" & 'c'"#), "a &lt; &quot;b&quot; &amp; &#39;c&#39;");
/// ```
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Items of a row wrapped in one `<mrow>` (a single item stays as it is).
fn mrow(items: Vec<String>) -> String {
    if items.len() == 1 {
        items.into_iter().next().unwrap_or_default()
    } else {
        format!("<mrow>{}</mrow>", items.concat())
    }
}

/// What a command stands for: an identifier (a Greek letter, a named function) or an operator.
enum Symbol {
    Identifier(&'static str),
    Operator(&'static str),
    Space(&'static str),
}

/// The commands read as a single symbol.
fn command(name: &str) -> Option<Symbol> {
    use Symbol::*;
    Some(match name {
        "omega" => Identifier("ω"),
        "Delta" => Identifier("Δ"),
        "pi" => Identifier("π"),
        "mu" => Identifier("μ"),
        "alpha" => Identifier("α"),
        "theta" => Identifier("θ"),
        "max" => Identifier("max"),
        "min" => Identifier("min"),
        "approx" => Operator("≈"),
        "le" | "leq" => Operator("≤"),
        "ge" | "geq" => Operator("≥"),
        "ne" | "neq" => Operator("≠"),
        "cdot" => Operator("·"),
        "times" => Operator("×"),
        "infty" => Identifier("∞"),
        "to" => Operator("→"),
        "Rightarrow" => Operator("⇒"),
        "pm" => Operator("±"),
        "," => Space("0.1667em"),
        ";" => Space("0.2778em"),
        "quad" => Space("1em"),
        "qquad" => Space("2em"),
        _ => return None,
    })
}

struct Reader {
    chars: Vec<char>,
    at: usize,
}

impl Reader {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    /// Items up to the end, to a closing brace (consumed), or to `\right` / `\rvert` when
    /// `until` names it (left for the caller).
    fn row(&mut self, until: Option<&str>) -> Vec<String> {
        let mut items = Vec::new();
        while let Some(c) = self.peek() {
            if c == '}' {
                self.at += 1;
                break;
            }
            if let Some(stop) = until
                && self.looking_at(stop)
            {
                break;
            }
            if c.is_whitespace() {
                self.at += 1;
                continue;
            }
            let base = self.atom();
            items.push(self.scripts(base));
        }
        items
    }

    fn looking_at(&self, command: &str) -> bool {
        let word: Vec<char> = command.chars().collect();
        self.chars[self.at..].starts_with(&word)
            && !self
                .chars
                .get(self.at + word.len())
                .is_some_and(|c| c.is_ascii_alphabetic())
    }

    /// `base` with its `^` and `_` scripts.
    fn scripts(&mut self, base: String) -> String {
        let (mut sub, mut sup) = (None, None);
        loop {
            self.skip_spaces();
            match self.peek() {
                Some('^') if sup.is_none() => {
                    self.at += 1;
                    sup = Some(self.argument());
                }
                Some('_') if sub.is_none() => {
                    self.at += 1;
                    sub = Some(self.argument());
                }
                _ => break,
            }
        }
        match (sub, sup) {
            (None, None) => base,
            (Some(b), None) => format!("<msub>{base}{b}</msub>"),
            (None, Some(p)) => format!("<msup>{base}{p}</msup>"),
            (Some(b), Some(p)) => format!("<msubsup>{base}{b}{p}</msubsup>"),
        }
    }

    fn skip_spaces(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.at += 1;
        }
    }

    /// A braced group or a single atom (a script, an argument of `\frac`).
    fn argument(&mut self) -> String {
        self.skip_spaces();
        if self.peek() == Some('{') {
            self.at += 1;
            mrow(self.row(None))
        } else {
            self.atom()
        }
    }

    fn atom(&mut self) -> String {
        let Some(c) = self.peek() else {
            return "<mrow></mrow>".into();
        };
        self.at += 1;
        match c {
            '{' => mrow(self.row(None)),
            '\\' => self.command(),
            '0'..='9' | '.' => {
                let mut number = c.to_string();
                while let Some(d) = self.peek().filter(|d| d.is_ascii_digit() || *d == '.') {
                    number.push(d);
                    self.at += 1;
                }
                format!("<mn>{number}</mn>")
            }
            c if c.is_alphabetic() => format!("<mi>{}</mi>", escape(&c.to_string())),
            '*' => "<mo>*</mo>".into(),
            '\'' => "<mo>′</mo>".into(),
            '(' | ')' | '[' | ']' | '|' => format!("<mo stretchy=\"false\">{c}</mo>"),
            // A slash between symbols, as in running text: no operator space around it.
            '/' => "<mo lspace=\"0\" rspace=\"0\">/</mo>".into(),
            '-' => "<mo>−</mo>".into(),
            c => format!("<mo>{}</mo>", escape(&c.to_string())),
        }
    }

    /// After a backslash: a command and its arguments.
    fn command(&mut self) -> String {
        let mut name = String::new();
        while let Some(c) = self.peek().filter(char::is_ascii_alphabetic) {
            name.push(c);
            self.at += 1;
        }
        if name.is_empty()
            && let Some(c) = self.peek()
        {
            // A one-character command: `\,`, `\;`, `\{`.
            name.push(c);
            self.at += 1;
        }
        match name.as_str() {
            "frac" => {
                let num = self.argument();
                let den = self.argument();
                format!("<mfrac>{num}{den}</mfrac>")
            }
            "sqrt" => {
                let radicand = self.argument();
                // A single-item radicand is wrapped too: `msqrt` takes a row.
                format!("<msqrt>{radicand}</msqrt>")
            }
            "mathrm" | "text" => {
                let mut word = String::new();
                self.skip_spaces();
                if self.peek() == Some('{') {
                    self.at += 1;
                    while let Some(c) = self.peek() {
                        self.at += 1;
                        if c == '}' {
                            break;
                        }
                        word.push(c);
                    }
                }
                format!("<mi mathvariant=\"normal\">{}</mi>", escape(&word))
            }
            "left" | "right" => {
                // The fence itself is the next character (`\left(`), stretched to its content.
                self.skip_spaces();
                let fence = self.peek().map(|c| c.to_string()).unwrap_or_default();
                self.at += fence.chars().count();
                let fence = if fence == "." { String::new() } else { fence };
                if name == "left" {
                    let inner = self.row(Some("\\right"));
                    let close = if self.looking_at("\\right") {
                        self.at += "\\right".len();
                        self.command_fence()
                    } else {
                        String::new()
                    };
                    format!(
                        "<mrow><mo>{}</mo>{}<mo>{}</mo></mrow>",
                        escape(&fence),
                        inner.concat(),
                        escape(&close)
                    )
                } else {
                    format!("<mo>{}</mo>", escape(&fence))
                }
            }
            "lvert" => {
                let inner = self.row(Some("\\rvert"));
                if self.looking_at("\\rvert") {
                    self.at += "\\rvert".len();
                }
                format!("<mrow><mo>|</mo>{}<mo>|</mo></mrow>", inner.concat())
            }
            "{" | "}" => format!("<mo>{name}</mo>"),
            other => match command(other) {
                Some(Symbol::Identifier(s)) => format!("<mi>{s}</mi>"),
                Some(Symbol::Operator(s)) => format!("<mo>{s}</mo>"),
                Some(Symbol::Space(w)) => format!("<mspace width=\"{w}\"/>"),
                None => format!("<merror><mtext>\\{}</mtext></merror>", escape(other)),
            },
        }
    }

    /// The fence after `\right`.
    fn command_fence(&mut self) -> String {
        self.skip_spaces();
        let fence = self.peek().map(|c| c.to_string()).unwrap_or_default();
        self.at += fence.chars().count();
        if fence == "." { String::new() } else { fence }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::notation::{Notation, root};
    use crate::field::q;

    fn inner(latex: &str) -> String {
        let m = math(latex, false);
        m["<math>".len()..m.len() - "</math>".len()].to_string()
    }

    #[test]
    fn scripts_fractions_roots_and_fences() {
        assert_eq!(inner("v_0"), "<msub><mi>v</mi><mn>0</mn></msub>");
        assert_eq!(
            inner("a^{*2}"),
            "<msup><mi>a</mi><mrow><mo>*</mo><mn>2</mn></mrow></msup>"
        );
        assert_eq!(
            inner(r"\omega_{\max}"),
            "<msub><mi>ω</mi><mi>max</mi></msub>"
        );
        assert_eq!(
            inner("r_G^2"),
            "<msubsup><mi>r</mi><mi>G</mi><mn>2</mn></msubsup>"
        );
        assert_eq!(
            inner(r"\left(1 + e\right) \sqrt{x}"),
            "<mrow><mrow><mo>(</mo><mn>1</mn><mo>+</mo><mi>e</mi><mo>)</mo></mrow><msqrt><mi>x</mi></msqrt></mrow>"
        );
        assert_eq!(
            inner(r"\lvert p\rvert \le l"),
            "<mrow><mrow><mo>|</mo><mi>p</mi><mo>|</mo></mrow><mo>≤</mo><mi>l</mi></mrow>"
        );
        assert_eq!(
            inner(r"\mathrm{kg}\,x"),
            "<mrow><mi mathvariant=\"normal\">kg</mi><mspace width=\"0.1667em\"/><mi>x</mi></mrow>"
        );
    }

    /// Every root the tables print in LaTeX reads as a fraction of a root, the same number.
    #[test]
    fn the_notation_of_exact_numbers() {
        assert_eq!(
            inner(&root(&q(16, 3), Notation::Latex)),
            "<mfrac><mrow><mn>4</mn><msqrt><mn>3</mn></msqrt></mrow><mn>3</mn></mfrac>"
        );
        assert_eq!(
            inner(&root(&q(125, 1), Notation::Latex)),
            "<mrow><mn>5</mn><msqrt><mn>5</mn></msqrt></mrow>"
        );
    }

    proptest::proptest! {
        /// Law: any text (the LaTeX subset's characters, weighted towards its troublemakers)
        /// gives one `<math>` element, with no raw `<` or `&` from the input.
        #[test]
        fn any_input_gives_one_math_element(latex in r"[\\{}^_a-z0-9 (),.*/<>&|+=-]{0,40}") {
            let out = math(&latex, false);
            proptest::prop_assert!(out.starts_with("<math>") && out.ends_with("</math>"));
            proptest::prop_assert_eq!(out.matches("<math").count(), 1);
            // Every `&` starts an entity, every `<` a tag: nothing of the input is raw markup.
            for (i, _) in out.match_indices('&') {
                let rest = &out[i..];
                proptest::prop_assert!(
                    ["&amp;", "&lt;", "&gt;", "&quot;", "&#39;"].iter().any(|e| rest.starts_with(e)),
                    "{}", out
                );
            }
            for (i, _) in out.match_indices('<') {
                let next = out[i + 1..].chars().next();
                proptest::prop_assert!(next.is_some_and(|c| c.is_ascii_lowercase() || c == '/'), "{}", out);
            }
        }
    }

    /// An unknown command is shown, never silently dropped; unbalanced input does not panic.
    #[test]
    fn unknown_and_unbalanced_input() {
        assert_eq!(
            inner(r"\foo x"),
            "<mrow><merror><mtext>\\foo</mtext></merror><mi>x</mi></mrow>"
        );
        for broken in [
            r"\frac{1",
            "a^",
            r"\left(",
            r"\sqrt",
            "}}",
            r"\",
            r"\lvert x",
            "_{",
        ] {
            let out = math(broken, true);
            assert!(
                out.starts_with("<math") && out.ends_with("</math>"),
                "{broken}"
            );
        }
    }
}
