//! Regression (G6 of the third hostile-input review): an engine log could name its own columns
//! `v_ok`, `laws_held`, `v_exact`, `diagnosis`, ...; they passed through beside rodimpact's
//! columns of the same names, and a reader taking the first column of a name read the forged
//! verdict. Now no output header ever holds a name twice: such a header is refused.

use proptest::prelude::*;
use rodimpact::batch::{Agreement, Arithmetic, Batch, FloatFormat};
use rodimpact::field::q;

/// Every name a header might hold: rodimpact's inputs, claims and outputs under every option,
/// an engine's own columns, an empty name and one with spaces.
const VOCABULARY: &[&str] = &[
    "l",
    "a",
    "v0",
    "rod",
    "e",
    "pivot",
    "v0t",
    "mu",
    "radius",
    "spin",
    "rod-v",
    "rod-vt",
    "rod-omega",
    "v",
    "V",
    "omega",
    "J",
    "energy_before",
    "energy_after",
    "v_exact",
    "V_exact",
    "omega_exact",
    "J_exact",
    "energy_before_exact",
    "energy_after_exact",
    "v_f64",
    "V_f64",
    "omega_f64",
    "J_f64",
    "vt",
    "Vt",
    "spin_after",
    "tangential_impulse",
    "contact",
    "laws_held",
    "v_ok",
    "v_rel_error",
    "v_ulps",
    "V_ok",
    "V_rel_error",
    "V_ulps",
    "omega_ok",
    "omega_rel_error",
    "omega_ulps",
    "J_ok",
    "J_rel_error",
    "energy_after_ok",
    "energy_change",
    "diagnosis",
    "id",
    "engine",
    "dt",
    "",
    " v_ok",
    "diagnosis ",
    "m",
    "M",
];

fn names(header: &str) -> Vec<String> {
    header
        .trim_end()
        .split(',')
        .map(|n| n.trim().to_string())
        .collect()
}

/// The header, arithmetic and agreement, or the first refusal.
fn build(header: &str, f64: bool, agreement: u8) -> Result<Batch, String> {
    let arithmetic = if f64 {
        Arithmetic::F64
    } else {
        Arithmetic::Exact
    };
    let agreement = match agreement {
        0 => Agreement::Exact,
        1 => Agreement::Relative(q(1, 1000)),
        _ => Agreement::Ulps(4, FloatFormat::F64),
    };
    Batch::new(header, arithmetic)
        .and_then(|b| b.with_agreement(agreement))
        .map_err(|e| e.to_string())
}

#[test]
fn the_forged_engine_log_of_the_review_is_refused() {
    let err = build("m,M,v,v_exact,v_ok,laws_held", false, 0).unwrap_err();
    assert!(
        err.starts_with("header: column 'v_exact' is a name rodimpact writes"),
        "{err}"
    );
    for (header, name) in [
        ("id,m,M,v,V,omega,omega_ok", "omega_ok"),
        ("id,m,M,v,V,omega,diagnosis", "diagnosis"),
        ("id,m,M,v,V,omega,energy_change", "energy_change"),
        ("id,m,M,laws_held", "laws_held"),
        ("m,M,mu,contact", "contact"),
        ("m,M, laws_held ", "laws_held"),
    ] {
        let err = build(header, false, 0).unwrap_err();
        assert!(
            err.starts_with(&format!(
                "header: column '{name}' is a name rodimpact writes"
            )),
            "{header}: {err}"
        );
    }
    // Only what this output writes is refused: `v_exact` is free when v is not claimed, and
    // `v_ulps` when the agreement is not in ulps.
    assert!(build("m,M,v_exact", false, 0).is_ok());
    assert!(build("m,M,v,v_ulps", false, 1).is_ok());
    assert!(
        build("m,M,v,v_ulps", false, 2)
            .unwrap_err()
            .contains("'v_ulps' is a name rodimpact writes")
    );
    assert_eq!(
        build("id,m,M,id", false, 0).unwrap_err(),
        "header: column 'id' given twice"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Whatever the header, arithmetic and agreement: an accepted batch writes every name once,
    /// and a refused one names a column of its input.
    #[test]
    fn no_output_header_holds_a_name_twice(
        picks in proptest::collection::vec(0..VOCABULARY.len(), 0..10),
        f64 in any::<bool>(),
        agreement in 0u8..3,
        at in 0usize..10,
    ) {
        let mut columns: Vec<&str> = picks.iter().map(|&i| VOCABULARY[i]).collect();
        columns.insert(at.min(columns.len()), "M");
        columns.insert(0, "m");
        let header = columns.join(",");
        match build(&header, f64, agreement) {
            Ok(batch) => {
                let out = names(&batch.output_header());
                let mut sorted = out.clone();
                sorted.sort();
                sorted.dedup();
                prop_assert_eq!(sorted.len(), out.len(), "{} -> {:?}", header, out);
            }
            Err(err) => {
                prop_assert!(err.lines().count() == 1, "{}", err);
                if let Some(rest) = err.strip_prefix("header: column '") {
                    let name = &rest[..rest.find('\'').unwrap()];
                    prop_assert!(names(&header).iter().any(|n| n == name), "{}: {}", header, err);
                }
            }
        }
    }
}
