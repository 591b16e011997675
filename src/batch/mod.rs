//! Many scenes from a CSV file: solved exactly (or in f64), streamed in chunks, in parallel,
//! written back in input order with the results appended.
//!
//! The header names columns among `m, M, l, a, v0, rod, e, pivot` (m and M required, the others
//! take the `solve` defaults, also when a cell is empty) and optionally `v, V, omega`: claimed
//! results, each compared with the computed value. Appended columns: `v, V, omega` (named
//! `v_exact`, ... when the input already has a claim of that name; `v_f64, V_f64, omega_f64`
//! in f64), `laws_held` (`-` in f64, which decides no law), and for each claim
//! `<name>_ok, <name>_rel_error`. A header with an oblique column (`v0t, mu, radius, spin,
//! rod-v, rod-vt, rod-omega`, exact arithmetic only) also gets `vt, Vt, spin,
//! tangential_impulse, contact` after `omega`, and may claim `vt, Vt, spin_after,
//! tangential_impulse` (each then appended as `<claim>_exact`) instead of J and the energies.
//!
//! Limits: at most [`MAX_ROWS`] rows and [`MAX_LINE`] bytes per line; each number at most
//! [`number::MAX_DIGITS`](crate::number::MAX_DIGITS) digits. Memory stays flat in the number of
//! rows: at most three chunks of [`CHUNK`] rows are held at a time (one being read, one solved,
//! one written), and the median of the summary comes from a histogram of relative errors
//! rounded to two significant digits.
//!
//! One job per file: the header and the cells of a row (`header.rs`: [`Batch`]), solving a row
//! and writing its output line (`row.rs`: [`SolvedRow`]), claimed values against computed ones
//! (`compare.rs`: [`OutputCheck`], its exact error kept as computed in `rel_error.rs`), the tolerances per class of rows (`classes.rs`:
//! [`ClassRule`]), the known findings of `--expect` (`expected.rs`:
//! [`KnownFindings`]), the totals (`summary.rs`: [`Summary`], rendered by
//! [`crate::report::batch_summary`]) and the chunked, parallel stream (`stream.rs`: [`run`]).
//! The word rows are shortcuts that give the general row's line byte for byte: the paper's row
//! (`fixed_width_row.rs`), its f64 twin (`float_row.rs`), an engine's row with any rod, pivot and
//! claims, audited on fixed-width integers (`claimed_row.rs`), and an engine's row of an oblique
//! header, its claims checked on words (`claimed_row/oblique.rs`). An engine's rows come in runs
//! of one scene, which both engine rows solve once a run (`last_scene.rs`).

mod audit;
mod claimed_row;
mod classes;
mod compare;
mod expected;
mod fixed_width_row;
mod float_row;
mod header;
mod impacts;
mod last_scene;
mod plan;
mod rel_error;
mod row;
mod stream;
mod summary;
mod ulps;

pub use audit::{Audit, Finding, LAW_TOLERANCE, STATE_TOLERANCE, audit};
pub use classes::{ClassRule, RowClass};
pub(crate) use compare::unit_fraction;
pub use compare::{Agreement, FLOAT_TOLERANCE, MAX_ULPS};
pub use expected::{ExpectedEntry, KnownFindings, MAX_EXPECTED_BYTES};
pub use header::{Batch, read_header, scene_columns};
pub use impacts::{
    EngineChoice, EngineReference, ErrorSplit, ImpactAudit, ImpactBatchSummary, ImpactTolerance,
    Kind, MAX_NAMED_SCENES, Scenes, audit_impact, parse_line, profile_of_claim,
};
pub use plan::{Arithmetic, Diagnosis, OutputCheck, RowExpectation, SolvedRow};
pub use stream::{CHUNK, MAX_LINE, MAX_ROWS, run};
pub use summary::{Baseline, FINDING_EXAMPLES, OutputStats, Summary, WRONG_ROWS_SHOWN};
pub use ulps::{FloatFormat, ulp_distance};
