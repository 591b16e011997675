//! One table model, three formats: Markdown, LaTeX (booktabs) and CSV.
//!
//! Cells hold exact values ([`Cell::Rational`], [`Cell::Surd`], [`Cell::Root`]) and each
//! format prints them its own way: `2/3`, `\frac{2}{3}`; `2√6/5`, `\frac{2\sqrt{6}}{5}`,
//! `2/5*sqrt(6)`. Decimals are separate, correctly rounded cells.

use crate::field::{Q, QSqrt, TrySqrt};
use num_traits::{One, Signed, Zero};
use std::fmt::Write as _;

/// Output format of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// GitHub-flavoured Markdown.
    Markdown,
    /// LaTeX with booktabs; a complete document that compiles with plain `pdflatex`.
    Latex,
    /// Comma-separated values: exact strings and decimals, one header line per table.
    Csv,
}

impl Format {
    /// Parses `md`, `markdown`, `latex`, `tex` or `csv`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::report::Format;
    /// assert_eq!(Format::parse("tex"), Some(Format::Latex));
    /// assert_eq!(Format::parse("pdf"), None);
    /// ```
    pub fn parse(text: &str) -> Option<Format> {
        match text {
            "md" | "markdown" => Some(Format::Markdown),
            "latex" | "tex" => Some(Format::Latex),
            "csv" => Some(Format::Csv),
            _ => None,
        }
    }

    /// The usual file extension: `md`, `tex`, `csv`.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Markdown => "md",
            Format::Latex => "tex",
            Format::Csv => "csv",
        }
    }
}

/// One table cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// An exact rational.
    Rational(Q),
    /// An exact element x + y sqrt(d) of a quadratic field.
    Surd(QSqrt),
    /// The square root of a nonnegative rational, printed as a root (`√(2/3)`).
    Root(Q),
    /// Plain text (`yes`, `none`).
    Text(String),
}

impl Cell {
    /// The cell in `format`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::report::{Cell, Format};
    /// use rodimpact::field::{q, QSqrt};
    /// let c = Cell::Surd(QSqrt::sqrt_of(&q(24, 25)));
    /// assert_eq!(c.render(Format::Markdown), "2√6/5");
    /// assert_eq!(c.render(Format::Latex), r"$\frac{2\sqrt{6}}{5}$");
    /// assert_eq!(c.render(Format::Csv), "2/5*sqrt(6)");
    /// assert_eq!(Cell::Root(q(2, 3)).render(Format::Latex), r"$\sqrt{\frac{2}{3}}$");
    /// ```
    pub fn render(&self, format: Format) -> String {
        match (self, format) {
            (Cell::Text(t), Format::Latex) => latex_text(t),
            (Cell::Text(t), _) => t.clone(),
            (Cell::Rational(x), Format::Latex) => format!("${}$", latex_rational(x)),
            (Cell::Rational(x), _) => x.to_string(),
            (Cell::Surd(x), Format::Csv) => x.to_string(),
            (Cell::Surd(x), Format::Markdown) => surd(x, &Markdown),
            (Cell::Surd(x), Format::Latex) => format!("${}$", surd(x, &Latex)),
            (Cell::Root(x), _) => match x.try_sqrt() {
                Some(r) => Cell::Rational(r).render(format),
                None => match format {
                    Format::Csv => format!("sqrt({x})"),
                    Format::Markdown if x.is_integer() => format!("√{x}"),
                    Format::Markdown => format!("√({x})"),
                    Format::Latex => format!("$\\sqrt{{{}}}$", latex_rational(x)),
                },
            },
        }
    }
}

/// A column heading in each format.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    /// Markdown / plain heading.
    pub markdown: String,
    /// LaTeX heading (math allowed).
    pub latex: String,
    /// CSV column name (no commas, no spaces).
    pub csv: String,
}

impl Header {
    /// A heading from its three spellings.
    pub fn new(markdown: &str, latex: &str, csv: &str) -> Header {
        Header {
            markdown: markdown.into(),
            latex: latex.into(),
            csv: csv.into(),
        }
    }
}

/// A table: id, title, a note on units and conventions, headings and rows of cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Short id (`T1`).
    pub id: &'static str,
    /// Title.
    pub title: String,
    /// Units and conventions, printed under the title.
    pub note: String,
    /// Column headings.
    pub headers: Vec<Header>,
    /// Rows; each as long as `headers`.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// The table in `format` (a LaTeX `table` environment, without document preamble).
    pub fn render(&self, format: Format) -> String {
        match format {
            Format::Markdown => self.markdown(),
            Format::Latex => self.latex(),
            Format::Csv => self.csv(),
        }
    }

    fn markdown(&self) -> String {
        let mut out = format!("### {}. {}\n\n{}\n\n", self.id, self.title, self.note);
        let heads: Vec<&str> = self.headers.iter().map(|h| h.markdown.as_str()).collect();
        let _ = writeln!(out, "| {} |", heads.join(" | "));
        let _ = writeln!(out, "|{}", "---|".repeat(heads.len()));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|c| c.render(Format::Markdown).replace('|', "\\|"))
                .collect();
            let _ = writeln!(out, "| {} |", cells.join(" | "));
        }
        out
    }

    fn latex(&self) -> String {
        let mut out = String::from("\\begin{table}[ht]\n\\centering\n");
        let _ = writeln!(
            out,
            "\\caption{{{}. {}}}\\label{{tab:{}}}",
            latex_text(&self.title),
            latex_text(&self.note),
            self.id
        );
        let _ = writeln!(
            out,
            "\\begin{{tabular}}{{{}}}\n\\toprule",
            "l".repeat(self.headers.len())
        );
        let heads: Vec<&str> = self.headers.iter().map(|h| h.latex.as_str()).collect();
        let _ = writeln!(out, "{} \\\\\n\\midrule", heads.join(" & "));
        for row in &self.rows {
            let cells: Vec<String> = row.iter().map(|c| c.render(Format::Latex)).collect();
            let _ = writeln!(out, "{} \\\\", cells.join(" & "));
        }
        out.push_str("\\bottomrule\n\\end{tabular}\n\\end{table}\n");
        out
    }

    fn csv(&self) -> String {
        let mut out = String::new();
        let heads: Vec<String> = self.headers.iter().map(|h| csv_field(&h.csv)).collect();
        let _ = writeln!(out, "{}", heads.join(","));
        for row in &self.rows {
            let cells: Vec<String> = row
                .iter()
                .map(|c| csv_field(&c.render(Format::Csv)))
                .collect();
            let _ = writeln!(out, "{}", cells.join(","));
        }
        out
    }
}

