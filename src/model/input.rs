//! A system as written: a scene file (TOML, `rodimpact impact FILE.toml`) or one line of a
//! batch (JSON, `rodimpact impact --batch FILE.jsonl`), the same structure either way, read
//! into a validated [`System`]. Numbers are exact as everywhere: strings such as `"3/7"`,
//! `"0.25"`, `"1.5e-3"`, with a unit of the field's dimension where one fits (`"200 g"`,
//! `"36 km/h"`), or integers; a floating-point literal is refused (it would not be read as
//! written).
//!
//! ```toml
//! title = "A tilted rod lands on its end on a rough floor"
//! [[body]]
//! name = "rod"
//! mass = "1"
//! shape = "rod"             # or inertia = "1/3"; also disc, box, polygon, point
//! length = "2"
//! axis = ["3", "4"]         # the rod's direction, not normalised
//! position = ["0", "4/5"]   # centre of mass
//! velocity = ["1", "-1"]
//! omega = "0"               # counterclockwise positive
//! [[body]]
//! name = "floor"
//! fixed = true              # the ground: a face through the contact point across the normal
//! [[contact]]
//! bodies = ["rod", "floor"] # A, B: the impulse on A is P, on B -P
//! point = ["-3/5", "0"]
//! normal = ["0", "1"]       # from B into A, not normalised
//! e = "1"                   # default 1
//! mu = "1/3"                # default 0
//! [[pin]]                   # optional: a body held at a point
//! body = "rod"
//! point = ["0", "4/5"]
//! ```

use super::shape::{Shape, is_convex};
use super::system::{Body, Contact, MAX_BODIES, Mobility, System, check_names};
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::mechanics::planar::Vec2;
use crate::units::{Dimension, parse_si};
use num_traits::{Signed, Zero};
use serde_json::{Map, Value};

/// The largest scene file or batch line read, in bytes.
pub const MAX_SCENE_BYTES: usize = 1 << 20;
/// The most vertices of a polygon.
pub const MAX_VERTICES: usize = 1_000;

/// Reads a scene file's text (TOML); `label` names the file in errors.
///
/// # Errors
/// The TOML's own error with its line, or the first bad field named `label: body[2].mass`.
///
/// # Examples
/// ```
/// use rodimpact::model::parse_toml;
/// let text = r#"
/// [[body]]
/// name = "ball"
/// mass = "200 g"
/// velocity = ["0", "-1"]
/// [[body]]
/// name = "floor"
/// fixed = true
/// [[contact]]
/// bodies = ["ball", "floor"]
/// point = ["0", "0"]
/// normal = ["0", "1"]
/// "#;
/// let system = parse_toml("ball.toml", text)?;
/// assert_eq!(system.bodies[0].mass.to_string(), "1/5");
/// let bad = text.replace("\"200 g\"", "\"-1\"");
/// assert_eq!(parse_toml("ball.toml", &bad).unwrap_err().to_string(),
///            "ball.toml: body[1].mass: must be > 0, got -1");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn parse_toml(label: &str, text: &str) -> Result<System, Error> {
    let value = toml_value(label, text)?;
    from_value(&value).map_err(|e| Error::new(format!("{label}: {}", e.field), e.kind))
}

/// A scene file's text (TOML) as its JSON form, unchecked: what [`from_value`] reads, and
/// where a scene's other tables (its published `claim`s) are found.
///
/// # Errors
/// The TOML's own error with its line, or a file over [`MAX_SCENE_BYTES`].
///
/// # Examples
/// ```
/// let v = rodimpact::model::toml_value("t.toml", "title = \"x\"\n[[claim]]\nlaw = \"newton\"\n")?;
/// assert_eq!(v["claim"][0]["law"], "newton");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn toml_value(label: &str, text: &str) -> Result<Value, Error> {
    if text.len() > MAX_SCENE_BYTES {
        return Err(Error::out_of_range(
            label,
            format!("file larger than {MAX_SCENE_BYTES} bytes (limit)"),
        ));
    }
    let table: toml::Table = toml::from_str(text).map_err(|e| {
        let line = e.span().map(|s| {
            format!(
                "line {}: ",
                text.get(..s.start).unwrap_or(text).matches('\n').count() + 1
            )
        });
        let message = e.message().lines().next().unwrap_or("invalid TOML");
        Error::new(
            label,
            ErrorKind::Invalid(format!("{}{message}", line.unwrap_or_default())),
        )
    })?;
    serde_json::to_value(&table)
        .map_err(|e| Error::new(label, ErrorKind::Invalid(format!("not a scene: {e}"))))
}

