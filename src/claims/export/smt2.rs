//! SMT-LIB 2 (QF_NRA) for z3: the hypotheses asserted, then for each check the negation of the
//! conclusion (or the conclusion, for a witness), `(check-sat-using qfnra)` (z3's strategy for
//! nonlinear real arithmetic: preprocessing, then its complete procedure nlsat; its default
//! incremental solver times out on some of these after a `push`, and nlsat alone on the
//! frictional energy of X30), and a last line
//! `; expect: ...` with the answers meant, in order.

use super::expr::{Expr, Prop, parse};
use super::physics::{hypotheses, unknowns};
use super::statement::{Expect, Statement};
use super::{Exported, header};
use crate::claims::Entry;
use crate::claims::certificate::Relation;
use std::collections::BTreeSet;

fn expr(e: &Expr) -> String {
    match e {
        Expr::Int(n) => n.to_string(),
        Expr::Name(n) => n.clone(),
        Expr::Neg(x) => format!("(- {})", expr(x)),
        Expr::Add(x, y) => format!("(+ {} {})", expr(x), expr(y)),
        Expr::Sub(x, y) => format!("(- {} {})", expr(x), expr(y)),
        Expr::Mul(x, y) => format!("(* {} {})", expr(x), expr(y)),
        Expr::Div(x, y) => format!("(/ {} {})", expr(x), expr(y)),
        Expr::Pow(x, n) => {
            let base = expr(x);
            if *n == 1 {
                base
            } else {
                format!("(* {})", vec![base; *n as usize].join(" "))
            }
        }
    }
}

fn prop(p: &Prop) -> String {
    match p {
        Prop::Relation(op, x, y) => {
            let (x, y) = (expr(x), expr(y));
            match op {
                Relation::Eq => format!("(= {x} {y})"),
                Relation::Ne => format!("(not (= {x} {y}))"),
                Relation::Lt => format!("(< {x} {y})"),
                Relation::Le => format!("(<= {x} {y})"),
                Relation::Gt => format!("(> {x} {y})"),
                Relation::Ge => format!("(>= {x} {y})"),
            }
        }
        Prop::Not(q) => format!("(not {})", prop(q)),
        Prop::And(qs) => format!("(and {})", join(qs)),
        Prop::Or(qs) => format!("(or {})", join(qs)),
        Prop::Implies(q, r) => format!("(=> {} {})", prop(q), prop(r)),
    }
}

fn join(ps: &[Prop]) -> String {
    ps.iter().map(prop).collect::<Vec<_>>().join(" ")
}

fn parsed(text: &str) -> Prop {
    parse(text).unwrap_or_else(|e| panic!("a claim's statement: {e}"))
}

/// The SMT-LIB 2 file of a stated claim.
pub(super) fn write(entry: &Entry, statement: &Statement) -> Exported {
    let hyps = hypotheses(statement);
    let mut names = BTreeSet::new();
    for h in &hyps {
        names.extend(parsed(&h.text).names());
    }
    for impact in statement.impacts {
        names.extend(unknowns(&statement.scene, impact));
    }
    let checks: Vec<_> = statement
        .checks
        .iter()
        .map(|c| {
            let given: Vec<Prop> = c.given.iter().map(|g| parsed(g)).collect();
            let claim = parsed(c.claim);
            for p in given.iter().chain([&claim]) {
                names.extend(p.names());
            }
            (c, given, claim)
        })
        .collect();
    let mut out = header(entry, statement, "; ");
    out.push_str(
        "; The hypotheses are the physics (balance equations and contact law in fresh unknowns,\n\
         ; the domain), not rodimpact's solution. Each check asserts the negation of its\n\
         ; conclusion, so `unsat` proves it (after a `sat`, with a model, showing that the\n\
         ; hypotheses alone are consistent, so the proof is not vacuous); a reading meant to fail,\n\
         ; or a witness, answers `sat` with a model. Run: z3 FILE\n",
    );
    out.push_str("(set-logic QF_NRA)\n");
    for n in &names {
        out.push_str(&format!("(declare-const {n} Real)\n"));
    }
    for h in &hyps {
        out.push_str(&format!(
            "; {}\n(assert {})\n",
            h.label,
            prop(&parsed(&h.text))
        ));
    }
    let mut answers = Vec::new();
    for (i, (check, given, claim)) in checks.iter().enumerate() {
        out.push_str(&format!("; check {}: {}\n", i + 1, check.what));
        let lemmas: Vec<String> = check
            .using
            .iter()
            .map(|&j| {
                let (earlier, _, proved) = &checks[j];
                assert!(
                    j < i
                        && earlier.expect == Expect::Holds
                        && earlier.given.iter().all(|g| check.given.contains(g)),
                    "{}: check {} may use only earlier proved checks whose hypotheses it has",
                    entry.id,
                    i + 1
                );
                format!(
                    "; proved above (check {}), a lemma\n(assert {})\n",
                    j + 1,
                    prop(proved)
                )
            })
            .collect();
        let mut block = |note: &str, asserted: Option<String>, answer: &'static str| {
            out.push_str(&format!("; {note}\n(push 1)\n"));
            for g in given {
                out.push_str(&format!("(assert {})\n", prop(g)));
            }
            for lemma in &lemmas {
                out.push_str(lemma);
            }
            if let Some(asserted) = asserted {
                out.push_str(&format!("(assert {asserted})\n"));
            }
            out.push_str("(check-sat-using qfnra)\n");
            if answer == "sat" {
                out.push_str("(get-model)\n");
            }
            out.push_str("(pop 1)\n");
            answers.push(answer);
        };
        let negated = Some(format!("(not {})", prop(claim)));
        match check.expect {
            Expect::Holds => {
                // Not vacuous: the hypotheses alone have a model.
                block("the hypotheses are consistent", None, "sat");
                block("the negation of the conclusion is not", negated, "unsat");
            }
            Expect::Fails => block("the negation of the reading is satisfiable", negated, "sat"),
            Expect::Exists => block("a witness", Some(prop(claim)), "sat"),
        }
    }
    out.push_str(&format!("; expect: {}\n", answers.join(" ")));
    Exported {
        name: format!("{}.smt2", entry.id),
        text: out,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powers_are_written_as_products_and_logic_as_prefix() {
        let p = parse("not (x^3 - y/2 >= -z or x != 1)").unwrap();
        assert_eq!(
            prop(&p),
            "(not (or (>= (- (* x x x) (/ y 2)) (- z)) (not (= x 1))))"
        );
    }
}
