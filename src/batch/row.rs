//! Solving one data row, on the arithmetic of the batch, and writing its output line: the input
//! line with v, V, omega, whether the laws held, and each claim's check appended.

use super::audit::{Finding, audit};
use super::claimed_row::{claimed_row, oblique_row};
use super::compare::{Agreement, Claimed, compare};
use super::fixed_width_row::fixed_width_row;
use super::float_row::float_word_row;
use super::header::Batch;
use super::plan::{
    Arithmetic, CLAIMS, Diagnosis, OutputCheck, RowExpectation, STATE, SolvedRow, write_float,
};
use crate::error::Error;
use crate::field::big::{RBig, to_q, to_rbig};
use crate::field::int::{I256, Unreduced, UnreducedInt, Wide, within};
use crate::field::{Field, Q};
use crate::impact::Mode;
use crate::scene::Scene;
use crate::scene::{Motion, kinetic_energy};
use crate::solve::fast::oblique::State;
use crate::solve::{self, Impact, Route, Why};
use num_traits::{Signed, Zero};

impl Batch {
    /// Solves data row `number` (1-based) given as its line.
    ///
    /// # Errors
    /// `row N, column X: reason` for a bad cell; `row N: ...` for a wrong number of cells.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,omega", Arithmetic::Exact).unwrap();
    /// let row = b.row(1, "1,1,6/5").unwrap();
    /// assert_eq!(row.line, "1,1,6/5,3/5,2/5,6/5,true,true,0\n");
    /// assert_eq!(b.row(2, "1,-1,1").unwrap_err().to_string(), "row 2, column M: must be > 0, got -1");
    ///
    /// // An engine's state, audited: Box2D 2.3 at 1 m/s returns the e = 0 answer for e = 1.
    /// let engine = Batch::new("id,m,M,a,v,V,omega", Arithmetic::Exact).unwrap();
    /// let row = engine.row(1, "low-speed-3,1,1,1/2,0.63592,0.36408,0.54612").unwrap();
    /// assert!(row.line.ends_with(",-0.364,energy-loss;restitution-ignored\n"), "{}", row.line);
    /// ```
    pub fn row(&self, number: usize, line: &str) -> Result<SolvedRow, Error> {
        let line = line.trim_end_matches(['\n', '\r']);
        if let Some(row) = self
            .word_plan
            .as_ref()
            .and_then(|plan| match self.arithmetic {
                Arithmetic::Exact if plan.oblique => {
                    oblique_row(plan, &self.agreement, number, line)
                }
                Arithmetic::Exact => fixed_width_row(plan, number, line)
                    .or_else(|| claimed_row(plan, &self.agreement, number, line)),
                Arithmetic::F64 => float_word_row(plan, &self.agreement, number, line),
            })
        {
            return Ok(self.labelled(row, line));
        }
        let (scene, claimed) = self.cells(number, line)?;
        let mut out = String::with_capacity(2 * line.len() + 64);
        out.push_str(line);
        let extra = |k: usize| self.claims.contains(&k);
        let (values, laws_held, exact_state) = match self.arithmetic {
            Arithmetic::Exact if self.is_oblique() => {
                let (values, laws_hold) = oblique_values(&scene, &mut out);
                out.push_str(if laws_hold { ",true" } else { ",false" });
                (values, Some(laws_hold), None)
            }
            Arithmetic::Exact => {
                let solved = solve::with::<Q>(&scene, self.arithmetic.route())
                    .expect("the fraction-free route takes every scene in Q");
                let laws_hold = solved.laws_hold.unwrap_or(false);
                let values = exact_values(&scene, &solved.after, extra);
                for value in values.iter().flatten() {
                    out.push(',');
                    crate::field::decimal::write_exact(&mut out, value);
                }
                out.push_str(if laws_hold { ",true" } else { ",false" });
                (values, Some(laws_hold), Some(solved.after))
            }
            Arithmetic::F64 => {
                let (values, texts) = float_values(
                    &scene,
                    self.arithmetic.route(),
                    extra,
                    !self.claims.is_empty(),
                );
                for t in texts.iter().flatten() {
                    out.push(',');
                    out.push_str(t);
                }
                (values, None, None)
            }
        };
        let agreement = self.agreement_for(&scene, line);
        let checks = self.write_checks(&mut out, &scene, &claimed, &values, agreement);
        let diagnosis = match (self.audits(), &exact_state) {
            (true, Some(exact)) => {
                let (change, diagnosis) = diagnose(&scene, exact, &claimed, &checks);
                out.push(',');
                out.push_str(&change);
                out.push(',');
                diagnosis.push_text(&mut out);
                Some(diagnosis)
            }
            _ => None,
        };
        out.push('\n');
        let row = SolvedRow::unlabelled(number, out, laws_held, checks, diagnosis);
        Ok(self.labelled(row, line))
    }
}

