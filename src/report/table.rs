//! One table model, three formats: Markdown, LaTeX (booktabs) and CSV.
//!
//! Cells hold exact values ([`Cell::Rational`], [`Cell::Surd`]); each format prints them in its
//! notation (`2√6/5`, `\frac{2\sqrt{6}}{5}`, `2*sqrt(6)/5`, see [`crate::field::notation`]) and
//! derives the decimals itself: a column marked [`Column::approx`] gets a `≈` column beside it
//! in Markdown and LaTeX (decimal-aligned there), and in CSV *every* numeric column gets a
//! `<name>_decimal` column. Titles, notes and headings are [`markup`](super::markup): plain
//! text with `$…$` math.

use super::{markup, mathml};
use crate::field::decimal;
use crate::field::notation::{self, Notation};
use crate::tables::{Cell, Table};
use std::fmt::Write as _;

/// Output format of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// GitHub-flavoured Markdown, the math in Unicode (readable in a terminal too).
    Markdown,
    /// LaTeX with booktabs and dcolumn; a complete document that compiles with plain `pdflatex`.
    Latex,
    /// Comma-separated values: exact strings beside decimals, one header line.
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
    ///
    /// # Examples
    /// ```
    /// use rodimpact::report::Format;
    /// assert_eq!(Format::Latex.extension(), "tex");
    /// ```
    pub fn extension(self) -> &'static str {
        match self {
            Format::Markdown => "md",
            Format::Latex => "tex",
            Format::Csv => "csv",
        }
    }
}

/// Significant digits of the `≈` columns in Markdown and LaTeX.
const TABLE_DIGITS: usize = 12;

/// Significant digits of the CSV decimals: enough to round-trip an `f64`.
const CSV_DIGITS: usize = 17;

impl Cell {
    /// The cell in `format`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Format, tables::Cell};
    /// use rodimpact::field::{q, QSqrt};
    /// let c = Cell::Surd(QSqrt::sqrt_of(&q(24, 25)));
    /// assert_eq!(c.render(Format::Markdown), "2√6/5");
    /// assert_eq!(c.render(Format::Latex), r"$\frac{2\sqrt{6}}{5}$");
    /// assert_eq!(c.render(Format::Csv), "2*sqrt(6)/5");
    /// assert_eq!(Cell::Absent.render(Format::Csv), "");
    /// ```
    pub fn render(&self, format: Format) -> String {
        match (self, format) {
            (Cell::Text(t), Format::Latex) => markup::latex(t),
            (Cell::Text(t), _) => t.clone(),
            (Cell::Absent, Format::Csv) => String::new(),
            (Cell::Absent, _) => "none".into(),
            (Cell::Rational(x), Format::Latex) => {
                format!("${}$", notation::rational(x, Notation::Latex))
            }
            (Cell::Rational(x), _) => x.to_string(),
            (Cell::Surd(x), Format::Latex) => format!("${}$", notation::surd(x, Notation::Latex)),
            (Cell::Surd(x), Format::Markdown) => notation::surd(x, Notation::Unicode),
            (Cell::Surd(x), Format::Csv) => notation::surd(x, Notation::Ascii),
        }
    }

    /// The value correctly rounded to `digits` significant digits, for a number; `None` for
    /// text and absent values.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::Cell;
    /// use rodimpact::field::q;
    /// assert_eq!(Cell::root(&q(2, 1)).decimal(5).as_deref(), Some("1.4142"));
    /// assert_eq!(Cell::Absent.decimal(5), None);
    /// ```
    pub fn decimal(&self, digits: usize) -> Option<String> {
        match self {
            Cell::Rational(x) => Some(decimal::decimal(x, digits)),
            Cell::Surd(x) => Some(x.decimal(digits)),
            Cell::Text(_) | Cell::Absent => None,
        }
    }

