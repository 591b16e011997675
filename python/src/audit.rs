//! `audit`: the `batch` audit, streamed. A worker thread runs the library's
//! [`rodimpact::batch::run`] (the very function `rodimpact batch` runs: chunks solved in
//! parallel, written in input order) on the file or on the CSV text Python feeds it, and cuts
//! its output lines into columns, handed to Python a block of rows at a time as Arrow string
//! buffers (offsets and bytes), so that no CSV is parsed on the way back.

use crate::value_error;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;
use rodimpact::app::batch::{BatchOptions, Spelling};
use rodimpact::batch::{Agreement, Batch, Summary, read_header, run};
use rodimpact::{Error, ErrorKind};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::PathBuf;
use std::sync::mpsc::{Receiver, Sender, SyncSender, channel, sync_channel};
use std::thread::JoinHandle;

/// Rows per block handed to Python.
const BLOCK_ROWS: usize = 1 << 16;
/// Input pieces Python may feed ahead of the worker.
const INPUT_AHEAD: usize = 4;

/// One block of output rows: per column, the cells' bytes one after another and the Arrow
/// `large_string` offsets (little-endian i64, rows + 1 of them).
struct Block {
    rows: usize,
    columns: Vec<(Vec<u8>, Vec<u8>)>,
}

impl Block {
    fn new(width: usize) -> Block {
        Block {
            rows: 0,
            columns: (0..width)
                .map(|_| (Vec::new(), 0i64.to_le_bytes().to_vec()))
                .collect(),
        }
    }

    /// Appends one output line (no newline), cut at its commas: the batch's cells never hold
    /// a comma (the reader splits at every one). A line with more cells than the header keeps
    /// the rest in its last column; one with fewer leaves the others empty.
    fn push(&mut self, line: &[u8]) {
        let width = self.columns.len();
        let mut cells = line.splitn(width, |&b| b == b',');
        for (data, offsets) in &mut self.columns {
            if let Some(cell) = cells.next() {
                data.extend_from_slice(cell);
            }
            offsets.extend_from_slice(&(data.len() as i64).to_le_bytes());
        }
        self.rows += 1;
    }
}

/// The writer `run` writes its output lines to: complete lines go into the current block, and
/// a full block goes to Python.
struct BlockWriter {
    width: usize,
    pending: Vec<u8>,
    block: Block,
    out: Sender<Block>,
}

impl BlockWriter {
    fn take_lines(&mut self) {
        let mut start = 0;
        while let Some(end) = self.pending[start..].iter().position(|&b| b == b'\n') {
            let mut line = &self.pending[start..start + end];
            if let [rest @ .., b'\r'] = line {
                line = rest;
            }
            self.block.push(line);
            start += end + 1;
            if self.block.rows >= BLOCK_ROWS {
                self.send();
            }
        }
        self.pending.drain(..start);
    }

    fn send(&mut self) {
        let full = std::mem::replace(&mut self.block, Block::new(self.width));
        // Python gone (the stream dropped): nothing to hand the rows to.
        let _ = self.out.send(full);
    }
}

impl Write for BlockWriter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.pending.extend_from_slice(buf);
        self.take_lines();
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The rows Python feeds, as a reader: each piece is whole lines of CSV text; the end of the
/// input is the sender dropped ([`AuditStream::close`]).
struct FedReader {
    pieces: Receiver<Vec<u8>>,
    piece: Vec<u8>,
    at: usize,
}

impl Read for FedReader {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let available = self.fill_buf()?;
        let n = available.len().min(buf.len());
        buf[..n].copy_from_slice(&available[..n]);
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for FedReader {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        while self.at >= self.piece.len() {
            match self.pieces.recv() {
                Ok(piece) => {
                    self.piece = piece;
                    self.at = 0;
                }
                Err(_) => return Ok(&[]),
            }
        }
        Ok(&self.piece[self.at..])
    }
    fn consume(&mut self, amount: usize) {
        self.at += amount;
    }
}

/// What the worker hands back at the end: the totals, or the error that stopped it (the rows
/// before a bad row were all sent first, as the CLI writes them before reporting it).
type Outcome = Result<Summary, Error>;

