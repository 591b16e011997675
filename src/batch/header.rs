//! The header of a batch file (which column feeds which scene field or claim, and the columns
//! appended to the output) and the cells of a data row, read into a scene and claimed values.

use super::compare::Claimed;
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::scene::{Scene, SceneInput};
use crate::solve::Route;

/// The arithmetic of a batch (`rodimpact batch --backend exact|f64`). Not a
/// [`stability::Backend`](crate::stability::Backend): that one pairs a number format with a float
/// formula to measure its error; this one only says how the batch's rows are solved.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Arithmetic};
/// let row = Batch::new("m,M", Arithmetic::F64).unwrap().row(1, "1,1").unwrap();
/// assert_eq!(row.laws_held, None); // f64 decides nothing exactly
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arithmetic {
    /// Exact rationals by [`Route::FractionFree`]: claims agree only when exactly equal.
    Exact,
    /// The naive closed form in f64 ([`Route::ClosedForm`], the paper's formulas as a float
    /// code would write them): claims agree within [`FLOAT_TOLERANCE`](super::FLOAT_TOLERANCE);
    /// laws not decided.
    F64,
}

impl Arithmetic {
    /// The route the batch solves by.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{batch::Arithmetic, solve::Route};
    /// assert_eq!(Arithmetic::F64.route(), Route::ClosedForm);
    /// ```
    pub fn route(self) -> Route {
        match self {
            Arithmetic::Exact => Route::FractionFree,
            Arithmetic::F64 => Route::ClosedForm,
        }
    }
}

const SCENE_COLUMNS: [&str; 15] = [
    "m",
    "M",
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
];
/// The first of the oblique scene columns (`v0t` ... `rod-omega`) in `SCENE_COLUMNS`.
const FIRST_OBLIQUE: usize = 8;
/// The columns an oblique header appends after `omega` (docs/conventions.md).
pub(super) const OBLIQUE_OUTPUTS: [&str; 5] = ["vt", "Vt", "spin", "tangential_impulse", "contact"];
pub(super) const OUTPUTS: [&str; 3] = ["v", "V", "omega"];

/// A parsed header: which input column feeds which scene field or claim.
#[derive(Debug, Clone)]
pub struct Batch {
    pub(super) arithmetic: Arithmetic,
    /// Per input column: index into `SCENE_COLUMNS`, or its length + index into `OUTPUTS` for a
    /// claim.
    columns: Vec<usize>,
    pub(super) claims: Vec<usize>,
    header: String,
}

impl Batch {
    /// Parses the header line.
    ///
    /// # Errors
    /// `header: ...` for an unknown or repeated column, or when m or M is missing.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,a,v", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,a,v,v_exact,V,omega,laws_held,v_ok,v_rel_error\n");
    /// assert_eq!(Batch::new("m,M,x", Arithmetic::Exact).unwrap_err().to_string(),
    ///            "header: unknown column 'x' (expected m, M, l, a, v0, rod, e, pivot, v0t, mu, radius, spin, rod-v, rod-vt, rod-omega, v, V, omega)");
    /// ```
    pub fn new(header: &str, arithmetic: Arithmetic) -> Result<Batch, Error> {
        let header = header.trim_start_matches('\u{feff}').trim_end();
        let bad = |why: String| Error::new("header", ErrorKind::Invalid(why));
        let mut columns = Vec::new();
        for name in header.split(',').map(str::trim) {
            let index = SCENE_COLUMNS
                .iter()
                .chain(&OUTPUTS)
                .position(|c| *c == name)
                .ok_or_else(|| {
                    bad(format!(
                        "unknown column '{}' (expected {}, {})",
                        crate::echo::echo(name),
                        SCENE_COLUMNS.join(", "),
                        OUTPUTS.join(", ")
                    ))
                })?;
            if columns.contains(&index) {
                return Err(bad(format!(
                    "column '{}' given twice",
                    crate::echo::echo(name)
                )));
            }
            columns.push(index);
        }
        for required in [0, 1] {
            if !columns.contains(&required) {
                return Err(bad(format!(
                    "column '{}' is required",
                    SCENE_COLUMNS[required]
                )));
            }
        }
        let claims = (0..3)
            .filter(|k| columns.contains(&(SCENE_COLUMNS.len() + k)))
            .collect();
        let oblique = columns
            .iter()
            .find(|&&c| (FIRST_OBLIQUE..SCENE_COLUMNS.len()).contains(&c));
        if let (Some(&c), Arithmetic::F64) = (oblique, arithmetic) {
            return Err(bad(format!(
                "column '{}': oblique and frictional scenes are solved exactly; the f64 arithmetic takes the paper's scene only",
                SCENE_COLUMNS[c]
            )));
        }
        Ok(Batch {
            arithmetic,
            columns,
            claims,
            header: header.to_string(),
        })
    }