    /// The `≈` beside an exact value in Markdown and LaTeX: [`Cell::decimal`], without the
    /// trailing zeros of a value the digits hold exactly (`1/25` is `0.04`).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::Cell;
    /// use rodimpact::field::q;
    /// assert_eq!(Cell::Rational(q(1, 25)).approx(12).as_deref(), Some("0.04"));
    /// assert_eq!(Cell::root(&q(2, 1)).approx(5).as_deref(), Some("1.4142"));
    /// ```
    pub fn approx(&self, digits: usize) -> Option<String> {
        match self {
            Cell::Rational(x) => Some(decimal::decimal_short(x, digits)),
            Cell::Surd(x) => Some(x.decimal(digits)),
            Cell::Text(_) | Cell::Absent => None,
        }
    }

    fn is_number(&self) -> bool {
        matches!(self, Cell::Rational(_) | Cell::Surd(_))
    }
}

impl Table {
    /// The table in `format`: a Markdown section, a LaTeX `table` environment (without the
    /// document preamble), or a CSV file (header line, one line per row).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{report::Format, tables::{Cell, Column, Table}};
    /// use rodimpact::field::q;
    /// let t = Table { id: "T0", title: "Demo".into(), note: "$x$ exact.".into(),
    ///     columns: vec![Column::with_decimals("$x$", "x")], rows: vec![vec![Cell::Rational(q(1, 3))]] };
    /// assert_eq!(t.render(Format::Csv), "x,x_decimal\n1/3,0.33333333333333333\n");
    /// assert!(t.render(Format::Markdown).contains("| 1/3 | 0.333333333333 |"));
    /// ```
    pub fn render(&self, format: Format) -> String {
        match format {
            Format::Markdown => self.markdown(),
            Format::Latex => self.latex(),
            Format::Csv => csv_document(&[self]),
        }
    }

    /// The cell of `row` and its decimal when the column shows one (Markdown, LaTeX).
    fn shown_cells(&self, row: &[Cell], format: Format) -> Vec<String> {
        let mut out = Vec::new();
        for (cell, column) in row.iter().zip(&self.columns) {
            out.push(cell.render(format));
            if column.approx {
                out.push(cell.approx(TABLE_DIGITS).unwrap_or_default());
            }
        }
        out
    }

    /// The table in GitHub Markdown with its title, note and headings as GitHub math
    /// (`` $`a^*/l`$ ``), for `report.md`; [`Format::Markdown`] spells the math in Unicode.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::{Cell, Column, Table};
    /// use rodimpact::field::q;
    /// let t = Table { id: "T0", title: "Demo".into(), note: "$x$ exact.".into(),
    ///     columns: vec![Column::exact("$x$", "x")], rows: vec![vec![Cell::Rational(q(1, 3))]] };
    /// assert!(t.github_markdown().starts_with("### T0. Demo\n\n$`x`$ exact."));
    /// ```
    pub fn github_markdown(&self) -> String {
        self.markdown_with(markup::github)
    }

    /// The table as an HTML `<table>` for a web page: its id and title as the caption, the
    /// note under it, headings and exact values in MathML, the decimals beside them.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::{Cell, Column, Table};
    /// use rodimpact::field::q;
    /// let t = Table { id: "T0", title: "Demo".into(), note: "$x$ exact.".into(),
    ///     columns: vec![Column::with_decimals("$x$", "x")], rows: vec![vec![Cell::Rational(q(1, 3))]] };
    /// let html = t.html();
    /// assert!(html.starts_with("<table id=\"T0\">\n<caption>T0. Demo"));
    /// assert!(html.contains("<mfrac><mn>1</mn><mn>3</mn></mfrac>"));
    /// assert!(html.contains("<td class=\"decimal\">0.333333333333</td>"));
    /// ```
    pub fn html(&self) -> String {
        let mut out = format!(
            "<table id=\"{}\">\n<caption>{}. {}<br><span class=\"note\">{}</span></caption>\n<thead><tr>",
            self.id,
            self.id,
            mathml::text(&self.title),
            mathml::text(&self.note)
        );
        for column in &self.columns {
            let _ = write!(
                out,
                "<th scope=\"col\">{}</th>",
                mathml::text(&column.heading)
            );
            if column.approx {
                out.push_str("<th scope=\"col\" class=\"decimal\">≈</th>");
            }
        }
        out.push_str("</tr></thead>\n<tbody>\n");
        for row in &self.rows {
            out.push_str("<tr>");
            for (cell, column) in row.iter().zip(&self.columns) {
                let shown = match cell {
                    Cell::Text(t) => mathml::text(t),
                    Cell::Absent => "none".into(),
                    Cell::Rational(_) | Cell::Surd(_) => mathml::text(&cell.render(Format::Latex)),
                };
                let _ = write!(out, "<td>{shown}</td>");
                if column.approx {
                    let _ = write!(
                        out,
                        "<td class=\"decimal\">{}</td>",
                        cell.approx(TABLE_DIGITS).unwrap_or_default()
                    );
                }
            }
            out.push_str("</tr>\n");
        }
        out.push_str("</tbody>\n</table>\n");
        out
    }