/// A running audit: Python feeds rows (or the worker reads the file), takes blocks of output
/// columns, and finishes with the summary.
#[pyclass(module = "rodimpact._native")]
pub(crate) struct AuditStream {
    input: Option<SyncSender<Vec<u8>>>,
    output: std::sync::Mutex<Receiver<Block>>,
    worker: Option<JoinHandle<Outcome>>,
    names: Vec<String>,
    input_width: usize,
    passed: Vec<String>,
    agreement: Option<Agreement>,
    atol: Option<String>,
}

/// The batch for `header` with the options of `rodimpact batch`, read by the library's one
/// reader of them ([`BatchOptions`]).
fn batch_for(header: &str, options: &Options) -> Result<(Batch, Option<Agreement>), Error> {
    let batch_options = BatchOptions {
        arithmetic: BatchOptions::arithmetic_of(options.backend.as_deref())?,
        float: BatchOptions::float_of(options.float.as_deref())?,
        rtol: options.rtol.clone(),
        ulps: options.ulps.clone(),
        atol: options.atol.clone(),
        tolerance: Vec::new(),
        spelling: Spelling::Keywords,
    };
    let checked = batch_options.checked()?;
    let batch = batch_options.batch(header, &checked)?;
    Ok((batch, checked.agreement))
}

/// The options of `rodimpact batch`, as text (each read by the library's own parser).
#[derive(Clone, Default)]
struct Options {
    backend: Option<String>,
    rtol: Option<String>,
    ulps: Option<String>,
    float: Option<String>,
    atol: Option<String>,
    jobs: Option<usize>,
}

impl AuditStream {
    fn start(
        header: &str,
        options: &Options,
        source: impl BufRead + Send + 'static,
        input: Option<SyncSender<Vec<u8>>>,
    ) -> Result<AuditStream, Error> {
        let (batch, agreement) = batch_for(header, options)?;
        let names: Vec<String> = batch
            .output_header()
            .trim_end()
            .split(',')
            .map(str::to_string)
            .collect();
        let passed = batch
            .passed_through()
            .iter()
            .map(|s| s.to_string())
            .collect();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(options.jobs.unwrap_or(0))
            .build()
            .map_err(|why| Error::new("jobs", ErrorKind::Invalid(why.to_string())))?;
        let (out, output) = channel();
        let width = names.len();
        let worker = std::thread::spawn(move || {
            let mut writer = BlockWriter {
                width,
                pending: Vec::new(),
                block: Block::new(width),
                out,
            };
            let outcome = pool.install(|| run(source, &mut writer, &batch, |_| {}));
            writer.take_lines();
            if writer.block.rows > 0 {
                writer.send();
            }
            outcome
        });
        Ok(AuditStream {
            input,
            output: std::sync::Mutex::new(output),
            worker: Some(worker),
            names,
            input_width: header.trim_end().split(',').count(),
            passed,
            agreement,
            atol: options.atol.clone(),
        })
    }
}

fn options(
    backend: Option<String>,
    rtol: Option<String>,
    ulps: Option<String>,
    float: Option<String>,
    atol: Option<String>,
    jobs: Option<usize>,
) -> Result<Options, Error> {
    if let Some(n) = jobs
        && !(1..=1024).contains(&n)
    {
        return Err(Error::out_of_range(
            "jobs",
            format!("must be a whole number from 1 to 1024, got '{n}'"),
        ));
    }
    Ok(Options {
        backend,
        rtol,
        ulps,
        float,
        atol,
        jobs,
    })
}

