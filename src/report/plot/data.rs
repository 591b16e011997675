//! The sampled values behind a figure, as CSV: each exact value beside its decimal.

use crate::field::Q;
use crate::field::decimal;

/// Significant digits of the decimal columns (enough to round-trip an f64).
const DIGITS: usize = 17;

/// One value of a sample: an exact rational, or the square root of one (a*).
///
/// # Examples
/// ```
/// use rodimpact::{report::PlotValue, field::q};
/// let a_star = PlotValue::Root(q(2, 3));
/// assert_ne!(a_star, PlotValue::Exact(q(2, 3)));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// An exact rational.
    Exact(Q),
    /// `sqrt(x)` of the exact rational `x >= 0`.
    Root(Q),
}

impl Value {
    fn exact(&self) -> String {
        match self {
            Value::Exact(x) => x.to_string(),
            Value::Root(x) => decimal::surd(x),
        }
    }
    fn decimal(&self) -> String {
        match self {
            Value::Exact(x) => decimal::decimal(x, DIGITS),
            Value::Root(x) => decimal::decimal_sqrt(x, DIGITS),
        }
    }
}

/// The data of a figure: named columns, one row per sample point.
///
/// # Examples
/// ```
/// use rodimpact::{scene::Scene, field::q};
/// let s = Scene::builder(q(1, 1), q(1, 1)).build().unwrap();
/// let data = rodimpact::report::quantities_figure(&s).unwrap().data.unwrap();
/// assert_eq!(data.columns, ["a", "v", "V", "omega", "J", "lever_times_J"]);
/// assert_eq!(data.rows.len(), 201);
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlotData {
    /// Column names (the CSV has `name` with the exact value and `name_decimal` beside it).
    pub columns: Vec<String>,
    /// The rows, each as long as `columns`.
    pub rows: Vec<Vec<Value>>,
}

impl PlotData {
    /// Empty data with these columns.
    pub(crate) fn new(columns: &[&str]) -> PlotData {
        PlotData {
            columns: columns.iter().map(|c| c.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// The CSV text: a header, then one line per row; exact values and decimals correctly
    /// rounded to 17 significant digits.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::report::{PlotData, PlotValue};
    /// use rodimpact::field::q;
    /// let data = PlotData {
    ///     columns: vec!["a".into(), "a_star".into()],
    ///     rows: vec![vec![PlotValue::Exact(q(1, 2)), PlotValue::Root(q(2, 3))]],
    /// };
    /// assert_eq!(
    ///     data.to_csv(),
    ///     "a,a_decimal,a_star,a_star_decimal\n1/2,0.50000000000000000,sqrt(6)/3,0.81649658092772603\n"
    /// );
    /// ```
    pub fn to_csv(&self) -> String {
        let header: Vec<String> = self
            .columns
            .iter()
            .flat_map(|c| [c.clone(), format!("{c}_decimal")])
            .collect();
        let mut out = header.join(",");
        out.push('\n');
        for row in &self.rows {
            let fields: Vec<String> = row.iter().flat_map(|v| [v.exact(), v.decimal()]).collect();
            out.push_str(&fields.join(","));
            out.push('\n');
        }
        out
    }
}
