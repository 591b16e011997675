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
//! | `oblique-frictionless` | v0t along the rod, mu = 0 | the slide must pass through unchanged |
//! | `oblique-slide` | v0t = v0, mu = 1/10, a = ±l/2: the contact slides | Coulomb's cone, spin from friction |
//! | `oblique-stick` | v0t = 1, mu = 1: the contact sticks | static friction in one impact |
//! | `oblique-threshold` | mu = mu* exactly, and 9/10 and 11/10 of it | stick against slide at the boundary |
//! | `spinning-disc` | a spinning disc, no v0t; sticking and sliding | spin coupled to the slip |
//! | `moving-rod` | the rod drifting before the impact | Galilean invariance |
//! | `pivot-friction` | pivot at the centre, v0t towards it; sticking and sliding | the joint takes the tangential impulse |
//!
//! The oblique classes (issue 20) strike with a solid disc of radius l/20 (the radius every
//! engine's ball has), with the rod thin: engines model it as a box of half-thickness l/100, so
//! their tangential impulse acts l/100 off the axis and turns the rod a little (docs/engines.md
//! gives the size of that effect); the thin rod's exact omega does not depend on friction (X27).

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
    /// The oblique part (issue 20), or `None` for the paper's perpendicular frictionless impact.
    pub oblique: Option<SuiteOblique>,
}

/// The oblique part of a suite scene: the projectile's slide, friction, the disc and the rod's
/// motion before the impact (the rod never turns before it in the suite).
#[derive(Debug, Clone, PartialEq)]
pub struct SuiteOblique {
    /// The projectile's velocity along the rod, v0t.
    pub v0t: Q,
    /// Coulomb friction coefficient mu.
    pub mu: Q,
    /// The disc's radius.
    pub radius: Q,
    /// The disc's spin before the impact (counterclockwise).
    pub spin: Q,
    /// The rod centre's velocity across the rod before the impact.
    pub rod_v: Q,
    /// The rod centre's velocity along the rod before the impact.
    pub rod_vt: Q,
}

/// The header of the suite's CSV (the columns `rodimpact batch` reads, with `id` and `class`
/// passed through).
pub const HEADER: &str =
    "id,class,m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega";

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
    oblique: Option<SuiteOblique>,
}

/// The base of the oblique classes: a disc of radius l/20, no slide, no friction, no spin, the
/// rod at rest.
fn oblique_base() -> SuiteOblique {
    SuiteOblique {
        v0t: q(0, 1),
        mu: q(0, 1),
        radius: q(1, 20),
        spin: q(0, 1),
        rod_v: q(0, 1),
        rod_vt: q(0, 1),
    }
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
    /// The oblique part, changed by `change` from what the variation has (or the base).
    fn oblique(self, change: impl FnOnce(&mut SuiteOblique)) -> Self {
        let mut o = self.oblique.clone().unwrap_or_else(oblique_base);
        change(&mut o);
        Vary {
            oblique: Some(o),
            ..self
        }
    }
    fn v0t(self, x: Q) -> Self {
        self.oblique(|o| o.v0t = x)
    }
    fn mu(self, x: Q) -> Self {
        self.oblique(|o| o.mu = x)
    }
    fn spin(self, x: Q) -> Self {
        self.oblique(|o| o.spin = x)
    }
    fn drift(self, v: Q, vt: Q) -> Self {
        self.oblique(|o| {
            o.rod_v = v;
            o.rod_vt = vt;
        })
    }
}

