//! One line of `impact --batch` as JSON, read strictly: a key given twice in one object is
//! refused (serde_json's `Value` keeps the last silently, and a line with two `"claimed"` or two
//! `"omega"` is ambiguous input), naming the key's path.

use crate::error::{Error, ErrorKind};
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};
use std::cell::RefCell;
use std::fmt;

/// `text` as a JSON value, refusing a key repeated within one object.
///
/// # Errors
/// `not JSON: <serde_json's reason>` (field `line`); a repeated key as its path,
/// `claimed.bodies.rod.omega: given twice (a key may appear once in an object)`.
///
/// # Examples
/// ```
/// use rodimpact::batch::parse_line;
/// assert_eq!(parse_line(r#"{"a": [1, "x"]}"#)?, serde_json::json!({"a": [1, "x"]}));
/// let err = parse_line(r#"{"claimed": {"bodies": {"rod": {"omega": "1", "omega": "2"}}}}"#).unwrap_err();
/// assert_eq!(err.to_string(), "claimed.bodies.rod.omega: given twice (a key may appear once in an object)");
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn parse_line(text: &str) -> Result<Value, Error> {
    let twice = RefCell::new(None);
    let mut reader = serde_json::Deserializer::from_str(text);
    let parsed = Strict {
        path: String::new(),
        twice: &twice,
    }
    .deserialize(&mut reader)
    .and_then(|value| reader.end().map(|()| value));
    parsed.map_err(|e| match twice.take() {
        Some(path) => Error::new(
            path,
            ErrorKind::Invalid("given twice (a key may appear once in an object)".into()),
        ),
        None => Error::new("line", ErrorKind::Invalid(format!("not JSON: {e}"))),
    })
}

/// A value at `path` (dotted keys from the top); `twice` receives the path of a repeated key.
struct Strict<'a> {
    path: String,
    twice: &'a RefCell<Option<String>>,
}

impl<'de> DeserializeSeed<'de> for Strict<'_> {
    type Value = Value;

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Value, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Strict<'_> {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }

    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::Number(v.into()))
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Value, E> {
        Number::from_f64(v)
            .map(Value::Number)
            .ok_or_else(|| E::custom("not a finite number"))
    }

    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_owned()))
    }

    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }

    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut items = Vec::new();
        while let Some(item) = seq.next_element_seed(Strict {
            path: format!("{}[{}]", self.path, items.len() + 1),
            twice: self.twice,
        })? {
            items.push(item);
        }
        Ok(Value::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Value, A::Error> {
        let mut out = Map::new();
        while let Some(key) = map.next_key::<String>()? {
            let path = if self.path.is_empty() {
                crate::echo::echo(&key)
            } else {
                format!("{}.{}", self.path, crate::echo::echo(&key))
            };
            if out.contains_key(&key) {
                *self.twice.borrow_mut() = Some(path);
                return Err(de::Error::custom("a key given twice"));
            }
            let value = map.next_value_seed(Strict {
                path,
                twice: self.twice,
            })?;
            out.insert(key, value);
        }
        Ok(Value::Object(out))
    }
}
