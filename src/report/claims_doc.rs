//! `docs/claims.md`: the list of claims, written from the claims registry so that it cannot
//! drift from what `rodimpact prove` decides (a golden test regenerates and compares it).

use super::markup::markdown_text;
use crate::claims::{self, Decided, Group};
use std::fmt::Write as _;

/// What the list says before the claims: the paper, the standing assumptions, the notation and
/// how to read the table.
fn preamble() -> String {
    format!(
        "\
# The claims

<!-- Generated from the claims registry (src/claims/); do not edit by hand. After a change to a \
claim, regenerate with `RODIMPACT_BLESS=1 cargo test --release --test golden`. -->

rodimpact decides every claim of N. A. Lemos, *Failure of intuition in elementary rigid body \
dynamics*, [arXiv:0801.1644](https://arxiv.org/abs/0801.1644) (2008), and a set of results \
beyond it. The paper's claims are numbered \
{} in the order the paper makes them; the results beyond it are {}. Each is formalised \
with every assumption explicit and decided by exact computation: **PROVED**, **REFUTED** (with \
a counterexample), or **QUALIFIED** (the natural reading is false; a qualification that makes \
it true is stated and proved). The verdicts are in [`proofs/README.md`](../proofs/README.md), \
and the certificate of each claim is linked in the table. `rodimpact prove ID` decides a claim \
again, and `rodimpact paper` prints the whole report.

Standing assumptions, unless a claim says otherwise: the masses m and M, the speed v0 and the \
half-length l are positive; the rod is rigid, thin, symmetric about its centre and at rest, \
with moment of inertia I = M r_G^2 about its centre, 0 < r_G <= l; the projectile is a point \
and strikes perpendicularly at 0 <= a <= l; the impact is instantaneous and frictionless. \
Notation: D = 1 + m/M + m a^2/I, mu = m M/(M + m), a*^2 = I (M + m)/(m M). Velocities and \
omega are signed as in [conventions.md](conventions.md).

*Where* names the place in the paper: an equation by its label in the paper's source \
(Eq. (omega) is the formula for omega), a section by its subject (§optimum: where omega is \
largest; §intuition: why intuition fails; §inhomogeneous: the inhomogeneous rod) and ¶ the \
paragraph within it.
",
        claims::paper_ids(),
        claims::beyond_ids()
    )
}

/// `docs/claims.md`: the preamble (the paper, the assumptions, the notation), then every claim
/// in registry order, grouped as the paper runs (id, where, the claim as stated, a link to its
/// certificate); the paper's claims first, then the results beyond it (without the "where").
///
/// # Examples
/// ```
/// use rodimpact::claims::{decide, Paper};
/// let d = decide("C15", &Paper::as_printed()).unwrap();
/// let md = rodimpact::report::claims_markdown(&[d]);
/// assert!(md.starts_with("# The claims"));
/// assert!(md.contains(&format!("## The paper ({})", rodimpact::claims::paper_ids())));
/// assert!(md.contains("arXiv:0801.1644"));
/// assert!(md.contains("| C15 | Eq. (omega) | omega = (2ma/I)/D v0 | [C15](../proofs/C15.md) |"));
/// ```
pub fn claims_markdown(all: &[Decided]) -> String {
    let mut out = preamble();
    let parts = [
        (format!("The paper ({})", claims::paper_ids()), false),
        (format!("Beyond the paper ({})", claims::beyond_ids()), true),
    ];
    for (title, beyond) in parts {
        let _ = write!(out, "\n## {title}\n");
        let mut groups: Vec<Group> = Vec::new();
        for d in all {
            let group = d.claim.group;
            if (group == Group::Beyond) == beyond && !groups.contains(&group) {
                groups.push(group);
            }
        }
        for group in groups {
            if !beyond {
                let _ = write!(out, "\n### {}\n", group.title());
            }
            out.push_str(if beyond {
                "\n| id | result | certificate |\n|---|---|---|\n"
            } else {
                "\n| id | where | claim | certificate |\n|---|---|---|---|\n"
            });
            for d in all.iter().filter(|d| d.claim.group == group) {
                let c = &d.claim;
                let place = if beyond {
                    String::new()
                } else {
                    format!(" {} |", markdown_text(c.location))
                };
                let _ = writeln!(
                    out,
                    "| {id} |{place} {} | [{id}](../proofs/{id}.md) |",
                    markdown_text(c.statement),
                    id = c.id
                );
            }
        }
    }
    out
}