/// The friction coefficient at which the base scene struck at a = l/2 with `v0t` (and the
/// disc of radius 1/20, m = M = l = 1, v0 = 3, uniform rod, `e`) is on the stick/slide boundary:
/// mu* = u_t k_n/((1 + e) u_n k_t), k_n = 1/m + 1/M + a^2/I = 11/4, k_t = 3/m + 1/M = 4 (X28).
fn threshold_mu(v0t: Q, e: Q) -> Q {
    let k_n = q(11, 4);
    let k_t = q(4, 1);
    v0t * &k_n / &((q(1, 1) + &e) * &q(3, 1) * &k_t)
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
            oblique: v.oblique,
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

/// The engine suite, in order: 107 scenes in 19 classes (the last 7 oblique).
///
/// # Examples
/// ```
/// use rodimpact::suite::engine_suite;
/// let suite = engine_suite();
/// assert_eq!(suite.len(), 107);
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

    let frictionless = vec![
        at().v0t(q(1, 1)),
        at().v0t(q(3, 1)),
        at().v0t(q(-2, 1)),
        at().v0t(q(1, 1)).e(q(1, 2)),
    ];
    let sliding = at().v0t(q(3, 1)).mu(q(1, 10));
    let slide = vec![
        sliding.clone(),
        sliding.clone().e(q(1, 2)),
        sliding.a(q(-1, 2)),
    ];
    let sticking_oblique = at().v0t(q(1, 1)).mu(q(1, 1));
    let stick = vec![sticking_oblique.clone(), sticking_oblique.e(q(1, 2))];
    let boundary = threshold_mu(q(3, 1), q(1, 1));
    let threshold = [q(1, 1), q(9, 10), q(11, 10)]
        .map(|f| at().v0t(q(3, 1)).mu(&boundary * &f))
        .to_vec();
    let spinning_disc = vec![
        at().spin(q(20, 1)).mu(q(1, 1)),
        at().spin(q(20, 1)).mu(q(1, 20)),
        at().spin(q(-20, 1)).mu(q(1, 1)),
    ];
    let moving_rod = vec![
        at().v0t(q(1, 1)).mu(q(1, 2)).drift(q(-1, 1), q(1, 2)),
        at().v0t(q(1, 1)).mu(q(1, 2)).drift(q(1, 1), q(-1, 2)),
    ];
    // Struck inside the rod and sliding towards the pivot: never over the rod's end.
    let pivot_friction = vec![
        at().pivot(q(0, 1)).v0t(q(-2, 1)).mu(q(1, 2)),
        at().pivot(q(0, 1)).v0t(q(-2, 1)).mu(q(1, 20)),
    ];

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
        .chain(class("oblique-frictionless", frictionless))
        .chain(class("oblique-slide", slide))
        .chain(class("oblique-stick", stick))
        .chain(class("oblique-threshold", threshold))
        .chain(class("spinning-disc", spinning_disc))
        .chain(class("moving-rod", moving_rod))
        .chain(class("pivot-friction", pivot_friction))
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
        let builder = match &self.oblique {
            Some(o) => builder
                .v0t(o.v0t.clone())
                .mu(o.mu.clone())
                .disc(o.radius.clone(), o.spin.clone())
                .rod_before(o.rod_v.clone(), o.rod_vt.clone(), q(0, 1)),
            None => builder,
        };
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
    /// assert_eq!(suite[6].csv_line(), "free-inside-7,free-inside,1,1,1,1/2,3,I=1/5,1/2,,,,,,,,\n");
    /// let slide = suite.iter().find(|s| s.id == "oblique-slide-1").unwrap();
    /// assert_eq!(slide.csv_line(), "oblique-slide-1,oblique-slide,1,1,1,1/2,3,uniform,1,,3,1/10,1/20,0,0,0,0\n");
    /// ```
    pub fn csv_line(&self) -> String {
        let rod = match &self.rod {
            RodInertia::Uniform => "uniform".to_string(),
            RodInertia::Dumbbell => "dumbbell".to_string(),
            RodInertia::Gyration(r) => format!("rg={r}"),
            RodInertia::Moment(i) => format!("I={i}"),
        };
        let pivot = self.pivot.as_ref().map(Q::to_string).unwrap_or_default();
        let oblique = match &self.oblique {
            Some(o) => format!(
                "{},{},{},{},{},{},0",
                o.v0t, o.mu, o.radius, o.spin, o.rod_v, o.rod_vt
            ),
            None => ",,,,,,".to_string(),
        };
        format!(
            "{},{},{},{},{},{},{},{rod},{},{pivot},{oblique}\n",
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
/// assert!(csv.starts_with("id,class,m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega\n\
///     free-inside-1,free-inside,1,1,1,1/2,3,uniform,1,,,,,,,,\n"));
/// assert_eq!(csv.lines().count(), 108);
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
            ("oblique-frictionless", 4),
            ("oblique-slide", 3),
            ("oblique-stick", 2),
            ("oblique-threshold", 3),
            ("spinning-disc", 3),
            ("moving-rod", 2),
            ("pivot-friction", 2),
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
            let solved = crate::solve::fast::linear::solve(&params).unwrap();
            assert_eq!(solved.pivot_impulse, Some(q(0, 1)), "{}", s.id);
        }
        for s in suite.iter().filter(|s| s.class == "pivot-at-impact") {
            let after = crate::solve::fast::fraction_free::solve(&s.scene().unwrap()).after;
            assert_eq!(after.omega, q(0, 1), "{}", s.id);
            assert_eq!(after.v, -(&s.e * &s.v0), "{}", s.id);
        }
        let at_optimum = suite.iter().find(|s| s.id == "omega-max-1").unwrap();
        let optimum = crate::solve::optimum::optimum(&at_optimum.scene().unwrap())
            .expect("a rod at rest before the impact has an optimum");
        assert_eq!(optimum.squared, &at_optimum.a * &at_optimum.a);
    }
}
