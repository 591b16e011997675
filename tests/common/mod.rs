//! Shared test helpers: exact numbers from strings, scenes from `key=value` text, and proptest
//! strategies for random rational scenes. Included by the library's tests (`tests/lib`) and the
//! command line's (`crates/rodimpact-cli/tests/cli`), each of which names the repository's
//! root as `crate::ROOT`.
#![allow(dead_code)]

use proptest::prelude::*;
use rodimpact::field::Q;
use rodimpact::scene::{RodInertia, Scene, SceneInput};

/// How long a test waits for something that needs no more than a second of work (a process to
/// end, a file to appear, a lock to be waited on) before it calls it a deadlock. No test asserts
/// speed: this is ten minutes so that no load can reach it, and a runaway computation is bounded
/// by CPU time instead (`ulimit -t`, which load does not change).
pub const DEADLOCK: std::time::Duration = std::time::Duration::from_secs(600);

/// An exact rational from its string form (test data only).
pub fn rat(text: &str) -> Q {
    rodimpact::number::parse(text).unwrap_or_else(|e| panic!("bad test number {text}: {e}"))
}

/// A scene from `"m=1 M=1 a=1 e=0 pivot=0 rod=dumbbell"` (keys of `SceneInput`).
pub fn scene(text: &str) -> Scene {
    let mut s = SceneInput::default();
    for pair in text.split_whitespace() {
        let (k, v) = pair.split_once('=').expect("key=value");
        *s.slot(k).expect("a known scene key") = Some(v.to_string());
    }
    s.build()
        .unwrap_or_else(|e| panic!("bad test scene {text}: {e}"))
}

/// A positive rational with numerator and denominator in 1..=1000.
pub fn positive() -> impl Strategy<Value = Q> {
    (1i64..=1000, 1i64..=1000).prop_map(|(n, d)| Q::new(n.into(), d.into()))
}

/// A rational in [0, 1] with denominator in 1..=100.
pub fn unit_interval() -> impl Strategy<Value = Q> {
    (1i64..=100).prop_flat_map(|d| (0..=d).prop_map(move |n| Q::new(n.into(), d.into())))
}

/// A rational in [-1, 1] with denominator in 1..=100.
pub fn signed_unit() -> impl Strategy<Value = Q> {
    (1i64..=100).prop_flat_map(|d| (-d..=d).prop_map(move |n| Q::new(n.into(), d.into())))
}

/// Any valid rod inertia for rod mass `big_m` and half-length `l`, given a fraction in (0, 1].
pub fn inertia_kind() -> impl Strategy<Value = (u8, Q)> {
    (
        0u8..4,
        (1i64..=100).prop_map(|n| Q::new(n.into(), 100.into())),
    )
}

/// Any valid scene: random masses, length, speed, impact point, e, inertia, free or pivoted.
pub fn any_scene() -> impl Strategy<Value = Scene> {
    (
        positive(),
        positive(),
        positive(),
        positive(),
        signed_unit(),
        unit_interval(),
        inertia_kind(),
        proptest::option::of(signed_unit()),
    )
        .prop_map(|(m, big_m, l, v0, a_frac, e, (kind, frac), pivot)| {
            let rod = match kind {
                0 => RodInertia::Uniform,
                1 => RodInertia::Dumbbell,
                2 => RodInertia::Gyration(&l * &frac),
                _ => RodInertia::Moment(&big_m * &l * &l * &frac),
            };
            let mut b = Scene::builder(m, big_m)
                .half_length(l.clone())
                .v0(v0)
                .a(&a_frac * &l)
                .e(e)
                .rod(rod);
            if let Some(p) = pivot {
                b = b.pivot(&p * &l);
            }
            b.build().expect("strategy builds valid scenes")
        })
}

/// A new empty directory of its own for one test (`rodimpact-TAG-XXXXXX` under the system's
/// temporary directory), created race-free, so tests running side by side (and test runs of
/// other checkouts) never share a file. The test removes it when it is done.
pub fn scratch(tag: &str) -> std::path::PathBuf {
    tempfile::Builder::new()
        .prefix(&format!("rodimpact-{tag}-"))
        .tempdir()
        .expect("a temporary directory")
        .keep()
}

/// The path of a file of `tests/data/` (the reference batches; see `tests/data/README.md`).
pub fn data_file(file: &str) -> String {
    format!("{}/tests/data/{file}", crate::ROOT)
}

/// The first `limit` rows of a reference batch of `tests/data/`: the line, its scene
/// (columns m, M, l, a, v0) and its exact v, V, omega, read as `rodimpact batch` reads them.
pub fn reference_rows(file: &str, limit: usize) -> Vec<(String, Scene, [Q; 3])> {
    let path = data_file(file);
    rodimpact::samples::read_batch(path.as_ref(), limit)
        .unwrap_or_else(|e| panic!("the reference batch {file}: {e}"))
        .into_iter()
        .map(|row| {
            let expected = row
                .claimed
                .map(|x| x.expect("the reference gives v, V and omega"));
            (row.line, row.scene, expected)
        })
        .collect()
}

/// A random oblique scene the library accepts: any masses, impact point, restitution,
/// friction, slip, an optional spinning disc, an optional pivot, and the rod moving or turning
/// before the impact (refused scenes, no approach, are left out by the caller).
pub fn oblique_scene() -> impl Strategy<Value = Option<Scene>> {
    (
        (
            positive(),
            positive(),
            signed_unit(),
            unit_interval(),
            positive(),
        ),
        (
            signed_unit(),
            unit_interval(),
            proptest::option::of((positive(), signed_unit())),
        ),
        (
            proptest::option::of(signed_unit()),
            signed_unit(),
            signed_unit(),
            signed_unit(),
        ),
    )
        .prop_map(
            |((m, big_m, a, e, v0), (v0t, mu, disc), (pivot, rv, rvt, rw))| {
                let mut b = Scene::builder(m, big_m)
                    .a(a)
                    .e(e)
                    .v0(v0 * rat("3") + rat("2"))
                    .v0t(v0t)
                    .mu(mu);
                if let Some((radius, spin)) = disc {
                    b = b.disc(radius, spin * rat("5"));
                }
                b = match pivot {
                    Some(p) => b.pivot(p).rod_before(rat("0"), rat("0"), rw),
                    None => b.rod_before(rv, rvt, rw),
                };
                b.build().ok()
            },
        )
}
