//! The word-level rows (exact, and f64 with or without claims) are shortcuts, never a second opinion:
//! on every row they take, the line is the general row's, byte for byte. The general row is reached without a test hook:
//! a `rod` column (here always `uniform`, the default) is one the word row does not read, so
//! the same rows with that column go the general way; the cell is then cut out of the line.

use proptest::prelude::*;
use rodimpact::batch::{Agreement, Arithmetic, Batch, SolvedRow};
use rodimpact::field::Q;

/// The rows of `header`/`lines` solved twice: as given (the word row where it applies) and
/// with a trailing `rod` column of `uniform` (the general row), that cell removed again.
fn both_ways(header: &str, lines: &[String]) -> Vec<(SolvedRow, SolvedRow)> {
    in_arithmetic(Arithmetic::Exact, header, lines)
}

/// [`both_ways`] in `arithmetic`.
fn in_arithmetic(
    arithmetic: Arithmetic,
    header: &str,
    lines: &[String],
) -> Vec<(SolvedRow, SolvedRow)> {
    agreeing(arithmetic, Agreement::Exact, header, lines)
}

/// [`in_arithmetic`] with claims agreeing by `agreement`.
fn agreeing(
    arithmetic: Arithmetic,
    agreement: Agreement,
    header: &str,
    lines: &[String],
) -> Vec<(SolvedRow, SolvedRow)> {
    let batch = |header: &str| {
        let b = Batch::new(header, arithmetic).unwrap();
        b.with_agreement(agreement.clone()).unwrap()
    };
    let (words, general) = (batch(header), batch(&format!("{header},rod")));
    lines
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let fast = words.row(k + 1, line).unwrap();
            let mut slow = general.row(k + 1, &format!("{line},uniform")).unwrap();
            slow.line = slow.line.replacen(",uniform,", ",", 1);
            (fast, slow)
        })
        .collect()
}

fn reference(name: &str) -> (String, Vec<String>) {
    let text = std::fs::read_to_string(format!("tests/data/{name}")).unwrap();
    let mut lines = text.lines().map(str::to_string);
    let header = lines.next().unwrap();
    (header, lines.collect())
}

/// Both reference batches, with and without their exact claims: every row the same line, the
/// same checks, laws and diagnosis.
#[test]
fn the_reference_batches_give_the_general_rows_lines() {
    for name in ["bench-1e6.csv", "bench-textbook.csv"] {
        let (header, lines) = reference(name);
        let inputs_only: Vec<String> = lines
            .iter()
            .map(|l| l.split(',').take(5).collect::<Vec<_>>().join(","))
            .collect();
        let short = header.split(',').take(5).collect::<Vec<_>>().join(",");
        for (h, rows) in [(&header, &lines), (&short, &inputs_only)] {
            for arithmetic in [Arithmetic::Exact, Arithmetic::F64] {
                for (fast, slow) in in_arithmetic(arithmetic, h, rows) {
                    assert_eq!(fast, slow, "{name} {arithmetic:?}");
                }
            }
        }
    }
}