#[pymethods]
impl AuditStream {
    /// An audit of the CSV file at `path` (header and rows), read by the worker.
    #[staticmethod]
    #[pyo3(signature = (path, backend=None, rtol=None, ulps=None, float=None, atol=None, jobs=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_path(
        py: Python<'_>,
        path: PathBuf,
        backend: Option<String>,
        rtol: Option<String>,
        ulps: Option<String>,
        float: Option<String>,
        atol: Option<String>,
        jobs: Option<usize>,
    ) -> PyResult<AuditStream> {
        py.detach(|| {
            let options = options(backend, rtol, ulps, float, atol, jobs)?;
            let label = rodimpact::echo::echo_path(&path);
            let file = std::fs::File::open(&path)
                .map_err(|why| Error::io("FILE", format!("cannot read {label}"), why))?;
            let mut input = BufReader::with_capacity(1 << 16, file);
            let header = read_header(&mut input, &label)?;
            AuditStream::start(&header, &options, input, None)
        })
        .map_err(value_error)
    }

    /// An audit of rows Python feeds as CSV text ([`AuditStream::feed`]) under `header`.
    #[staticmethod]
    #[pyo3(signature = (header, backend=None, rtol=None, ulps=None, float=None, atol=None, jobs=None))]
    #[allow(clippy::too_many_arguments)]
    fn from_header(
        py: Python<'_>,
        header: String,
        backend: Option<String>,
        rtol: Option<String>,
        ulps: Option<String>,
        float: Option<String>,
        atol: Option<String>,
        jobs: Option<usize>,
    ) -> PyResult<AuditStream> {
        py.detach(|| {
            let options = options(backend, rtol, ulps, float, atol, jobs)?;
            let (input, pieces) = sync_channel(INPUT_AHEAD);
            let reader = FedReader {
                pieces,
                piece: Vec::new(),
                at: 0,
            };
            AuditStream::start(&header, &options, reader, Some(input))
        })
        .map_err(value_error)
    }

    /// The output columns, in the CLI's order (the input's, then those the audit appends).
    #[getter]
    fn columns(&self) -> Vec<String> {
        self.names.clone()
    }

    /// The number of input columns: the output's first columns are the input's.
    #[getter]
    fn input_width(&self) -> usize {
        self.input_width
    }

    /// The input columns passed through unchanged (the CLI's `passed through:` line).
    #[getter]
    fn passed_through(&self) -> Vec<String> {
        self.passed.clone()
    }

    /// When a claim agrees, in words (the CLI's `claims agree ...` line), if a rule was given.
    #[getter]
    fn agreement(&self) -> Option<String> {
        self.agreement.as_ref().map(Agreement::describe)
    }

    /// Feeds whole lines of CSV text (no header). Returns False when the worker has stopped
    /// (a bad row: [`AuditStream::finish`] tells which), so the caller stops feeding.
    fn feed(&self, py: Python<'_>, data: Vec<u8>) -> bool {
        let Some(input) = &self.input else {
            return false;
        };
        py.detach(|| input.send(data).is_ok())
    }

    /// The end of the fed rows.
    fn close(&mut self) {
        self.input = None;
    }

    /// The next block of output rows as `(rows, [(bytes, offsets), ...])`, one pair per
    /// column; `None` when no block is ready (`wait=False`) or none will come.
    #[pyo3(signature = (wait))]
    #[allow(clippy::type_complexity)]
    fn next_block(
        &self,
        py: Python<'_>,
        wait: bool,
    ) -> Option<(usize, Vec<(Py<PyBytes>, Py<PyBytes>)>)> {
        let block = py.detach(|| {
            let output = self.output.lock().ok()?;
            if wait {
                output.recv().ok()
            } else {
                output.try_recv().ok()
            }
        })?;
        let columns = block
            .columns
            .iter()
            .map(|(data, offsets)| {
                (
                    PyBytes::new(py, data).unbind(),
                    PyBytes::new(py, offsets).unbind(),
                )
            })
            .collect();
        Some((block.rows, columns))
    }

    /// Waits for the worker: what the CLI prints on standard error after the rows, whether
    /// it would exit 0 (no wrong claim, every law held, no finding) and the number of rows; or
    /// the `ValueError` of the first bad row.
    fn finish(&mut self, py: Python<'_>) -> PyResult<(String, bool, usize)> {
        self.input = None;
        let Some(worker) = self.worker.take() else {
            return Err(PyValueError::new_err("audit: already finished"));
        };
        let outcome = py.detach(|| worker.join());
        let summary = match outcome {
            Ok(Ok(summary)) => summary,
            Ok(Err(e)) => return Err(value_error(e)),
            Err(_) => {
                return Err(crate::internal("the audit's worker stopped unexpectedly"));
            }
        };
        let passed: Vec<&str> = self.passed.iter().map(String::as_str).collect();
        let text = rodimpact::report::batch_report(
            &summary,
            &passed,
            self.agreement.as_ref(),
            &[],
            self.atol.as_deref(),
        );
        Ok((
            text,
            rodimpact::report::batch_passed(&summary),
            summary.rows,
        ))
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<AuditStream>()?;
    Ok(())
}
