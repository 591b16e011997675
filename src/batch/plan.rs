//! The vocabulary every part of a batch shares: how rows are solved ([`Arithmetic`]), which
//! columns are claims, what the word rows read ([`WordPlan`]), and what a solved row is
//! ([`SolvedRow`], [`Diagnosis`]). It imports nothing from the rest of `batch/`, so the files
//! that read the header, solve a row, compare claims and summarise depend on it and not on
//! each other in a circle.

use super::audit::Finding;
use super::rel_error::RelError;
use crate::field::Q;
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
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Arithmetic {
    /// Exact rationals by [`Route::FractionFree`]: claims agree only when exactly equal.
    #[default]
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

/// The columns an oblique header appends after `omega` (docs/conventions.md).
pub(super) const OBLIQUE_OUTPUTS: [&str; 5] = ["vt", "Vt", "spin", "tangential_impulse", "contact"];
/// The claim columns, in the order of their checks: the state after the impact, the impulse on
/// the rod, the energies, then an oblique scene's outputs along the rod.
pub(super) const CLAIMS: [&str; 10] = [
    "v",
    "V",
    "omega",
    "J",
    "energy_before",
    "energy_after",
    "vt",
    "Vt",
    "spin_after",
    "tangential_impulse",
];
/// The first claim of an oblique scene's own outputs (`vt, Vt, spin_after,
/// tangential_impulse`, as `check` names them; `spin_after` because `spin` is the disc's spin
/// before); J and the energies are claimed for the paper's scene only.
pub(super) const OBLIQUE_CLAIMS: usize = 6;
/// The claims that make up the state after the impact (audited when all three are claimed).
pub(super) const STATE: usize = 3;

/// The scene columns the word rows read, in this order (the inputs of
/// [`crate::solve::fast::fixed_width`], then the pivot; the `rod` column has a role of its own).
pub(super) const WORD_SCENE: [&str; 7] = ["m", "M", "l", "a", "v0", "e", "pivot"];
/// The claims the word rows check: v, V, omega, J and the energies ([`CLAIMS`] up to
/// [`OBLIQUE_CLAIMS`]).
pub(super) const WORD_CLAIMS: usize = OBLIQUE_CLAIMS;

/// What one cell of a row holds, for the word rows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Role {
    /// A scene input of the paper's scene: an index into [`WORD_SCENE`].
    Scene(usize),
    /// The rod's mass distribution (`uniform`, `dumbbell`, `rg=Q`, `I=Q`).
    Rod,
    /// A scene input of an oblique plan (any scene column, the rod's too): an index into
    /// [`SCENE_KEYS`](crate::scene::SCENE_KEYS).
    Input(usize),
    /// A claim: an index into [`CLAIMS`].
    Claim(usize),
    /// Anything else, passed through.
    Passed,
}

/// Where a batch's rows keep the inputs and claims the word rows read.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct WordPlan {
    /// The role of each cell, in order.
    pub(super) roles: Vec<Role>,
    /// Which claims are claimed (their checks come in this order).
    pub(super) claimed: [bool; CLAIMS.len()],
    /// The claimed state is audited (v, V and omega all claimed).
    pub(super) audits: bool,
    /// The paper's word row may take the rows: no rod or pivot column, claims among v, V,
    /// omega only.
    pub(super) paper: bool,
    /// An oblique header's plan: its scene columns are [`Role::Input`]s, and its rows are the
    /// oblique engine row's.
    pub(super) oblique: bool,
}

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
    /// The audit of the claimed state (`None` when the batch audits none: v, V, omega not all
    /// claimed, or the f64 arithmetic).
    pub diagnosis: Option<Diagnosis>,
    /// What the summary calls the row when its audit found something or a claim is wrong:
    /// its `id` cell when the batch has an `id` column, else `row N`.
    pub label: Option<String>,
    /// The row against the baseline, when the batch has one (`--expect`).
    pub expectation: Option<RowExpectation>,
}

/// A row against the baseline of `--expect` ([`KnownFindings::check`](super::KnownFindings::check)).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct RowExpectation {
    /// The baseline entries (0-based) that allowed its findings.
    pub used: Vec<usize>,
    /// Its findings (and `wrong`) that no entry allows.
    pub unexpected: Vec<&'static str>,
}

/// The diagnosis of a row: its findings, `ok`, or not audited (a state claim missing).
///
/// # Examples
/// ```
/// use rodimpact::batch::{Arithmetic, Batch, Diagnosis, Finding};
/// let b = Batch::new("m,M,v,V,omega", Arithmetic::Exact).unwrap();
/// assert_eq!(b.row(1, "1,1,1,0,0").unwrap().diagnosis, Some(Diagnosis::Findings(vec![Finding::NoContact])));
/// assert_eq!(b.row(2, "1,1,0.6,0.4,").unwrap().diagnosis, Some(Diagnosis::NotAudited));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Diagnosis {
    /// v, V or omega not claimed in this row: nothing audited.
    NotAudited,
    /// The findings (none: `ok`).
    Findings(Vec<Finding>),
}