/// A cell as a user might write it: unreduced, signed with `+`, spaced, or a decimal (which
/// the word row leaves to the general one).
fn written(n: i64, d: u64, style: u8) -> String {
    match style % 4 {
        0 => format!("{n}/{d}"),
        1 if n >= 0 => format!("+{}/{}", 2 * n, 2 * d),
        2 => format!(" {n}/{d} "),
        _ if d == 1 => format!("{n}.0"),
        _ => format!("{}/{}", 3 * n, 3 * d),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Random scenes (any e, a anywhere on the rod, inputs up to 2^40), written in several
    /// ways, with exact, unreduced, wrong or missing claims: the same line both ways.
    #[test]
    fn random_rows_give_the_general_rows_lines(
        m in 1u64..1 << 40, md in 1u64..1 << 40,
        big in 1u64..1 << 40, big_d in 1u64..1 << 40,
        l in 1u64..1 << 20, a_frac in -1000i64..=1000,
        v0 in 1u64..1 << 30, v0d in 1u64..1 << 30,
        e in 0u64..=7, style in any::<u8>(), claim_style in 0u8..6, small in any::<bool>(),
    ) {
        // Half the scenes below 2^23 a part, where the f64 row takes them too.
        let fit = |x: u64| if small { x % (1 << 23) + 1 } else { x };
        let (m, md, big, big_d, v0, v0d) = (fit(m), fit(md), fit(big), fit(big_d), fit(v0), fit(v0d));
        let a = format!("{}/{}", a_frac * l as i64, 1000);
        let scene = [
            written(m as i64, md, style),
            written(big as i64, big_d, style / 4),
            written(l as i64, 1, style / 16),
            a,
            written(v0 as i64, v0d, style / 64),
            format!("{e}/7"),
        ]
        .join(",");
        // The exact answer, from the general row, as the claims (in several forms).
        let general = Batch::new("m,M,l,a,v0,e,rod", Arithmetic::Exact).unwrap();
        let solved = general.row(1, &format!("{scene},uniform")).unwrap();
        let values: Vec<&str> = solved.line.trim_end().split(',').skip(7).take(3).collect();
        let claims: Vec<String> = values
            .iter()
            .map(|v| match claim_style {
                0 => v.to_string(),
                1 => format!("{v}0").replacen('/', "0/", 1), // unreduced: times 10/10
                2 => "1/3".to_string(),
                3 => String::new(),
                4 => "0".to_string(),
                _ => v.strip_prefix('-').map_or_else(|| format!("-{v}"), str::to_string),
            })
            .collect();
        let rows = both_ways("m,M,l,a,v0,e,v,V,omega", &[format!("{scene},{}", claims.join(","))]);
        for (fast, slow) in rows {
            prop_assert_eq!(fast, slow);
        }
        let rows = both_ways("m,M,l,a,v0,e", std::slice::from_ref(&scene));
        for (fast, slow) in rows {
            prop_assert_eq!(fast, slow);
        }
        // The f64 row rounds every input (and the inertia) from its parts as the general row
        // rounds the exact scene, and measures each claim's relative error the same way.
        let claimed = [format!("{scene},{}", claims.join(","))];
        let header = "m,M,l,a,v0,e,v,V,omega";
        let tight = Agreement::Relative(Q::new(1.into(), 10u64.pow(16).into()));
        for agreement in [Agreement::Exact, tight] {
            for (fast, slow) in agreeing(Arithmetic::F64, agreement, header, &claimed) {
                prop_assert_eq!(fast, slow);
            }
        }
        for (fast, slow) in in_arithmetic(Arithmetic::F64, "m,M,l,a,v0,e", &[scene]) {
            prop_assert_eq!(fast, slow);
        }
    }
}

/// A decimal as a sweep writes it: `[-]w.f[e±x]`, `.f`, `w.`; mantissa of up to 18 digits.
fn decimal(whole: u64, fraction: u64, places: u32, exponent: i32, style: u8) -> String {
    let fraction = (fraction % 10u64.pow(places)).max(1);
    let fraction = format!("{fraction:0width$}", width = places as usize);
    let mantissa = match style % 3 {
        0 if places > 0 => format!(".{fraction}"),
        1 => format!("{whole}."),
        _ if places > 0 => format!("{whole}.{fraction}"),
        _ => whole.to_string(),
    };
    match exponent {
        0 => mantissa,
        x if style.is_multiple_of(2) => format!("{mantissa}e{x}"),
        x => format!("{mantissa}E{x:+}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Scenes written in decimals (the word row reads them as digits over a power of ten, up to
    /// 18 digits a part; beyond, the general row): the same line both ways, exact and f64, with
    /// and without claims.
    #[test]
    fn decimal_rows_give_the_general_rows_lines(
        m in (1u64..1_000_000, 0u64..1 << 40, 0u32..12, -4i32..4, any::<u8>()),
        big in (1u64..1_000_000, 0u64..1 << 40, 0u32..12, -4i32..4, any::<u8>()),
        a_tenths in -10i64..=10, v0 in (1u64..1000, 0u64..1000, 0u32..4, any::<u8>()),
        e_hundredths in 0u64..=100, claims in any::<bool>(),
    ) {
        let (mw, mf, mp, mx, ms) = m;
        let (bw, bf, bp, bx, bs) = big;
        let (vw, vf, vp, vs) = v0;
        let scene = [
            decimal(mw, mf, mp, mx, ms),
            decimal(bw, bf, bp, bx, bs),
            "1.0".to_string(),
            format!("{}{}.{}", if a_tenths < 0 { "-" } else { "" }, a_tenths.abs() / 10, a_tenths.abs() % 10),
            decimal(vw, vf, vp, 0, vs),
            format!("0.{e_hundredths:02}").replace("0.100", "1.00"),
        ]
        .join(",");
        let general = Batch::new("m,M,l,a,v0,e,rod", Arithmetic::Exact).unwrap();
        let solved = general.row(1, &format!("{scene},uniform")).unwrap();
        let (header, line) = if claims {
            let values: Vec<&str> = solved.line.trim_end().split(',').skip(7).take(3).collect();
            ("m,M,l,a,v0,e,v,V,omega", format!("{scene},{}", values.join(",")))
        } else {
            ("m,M,l,a,v0,e", scene.clone())
        };
        for arithmetic in [Arithmetic::Exact, Arithmetic::F64] {
            for (fast, slow) in in_arithmetic(arithmetic, header, std::slice::from_ref(&line)) {
                prop_assert_eq!(fast, slow, "{}", line);
            }
        }
    }
}
