//! A scene as given on the command line or in a problem file, every field read once: a number
//! with an optional unit, or a formula in the scene's symbols.

use crate::error::{Error, ErrorKind};
use crate::field::{Field, RatFn, Sym};
use crate::scene::{RodInertia, SceneInput, dimension_of};
use crate::textbook::claim::{ClaimedValue, read_value};
use crate::textbook::expr::{Budget, size_of};
use crate::units::Dimension;

/// The paper's numeric scene inputs in the order they are read, (key, text): every scene key
/// but the rod's kind and the oblique inputs.
fn numeric_fields(input: &SceneInput) -> impl Iterator<Item = (&'static str, &Option<String>)> {
    input
        .inputs()
        .filter(|(k, _)| !k.oblique && k.name != "rod")
        .map(|(k, text)| (k.name, text))
}

/// How the rod was given.
#[derive(Debug, Clone)]
pub(super) enum RodGiven {
    /// Not given: uniform, the default.
    Default,
    /// `uniform` or `dumbbell`.
    Named(RodInertia),
    /// `rg=F`: the radius of gyration.
    Gyration(RatFn),
    /// `I=F`: the moment of inertia about the centre.
    Moment(RatFn),
}

/// A scene as given, every value read once: numbers (in SI) as constant rational functions,
/// formulas in the scene's symbols (`L` and `d` already expanded).
#[derive(Debug, Clone)]
pub struct GivenScene {
    values: Vec<(&'static str, String, RatFn)>,
    pub(super) rod: RodGiven,
    formula: bool,
}

impl GivenScene {
    /// Reads every field of `input`: a number with an optional unit, or a formula (charged to
    /// `budget`).
    ///
    /// # Errors
    /// A field that is neither, naming it; a square root in a scene quantity; an unknown rod.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{scene::SceneInput, textbook::{expr::Budget, symbolic::GivenScene}};
    /// let s = SceneInput { m: Some("100 g".into()), rod_mass: Some("4*m".into()), ..Default::default() };
    /// assert!(GivenScene::read(&s, &mut Budget::run()).unwrap().has_formula());
    /// let s = SceneInput { m: Some("100 g".into()), ..Default::default() };
    /// assert!(!GivenScene::read(&s, &mut Budget::run()).unwrap().has_formula());
    /// ```
    pub fn read(input: &SceneInput, budget: &mut Budget) -> Result<GivenScene, Error> {
        let mut values = Vec::new();
        let mut formula = false;
        for (key, text) in numeric_fields(input) {
            if let Some(text) = text {
                let (value, is_formula) = value_of(key, text, dimension_of(key), budget)?;
                formula |= is_formula;
                values.push((key, text.trim().to_string(), value));
            }
        }
        let rod = match input.rod.as_deref().map(str::trim) {
            None => RodGiven::Default,
            Some(text) => {
                let read = |body: &str, dimension, budget: &mut Budget| {
                    value_of("rod", body, dimension, budget)
                };
                if let Some(body) = text.strip_prefix("rg=") {
                    let (r, is_formula) = read(body, Dimension::Length, budget)?;
                    formula |= is_formula;
                    RodGiven::Gyration(r)
                } else if let Some(body) = text.strip_prefix("I=") {
                    let (i, is_formula) = read(body, Dimension::MomentOfInertia, budget)?;
                    formula |= is_formula;
                    RodGiven::Moment(i)
                } else {
                    RodGiven::Named(RodInertia::parse(text)?)
                }
            }
        };
        Ok(GivenScene {
            values,
            rod,
            formula,
        })
    }

    /// Whether some field is a formula rather than a number.
    pub fn has_formula(&self) -> bool {
        self.formula
    }

    pub(super) fn get(&self, key: &str) -> Option<&RatFn> {
        self.values
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|(_, _, v)| v)
    }

    pub(super) fn text(&self, key: &str) -> Option<&str> {
        self.values
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|(_, t, _)| t.as_str())
    }
}

/// The given field whose value is largest (the words of its coefficients), the one to name when
/// solving the scene in symbols costs too much; `None` when no field is a formula. Every field
/// is read again on a budget of its own; a field that does not read counts for nothing (its
/// error is reported where the scene is read).
///
/// # Examples
/// ```
/// use rodimpact::{scene::SceneInput, textbook::symbolic::heaviest_field};
/// let s = SceneInput { rod_mass: Some("m*(l+12345678901234567890*v0)^3".into()), v0: Some("2*l".into()), ..Default::default() };
/// assert_eq!(heaviest_field(&s), Some("M"));
/// assert_eq!(heaviest_field(&SceneInput { rod_mass: Some("2".into()), ..Default::default() }), None);
/// ```
pub fn heaviest_field(input: &SceneInput) -> Option<&'static str> {
    input
        .inputs()
        .filter_map(|(key, text)| {
            let text = text.as_deref()?.trim();
            let (body, dimension) = match key.name {
                "rod" => text
                    .strip_prefix("rg=")
                    .map(|b| (b, Dimension::Length))
                    .or_else(|| {
                        text.strip_prefix("I=")
                            .map(|b| (b, Dimension::MomentOfInertia))
                    })?,
                name => (text, dimension_of(name)),
            };
            let (value, formula) = value_of(key.name, body, dimension, &mut Budget::run()).ok()?;
            formula.then(|| (size_of(&value), key.name))
        })
        .fold(
            None,
            |best: Option<(u64, &'static str)>, (size, name)| match best {
                Some((b, _)) if b >= size => best,
                _ => Some((size, name)),
            },
        )
        .map(|(_, name)| name)
}

/// A field's value, and whether it was a formula; `L` and `d` are expanded to `2*l` and
/// `l - a`.
pub(super) fn value_of(
    field: &str,
    text: &str,
    dimension: Dimension,
    budget: &mut Budget,
) -> Result<(RatFn, bool), Error> {
    let r = match read_value(field, text, dimension, budget)? {
        ClaimedValue::Printed(m) => {
            let si = m.si().ok_or_else(|| {
                Error::new(
                    field,
                    ErrorKind::Invalid("rpm is not a unit of a scene quantity".into()),
                )
            })?;
            return Ok((RatFn::from_rational(&si), false));
        }
        ClaimedValue::Formula(r) => r,
    };
    if !r.is_rational() {
        return Err(Error::new(
            field,
            ErrorKind::Invalid("a scene quantity cannot contain a square root".into()),
        ));
    }
    let (l, a) = (RatFn::symbol("l"), RatFn::symbol("a"));
    let value = r
        .coeff
        .subs_all(&[
            (Sym::new("L"), RatFn::from(2) * &l),
            (Sym::new("d"), l - &a),
        ])
        .ok_or_else(|| Error::new(field, ErrorKind::DivisionByZero))?;
    Ok((value, true))
}
