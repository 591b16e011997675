//! Streaming a batch: data rows read [`CHUNK`] at a time, each chunk solved in parallel and
//! written in input order, reading and writing overlapped with solving.

use super::header::Batch;
use super::plan::SolvedRow;
use super::summary::Summary;
use crate::error::{Error, ErrorKind};
use rayon::prelude::*;
use std::io::{BufRead, Read, Write};
use std::ops::Range;

/// The largest number of data rows accepted.
pub const MAX_ROWS: usize = 100_000_000;
/// The longest line accepted, in bytes.
pub const MAX_LINE: usize = 1 << 20;
/// Rows read, solved in parallel and written per step.
pub const CHUNK: usize = 2048;

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
/// use rodimpact::batch::{run, Batch, Arithmetic};
/// let b = Batch::new("m,M", Arithmetic::Exact).unwrap();
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
        chunk_bytes: CHUNK * 80,
    };
    let mut solved: Vec<SolvedRow> = Vec::new();
    // `stop`: the error that ended reading, after the lines of `current`.
    let (mut current, mut stop) = reader.next_chunk();
    while !current.is_empty() {
        let mut rows = Vec::new();
        let (mut written, mut next) = (Ok(()), (Chunk::default(), None));
        let reading = stop.is_none();
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| {
                rows = current
                    .rows
                    .par_iter()
                    .map(|(n, place)| batch.row(*n, &current.text[place.clone()]))
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

fn write_rows(
    out: &mut impl Write,
    rows: &[SolvedRow],
    summary: &mut Summary,
) -> Result<(), Error> {
    for row in rows {
        out.write_all(row.line.as_bytes())
            .map_err(|why| Error::io("out", "cannot write", why))?;
        summary.add(row);
    }
    Ok(())
}

/// Rows read together: their lines one after another in one string (one allocation for the
/// chunk, not one per row), and each row's number and place in it.
#[derive(Default)]
struct Chunk {
    text: String,
    rows: Vec<(usize, Range<usize>)>,
}

impl Chunk {
    fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }
}

/// Reads data rows [`CHUNK`] at a time, enforcing [`MAX_LINE`] and [`MAX_ROWS`].
struct ChunkReader<R> {
    input: R,
    /// Bytes read so far.
    bytes: u64,
    /// The number of the last row read (1-based, blank lines counted).
    number: usize,
    /// The room a chunk's text is given: the last chunk's length, and an eighth more (an
    /// engine's rows of 200 bytes outgrew a fixed guess, copying the chunk at each doubling).
    chunk_bytes: usize,
}

impl<R: BufRead> ChunkReader<R> {
    /// Up to [`CHUNK`] non-blank rows with their numbers (empty at the end of the input), and
    /// the error that stopped reading after them, if any.
    fn next_chunk(&mut self) -> (Chunk, Option<Error>) {
        let mut chunk = Chunk {
            text: String::with_capacity(self.chunk_bytes),
            rows: Vec::with_capacity(CHUNK),
        };
        while chunk.rows.len() < CHUNK {
            match self.next_line(&mut chunk.text) {
                Ok(Some(row)) => chunk.rows.push(row),
                Ok(None) => break,
                Err(e) => return (chunk, Some(e)),
            }
        }
        self.chunk_bytes = self
            .chunk_bytes
            .max(chunk.text.len() + chunk.text.len() / 8);
        (chunk, None)
    }

    /// Appends the next non-blank row to `text`: its number and place, or `None` at the end
    /// of the input.
    fn next_line(&mut self, text: &mut String) -> Result<Option<(usize, Range<usize>)>, Error> {
        loop {
            let start = text.len();
            let n = (&mut self.input)
                .take(MAX_LINE as u64 + 1)
                .read_line(text)
                .map_err(|why| Error::io(format!("row {}", self.number + 1), "cannot read", why))?;
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
            if text[start..].trim().is_empty() {
                text.truncate(start);
            } else {
                return Ok(Some((self.number, start..text.len())));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::Arithmetic;

    #[test]
    fn long_lines_are_refused_and_blank_lines_skipped() {
        let b = Batch::new("m,M", Arithmetic::Exact).unwrap();
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
