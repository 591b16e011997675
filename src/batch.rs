//! Many scenes from a CSV file: solved exactly (or in f64), streamed in chunks, in parallel,
//! written back in input order with the results appended.
//!
//! The header names columns among `m, M, l, a, v0, rod, e, pivot` (m and M required, the others
//! take the `solve` defaults, also when a cell is empty) and optionally `v, V, omega`: claimed
//! results, each compared with the computed value. Appended columns: `v, V, omega` (named
//! `v_exact`, ... when the input already has a claim of that name; `v_f64, V_f64, omega_f64`
//! with the f64 backend), `laws_held` (`-` with the f64 backend, which decides no law), and for
//! each claim `<name>_ok, <name>_rel_error`.
//!
//! Limits: at most [`MAX_ROWS`] rows and [`MAX_LINE`] bytes per line; each number at most
//! [`number::MAX_DIGITS`](crate::number::MAX_DIGITS) digits. Memory stays flat in the number of
//! rows: at most three chunks of [`CHUNK`] rows are held at a time (one being read, one solved,
//! one written), and the median of the summary comes from a histogram of relative errors
//! rounded to two significant digits.

use crate::error::{Error, ErrorKind};
use crate::fast;
use crate::field::Q;
use crate::mechanics::Motion;
use crate::number::WordRatio;
use crate::scene::{Scene, SceneInput};
use crate::units::{Dimension, parse_si};
use num_traits::{Signed, Zero};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::io::{BufRead, Read, Write};

/// The largest number of data rows accepted.
pub const MAX_ROWS: usize = 100_000_000;
/// The longest line accepted, in bytes.
pub const MAX_LINE: usize = 1 << 20;
/// Rows read, solved in parallel and written per step.
pub const CHUNK: usize = 8192;
/// The relative error up to which a claim agrees with a float backend's value.
pub const FLOAT_TOLERANCE: f64 = 1e-9;

/// The arithmetic of the batch.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Backend};
/// let row = Batch::new("m,M", Backend::F64).unwrap().row(1, "1,1").unwrap();
/// assert_eq!(row.laws_held, None); // a float backend decides nothing exactly
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backend {
    /// Exact rationals ([`fast::solve`]): claims agree only when exactly equal.
    Exact,
    /// The closed form in f64: claims agree within [`FLOAT_TOLERANCE`]; laws not decided.
    F64,
}

const SCENE_COLUMNS: [&str; 8] = ["m", "M", "l", "a", "v0", "rod", "e", "pivot"];
const OUTPUTS: [&str; 3] = ["v", "V", "omega"];

/// A parsed header: which input column feeds which scene field or claim.
#[derive(Debug, Clone)]
pub struct Batch {
    backend: Backend,
    /// Per input column: index into `SCENE_COLUMNS`, or 8 + index into `OUTPUTS` for a claim.
    columns: Vec<usize>,
    claims: Vec<usize>,
    header: String,
}

/// A claimed value compared with the computed one.
///
/// # Examples
/// ```
/// use rodimpact::{batch::{Batch, Backend}, field::q};
/// let row = Batch::new("m,M,V", Backend::Exact).unwrap().row(1, "1,1,0.5").unwrap();
/// let verdict = &row.verdicts[0];
/// assert_eq!((verdict.output, verdict.ok), (1, false));
/// assert_eq!(verdict.rel_error, Some(q(1, 4))); // |1/2 - 2/5| / (2/5)
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    /// Which output: 0 v, 1 V, 2 omega.
    pub output: usize,
    /// The claim agrees (exactly, or within [`FLOAT_TOLERANCE`] for a float backend).
    pub ok: bool,
    /// |claim - value| / |value|, exact; `None` when the value is 0 and the claim is not.
    pub rel_error: Option<Q>,
}

