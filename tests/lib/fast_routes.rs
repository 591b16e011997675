//! Every fast route of the paper's family equals the core. Any scene of the family (free or
//! pivoted rod, any inertia and e; oblique, frictional, a spinning disc, a rod moving or turning
//! before) written as bodies (`Scene::system`) and answered by the general solver
//! (`impact::solve_contact`) under each of the three laws gives exactly what each route gives:
//! the linear solve (in Q and in Q(sqrt d)), the closed form, the fraction-free route, the
//! fixed-width row of `batch`, the oblique completion, the front door `Answer::of`, and the float
//! formulas within their rounding. Since the contact matrix W of these scenes is diagonal, the
//! three laws coincide.

use crate::common::{any_scene, oblique_scene};
use proptest::prelude::*;
use rodimpact::batch::{Arithmetic, Batch};
use rodimpact::field::{Field, Q, QSqrt};
use rodimpact::impact::{Law, LawAnswer, contact_matrix, solve_contact};
use rodimpact::scene::{Motion, RodInertia, Scene, Support};
use rodimpact::solve::Answer;
use rodimpact::solve::fast::{closed_form, float::FloatFormula, fraction_free, linear, oblique};

fn exact(x: &Q) -> QSqrt {
    QSqrt::rational(x.clone())
}

/// The core's (v, V, omega) in the paper's convention (the rod's spin is -omega).
fn paper_motion(general: &LawAnswer<QSqrt>) -> Motion<QSqrt> {
    let (projectile, rod) = (&general.bodies[0], &general.bodies[1]);
    Motion {
        v: projectile.velocity.x.clone(),
        rod_v: rod.velocity.x.clone(),
        omega: -rod.omega.clone(),
    }
}

/// The core's answer under every law, which must be one.
fn core(scene: &Scene) -> Result<LawAnswer<QSqrt>, TestCaseError> {
    let system = scene.system();
    let (w, _) = contact_matrix::<Q>(&system);
    prop_assert_eq!(
        w.nt,
        Q::from_integer(0.into()),
        "W is diagonal in the paper's family"
    );
    let newton = solve_contact::<QSqrt>(&system, Law::Newton).expect("answered");
    for law in [Law::Poisson, Law::Energetic] {
        let other = solve_contact::<QSqrt>(&system, law).expect("answered");
        prop_assert_eq!(&paper_motion(&other), &paper_motion(&newton), "{}", law);
        prop_assert_eq!(&other.tau, &newton.tau, "{} tau", law);
        prop_assert!(
            other.balances.all_zero(),
            "{} {:?}",
            law,
            other.balances.failing()
        );
    }
    prop_assert!(
        newton.balances.all_zero(),
        "{:?}",
        newton.balances.failing()
    );
    prop_assert!(!newton.energy.gain());
    Ok(newton)
}

/// The front door (`Answer::of`, which takes the fraction-free and fixed-width routes for a
/// plain scene and the oblique completion otherwise) equals the core, on both axes.
fn front_door_agrees(scene: &Scene, general: &LawAnswer<QSqrt>) -> Result<(), TestCaseError> {
    let answer = Answer::of(scene);
    let paper = &answer.impact;
    let (v, vt, spin, rod_v, rod_vt, omega, jt) = match &paper.oblique {
        Some(o) => (
            o.after.v.clone(),
            o.after.vt.clone(),
            o.after.spin.clone(),
            o.after.rod.v.clone(),
            o.after.rod.vt.clone(),
            o.after.rod.omega.clone(),
            o.tangential_impulse.clone(),
        ),
        None => {
            let a = &paper.outcome.after;
            let zero = Q::from_integer(0.into());
            (
                a.v.clone(),
                zero.clone(),
                None,
                a.rod_v.clone(),
                zero.clone(),
                a.omega.clone(),
                zero,
            )
        }
    };
    let lost = match &paper.oblique {
        Some(o) => o.energy.lost(),
        None => paper.outcome.energy.lost(),
    };
    let (projectile, rod) = (&general.bodies[0], &general.bodies[1]);
    prop_assert_eq!(&projectile.velocity.x, &exact(&v), "v");
    prop_assert_eq!(&projectile.velocity.y, &exact(&vt), "vt");
    if let Some(spin) = &spin {
        prop_assert_eq!(&projectile.omega, &exact(spin), "spin");
    }
    prop_assert_eq!(&rod.velocity.x, &exact(&rod_v), "V");
    prop_assert_eq!(&rod.velocity.y, &exact(&rod_vt), "Vt");
    prop_assert_eq!(&rod.omega, &exact(&-omega), "omega");
    // The impulse on the rod is (lam, tau): the normal is (-1, 0) into the projectile.
    prop_assert_eq!(&general.lam, &exact(&answer.impulse), "J");
    prop_assert_eq!(&general.tau, &exact(&jt), "Jt");
    prop_assert_eq!(&general.energy.change, &exact(&-lost), "energy");
    if let Support::Pivot(_) = scene.support() {
        let pin = rod
            .pin_impulse
            .as_ref()
            .expect("a pinned rod's pin impulse");
        let across = match &paper.oblique {
            Some(o) => o.pivot_impulse.clone().expect("pivot").0,
            None => paper.outcome.pivot_impulse.clone().expect("pivot"),
        };
        prop_assert_eq!(&pin.x, &exact(&across), "pivot impulse");
    }
    Ok(())
}

