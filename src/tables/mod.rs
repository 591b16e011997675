//! The exact tables of the paper's results (T1-T6) as data: columns and rows of exact cells,
//! computed here ([`paper`]) and rendered by [`crate::report`] in Markdown, LaTeX, CSV or HTML.

pub mod paper;

use crate::field::{Q, QSqrt};

pub use paper::{
    ALL_TABLE_IDS, TABLE_IDS, TableOptions, all_tables, t1, t2, t3, t4, t5, t6, tables,
};

/// One table cell.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// An exact rational.
    Rational(Q),
    /// An exact element x + y sqrt(d) of a quadratic field.
    Surd(QSqrt),
    /// Plain text (`inside`, `centre`).
    Text(String),
    /// No value (a threshold that does not exist): `none` in Markdown and LaTeX, empty in CSV.
    Absent,
}

impl Cell {
    /// The square root of a rational `x >= 0`, exact.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::Cell;
    /// use rodimpact::field::q;
    /// assert_eq!(Cell::root(&q(2, 3)), Cell::Surd(rodimpact::field::QSqrt::sqrt_of(&q(2, 3))));
    /// ```
    pub fn root(x: &Q) -> Cell {
        Cell::Surd(QSqrt::sqrt_of(x))
    }
}

/// A column: its heading (`crate::report` markup), its CSV name, and whether Markdown and
/// LaTeX show its decimals beside it.
///
/// # Examples
/// ```
/// use rodimpact::tables::Column;
/// let c = Column::with_decimals("$v/v_0$", "v/v0");
/// assert_eq!((c.heading.as_str(), c.csv.as_str(), c.approx), ("$v/v_0$", "v/v0", true));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// The heading, plain text with `$…$` math (`$a^*/l$`).
    pub heading: String,
    /// The CSV column name: ASCII, no commas, units in the name (`v/v0`, `a_star/l`).
    pub csv: String,
    /// Show a `≈` column of decimals beside it (Markdown, LaTeX).
    pub approx: bool,
}

impl Column {
    /// A column of exact values (or text) only.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::Column;
    /// assert!(!Column::exact("$M/m$", "M/m").approx);
    /// ```
    pub fn exact(heading: &str, csv: &str) -> Column {
        Column {
            heading: heading.into(),
            csv: csv.into(),
            approx: false,
        }
    }

    /// A column of exact values followed by their decimals.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::tables::Column;
    /// assert!(Column::with_decimals("$a^*/l$", "a_star/l").approx);
    /// ```
    pub fn with_decimals(heading: &str, csv: &str) -> Column {
        Column {
            approx: true,
            ..Column::exact(heading, csv)
        }
    }
}

/// A table: id, title, a note on units and conventions, columns and rows of cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Short id (`T1`).
    pub id: &'static str,
    /// Title (`crate::report` markup).
    pub title: String,
    /// Units and conventions, printed under the title (`crate::report` markup).
    pub note: String,
    /// The columns.
    pub columns: Vec<Column>,
    /// Rows; each as long as `columns`.
    pub rows: Vec<Vec<Cell>>,
}
