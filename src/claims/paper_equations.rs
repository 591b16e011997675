//! Claims C1-C18: the abstract, the introduction, the impulse equations and the limiting cases.

use super::model::*;
use super::{Certificate, Claim, Decision, Entry, Group, Paper, PosExpr};

/// The registered claims of this part of the paper.
pub(super) const ENTRIES: &[Entry] = &[
    Entry {
        id: "C5",
        build: c5,
    },
    Entry {
        id: "C15",
        build: c15,
    },
];

fn c5(_paper: &Paper) -> Claim {
    let p = free_rod(sym("I"), sym("e"));
    let after = motion(&p);
    let lhs = sym("m") * &after.v + &(sym("M") * &after.rod_v);
    Claim {
        id: "C5",
        location: "Eq. (linear)",
        group: Group::Equations,
        statement: "m v0 = m v + M V",
        formal: "For all m, M, I > 0, any a, v0 and any restitution e, the solution of the impulse \
                 equations (momentum, angular momentum about the rod's centre, Newton's restitution) \
                 satisfies m v + M V = m v0: the table is frictionless, so no external impulse acts \
                 along x."
            .into(),
        reason: "the momentum residual of the symbolic solution is identically 0, for every e".into(),
        decision: Decision::Proved(vec![Certificate::identity(
            "linear momentum after the impact equals m v0 (v, V from the generic solver over Q(m, M, I, a, v0, e))",
            lhs,
            sym("m") * &sym("v0"),
        )]),
    }
}

fn c15(paper: &Paper) -> Claim {
    let inertia = sym("I");
    let after = motion(&free_rod(inertia.clone(), k(1, 1)));
    let d_positive = Certificate::Positive {
        title: "D = 1 + m/M + m a^2/I > 0".into(),
        expr: paper_d(&inertia),
        strict: true,
        substitutions: vec![],
        positive: vec![
            crate::field::Sym::new("m"),
            crate::field::Sym::new("M"),
            crate::field::Sym::new("I"),
        ],
        nonnegative: vec![],
        form: PosExpr::sum([
            PosExpr::constant(1, 1),
            PosExpr::quotient(PosExpr::sym("m"), PosExpr::sym("M")),
            PosExpr::quotient(
                PosExpr::product([PosExpr::sym("m"), PosExpr::Square(sym("a"))]),
                PosExpr::sym("I"),
            ),
        ]),
    };
    Claim {
        id: "C15",
        location: "Eq. (omega)",
        group: Group::Equations,
        statement: "omega = (2ma/I)/D v0",
        formal: "For m, M, I > 0 and any a, v0, the elastic (e = 1) solution of the impulse equations has \
                 omega = (2 m a/I)/D v0 with D = 1 + m/M + m a^2/I > 0 (omega signed as in DESIGN.md: \
                 the struck point moves forward for a > 0)."
            .into(),
        reason: "the generic solver's omega equals Eq. (omega) identically, and D is visibly positive".into(),
        decision: Decision::Proved(vec![
            Certificate::identity(
                "omega from the impulse equations (e = 1) equals Eq. (omega)",
                after.omega,
                paper.omega.clone(),
            ),
            d_positive,
        ]),
    }
}
