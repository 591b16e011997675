//! The header of a batch file (which column feeds which scene field or claim, and the columns
//! appended to the output) and the cells of a data row, read into a scene and claimed values.

use super::classes::ClassRule;
use super::compare::{Agreement, Claimed};
use super::expected::KnownFindings;
use super::plan::{
    Arithmetic, CLAIMS, OBLIQUE_CLAIMS, OBLIQUE_OUTPUTS, Role, STATE, WORD_CLAIMS, WORD_SCENE,
    WordPlan,
};
use crate::error::{Error, ErrorKind};
use crate::field::Q;
use crate::scene::{SCENE_KEYS, Scene, SceneInput, SceneKey};
use std::sync::Arc;

/// The scene key of the batch column `name`, if it is one.
fn scene_column(name: &str) -> Option<&'static SceneKey> {
    SCENE_KEYS.iter().find(|k| k.column && k.name == name)
}

/// The scene columns a batch reads, comma-separated, from the one table of scene keys.
///
/// # Examples
/// ```
/// assert!(rodimpact::batch::scene_columns().starts_with("m,M,l,a,v0,rod,e,pivot,v0t,"));
/// ```
pub fn scene_columns() -> String {
    SCENE_KEYS
        .iter()
        .filter(|k| k.column)
        .map(|k| k.name)
        .collect::<Vec<_>>()
        .join(",")
}

/// Reads the header line of a batch file from `input` (named `label` in errors), no further
/// than [`MAX_LINE`](super::MAX_LINE) bytes, so that a file of one endless line is refused
/// instead of read into memory. The rows follow in `input`.
///
/// # Errors
/// `header (line 1): cannot read LABEL: ...`, `header (line 1): line longer than ... (limit)`,
/// or `FILE: LABEL has no header line (expected columns among ...)` for an empty file.
///
/// # Examples
/// ```
/// use rodimpact::batch::read_header;
/// let mut input = "m,M\n1,1\n".as_bytes();
/// assert_eq!(read_header(&mut input, "runs.csv").unwrap(), "m,M\n");
/// assert_eq!(input, b"1,1\n");
/// let err = read_header(&mut "\n".as_bytes(), "empty.csv").unwrap_err().to_string();
/// assert!(err.starts_with("FILE: empty.csv has no header line (expected columns among m,M,"));
/// ```
pub fn read_header(input: &mut impl std::io::BufRead, label: &str) -> Result<String, Error> {
    use std::io::{BufRead, Read};
    let max = super::MAX_LINE;
    let mut header = String::new();
    let n = Read::take(&mut *input, max as u64 + 1)
        .read_line(&mut header)
        .map_err(|why| Error::io("header (line 1)", format!("cannot read {label}"), why))?;
    if n > max {
        return Err(Error::new(
            "header (line 1)",
            ErrorKind::Invalid(format!("line longer than {max} bytes (limit)")),
        ));
    }
    if header.trim().is_empty() {
        return Err(Error::new(
            "FILE",
            ErrorKind::Invalid(format!(
                "{label} has no header line (expected columns among {},v,V,omega)",
                scene_columns()
            )),
        ));
    }
    Ok(header)
}

/// What one input column feeds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    /// A scene field: a key of [`SCENE_KEYS`] that is a batch column.
    Scene(&'static SceneKey),
    /// A claim: index into [`CLAIMS`].
    Claim(usize),
    /// Any other column (an engine log's `id`, `engine`, `dt`, ...): passed through in place.
    Passed,
}

/// A parsed header: which input column feeds which scene field or claim, and the agreement
/// rule of the claims.
#[derive(Debug, Clone)]
pub struct Batch {
    pub(super) arithmetic: Arithmetic,
    pub(super) agreement: Agreement,
    columns: Vec<Column>,
    /// The claimed outputs, in [`CLAIMS`] order.
    pub(super) claims: Vec<usize>,
    /// The input column named `id`, if any: it names the rows of the summary.
    pub(super) id_column: Option<usize>,
    /// Where the word row finds its cells, when the header allows it (see [`WordPlan`]).
    pub(super) word_plan: Option<WordPlan>,
    /// `--atol`: a claim also agrees within this many of the scene's own units.
    pub(super) atol: Option<Q>,
    /// `--expect`: the findings the batch is allowed to have.
    pub(super) expected: Option<Arc<KnownFindings>>,
    /// `--tolerance`: the agreement of classes of rows, the first that takes a row.
    pub(super) class_rules: Vec<ClassRule>,
    header: String,
}

