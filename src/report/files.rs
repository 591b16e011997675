//! Writing output files so that no reader ever sees a half-written one.

use crate::error::{Error, ErrorKind};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `contents` to `path` atomically: into a temporary file in the same directory, flushed
/// to disk, then renamed over `path`. An interrupted or failing run leaves the previous file
/// intact. `field` names the option the path came from, for the error message.
///
/// # Errors
/// `field: cannot write <path>: <reason>` when the directory or file cannot be written.
///
/// # Examples
/// ```
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("x.md");
/// rodimpact::report::write_atomic("out", &path, "hello\n").unwrap();
/// assert_eq!(std::fs::read_to_string(&path).unwrap(), "hello\n");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_atomic(field: &str, path: &Path, contents: &str) -> Result<(), Error> {
    let fail = |why: std::io::Error| io_error(field, path, why);
    let tmp = temporary_sibling(path);
    let written = (|| {
        let mut file = fs::File::create(&tmp)?;
        file.write_all(contents.as_bytes())?;
        file.sync_all()?;
        fs::rename(&tmp, path)
    })();
    if let Err(why) = written {
        let _ = fs::remove_file(&tmp);
        return Err(fail(why));
    }
    Ok(())
}

/// Creates `dir` (and its parents) for output.
///
/// # Errors
/// `field: cannot create <dir>: <reason>`.
///
/// # Examples
/// ```
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-dir-{}", std::process::id()));
/// rodimpact::report::create_output_dir("write", &dir).unwrap();
/// assert!(dir.is_dir());
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn create_output_dir(field: &str, dir: &Path) -> Result<(), Error> {
    fs::create_dir_all(dir).map_err(|why| {
        Error::new(
            field,
            ErrorKind::Io(format!("cannot create {}: {why}", dir.display())),
        )
    })
}

/// An output file written as a stream, atomically: the bytes go to a temporary file in the
/// target's directory, which [`AtomicFile::commit`] flushes and renames over the target. If it is
/// dropped without a commit (an error, a panic), the temporary file is removed and the target
/// is untouched.
///
/// # Examples
/// ```
/// use std::io::Write;
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-atomic-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("rows.csv");
/// let mut out = rodimpact::report::AtomicFile::create("out", &path).unwrap();
/// out.write_all(b"a,b\n").unwrap();
/// assert!(!path.exists()); // nothing visible before the commit
/// out.commit().unwrap();
/// assert_eq!(std::fs::read_to_string(&path).unwrap(), "a,b\n");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub struct AtomicFile {
    field: String,
    path: PathBuf,
    tmp: PathBuf,
    file: Option<std::io::BufWriter<fs::File>>,
}

impl AtomicFile {
    /// Opens the temporary file beside `path`.
    ///
    /// # Errors
    /// `field: cannot write <path>: <reason>`.
    ///
    /// # Examples
    /// ```
    /// let err = rodimpact::report::AtomicFile::create("out", "/nonexistent/x.csv".as_ref());
    /// assert!(err.err().unwrap().to_string().starts_with("out: cannot write /nonexistent/x.csv"));
    /// ```
    pub fn create(field: &str, path: &Path) -> Result<AtomicFile, Error> {
        let tmp = temporary_sibling(path);
        let file = fs::File::create(&tmp).map_err(|why| io_error(field, path, why))?;
        Ok(AtomicFile {
            field: field.to_string(),
            path: path.to_path_buf(),
            tmp,
            file: Some(std::io::BufWriter::new(file)),
        })
    }

    /// Flushes the data to disk and renames the temporary file over the target.
    ///
    /// # Errors
    /// `field: cannot write <path>: <reason>` (the temporary file is then removed).
    ///
    /// # Examples
    /// ```
    /// use std::io::Write;
    /// let dir = std::env::temp_dir().join(format!("rodimpact-doc-commit-{}", std::process::id()));
    /// std::fs::create_dir_all(&dir).unwrap();
    /// let mut dropped = rodimpact::report::AtomicFile::create("out", &dir.join("a.csv")).unwrap();
    /// dropped.write_all(b"x").unwrap();
    /// drop(dropped); // no commit: nothing left behind
    /// assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    /// # std::fs::remove_dir_all(&dir).unwrap();
    /// ```
    pub fn commit(mut self) -> Result<(), Error> {
        let file = self.file.take().expect("open until committed");
        let done = file
            .into_inner()
            .map_err(|e| e.into_error())
            .and_then(|f| f.sync_all())
            .and_then(|()| fs::rename(&self.tmp, &self.path));
        done.map_err(|why| {
            let _ = fs::remove_file(&self.tmp);
            io_error(&self.field, &self.path, why)
        })
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.file.as_mut().expect("open until committed").write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.file.as_mut().expect("open until committed").flush()
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.file.take().is_some() {
            let _ = fs::remove_file(&self.tmp);
        }
    }
}

fn io_error(field: &str, path: &Path, why: std::io::Error) -> Error {
    Error::new(
        field,
        ErrorKind::Io(format!("cannot write {}: {why}", path.display())),
    )
}

fn temporary_sibling(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}