/// One output row: the CSV line (with its newline) and what the summary needs.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Backend};
/// let row = Batch::new("m,M", Backend::Exact).unwrap().row(1, "1,1").unwrap();
/// assert_eq!((row.line.as_str(), row.laws_held), ("1,1,3/5,2/5,6/5,true\n", Some(true)));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The data row's number (1-based, as in error messages).
    pub number: usize,
    /// The output line.
    pub line: String,
    /// The laws held exactly (`None` for a float backend).
    pub laws_held: Option<bool>,
    /// The claims of the row.
    pub verdicts: Vec<Verdict>,
}

impl Batch {
    /// Parses the header line.
    ///
    /// # Errors
    /// `header: ...` for an unknown or repeated column, or when m or M is missing.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Backend};
    /// let b = Batch::new("m,M,a,v", Backend::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,a,v,v_exact,V,omega,laws_held,v_ok,v_rel_error\n");
    /// assert_eq!(Batch::new("m,M,x", Backend::Exact).unwrap_err().to_string(),
    ///            "header: unknown column 'x' (expected m, M, l, a, v0, rod, e, pivot, v, V, omega)");
    /// ```
    pub fn new(header: &str, backend: Backend) -> Result<Batch, Error> {
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
        let claims = (0..3).filter(|k| columns.contains(&(8 + k))).collect();
        Ok(Batch {
            backend,
            columns,
            claims,
            header: header.to_string(),
        })
    }

