//! The engine suite (`rodimpact scenes --suite engines`): scenes that discriminate physics
//! engines on this problem family. Engines get the single free frictionless impact right to
//! rounding; what they get wrong shows on pivots (joints), low speeds (restitution thresholds),
//! the exact end of the rod (degenerate contact geometry) and sticking (soft contacts).
//!
//! Every scene is a variation of one base scene: m = M = l = 1, a = l/2, v0 = 3, uniform rod,
//! e = 1, free. The classes, in order (docs/engines.md says what each engine does on them):
//!
//! | class | varies | discriminates |
//! |---|---|---|
//! | `free-inside` | a = l/2, 0, -l/2, every rod form, l = 2 and 1/2 | nothing: a control |
//! | `free-end` | a = l and -l exactly; e; rod; M/m | the contact at the rod's corner |
//! | `free-near-end` | a = 999/1000 l: the same without the corner | corner against lever arm |
//! | `low-speed` | v0 = 1/10 ... 2 at e = 1, 1/2 (e = 0 controls) | restitution thresholds (1, 2 m/s) |
//! | `sticking` | e = 0 over a, rod, M/m | soft contacts |
//! | `mass-decade` | M/m = 1/100 ... 100 | conditioning of iterative solvers |
//! | `omega-max` | the paper's optimum a* = 2/3 for m = 3, M = 1; M = 2m | omega above the proven maximum |
//! | `pivot-centre` | pivot at the centre | joints absorbing the bounce |
//! | `pivot-end` | pivot at an end | the same, large pivot impulse |
//! | `pivot-cop` | pivot at the end, struck at the centre of percussion | a zero pivot impulse |
//! | `pivot-at-impact` | pivot at the impact point | the joint takes the whole impulse |
//! | `pivot-low-speed` | pivot at the centre, v0 = 1/2, 1, 2 | thresholds and joints together |

use crate::field::{Q, q};
use crate::scene::{RodInertia, Scene};

/// One scene of the suite, with its id and class.
///
/// # Examples
/// ```
/// use rodimpact::{suite::engine_suite, field::q};
/// let suite = engine_suite();
/// let cop = suite.iter().find(|s| s.id == "pivot-cop-1").unwrap();
/// assert_eq!((&cop.a, &cop.pivot), (&q(1, 3), &Some(q(-1, 1))));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteScene {
    /// `<class>-<n>`, n counted from 1 within the class.
    pub id: String,
    /// The class (what the scene discriminates).
    pub class: &'static str,
    /// Projectile mass m.
    pub m: Q,
    /// Rod mass M.
    pub rod_mass: Q,
    /// Half-length l.
    pub l: Q,
    /// Signed impact point a.
    pub a: Q,
    /// Projectile speed v0.
    pub v0: Q,
    /// The rod's mass distribution.
    pub rod: RodInertia,
    /// Coefficient of restitution e.
    pub e: Q,
    /// Pivot position, or `None` for a free rod.
    pub pivot: Option<Q>,
}

/// The header of the suite's CSV (the columns `rodimpact batch` reads, with `id` and `class`
/// passed through).
pub const HEADER: &str = "id,class,m,M,l,a,v0,rod,e,pivot";

/// A variation of the base scene: the fields it changes.
#[derive(Clone, Default)]
struct Vary {
    m: Option<Q>,
    rod_mass: Option<Q>,
    l: Option<Q>,
    a: Option<Q>,
    v0: Option<Q>,
    rod: Option<RodInertia>,
    e: Option<Q>,
    pivot: Option<Q>,
}

