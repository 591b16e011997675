//! Tolerances per class of rows (`batch --tolerance CLASS=RULE`): a CI job auditing an engine
//! wants ulps where the engine integrates freely and a relative error where a joint (a pivot)
//! is solved iteratively. A class is a kind of scene (`free`, `pivot`, `oblique`) or a pattern
//! of ids (`id:joint-*`); the first rule whose class takes a row sets its agreement, and rows no
//! rule takes keep the batch's own (`--rtol`, `--ulps` or exact).

use super::compare::Agreement;
use super::expected::matches;
use super::ulps::FloatFormat;
use crate::error::{Error, ErrorKind};
use crate::scene::{Scene, Support};

/// The rows a rule applies to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RowClass {
    /// A free rod (no pivot).
    Free,
    /// A rod on a pivot.
    Pivot,
    /// An oblique or frictional scene (a column `v0t`, `mu`, ... given).
    Oblique,
    /// Rows whose `id` matches the pattern (`*` stands for any text).
    Id(String),
}

/// One `--tolerance CLASS=RULE`.
#[derive(Debug, Clone, PartialEq)]
pub struct ClassRule {
    /// The rows it takes.
    pub class: RowClass,
    /// When their claims agree.
    pub agreement: Agreement,
}

impl ClassRule {
    /// Reads `CLASS=RULE`: CLASS `free`, `pivot`, `oblique` or `id:PATTERN`; RULE `rtol:R`,
    /// `ulps:N` (in `format`, --float's) or `exact`.
    ///
    /// # Errors
    /// `tolerance: ...` naming what is wrong.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Agreement, ClassRule, FloatFormat, RowClass};
    /// use rodimpact::field::q;
    /// let rule = ClassRule::parse("pivot=rtol:1e-6", FloatFormat::F64)?;
    /// assert_eq!(rule, ClassRule { class: RowClass::Pivot, agreement: Agreement::Relative(q(1, 1_000_000)) });
    /// let ids = ClassRule::parse("id:free-*=ulps:16", FloatFormat::F32)?;
    /// assert_eq!(ids.agreement, Agreement::Ulps(16, FloatFormat::F32));
    /// assert_eq!(ids.describe(), "rows with an id like free-*: within 16 f32 ulps of the exact value");
    /// assert_eq!(ClassRule::parse("joints=exact", FloatFormat::F64).unwrap_err().to_string(),
    ///     "tolerance: 'joints' is not a class: free, pivot, oblique or id:PATTERN");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn parse(text: &str, format: FloatFormat) -> Result<ClassRule, Error> {
        let invalid = |why: String| Error::new("tolerance", ErrorKind::Invalid(why));
        let echo = crate::echo::echo;
        let (class, rule) = text.split_once('=').ok_or_else(|| {
            invalid(format!(
                "'{}' is not CLASS=RULE (e.g. pivot=rtol:1e-6)",
                echo(text)
            ))
        })?;
        let class = match class.trim() {
            "free" => RowClass::Free,
            "pivot" => RowClass::Pivot,
            "oblique" => RowClass::Oblique,
            other => match other.strip_prefix("id:") {
                Some(pattern) if !pattern.is_empty() => RowClass::Id(pattern.to_string()),
                _ => {
                    return Err(invalid(format!(
                        "'{}' is not a class: free, pivot, oblique or id:PATTERN",
                        echo(other)
                    )));
                }
            },
        };
        let rule = rule.trim();
        let agreement = match rule.split_once(':') {
            _ if rule == "exact" => Agreement::Exact,
            Some(("rtol", r)) => Agreement::parse_rtol(r)?,
            Some(("ulps", n)) => Agreement::parse_ulps(n, format)?,
            _ => {
                return Err(invalid(format!(
                    "'{}' is not a rule: rtol:R, ulps:N or exact",
                    echo(rule)
                )));
            }
        };
        Ok(ClassRule { class, agreement })
    }

    /// Whether the rule takes a row with this scene and id.
    pub fn takes(&self, scene: &Scene, id: Option<&str>) -> bool {
        match &self.class {
            RowClass::Free => matches!(scene.support(), Support::Free),
            RowClass::Pivot => matches!(scene.support(), Support::Pivot(_)),
            RowClass::Oblique => scene.oblique().is_some(),
            RowClass::Id(pattern) => id.is_some_and(|id| matches(pattern, id)),
        }
    }

    /// The rule in words, as the batch's report prints it.
    pub fn describe(&self) -> String {
        let rows = match &self.class {
            RowClass::Free => "free-rod rows".to_string(),
            RowClass::Pivot => "pivot rows".to_string(),
            RowClass::Oblique => "oblique rows".to_string(),
            RowClass::Id(pattern) => format!("rows with an id like {}", crate::echo::echo(pattern)),
        };
        format!("{rows}: {}", self.agreement.describe())
    }
}
