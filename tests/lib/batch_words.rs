//! The word-level rows (exact, and f64 with or without claims, and an engine's rows with any
//! rod, pivot and claims) are shortcuts, never a second opinion: on every row they take, the
//! line is the general row's, byte for byte. The general row is reached without a test hook:
//! an absolute tolerance of zero (`--atol 0`) agrees no claim the exact and relative rules do
//! not already agree, and the word rows leave a batch with an absolute tolerance to the
//! general row.

use proptest::prelude::*;
use rodimpact::batch::{Agreement, Arithmetic, Batch, SolvedRow};
use rodimpact::field::Q;

/// The rows of `header`/`lines` solved twice: as given (a word row where one applies) and
/// with `--atol 0` (the general row).
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
    let words = Batch::new(header, arithmetic)
        .unwrap()
        .with_agreement(agreement)
        .unwrap();
    let general = words.clone().with_atol("0").unwrap();
    lines
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let fast = words.row(k + 1, line).unwrap();
            let slow = general.row(k + 1, line).unwrap();
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
        let general = Batch::new("m,M,l,a,v0,e", Arithmetic::Exact).unwrap().with_atol("0").unwrap();
        let solved = general.row(1, &scene).unwrap();
        let values: Vec<&str> = solved.line.trim_end().split(',').skip(6).take(3).collect();
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
        let general = Batch::new("m,M,l,a,v0,e", Arithmetic::Exact).unwrap().with_atol("0").unwrap();
        let solved = general.row(1, &scene).unwrap();
        let (header, line) = if claims {
            let values: Vec<&str> = solved.line.trim_end().split(',').skip(6).take(3).collect();
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

/// An engine's cell for the exact `value`: the value itself, or the value times
/// `1 + k/10^j` printed to 17 significant digits as an engine prints a float (`0.8181818181818183`,
/// `3.0598936213463403e-5`), or a wrong fraction, or nothing (an engine that did not report it),
/// or a float's residue in place of a zero (`4.5569729555140306e-91`: Rapier's V at a centre
/// pivot), of 17 digits and an exponent from -67 to -622: the audit's 1024 and 2560 bits take
/// those an f64 can hold, the general row's rationals the rest.
fn engine_cell(value: &str, (style, k, j): (u8, i64, u32)) -> String {
    let exact = rodimpact::number::parse(value).unwrap();
    match style % 7 {
        0 => value.to_string(),
        1 => "1/3".to_string(),
        5 => String::new(),
        6 => format!(
            "{}4.5569729555140306e-{}",
            if k < 0 { "-" } else { "" },
            30 + 37 * j
        ),
        _ => {
            let off = exact * (Q::from_integer(1.into()) + Q::new(k.into(), 10i64.pow(j).into()));
            let text = rodimpact::field::decimal::decimal(&off, 17);
            if style % 5 == 4 {
                text.replace('e', "E")
            } else {
                text
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// An engine's rows (every rod, free or pivoted, e from 0 to 1, claims of v, V, omega, J
    /// and the energies written as an engine writes them, exact or a little off or wrong),
    /// under exact and relative agreement: the engine row gives the general row's line, checks
    /// and diagnosis.
    #[test]
    fn engine_rows_give_the_general_rows_lines(
        masses in (1i64..40, 1i64..12, 1i64..40, 1i64..12),
        l in (1i64..20, 1i64..6), a in -12i64..=12, v0 in (1i64..40, 1i64..12),
        rod in 0u8..5, e in 0i64..=4, pivot_at in proptest::option::of(-4i64..=4),
        claims in proptest::collection::vec((any::<u8>(), -50i64..50, 1u32..17), 6),
        near in 0u8..5, above in -4i64..=6,
    ) {
        let (m, md, big, big_d) = masses;
        let rod = match rod {
            0 => "uniform".to_string(),
            1 => "dumbbell".to_string(),
            2 => format!("rg={}/{}", l.0, l.1 * 2),
            3 => format!("I={}/{}", big * l.0 * l.0, big_d * l.1 * l.1 * 7),
            _ => String::new(),
        };
        let pivot = pivot_at.map_or(String::new(), |p| format!("{}/{}", p * l.0, 4 * l.1));
        let scene_with = |e: &str| format!(
            "{m}/{md},{big}/{big_d},{}/{},{}/{},{}/{},{rod},{e},{pivot}",
            l.0, l.1, a * l.0, 12 * l.1, v0.0, v0.1
        );
        let scene = scene_with(&format!("{e}/4"));
        let header = "id,m,M,l,a,v0,rod,e,pivot";
        let general = Batch::new(&format!("{header},J,energy_before,energy_after"), Arithmetic::Exact)
            .unwrap()
            .with_atol("0")
            .unwrap();
        let solved = general.row(1, &format!("row,{scene},1,1,1")).unwrap();
        let outputs = |line: &str| -> Vec<String> {
            line.trim_end().split(',').skip(12).take(6).map(str::to_string).collect()
        };
        let mut values = outputs(&solved.line);
        prop_assume!(values.len() == 6);
        // Half the states near another answer the audit names (the e = 0 answer, the state
        // before the impact, the spin flipped), a little off it on either side of 1/100.
        match near {
            1 => {
                let sticking = scene_with("0");
                let stuck = general.row(1, &format!("row,{sticking},1,1,1")).unwrap();
                values[..3].clone_from_slice(&outputs(&stuck.line)[..3]);
            }
            2 => {
                values[0] = format!("{}/{}", v0.0, v0.1);
                values[1] = "0".to_string();
                values[2] = "0".to_string();
            }
            3 => {
                let w = &values[2];
                values[2] = w.strip_prefix('-').map_or_else(|| format!("-{w}"), str::to_string);
            }
            4 => {
                // A spin around the largest any impact point gives, within a few 1/1000.
                let q = |n: i64, d: i64| Q::new(n.into(), d.into());
                let mut b = rodimpact::scene::Scene::builder(q(m, md), q(big, big_d))
                    .half_length(q(l.0, l.1))
                    .a(q(a * l.0, 12 * l.1))
                    .v0(q(v0.0, v0.1))
                    .e(q(e, 4))
                    .rod(rodimpact::scene::RodInertia::parse(if rod.is_empty() { "uniform" } else { &rod }).unwrap());
                if let Some(p) = pivot_at {
                    b = b.pivot(q(p * l.0, 4 * l.1));
                }
                let squared: Q = rodimpact::solve::optimum::omega_max_squared(&b.build().unwrap()).unwrap();
                let omega = num_traits::ToPrimitive::to_f64(&squared).unwrap().sqrt() * (1.0 + above as f64 / 1000.0);
                values[2] = format!("{omega:e}");
            }
            _ => {}
        }
        let cells: Vec<String> = values.iter().zip(&claims).map(|(v, c)| engine_cell(v, *c)).collect();
        let line = format!("row,{scene},{}", cells.join(","));
        let claimed = format!("{header},v,V,omega,J,energy_before,energy_after");
        let rtol = Agreement::Relative(Q::new(1.into(), 1_000_000.into()));
        for agreement in [Agreement::Exact, rtol] {
            for (fast, slow) in agreeing(Arithmetic::Exact, agreement, &claimed, std::slice::from_ref(&line)) {
                prop_assert_eq!(fast, slow, "{}", line);
            }
        }
        // The state alone, audited; and the scene alone.
        let state = format!("row,{scene},{}", cells[..3].join(","));
        for (fast, slow) in both_ways(&format!("{header},v,V,omega"), &[state]) {
            prop_assert_eq!(fast, slow);
        }
        for (fast, slow) in both_ways(header, &[format!("row,{scene}")]) {
            prop_assert_eq!(fast, slow);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// An engine's rows of an oblique scene (any rod, free or pivoted, e from 0 to 1, a
    /// tangential speed, friction that lets the contact slide or stick, a point or a spinning
    /// disc, a rod already moving), claims of v, V, omega, vt, Vt, the spin after and the
    /// tangential impulse written as an engine writes them, a run of two rows of the scene and
    /// the scene under fewer claims, under exact and relative agreement: the oblique engine
    /// row gives the general row's line and checks.
    #[test]
    fn oblique_engine_rows_give_the_general_rows_lines(
        masses in (1i64..40, 1i64..12, 1i64..40, 1i64..12),
        a in -12i64..=12, v0 in (1i64..40, 1i64..12),
        rod in 0u8..4, e in 0i64..=4, pivot_at in proptest::option::of(-4i64..=4),
        v0t in -6i64..=6, mu in proptest::option::of(0i64..=8),
        disc in proptest::option::of((1i64..6, -9i64..=9)),
        moving in proptest::option::of((-3i64..=3, -3i64..=3, -3i64..=3)),
        claims in proptest::collection::vec((any::<u8>(), -50i64..50, 1u32..17), 14),
    ) {
        let (m, md, big, big_d) = masses;
        let rod = ["uniform", "dumbbell", "rg=1/3", ""][usize::from(rod)];
        let pivot = pivot_at.map_or(String::new(), |p| format!("{p}/4"));
        let mu = mu.map_or(String::new(), |k| format!("{k}/4"));
        let (radius, spin) = disc.map_or((String::new(), String::new()), |(r, w)| {
            (format!("{r}/20"), format!("{w}/2"))
        });
        let (rod_v, rod_vt, rod_omega) = match moving {
            Some((v, vt, w)) if pivot_at.is_none() => (format!("{v}/5"), format!("{vt}/7"), format!("{w}/3")),
            Some((_, _, w)) => ("0".to_string(), "0".to_string(), format!("{w}/3")),
            None => (String::new(), String::new(), String::new()),
        };
        let scene = format!(
            "{m}/{md},{big}/{big_d},1,{a}/12,{}/{},{rod},{e}/4,{pivot},{v0t}/3,{mu},{radius},{spin},{rod_v},{rod_vt},{rod_omega}",
            v0.0, v0.1
        );
        let header = "id,m,M,l,a,v0,rod,e,pivot,v0t,mu,radius,spin,rod-v,rod-vt,rod-omega";
        let general = Batch::new(header, Arithmetic::Exact).unwrap().with_atol("0").unwrap();
        let solved = general.row(1, &format!("row,{scene}"));
        prop_assume!(solved.is_ok());
        let values: Vec<String> = solved
            .unwrap()
            .line
            .trim_end()
            .split(',')
            .skip(16)
            .take(7)
            .map(str::to_string)
            .collect();
        let cell = |k: usize| -> String {
            if values[k % 7].is_empty() {
                // No spin after for a point projectile: any claim of it is not checked.
                ["", "1", "0"][usize::from(claims[k].0 % 3)].to_string()
            } else {
                engine_cell(&values[k % 7], claims[k])
            }
        };
        let first: Vec<String> = (0..7).map(cell).collect();
        let second: Vec<String> = (7..14).map(cell).collect();
        let claimed = format!("{header},v,V,omega,vt,Vt,spin_after,tangential_impulse");
        let lines = [
            format!("row,{scene},{}", first.join(",")),
            format!("row,{scene},{}", second.join(",")),
        ];
        let rtol = Agreement::Relative(Q::new(1.into(), 1_000_000.into()));
        for agreement in [Agreement::Exact, rtol] {
            for (fast, slow) in agreeing(Arithmetic::Exact, agreement, &claimed, &lines) {
                prop_assert_eq!(fast, slow, "{:?}", lines);
            }
        }
        // The state alone; and the scene alone.
        let state = format!("row,{scene},{}", first[..3].join(","));
        for (fast, slow) in both_ways(&format!("{header},v,V,omega"), &[state]) {
            prop_assert_eq!(fast, slow);
        }
        for (fast, slow) in both_ways(header, &[format!("row,{scene}")]) {
            prop_assert_eq!(fast, slow);
        }
    }
}