/// Several tables as one document: Markdown sections, a complete LaTeX document (compiles
/// with plain `pdflatex`), or CSV blocks separated by a `# T1. title` comment line and a blank
/// line.
///
/// # Examples
/// ```
/// use rodimpact::report::{render_document, Cell, Format, Header, Table};
/// use rodimpact::field::q;
/// let t = Table { id: "T0", title: "Demo".into(), note: "Exact.".into(),
///     headers: vec![Header::new("x", "$x$", "x")], rows: vec![vec![Cell::Rational(q(1, 2))]] };
/// assert!(render_document(&[t.clone()], Format::Latex).contains(r"\documentclass"));
/// assert_eq!(render_document(&[t], Format::Csv), "# T0. Demo\nx\n1/2\n");
/// ```
pub fn render_document(tables: &[Table], format: Format) -> String {
    match format {
        Format::Markdown => tables
            .iter()
            .map(|t| t.render(format))
            .collect::<Vec<_>>()
            .join("\n"),
        Format::Csv => tables
            .iter()
            .map(|t| format!("# {}. {}\n{}", t.id, t.title, t.render(format)))
            .collect::<Vec<_>>()
            .join("\n"),
        Format::Latex => {
            let body: Vec<String> = tables.iter().map(|t| t.render(format)).collect();
            format!(
                "\\documentclass{{article}}\n\\usepackage{{amsmath}}\n\\usepackage{{booktabs}}\n\\usepackage[margin=2cm]{{geometry}}\n\\renewcommand{{\\arraystretch}}{{1.5}}\n\\begin{{document}}\n\n{}\n\\end{{document}}\n",
                body.join("\n")
            )
        }
    }
}

/// How a format writes roots and fractions.
trait Style {
    fn root(&self, d: &str) -> String;
    fn fraction(&self, num: &str, den: &str) -> String;
}

struct Markdown;
struct Latex;

impl Style for Markdown {
    fn root(&self, d: &str) -> String {
        format!("√{d}")
    }
    fn fraction(&self, num: &str, den: &str) -> String {
        format!("{num}/{den}")
    }
}

impl Style for Latex {
    fn root(&self, d: &str) -> String {
        format!("\\sqrt{{{d}}}")
    }
    fn fraction(&self, num: &str, den: &str) -> String {
        format!("\\frac{{{num}}}{{{den}}}")
    }
}

/// `x + y sqrt(d)` in a style: `2√6/5`, `1 - √2`, `\frac{2\sqrt{6}}{5}`.
fn surd(value: &QSqrt, style: &dyn Style) -> String {
    let rational = |x: &Q| {
        if x.is_integer() {
            x.numer().abs().to_string()
        } else {
            style.fraction(&x.numer().abs().to_string(), &x.denom().to_string())
        }
    };
    let (x, y) = (value.x(), value.y());
    let Some(d) = value.d().filter(|_| !y.is_zero()) else {
        let sign = if x.is_negative() { "-" } else { "" };
        return format!("{sign}{}", rational(x));
    };
    let root = style.root(&d.to_string());
    let numerator = if y.numer().abs().is_one() {
        root
    } else {
        format!("{}{root}", y.numer().abs())
    };
    let y_part = if y.denom().is_one() {
        numerator
    } else {
        style.fraction(&numerator, &y.denom().to_string())
    };
    match (x.is_zero(), x.is_negative(), y.is_negative()) {
        (true, _, neg_y) => format!("{}{y_part}", if neg_y { "-" } else { "" }),
        (false, neg_x, neg_y) => format!(
            "{}{} {} {y_part}",
            if neg_x { "-" } else { "" },
            rational(x),
            if neg_y { "-" } else { "+" }
        ),
    }
}

fn latex_rational(x: &Q) -> String {
    let sign = if x.is_negative() { "-" } else { "" };
    if x.is_integer() {
        format!("{sign}{}", x.numer().abs())
    } else {
        format!("{sign}\\frac{{{}}}{{{}}}", x.numer().abs(), x.denom())
    }
}

/// Plain text made safe for LaTeX: special characters escaped, `√` written as math.
fn latex_text(text: &str) -> String {
    let mut out = String::new();
    for ch in text.chars() {
        match ch {
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(ch);
            }
            '~' => out.push_str("\\textasciitilde{}"),
            '^' => out.push_str("\\textasciicircum{}"),
            '\\' => out.push_str("\\textbackslash{}"),
            '√' => out.push_str("$\\surd$"),
            '≤' => out.push_str("$\\le$"),
            '·' => out.push_str("$\\cdot$"),
            'ω' => out.push_str("$\\omega$"),
            'Δ' => out.push_str("$\\Delta$"),
            '²' => out.push_str("$^2$"),
            '≈' => out.push_str("$\\approx$"),
            _ => out.push(ch),
        }
    }
    out
}

fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}
