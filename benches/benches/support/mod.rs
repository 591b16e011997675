//! The benchmarks' one helper: the scenes of a reference batch in `tests/data/` (see
//! `tests/data/README.md`).

use rodimpact::scene::Scene;

/// The first `limit` scenes of the reference batch `file` of `tests/data/`.
pub fn reference(file: &str, limit: usize) -> Vec<Scene> {
    let path = format!("{}/../tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    rodimpact::samples::read_batch(path.as_ref(), limit)
        .unwrap_or_else(|e| panic!("the reference batch {file}: {e}"))
        .into_iter()
        .map(|row| row.scene)
        .collect()
}
