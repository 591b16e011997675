//! `rodimpact batch FILE.csv`: many scenes, streamed, in parallel, written back in order.

use super::Failure;
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use rodimpact::app::batch::{BatchOptions, Spelling};
use rodimpact::batch::{Arithmetic, Batch, FloatFormat, read_header, run, scene_columns};
use rodimpact::echo::{echo, echo_path};
use rodimpact::io::AtomicFile;
use rodimpact::report::{batch_passed, batch_report, batch_summary_json, expected_report};
use rodimpact::{Error, ErrorKind};
use std::io::{BufReader, IsTerminal, Write};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub(crate) struct BatchArgs {
    #[arg(value_name = "FILE.csv", help = file_help())]
    pub(crate) file: PathBuf,
    /// Arithmetic: exact rationals, or the paper's closed form in f64 (the naive formula, not
    /// the stable one of `solve --backend f64`).
    #[arg(long, value_enum, default_value = "exact")]
    pub(crate) backend: BackendArg,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    pub(crate) jobs: Option<String>,
    /// Write the rows here (all or nothing) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: Option<PathBuf>,
    /// A claim agrees when its relative error is at most R (0 <= R <= 1).
    #[arg(
        long,
        value_name = "R",
        conflicts_with = "ulps",
        allow_hyphen_values = true
    )]
    pub(crate) rtol: Option<String>,
    /// A claim agrees when it is at most N floats from the correctly rounded exact value
    /// (exact backend).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub(crate) ulps: Option<String>,
    /// The float format of --ulps and of the ulps tolerances [default: f64].
    #[arg(long, value_enum, value_name = "f32|f64")]
    pub(crate) float: Option<FloatArg>,
    /// A tolerance for a class of rows, CLASS=RULE (repeatable; the first that takes a row
    /// wins, the other rows keep --rtol/--ulps): CLASS free, pivot, oblique or id:PATTERN (`*`
    /// for any text); RULE rtol:R, ulps:N or exact. E.g. --tolerance pivot=rtol:1e-6
    /// --tolerance free=ulps:16.
    #[arg(long, value_name = "CLASS=RULE")]
    pub(crate) tolerance: Vec<String>,
    /// A claim also agrees when it lies within X of the exact value in the scene's own units
    /// (X v0 for v and V, X v0/l for omega, X m v0 for J, X m v0^2/2 for the energies; 0 <= X
    /// <= 1): for quantities that vanish exactly, where an engine returns round-off.
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub(crate) atol: Option<String>,
    /// Known findings (CSV `id,finding`, `*` in an id for a class of scenes): the batch fails
    /// only on findings the file does not allow (needs an id column).
    #[arg(long, value_name = "FILE")]
    pub(crate) expect: Option<PathBuf>,
    /// Also write the summary as JSON here (all or nothing), for a CI job.
    #[arg(long, value_name = "FILE")]
    pub(crate) summary_json: Option<PathBuf>,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(crate) enum FloatArg {
    F32,
    F64,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
pub(crate) enum BackendArg {
    /// Exact rationals by the fraction-free route (integers over one common denominator).
    Exact,
    /// The naive closed form in IEEE binary64 (route "closed form"): the paper's formulas as a
    /// float code would write them; claims agree within a relative 1e-9.
    F64,
}

/// The most worker threads `--jobs` accepts.
const MAX_JOBS: usize = 1024;

fn parse_jobs(text: &str) -> Result<usize, Error> {
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=MAX_JOBS).contains(&n) => Ok(n),
        _ => Err(Error::out_of_range(
            "jobs",
            format!(
                "must be a whole number from 1 to {MAX_JOBS}, got '{}'",
                echo(text)
            ),
        )),
    }
}

