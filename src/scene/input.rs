//! A scene as the user typed it: every number still a string, each parsed with its field name
//! and an optional unit of the field's dimension.

use super::keys::{SCENE_KEYS, SceneKey, scene_key};
use super::{RodInertia, Scene, conflict, spin_without_disc};
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::number;
use crate::units::{Dimension, parse_si};
use num_traits::{One, Signed};

/// A scene as the user typed it: every number still a string, each parsed with its field name.
///
/// This is what the command line and scene files fill in; [`SceneInput::build`] turns it into a
/// [`Scene`] or one error naming the field.
#[derive(Debug, Clone, Default)]
pub struct SceneInput {
    /// Projectile mass (required).
    pub m: Option<String>,
    /// Rod mass (required).
    pub rod_mass: Option<String>,
    /// Half-length l (default 1).
    pub l: Option<String>,
    /// Full length L = 2l, the textbook alternative to `l`.
    pub length: Option<String>,
    /// Impact distance from the centre (default l).
    pub a: Option<String>,
    /// Impact distance from the nearer end, a = l - d, the textbook alternative to `a`.
    pub from_end: Option<String>,
    /// Projectile speed (default 1).
    pub v0: Option<String>,
    /// `uniform`, `dumbbell`, `rg=Q` or `I=Q` (default uniform).
    pub rod: Option<String>,
    /// Coefficient of restitution (default 1).
    pub e: Option<String>,
    /// Pivot position, if the rod is pivoted.
    pub pivot: Option<String>,
    /// The projectile's velocity along the rod (default 0).
    pub v0t: Option<String>,
    /// Coulomb friction coefficient at the contact (default 0).
    pub mu: Option<String>,
    /// Radius of a disc projectile (default: a point projectile).
    pub radius: Option<String>,
    /// The disc's spin before the impact, counterclockwise seen from above (needs `radius`).
    pub spin: Option<String>,
    /// The rod centre's velocity across the rod before the impact (default 0).
    pub rod_v: Option<String>,
    /// The rod centre's velocity along the rod before the impact (default 0).
    pub rod_vt: Option<String>,
    /// The rod's angular velocity before the impact (default 0).
    pub rod_omega: Option<String>,
}

impl SceneInput {
    /// Every input in the order of [`SCENE_KEYS`](super::SCENE_KEYS), with its key.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// let input = SceneInput { m: Some("2".into()), rod_v: Some("1".into()), ..Default::default() };
    /// let given: Vec<_> = input.inputs().filter(|(_, t)| t.is_some()).map(|(k, _)| k.name).collect();
    /// assert_eq!(given, ["m", "rod-v"]);
    /// ```
    pub fn inputs(&self) -> impl Iterator<Item = (&'static SceneKey, &Option<String>)> {
        let fields = [
            &self.m,
            &self.rod_mass,
            &self.l,
            &self.length,
            &self.a,
            &self.from_end,
            &self.v0,
            &self.rod,
            &self.e,
            &self.pivot,
            &self.v0t,
            &self.mu,
            &self.radius,
            &self.spin,
            &self.rod_v,
            &self.rod_vt,
            &self.rod_omega,
        ];
        SCENE_KEYS.iter().zip(fields)
    }

    /// The oblique inputs by name, in the order they are read: `v0t`, `mu`, `radius`, `spin`,
    /// `rod-v`, `rod-vt`, `rod-omega`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// let input = SceneInput { mu: Some("1/4".into()), ..Default::default() };
    /// let given: Vec<_> = input.oblique_inputs().filter(|(_, t)| t.is_some()).map(|(k, _)| k).collect();
    /// assert_eq!(given, ["mu"]);
    /// ```
    pub fn oblique_inputs(&self) -> impl Iterator<Item = (&'static str, &Option<String>)> {
        self.inputs()
            .filter(|(k, _)| k.oblique)
            .map(|(k, text)| (k.name, text))
    }