    /// Whether the header has an oblique scene column: then every row is solved as an oblique
    /// scene and the output gains `vt, Vt, spin, tangential_impulse, contact` after `omega`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// assert!(Batch::new("m,M,mu", Arithmetic::Exact).unwrap().is_oblique());
    /// assert!(!Batch::new("m,M,e", Arithmetic::Exact).unwrap().is_oblique());
    /// let disc = Batch::new("m,M,radius,spin", Arithmetic::Exact).unwrap();
    /// assert!(disc.output_header().contains(",spin_after,"));
    /// ```
    pub fn is_oblique(&self) -> bool {
        self.columns
            .iter()
            .any(|&c| (FIRST_OBLIQUE..SCENE_COLUMNS.len()).contains(&c))
    }

    /// The header of the output file (with its newline). The computed columns are named for
    /// what they hold: `v, V, omega` exactly (`v_exact`, ... beside a claim of that name), or
    /// `v_f64, V_f64, omega_f64` with the f64 arithmetic.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,omega", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,omega,v,V,omega_exact,laws_held,omega_ok,omega_rel_error\n");
    /// let f = Batch::new("m,M", Arithmetic::F64).unwrap();
    /// assert_eq!(f.output_header(), "m,M,v_f64,V_f64,omega_f64,laws_held\n");
    /// ```
    pub fn output_header(&self) -> String {
        let mut out = self.header.clone();
        for (k, name) in OUTPUTS.iter().enumerate() {
            let suffix = match self.arithmetic {
                Arithmetic::F64 => "_f64",
                Arithmetic::Exact if self.claims.contains(&k) => "_exact",
                Arithmetic::Exact => "",
            };
            out.push_str(&format!(",{name}{suffix}"));
        }
        if self.is_oblique() {
            for name in OBLIQUE_OUTPUTS {
                // The disc's spin after the impact, beside the input column `spin` (before).
                let input = SCENE_COLUMNS.iter().position(|c| *c == name);
                let clash = input.is_some_and(|c| self.columns.contains(&c));
                let suffix = if clash { "_after" } else { "" };
                out.push_str(&format!(",{name}{suffix}"));
            }
        }
        out.push_str(",laws_held");
        for &k in &self.claims {
            out.push_str(&format!(",{0}_ok,{0}_rel_error", OUTPUTS[k]));
        }
        out.push('\n');
        out
    }

    /// The scene and the claimed v, V, omega of data row `number` (1-based), without solving.
    ///
    /// # Errors
    /// As [`Batch::row`]: `row N, column X: reason`, or `row N: ...` for a wrong number of cells.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// use rodimpact::field::q;
    /// let b = Batch::new("m,M,l,a,v0,omega", Arithmetic::Exact).unwrap();
    /// let (scene, claimed) = b.scene(1, "1,1,1,1/2,1,6/5").unwrap();
    /// assert_eq!(scene.a(), &q(1, 2));
    /// assert_eq!(claimed, [None, None, Some(q(6, 5))]);
    /// ```
    pub fn scene(&self, number: usize, line: &str) -> Result<(Scene, [Option<Q>; 3]), Error> {
        let (scene, claimed) = self.cells(number, line)?;
        Ok((scene, claimed.map(|c| c.as_ref().map(Claimed::value))))
    }

    /// [`Batch::scene`] with the claims as read (not reduced).
    pub(super) fn cells(
        &self,
        number: usize,
        line: &str,
    ) -> Result<(Scene, [Option<Claimed>; 3]), Error> {
        let line = line.trim_end_matches(['\n', '\r']);
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        if cells.len() != self.columns.len() {
            return Err(Error::new(
                format!("row {number}"),
                ErrorKind::Invalid(format!(
                    "expected {} cells, got {}",
                    self.columns.len(),
                    cells.len()
                )),
            ));
        }
        let at = |e: Error| Error::new(format!("row {number}, column {}", e.field), e.kind);
        let mut input = SceneInput::default();
        let mut claimed: [Option<Claimed>; 3] = [None, None, None];
        for (&column, &cell) in self.columns.iter().zip(&cells) {
            if cell.is_empty() && column >= 2 {
                continue;
            }
            match SCENE_COLUMNS.get(column) {
                Some(name) => {
                    *input.slot(name).expect("scene columns are scene inputs") =
                        Some(cell.to_string());
                }
                None => {
                    let k = column - SCENE_COLUMNS.len();
                    claimed[k] = Some(Claimed::parse(k, cell).map_err(at)?);
                }
            }
        }
        Ok((input.build().map_err(at)?, claimed))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headers_are_checked() {
        for (header, want) in [
            ("m,m,M", "header: column 'm' given twice"),
            ("M,l", "header: column 'm' is required"),
        ] {
            assert_eq!(
                Batch::new(header, Arithmetic::Exact)
                    .unwrap_err()
                    .to_string(),
                want
            );
        }
        let b = Batch::new("m,M", Arithmetic::Exact).unwrap();
        assert_eq!(
            b.row(4, "1").unwrap_err().to_string(),
            "row 4: expected 2 cells, got 1"
        );
    }
}