/// The plain scene's routes, one by one, equal the core.
fn plain_routes_agree(scene: &Scene, general: &LawAnswer<QSqrt>) -> Result<(), TestCaseError> {
    let want = paper_motion(general);
    let lift = |m: Motion<Q>| m.map(QSqrt::rational);
    let linear_q = linear::solve(&scene.params::<Q>()).expect("nonsingular");
    prop_assert_eq!(&lift(linear_q.after.clone()), &want, "linear in Q");
    prop_assert_eq!(
        &exact(&-linear_q.energy.lost()),
        &general.energy.change,
        "linear's energy"
    );
    let linear_surd = linear::solve(&scene.params::<QSqrt>()).expect("nonsingular");
    prop_assert_eq!(&linear_surd.after, &want, "linear in Q(sqrt d)");
    let closed = closed_form::closed_form(&scene.params::<Q>()).expect("nonsingular");
    prop_assert_eq!(&lift(closed), &want, "closed form");
    let free = fraction_free::solve(scene);
    prop_assert_eq!(&lift(free.after), &want, "fraction-free");
    prop_assert!(free.laws_hold);
    // The fixed-width row of `batch` (the paper's columns on machine words).
    let line = row_of(scene);
    let header = "m,M,l,a,v0,rod,e,pivot";
    let solved = Batch::new(header, Arithmetic::Exact)
        .unwrap()
        .row(1, &line)
        .unwrap();
    let cells: Vec<&str> = solved.line.split(',').collect();
    let printed = |k: usize| rodimpact::number::parse(cells[8 + k]).expect("an exact cell");
    let words = Motion {
        v: printed(0),
        rod_v: printed(1),
        omega: printed(2),
    };
    prop_assert_eq!(&lift(words), &want, "fixed-width row {}", solved.line);
    // The float formulas of the free rod, within rounding.
    if matches!(scene.support(), Support::Free) {
        let scale = [&want.v, &want.rod_v, &want.omega]
            .iter()
            .map(|x| x.nearest_f64().abs())
            .fold(scene.v0().nearest_f64().abs(), f64::max);
        for formula in [FloatFormula::Naive, FloatFormula::Sq, FloatFormula::Scomp] {
            let Some(got) = formula.eval_scene::<f64>(scene) else {
                continue; // a float that underflowed: refused, never wrong
            };
            for (x, y) in got.iter().zip(want.iter()) {
                prop_assert!(
                    (x - y.nearest_f64()).abs() <= 1e-12 * scale,
                    "float/{}: {} against {}",
                    formula.name(),
                    x,
                    y
                );
            }
        }
    }
    Ok(())
}

/// The scene as a row of `batch` with the columns m, M, l, a, v0, rod, e, pivot.
fn row_of(scene: &Scene) -> String {
    let rod = match scene.rod() {
        RodInertia::Uniform => "uniform".to_string(),
        RodInertia::Dumbbell => "dumbbell".to_string(),
        RodInertia::Gyration(r) => format!("rg={r}"),
        RodInertia::Moment(i) => format!("I={i}"),
    };
    let pivot = match scene.support() {
        Support::Free => String::new(),
        Support::Pivot(p) => p.to_string(),
    };
    format!(
        "{},{},{},{},{},{rod},{},{pivot}",
        scene.m(),
        scene.rod_mass(),
        scene.half_length(),
        scene.a(),
        scene.v0(),
        scene.e()
    )
}

/// The oblique completion, called directly, equals the core (the contact mode included).
fn oblique_route_agrees(scene: &Scene, general: &LawAnswer<QSqrt>) -> Result<(), TestCaseError> {
    let o = scene.oblique().expect("an oblique scene");
    let out = oblique::solve(&scene.params::<Q>(), &o.params(), None).expect("answered");
    prop_assert_eq!(&exact(&out.after.v), &general.bodies[0].velocity.x, "v");
    prop_assert_eq!(&exact(&out.after.vt), &general.bodies[0].velocity.y, "vt");
    prop_assert_eq!(&exact(&out.tangential_impulse), &general.tau, "Jt");
    // The phase the core ends in is the oblique route's contact mode.
    let last = general.phases.last().expect("a phase").mode;
    if let Some(mode) = out.contact {
        prop_assert_eq!(mode.kind(), last.kind(), "contact mode");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    /// Free and pivoted rods of every inertia kind, any e and impact point: every route.
    #[test]
    fn every_route_of_the_papers_scenes_equals_the_core(scene in any_scene()) {
        let general = core(&scene)?;
        front_door_agrees(&scene, &general)?;
        plain_routes_agree(&scene, &general)?;
    }

    /// Oblique and frictional impacts, spinning discs, rods moving or turning before the
    /// impact, free or pivoted: the oblique completion and the front door.
    #[test]
    fn the_oblique_completion_equals_the_core(scene in oblique_scene()) {
        if let Some(scene) = scene {
            let general = core(&scene)?;
            front_door_agrees(&scene, &general)?;
            if scene.oblique().is_some() {
                oblique_route_agrees(&scene, &general)?;
            }
        }
    }
}