impl Batch {
    /// Compares each claim of the row with its computed value and writes its cells:
    /// `<name>_ok,<name>_rel_error` (and `<name>_ulps` under `--ulps`), empty for a claim not
    /// given in this row.
    fn write_checks(
        &self,
        out: &mut String,
        scene: &Scene,
        claimed: &[Option<Claimed>; CLAIMS.len()],
        values: &[Option<Q>; CLAIMS.len()],
        agreement: &Agreement,
    ) -> Vec<OutputCheck> {
        let ulps_column = self.ulps_columns();
        let mut checks = Vec::new();
        for &k in &self.claims {
            let (Some(claim), Some(value)) = (&claimed[k], &values[k]) else {
                out.push_str(if ulps_column { ",,," } else { ",," });
                continue;
            };
            let mut check = compare(k, claim, value, agreement, self.arithmetic);
            if let Some(atol) = &self.atol
                && !check.ok
                && let Some(claimed) = claim.value()
            {
                check.ok = (claimed - value).abs() <= atol.clone() * scene_unit(k, scene);
            }
            check.write_cells(out, ulps_column);
            checks.push(check);
        }
        checks
    }

    /// The row, named when the summary lists it (a finding, or a wrong claim), and checked
    /// against the baseline of `--expect`.
    fn labelled(&self, mut row: SolvedRow, line: &str) -> SolvedRow {
        let found = matches!(&row.diagnosis, Some(Diagnosis::Findings(f)) if !f.is_empty());
        let wrong = row.checks.iter().any(|c| !c.ok);
        if found || wrong {
            let label = self.label(row.number, line);
            if let Some(expected) = &self.expected {
                let findings: Vec<&'static str> = match &row.diagnosis {
                    Some(Diagnosis::Findings(f)) => f.iter().map(|f| f.name()).collect(),
                    _ => Vec::new(),
                };
                let (used, unexpected) = expected.check(&label, &findings, wrong);
                row.expectation = Some(RowExpectation { used, unexpected });
            }
            row.label = Some(label);
        } else if self.expected.is_some() {
            row.expectation = Some(RowExpectation::default());
        }
        row
    }

    /// The agreement of a row: the first class rule that takes it, else the batch's own.
    fn agreement_for(&self, scene: &Scene, line: &str) -> &Agreement {
        if self.class_rules.is_empty() {
            return &self.agreement;
        }
        let id = self
            .id_column
            .and_then(|k| line.split(',').nth(k))
            .map(str::trim);
        self.class_rules
            .iter()
            .find(|rule| rule.takes(scene, id))
            .map_or(&self.agreement, |rule| &rule.agreement)
    }

    /// The row's name in the summary: its `id` cell (escaped), or `row N`.
    fn label(&self, number: usize, line: &str) -> String {
        match self.id_column.and_then(|k| line.split(',').nth(k)) {
            Some(id) if !id.trim().is_empty() => crate::echo::echo(id.trim()),
            _ => format!("row {number}"),
        }
    }
}

/// The scene's own unit of the claimed output `k` (v, V, omega, J, energy before, after, vt,
/// Vt, the disc's spin after, Jt): |v0| for the speeds, |v0|/l for omega, |v0|/r for the
/// disc's spin, m |v0| for the impulses, m v0^2/2 for the energies.
fn scene_unit(k: usize, scene: &Scene) -> Q {
    let speed = scene.v0().abs();
    match k {
        0 | 1 | 6 | 7 => speed,
        2 => speed / scene.half_length(),
        8 => match scene.oblique().and_then(|o| o.disc.as_ref()) {
            Some(disc) => speed / &disc.radius,
            None => speed / scene.half_length(),
        },
        3 | 9 => scene.m() * &speed,
        _ => scene.m() * &speed * &speed / Q::from_integer(2.into()),
    }
}