    /// The header of the output file (with its newline). The computed columns are named for
    /// what they hold: `v, V, omega` exactly (`v_exact`, ... beside a claim of that name), or
    /// `v_f64, V_f64, omega_f64` from the f64 backend.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Backend};
    /// let b = Batch::new("m,M,omega", Backend::Exact).unwrap();
    /// assert_eq!(b.output_header(), "m,M,omega,v,V,omega_exact,laws_held,omega_ok,omega_rel_error\n");
    /// let f = Batch::new("m,M", Backend::F64).unwrap();
    /// assert_eq!(f.output_header(), "m,M,v_f64,V_f64,omega_f64,laws_held\n");
    /// ```
    pub fn output_header(&self) -> String {
        let mut out = self.header.clone();
        for (k, name) in OUTPUTS.iter().enumerate() {
            let suffix = match self.backend {
                Backend::F64 => "_f64",
                Backend::Exact if self.claims.contains(&k) => "_exact",
                Backend::Exact => "",
            };
            out.push_str(&format!(",{name}{suffix}"));
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
    /// use rodimpact::batch::{Batch, Backend};
    /// use rodimpact::field::q;
    /// let b = Batch::new("m,M,l,a,v0,omega", Backend::Exact).unwrap();
    /// let (scene, claimed) = b.scene(1, "1,1,1,1/2,1,6/5").unwrap();
    /// assert_eq!(scene.a(), &q(1, 2));
    /// assert_eq!(claimed, [None, None, Some(q(6, 5))]);
    /// ```
    pub fn scene(&self, number: usize, line: &str) -> Result<(Scene, [Option<Q>; 3]), Error> {
        let (scene, claimed) = self.cells(number, line)?;
        Ok((scene, claimed.map(|c| c.as_ref().map(Claimed::value))))
    }

    /// [`Batch::scene`] with the claims as read (not reduced).
    fn cells(&self, number: usize, line: &str) -> Result<(Scene, [Option<Claimed>; 3]), Error> {
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

    /// Solves data row `number` (1-based) given as its line.
    ///
    /// # Errors
    /// `row N, column X: reason` for a bad cell; `row N: ...` for a wrong number of cells.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Backend};
    /// let b = Batch::new("m,M,omega", Backend::Exact).unwrap();
    /// let row = b.row(1, "1,1,6/5").unwrap();
    /// assert_eq!(row.line, "1,1,6/5,3/5,2/5,6/5,true,true,0\n");
    /// assert_eq!(b.row(2, "1,-1,1").unwrap_err().to_string(), "row 2, column M: must be > 0, got -1");
    /// ```
    pub fn row(&self, number: usize, line: &str) -> Result<Row, Error> {
        let line = line.trim_end_matches(['\n', '\r']);
        let (scene, claimed) = self.cells(number, line)?;
        let mut out = String::with_capacity(2 * line.len() + 64);
        out.push_str(line);
        let (exact, laws_held) = match self.backend {
            Backend::Exact => {
                let solved = fast::solve(&scene);
                let m = solved.after;
                for value in [&m.v, &m.rod_v, &m.omega] {
                    out.push(',');
                    crate::number::write_exact(&mut out, value);
                }
                ([m.v, m.rod_v, m.omega], Some(solved.laws_hold))
            }
            Backend::F64 => {
                let (exact, texts) = float_values(&scene);
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
        let mut verdicts = Vec::new();
        for &k in &self.claims {
            let Some(claim) = &claimed[k] else {
                out.push_str(",,");
                continue;
            };
            let verdict = compare(k, claim, &exact[k], self.backend);
            out.push_str(if verdict.ok { ",true," } else { ",false," });
            out.push_str(&match &verdict.rel_error {
                Some(r) => crate::number::decimal(r, 3),
                None => "inf".to_string(),
            });
            verdicts.push(verdict);
        }
        out.push('\n');
        Ok(Row {
            number,
            line: out,
            laws_held,
            verdicts,
        })
    }
}

/// v, V, omega by the closed form in f64, as exact dyadic rationals and shortest round-trip text
/// (a zero is written `0.0`, whatever its sign: `-0.0` only says which way the float rounded).
fn float_values(scene: &crate::scene::Scene) -> ([Q; 3], [String; 3]) {
    let nan = Motion {
        v: f64::NAN,
        rod_v: f64::NAN,
        omega: f64::NAN,
    };
    let m = crate::solve::closed_form(&scene.params::<f64>()).unwrap_or(nan);
    let xs = [m.v, m.rod_v, m.omega];
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

/// A claimed value as read: on machine words (compared without reducing), or exact.
#[derive(Debug, Clone)]
enum Claimed {
    Word(WordRatio),
    Exact(Q),
}

impl Claimed {
    fn parse(output: usize, cell: &str) -> Result<Claimed, Error> {
        match WordRatio::parse(cell) {
            Some(word) => Ok(Claimed::Word(word)),
            None => {
                let dimension = if output == 2 {
                    Dimension::AngularSpeed
                } else {
                    Dimension::Speed
                };
                parse_si(OUTPUTS[output], cell, dimension).map(Claimed::Exact)
            }
        }
    }

    fn value(&self) -> Q {
        match self {
            Claimed::Word(word) => word.value(),
            Claimed::Exact(q) => q.clone(),
        }
    }
}

fn compare(output: usize, claim: &Claimed, value: &Q, backend: Backend) -> Verdict {
    let equal = match claim {
        Claimed::Word(word) => word.equals(value),
        Claimed::Exact(q) => Some(q == value),
    };
    if equal == Some(true) {
        return Verdict {
            output,
            ok: true,
            rel_error: Some(Q::zero()),
        };
    }
    let claim = &claim.value();
    let rel_error = if value.is_zero() {
        claim.is_zero().then(Q::zero)
    } else {
        // |c - v| / |v| = |cn vd - vn cd| / (|vn| cd), reduced once (one GCD instead of the
        // three of a subtraction and a division of rationals).
        let difference = claim.numer() * value.denom() - value.numer() * claim.denom();
        Some(Q::new(
            difference.abs(),
            value.numer().abs() * claim.denom(),
        ))
    };
    let ok = match backend {
        Backend::Exact => claim == value,
        Backend::F64 => rel_error
            .as_ref()
            .is_some_and(|r| crate::field::Field::nearest_f64(r) <= FLOAT_TOLERANCE),
    };
    Verdict {
        output,
        ok,
        rel_error,
    }
}

/// Counts, the largest relative error and a bounded histogram for the median, per claimed
/// output.
///
/// # Examples
/// ```
/// use rodimpact::batch::{Batch, Backend, Summary};
/// let b = Batch::new("m,M", Backend::Exact).unwrap();
/// let mut s = Summary::default();
/// s.add(&b.row(1, "1,1").unwrap());
/// assert_eq!((s.rows, s.laws_failed, s.wrong()), (1, 0, 0));
/// ```
#[derive(Debug, Clone, Default)]
pub struct Summary {
    /// Data rows processed.
    pub rows: usize,
    /// Rows whose laws did not hold exactly (exact backend).
    pub laws_failed: usize,
    /// Rows whose laws were not checked (f64 backend).
    pub laws_unchecked: usize,
    claims: [ClaimStats; 3],
}

#[derive(Debug, Clone, Default)]
struct ClaimStats {
    compared: usize,
    wrong: usize,
    /// `None` before the first claim; `Some(None)` once an infinite error was seen.
    max: Option<Option<Q>>,
    /// Relative errors rounded to 2 significant digits (f64 bits, ordered as the values).
    histogram: BTreeMap<u64, usize>,
    /// The first [`WRONG_ROWS_SHOWN`] rows with a wrong claim.
    wrong_rows: Vec<usize>,
}

/// How many rows with a wrong claim the summary names, per output.
pub const WRONG_ROWS_SHOWN: usize = 10;

impl Summary {
    /// Adds one row (see the type's example).
    pub fn add(&mut self, row: &Row) {
        self.rows += 1;
        match row.laws_held {
            Some(true) => {}
            Some(false) => self.laws_failed += 1,
            None => self.laws_unchecked += 1,
        }
        for v in &row.verdicts {
            let s = &mut self.claims[v.output];
            s.compared += 1;
            s.wrong += usize::from(!v.ok);
            if !v.ok && s.wrong_rows.len() < WRONG_ROWS_SHOWN {
                s.wrong_rows.push(row.number);
            }
            let bigger = match (&s.max, &v.rel_error) {
                (None, _) | (Some(Some(_)), None) => true,
                (Some(Some(old)), Some(new)) => new > old,
                (Some(None), _) => false,
            };
            if bigger {
                s.max = Some(v.rel_error.clone());
            }
            let rounded = match &v.rel_error {
                Some(r) if r.is_zero() => 0.0,
                Some(r) => format!("{:.1e}", crate::field::Field::nearest_f64(r))
                    .parse::<f64>()
                    .unwrap_or(f64::INFINITY),
                None => f64::INFINITY,
            };
            *s.histogram.entry(rounded.to_bits()).or_default() += 1;
        }
    }

    /// Claims that were wrong, over all outputs.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Backend, Summary};
    /// let b = Batch::new("m,M,v", Backend::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,3/5").unwrap());
    /// s.add(&b.row(2, "1,1,0.6000001").unwrap());
    /// assert_eq!(s.wrong(), 1);
    /// ```
    pub fn wrong(&self) -> usize {
        self.claims.iter().map(|c| c.wrong).sum()
    }

    /// The report for stderr: rows, laws (or that they were not checked, with the f64 backend),
    /// and per claimed output the count wrong (naming the first [`WRONG_ROWS_SHOWN`] rows), the
    /// maximum and the median relative error.
    ///
    /// # Examples
    /// ```
    /// use rodimpact::batch::{Batch, Backend, Summary};
    /// let b = Batch::new("m,M,v", Backend::Exact).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&b.row(1, "1,1,3/5").unwrap());
    /// assert_eq!(s.report(), "1 rows, laws held exactly on 1\nv: 1 claims, 0 wrong, max rel error 0, median 0\n");
    /// s.add(&b.row(2, "1,1,0.6").unwrap());
    /// s.add(&b.row(3, "1,1,0.61").unwrap());
    /// assert!(s.report().contains("v: 3 claims, 1 wrong (row 3), max rel error 0.0167, median 0"));
    ///
    /// let f = Batch::new("m,M", Backend::F64).unwrap();
    /// let mut s = Summary::default();
    /// s.add(&f.row(1, "1,1").unwrap());
    /// assert_eq!(s.report(), "1 rows (f64: conservation laws not checked)\n");
    /// ```
    pub fn report(&self) -> String {
        let mut out = if self.laws_unchecked > 0 {
            format!("{} rows (f64: conservation laws not checked)\n", self.rows)
        } else {
            format!(
                "{} rows, laws held exactly on {}\n",
                self.rows,
                self.rows - self.laws_failed
            )
        };
        for (k, s) in self.claims.iter().enumerate() {
            if s.compared == 0 {
                continue;
            }
            let max = match &s.max {
                Some(Some(r)) => crate::number::decimal(r, 3),
                _ => "inf".to_string(),
            };
            out.push_str(&format!(
                "{}: {} claims, {} wrong{}, max rel error {max}, median {}\n",
                OUTPUTS[k],
                s.compared,
                s.wrong,
                s.wrong_rows_text(),
                s.median()
            ));
        }
        out
    }
}

impl ClaimStats {
    /// ` (rows 3, 17 and 5 more)`, or nothing when no claim was wrong.
    fn wrong_rows_text(&self) -> String {
        let rows: Vec<String> = self.wrong_rows.iter().map(usize::to_string).collect();
        let more = self.wrong - rows.len();
        match (rows.len(), more) {
            (0, _) => String::new(),
            (1, 0) => format!(" (row {})", rows[0]),
            (_, 0) => format!(" (rows {})", rows.join(", ")),
            _ => format!(" (rows {} and {more} more)", rows.join(", ")),
        }
    }

    fn median(&self) -> String {
        let mut seen = 0;
        for (&bits, &count) in &self.histogram {
            seen += count;
            if 2 * seen > self.compared {
                let x = f64::from_bits(bits);
                return if x == 0.0 {
                    "0".to_string()
                } else {
                    format!("{x:.1e}")
                };
            }
        }
        "-".to_string()
    }
}

/// Streams the data rows of `input` (after the header) to `out`, [`CHUNK`] rows at a time, each
/// chunk solved in parallel on the current rayon pool and written in input order. Reading the
/// next chunk and writing the previous one overlap with solving the current one. `progress`
/// gets the number of bytes read so far after each chunk.
///
/// # Errors
/// The first bad row in input order (`row N, column X: ...`), an over-long line or too many
/// rows, `row N: cannot read: ...` when reading fails, `out: ...` when writing fails. Every row
/// before the bad one is written first (so a stream shows all the good rows up to it): write to
/// an [`crate::io::AtomicFile`] to publish all or nothing.
///
/// # Examples
/// ```
/// use rodimpact::batch::{run, Batch, Backend};
/// let b = Batch::new("m,M", Backend::Exact).unwrap();
/// let mut out = Vec::new();
/// let summary = run("1,1\n2,1\n".as_bytes(), &mut out, &b, |_| {}).unwrap();
/// assert_eq!(String::from_utf8(out).unwrap(), "1,1,3/5,2/5,6/5,true\n2,1,7/9,4/9,4/3,true\n");
/// assert_eq!(summary.rows, 2);
///
/// let mut out = Vec::new();
/// let err = run("1,1\n2,-1\n3,1\n".as_bytes(), &mut out, &b, |_| {}).unwrap_err();
/// assert_eq!(err.to_string(), "row 2, column M: must be > 0, got -1");
/// assert_eq!(String::from_utf8(out).unwrap(), "1,1,3/5,2/5,6/5,true\n"); // row 1 is out
/// ```
pub fn run(
    input: impl BufRead,
    out: &mut impl Write,
    batch: &Batch,
    mut progress: impl FnMut(u64),
) -> Result<Summary, Error> {
    let mut summary = Summary::default();
    let mut reader = ChunkReader {
        input,
        bytes: 0,
        number: 0,
    };
    let mut solved: Vec<Row> = Vec::new();
    // `stop`: the error that ended reading, after the lines of `current`.
    let (mut current, mut stop) = reader.next_chunk();
    while !current.is_empty() {
        let mut rows = Vec::new();
        let (mut written, mut next) = (Ok(()), (Vec::new(), None));
        let reading = stop.is_none();
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| {
                rows = current
                    .par_iter()
                    .map(|(n, line)| batch.row(*n, line))
                    .collect();
            });
            written = write_rows(out, &solved, &mut summary);
            if reading {
                next = reader.next_chunk();
            }
        });
        written?;
        progress(reader.bytes);
        // The current chunk's first bad row comes before any error in the next chunk, and the
        // rows before it are written before it is reported.
        let mut good = Vec::with_capacity(rows.len());
        for row in rows {
            match row {
                Ok(row) => good.push(row),
                Err(e) => {
                    write_rows(out, &good, &mut summary)?;
                    return Err(e);
                }
            }
        }
        solved = good;
        if !reading {
            break;
        }
        (current, stop) = next;
    }
    write_rows(out, &solved, &mut summary)?;
    match stop {
        Some(e) => Err(e),
        None => Ok(summary),
    }
}

fn write_rows(out: &mut impl Write, rows: &[Row], summary: &mut Summary) -> Result<(), Error> {
    for row in rows {
        out.write_all(row.line.as_bytes())
            .map_err(|why| Error::new("out", ErrorKind::Io(format!("cannot write: {why}"))))?;
        summary.add(row);
    }
    Ok(())
}

/// Reads data rows [`CHUNK`] at a time, enforcing [`MAX_LINE`] and [`MAX_ROWS`].
struct ChunkReader<R> {
    input: R,
    /// Bytes read so far.
    bytes: u64,
    /// The number of the last row read (1-based, blank lines counted).
    number: usize,
}

impl<R: BufRead> ChunkReader<R> {
    /// Up to [`CHUNK`] non-blank rows with their numbers (empty at the end of the input), and
    /// the error that stopped reading after them, if any.
    fn next_chunk(&mut self) -> (Vec<(usize, String)>, Option<Error>) {
        let mut lines = Vec::with_capacity(CHUNK);
        while lines.len() < CHUNK {
            match self.next_line() {
                Ok(Some(line)) => lines.push(line),
                Ok(None) => break,
                Err(e) => return (lines, Some(e)),
            }
        }
        (lines, None)
    }

    /// The next non-blank row with its number, or `None` at the end of the input.
    fn next_line(&mut self) -> Result<Option<(usize, String)>, Error> {
        loop {
            let mut line = String::new();
            let n = (&mut self.input)
                .take(MAX_LINE as u64 + 1)
                .read_line(&mut line)
                .map_err(|why| {
                    Error::new(
                        format!("row {}", self.number + 1),
                        ErrorKind::Io(format!("cannot read: {why}")),
                    )
                })?;
            if n == 0 {
                return Ok(None);
            }
            self.bytes += n as u64;
            self.number += 1;
            if n > MAX_LINE {
                return Err(Error::new(
                    format!("row {}", self.number),
                    ErrorKind::Invalid(format!("line longer than {MAX_LINE} bytes")),
                ));
            }
            if self.number > MAX_ROWS {
                return Err(Error::new(
                    format!("row {}", self.number),
                    ErrorKind::Invalid(format!("more than {MAX_ROWS} rows (limit per batch)")),
                ));
            }
            if !line.trim().is_empty() {
                return Ok(Some((self.number, line)));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claims_agree_only_when_exact() {
        let b = Batch::new("m,M,v,V,omega", Backend::Exact).unwrap();
        let row = b.row(1, "1,1,0.6,2/5,1.2").unwrap();
        assert!(row.verdicts.iter().all(|v| v.ok));
        let wrong = b.row(2, "1,1,0.6,0.4000001,1.2").unwrap();
        assert_eq!(
            wrong.line,
            "1,1,0.6,0.4000001,1.2,3/5,2/5,6/5,true,true,0,false,0.000000250,true,0\n"
        );
    }

    #[test]
    fn claims_on_machine_words_are_compared_unreduced_and_with_their_sign() {
        // M = 3m hit at the centre: v = -1/2, V = 1/2, omega = 0.
        let b = Batch::new("m,M,a,v,V,omega", Backend::Exact).unwrap();
        let row = b.row(1, "1,3,0,-3/6,+2/4,-0").unwrap();
        assert!(row.verdicts.iter().all(|v| v.ok), "{row:?}");
        let signs = b.row(2, "1,3,0,1/2,-1/2,0/7").unwrap();
        let oks: Vec<bool> = signs.verdicts.iter().map(|v| v.ok).collect();
        assert_eq!(oks, [false, false, true]);
        assert_eq!(signs.verdicts[0].rel_error, Some(Q::from_integer(2.into())));
        // Beyond 38 digits a claim takes the general parser, with the same verdict.
        let long = format!("{}/{}", "1".repeat(40), "2".repeat(40));
        let row = b.row(3, &format!("1,3,0,-1/2,{long},0")).unwrap();
        let oks: Vec<bool> = row.verdicts.iter().map(|v| v.ok).collect();
        assert_eq!(oks, [true, true, true]);
    }

    #[test]
    fn empty_optional_cells_take_the_defaults() {
        let b = Batch::new("m,M,pivot,e", Backend::Exact).unwrap();
        let free = b.row(1, "1,1,,").unwrap();
        assert_eq!(free.line, "1,1,,,3/5,2/5,6/5,true\n");
        let pivoted = b.row(2, "1,3,0,0").unwrap();
        assert_eq!(pivoted.line, "1,3,0,0,1/2,0,1/2,true\n");
        assert_eq!(
            b.row(3, ",1,,").unwrap_err().to_string(),
            "row 3, column m: empty number"
        );
    }

    #[test]
    fn a_zero_value_with_a_nonzero_claim_is_infinitely_wrong() {
        let b = Batch::new("m,M,a,omega", Backend::Exact).unwrap();
        let row = b.row(1, "1,1,0,1/1000").unwrap();
        assert!(row.line.ends_with(",false,inf\n"), "{}", row.line);
        let mut s = Summary::default();
        s.add(&row);
        assert!(
            s.report()
                .contains("omega: 1 claims, 1 wrong (row 1), max rel error inf")
        );
    }

    #[test]
    fn the_f64_backend_agrees_within_its_tolerance() {
        let b = Batch::new("m,M,V", Backend::F64).unwrap();
        let row = b.row(1, "1,1,2/5").unwrap();
        assert!(row.line.starts_with("1,1,2/5,0.6,0.4,1.2"), "{}", row.line);
        assert!(row.line.contains(",-,true,"), "{}", row.line);
        assert!(!b.row(2, "1,1,0.41").unwrap().verdicts[0].ok);
    }

    #[test]
    fn headers_are_checked() {
        for (header, want) in [
            ("m,m,M", "header: column 'm' given twice"),
            ("M,l", "header: column 'm' is required"),
        ] {
            assert_eq!(
                Batch::new(header, Backend::Exact).unwrap_err().to_string(),
                want
            );
        }
        let b = Batch::new("m,M", Backend::Exact).unwrap();
        assert_eq!(
            b.row(4, "1").unwrap_err().to_string(),
            "row 4: expected 2 cells, got 1"
        );
    }

    #[test]
    fn long_lines_are_refused_and_blank_lines_skipped() {
        let b = Batch::new("m,M", Backend::Exact).unwrap();
        let long = format!("1,{}\n", "1".repeat(MAX_LINE));
        let err = run(long.as_bytes(), &mut Vec::new(), &b, |_| {}).unwrap_err();
        assert_eq!(
            err.to_string(),
            format!("row 1: line longer than {MAX_LINE} bytes")
        );
        let mut out = Vec::new();
        let s = run("1,1\n\n1,1\n".as_bytes(), &mut out, &b, |_| {}).unwrap();
        assert_eq!(s.rows, 2);
    }
}