    /// The first oblique input given, if any (the scene is then oblique or frictional).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// assert_eq!(SceneInput { spin: Some("3".into()), ..Default::default() }.first_oblique(), Some("spin"));
    /// assert_eq!(SceneInput::default().first_oblique(), None);
    /// ```
    pub fn first_oblique(&self) -> Option<&'static str> {
        self.oblique_inputs()
            .find_map(|(key, text)| text.is_some().then_some(key))
    }

    /// The slot of the input named `key` (a key of [`SCENE_KEYS`](super::SCENE_KEYS): the
    /// command-line flag without dashes), or `None` for an unknown key.
    ///
    /// Scene files, batch columns and tests fill a scene by name through this one map.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// let mut input = SceneInput::default();
    /// *input.slot("M").unwrap() = Some("3".into());
    /// assert_eq!(input.rod_mass.as_deref(), Some("3"));
    /// assert!(input.slot("mass").is_none());
    /// ```
    pub fn slot(&mut self, key: &str) -> Option<&mut Option<String>> {
        let index = SCENE_KEYS.iter().position(|k| k.name == key)?;
        let fields = [
            &mut self.m,
            &mut self.rod_mass,
            &mut self.l,
            &mut self.length,
            &mut self.a,
            &mut self.from_end,
            &mut self.v0,
            &mut self.rod,
            &mut self.e,
            &mut self.pivot,
            &mut self.v0t,
            &mut self.mu,
            &mut self.radius,
            &mut self.spin,
            &mut self.rod_v,
            &mut self.rod_vt,
            &mut self.rod_omega,
        ];
        fields.into_iter().nth(index)
    }

    /// Parses and validates every field. Numbers may carry a unit of their field's dimension
    /// (`100 g`, `120 cm`, `36 km/h`), converted exactly to SI.
    ///
    /// # Errors
    /// The first bad field: missing `m`/`M`, a number that does not parse, conflicting
    /// alternatives (`l` with `length`, `a` with `from-end`), or a violated constraint.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::scene::SceneInput;
    /// use rodimpact::field::q;
    /// let input = SceneInput {
    ///     m: Some("0.25".into()),
    ///     rod_mass: Some("3/4".into()),
    ///     length: Some("2".into()),
    ///     from_end: Some("1/2".into()),
    ///     ..Default::default()
    /// };
    /// let s = input.build().unwrap();
    /// assert_eq!((s.m(), s.half_length(), s.a()), (&q(1, 4), &q(1, 1), &q(1, 2)));
    /// let grams = SceneInput { m: Some("100 g".into()), rod_mass: Some("1.5kg".into()), ..Default::default() };
    /// assert_eq!(grams.build().unwrap().m(), &q(1, 10));
    /// let bad = SceneInput { m: Some("1/0".into()), rod_mass: Some("1".into()), ..Default::default() };
    /// assert_eq!(bad.build().unwrap_err().to_string(), "m: division by zero");
    /// ```
    pub fn build(&self) -> Result<Scene, Error> {
        let m = required("m", &self.m)?;
        let rod_mass = required("M", &self.rod_mass)?;
        let mut builder = Scene::builder(m, rod_mass);
        let half_length = match (&self.l, &self.length) {
            (Some(_), Some(_)) => {
                return Err(conflict("length", "give either --l or --length, not both"));
            }
            (Some(l), None) => number_of("l", l)?,
            (None, Some(len)) => {
                let len = number_of("length", len)?;
                if !len.is_positive() {
                    return Err(Error::out_of_range(
                        "length",
                        format!("must be > 0, got {len}"),
                    ));
                }
                len / Q::from_integer(2.into())
            }
            (None, None) => Q::one(),
        };
        builder = builder.half_length(half_length.clone());
        match (&self.a, &self.from_end) {
            (Some(_), Some(_)) => {
                return Err(conflict(
                    "from-end",
                    "give either --a or --from-end, not both",
                ));
            }
            (Some(a), None) if a.replace(' ', "").trim_start_matches(['+', '-']) == "a*" => {
                return Err(Error::new(
                    "a",
                    ErrorKind::Invalid(
                        "a* is not a number here: solve prints a* and omega_max for the scene; `check --a a*` and `explore` strike at a* exactly".into(),
                    ),
                ));
            }
            (Some(a), None) => builder = builder.a(number_of("a", a)?),
            (None, Some(d)) => {
                let d = number_of("from-end", d)?;
                if d.is_negative() || d > &half_length * Q::from_integer(2.into()) {
                    return Err(Error::out_of_range(
                        "from-end",
                        format!(
                            "distance from the end must lie in [0, 2l] = [0, {}], got {d}",
                            &half_length * Q::from_integer(2.into())
                        ),
                    ));
                }
                builder = builder.a(&half_length - d);
            }
            (None, None) => {}
        }
        if let Some(v0) = &self.v0 {
            builder = builder.v0(number_of("v0", v0)?);
        }
        if let Some(rod) = &self.rod {
            builder = builder.rod(RodInertia::parse(rod)?);
        }
        if let Some(e) = &self.e {
            builder = builder.e(number_of("e", e)?);
        }
        if let Some(p) = &self.pivot {
            builder = builder.pivot(number_of("pivot", p)?);
        }
        let optional = |key: &str, text: &Option<String>| -> Result<Option<Q>, Error> {
            text.as_deref().map(|t| number_of(key, t)).transpose()
        };
        if let Some(v0t) = optional("v0t", &self.v0t)? {
            builder = builder.v0t(v0t);
        }
        if let Some(mu) = optional("mu", &self.mu)? {
            builder = builder.mu(mu);
        }
        match (
            optional("radius", &self.radius)?,
            optional("spin", &self.spin)?,
        ) {
            (Some(radius), spin) => builder = builder.disc(radius, spin.unwrap_or_default()),
            (None, Some(_)) => return Err(spin_without_disc()),
            (None, None) => {}
        }
        let rod = [
            optional("rod-v", &self.rod_v)?,
            optional("rod-vt", &self.rod_vt)?,
            optional("rod-omega", &self.rod_omega)?,
        ];
        if rod.iter().any(Option::is_some) {
            let [v, vt, omega] = rod.map(Option::unwrap_or_default);
            builder = builder.rod_before(v, vt, omega);
        }
        builder.build()
    }
}

