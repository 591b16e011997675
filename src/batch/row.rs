//! Solving one data row, on the arithmetic of the batch, and writing its output line: the input
//! line with v, V, omega, whether the laws held, and each claim's check appended.

use super::compare::{OutputCheck, compare};
use super::header::{Arithmetic, Batch};
use crate::error::Error;
use crate::field::Q;
use crate::mechanics::Motion;
use crate::scene::Scene;
use crate::solve::{self, Route, Why, oblique};
use num_traits::Zero;

/// One output row: the CSV line (with its newline) and what the summary needs.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Arithmetic};
/// let row = Batch::new("m,M", Arithmetic::Exact).unwrap().row(1, "1,1").unwrap();
/// assert_eq!((row.line.as_str(), row.laws_held), ("1,1,3/5,2/5,6/5,true\n", Some(true)));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct SolvedRow {
    /// The data row's number (1-based, as in error messages).
    pub number: usize,
    /// The output line.
    pub line: String,
    /// The laws held exactly (`None` in f64, which decides no law).
    pub laws_held: Option<bool>,
    /// The claims of the row.
    pub checks: Vec<OutputCheck>,
}

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
    /// ```
    pub fn row(&self, number: usize, line: &str) -> Result<SolvedRow, Error> {
        let line = line.trim_end_matches(['\n', '\r']);
        let (scene, claimed) = self.cells(number, line)?;
        let mut out = String::with_capacity(2 * line.len() + 64);
        out.push_str(line);
        let (exact, laws_held) = match self.arithmetic {
            Arithmetic::Exact if self.is_oblique() => oblique_values(&scene, &mut out),
            Arithmetic::Exact => {
                let solved = solve::with::<Q>(&scene, self.arithmetic.route())
                    .expect("the fraction-free route takes every scene in Q");
                for value in solved.after.iter() {
                    out.push(',');
                    crate::field::decimal::write_exact(&mut out, value);
                }
                (solved.after.into_array(), solved.laws_hold)
            }
            Arithmetic::F64 => {
                let (exact, texts) = float_values(&scene, self.arithmetic.route());
                for t in &texts {
                    out.push(',');
                    out.push_str(t);
                }
                (exact, None)
            }
        };
        out.push_str(match laws_held {
            Some(true) => ",true",
            Some(false) => ",false",
            None => ",-",
        });
        let mut checks = Vec::new();
        for &k in &self.claims {
            let Some(claim) = &claimed[k] else {
                out.push_str(",,");
                continue;
            };
            let check = compare(k, claim, &exact[k], self.arithmetic);
            out.push_str(if check.ok { ",true," } else { ",false," });
            out.push_str(&match &check.rel_error {
                Some(r) => crate::field::decimal::decimal(r, 3),
                None => "inf".to_string(),
            });
            checks.push(check);
        }
        out.push('\n');
        Ok(SolvedRow {
            number,
            line: out,
            laws_held,
            checks,
        })
    }
}

/// Writes v, V, omega and the oblique columns (`vt, Vt, spin, tangential_impulse, contact`;
/// `spin` empty for a point projectile, `contact` empty without friction) of an oblique
/// header's row, solved exactly (the normal problem fraction-free, then
/// [`oblique::complete`]); returns v, V, omega and whether every law held.
fn oblique_values(scene: &Scene, out: &mut String) -> ([Q; 3], Option<bool>) {
    let normal = scene.normal_problem();
    let solved = solve::with::<Q>(&normal, Route::FractionFree)
        .expect("the fraction-free route takes every scene in Q");
    let o = scene.oblique().cloned().unwrap_or_default();
    let done = oblique::complete(&scene.params(), &o.params(), solved.after, None)
        .expect("Q decides stick or slide, and every mass is positive");
    let after = &done.after;
    let values = [
        Some(&after.v),
        Some(&after.rod.v),
        Some(&after.rod.omega),
        Some(&after.vt),
        Some(&after.rod.vt),
        after.spin.as_ref(),
        Some(&done.tangential_impulse),
    ];
    for value in values {
        out.push(',');
        if let Some(x) = value {
            crate::field::decimal::write_exact(out, x);
        }
    }
    out.push(',');
    out.push_str(done.contact.map_or("", |c| c.as_str()));
    let laws = solved.laws_hold == Some(true) && done.residuals.all_zero();
    let exact = [
        after.v.clone(),
        after.rod.v.clone(),
        after.rod.omega.clone(),
    ];
    (exact, Some(laws))
}

/// v, V, omega by `route` in f64 (NaN where the system underflowed to a singular one), as exact
/// dyadic rationals and shortest round-trip text (a zero is written `0.0`, whatever its sign:
/// `-0.0` only says which way the float rounded).
fn float_values(scene: &Scene, route: Route) -> ([Q; 3], [String; 3]) {
    let xs = match solve::with::<f64>(scene, route) {
        Ok(solved) => solved.after,
        Err(e) if e.why == Why::Singular => Motion {
            v: f64::NAN,
            rod_v: f64::NAN,
            omega: f64::NAN,
        },
        Err(e) => unreachable!("{e}: the batch's f64 route takes every scene"),
    }
    .into_array();
    let exact = xs.map(|x| Q::from_float(x).unwrap_or_else(Q::zero));
    let text = |x: f64| {
        if x == 0.0 {
            "0.0".to_string()
        } else {
            format!("{x:?}")
        }
    };
    (exact, xs.map(text))
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
            "1,1,0.6,0.4000001,1.2,3/5,2/5,6/5,true,true,0,false,0.000000250,true,0\n"
        );
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
    /// friction, and f64 refused.
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
    }
}
