//! Writing a set of files into a directory all-or-nothing (`paper --out DIR`, `prove --write
//! DIR`, `prove --export FORMAT DIR`).
//!
//! `DIR` itself is never replaced, moved or re-created: it keeps its inode, mode, owner and
//! group, and every entry this run does not write stays exactly where it is (a user's notes,
//! the certificates of other claims, files another process writes into `DIR` meanwhile). A
//! missing `DIR` is created.
//!
//! 1. **Check.** A target name that exists in `DIR` as a directory (or another non-file) is
//!    refused before anything is written, since replacing it would delete what it holds. A
//!    final symbolic link of `DIR` planted in a shared sticky directory is refused
//!    (`may_follow_link`).
//! 2. **Stage.** Every file is written into its own temporary beside its target, in `DIR`
//!    (`.NAME.RANDOM.tmp`, created exclusively, registered for removal on SIGINT, SIGTERM and
//!    SIGHUP), with the mode and (where allowed) owner of the file it will replace, and synced.
//!    An error here removes the temporaries: `DIR` is as it was.
//! 3. **Lock.** An exclusive advisory lock (`flock`) on `DIR` itself: a second rodimpact run
//!    writing into the same `DIR` waits until the first is done, so the two sets never
//!    interleave (the last run's set wins, whole). Other programs are not stopped by it. On a
//!    file system without `flock` on directories the run goes on unlocked.
//! 4. **Install.** Each temporary is renamed over its target (a previous target is exchanged
//!    atomically with it, so a failure part-way exchanges the earlier ones back), and only then
//!    are the previous contents removed. A catchable signal waits for this step to end.
//!
//! A target that is a symbolic link is replaced by the file (the link is not followed, unlike a
//! single `--out FILE`). SIGKILL during step 2 or 4 can leave hidden `.NAME.RANDOM.tmp` files
//! in `DIR`; it never leaves a half-written visible file.

use super::atomic::{self, Staged};
use crate::echo::echo_path;
use crate::error::{Error, ErrorKind};
use std::fs;
use std::path::Path;

fn io_error(field: &str, path: &Path, why: std::io::Error) -> Error {
    Error::io(field, format!("cannot write {}", echo_path(path)), why)
}

/// A directory this module will not write, and why (not an operating-system error).
fn refused(field: &str, path: &Path, why: &str) -> Error {
    Error::new(
        field,
        ErrorKind::Invalid(format!("cannot write {}: {why}", echo_path(path))),
    )
}

/// Writes `files` (name, contents) into `dir` all-or-nothing: either every file is in place, or
/// `dir` is left as it was. `dir` itself and every entry of it that `files` does not name are
/// never touched; see the module documentation for the steps, the lock and signals.
///
/// # Errors
/// `field: cannot write <path>: <reason>`: `dir` is not a directory, a target name is a
/// directory in it, `dir` is a planted link, or a file cannot be written.
///
/// # Examples
/// ```
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-outdir-{}", std::process::id()));
/// let files = [("a.md".to_string(), "new\n".to_string())];
/// rodimpact::io::write_directory("out", &dir, &files).unwrap();
/// std::fs::write(dir.join("notes.txt"), "mine").unwrap();
/// std::fs::create_dir(dir.join("b.md")).unwrap(); // in the way of the next run
/// let more = [("a.md".to_string(), "newer\n".to_string()), ("b.md".to_string(), "b\n".to_string())];
/// assert!(rodimpact::io::write_directory("out", &dir, &more).is_err());
/// assert_eq!(std::fs::read_to_string(dir.join("a.md")).unwrap(), "new\n"); // untouched
/// std::fs::remove_dir(dir.join("b.md")).unwrap();
/// rodimpact::io::write_directory("out", &dir, &more).unwrap();
/// assert_eq!(std::fs::read_to_string(dir.join("b.md")).unwrap(), "b\n");
/// assert_eq!(std::fs::read_to_string(dir.join("notes.txt")).unwrap(), "mine");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_directory(field: &str, dir: &Path, files: &[(String, String)]) -> Result<(), Error> {
    let fail = |path: &Path, why: std::io::Error| io_error(field, path, why);
    atomic::check_links(dir).map_err(|why| fail(dir, why))?;
    let created = match fs::metadata(dir) {
        Ok(meta) if meta.is_dir() => false,
        Ok(_) => return Err(refused(field, dir, "not a directory")),
        Err(why) if why.kind() == std::io::ErrorKind::NotFound => {
            fs::create_dir_all(dir).map_err(|why| fail(dir, why))?;
            atomic::register_directory(dir);
            true
        }
        Err(why) => return Err(fail(dir, why)),
    };
    let written = write_into(field, dir, files);
    if created {
        atomic::forget_directory(dir);
        if written.is_err() {
            // Only if still empty: another process may have written into it meanwhile.
            let _ = fs::remove_dir(dir);
        }
    }
    written
}

/// Steps 1-4 of the module documentation, into the existing directory `dir`.
fn write_into(field: &str, dir: &Path, files: &[(String, String)]) -> Result<(), Error> {
    check_targets(field, dir, files)?;
    let mut staged = stage(field, dir, files)?;
    let _lock = lock(dir).map_err(|why| io_error(field, dir, why))?;
    check_targets(field, dir, files)?;
    atomic::install(&mut staged).map_err(|(target, why)| io_error(field, &target, why))
}

/// Refuses a target name that exists in `dir` as anything but a regular file or a link.
fn check_targets(field: &str, dir: &Path, files: &[(String, String)]) -> Result<(), Error> {
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
    Ok(())
}