impl Batch {
    /// Parses the header line. Columns other than the scene's and the claims' are passed
    /// through unchanged (see [`Batch::passed_through`]).
    ///
    /// # Errors
    /// `header: ...` for a repeated column, a passed-through column named like a column
    /// rodimpact writes (`v_ok`, `laws_held`, ...: no output header holds a name twice), or
    /// when m or M is missing.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,a,v", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,a,v,v_exact,V,omega,laws_held,v_ok,v_rel_error\n");
    /// let tagged = Batch::new("id,m,M,dt", Arithmetic::Exact).unwrap();
    /// assert_eq!(tagged.passed_through(), ["id", "dt"]);
    /// assert_eq!(Batch::new("m,M,m", Arithmetic::Exact).unwrap_err().to_string(),
    ///            "header: column 'm' given twice");
    /// // An engine log may not forge rodimpact's own verdict columns.
    /// let forged = Batch::new("m,M,v,v_ok", Arithmetic::Exact).unwrap_err().to_string();
    /// assert!(forged.starts_with("header: column 'v_ok' is a name rodimpact writes"), "{forged}");
    /// ```
    pub fn new(header: &str, arithmetic: Arithmetic) -> Result<Batch, Error> {
        let header = header.trim_start_matches('\u{feff}').trim_end();
        let bad = |why: String| Error::new("header", ErrorKind::Invalid(why));
        let mut columns = Vec::new();
        for name in header.split(',').map(str::trim) {
            let column = match scene_column(name) {
                Some(k) => Column::Scene(k),
                None => CLAIMS
                    .iter()
                    .position(|c| *c == name)
                    .map_or(Column::Passed, Column::Claim),
            };
            if column != Column::Passed && columns.contains(&column) {
                return Err(bad(format!(
                    "column '{}' given twice",
                    crate::echo::echo(name)
                )));
            }
            columns.push(column);
        }
        for required in ["m", "M"] {
            if !columns
                .iter()
                .any(|c| matches!(c, Column::Scene(k) if k.name == required))
            {
                if let Some(separator) = [';', '\t', '|']
                    .into_iter()
                    .find(|s| !header.contains(',') && header.contains(*s))
                {
                    return Err(bad(format!(
                        "the header has no commas (it is separated by {separator:?}): rodimpact reads comma-separated files"
                    )));
                }
                return Err(bad(format!("column '{required}' is required")));
            }
        }
        let claims = (0..CLAIMS.len())
            .filter(|k| columns.contains(&Column::Claim(*k)))
            .collect();
        let id_column = header
            .split(',')
            .zip(&columns)
            .position(|(name, c)| *c == Column::Passed && name.trim() == "id");
        let oblique = columns.iter().find_map(|c| match c {
            Column::Scene(k) if k.oblique => Some(k.name),
            _ => None,
        });
        if oblique.is_none()
            && let Some(k) =
                (OBLIQUE_CLAIMS..CLAIMS.len()).find(|k| columns.contains(&Column::Claim(*k)))
        {
            return Err(bad(format!(
                "claim column '{}' is an oblique scene's output: it needs a column among v0t, mu, radius, spin, rod-v, rod-vt, rod-omega",
                CLAIMS[k]
            )));
        }
        if let Some(name) = oblique {
            if arithmetic == Arithmetic::F64 {
                return Err(bad(format!(
                    "column '{name}': oblique and frictional scenes are solved exactly; the f64 arithmetic takes the paper's scene only"
                )));
            }
            if let Some(k) = (STATE..OBLIQUE_CLAIMS).find(|k| columns.contains(&Column::Claim(*k)))
            {
                return Err(bad(format!(
                    "claim column '{}' with column '{name}': J and the energies are checked for the paper's scene only (claim v, V, omega, vt, Vt, spin_after, tangential_impulse)",
                    CLAIMS[k]
                )));
            }
        }
        let word_plan = word_plan(&columns);
        let batch = Batch {
            arithmetic,
            agreement: Agreement::Exact,
            columns,
            claims,
            id_column,
            word_plan,
            atol: None,
            expected: None,
            class_rules: Vec::new(),
            header: header.to_string(),
        };
        batch.names_each_column_once()?;
        Ok(batch)
    }

