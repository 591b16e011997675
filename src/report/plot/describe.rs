//! The words of titles and labels: the rod as a reader names it ("r_G = l/10", not the CLI's
//! "rg=1/10"), the collision law, the support, multiples of l.

use crate::field::Q;
use crate::scene::{RodInertia, Scene, Support};
use num_traits::{One, Signed, Zero};

/// The longest exact number a figure's label prints; a longer one is printed to four
/// significant digits, with `…` when that is not exact (`M = 3.000…m` for a threshold of
/// 3 + 10^-600 times m, not six hundred digits across the figure).
const LABEL_DIGITS: usize = 20;

/// `|q|` for a label: exact when short, else four significant digits (`…` if rounded).
fn magnitude_text(q: &Q) -> (String, bool) {
    let exact = q.abs().to_string();
    if exact.len() <= LABEL_DIGITS {
        return (exact, true);
    }
    let rounded = crate::field::decimal::decimal(&q.abs(), 4);
    let is_exact = crate::number::parse(&rounded).is_ok_and(|back| back == q.abs());
    (
        if is_exact {
            rounded
        } else {
            format!("{rounded}…")
        },
        false,
    )
}

/// `q` times the symbol `unit` as a reader writes it: `l`, `−l/2`, `3l/10`, `0`; a number too
/// long for a label to four digits, `1.000e-300 l`.
pub(crate) fn multiple(q: &Q, unit: &str) -> String {
    if q.is_zero() {
        return "0".into();
    }
    let sign = if q.is_negative() { "−" } else { "" };
    let (text, short) = magnitude_text(q);
    if !short {
        return format!("{sign}{text} {unit}");
    }
    let (n, d) = (q.numer().abs(), q.denom().clone());
    let numerator = if n.is_one() {
        unit.to_string()
    } else {
        format!("{n}{unit}")
    };
    if d.is_one() {
        format!("{sign}{numerator}")
    } else {
        format!("{sign}{numerator}/{d}")
    }
}

/// An exact number with a true minus sign: `−1/2`; a number too long for a label to four
/// digits, `1.000e300`.
pub(crate) fn signed(q: &Q) -> String {
    let sign = if q.is_negative() { "−" } else { "" };
    format!("{sign}{}", magnitude_text(q).0)
}

/// The rod's mass distribution with its moment of inertia, for `scene`'s M and l.
pub(crate) fn rod(scene: &Scene) -> String {
    let l = scene.half_length();
    match scene.rod() {
        RodInertia::Uniform => "uniform rod (I = Ml^{2}/3)".into(),
        RodInertia::Dumbbell => "dumbbell: all the mass at the two ends (I = Ml^{2})".into(),
        RodInertia::Gyration(r) => {
            let ratio = r / l;
            format!(
                "rod with r_{{G}} = {} (I = {})",
                multiple(&ratio, "l"),
                multiple(&(&ratio * &ratio), "Ml^{2}")
            )
        }
        RodInertia::Moment(_) => {
            let k = scene.inertia() / (scene.rod_mass() * l * l);
            format!("rod with I = {}", multiple(&k, "Ml^{2}"))
        }
    }
}

/// The collision law: `elastic (e = 1)`, `sticking (e = 0)`, `partly elastic (e = 1/2)`.
pub(crate) fn law(e: &Q) -> String {
    if e.is_one() {
        "elastic (e = 1)".into()
    } else if e.is_zero() {
        "sticking, totally inelastic (e = 0)".into()
    } else {
        format!("partly elastic (e = {e})")
    }
}

/// How the rod is held: `free on the table` or `on a fixed pivot at p = −l/2`.
pub(crate) fn support(scene: &Scene) -> String {
    match scene.support() {
        Support::Free => "free on the table".into(),
        Support::Pivot(p) => format!(
            "on a fixed pivot at p = {}",
            multiple(&(p / scene.half_length()), "l")
        ),
    }
}

/// The rod, its support and the collision law on one line.
pub(crate) fn scene_line(scene: &Scene) -> String {
    format!("{}, {}, {}", rod(scene), support(scene), law(scene.e()))
}

/// The scene's numbers: `m = 1, M = 3, l = 1, v_{0} = 1`.
pub(crate) fn numbers(scene: &Scene, with_rod_mass: bool) -> String {
    let mut parts = vec![format!("m = {}", signed(scene.m()))];
    if with_rod_mass {
        parts.push(format!("M = {}", signed(scene.rod_mass())));
    }
    parts.push(format!("l = {}", signed(scene.half_length())));
    parts.push(format!("v_{{0}} = {}", signed(scene.v0())));
    parts.join(", ")
}

/// Whether the scene's rod is pivoted.
pub(crate) fn pivot_of(scene: &Scene) -> Option<&Q> {
    match scene.support() {
        Support::Free => None,
        Support::Pivot(p) => Some(p),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::q;

    #[test]
    fn multiples_of_l_read_as_written_by_hand() {
        assert_eq!(multiple(&q(1, 10), "l"), "l/10");
        assert_eq!(multiple(&q(3, 10), "l"), "3l/10");
        assert_eq!(multiple(&q(-1, 2), "l"), "−l/2");
        assert_eq!(multiple(&q(1, 1), "l"), "l");
        assert_eq!(multiple(&q(0, 1), "l"), "0");
        assert_eq!(multiple(&q(-2, 1), "l"), "−2l");
        let tiny = Q::new(1.into(), num_bigint::BigInt::from(10).pow(300));
        assert_eq!(multiple(&tiny, "l"), "1.000e-300 l");
        let three_and_a_bit = Q::from_integer(3.into()) + &tiny;
        assert_eq!(multiple(&three_and_a_bit, "m"), "3.000… m");
        assert_eq!(signed(&-(Q::from_integer(3.into()) / &tiny)), "−3.000e300");
        assert_eq!(signed(&q(-1, 2)), "−1/2");
    }

    #[test]
    fn rods_laws_and_supports_are_named() {
        let s = Scene::builder(q(1, 1), q(2, 1))
            .rod(RodInertia::Gyration(q(1, 10)))
            .e(q(0, 1))
            .pivot(q(-1, 2))
            .build()
            .unwrap();
        assert_eq!(
            scene_line(&s),
            "rod with r_{G} = l/10 (I = Ml^{2}/100), on a fixed pivot at p = −l/2, \
             sticking, totally inelastic (e = 0)"
        );
        let s = Scene::builder(q(1, 1), q(2, 1))
            .rod(RodInertia::Moment(q(2, 5)))
            .half_length(q(2, 1))
            .e(q(1, 2))
            .build()
            .unwrap();
        // I = 2/5 with M = 2, l = 2: I/(M l^2) = 1/20.
        assert_eq!(rod(&s), "rod with I = Ml^{2}/20");
        assert_eq!(law(s.e()), "partly elastic (e = 1/2)");
    }
}