    fn markdown(&self) -> String {
        self.markdown_with(markup::unicode)
    }

    fn markdown_with(&self, math: fn(&str) -> String) -> String {
        let mut out = format!(
            "### {}. {}\n\n{}\n\n",
            self.id,
            math(&self.title),
            math(&self.note)
        );
        let mut heads = Vec::new();
        for column in &self.columns {
            heads.push(math(&column.heading));
            if column.approx {
                heads.push("≈".into());
            }
        }
        let _ = writeln!(out, "| {} |", heads.join(" | "));
        let _ = writeln!(out, "|{}", "---|".repeat(heads.len()));
        for row in &self.rows {
            let cells: Vec<String> = self
                .shown_cells(row, Format::Markdown)
                .iter()
                .map(|c| c.replace('|', "\\|"))
                .collect();
            let _ = writeln!(out, "| {} |", cells.join(" | "));
        }
        out
    }

    /// The dcolumn specification `D{.}{.}{b.a}` of a decimal column: `b` digits (and sign)
    /// before the point, `a` after, the widest of the column.
    fn decimal_spec(&self, index: usize) -> String {
        let (mut before, mut after) = (1, 0);
        for row in &self.rows {
            if let Some(d) = row[index].approx(TABLE_DIGITS) {
                let (int, frac) = d.split_once('.').unwrap_or((&d, ""));
                before = before.max(int.len());
                after = after.max(frac.len());
            }
        }
        format!("D{{.}}{{.}}{{{before}.{after}}}")
    }

    fn latex(&self) -> String {
        let mut spec = String::new();
        let mut heads = Vec::new();
        for (i, column) in self.columns.iter().enumerate() {
            let numeric = self.rows.iter().any(|r| r[i].is_number());
            spec.push(if numeric { 'c' } else { 'l' });
            heads.push(markup::latex(&column.heading));
            if column.approx {
                spec.push_str(&self.decimal_spec(i));
                heads.push("\\multicolumn{1}{c}{$\\approx$}".into());
            }
        }
        let mut out = String::from("\\begin{table}[ht]\n\\centering\n");
        if heads.len() > 9 {
            // Ten columns and more (T6 with a disc) fit the page with narrower gaps.
            out.push_str("\\setlength{\\tabcolsep}{4pt}\n");
        }
        let _ = writeln!(
            out,
            "\\caption{{{}. {}}}\\label{{tab:{}}}",
            markup::latex(&self.title),
            markup::latex(&self.note),
            self.id
        );
        let _ = writeln!(out, "\\begin{{tabular}}{{{spec}}}\n\\toprule");
        let _ = writeln!(out, "{} \\\\\n\\midrule", heads.join(" & "));
        for row in &self.rows {
            let mut cells = Vec::new();
            for (cell, column) in row.iter().zip(&self.columns) {
                cells.push(cell.render(Format::Latex));
                if column.approx {
                    // A decimal column is typeset in math mode; no number: an empty cell.
                    cells.push(cell.approx(TABLE_DIGITS).unwrap_or_default());
                }
            }
            let _ = writeln!(out, "{} \\\\", cells.join(" & "));
        }
        out.push_str("\\bottomrule\n\\end{tabular}\n\\end{table}\n");
        out
    }

    /// The CSV columns: each column's name, followed for a numeric column by `<name>_decimal`.
    fn csv_names(&self) -> Vec<String> {
        let mut names = Vec::new();
        for (i, column) in self.columns.iter().enumerate() {
            names.push(column.csv.clone());
            if self.rows.iter().any(|r| r[i].is_number()) {
                names.push(format!("{}_decimal", column.csv));
            }
        }
        names
    }

