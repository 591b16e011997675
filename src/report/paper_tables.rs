//! The exact tables of the paper's results, T1-T5, for `rodimpact table` and `rodimpact paper`.
//!
//! Every scene is taken with m = 1, l = 1 and v0 = 1, so lengths are in units of l, velocities
//! in units of v0 and angular velocities in units of v0/l; the mass ratio M/m is the parameter.

use super::table::{Cell, Header, Table};
use crate::error::Error;
use crate::field::{Q, QSqrt, q};
use crate::number;
use crate::optimum::{Placement, optimum};
use crate::scene::{Params, RodInertia, Scene};
use crate::solve::{Outcome, solve};
use num_traits::{One, Zero};

/// The choices a user can make for the tables.
#[derive(Debug, Clone, PartialEq)]
pub struct TableOptions {
    /// Mass ratios M/m for T1 and T5.
    pub ratios: Vec<Q>,
    /// The mass ratio M/m of T2 and T3.
    pub ratio: Q,
    /// Mass distribution of the rod (T1, T2, T3, T5); `rg=` and `I=` are in units of l and M l^2.
    pub rod: RodInertia,
    /// Coefficient of restitution (T1, T2, T5).
    pub e: Q,
    /// A pivot position in units of l for T1 (T5 always shows the centre and an end).
    pub pivot: Option<Q>,
}

impl Default for TableOptions {
    /// The paper's setting: uniform elastic free rod, M/m from 1/100 to 100, M = m for T2/T3.
    fn default() -> Self {
        TableOptions {
            ratios: [
                (1, 100),
                (1, 10),
                (1, 2),
                (1, 1),
                (3, 2),
                (2, 1),
                (3, 1),
                (10, 1),
                (100, 1),
            ]
            .iter()
            .map(|&(n, d)| q(n, d))
            .collect(),
            ratio: Q::one(),
            rod: RodInertia::Uniform,
            e: Q::one(),
            pivot: None,
        }
    }
}

/// Decimal digits shown next to exact values.
const DIGITS: usize = 12;

fn decimal(x: &Q) -> Cell {
    Cell::Text(number::decimal(x, DIGITS))
}

fn decimal_surd(x: &QSqrt) -> Cell {
    Cell::Text(x.decimal(DIGITS))
}

fn decimal_root(x: &Q) -> Cell {
    Cell::Text(number::decimal_sqrt(x, DIGITS))
}

/// The unit scene (m = l = v0 = 1) with rod mass `ratio`.
fn unit_scene(ratio: &Q, rod: &RodInertia, e: &Q, pivot: Option<&Q>) -> Result<Scene, Error> {
    let mut b = Scene::builder(Q::one(), ratio.clone())
        .rod(rod.clone())
        .e(e.clone());
    if let Some(p) = pivot {
        b = b.pivot(p.clone());
    }
    b.build()
}

/// T1: where omega peaks, against the mass ratio.
pub fn t1(opts: &TableOptions) -> Result<Table, Error> {
    let mut rows = Vec::new();
    for ratio in &opts.ratios {
        let s = unit_scene(ratio, &opts.rod, &opts.e, opts.pivot.as_ref())?;
        let o = optimum(&s);
        let ratio_end = o.end_to_max();
        rows.push(vec![
            Cell::Rational(ratio.clone()),
            Cell::Rational(o.squared.clone()),
            Cell::Root(o.squared.clone()),
            decimal_root(&o.squared),
            Cell::Text(o.placement.as_str().into()),
            Cell::Surd(ratio_end.clone()),
            decimal_surd(&ratio_end),
        ]);
    }
    let from = if opts.pivot.is_some() {
        "from the pivot"
    } else {
        "from the centre"
    };
    Ok(Table {
        id: "T1",
        title: "Where the rod spins fastest".into(),
        note: format!(
            "a* = optimal impact distance {from}, in units of l; ω(end)/ω_max is the fraction of the best spin that an end hit gives. Rod: {}, e = {}.",
            opts.rod, opts.e
        ),
        headers: vec![
            Header::new("M/m", "$M/m$", "M_over_m"),
            Header::new("a*²/l²", "$a^{*2}/l^2$", "a_star_squared_over_l2"),
            Header::new("a*/l", "$a^*/l$", "a_star_over_l"),
            Header::new("≈", "$\\approx$", "a_star_over_l_decimal"),
            Header::new("a*", "$a^*$", "a_star_position"),
            Header::new(
                "ω(end)/ω_max",
                "$\\omega(\\mathrm{end})/\\omega_{\\max}$",
                "omega_end_over_max",
            ),
            Header::new("≈", "$\\approx$", "omega_end_over_max_decimal"),
        ],
        rows,
    })
}