impl Vary {
    fn m(self, x: Q) -> Self {
        Vary { m: Some(x), ..self }
    }
    fn rod_mass(self, x: Q) -> Self {
        Vary {
            rod_mass: Some(x),
            ..self
        }
    }
    fn l(self, x: Q) -> Self {
        Vary { l: Some(x), ..self }
    }
    fn a(self, x: Q) -> Self {
        Vary { a: Some(x), ..self }
    }
    fn v0(self, x: Q) -> Self {
        Vary {
            v0: Some(x),
            ..self
        }
    }
    fn rod(self, x: RodInertia) -> Self {
        Vary {
            rod: Some(x),
            ..self
        }
    }
    fn e(self, x: Q) -> Self {
        Vary { e: Some(x), ..self }
    }
    fn pivot(self, x: Q) -> Self {
        Vary {
            pivot: Some(x),
            ..self
        }
    }
}

fn at() -> Vary {
    Vary::default()
}

/// The class's scenes from its variations of the base scene.
fn class(name: &'static str, variations: Vec<Vary>) -> impl Iterator<Item = SuiteScene> {
    variations
        .into_iter()
        .enumerate()
        .map(move |(n, v)| SuiteScene {
            id: format!("{name}-{}", n + 1),
            class: name,
            m: v.m.unwrap_or_else(|| q(1, 1)),
            rod_mass: v.rod_mass.unwrap_or_else(|| q(1, 1)),
            l: v.l.unwrap_or_else(|| q(1, 1)),
            a: v.a.unwrap_or_else(|| q(1, 2)),
            v0: v.v0.unwrap_or_else(|| q(3, 1)),
            rod: v.rod.unwrap_or(RodInertia::Uniform),
            e: v.e.unwrap_or_else(|| q(1, 1)),
            pivot: v.pivot,
        })
}

/// The elastic, half-elastic and sticking variants of one scene.
fn restitutions(base: Vary) -> Vec<Vary> {
    [q(1, 1), q(1, 2), q(0, 1)]
        .into_iter()
        .map(|e| base.clone().e(e))
        .collect()
}

/// Struck at `end` (l or 999/1000 l): every e, the other side, a dumbbell, M/m = 1/10, 10.
fn near(end: Q) -> Vec<Vary> {
    let mut v = restitutions(at().a(end.clone()));
    v.push(at().a(-end.clone()));
    v.push(at().a(end.clone()).rod(RodInertia::Dumbbell));
    v.extend([q(1, 10), q(10, 1)].map(|big_m| at().a(end.clone()).rod_mass(big_m)));
    v
}