    /// Refuses a header whose output would hold a name twice: a passed-through column named
    /// like a column rodimpact writes (`v_ok`, `laws_held`, `v_exact`, `diagnosis`, ...), or a
    /// passed-through name given twice. Refused rather than renamed: an engine log that names
    /// its own `v_ok` would otherwise shadow rodimpact's audit for any reader that takes the
    /// first column of a name (and a renamed copy can still be mistaken for it), so the forger
    /// and the honest author alike are told, and no output ever needs a second look.
    fn names_each_column_once(&self) -> Result<(), Error> {
        let output = self.output_header();
        let names: Vec<&str> = output.trim_end().split(',').map(str::trim).collect();
        let inputs = self.columns.len();
        for (i, name) in names.iter().enumerate() {
            let Some(j) = names[..i].iter().position(|n| n == name) else {
                continue;
            };
            let why = if i < inputs {
                format!("column '{}' given twice", crate::echo::echo(name))
            } else {
                debug_assert!(j < inputs, "rodimpact's own columns are distinct");
                format!(
                    "column '{}' is a name rodimpact writes in this output, so it would appear \
                     twice (a passed-through '{0}' would shadow the computed one): rename it",
                    crate::echo::echo(name)
                )
            };
            return Err(Error::new("header", ErrorKind::Invalid(why)));
        }
        Ok(())
    }

    /// Sets when a claim agrees (`--rtol`, `--ulps`); the default is exact equality (within
    /// [`FLOAT_TOLERANCE`](super::FLOAT_TOLERANCE) with the f64 arithmetic).
    ///
    /// # Errors
    /// `ulps: ...` with the f64 arithmetic: the ulp distance is measured to the correctly
    /// rounded exact value, which f64 does not compute; `header: ...` when a passed-through
    /// column is named like an `<claim>_ulps` column the agreement adds.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Agreement, Arithmetic, Batch, FloatFormat};
    /// let ulps = Agreement::Ulps(4, FloatFormat::F32);
    /// let b = Batch::new("m,M,v", Arithmetic::Exact).unwrap().with_agreement(ulps.clone()).unwrap();
    /// assert!(b.output_header().ends_with(",v_ok,v_rel_error,v_ulps\n"));
    /// let f = Batch::new("m,M,v", Arithmetic::F64).unwrap();
    /// assert!(f.with_agreement(ulps).is_err());
    /// ```
    pub fn with_agreement(mut self, agreement: Agreement) -> Result<Batch, Error> {
        self.takes_ulps("ulps", "needs", "--rtol", &agreement)?;
        if matches!(agreement, Agreement::Ulps(..)) {
            // Ulp distances are counted by the general row only (as class rules and --atol).
            self.word_plan = None;
        }
        self.agreement = agreement;
        // `--ulps` adds `<claim>_ulps` columns, which an input column may already hold.
        self.names_each_column_once()?;
        Ok(self)
    }

    /// Sets the agreement of classes of rows (`--tolerance CLASS=RULE`, in order: the first
    /// rule that takes a row sets its agreement; the others keep [`Batch::with_agreement`]'s).
    /// The rows are then solved by the general row, which decides each row's class.
    ///
    /// # Errors
    /// `tolerance: ...` for an ulps rule with the f64 arithmetic; `header: ...` when a
    /// passed-through column is named like an `<claim>_ulps` column an ulps rule adds.
    ///
    /// # Examples
    /// A pivoted row agrees within a relative 1e-3; the free row is held to exact equality.
    /// ```
    /// use rodimpact::batch::{Arithmetic, Batch, ClassRule, FloatFormat};
    /// let pivots = ClassRule::parse("pivot=rtol:1e-3", FloatFormat::F64)?;
    /// let b = Batch::new("m,M,a,pivot,omega", Arithmetic::Exact)?.with_class_rules(vec![pivots])?;
    /// assert!(b.row(1, "1,1,1,-1,0.7501").unwrap().checks[0].ok); // exact 3/4
    /// assert!(!b.row(2, "1,1,1,,0.6001").unwrap().checks[0].ok); // exact 3/5, free
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn with_class_rules(mut self, rules: Vec<ClassRule>) -> Result<Batch, Error> {
        for rule in &rules {
            self.takes_ulps("tolerance", "an ulps rule needs", "rtol:R", &rule.agreement)?;
        }
        if !rules.is_empty() {
            self.word_plan = None;
        }
        self.class_rules = rules;
        self.names_each_column_once()?;
        Ok(self)
    }

