//! The general solver, the ground floor of the mechanics: any planar impact of bodies and
//! contacts ([`crate::model::System`]) answered exactly, with one contact under Newton's,
//! Poisson's and Stronge's restitution laws and Coulomb friction followed through the impact,
//! and with several contacts under each named model (simultaneous, sequential, projected
//! Gauss-Seidel).
//!
//! Contacts are rows of a Jacobian over the moving bodies' velocity coordinates, and the
//! system's response to contact impulses is `W = J M^-1 J^T`, as rapier's contact constraints
//! build it: nothing in the solvers depends on how many coordinates a body has. The paper's
//! family is a special case (`Scene::system`), and its fast routes (`crate::solve`) are held
//! equal to these solvers by tests.
//!
//! | file | what it does |
//! |---|---|
//! | `law.rs` | the restitution laws ([`Law`]), stated once |
//! | `coulomb.rs` | Coulomb's law: what friction does in a phase ([`Mode`]), the cone |
//! | `engines.rs` | the engines' profiles: the law each converges to, its iterations, threshold, rules |
//! | `ledger.rs` | what an impact conserves and changes: [`EnergyLedger`], [`Balances`] |
//! | `jacobian.rs` | the bodies' coordinates, the contacts' rows, W, the impulses' effect |
//! | `planar.rs` | the plane's bodies and contacts as coordinates and rows, and back |
//! | `one_contact/` | one contact: Routh's path in the normal impulse and each law's end |
//! | `multi_contact/` | several contacts under each model: LCPs, sequential, PGS, friction |
//! | `work.rs` | the work budget of iterated exact work ([`Work`], [`Stopped`]) |

mod coulomb;
mod engines;
mod jacobian;
mod law;
mod ledger;
mod multi_contact;
mod one_contact;
mod planar;
mod work;

pub use coulomb::{Mode, cone_excess, within_cone};
pub use engines::{Combine, Engine, Profile};
pub use jacobian::ContactMatrix;
pub use law::Law;
pub use ledger::{Balance, Balances, EnergyLedger};
pub use multi_contact::{
    Ledger, MAX_ENGINE_STEPS, MAX_ENUMERATED, MAX_ORDERED, MAX_SEQUENTIAL_IMPACTS, MAX_SWEEPS,
    Model, ModelAnswer, ModelOutcome, orders, solve_several, solve_several_sharing,
};
pub use one_contact::{
    BodyAfter, ImpactError, Jam, LawAnswer, PathPoint, Phase, Roots, contact_matrix, contact_path,
    solve_contact, solve_engine, solve_engine_exact, solve_exact,
};
pub use work::{Stopped, WORK_LIMIT, Work};