/// Reads a system from its JSON form (one line of `impact --batch`; a TOML file's structure).
///
/// # Errors
/// The first bad field, named (`body[2].mass`, `contact[1].normal`).
///
/// # Examples
/// ```
/// use rodimpact::model::from_value;
/// let v = serde_json::json!({
///     "body": [{"name": "puck", "mass": "1", "velocity": ["1", "0"]},
///              {"name": "wall", "fixed": true, "position": ["0", "0"]}],
///     "contact": [{"bodies": ["puck", "wall"], "point": ["0", "0"], "normal": ["-1", "0"], "e": "1/2"}]});
/// assert_eq!(from_value(&v)?.contacts[0].e.to_string(), "1/2");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn from_value(value: &Value) -> Result<System, Error> {
    let top = object(value, "scene")?;
    only_keys(
        top,
        "scene",
        &[
            "title", "body", "contact", "pin", "claimed", "claim", "source",
        ],
    )?;
    super::budget::check_scene_digits(top)?;
    let title = match top.get("title") {
        None => None,
        // The title is printed at the head of every report: no control character may reach
        // the terminal from it (a newline, ESC, CR or NUL).
        Some(Value::String(t)) if t.chars().any(char::is_control) => {
            return Err(invalid(
                "title",
                "no control characters (newlines, escapes), as in names".into(),
            ));
        }
        Some(Value::String(t)) => Some(t.clone()),
        Some(_) => return Err(invalid("title", "must be a string".into())),
    };
    let body_values = list(top, "body")?;
    if body_values.len() > MAX_BODIES {
        return Err(Error::out_of_range(
            "body",
            format!("more than {MAX_BODIES} bodies (limit)"),
        ));
    }
    let mut bodies = body_values
        .iter()
        .enumerate()
        .map(|(i, v)| body(&format!("body[{}]", i + 1), v))
        .collect::<Result<Vec<_>, _>>()?;
    check_names(&bodies)?;
    let names: Vec<String> = bodies.iter().map(|b| b.name.clone()).collect();
    let index_of = |field: &str, name: &Value| -> Result<usize, Error> {
        let Value::String(name) = name else {
            return Err(invalid(field, "a body's name (a string)".into()));
        };
        names.iter().position(|n| n == name).ok_or_else(|| {
            let all: Vec<&str> = names.iter().map(String::as_str).collect();
            let hint = crate::echo::did_you_mean(name, &all)
                .map(|n| format!("; did you mean '{}'?", crate::echo::echo(n)))
                .unwrap_or_default();
            invalid(
                field,
                format!("no body is named '{}'{hint}", crate::echo::echo(name)),
            )
        })
    };
    for (k, v) in list_or_empty(top, "pin")?.iter().enumerate() {
        let field = format!("pin[{}]", k + 1);
        let pin = object(v, &field)?;
        only_keys(pin, &field, &["body", "point"])?;
        let at = index_of(&format!("{field}.body"), required(pin, &field, "body")?)?;
        let point = vector(
            required(pin, &field, "point")?,
            &format!("{field}.point"),
            Dimension::Length,
        )?;
        match &bodies[at].mobility {
            Mobility::Free => bodies[at].mobility = Mobility::Pinned(point),
            Mobility::Pinned(_) => {
                return Err(invalid(
                    &format!("{field}.body"),
                    format!("'{}' is pinned twice: a body takes one pin", names[at]),
                ));
            }
            Mobility::Fixed => {
                return Err(invalid(
                    &format!("{field}.body"),
                    format!("'{}' is fixed: it needs no pin", names[at]),
                ));
            }
        }
    }
    let contacts = list(top, "contact")?
        .iter()
        .enumerate()
        .map(|(k, v)| {
            let field = format!("contact[{}]", k + 1);
            let c = object(v, &field)?;
            only_keys(c, &field, &["bodies", "point", "normal", "e", "mu"])?;
            let pair = match required(c, &field, "bodies")? {
                Value::Array(pair) if pair.len() == 2 => pair,
                _ => {
                    return Err(invalid(
                        &format!("{field}.bodies"),
                        "two body names, [A, B]".into(),
                    ));
                }
            };
            let a = index_of(&format!("{field}.bodies"), &pair[0])?;
            let b = index_of(&format!("{field}.bodies"), &pair[1])?;
            Ok(Contact {
                a,
                b,
                point: vector(
                    required(c, &field, "point")?,
                    &format!("{field}.point"),
                    Dimension::Length,
                )?,
                normal: vector(
                    required(c, &field, "normal")?,
                    &format!("{field}.normal"),
                    Dimension::Pure,
                )?,
                e: optional_number(c, &field, "e", Dimension::Pure)?
                    .unwrap_or_else(|| Q::from_integer(1.into())),
                mu: optional_number(c, &field, "mu", Dimension::Pure)?.unwrap_or_else(Q::zero),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    System::new(title, bodies, contacts)
}

/// One body of the file.
fn body(field: &str, v: &Value) -> Result<Body, Error> {
    let b = object(v, field)?;
    only_keys(
        b,
        field,
        &[
            "name",
            "fixed",
            "mass",
            "inertia",
            "shape",
            "radius",
            "length",
            "thickness",
            "width",
            "height",
            "axis",
            "vertices",
            "position",
            "velocity",
            "omega",
        ],
    )?;
    let name = match required(b, field, "name")? {
        Value::String(n)
            if !n.trim().is_empty() && n.len() <= 100 && !n.chars().any(char::is_control) =>
        {
            n.clone()
        }
        _ => {
            return Err(invalid(
                &format!("{field}.name"),
                "a non-empty name of at most 100 characters, no control characters".into(),
            ));
        }
    };
    let fixed = match b.get("fixed") {
        None => false,
        Some(Value::Bool(f)) => *f,
        Some(_) => return Err(invalid(&format!("{field}.fixed"), "true or false".into())),
    };
    let shape = shape(b, field)?;
    let position = match (b.get("position"), &shape) {
        (Some(p), _) => vector(p, &format!("{field}.position"), Dimension::Length)?,
        (None, Some(s @ Shape::Polygon { .. })) => s.centroid().expect("a polygon has a centroid"),
        (None, _) => Vec2::zero(),
    };
    if let Some(s @ Shape::Polygon { .. }) = &shape
        && s.centroid().as_ref() != Some(&position)
    {
        return Err(Error::out_of_range(
            format!("{field}.position"),
            "a polygon's position is its centroid (leave position out to take it)",
        ));
    }
    if fixed {
        for key in ["mass", "inertia", "velocity", "omega"] {
            if b.contains_key(key) {
                return Err(Error::new(
                    format!("{field}.{key}"),
                    ErrorKind::Conflict(
                        "a fixed body never moves: give it no mass or motion".into(),
                    ),
                ));
            }
        }
        return Ok(Body {
            name,
            mobility: Mobility::Fixed,
            mass: Q::zero(),
            inertia: Q::zero(),
            position,
            velocity: Vec2::zero(),
            omega: Q::zero(),
            shape,
        });
    }
    let mass = number(
        required(b, field, "mass")?,
        &format!("{field}.mass"),
        Dimension::Mass,
    )?;
    let inertia = match (
        optional_number(b, field, "inertia", Dimension::MomentOfInertia)?,
        &shape,
    ) {
        (Some(i), _) => i,
        (None, Some(s)) => s.inertia(&mass, &position),
        (None, None) => Q::zero(),
    };
    Ok(Body {
        name,
        mobility: Mobility::Free,
        mass,
        inertia,
        position,
        velocity: match b.get("velocity") {
            Some(v) => vector(v, &format!("{field}.velocity"), Dimension::Speed)?,
            None => Vec2::zero(),
        },
        omega: optional_number(b, field, "omega", Dimension::AngularSpeed)?.unwrap_or_else(Q::zero),
        shape,
    })
}

/// The body's shape from `shape` and its dimensions.
fn shape(b: &Map<String, Value>, field: &str) -> Result<Option<Shape>, Error> {
    let kind = match b.get("shape") {
        None => {
            for key in [
                "radius",
                "length",
                "thickness",
                "width",
                "height",
                "axis",
                "vertices",
            ] {
                if b.contains_key(key) {
                    return Err(Error::new(
                        format!("{field}.{key}"),
                        ErrorKind::Conflict("a dimension without a shape: add shape = ...".into()),
                    ));
                }
            }
            return Ok(None);
        }
        Some(Value::String(kind)) => kind.as_str(),
        Some(_) => {
            return Err(invalid(
                &format!("{field}.shape"),
                "point, disc, rod, box or polygon".into(),
            ));
        }
    };
    let keys: &[&str] = match kind {
        "point" => &[],
        "disc" => &["radius"],
        "rod" => &["length", "thickness", "axis"],
        "box" => &["width", "height", "axis"],
        "polygon" => &["vertices"],
        other => {
            return Err(invalid(
                &format!("{field}.shape"),
                format!(
                    "expected point, disc, rod, box or polygon, got '{}'",
                    crate::echo::echo(other)
                ),
            ));
        }
    };
    for key in [
        "radius",
        "length",
        "thickness",
        "width",
        "height",
        "axis",
        "vertices",
    ] {
        if b.contains_key(key) && !keys.contains(&key) {
            return Err(Error::new(
                format!("{field}.{key}"),
                ErrorKind::Conflict(format!("a {kind} has no {key}")),
            ));
        }
    }
    let positive = |key: &str| -> Result<Q, Error> {
        let x = number(
            required(b, field, key)?,
            &format!("{field}.{key}"),
            Dimension::Length,
        )?;
        if x.is_positive() {
            Ok(x)
        } else {
            Err(Error::out_of_range(
                format!("{field}.{key}"),
                format!("must be > 0, got {x}"),
            ))
        }
    };
    let axis = || -> Result<Vec2<Q>, Error> {
        let axis = match b.get("axis") {
            Some(v) => vector(v, &format!("{field}.axis"), Dimension::Pure)?,
            None => Vec2::new(Q::from_integer(1.into()), Q::zero()),
        };
        if axis.x.is_zero() && axis.y.is_zero() {
            return Err(Error::out_of_range(
                format!("{field}.axis"),
                "the axis is zero",
            ));
        }
        Ok(axis)
    };
    Ok(Some(match kind {
        "point" => Shape::Point,
        "disc" => Shape::Disc {
            radius: positive("radius")?,
        },
        "rod" => Shape::Rod {
            length: positive("length")?,
            thickness: match optional_number(b, field, "thickness", Dimension::Length)? {
                Some(h) if h.is_negative() => {
                    return Err(Error::out_of_range(
                        format!("{field}.thickness"),
                        format!("must be >= 0, got {h}"),
                    ));
                }
                Some(h) => h,
                None => Q::zero(),
            },
            axis: axis()?,
        },
        "box" => Shape::Box {
            width: positive("width")?,
            height: positive("height")?,
            axis: axis()?,
        },
        _ => {
            let vertices = match required(b, field, "vertices")? {
                Value::Array(vs) if (3..=MAX_VERTICES).contains(&vs.len()) => vs
                    .iter()
                    .enumerate()
                    .map(|(j, v)| {
                        vector(
                            v,
                            &format!("{field}.vertices[{}]", j + 1),
                            Dimension::Length,
                        )
                    })
                    .collect::<Result<Vec<_>, _>>()?,
                _ => {
                    return Err(invalid(
                        &format!("{field}.vertices"),
                        format!("3 to {MAX_VERTICES} vertices [x, y]"),
                    ));
                }
            };
            if !is_convex(&vertices) {
                return Err(Error::out_of_range(
                    format!("{field}.vertices"),
                    "the polygon must be convex, its vertices in order around it",
                ));
            }
            Shape::Polygon { vertices }
        }
    }))
}

fn object<'a>(v: &'a Value, field: &str) -> Result<&'a Map<String, Value>, Error> {
    v.as_object()
        .ok_or_else(|| invalid(field, "expected a table of keys".into()))
}

fn only_keys(map: &Map<String, Value>, field: &str, known: &[&str]) -> Result<(), Error> {
    match map.keys().find(|k| !known.contains(&k.as_str())) {
        Some(k) => Err(invalid(
            &format!("{field}.{}", crate::echo::echo(k)),
            match crate::echo::did_you_mean(k, known) {
                Some(near) => format!(
                    "unknown key: did you mean '{near}'? (expected one of {})",
                    known.join(", ")
                ),
                None => format!("unknown key (expected one of {})", known.join(", ")),
            },
        )),
        None => Ok(()),
    }
}

fn required<'a>(map: &'a Map<String, Value>, field: &str, key: &str) -> Result<&'a Value, Error> {
    map.get(key)
        .ok_or_else(|| Error::new(format!("{field}.{key}"), ErrorKind::Missing))
}