    /// An ulps count needs the exact arithmetic: refused as `flag` otherwise (`what needs`
    /// the exact backend; use `instead`).
    fn takes_ulps(
        &self,
        flag: &str,
        what: &str,
        instead: &str,
        agreement: &Agreement,
    ) -> Result<(), Error> {
        if self.arithmetic == Arithmetic::F64 && matches!(agreement, Agreement::Ulps(..)) {
            return Err(Error::new(
                flag,
                ErrorKind::Invalid(format!(
                    "{what} the exact backend (the distance is to the correctly rounded exact \
                     value); use {instead} with --backend f64"
                )),
            ));
        }
        Ok(())
    }

    /// Whether the output has `<claim>_ulps` columns: an ulps agreement for some rows.
    pub(super) fn ulps_columns(&self) -> bool {
        std::iter::once(&self.agreement)
            .chain(self.class_rules.iter().map(|r| &r.agreement))
            .any(|a| matches!(a, Agreement::Ulps(..)))
    }

    /// The class rules, in order (`--tolerance`).
    pub fn class_rules(&self) -> &[ClassRule] {
        &self.class_rules
    }

    /// `--atol X`: a claim also agrees when it lies within X of the exact value in the scene's
    /// own units: X |v0| for v and V, X |v0|/l for omega, X m |v0| for J, X m v0^2/2 for the
    /// energies. For the quantities that vanish exactly (omega at a = 0, V at a centre pivot),
    /// where an engine returns round-off and no relative error or ulp count can agree. The
    /// word rows, which take exact claims only, are then left to the general row.
    ///
    /// # Errors
    /// `atol: ...` when X is not a number from 0 to 1.
    ///
    /// # Examples
    /// A centre hit (omega exactly 0) claimed as 1e-17 by an engine:
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic, Agreement, FloatFormat};
    /// let ulps = Agreement::parse_ulps("16", FloatFormat::F64).unwrap();
    /// let b = Batch::new("m,M,a,v,V,omega", Arithmetic::Exact).unwrap().with_agreement(ulps).unwrap();
    /// assert!(!b.row(1, "1,1,0,0,1,1e-17").unwrap().checks[2].ok);
    /// let b = b.with_atol("1e-12").unwrap();
    /// assert!(b.row(1, "1,1,0,0,1,1e-17").unwrap().checks[2].ok);
    /// assert!(!b.row(2, "1,1,0,0,1,1e-11").unwrap().checks[2].ok);
    /// ```
    pub fn with_atol(mut self, text: &str) -> Result<Batch, Error> {
        let x = super::compare::unit_fraction("atol", text)?;
        self.atol = Some(x);
        self.word_plan = None;
        Ok(self)
    }

    /// The batch with a baseline of known findings (`--expect`): the summary then tells the
    /// rows whose findings the baseline allows from those with new ones
    /// ([`Summary::baseline`](super::Summary::baseline)).
    ///
    /// # Errors
    /// `expect: ...` when the header has no `id` column to match the baseline's ids against.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Arithmetic, Batch, KnownFindings};
    /// let known = KnownFindings::parse("known.csv", "id,finding\nend,no-contact\n")?;
    /// let b = Batch::new("id,m,M,a,v,V,omega", Arithmetic::Exact)?.with_expected(known.clone())?;
    /// let row = b.row(1, "end,1,1,1,1,0,0")?;
    /// assert_eq!(row.expectation.unwrap().unexpected, Vec::<&str>::new());
    /// let untagged = Batch::new("m,M,v", Arithmetic::Exact)?.with_expected(known);
    /// assert_eq!(untagged.unwrap_err().to_string(),
    ///     "expect: the batch has no id column to match the baseline's ids against");
    /// # Ok::<(), rodimpact::Error>(())
    /// ```
    pub fn with_expected(mut self, expected: KnownFindings) -> Result<Batch, Error> {
        if self.id_column.is_none() {
            return Err(Error::new(
                "expect",
                ErrorKind::Invalid(
                    "the batch has no id column to match the baseline's ids against".into(),
                ),
            ));
        }
        self.expected = Some(Arc::new(expected));
        Ok(self)
    }

    /// The input columns that are neither scene fields nor claims, passed through in place.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("id,engine,m,M,dt,omega", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.passed_through(), ["id", "engine", "dt"]);
    /// ```
    pub fn passed_through(&self) -> Vec<&str> {
        self.header
            .split(',')
            .zip(&self.columns)
            .filter(|(_, c)| **c == Column::Passed)
            .map(|(name, _)| name.trim())
            .collect()
    }

    /// The claimed state (v, V and omega all claimed) is audited: exact arithmetic and the
    /// paper's scene only (the audit's laws are those of the perpendicular frictionless impact).
    pub(super) fn audits(&self) -> bool {
        self.arithmetic == Arithmetic::Exact
            && !self.is_oblique()
            && (0..STATE).all(|k| self.claims.contains(&k))
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
            .any(|c| matches!(c, Column::Scene(k) if k.oblique))
    }

    /// The header of the output file (with its newline). The computed columns are named for
    /// what they hold: `v, V, omega` exactly (`v_exact`, ... beside a claim of that name), or
    /// `v_f64, V_f64, omega_f64` with the f64 arithmetic; a claimed `J`, `energy_before` or
    /// `energy_after` gets its computed column too. Then `laws_held` (exact only: f64 checks
    /// no law), per claim `<name>_ok,<name>_rel_error` (and `<name>_ulps` under `--ulps`),
    /// and, when v, V and omega are all claimed, `energy_change,diagnosis` (exact only).
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Arithmetic};
    /// let b = Batch::new("m,M,omega", Arithmetic::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,omega,v,V,omega_exact,laws_held,omega_ok,omega_rel_error\n");
    /// let f = Batch::new("m,M", Arithmetic::F64).unwrap();
    /// assert_eq!(f.output_header(), "m,M,v_f64,V_f64,omega_f64\n");
    /// let engine = Batch::new("id,m,M,v,V,omega,J", Arithmetic::Exact).unwrap();
    /// assert_eq!(engine.output_header(), "id,m,M,v,V,omega,J,v_exact,V_exact,omega_exact,J_exact,\
    ///     laws_held,v_ok,v_rel_error,V_ok,V_rel_error,omega_ok,omega_rel_error,J_ok,J_rel_error,\
    ///     energy_change,diagnosis\n");
    /// ```
    pub fn output_header(&self) -> String {
        let mut out = self.header.clone();
        for (k, name) in CLAIMS[..OBLIQUE_CLAIMS].iter().enumerate() {
            if k >= STATE && !self.claims.contains(&k) {
                continue;
            }
            let suffix = match self.arithmetic {
                Arithmetic::F64 => "_f64",
                Arithmetic::Exact if self.claims.contains(&k) => "_exact",
                Arithmetic::Exact => "",
            };
            out.push_str(&format!(",{name}{suffix}"));
        }
        if self.is_oblique() {
            for (k, name) in (OBLIQUE_CLAIMS..).zip(OBLIQUE_OUTPUTS) {
                // A claimed output is `<claim>_exact`; the disc's spin after the impact is
                // `spin_after` beside the input column `spin` (before).
                let clash =
                    scene_column(name).is_some_and(|k| self.columns.contains(&Column::Scene(k)));
                if self.claims.contains(&k) {
                    out.push_str(&format!(",{}_exact", CLAIMS[k]));
                } else {
                    out.push_str(&format!(",{name}{}", if clash { "_after" } else { "" }));
                }
            }
        }
        if self.arithmetic == Arithmetic::Exact {
            out.push_str(",laws_held");
        }
        for &k in &self.claims {
            out.push_str(&format!(",{0}_ok,{0}_rel_error", CLAIMS[k]));
            if self.ulps_columns() {
                out.push_str(&format!(",{}_ulps", CLAIMS[k]));
            }
        }
        if self.audits() {
            out.push_str(",energy_change,diagnosis");
        }
        out.push('\n');
        out
    }

    /// The scene and the claimed v, V, omega of data row `number` (1-based), without solving
    /// (`None` for a claim not given or not a finite number).
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
        let value = |k: usize| claimed[k].as_ref().and_then(Claimed::value);
        Ok((scene, [value(0), value(1), value(2)]))
    }

    /// [`Batch::scene`] with every claim as read (not reduced).
    pub(super) fn cells(
        &self,
        number: usize,
        line: &str,
    ) -> Result<(Scene, [Option<Claimed>; CLAIMS.len()]), Error> {
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
        let mut claimed: [Option<Claimed>; CLAIMS.len()] = Default::default();
        for (&column, &cell) in self.columns.iter().zip(&cells) {
            match column {
                Column::Scene(k) => put_scene_cell(&mut input, k, cell),
                Column::Claim(k) if !cell.is_empty() => {
                    claimed[k] = Some(Claimed::parse(k, cell).map_err(at)?);
                }
                _ => {}
            }
        }
        Ok((input.build().map_err(at)?, claimed))
    }
}

