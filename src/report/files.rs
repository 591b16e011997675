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
    let fail = |why: std::io::Error| {
        Error::new(
            field,
            ErrorKind::Io(format!("cannot write {}: {why}", path.display())),
        )
    };
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

fn temporary_sibling(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.tmp-{}", std::process::id()))
}