/// The engine suite, in order: 88 scenes in 12 classes.
///
/// # Examples
/// ```
/// use rodimpact::suite::engine_suite;
/// let suite = engine_suite();
/// assert_eq!(suite.len(), 88);
/// assert_eq!(suite[0].id, "free-inside-1");
/// assert!(suite.iter().all(|s| s.scene().is_ok()));
/// ```
pub fn engine_suite() -> Vec<SuiteScene> {
    let speeds = [q(1, 10), q(1, 2), q(1, 1), q(3, 2), q(2, 1)];
    let masses = [q(1, 100), q(1, 10), q(10, 1), q(100, 1)];

    let free_inside = vec![
        at(),
        at().e(q(1, 2)),
        at().a(q(0, 1)),
        at().a(q(-1, 2)),
        at().rod(RodInertia::Dumbbell),
        at().rod(RodInertia::Gyration(q(1, 2))),
        at().rod(RodInertia::Moment(q(1, 5))).e(q(1, 2)),
        at().l(q(2, 1)).a(q(1, 1)),
        at().l(q(1, 2)).a(q(1, 4)).v0(q(2, 1)),
    ];
    let mut low_speed: Vec<Vary> = [q(1, 1), q(1, 2)]
        .into_iter()
        .flat_map(|e| speeds.clone().map(|v0| at().v0(v0).e(e.clone())))
        .collect();
    low_speed.extend([q(1, 2), q(1, 1)].map(|v0| at().v0(v0).e(q(0, 1))));
    low_speed.extend([q(1, 2), q(1, 1)].map(|v0| at().a(q(1, 1)).v0(v0)));
    let sticking = vec![
        at(),
        at().a(q(0, 1)),
        at().rod(RodInertia::Dumbbell),
        at().rod_mass(q(1, 10)),
        at().rod_mass(q(10, 1)),
        at().rod_mass(q(100, 1)),
    ]
    .into_iter()
    .map(|v| v.e(q(0, 1)))
    .collect();
    let mut mass_decade: Vec<Vary> = [q(1, 1), q(1, 2)]
        .into_iter()
        .flat_map(|e| {
            masses
                .clone()
                .map(|big_m| at().rod_mass(big_m).e(e.clone()))
        })
        .collect();
    mass_decade.extend([q(1, 100), q(100, 1)].map(|big_m| at().a(q(1, 1)).rod_mass(big_m)));
    mass_decade.push(at().m(q(1, 100)));
    let optimum = at().m(q(3, 1)).a(q(2, 3));
    let omega_max = vec![
        optimum.clone(),
        optimum.e(q(1, 2)),
        at().m(q(3, 1)).a(q(1, 1)),
        at().rod_mass(q(2, 1)).a(q(1, 1)),
    ];
    let centre = at().pivot(q(0, 1));
    let mut pivot_centre = restitutions(centre.clone().a(q(1, 1)));
    pivot_centre.extend(restitutions(centre.clone()));
    pivot_centre.push(centre.clone().a(q(-1, 1)));
    pivot_centre.push(centre.clone().a(q(1, 1)).rod(RodInertia::Dumbbell));
    pivot_centre
        .extend([q(1, 10), q(10, 1)].map(|big_m| centre.clone().a(q(1, 1)).rod_mass(big_m)));
    let end = at().pivot(q(-1, 1));
    let mut pivot_end = restitutions(end.clone().a(q(1, 1)));
    pivot_end.push(end.clone().a(q(0, 1)));
    pivot_end.push(end.clone().a(q(999, 1000)));
    pivot_end.push(end.clone().a(q(1, 1)).rod_mass(q(10, 1)));
    pivot_end.push(at().pivot(q(1, 1)).a(q(-1, 1)));
    let percussion = end.clone().a(q(1, 3));
    let mut pivot_cop = restitutions(percussion.clone());
    pivot_cop.extend([q(1, 10), q(10, 1)].map(|big_m| percussion.clone().rod_mass(big_m)));
    pivot_cop.push(end.a(q(1, 1)).rod(RodInertia::Dumbbell));
    let pivot_at_impact = vec![
        at().pivot(q(1, 2)),
        at().pivot(q(1, 2)).e(q(1, 2)),
        at().a(q(1, 1)).pivot(q(1, 1)),
    ];
    let struck_end = centre.a(q(1, 1));
    let mut pivot_low_speed: Vec<Vary> = [q(1, 2), q(1, 1), q(2, 1)]
        .map(|v0| struck_end.clone().v0(v0))
        .to_vec();
    pivot_low_speed.push(struck_end.v0(q(1, 2)).e(q(1, 2)));

    class("free-inside", free_inside)
        .chain(class("free-end", near(q(1, 1))))
        .chain(class("free-near-end", near(q(999, 1000))))
        .chain(class("low-speed", low_speed))
        .chain(class("sticking", sticking))
        .chain(class("mass-decade", mass_decade))
        .chain(class("omega-max", omega_max))
        .chain(class("pivot-centre", pivot_centre))
        .chain(class("pivot-end", pivot_end))
        .chain(class("pivot-cop", pivot_cop))
        .chain(class("pivot-at-impact", pivot_at_impact))
        .chain(class("pivot-low-speed", pivot_low_speed))
        .collect()
}

impl SuiteScene {
    /// The validated scene.
    ///
    /// # Errors
    /// As [`crate::scene::SceneBuilder::build`] (never for the suite's own scenes).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{suite::engine_suite, field::q};
    /// let scene = engine_suite()[0].scene().unwrap();
    /// assert_eq!((scene.a(), scene.v0()), (&q(1, 2), &q(3, 1)));
    /// ```
    pub fn scene(&self) -> Result<Scene, crate::Error> {
        let builder = Scene::builder(self.m.clone(), self.rod_mass.clone())
            .half_length(self.l.clone())
            .a(self.a.clone())
            .v0(self.v0.clone())
            .rod(self.rod.clone())
            .e(self.e.clone());
        match &self.pivot {
            Some(p) => builder.pivot(p.clone()).build(),
            None => builder.build(),
        }
    }