pub(crate) fn run_batch(args: &BatchArgs) -> Result<(), Failure> {
    let options = BatchOptions {
        arithmetic: match args.backend {
            BackendArg::Exact => Arithmetic::Exact,
            BackendArg::F64 => Arithmetic::F64,
        },
        float: args.float.map(|f| match f {
            FloatArg::F32 => FloatFormat::F32,
            FloatArg::F64 => FloatFormat::F64,
        }),
        rtol: args.rtol.clone(),
        ulps: args.ulps.clone(),
        atol: args.atol.clone(),
        tolerance: args.tolerance.clone(),
        spelling: Spelling::Flags,
    };
    let jobs = args.jobs.as_deref().map(parse_jobs).transpose()?;
    let checked = options.checked()?;
    let expected = args
        .expect
        .as_deref()
        .map(rodimpact::app::impact_batch::read_known_findings)
        .transpose()?;
    let read_error = |why: std::io::Error| {
        Error::io(
            "FILE",
            format!("cannot read {}", echo_path(&args.file)),
            why,
        )
    };
    let file = std::fs::File::open(&args.file).map_err(read_error)?;
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    let mut input = BufReader::with_capacity(1 << 16, file);
    let header = read_header(&mut input, &echo_path(&args.file))?;
    let batch = options.batch(&header, &checked)?;
    let batch = match &expected {
        Some(expected) => batch.with_expected(expected.clone())?,
        None => batch,
    };

    let bar = std::io::stderr().is_terminal().then(|| {
        let bar = ProgressBar::new(size);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {bytes}/{total_bytes} {eta}")
                .expect("constant template"),
        );
        bar.set_position(header.len() as u64);
        bar
    });
    let header_len = header.len() as u64;
    let progress = |bytes: u64| {
        if let Some(bar) = &bar {
            bar.set_position(header_len + bytes);
        }
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.unwrap_or(0))
        .build()
        .map_err(|why| Error::new("jobs", ErrorKind::Invalid(why.to_string())))?;

    let summary_file = super::SummaryFile::open(args.summary_json.as_deref())?;
    let summary = match &args.out {
        Some(path) => {
            let mut out = AtomicFile::create("out", path)?;
            write_header(&mut out, &batch)?;
            let summary = pool.install(|| run(input, &mut out, &batch, progress))?;
            out.commit()?;
            summary
        }
        None => {
            let mut out = Recorded::new(std::io::BufWriter::new(std::io::stdout()));
            let streamed = write_header(&mut out, &batch)
                .and_then(|()| pool.install(|| run(input, &mut out, &batch, progress)));
            // Rows before a bad one are written out before the error is told; a failed write
            // is reported as such (quietly for a closed pipe, `| head`).
            let flushed = out.flush();
            if let Some(why) = out.failure.take() {
                super::stdout_failed(&why);
            }
            if let Err(why) = flushed {
                super::stdout_failed(&why);
            }
            streamed?
        }
    };
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let mut text = batch_report(
        &summary,
        &batch.passed_through(),
        checked.agreement.as_ref(),
        batch.class_rules(),
        args.atol.as_deref(),
    );
    if let (Some(path), Some(expected)) = (&args.expect, &expected) {
        text.push_str(&expected_report(&summary, expected, path));
    }
    super::print_err(&text);
    summary_file.write(&batch_summary_json(&summary, expected.as_ref()))?;
    if batch_passed(&summary) {
        Ok(())
    } else {
        Err(Failure::Check)
    }
}

/// The help of the FILE argument: every scene column, the claims, and the rest passed through.
fn file_help() -> String {
    format!(
        "CSV file: header among {} (m and M required), claimed v,V,omega,J,energy_before,energy_after (an oblique scene: v,V,omega,vt,Vt,spin_after,tangential_impulse), and any other columns (passed through)",
        scene_columns()
    )
}

/// A writer that keeps its first error, so that the command can tell a failed write to
/// standard output (a closed pipe, a full disk) from a bad input row after `run` has turned
/// both into an [`Error`].
struct Recorded<W> {
    inner: W,
    failure: Option<std::io::Error>,
}

impl<W: Write> Recorded<W> {
    fn new(inner: W) -> Self {
        Recorded {
            inner,
            failure: None,
        }
    }

    fn keep<T>(&mut self, result: std::io::Result<T>) -> std::io::Result<T> {
        if let Err(why) = &result
            && why.kind() != std::io::ErrorKind::Interrupted
            && self.failure.is_none()
        {
            self.failure = Some(std::io::Error::new(why.kind(), why.to_string()));
        }
        result
    }
}

impl<W: Write> Write for Recorded<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let written = self.inner.write(buf);
        self.keep(written)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        let flushed = self.inner.flush();
        self.keep(flushed)
    }
}

fn write_header(out: &mut impl Write, batch: &Batch) -> Result<(), Error> {
    out.write_all(batch.output_header().as_bytes())
        .map_err(|why| Error::io("out", "cannot write", why))
}