/// Puts a row's (trimmed) cell of the scene column `key` into `input`: m and M always (an
/// empty one is refused by name when the scene is built), any other unless empty (an empty
/// cell takes the default).
pub(super) fn put_scene_cell(input: &mut SceneInput, key: &SceneKey, cell: &str) {
    if ["m", "M"].contains(&key.name) || !cell.is_empty() {
        *input
            .slot(key.name)
            .expect("scene columns are scene inputs") = Some(cell.to_string());
    }
}

/// The word rows' plan: for a header whose scene columns are among m, M, l, a, v0, e, pivot
/// and rod and whose claims among v, V, omega, J and the energies (any other column passes
/// through), or for an oblique header (any scene column and claim it allows); `None`
/// otherwise.
fn word_plan(columns: &[Column]) -> Option<WordPlan> {
    let oblique = columns
        .iter()
        .any(|c| matches!(c, Column::Scene(k) if k.oblique));
    let roles = columns
        .iter()
        .map(|column| match *column {
            Column::Scene(k) if oblique => SCENE_KEYS
                .iter()
                .position(|key| key.name == k.name)
                .map(Role::Input),
            Column::Scene(k) if k.name == "rod" => Some(Role::Rod),
            Column::Scene(k) => WORD_SCENE
                .iter()
                .position(|&w| w == k.name)
                .map(Role::Scene),
            Column::Claim(k) => (oblique || k < WORD_CLAIMS).then_some(Role::Claim(k)),
            Column::Passed => Some(Role::Passed),
        })
        .collect::<Option<Vec<Role>>>()?;
    let claimed: [bool; CLAIMS.len()] = std::array::from_fn(|k| roles.contains(&Role::Claim(k)));
    let paper = !oblique
        && !roles.iter().any(|role| {
            matches!(role, Role::Rod | Role::Scene(6))
                || matches!(role, Role::Claim(k) if *k >= STATE)
        });
    Some(WordPlan {
        roles,
        claimed,
        audits: !oblique && claimed[..STATE].iter().all(|c| *c),
        paper,
        oblique,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headers_are_checked() {
        for (header, want) in [
            ("m,m,M", "header: column 'm' given twice"),
            ("M,l", "header: column 'm' is required"),
            (
                "m;M;a",
                "header: the header has no commas (it is separated by ';'): rodimpact reads comma-separated files",
            ),
            (
                "m\tM",
                "header: the header has no commas (it is separated by '\\t'): rodimpact reads comma-separated files",
            ),
            ("m,M,v,J,v", "header: column 'v' given twice"),
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