    /// The scene's CSV line (with its newline), in [`HEADER`]'s columns.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::suite::engine_suite;
    /// let suite = engine_suite();
    /// assert_eq!(suite[6].csv_line(), "free-inside-7,free-inside,1,1,1,1/2,3,I=1/5,1/2,\n");
    /// ```
    pub fn csv_line(&self) -> String {
        let rod = match &self.rod {
            RodInertia::Uniform => "uniform".to_string(),
            RodInertia::Dumbbell => "dumbbell".to_string(),
            RodInertia::Gyration(r) => format!("rg={r}"),
            RodInertia::Moment(i) => format!("I={i}"),
        };
        let pivot = self.pivot.as_ref().map(Q::to_string).unwrap_or_default();
        format!(
            "{},{},{},{},{},{},{},{rod},{},{pivot}\n",
            self.id, self.class, self.m, self.rod_mass, self.l, self.a, self.v0, self.e
        )
    }
}

/// The suite as a CSV file: [`HEADER`] and one line per scene.
///
/// # Examples
/// ```
/// use rodimpact::suite::{engine_suite, suite_csv};
/// let csv = suite_csv(&engine_suite());
/// assert!(csv.starts_with("id,class,m,M,l,a,v0,rod,e,pivot\nfree-inside-1,free-inside,1,1,1,1/2,3,uniform,1,\n"));
/// assert_eq!(csv.lines().count(), 89);
/// ```
pub fn suite_csv(scenes: &[SuiteScene]) -> String {
    let mut out = format!("{HEADER}\n");
    for scene in scenes {
        out.push_str(&scene.csv_line());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_and_classes_have_their_documented_sizes() {
        let suite = engine_suite();
        let mut ids: Vec<&str> = suite.iter().map(|s| s.id.as_str()).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), suite.len());
        let sizes: Vec<(&str, usize)> = [
            ("free-inside", 9),
            ("free-end", 7),
            ("free-near-end", 7),
            ("low-speed", 14),
            ("sticking", 6),
            ("mass-decade", 11),
            ("omega-max", 4),
            ("pivot-centre", 10),
            ("pivot-end", 7),
            ("pivot-cop", 6),
            ("pivot-at-impact", 3),
            ("pivot-low-speed", 4),
        ]
        .to_vec();
        for (class, n) in sizes {
            assert_eq!(
                suite.iter().filter(|s| s.class == class).count(),
                n,
                "{class}"
            );
        }
    }

    /// The classes hold what they promise: the centre-of-percussion scenes have a zero pivot
    /// impulse (a = l/3 from the centre with the pivot at -l for a uniform rod), the
    /// pivot-at-impact scenes leave the rod still, and omega-max-1 strikes at a*.
    #[test]
    fn the_classes_are_what_they_say() {
        let suite = engine_suite();
        for s in suite.iter().filter(|s| s.class == "pivot-cop") {
            let params = s.scene().unwrap().params::<Q>();
            let solved = crate::solve::linear::solve(&params).unwrap();
            assert_eq!(solved.pivot_impulse, Some(q(0, 1)), "{}", s.id);
        }
        for s in suite.iter().filter(|s| s.class == "pivot-at-impact") {
            let after = crate::solve::fraction_free::solve(&s.scene().unwrap()).after;
            assert_eq!(after.omega, q(0, 1), "{}", s.id);
            assert_eq!(after.v, -(&s.e * &s.v0), "{}", s.id);
        }
        let at_optimum = suite.iter().find(|s| s.id == "omega-max-1").unwrap();
        let optimum = crate::optimum::optimum(&at_optimum.scene().unwrap());
        assert_eq!(optimum.squared, &at_optimum.a * &at_optimum.a);
    }
}