/// The energy change cell and the diagnosis of a row whose state is claimed.
fn diagnose(
    scene: &Scene,
    exact: &Motion<Q>,
    claimed: &[Option<Claimed>; CLAIMS.len()],
    checks: &[OutputCheck],
) -> (String, Diagnosis) {
    let state: Vec<Option<Option<Q>>> = claimed[..STATE]
        .iter()
        .map(|c| c.as_ref().map(Claimed::value))
        .collect();
    if state.iter().any(Option::is_none) {
        return ("-".to_string(), Diagnosis::NotAudited);
    }
    let [Some(Some(v)), Some(Some(rod_v)), Some(Some(omega))] = [&state[0], &state[1], &state[2]]
    else {
        // A claim that is not a finite number: no state to audit.
        return (
            "nan".to_string(),
            Diagnosis::Findings(vec![Finding::NonFinite]),
        );
    };
    // The exact state has no finding and no energy change: no audit work for exact claims
    // (the reference batches claim exact values on every row).
    if checks[..STATE].iter().all(OutputCheck::exact) {
        let finding = if checks.iter().any(|c| c.not_finite) {
            Some(Finding::NonFinite)
        } else {
            checks.iter().any(|c| !c.ok).then_some(Finding::Off)
        };
        return (
            "0".to_string(),
            Diagnosis::Findings(finding.into_iter().collect()),
        );
    }
    let claimed = Motion {
        v: v.clone(),
        rod_v: rod_v.clone(),
        omega: omega.clone(),
    };
    let mut audit = audit(scene, exact, &claimed);
    if checks.iter().any(|c| c.not_finite) {
        audit.findings.push(Finding::NonFinite);
    }
    if audit.findings.is_empty() && checks.iter().any(|c| !c.ok) {
        audit.findings.push(Finding::Off);
    }
    let change = crate::field::decimal::decimal(&audit.energy_change, 3);
    let change = if audit.energy_change.is_positive() {
        format!("+{change}")
    } else {
        change
    };
    (change, Diagnosis::Findings(audit.findings))
}

/// The exact v, V, omega, and J and the energies where `wanted` (they are claimed).
fn exact_values(
    scene: &Scene,
    after: &Motion<Q>,
    wanted: impl Fn(usize) -> bool,
) -> [Option<Q>; CLAIMS.len()] {
    let m = scene.m();
    [
        Some(after.v.clone()),
        Some(after.rod_v.clone()),
        Some(after.omega.clone()),
        wanted(3).then(|| m * (scene.v0() - &after.v)),
        wanted(4).then(|| exact_energy(scene, &Motion::before(scene.v0().clone()))),
        wanted(5).then(|| exact_energy(scene, after)),
        None,
        None,
        None,
        None,
    ]
}

/// The kinetic energy of `motion` in `scene`, exactly: on unreduced fractions of `i128`, 256-
/// or 512-bit integers (the first that holds it) with one reduction at the end, else over
/// dashu's rationals, whose GCD is cheaper than num-bigint's on long numbers.
fn exact_energy(scene: &Scene, motion: &Motion<Q>) -> Q {
    energy_on_words::<i128>(scene, motion)
        .or_else(|| energy_on_words::<I256>(scene, motion))
        .or_else(|| energy_on_words::<Wide>(scene, motion))
        .unwrap_or_else(|| {
            let lifted = motion.as_ref().map(to_rbig);
            to_q(&kinetic_energy(&scene.params::<RBig>(), &lifted))
        })
}

/// [`exact_energy`] on unreduced fractions of `T`; `None` when a value leaves its width.
fn energy_on_words<T: UnreducedInt>(scene: &Scene, motion: &Motion<Q>) -> Option<Q> {
    // Lifted inside `within`: a number too wide for `T` is reported there too.
    within(|| {
        let lifted = motion.as_ref().map(Unreduced::<T>::from_rational);
        kinetic_energy(&scene.params::<Unreduced<T>>(), &lifted)
    })
    .map(Unreduced::to_q)
}