fn list<'a>(map: &'a Map<String, Value>, key: &str) -> Result<&'a Vec<Value>, Error> {
    match map.get(key) {
        Some(Value::Array(items)) if !items.is_empty() => Ok(items),
        Some(Value::Array(_)) | None => Err(Error::new(key, ErrorKind::Missing)),
        Some(_) => Err(invalid(key, format!("expected [[{key}]] tables"))),
    }
}

fn list_or_empty<'a>(map: &'a Map<String, Value>, key: &str) -> Result<&'a [Value], Error> {
    match map.get(key) {
        None => Ok(&[]),
        Some(Value::Array(items)) => Ok(items),
        Some(_) => Err(invalid(key, format!("expected [[{key}]] tables"))),
    }
}

/// An exact number: a string (with an optional unit of `dimension`) or an integer.
fn number(v: &Value, field: &str, dimension: Dimension) -> Result<Q, Error> {
    match v {
        Value::String(text) => parse_si(field, text, dimension),
        Value::Number(n) if n.is_i64() || n.is_u64() => parse_si(field, &n.to_string(), dimension),
        Value::Number(_) => Err(invalid(
            field,
            "a floating-point literal is not read exactly: write the number as a string (\"0.25\")"
                .into(),
        )),
        _ => Err(invalid(
            field,
            "expected a number (a string such as \"3/7\")".into(),
        )),
    }
}

fn optional_number(
    map: &Map<String, Value>,
    field: &str,
    key: &str,
    dimension: Dimension,
) -> Result<Option<Q>, Error> {
    map.get(key)
        .map(|v| number(v, &format!("{field}.{key}"), dimension))
        .transpose()
}

/// `[x, y]`.
fn vector(v: &Value, field: &str, dimension: Dimension) -> Result<Vec2<Q>, Error> {
    match v {
        Value::Array(xy) if xy.len() == 2 => Ok(Vec2::new(
            number(&xy[0], &format!("{field}[1]"), dimension)?,
            number(&xy[1], &format!("{field}[2]"), dimension)?,
        )),
        _ => Err(invalid(field, "expected two numbers [x, y]".into())),
    }
}

fn invalid(field: &str, why: String) -> Error {
    Error::new(field, ErrorKind::Invalid(why))
}