/// `scene` hit at `a` (possibly irrational), solved exactly in Q(sqrt d).
fn solve_at(scene: &Scene, a: QSqrt) -> Outcome<QSqrt> {
    let params = Params {
        a,
        ..scene.params::<QSqrt>()
    };
    solve(&params).expect("a valid scene is nonsingular")
}

/// T2: v, V and omega along the rod for one mass ratio, a* included.
pub fn t2(opts: &TableOptions) -> Result<Table, Error> {
    let s = unit_scene(&opts.ratio, &opts.rod, &opts.e, None)?;
    let o = optimum(&s);
    let mut points: Vec<(Cell, QSqrt)> = [(0, 1), (1, 4), (1, 2), (3, 4), (1, 1)]
        .iter()
        .map(|&(n, d)| (Cell::Rational(q(n, d)), QSqrt::rational(q(n, d))))
        .collect();
    let a_star = QSqrt::sqrt_of(&o.squared);
    if o.placement != Placement::Beyond {
        let at = points
            .iter()
            .position(|(_, a)| a.cmp_exact(&a_star).is_ge())
            .unwrap_or(points.len());
        points.insert(at, (Cell::Root(o.squared.clone()), a_star));
    }
    let mut rows = Vec::new();
    for (label, a) in points {
        let after = solve_at(&s, a).after;
        rows.push(vec![
            label,
            Cell::Surd(after.v),
            Cell::Surd(after.rod_v),
            Cell::Surd(after.omega.clone()),
            decimal_surd(&after.omega),
        ]);
    }
    let star = match o.placement {
        Placement::Beyond => "a* lies beyond the end and is not listed".to_string(),
        _ => format!(
            "the row a/l = {} is the optimum a*",
            Cell::Root(o.squared.clone()).render(super::Format::Markdown)
        ),
    };
    Ok(Table {
        id: "T2",
        title: format!(
            "Velocities after the impact along the rod, M/m = {}",
            opts.ratio
        ),
        note: format!(
            "Velocities in units of v0, ω in units of v0/l; {star}. Rod: {}, e = {}.",
            opts.rod, opts.e
        ),
        headers: vec![
            Header::new("a/l", "$a/l$", "a_over_l"),
            Header::new("v/v0", "$v/v_0$", "v"),
            Header::new("V/v0", "$V/v_0$", "V"),
            Header::new("ω l/v0", "$\\omega l/v_0$", "omega"),
            Header::new("≈", "$\\approx$", "omega_decimal"),
        ],
        rows,
    })
}

/// T3: elastic, e = 1/2 and sticking impacts at the point of fastest spin.
pub fn t3(opts: &TableOptions) -> Result<Table, Error> {
    let mut rows = Vec::new();
    let mut omega_elastic = None;
    for e in [q(1, 1), q(1, 2), q(0, 1)] {
        let s = unit_scene(&opts.ratio, &opts.rod, &e, None)?;
        let o = optimum(&s);
        let a = match o.placement {
            Placement::Beyond => QSqrt::one(),
            _ => QSqrt::sqrt_of(&o.squared),
        };
        let out = solve_at(&s, a);
        let omega = out.after.omega;
        let reference = omega_elastic.get_or_insert_with(|| omega.clone()).clone();
        rows.push(vec![
            Cell::Rational(e),
            Cell::Surd(out.after.v),
            Cell::Surd(out.after.rod_v),
            Cell::Surd(omega.clone()),
            Cell::Surd(omega / &reference),
            Cell::Surd(out.energy.lost / &out.energy.before),
        ]);
    }
    Ok(Table {
        id: "T3",
        title: format!(
            "Elastic, half-elastic and sticking impacts at the optimum, M/m = {}",
            opts.ratio
        ),
        note: format!(
            "Struck at a* (or at the end when a* is beyond it); a* does not depend on e. Velocities in units of v0, ω in v0/l; ΔK/K0 is the fraction of the kinetic energy lost; ω/ω_el = (1 + e)/2 exactly, so ω_el = 2 ω_inel. Rod: {}.",
            opts.rod
        ),
        headers: vec![
            Header::new("e", "$e$", "e"),
            Header::new("v/v0", "$v/v_0$", "v"),
            Header::new("V/v0", "$V/v_0$", "V"),
            Header::new("ω l/v0", "$\\omega l/v_0$", "omega"),
            Header::new(
                "ω/ω_el",
                "$\\omega/\\omega_{\\mathrm{el}}$",
                "omega_over_elastic",
            ),
            Header::new("ΔK/K0", "$\\Delta K/K_0$", "energy_lost_fraction"),
        ],
        rows,
    })
}

