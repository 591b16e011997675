//! Writing a directory of outputs all-or-nothing (`paper --out DIR`, `prove --write DIR`).
//!
//! Every file is first written into a fresh, exclusively created staging directory beside
//! `DIR` (hidden: `.DIR.tmp-XXXXXX`). Only when all of them are complete is the staging
//! directory renamed into place:
//!
//! - `DIR` does not exist: one rename, atomic.
//! - `DIR` exists: the entries of `DIR` that this run does not write (a user's notes, the
//!   certificates of other claims) are moved into the staging directory, `DIR` is renamed aside
//!   (`.DIR.old-XXXXXX`), the staging directory takes its name, and the old one is removed.
//!   Every step that fails is undone, so a failing run leaves `DIR` as it was.
//!
//! Before anything is written, a target name that exists in `DIR` as a directory (or another
//! non-file) is refused, since replacing it would delete what it holds, and so is a `DIR` that
//! holds the current directory (`--out .`). A run killed between
//! the two renames leaves `DIR` missing and both hidden directories beside it; nothing is lost.

use crate::error::{Error, ErrorKind};
use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// `why` without the staging path that `tempfile` appends to its errors (the user named `DIR`).
fn plain(why: std::io::Error) -> std::io::Error {
    match why.raw_os_error() {
        Some(code) => std::io::Error::from_raw_os_error(code),
        None => why,
    }
}

fn io_error(field: &str, path: &Path, why: std::io::Error) -> Error {
    Error::io(field, format!("cannot write {}", path.display()), why)
}

/// A directory this module will not write, and why (not an operating-system error).
fn refused(field: &str, path: &Path, why: &str) -> Error {
    Error::new(
        field,
        ErrorKind::Invalid(format!("cannot write {}: {why}", path.display())),
    )
}

/// Writes `files` (name, contents) into `dir` all-or-nothing: either every file is in place, or
/// `dir` is left exactly as it was (see the module documentation). Other entries of `dir` are
/// kept.
///
/// # Errors
/// `field: cannot write <path>: <reason>`: `dir` is not a directory, a target name is a
/// directory in it, or a file or directory cannot be written.
///
/// # Examples
/// ```
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-outdir-{}", std::process::id()));
/// let files = [("a.md".to_string(), "new\n".to_string())];
/// rodimpact::io::write_directory("out", &dir, &files).unwrap();
/// std::fs::write(dir.join("notes.txt"), "mine").unwrap();
/// std::fs::create_dir(dir.join("b.md")).unwrap(); // in the way of the next run
/// let more = [files[0].clone(), ("b.md".to_string(), "b\n".to_string())];
/// assert!(rodimpact::io::write_directory("out", &dir, &more).is_err());
/// std::fs::remove_dir(dir.join("b.md")).unwrap();
/// rodimpact::io::write_directory("out", &dir, &more).unwrap();
/// assert_eq!(std::fs::read_to_string(dir.join("b.md")).unwrap(), "b\n");
/// assert_eq!(std::fs::read_to_string(dir.join("notes.txt")).unwrap(), "mine");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_directory(field: &str, dir: &Path, files: &[(String, String)]) -> Result<(), Error> {
    let fail = |path: &Path, why: std::io::Error| io_error(field, path, why);
    let exists = dir.exists();
    // Resolve `.`, `..` and a symlink to the directory itself, whose name the swap needs.
    let dir = if exists {
        fs::canonicalize(dir).map_err(|why| fail(dir, why))?
    } else {
        dir.to_path_buf()
    };
    if exists && !dir.is_dir() {
        return Err(refused(field, &dir, "not a directory"));
    }
    // The directory is replaced as a whole: a shell inside it would be left in a removed one.
    let cwd = std::env::current_dir().and_then(fs::canonicalize);
    if exists && cwd.is_ok_and(|cwd| cwd.starts_with(&dir)) {
        return Err(refused(
            field,
            &dir,
            "it holds the current directory, and is replaced as a whole: name a subdirectory",
        ));
    }
    let name = dir
        .file_name()
        .ok_or_else(|| refused(field, &dir, "no directory name"))?
        .to_string_lossy()
        .into_owned();
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if exists {
        for (file, _) in files {
            let target = dir.join(file);
            if let Ok(meta) = fs::symlink_metadata(&target) {
                let kind = meta.file_type();
                if !kind.is_file() && !kind.is_symlink() {
                    return Err(refused(
                        field,
                        &target,
                        "it exists and is not a regular file (left untouched)",
                    ));
                }
            }
        }
    }
    fs::create_dir_all(&parent).map_err(|why| fail(&parent, why))?;
    let staging = tempfile::Builder::new()
        .prefix(&format!(".{name}.tmp-"))
        .tempdir_in(&parent)
        .map_err(|why| fail(&dir, plain(why)))?;
    for (file, contents) in files {
        let path = staging.path().join(file);
        let written = fs::File::create_new(&path).and_then(|mut f| {
            f.write_all(contents.as_bytes())?;
            f.sync_all()
        });
        written.map_err(|why| fail(&dir.join(file), why))?;
    }
    if !exists {
        fs::rename(staging.path(), &dir).map_err(|why| fail(&dir, why))?;
        let _ = staging.keep();
        return Ok(());
    }
    swap_in(field, &dir, &name, &parent, staging, files)
}

/// Replaces the existing `dir` by the complete `staging` directory, carrying over the entries
/// of `dir` that `files` does not name; undoes every step on failure.
fn swap_in(
    field: &str,
    dir: &Path,
    name: &str,
    parent: &Path,
    staging: tempfile::TempDir,
    files: &[(String, String)],
) -> Result<(), Error> {
    let fail = |path: &Path, why: std::io::Error| io_error(field, path, why);
    let ours = |entry: &str| files.iter().any(|(f, _)| f == entry);
    let mut carried: Vec<std::ffi::OsString> = Vec::new();
    let carry_back = |carried: &[std::ffi::OsString]| {
        for entry in carried {
            let _ = fs::rename(staging.path().join(entry), dir.join(entry));
        }
    };
    let entries = fs::read_dir(dir).map_err(|why| fail(dir, why))?;
    for entry in entries {
        let entry = entry.map_err(|why| fail(dir, why))?;
        let entry_name = entry.file_name();
        if ours(&entry_name.to_string_lossy()) {
            continue;
        }
        if let Err(why) = fs::rename(entry.path(), staging.path().join(&entry_name)) {
            carry_back(&carried);
            return Err(fail(&entry.path(), why));
        }
        carried.push(entry_name);
    }
    let backup = match tempfile::Builder::new()
        .prefix(&format!(".{name}.old-"))
        .tempdir_in(parent)
    {
        Ok(b) => b,
        Err(why) => {
            carry_back(&carried);
            return Err(fail(dir, plain(why)));
        }
    };
    // Renaming a directory onto an empty one replaces it (POSIX).
    if let Err(why) = fs::rename(dir, backup.path()) {
        carry_back(&carried);
        return Err(fail(dir, why));
    }
    if let Err(why) = fs::rename(staging.path(), dir) {
        if fs::rename(backup.path(), dir).is_ok() {
            carry_back(&carried);
        } else {
            let _ = backup.keep(); // the previous directory stays, hidden, rather than being removed
        }
        return Err(fail(dir, why));
    }
    let _ = staging.keep();
    // `backup` now holds only the previous run's own files; dropping it removes them.
    drop(backup);
    Ok(())
}
