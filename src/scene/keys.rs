//! The one table of scene inputs: every key a scene can be given by, with its dimension, its
//! spelling in a problem file, whether it is a batch column and whether it makes a scene
//! oblique, and the help text of its command-line flag.
//!
//! The command-line flags (`crates/rodimpact-cli/src/commands/mod.rs`) take their help from here, `batch` its scene
//! columns, [`SceneInput::slot`](super::SceneInput::slot) its keys, [`dimension_of`](super::dimension_of)
//! the units a key accepts, and the symbolic readers their lists of numeric and oblique inputs.
//! A new numeric input is one row here and one field of [`SceneInput`](super::SceneInput).

use crate::units::Dimension;

/// One scene input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SceneKey {
    /// The key: the command-line flag without its dashes and the batch column (`m`, `rod-v`).
    pub name: &'static str,
    /// Its spelling in a problem file's `[problem.given]` table (`from_end`, `rod_v`).
    pub toml: &'static str,
    /// What a unit after its number must measure ([`Dimension::Pure`] for a plain number,
    /// and for `rod`, which is not a number).
    pub dimension: Dimension,
    /// A `batch` scene column (`length` and `from-end`, the textbook alternatives to `l` and
    /// `a`, are flags and problem keys only).
    pub column: bool,
    /// Part of what an oblique or frictional scene adds to the paper's.
    pub oblique: bool,
    /// The help of its command-line flag.
    pub help: &'static str,
}

const fn key(
    name: &'static str,
    toml: &'static str,
    dimension: Dimension,
    column: bool,
    oblique: bool,
    help: &'static str,
) -> SceneKey {
    SceneKey {
        name,
        toml,
        dimension,
        column,
        oblique,
        help,
    }
}

use Dimension::{AngularSpeed, Length, Mass, Pure, Speed};

/// Every scene input, in the order a scene is read (and of `batch`'s scene columns).
///
/// # Examples
/// ```
/// use rodimpact::scene::SCENE_KEYS;
/// let columns: Vec<_> = SCENE_KEYS.iter().filter(|k| k.column).map(|k| k.name).collect();
/// assert_eq!(columns, ["m", "M", "l", "a", "v0", "rod", "e", "pivot", "v0t", "mu", "radius",
///                      "spin", "rod-v", "rod-vt", "rod-omega"]);
/// ```
pub const SCENE_KEYS: [SceneKey; 17] = [
    key(
        "m",
        "m",
        Mass,
        true,
        false,
        "Projectile mass m (> 0); numbers may carry a unit (kg, g, lb; m, cm, mm, ft; m/s, cm/s, km/h, ft/s, mph), read exactly in SI",
    ),
    key("M", "M", Mass, true, false, "Rod mass M (> 0)"),
    key(
        "l",
        "l",
        Length,
        true,
        false,
        "Half-length l of the rod (the rod is 2l long) [default: 1]",
    ),
    key(
        "length",
        "length",
        Length,
        false,
        false,
        "Full length L = 2l of the rod, instead of --l",
    ),
    key(
        "a",
        "a",
        Length,
        true,
        false,
        "Signed impact distance a from the rod's centre, |a| <= l [default: l, the end]",
    ),
    key(
        "from-end",
        "from_end",
        Length,
        false,
        false,
        "Impact distance d from the end, instead of --a (a = l - d)",
    ),
    key(
        "v0",
        "v0",
        Speed,
        true,
        false,
        "Projectile speed v0 (> 0) [default: 1]",
    ),
    key(
        "rod",
        "rod",
        Pure,
        true,
        false,
        "Mass distribution: uniform, dumbbell, rg=<radius of gyration> or I=<moment of inertia> [default: uniform]",
    ),
    key(
        "e",
        "e",
        Pure,
        true,
        false,
        "Coefficient of restitution, 0 <= e <= 1 [default: 1]",
    ),
    key(
        "pivot",
        "pivot",
        Length,
        true,
        false,
        "Put the rod on a fixed frictionless pivot at signed position p, |p| <= l",
    ),
    key(
        "v0t",
        "v0t",
        Speed,
        true,
        true,
        "The projectile's velocity along the rod (+y, towards increasing a) [default: 0]",
    ),
    key(
        "mu",
        "mu",
        Pure,
        true,
        true,
        "Coulomb friction coefficient at the contact, mu >= 0 [default: 0]",
    ),
    key(
        "radius",
        "radius",
        Length,
        true,
        true,
        "A solid disc projectile of this radius (I = m r^2/2) instead of a point",
    ),
    key(
        "spin",
        "spin",
        AngularSpeed,
        true,
        true,
        "The disc's spin before the impact, counterclockwise seen from above [default: 0]",
    ),
    key(
        "rod-v",
        "rod_v",
        Speed,
        true,
        true,
        "The rod centre's velocity across the rod (along x) before the impact [default: 0]",
    ),
    key(
        "rod-vt",
        "rod_vt",
        Speed,
        true,
        true,
        "The rod centre's velocity along the rod before the impact [default: 0]",
    ),
    key(
        "rod-omega",
        "rod_omega",
        AngularSpeed,
        true,
        true,
        "The rod's angular velocity before the impact (sign of omega) [default: 0]",
    ),
];

/// The scene key named `name` (a flag without dashes or a batch column), if any.
///
/// # Examples
/// ```
/// use rodimpact::{scene::scene_key, units::Dimension};
/// assert_eq!(scene_key("rod-omega").map(|k| k.toml), Some("rod_omega"));
/// assert_eq!(scene_key("from-end").map(|k| k.dimension), Some(Dimension::Length));
/// assert!(scene_key("mass").is_none());
/// ```
pub fn scene_key(name: &str) -> Option<&'static SceneKey> {
    SCENE_KEYS.iter().find(|k| k.name == name)
}

/// The help of the flag `--name` (a compile-time lookup, for the command-line definitions).
///
/// # Examples
/// ```
/// assert!(rodimpact::scene::flag_help("mu").starts_with("Coulomb friction"));
/// ```
pub const fn flag_help(name: &str) -> &'static str {
    SCENE_KEYS[key_index(name)].help
}

/// Where the key `name` sits in [`SCENE_KEYS`] (a compile-time lookup, for a batch row that
/// reads its scene cells by key).
///
/// # Examples
/// ```
/// use rodimpact::scene::{SCENE_KEYS, key_index};
/// assert_eq!(SCENE_KEYS[key_index("rod-vt")].name, "rod-vt");
/// ```
pub const fn key_index(name: &str) -> usize {
    let mut i = 0;
    while i < SCENE_KEYS.len() {
        if same(SCENE_KEYS[i].name, name) {
            return i;
        }
        i += 1;
    }
    panic!("not a scene key")
}

/// `a == b`, in a `const fn`.
const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}