/// T4: inhomogeneous rods: the mass ratio below which a* lies on the rod.
pub fn t4() -> Result<Table, Error> {
    let mut rows = Vec::new();
    for tenths in 1..=10 {
        let r = q(tenths, 10);
        let s = unit_scene(&Q::one(), &RodInertia::Gyration(r.clone()), &Q::one(), None)?;
        let o = optimum(&s);
        let (threshold, approx) = match &o.threshold_mass {
            Some(t) => (Cell::Rational(t.clone()), decimal(t)),
            None => (
                Cell::Text("none".into()),
                Cell::Text("a* beyond the end for every M".into()),
            ),
        };
        rows.push(vec![
            Cell::Rational(r.clone()),
            Cell::Rational(&r * &r),
            threshold,
            approx,
            Cell::Root(o.squared.clone()),
            Cell::Text(o.placement.as_str().into()),
        ]);
    }
    Ok(Table {
        id: "T4",
        title: "Inhomogeneous rods: where intuition fails".into(),
        note: "Radius of gyration r_G (I = M r_G^2); a* < l exactly when M/m < (l/r_G)^2 - 1. r_G = l is the ideal dumbbell. The last two columns are for M = m.".into(),
        headers: vec![
            Header::new("r_G/l", "$r_G/l$", "rg_over_l"),
            Header::new("I/(M l²)", "$I/(M l^2)$", "I_over_M_l2"),
            Header::new("a* < l iff M/m <", "$a^*<l$ iff $M/m<$", "threshold_M_over_m"),
            Header::new("≈", "$\\approx$", "threshold_decimal"),
            Header::new("a*/l at M = m", "$a^*/l$ at $M=m$", "a_star_over_l_at_M_eq_m"),
            Header::new("a* at M = m", "$a^*$ at $M=m$", "a_star_position_at_M_eq_m"),
        ],
        rows,
    })
}

/// T5: the pivoted rod: best distance from the pivot and the centre of percussion.
pub fn t5(opts: &TableOptions) -> Result<Table, Error> {
    let mut rows = Vec::new();
    for (name, pivot) in [("centre", Q::zero()), ("end", -Q::one())] {
        for ratio in &opts.ratios {
            let s = unit_scene(ratio, &opts.rod, &opts.e, Some(&pivot))?;
            let o = optimum(&s);
            let inertia_p = s.inertia() + ratio * &pivot * &pivot;
            let percussion = if pivot.is_zero() {
                Cell::Text("none".into())
            } else {
                Cell::Rational(inertia_p / (ratio * &pivot * &pivot))
            };
            rows.push(vec![
                Cell::Text(name.into()),
                Cell::Rational(ratio.clone()),
                Cell::Root(o.squared.clone()),
                decimal_root(&o.squared),
                Cell::Text(o.placement.as_str().into()),
                percussion,
            ]);
        }
    }
    Ok(Table {
        id: "T5",
        title: "Rod on a fixed pivot: best impact distance and centre of percussion".into(),
        note: format!(
            "d* = sqrt(I_p/m) from the pivot (I_p = I + M p^2), in units of l; the free arm is l (pivot at the centre) or 2l (pivot at an end). The centre of percussion d = I_p/(M |p|) is where the pivot feels no impulse. Rod: {}, e = {}.",
            opts.rod, opts.e
        ),
        headers: vec![
            Header::new("pivot", "pivot", "pivot"),
            Header::new("M/m", "$M/m$", "M_over_m"),
            Header::new("d*/l", "$d^*/l$", "d_star_over_l"),
            Header::new("≈", "$\\approx$", "d_star_decimal"),
            Header::new("d*", "$d^*$", "d_star_position"),
            Header::new(
                "centre of percussion /l",
                "c.\\ of percussion $/l$",
                "percussion_over_l",
            ),
        ],
        rows,
    })
}

/// All five tables.
///
/// # Errors
/// An option that makes an invalid scene (for example `rg=` larger than 1).
///
/// # Examples
/// ```
/// use rodimpact::report::{all_tables, TableOptions};
/// let tables = all_tables(&TableOptions::default()).unwrap();
/// assert_eq!(tables.iter().map(|t| t.id).collect::<Vec<_>>(), ["T1", "T2", "T3", "T4", "T5"]);
/// ```
pub fn all_tables(opts: &TableOptions) -> Result<Vec<Table>, Error> {
    Ok(vec![t1(opts)?, t2(opts)?, t3(opts)?, t4()?, t5(opts)?])
}