/// Writes every file into its temporary beside its target (step 2); on an error the ones
/// already written are removed as `staged` drops.
fn stage(field: &str, dir: &Path, files: &[(String, String)]) -> Result<Vec<Staged>, Error> {
    let mut staged = Vec::with_capacity(files.len());
    for (file, contents) in files {
        let target = dir.join(file);
        let previous = fs::symlink_metadata(&target)
            .ok()
            .filter(fs::Metadata::is_file);
        let one = Staged::write(&target, previous.as_ref(), contents.as_bytes())
            .map_err(|why| io_error(field, &target, plain(why)))?;
        staged.push(one);
    }
    Ok(staged)
}

/// `why` without the temporary path that `tempfile` appends to its errors (the user named the
/// target, not an internal hidden name).
fn plain(why: std::io::Error) -> std::io::Error {
    match why.raw_os_error() {
        Some(code) => std::io::Error::from_raw_os_error(code),
        None => why,
    }
}

/// Takes the exclusive advisory lock on `dir` (step 3), waiting for another holder; released
/// when the returned handle drops. `None` where the file system has no `flock` on directories.
#[cfg(unix)]
fn lock(dir: &Path) -> std::io::Result<Option<fs::File>> {
    use rustix::fs::{FlockOperation, flock};
    use rustix::io::Errno;
    let handle = fs::File::open(dir)?;
    loop {
        match flock(&handle, FlockOperation::LockExclusive) {
            Ok(()) => return Ok(Some(handle)),
            Err(Errno::INTR) => continue,
            Err(Errno::NOLCK | Errno::OPNOTSUPP | Errno::BADF | Errno::INVAL) => return Ok(None),
            Err(why) => return Err(why.into()),
        }
    }
}

#[cfg(not(unix))]
fn lock(_: &Path) -> std::io::Result<Option<fs::File>> {
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn scratch(tag: &str) -> PathBuf {
        tempfile::Builder::new()
            .prefix(&format!("rodimpact-outdir-{tag}-"))
            .tempdir()
            .unwrap()
            .keep()
    }

    /// Every entry of `dir` with its contents (a directory as `name/`), sorted.
    fn listing(dir: &Path) -> Vec<(String, String)> {
        let mut all: Vec<(String, String)> = fs::read_dir(dir)
            .unwrap()
            .map(|e| {
                let path = e.unwrap().path();
                let name = path.file_name().unwrap().to_string_lossy().into_owned();
                if path.is_dir() {
                    (format!("{name}/"), String::new())
                } else {
                    (name, fs::read_to_string(&path).unwrap())
                }
            })
            .collect();
        all.sort();
        all
    }

    fn set(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
        pairs
            .iter()
            .map(|(n, c)| (n.to_string(), c.to_string()))
            .collect()
    }

    /// The temporaries of a staged set are in the registry the signal handler empties, and only
    /// while they exist.
    #[test]
    fn staged_temporaries_are_registered_for_the_signal_handler() {
        let dir = scratch("registered");
        let files = set(&[("a.md", "a"), ("b.md", "b")]);
        let mut staged = stage("out", &dir, &files).unwrap();
        let hidden: Vec<PathBuf> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        assert_eq!(hidden.len(), 2);
        for path in &hidden {
            assert!(atomic::is_registered(path), "{}", path.display());
        }
        atomic::install(&mut staged).unwrap();
        for path in &hidden {
            assert!(!atomic::is_registered(path), "{}", path.display());
        }
        assert_eq!(listing(&dir), set(&[("a.md", "a"), ("b.md", "b")]));
        fs::remove_dir_all(&dir).unwrap();
    }

    /// A failure part-way through the renames (a directory appeared at the second name after
    /// the files were staged) puts the first file's previous contents back: the directory is as
    /// it was, with no temporary left.
    #[test]
    fn a_failure_while_installing_undoes_the_files_already_in_place() {
        let dir = scratch("undo");
        fs::write(dir.join("a.md"), "old a").unwrap();
        fs::write(dir.join("notes.txt"), "mine").unwrap();
        let files = set(&[("a.md", "new a"), ("n.md", "new n"), ("b.md", "new b")]);
        let mut staged = stage("out", &dir, &files).unwrap();
        fs::create_dir(dir.join("b.md")).unwrap();
        fs::write(dir.join("b.md/inside"), "kept").unwrap();
        let (target, why) = atomic::install(&mut staged).unwrap_err();
        assert_eq!(target, dir.join("b.md"));
        assert_eq!(why.kind(), std::io::ErrorKind::IsADirectory);
        drop(staged);
        let expected = set(&[("a.md", "old a"), ("b.md/", ""), ("notes.txt", "mine")]);
        assert_eq!(listing(&dir), expected);
        assert_eq!(fs::read_to_string(dir.join("b.md/inside")).unwrap(), "kept");
        fs::remove_dir_all(&dir).unwrap();
    }

    /// A missing directory is created; when the run fails it is removed again, as it was.
    #[test]
    fn a_directory_created_for_a_failing_run_is_removed() {
        let root = scratch("created");
        let dir = root.join("new");
        let files = set(&[("a.md", "a"), ("b/c.md", "no such subdirectory")]);
        let err = write_directory("out", &dir, &files)
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("out: cannot write "), "{err}");
        assert!(err.contains("b/c.md"), "{err}");
        assert!(!dir.exists());
        assert!(!atomic::is_registered(&dir));
        fs::remove_dir_all(&root).unwrap();
    }
}
