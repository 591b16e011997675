//! The paper's routes are special cases of the general planar solver: any scene of the paper's
//! family (free or pivoted rod, any inertia and e; oblique, frictional, a spinning disc, a rod
//! moving or turning before) written as bodies (`model::paper_system`) and answered by
//! `solve::impact` gives exactly what `solve::Answer` gives, under each of the three laws; and
//! since the contact matrix W of these scenes is diagonal, the three laws coincide.

use crate::common::{any_scene, oblique_scene};
use proptest::prelude::*;
use rodimpact::field::{Q, QSqrt};
use rodimpact::model::paper_system;
use rodimpact::scene::{Scene, Support};
use rodimpact::solve::Answer;
use rodimpact::solve::impact::{Law, contact_matrix, solve_contact};

fn exact(x: &Q) -> QSqrt {
    QSqrt::rational(x.clone())
}

/// The general answer under every law equals the paper's answer.
fn agrees(scene: &Scene) -> Result<(), TestCaseError> {
    let system = paper_system(scene);
    let (w, _) = contact_matrix::<Q>(&system);
    prop_assert_eq!(
        w.nt,
        Q::from_integer(0.into()),
        "W is diagonal in the paper's family"
    );
    let answer = Answer::of(scene);
    let paper = &answer.impact;
    // The paper's values: both axes (an oblique scene's completion, or the plain scene's).
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
        Some(o) => o.energy.lost.clone(),
        None => paper.outcome.energy.lost.clone(),
    };
    for law in Law::ALL {
        let general = solve_contact::<QSqrt>(&system, law).expect("answered");
        let (projectile, rod) = (&general.bodies[0], &general.bodies[1]);
        prop_assert_eq!(&projectile.velocity.x, &exact(&v), "{} v", law);
        prop_assert_eq!(&projectile.velocity.y, &exact(&vt), "{} vt", law);
        if let Some(spin) = &spin {
            prop_assert_eq!(&projectile.omega, &exact(spin), "{} spin", law);
        }
        prop_assert_eq!(&rod.velocity.x, &exact(&rod_v), "{} V", law);
        prop_assert_eq!(&rod.velocity.y, &exact(&rod_vt), "{} Vt", law);
        prop_assert_eq!(&rod.omega, &exact(&-omega.clone()), "{} omega", law);
        // The impulse on the rod is (lam, tau): the normal is (-1, 0) into the projectile.
        prop_assert_eq!(&general.lam, &exact(&answer.impulse), "{} J", law);
        prop_assert_eq!(&general.tau, &exact(&jt), "{} Jt", law);
        prop_assert_eq!(
            &general.energy.change,
            &exact(&-lost.clone()),
            "{} energy",
            law
        );
        if let Support::Pivot(_) = scene.support() {
            let pin = rod
                .pin_impulse
                .as_ref()
                .expect("a pinned rod's pin impulse");
            let across = match &paper.oblique {
                Some(o) => o.pivot_impulse.clone().expect("pivot").0,
                None => paper.outcome.pivot_impulse.clone().expect("pivot"),
            };
            prop_assert_eq!(&pin.x, &exact(&across), "{} pivot impulse", law);
        }
        prop_assert!(general.laws_hold.all(), "{} {:?}", law, general.laws_hold);
        prop_assert!(!general.energy_gain);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    /// Free and pivoted rods of every inertia kind, any e and impact point.
    #[test]
    fn the_papers_scenes_are_special_cases(scene in any_scene()) {
        agrees(&scene)?;
    }

    /// Oblique and frictional impacts, spinning discs, rods moving or turning before the
    /// impact, free or pivoted.
    #[test]
    fn the_oblique_scenes_are_special_cases(scene in oblique_scene()) {
        if let Some(scene) = scene {
            agrees(&scene)?;
        }
    }
}
