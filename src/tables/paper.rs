//! The exact tables of the paper's results, T1-T5, for `rodimpact table` and `rodimpact paper`.
//!
//! Every scene is taken with m = 1, l = 1 and v0 = 1, so lengths are in units of l, velocities
//! in units of v0 and angular velocities in units of v0/l; the mass ratio M/m is the parameter.

use super::{Cell, Column, Table};
use crate::error::{Error, ErrorKind};
use crate::field::big::{RBig, to_q};
use crate::field::notation::{self, Notation};
use crate::field::{Q, QSqrt, q};
use crate::scene::{Disc, RodInertia, Scene};
use crate::solve::Outcome;
use crate::solve::fast::linear;
use crate::solve::fast::oblique;
use crate::solve::optimum::{Placement, optimum};
use num_traits::{One, Signed, Zero};

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
    /// The projectile's velocity along the rod, in units of v0, for T6 (the oblique table).
    pub v0t: Q,
    /// T6's impact point, in units of l (default 1, the end).
    pub a: Q,
    /// T6's projectile as a solid disc (I = m r^2/2): its radius in units of l and its spin
    /// before the impact in units of v0/l; a point projectile when `None`.
    pub disc: Option<Disc>,
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
            v0t: Q::one(),
            a: Q::one(),
            disc: None,
        }
    }
}

/// The unit scene (m = l = v0 = 1) with rod mass `ratio`; `rod` is in units of l and M l^2, so
/// `I=X` means I = X M l^2 = X * ratio here.
fn unit_scene(ratio: &Q, rod: &RodInertia, e: &Q, pivot: Option<&Q>) -> Result<Scene, Error> {
    let rod = match rod {
        RodInertia::Moment(x) => RodInertia::Moment(x * ratio),
        other => other.clone(),
    };
    let mut b = Scene::builder(Q::one(), ratio.clone())
        .rod(rod)
        .e(e.clone());
    if let Some(p) = pivot {
        b = b.pivot(p.clone());
    }
    b.build()
}

/// `x` times `unit` in math: `l`, `-l`, `1/10\,l` (for x = 1, -1, 1/10).
fn times(x: &Q, unit: &str) -> String {
    if x.is_one() {
        unit.to_string()
    } else if (-x).is_one() {
        format!("-{unit}")
    } else {
        format!("{x}\\,{unit}")
    }
}

/// The rod of the options, in words and math: `uniform`, `$r_G = 1/10\,l$`.
fn rod_markup(rod: &RodInertia) -> String {
    match rod {
        RodInertia::Uniform => "uniform".into(),
        RodInertia::Dumbbell => "dumbbell".into(),
        RodInertia::Gyration(r) => format!("$r_G = {}$", times(r, "l")),
        RodInertia::Moment(x) => format!("$I = {}$", times(x, "M l^2")),
    }
}

/// `Rod: uniform; $e = 1$.`: the end of every note that depends on the options.
fn setting(opts: &TableOptions, with_e: bool) -> String {
    let rod = rod_markup(&opts.rod);
    if with_e {
        format!("Rod: {rod}; $e = {}$.", opts.e)
    } else {
        format!("Rod: {rod}.")
    }
}

/// T1: where omega peaks, against the mass ratio.
pub fn t1(opts: &TableOptions) -> Result<Table, Error> {
    let mut rows = Vec::new();
    for ratio in &opts.ratios {
        let s = unit_scene(ratio, &opts.rod, &opts.e, opts.pivot.as_ref())?;
        let o = optimum(&s).expect("a rod at rest before the impact has an optimum");
        rows.push(vec![
            Cell::Rational(ratio.clone()),
            Cell::Rational(o.squared.clone()),
            Cell::root(&o.squared),
            Cell::Text(o.placement.as_str().into()),
            Cell::Surd(o.end_to_max()),
        ]);
    }
    let from = match &opts.pivot {
        Some(p) => format!("from the pivot at $p = {}$", times(p, "l")),
        None => "from the centre".into(),
    };
    Ok(Table {
        id: "T1",
        title: "Where the rod spins fastest".into(),
        note: format!(
            "$a^*$ is the optimal impact distance {from}, in units of $l$; $\\omega(\\mathrm{{end}})/\\omega_{{\\max}}$ is the fraction of the best spin that an end hit gives. {}",
            setting(opts, true)
        ),
        columns: vec![
            Column::exact("$M/m$", "M/m"),
            Column::exact("$a^{*2}/l^2$", "a_star^2/l^2"),
            Column::with_decimals("$a^*/l$", "a_star/l"),
            Column::exact("$a^*$", "a_star_position"),
            Column::with_decimals(
                "$\\omega(\\mathrm{end})/\\omega_{\\max}$",
                "omega_end/omega_max",
            ),
        ],
        rows,
    })
}