    /// One row's CSV cells, by column name.
    fn csv_row(&self, row: &[Cell]) -> Vec<(String, String)> {
        let mut cells = Vec::new();
        for (i, (cell, column)) in row.iter().zip(&self.columns).enumerate() {
            cells.push((column.csv.clone(), cell.render(Format::Csv)));
            if self.rows.iter().any(|r| r[i].is_number()) {
                cells.push((
                    format!("{}_decimal", column.csv),
                    cell.decimal(CSV_DIGITS).unwrap_or_default(),
                ));
            }
        }
        cells
    }
}

/// Several tables as one CSV file. One table: its own header and rows. Several: one
/// rectangular file whose first column `table` names the table (`T1`), followed by the union of
/// the tables' columns in order of first appearance; a cell is empty where its table has no
/// such column (a column of the same name means the same quantity in every table).
fn csv_document(tables: &[&Table]) -> String {
    let tagged = tables.len() > 1;
    let mut names: Vec<String> = Vec::new();
    for t in tables {
        for name in t.csv_names() {
            if !names.contains(&name) {
                names.push(name);
            }
        }
    }
    let mut out = String::new();
    let header: Vec<String> = tagged
        .then(|| "table".to_string())
        .into_iter()
        .chain(names.iter().cloned())
        .map(|n| csv_field(&n))
        .collect();
    let _ = writeln!(out, "{}", header.join(","));
    for t in tables {
        for row in &t.rows {
            let cells = t.csv_row(row);
            let line: Vec<String> = tagged
                .then(|| t.id.to_string())
                .into_iter()
                .chain(names.iter().map(|name| {
                    cells
                        .iter()
                        .find(|(n, _)| n == name)
                        .map(|(_, v)| v.clone())
                        .unwrap_or_default()
                }))
                .map(|c| csv_field(&c))
                .collect();
            let _ = writeln!(out, "{}", line.join(","));
        }
    }
    out
}

/// Several tables as one document: Markdown sections, a complete LaTeX document (compiles
/// with plain `pdflatex`), or one CSV file (see [`Table::render`]; several tables share one
/// rectangular file with a leading `table` column).
///
/// # Examples
/// ```
/// use rodimpact::{report::{render_document, Format}, tables::{Cell, Column, Table}};
/// use rodimpact::field::q;
/// let t = |id, x| Table { id, title: "Demo".into(), note: "Exact.".into(),
///     columns: vec![Column::exact("$x$", "x")], rows: vec![vec![Cell::Rational(x)]] };
/// assert!(render_document(&[t("T0", q(1, 2))], Format::Latex).contains(r"\documentclass"));
/// assert_eq!(render_document(&[t("T0", q(1, 2))], Format::Csv), "x,x_decimal\n1/2,0.50000000000000000\n");
/// assert_eq!(
///     render_document(&[t("T0", q(1, 2)), t("T9", q(2, 1))], Format::Csv),
///     "table,x,x_decimal\nT0,1/2,0.50000000000000000\nT9,2,2.0000000000000000\n"
/// );
/// ```
pub fn render_document(tables: &[Table], format: Format) -> String {
    match format {
        Format::Markdown => tables
            .iter()
            .map(|t| t.render(format))
            .collect::<Vec<_>>()
            .join("\n"),
        Format::Csv => csv_document(&tables.iter().collect::<Vec<_>>()),
        Format::Latex => {
            let body: Vec<String> = tables.iter().map(|t| t.render(format)).collect();
            super::latex_document(
                &[
                    "\\usepackage{booktabs}",
                    "\\usepackage{dcolumn}",
                    // The caption sits above the table: keep a gap between it and the rule.
                    "\\usepackage[tableposition=top,skip=6pt]{caption}",
                    "\\usepackage[margin=2cm]{geometry}",
                    "\\renewcommand{\\arraystretch}{1.5}",
                ],
                &format!("{}\n", body.join("\n")),
            )
        }
    }
}

fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}