impl Diagnosis {
    /// The `diagnosis` cell: `-`, `ok`, or the findings joined by `;`.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Diagnosis, Finding};
    /// assert_eq!(Diagnosis::Findings(vec![]).text(), "ok");
    /// assert_eq!(Diagnosis::Findings(vec![Finding::EnergyGain, Finding::AboveOmegaMax]).text(),
    ///            "energy-gain;above-omega-max");
    /// assert_eq!(Diagnosis::NotAudited.text(), "-");
    /// ```
    pub fn text(&self) -> String {
        let mut text = String::new();
        self.push_text(&mut text);
        text
    }

    /// Appends [`Diagnosis::text`] to `out` (a row writes its cells into its line).
    pub(super) fn push_text(&self, out: &mut String) {
        match self {
            Diagnosis::NotAudited => out.push('-'),
            Diagnosis::Findings(f) if f.is_empty() => out.push_str("ok"),
            Diagnosis::Findings(f) => {
                for (k, finding) in f.iter().enumerate() {
                    if k > 0 {
                        out.push(';');
                    }
                    out.push_str(finding.name());
                }
            }
        }
    }
}

/// Appends `x` as its shortest round-trip text (`0.6`, `1.2e-7`), a zero as `0.0` whatever its
/// sign (`-0.0` only says which way the float rounded).
pub(super) fn write_float(out: &mut String, x: f64) {
    if x == 0.0 {
        out.push_str("0.0");
    } else {
        crate::field::shortest::push_debug(out, x);
    }
}

/// A claimed value compared with the computed one.
///
/// # Examples
/// ```
/// use rodimpact::{batch::{Batch, Arithmetic}, field::q};
/// let row = Batch::new("m,M,V", Arithmetic::Exact).unwrap().row(1, "1,1,0.5").unwrap();
/// let check = &row.checks[0];
/// assert_eq!((check.output, check.ok), (1, false));
/// assert_eq!(check.rel_error(), Some(q(1, 4))); // |1/2 - 2/5| / (2/5)
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct OutputCheck {
    /// Which claim: 0 v, 1 V, 2 omega, 3 J, 4 energy_before, 5 energy_after.
    pub output: usize,
    /// The claim agrees under the batch's `Agreement`.
    pub ok: bool,
    /// |claim - value| / |value| as the row computed it (see [`OutputCheck::rel_error`]).
    pub(super) error: Option<RelError>,
    /// The f64 nearest to `error` (infinite when `error` is).
    pub(super) nearest: f64,
    /// The ulp distance, under `Agreement::Ulps` and for a finite claim.
    pub ulps: Option<u64>,
    /// The claim was NaN or infinite.
    pub not_finite: bool,
}

impl SolvedRow {
    /// A solved row before [`Batch::row`](super::Batch::row) names it and checks it against
    /// the baseline: its number, output line, laws, checks and diagnosis.
    pub(super) fn unlabelled(
        number: usize,
        line: String,
        laws_held: Option<bool>,
        checks: Vec<OutputCheck>,
        diagnosis: Option<Diagnosis>,
    ) -> SolvedRow {
        SolvedRow {
            number,
            line,
            laws_held,
            checks,
            diagnosis,
            label: None,
            expectation: None,
        }
    }
}

impl OutputCheck {
    /// Appends the check's cells: `,<ok>,<rel_error>`, and `,<ulps>` when `ulps_column`.
    pub(super) fn write_cells(&self, out: &mut String, ulps_column: bool) {
        out.push_str(if self.ok { ",true," } else { ",false," });
        self.push_rel_error_text(out);
        if ulps_column {
            out.push(',');
            // Empty for a row held to another rule (`--tolerance`): no count was asked of it.
            match (self.ulps, self.not_finite) {
                (Some(u), _) => out.push_str(&u.to_string()),
                (None, true) => out.push_str("nan"),
                (None, false) => {}
            }
        }
    }

    /// The text of the `<name>_rel_error` cell: three significant digits, `inf`, or `nan` for a
    /// claim that was not a finite number.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.row(1, "1,1,0.61").unwrap().checks[0].rel_error_text(), "0.0167");
    /// assert_eq!(b.row(2, "1,1,NaN").unwrap().checks[0].rel_error_text(), "nan");
    /// ```
    pub fn rel_error_text(&self) -> String {
        let mut out = String::new();
        self.push_rel_error_text(&mut out);
        out
    }

    /// [`OutputCheck::rel_error_text`], appended to `out`.
    fn push_rel_error_text(&self, out: &mut String) {
        match (&self.error, self.not_finite) {
            (_, true) => out.push_str("nan"),
            (Some(r), false) => r.push_text(out, self.nearest),
            (None, false) => out.push_str("inf"),
        }
    }

    /// |claim - value| / |value|, exact and in lowest terms; `None` when it is infinite (a
    /// zero value and a nonzero claim) or the claim is not a number.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::{batch::{Batch, Arithmetic}, field::q};
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.row(1, "1,1,0.61").unwrap().checks[0].rel_error(), Some(q(1, 60)));
    /// assert_eq!(b.row(2, "1,1,3/5").unwrap().checks[0].rel_error(), Some(q(0, 1)));
    /// assert_eq!(b.row(3, "1,1,NaN").unwrap().checks[0].rel_error(), None);
    /// ```
    pub fn rel_error(&self) -> Option<Q> {
        self.error.as_ref().map(RelError::value)
    }

    /// Whether the claim is exactly the value.
    pub(super) fn exact(&self) -> bool {
        self.error.as_ref().is_some_and(RelError::is_zero)
    }
}