/// The dimension of the numeric scene input named `key` (`m`, `M`, `l`, `length`, `a`,
/// `from-end`, `v0`, `e`, `pivot`, `v0t`, `mu`, `radius`, `spin`, `rod-v`, `rod-vt`,
/// `rod-omega`): what a unit written after its number must measure.
///
/// # Examples
/// ```
/// use rodimpact::{scene::dimension_of, units::Dimension};
/// assert_eq!(dimension_of("from-end"), Dimension::Length);
/// assert_eq!(dimension_of("e"), Dimension::Pure);
/// ```
pub fn dimension_of(key: &str) -> Dimension {
    scene_key(key).map_or(Dimension::Pure, |k| k.dimension)
}

/// The numeric scene input `key`, with an optional unit of its dimension, in SI.
fn number_of(key: &str, text: &str) -> Result<Q, Error> {
    parse_si(key, text, dimension_of(key))
}

fn required(field: &str, text: &Option<String>) -> Result<Q, Error> {
    match text {
        Some(t) => number_of(field, t),
        None => Err(Error::new(field, ErrorKind::Missing)),
    }
}

/// Parses one number, naming `field` in the error.
///
/// # Examples
/// ```
/// use rodimpact::scene::parse_field;
/// assert_eq!(parse_field("a", "0.5").unwrap().to_string(), "1/2");
/// assert_eq!(parse_field("a", "").unwrap_err().to_string(), "a: empty number");
/// ```
pub fn parse_field(field: &str, text: &str) -> Result<Q, Error> {
    number::parse(text).map_err(|kind| Error::new(field, kind))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    fn input(pairs: &[(&str, &str)]) -> SceneInput {
        let mut s = SceneInput::default();
        for (k, v) in pairs {
            *s.slot(k).expect("a known test key") = Some(v.to_string());
        }
        s
    }

    #[test]
    fn inertia_of_each_rod_kind() {
        let cases = [
            ("uniform", "3", "2", q(4, 1)),
            ("dumbbell", "3", "2", q(12, 1)),
            ("rg=1", "3", "2", q(3, 1)),
            ("I=5/2", "3", "2", q(5, 2)),
        ];
        for (rod, big_m, l, want) in cases {
            let s = input(&[("m", "1"), ("M", big_m), ("l", l), ("rod", rod)])
                .build()
                .unwrap();
            assert_eq!(s.inertia(), want, "rod {rod}");
        }
    }

    #[test]
    fn bad_inputs_name_their_field() {
        let cases: &[(&[(&str, &str)], &str)] = &[
            (&[("M", "1")], "m: required, but not given"),
            (&[("m", "1")], "M: required, but not given"),
            (&[("m", "-1"), ("M", "1")], "m: must be > 0, got -1"),
            (&[("m", "1"), ("M", "0")], "M: must be > 0, got 0"),
            (
                &[("m", "1"), ("M", "1"), ("l", "0")],
                "l: must be > 0, got 0",
            ),
            (
                &[("m", "1"), ("M", "1"), ("v0", "-2")],
                "v0: must be > 0, got -2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "2")],
                "a: must lie on the rod, |a| <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "-3/2")],
                "a: must lie on the rod, |a| <= l = 1, got -3/2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("e", "3/2")],
                "e: coefficient of restitution must lie in [0, 1], got 3/2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("e", "-1")],
                "e: coefficient of restitution must lie in [0, 1], got -1",
            ),
            (
                &[("m", "1"), ("M", "1"), ("pivot", "2")],
                "pivot: must lie on the rod, |pivot| <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "rg=2")],
                "rod: radius of gyration must satisfy 0 < r_G <= l = 1, got 2",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "rg=0")],
                "rod: radius of gyration must satisfy 0 < r_G <= l = 1, got 0",
            ),
            (
                &[("m", "1"), ("M", "2"), ("rod", "I=3")],
                "rod: moment of inertia must satisfy 0 < I <= M l^2 = 2, got 3",
            ),
            (
                &[("m", "1"), ("M", "1"), ("rod", "wood")],
                "rod: expected uniform, dumbbell, rg=<radius> or I=<inertia>, got 'wood'",
            ),
            (
                &[("m", "1"), ("M", "1"), ("l", "1"), ("length", "2")],
                "length: give either --l or --length, not both",
            ),
            (
                &[("m", "1"), ("M", "1"), ("a", "1"), ("from-end", "0")],
                "from-end: give either --a or --from-end, not both",
            ),
            (
                &[("m", "1"), ("M", "1"), ("from-end", "3")],
                "from-end: distance from the end must lie in [0, 2l] = [0, 2], got 3",
            ),
            (
                &[("m", "1"), ("M", "1"), ("length", "-2")],
                "length: must be > 0, got -2",
            ),
            (&[("m", "1/0"), ("M", "1")], "m: division by zero"),
        ];
        for (pairs, want) in cases {
            let err = input(pairs).build().unwrap_err();
            assert_eq!(err.to_string(), *want, "input {pairs:?}");
        }
    }

    #[test]
    fn textbook_conveniences_convert_exactly() {
        let s = input(&[("m", "1"), ("M", "1"), ("length", "3"), ("from-end", "0.5")])
            .build()
            .unwrap();
        assert_eq!(s.half_length(), &q(3, 2));
        assert_eq!(s.a(), &q(1, 1));
        let far = input(&[("m", "1"), ("M", "1"), ("length", "3"), ("from-end", "3")])
            .build()
            .unwrap();
        assert_eq!(far.a(), &q(-3, 2));
    }

    #[test]
    fn defaults_are_those_of_solve() {
        let s = input(&[("m", "1"), ("M", "2")]).build().unwrap();
        assert_eq!(
            (s.half_length(), s.a(), s.v0(), s.e()),
            (&q(1, 1), &q(1, 1), &q(1, 1), &q(1, 1))
        );
        assert_eq!(s.rod(), &RodInertia::Uniform);
        assert_eq!(s.support(), &super::super::Support::Free);
    }
}
