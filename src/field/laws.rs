//! The field-axiom checker every backend's tests run.
//!
//! [`check_field`] takes edge elements (0, +-1, 1/3, a huge and a tiny value, sqrt(d), a symbol)
//! and asserts commutativity, associativity, distributivity, identities and inverses on every
//! pair and triple, with an equality predicate chosen by the backend: `==` for exact fields, an
//! ulp bound for floats. A failure message prints the operands.

use super::Field;

/// Asserts the field axioms on every pair and triple of `samples`, comparing with `eq`.
///
/// # Panics
/// On the first axiom that fails, with the law and the operands in the message.
///
/// # Examples
/// ```
/// use rodimpact::field::{laws, q};
/// laws::check_field(&[q(0, 1), q(1, 1), q(-1, 1), q(1, 3)], |a, b| a == b);
/// ```
pub fn check_field<F: Field>(samples: &[F], eq: impl Fn(&F, &F) -> bool) {
    let zero = F::zero();
    let one = F::one();
    let law = |ok: bool, name: &str, ops: &[&F]| {
        assert!(ok, "{} fails in {} for operands {:?}", name, F::NAME, ops);
    };
    for a in samples {
        law(eq(&(a.clone() + &zero), a), "a + 0 = a", &[a]);
        law(eq(&(a.clone() * &one), a), "a * 1 = a", &[a]);
        law(
            eq(&(a.clone() + &(-a.clone())), &zero),
            "a + (-a) = 0",
            &[a],
        );
        law(eq(&(a.clone() - a), &zero), "a - a = 0", &[a]);
        law(eq(&(a.clone() * &zero), &zero), "a * 0 = 0", &[a]);
        if !a.is_zero() {
            let inv = one.clone() / a;
            law(eq(&(a.clone() * &inv), &one), "a * (1/a) = 1", &[a]);
            law(a.checked_div(a).is_some(), "a / a defined", &[a]);
        } else {
            law(one.checked_div(a).is_none(), "1 / 0 undefined", &[a]);
        }
        for b in samples {
            law(
                eq(&(a.clone() + b), &(b.clone() + a)),
                "a + b = b + a",
                &[a, b],
            );
            law(
                eq(&(a.clone() * b), &(b.clone() * a)),
                "a * b = b * a",
                &[a, b],
            );
            law(
                eq(&(a.clone() - b), &(a.clone() + &(-b.clone()))),
                "a - b = a + (-b)",
                &[a, b],
            );
            if !b.is_zero() {
                law(eq(&(a.clone() / b * b), a), "(a / b) * b = a", &[a, b]);
            }
            for c in samples {
                law(
                    eq(&(a.clone() + b + c), &(a.clone() + &(b.clone() + c))),
                    "(a + b) + c = a + (b + c)",
                    &[a, b, c],
                );
                law(
                    eq(&(a.clone() * b * c), &(a.clone() * &(b.clone() * c))),
                    "(a * b) * c = a * (b * c)",
                    &[a, b, c],
                );
                law(
                    eq(
                        &(a.clone() * &(b.clone() + c)),
                        &(a.clone() * b + &(a.clone() * c)),
                    ),
                    "a * (b + c) = a*b + a*c",
                    &[a, b, c],
                );
            }
        }
    }
}