/// Writes v, V, omega and the oblique columns (`vt, Vt, spin, tangential_impulse, contact`;
/// `spin` empty for a point projectile, `contact` empty without friction) of an oblique
/// header's row, solved exactly by [`Impact::on_both_axes`]; returns the values a claim may be
/// compared with (v, V, omega, vt, Vt, the spin after and Jt, in [`CLAIMS`] order) and whether
/// every law held.
fn oblique_values(scene: &Scene, out: &mut String) -> ([Option<Q>; CLAIMS.len()], bool) {
    let impact = Impact::on_both_axes(scene);
    let done = impact.oblique.as_ref().expect("answered on both axes");
    write_oblique_cells(
        out,
        (&done.after, &done.tangential_impulse, done.contact),
        crate::field::decimal::write_exact,
    );
    (
        oblique_claims(&done.after, &done.tangential_impulse),
        impact.laws_hold,
    )
}

/// Appends an oblique row's exact cells: v, V, omega, vt, Vt, the spin after (empty for a
/// point projectile), Jt, each by `write`, and the contact (empty without friction).
pub(super) fn write_oblique_cells<T>(
    out: &mut String,
    (after, jt, contact): (&State<T>, &T, Option<Mode>),
    write: impl Fn(&mut String, &T),
) {
    let values = [
        Some(&after.v),
        Some(&after.rod.v),
        Some(&after.rod.omega),
        Some(&after.vt),
        Some(&after.rod.vt),
        after.spin.as_ref(),
        Some(jt),
    ];
    for value in values {
        out.push(',');
        if let Some(x) = value {
            write(out, x);
        }
    }
    out.push(',');
    out.push_str(contact.map_or("", |c| c.kind()));
}

/// The exact value of each claim an oblique row checks, in [`CLAIMS`] order: v, V, omega, vt,
/// Vt, the spin after (a disc only) and Jt; none for J and the energies (the paper's scene's
/// claims).
pub(super) fn oblique_claims<T: Clone>(after: &State<T>, jt: &T) -> [Option<T>; CLAIMS.len()] {
    [
        Some(after.v.clone()),
        Some(after.rod.v.clone()),
        Some(after.rod.omega.clone()),
        None,
        None,
        None,
        Some(after.vt.clone()),
        Some(after.rod.vt.clone()),
        after.spin.clone(),
        Some(jt.clone()),
    ]
}