/// `scene` hit at `a` (possibly irrational), solved exactly in Q(sqrt d).
fn solve_at(scene: &Scene, a: QSqrt) -> Outcome<QSqrt> {
    linear::solve_at(scene, a).expect("a valid scene is nonsingular")
}

/// T2: v, V and omega along the rod for one mass ratio, a* included (once: when a* is one of
/// the listed points, that row is the optimum).
pub fn t2(opts: &TableOptions) -> Result<Table, Error> {
    let s = unit_scene(&opts.ratio, &opts.rod, &opts.e, None)?;
    let o = optimum(&s).expect("a rod at rest before the impact has an optimum");
    let mut points: Vec<QSqrt> = [(0, 1), (1, 4), (1, 2), (3, 4), (1, 1)]
        .iter()
        .map(|&(n, d)| QSqrt::rational(q(n, d)))
        .collect();
    let a_star = QSqrt::sqrt_of(&o.squared);
    if o.placement != Placement::Beyond {
        let at = points
            .iter()
            .position(|a| a.cmp_exact(&a_star).is_ge())
            .unwrap_or(points.len());
        if points.get(at).is_none_or(|a| a.cmp_exact(&a_star).is_ne()) {
            points.insert(at, a_star.clone());
        }
    }
    let mut rows = Vec::new();
    for a in points {
        let after = solve_at(&s, a.clone()).after;
        rows.push(vec![
            Cell::Surd(a),
            Cell::Surd(after.v),
            Cell::Surd(after.rod_v),
            Cell::Surd(after.omega),
        ]);
    }
    let star = match o.placement {
        Placement::Beyond => "$a^*$ lies beyond the end and is not listed".to_string(),
        _ => format!(
            "the row $a/l = {}$ is the optimum $a^*$",
            notation::surd(&a_star, Notation::LatexInline)
        ),
    };
    Ok(Table {
        id: "T2",
        title: format!(
            "Velocities after the impact along the rod, $M/m = {}$",
            opts.ratio
        ),
        note: format!(
            "Velocities in units of $v_0$, $\\omega$ in units of $v_0/l$; {star}. {}",
            setting(opts, true)
        ),
        columns: vec![
            Column::exact("$a/l$", "a/l"),
            Column::exact("$v/v_0$", "v/v0"),
            Column::exact("$V/v_0$", "V/v0"),
            Column::with_decimals("$\\omega\\, l/v_0$", "omega*l/v0"),
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
        let o = optimum(&s).expect("a rod at rest before the impact has an optimum");
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
            Cell::Surd(out.energy.lost() / &out.energy.before),
        ]);
    }
    Ok(Table {
        id: "T3",
        title: format!(
            "Elastic, half-elastic and sticking impacts at the optimum, $M/m = {}$",
            opts.ratio
        ),
        note: format!(
            "Struck at $a^*$ (or at the end when $a^*$ is beyond it); $a^*$ does not depend on $e$. Velocities in units of $v_0$, $\\omega$ in units of $v_0/l$; $\\Delta K/K_0$ is the fraction of the kinetic energy lost; $\\omega/\\omega_{{\\mathrm{{el}}}} = (1 + e)/2$ exactly, so $\\omega_{{\\mathrm{{el}}}} = 2\\,\\omega_{{\\mathrm{{inel}}}}$. {}",
            setting(opts, false)
        ),
        columns: vec![
            Column::exact("$e$", "e"),
            Column::exact("$v/v_0$", "v/v0"),
            Column::exact("$V/v_0$", "V/v0"),
            Column::with_decimals("$\\omega\\, l/v_0$", "omega*l/v0"),
            Column::exact("$\\omega/\\omega_{\\mathrm{el}}$", "omega/omega_elastic"),
            Column::exact("$\\Delta K/K_0$", "energy_lost/K0"),
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
        let o = optimum(&s).expect("a rod at rest before the impact has an optimum");
        rows.push(vec![
            Cell::Rational(r.clone()),
            Cell::Rational(&r * &r),
            o.threshold_mass
                .clone()
                .map_or(Cell::Absent, Cell::Rational),
            Cell::root(&o.squared),
            Cell::Text(o.placement.as_str().into()),
        ]);
    }
    Ok(Table {
        id: "T4",
        title: "Inhomogeneous rods: where intuition fails".into(),
        note: "Radius of gyration $r_G$ ($I = M r_G^2$); $a^* < l$ exactly when $M/m < (l/r_G)^2 - 1$, so for $r_G = l$ (the ideal dumbbell) $a^*$ lies beyond the end for every $M$ and there is no threshold. The last two columns are for $M = m$.".into(),
        columns: vec![
            Column::exact("$r_G/l$", "r_G/l"),
            Column::exact("$I/(M l^2)$", "I/(M*l^2)"),
            Column::with_decimals("$a^* < l$ iff $M/m <$", "threshold_M/m"),
            Column::with_decimals("$a^*/l$ at $M = m$", "a_star/l_at_M=m"),
            Column::exact("$a^*$ at $M = m$", "a_star_position_at_M=m"),
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
            let o = optimum(&s).expect("a rod at rest before the impact has an optimum");
            let inertia_p = s.inertia() + ratio * &pivot * &pivot;
            let percussion = if pivot.is_zero() {
                Cell::Absent
            } else {
                Cell::Rational(inertia_p / (ratio * &pivot * &pivot))
            };
            rows.push(vec![
                Cell::Text(name.into()),
                Cell::Rational(ratio.clone()),
                Cell::root(&o.squared),
                Cell::Text(o.placement.as_str().into()),
                percussion,
            ]);
        }
    }
    Ok(Table {
        id: "T5",
        title: "Rod on a fixed pivot: best impact distance and centre of percussion".into(),
        note: format!(
            "$d^* = \\sqrt{{I_p/m}}$ from the pivot ($I_p = I + M p^2$), in units of $l$; the free arm is $l$ (pivot at the centre) or $2l$ (pivot at an end). The centre of percussion $d = I_p/(M \\lvert p\\rvert)$ is where the pivot feels no impulse; a pivot at the centre has none. {}",
            setting(opts, true)
        ),
        columns: vec![
            Column::exact("pivot", "pivot"),
            Column::exact("$M/m$", "M/m"),
            Column::with_decimals("$d^*/l$", "d_star/l"),
            Column::exact("$d^*$", "d_star_position"),
            Column::exact("centre of percussion / $l$", "percussion/l"),
        ],
        rows,
    })
}

/// T6: an oblique impact with friction, as mu grows past the exact threshold mu* at which the
/// contact stops sliding: the rod of T2 and T3 (`ratio`, `rod`, `e`) struck at `a` (the end by
/// default) by a projectile also moving along the rod with `v0t`, or a solid disc spinning
/// with `disc`. The rows are mu = 0, 1/10, 1/4, 1/2, 1, 2 and mu* itself, and 2 mu* when mu* is
/// not below 2, so that the table always runs past the threshold.
///
/// # Errors
/// A scene the options make invalid (`a` off the rod, a radius that is not positive), or no
/// slip at the contact before the impact (v0t + spin r = 0): friction would have nothing to do.
///
/// # Examples
/// ```
/// use rodimpact::tables::{t6, Cell, TableOptions};
/// use rodimpact::field::q;
/// let t = t6(&TableOptions::default()).unwrap();
/// // M = m, end hit, e = 1, v0t = v0: mu* = 5/4, where the contact starts to stick.
/// let threshold = t.rows.iter().find(|r| r[1] == Cell::Text("stick".into())).unwrap();
/// assert_eq!(threshold[0], Cell::Rational(q(5, 4)));
/// ```
pub fn t6(opts: &TableOptions) -> Result<Table, Error> {
    let base = unit_scene(&opts.ratio, &opts.rod, &opts.e, None)?;
    let scene = |mu: &Q| {
        let mut b = Scene::builder(Q::one(), opts.ratio.clone())
            .rod(base.rod().clone())
            .e(opts.e.clone())
            .a(opts.a.clone())
            .v0t(opts.v0t.clone());
        if let Some(d) = &opts.disc {
            b = b.disc(d.radius.clone(), d.spin.clone());
        }
        if !mu.is_zero() {
            b = b.mu(mu.clone());
        }
        b.build()
    };
    // Over dashu's rationals: at the input limits num-bigint's GCD took most of a minute.
    let solved = |s: &Scene| {
        let o = s.oblique().cloned().unwrap_or_default();
        oblique::solve(&s.params::<RBig>(), &o.params(), None)
            .expect("exact rationals decide stick or slide, and every mass is positive")
    };
    // mu* = |u_t|/(J k_t): the stick impulse over the normal impulse.
    let frictionless = solved(&scene(&Q::zero())?);
    if frictionless.stick_impulse.is_zero() {
        return Err(Error::new(
            "v0t",
            ErrorKind::Invalid(
                "nothing slides at the contact before the impact (v0t + spin r = 0), so friction has nothing to do: give a --v0t or a disc's --spin".into(),
            ),
        ));
    }
    let threshold = to_q(&(frictionless.stick_impulse.abs() / &frictionless.impulse));
    let mut mus: Vec<Q> = [(0, 1), (1, 10), (1, 4), (1, 2), (1, 1), (2, 1)]
        .iter()
        .map(|&(n, d)| q(n, d))
        .chain([threshold.clone()])
        .collect();
    if threshold >= q(2, 1) {
        mus.push(&threshold * q(2, 1));
    }
    mus.sort();
    mus.dedup();
    let mut rows = Vec::new();
    for mu in &mus {
        let out = solved(&scene(mu)?);
        let contact = match out.contact {
            None => "frictionless",
            Some(c) => c.kind(),
        };
        let cell = |x: &RBig| Cell::Rational(to_q(x));
        let mut row = vec![
            Cell::Rational(mu.clone()),
            Cell::Text(contact.into()),
            cell(&out.tangential_impulse),
            cell(&out.after.vt),
            cell(&out.after.rod.vt),
        ];
        row.extend(out.after.spin.as_ref().map(cell));
        row.extend([cell(&out.after.rod.omega), cell(&out.lost_friction)]);
        rows.push(row);
    }
    let (title, at) = if opts.a.is_one() {
        (
            "at the end of the rod".to_string(),
            "the end ($a = l$)".to_string(),
        )
    } else {
        let at = format!("at $a = {}$", times(&opts.a, "l"));
        (at.clone(), at)
    };
    let along = if opts.v0t.is_zero() {
        "not along it".to_string()
    } else {
        format!("$v_{{0t}} = {}$ along it", times(&opts.v0t, "v_0"))
    };
    let disc = match &opts.disc {
        None => String::new(),
        Some(d) => format!(
            "; it is a solid disc of radius $r = {}$ ($I = m r^2/2$) spinning at $\\omega_{{d0}} = {}$ before the impact, so its rim slips at $v_{{0t}} + \\omega_{{d0}}\\,r$",
            times(&d.radius, "l"),
            times(&d.spin, "v_0/l")
        ),
    };
    let mut columns = vec![
        Column::exact("$\\mu$", "mu"),
        Column::exact("contact", "contact"),
        Column::with_decimals("$J_t/(m v_0)$", "Jt/(m*v0)"),
        Column::exact("$v_t/v_0$", "vt/v0"),
        Column::exact("$V_t/v_0$", "Vt/v0"),
    ];
    if opts.disc.is_some() {
        columns.push(Column::exact("$\\omega_d l/v_0$", "spin*l/v0"));
    }
    columns.extend([
        Column::exact("$\\omega l/v_0$", "omega*l/v0"),
        Column::with_decimals("$\\Delta E_{\\mu}/(m v_0^2)$", "friction_loss/(m*v0^2)"),
    ]);
    Ok(Table {
        id: "T6",
        title: format!("Oblique impact with friction {title}"),
        note: format!(
            "The projectile strikes {at} moving at $v_0$ across the rod and {along}{disc}; $m = 1$, $M/m = {}$. Friction $\\mu$ at the contact: the tangential impulse $J_t$ along the rod stops the slip when $\\mu$ is at least $\\mu^* = {}$ (stick), else it is $\\mu\\,J$ (slide). Impulses in units of $m v_0$, energies of $m v_0^2$, $\\omega$ of $v_0/l$; $\\Delta E_{{\\mu}}$ is the kinetic energy lost to friction, $\\omega$ the frictionless value in every row, since $J_t$ acts through the centre. {}",
            opts.ratio,
            threshold,
            setting(opts, true)
        ),
        columns,
        rows,
    })
}

/// A function that builds one table from the options.
type TableBuilder = fn(&TableOptions) -> Result<Table, Error>;

/// The ids of the paper's tables, in the order they are printed (`table` and `paper`).
pub const TABLE_IDS: [&str; 5] = ["T1", "T2", "T3", "T4", "T5"];

/// Every table `table --only` builds: the paper's and T6, the oblique impact beyond the paper.
pub const ALL_TABLE_IDS: [&str; 6] = ["T1", "T2", "T3", "T4", "T5", "T6"];

/// The tables whose ids `wanted` names (any order, `t2` or `T2`), built alone and printed in
/// the order of [`ALL_TABLE_IDS`]: a table not asked for is never computed.
///
/// # Errors
/// `only: unknown table 'X'` for an id that is not one of [`TABLE_IDS`]; a scene the options
/// make invalid.
///
/// # Examples
/// ```
/// use rodimpact::tables::{tables, TableOptions};
/// let t = tables(&["t5", "T2"], &TableOptions::default()).unwrap();
/// assert_eq!(t.iter().map(|t| t.id).collect::<Vec<_>>(), ["T2", "T5"]);
/// assert_eq!(tables(&["T9"], &TableOptions::default()).unwrap_err().to_string(),
///            "only: unknown table 'T9'; the tables are T1-T6");
/// ```
pub fn tables(wanted: &[&str], opts: &TableOptions) -> Result<Vec<Table>, Error> {
    let wanted: Vec<String> = wanted
        .iter()
        .map(|w| w.trim().to_ascii_uppercase())
        .collect();
    if let Some(bad) = wanted.iter().find(|w| !ALL_TABLE_IDS.contains(&w.as_str())) {
        return Err(Error::new(
            "only",
            ErrorKind::Invalid(format!(
                "unknown table '{}'; the tables are T1-T6",
                crate::echo::echo(bad)
            )),
        ));
    }
    let builders: [TableBuilder; 6] = [t1, t2, t3, |_| t4(), t5, t6];
    ALL_TABLE_IDS
        .iter()
        .zip(builders)
        .filter(|(id, _)| wanted.iter().any(|w| w == *id))
        .map(|(_, build)| build(opts))
        .collect()
}

/// The paper's tables, T1 to T5 (T6 only on request).
///
/// # Examples
/// ```
/// use rodimpact::tables::{all_tables, TableOptions};
/// let tables = all_tables(&TableOptions::default()).unwrap();
/// assert_eq!(tables.iter().map(|t| t.id).collect::<Vec<_>>(), ["T1", "T2", "T3", "T4", "T5"]);
/// ```
pub fn all_tables(opts: &TableOptions) -> Result<Vec<Table>, Error> {
    tables(&TABLE_IDS, opts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{Format, render_document};

    /// Regression (NEWCOMER #7): the captions put `<` and `|p|` in LaTeX's text mode, where OT1
    /// prints `¡` and em dashes, and wrote `ω_max`, `v0` and `a*` as text. Outside `$…$` the
    /// LaTeX now holds no character that text mode misprints, and the symbols are math.
    #[test]
    fn latex_keeps_math_in_math_mode() {
        let tables = all_tables(&TableOptions::default()).unwrap();
        let latex = render_document(&tables, Format::Latex);
        for (i, text) in latex.split('$').enumerate().filter(|(i, _)| i % 2 == 0) {
            for bad in ['<', '>', '|', '√', 'ω', '≈', '²', 'Δ'] {
                assert!(
                    !text.contains(bad),
                    "{bad:?} in text mode: {text:?} (part {i})"
                );
            }
            let unescaped_underscore = text
                .match_indices('_')
                .any(|(at, _)| !text[..at].ends_with('\\'));
            assert!(!unescaped_underscore, "raw _ in text mode: {text:?}");
        }
        for math in [
            r"$a^* < l$",
            r"$d = I_p/(M \lvert p\rvert)$",
            r"$v_0$",
            r"$\omega(\mathrm{end})/\omega_{\max}$",
            r"$d^* = \sqrt{I_p/m}$",
        ] {
            assert!(latex.contains(math), "{math}");
        }
        // Decimal columns are aligned on the point (dcolumn).
        assert!(latex.contains(r"\usepackage{dcolumn}"));
        assert!(latex.contains(r"D{.}{.}{1.12}"));
    }

    /// The end-hit fraction at M = m is 2√6/5 exactly; a* = √6/3 (the paper's sqrt(2/3)).
    #[test]
    fn t1_at_equal_masses() {
        let opts = TableOptions {
            ratios: vec![q(1, 1)],
            ..TableOptions::default()
        };
        let row = &t1(&opts).unwrap().rows[0];
        assert_eq!(row[1], Cell::Rational(q(2, 3)));
        assert_eq!(row[2].render(Format::Markdown), "√6/3");
        assert_eq!(row[4].render(Format::Csv), "2*sqrt(6)/5");
    }
}