/// v, V, omega by `route` in f64 (NaN where the system underflowed to a singular one; and J
/// and the energies where `wanted`), as shortest round-trip text (a zero is written `0.0`,
/// whatever its sign: `-0.0` only says which way the float rounded) and, when `compared`, as
/// exact dyadic rationals (no exact work otherwise).
fn float_values(
    scene: &Scene,
    route: Route,
    wanted: impl Fn(usize) -> bool,
    compared: bool,
) -> ([Option<Q>; CLAIMS.len()], [Option<String>; CLAIMS.len()]) {
    let m = match solve::with::<f64>(scene, route) {
        Ok(solved) => solved.after,
        Err(e) if e.why == Why::Singular => Motion {
            v: f64::NAN,
            rod_v: f64::NAN,
            omega: f64::NAN,
        },
        Err(e) => unreachable!("{e}: the batch's f64 route takes every scene"),
    };
    // The parameters (with the rod's exact inertia, rounded) only when J or an energy is
    // claimed.
    let params = (wanted(3) || wanted(4) || wanted(5)).then(|| scene.params::<f64>());
    let with = |f: &dyn Fn(&crate::scene::Params<f64>) -> f64| params.as_ref().map(f);
    let xs = [
        Some(m.v),
        Some(m.rod_v),
        Some(m.omega),
        wanted(3).then(|| with(&|p| p.m * (p.v0 - m.v))).flatten(),
        wanted(4)
            .then(|| with(&|p| kinetic_energy(p, &Motion::before(p.v0))))
            .flatten(),
        wanted(5)
            .then(|| with(&|p| kinetic_energy(p, &m)))
            .flatten(),
        None,
        None,
        None,
        None,
    ];
    let exact = xs.map(|x| {
        x.filter(|_| compared)
            .map(|x| crate::field::exact_float(x).unwrap_or_else(Q::zero))
    });
    let text = |x: f64| {
        let mut out = String::new();
        write_float(&mut out, x);
        out
    };
    (exact, xs.map(|x| x.map(text)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claims_agree_only_when_exact() {
        let b = Batch::new("m,M,v,V,omega", Arithmetic::Exact).unwrap();
        let row = b.row(1, "1,1,0.6,2/5,1.2").unwrap();
        assert!(row.checks.iter().all(|v| v.ok));
        let wrong = b.row(2, "1,1,0.6,0.4000001,1.2").unwrap();
        assert_eq!(
            wrong.line,
            "1,1,0.6,0.4000001,1.2,3/5,2/5,6/5,true,true,0,false,0.000000250,true,0,+8.00e-8,off\n"
        );
    }

    /// The energies are exact in every width: a scene of small fractions (i128), one whose
    /// numbers pass 2^127 (I256, Wide) and one beyond 512 bits (dashu's rationals), each
    /// against the energy over Q.
    #[test]
    fn energies_are_exact_in_every_width() {
        let wide = |bits: u32| Q::new(num_bigint::BigInt::from(3) << bits, 7.into());
        use crate::field::q;
        for m in [q(2, 3), wide(100), wide(200), wide(600)] {
            let s = Scene::builder(m, q(5, 2)).a(q(1, 3)).build().unwrap();
            let after = crate::solve::fast::fraction_free::solve(&s).after;
            let want = kinetic_energy(&s.params::<Q>(), &after);
            assert_eq!(exact_energy(&s, &after), want);
        }
    }

    #[test]
    fn empty_optional_cells_take_the_defaults() {
        let b = Batch::new("m,M,pivot,e", Arithmetic::Exact).unwrap();
        let free = b.row(1, "1,1,,").unwrap();
        assert_eq!(free.line, "1,1,,,3/5,2/5,6/5,true\n");
        let pivoted = b.row(2, "1,3,0,0").unwrap();
        assert_eq!(pivoted.line, "1,3,0,0,1/2,0,1/2,true\n");
        assert_eq!(
            b.row(3, ",1,,").unwrap_err().to_string(),
            "row 3, column m: empty number"
        );
    }

    /// The oblique columns: the sliding end hit of `solve --v0t 1 --mu 1/2` (m = M = 1, by
    /// hand v = 3/5, V = 2/5, omega = 6/5, vt = 4/5, Vt = 1/5, Jt = 1/5), a row without
    /// friction, f64 refused, and J or energy claims refused with oblique columns.
    #[test]
    fn oblique_columns_are_solved_exactly() {
        let b = Batch::new("m,M,v0t,mu,omega", Arithmetic::Exact).unwrap();
        assert_eq!(
            b.output_header(),
            "m,M,v0t,mu,omega,v,V,omega_exact,vt,Vt,spin,tangential_impulse,contact,laws_held,omega_ok,omega_rel_error\n"
        );
        let row = b.row(1, "1,1,1,1/2,6/5").unwrap();
        assert_eq!(
            row.line,
            "1,1,1,1/2,6/5,3/5,2/5,6/5,4/5,1/5,,1/5,slide,true,true,0\n"
        );
        let plain = b.row(2, "1,1,,,").unwrap();
        assert_eq!(plain.line, "1,1,,,,3/5,2/5,6/5,0,0,,0,,true,,\n");
        assert_eq!(
            Batch::new("m,M,mu", Arithmetic::F64)
                .unwrap_err()
                .to_string(),
            "header: column 'mu': oblique and frictional scenes are solved exactly; the f64 arithmetic takes the paper's scene only"
        );
        assert_eq!(
            Batch::new("m,M,mu,J", Arithmetic::Exact)
                .unwrap_err()
                .to_string(),
            "header: claim column 'J' with column 'mu': J and the energies are checked for the paper's scene only (claim v, V, omega, vt, Vt, spin_after, tangential_impulse)"
        );
        let audited = Batch::new("m,M,mu,v,V,omega", Arithmetic::Exact).unwrap();
        assert!(!audited.output_header().contains("diagnosis"));
    }
}
