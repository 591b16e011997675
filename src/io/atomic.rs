//! Writing output files so that no reader ever sees a half-written one, and no planted link or
//! special file is clobbered.
//!
//! A regular target (or a new one) is written into a temporary file in the target's directory
//! and renamed over it when complete. The temporary file is created exclusively (`O_EXCL`,
//! never through an existing name or link) under an unpredictable name, `.<name>.<random>.tmp`
//! with at most 32 bytes of the target's name, so a legal 255-byte name still fits. A final
//! symbolic link is resolved first and its target replaced, so the link stays a link, unless it
//! was planted in a shared sticky directory by another user ([`may_follow_link`]). The
//! replaced file keeps its permission bits (and, where the system allows, its owner and group).
//!
//! A target that is not a regular file (a character device such as `/dev/null`, a FIFO, a
//! descriptor such as `/dev/stdout` or the `/dev/fd/63` of `>(gzip > x.gz)`) is written in place:
//! no atomicity is possible there, and replacing the node would destroy it.
//!
//! Temporary files are registered while they exist; after [`remove_temporaries_on_signals`],
//! SIGINT, SIGTERM and SIGHUP remove them before the process ends (SIGKILL cannot be caught).

use crate::echo::echo_path;
use crate::error::Error;
use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// Writes `contents` to `path` as [`AtomicFile`] does: a regular file (or a new one) atomically,
/// a device, FIFO or descriptor in place. An interrupted or failing run leaves a previous file
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
/// rodimpact::io::write_atomic("out", &path, "hello\n").unwrap();
/// assert_eq!(std::fs::read_to_string(&path).unwrap(), "hello\n");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn write_atomic(field: &str, path: &Path, contents: &str) -> Result<(), Error> {
    write_atomic_bytes(field, path, contents.as_bytes())
}

/// [`write_atomic`] for bytes (a PNG): all of `contents` or nothing, at `path`.
///
/// # Errors
/// As [`write_atomic`].
///
/// # Examples
/// ```
/// let dir = tempfile::tempdir().unwrap();
/// let path = dir.path().join("x.bin");
/// rodimpact::io::write_atomic_bytes("out", &path, &[0, 159, 255])?;
/// assert_eq!(std::fs::read(&path).unwrap(), [0, 159, 255]);
/// # Ok::<(), rodimpact::Error>(())
/// ```
pub fn write_atomic_bytes(field: &str, path: &Path, contents: &[u8]) -> Result<(), Error> {
    let mut file = AtomicFile::create(field, path)?;
    file.write_all(contents)
        .map_err(|why| io_error(field, path, why))?;
    file.commit()
}

/// An output file written as a stream, atomically: the bytes go to a temporary file in the
/// target's directory, which [`AtomicFile::commit`] flushes and renames over the target. If it is
/// dropped without a commit (an error, a panic), the temporary file is removed and the target
/// is untouched. A target that is not a regular file (a device, a FIFO, `/dev/stdout`) is
/// written in place instead, as the module documentation explains.
///
/// # Examples
/// ```
/// use std::io::Write;
/// let dir = std::env::temp_dir().join(format!("rodimpact-doc-atomic-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("rows.csv");
/// let mut out = rodimpact::io::AtomicFile::create("out", &path).unwrap();
/// out.write_all(b"a,b\n").unwrap();
/// assert!(!path.exists()); // nothing visible before the commit
/// out.commit().unwrap();
/// assert_eq!(std::fs::read_to_string(&path).unwrap(), "a,b\n");
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub struct AtomicFile {
    field: String,
    /// The path as given, for messages.
    path: PathBuf,
    sink: Sink,
}

enum Sink {
    /// A temporary file beside the (resolved) regular target, renamed over it on commit.
    Replace {
        target: PathBuf,
        /// The previous target's metadata, whose mode (and owner) the new file takes.
        previous: Option<Box<fs::Metadata>>,
        /// `None` once committed or removed.
        temporary: Option<BufWriter<tempfile::NamedTempFile>>,
    },
    /// A device, FIFO or descriptor, written in place.
    InPlace(BufWriter<fs::File>),
}

impl AtomicFile {
    /// Opens the temporary file beside `path` (or `path` itself when it is a device, a FIFO or a
    /// descriptor).
    ///
    /// # Errors
    /// `field: cannot write <path>: <reason>`.
    ///
    /// # Examples
    /// ```
    /// let err = rodimpact::io::AtomicFile::create("out", "/nonexistent/x.csv".as_ref());
    /// assert!(err.err().unwrap().to_string().starts_with("out: cannot write /nonexistent/x.csv"));
    /// ```
    pub fn create(field: &str, path: &Path) -> Result<AtomicFile, Error> {
        let fail = |why| io_error(field, path, why);
        let sink = match resolve(path).map_err(fail)? {
            Target::InPlace(node) => {
                let file = fs::OpenOptions::new()
                    .write(true)
                    .truncate(node.is_file())
                    .open(path)
                    .map_err(fail)?;
                Sink::InPlace(BufWriter::new(file))
            }
            Target::Replace { target, previous } => {
                let temporary = create_temporary(&target, previous.as_ref()).map_err(fail)?;
                Sink::Replace {
                    target,
                    previous: previous.map(Box::new),
                    temporary: Some(BufWriter::new(temporary)),
                }
            }
        };
        Ok(AtomicFile {
            field: field.to_string(),
            path: path.to_path_buf(),
            sink,
        })
    }

    /// Flushes the data to disk and renames the temporary file over the target (or, for a
    /// device, FIFO or descriptor, flushes what was written in place).
    ///
    /// # Errors
    /// `field: cannot write <path>: <reason>` (the temporary file is then removed).
    ///
    /// # Examples
    /// ```
    /// use std::io::Write;
    /// let dir = std::env::temp_dir().join(format!("rodimpact-doc-commit-{}", std::process::id()));
    /// std::fs::create_dir_all(&dir).unwrap();
    /// let mut dropped = rodimpact::io::AtomicFile::create("out", &dir.join("a.csv")).unwrap();
    /// dropped.write_all(b"x").unwrap();
    /// drop(dropped); // no commit: nothing left behind
    /// assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    /// # std::fs::remove_dir_all(&dir).unwrap();
    /// ```
    pub fn commit(mut self) -> Result<(), Error> {
        let done = match &mut self.sink {
            Sink::InPlace(file) => file.flush(),
            Sink::Replace {
                target,
                previous,
                temporary,
            } => {
                let writer = temporary.take().expect("open until committed");
                persist(writer, target, previous.as_deref())
            }
        };
        done.map_err(|why| io_error(&self.field, &self.path, why))
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.sink {
            Sink::InPlace(file) => file.write(buf),
            Sink::Replace { temporary, .. } => {
                temporary.as_mut().expect("open until committed").write(buf)
            }
        }
    }
    fn flush(&mut self) -> io::Result<()> {
        match &mut self.sink {
            Sink::InPlace(file) => file.flush(),
            Sink::Replace { temporary, .. } => {
                temporary.as_mut().expect("open until committed").flush()
            }
        }
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if let Sink::Replace { temporary, .. } = &mut self.sink
            && let Some(writer) = temporary.take()
        {
            // Unflushed bytes are dropped with the file; it is removed (by its own drop) and
            // forgotten under the lock, so a signal handler never misses it.
            let (file, _unwritten) = writer.into_parts();
            let path = file.path().to_path_buf();
            let mut live = temporaries();
            drop(file);
            live.retain(|p| *p != path);
        }
    }
}

fn io_error(field: &str, path: &Path, why: io::Error) -> Error {
    Error::io(field, format!("cannot write {}", echo_path(path)), why)
}

/// Where the bytes for an output path go.
#[derive(Debug)]
enum Target {
    /// A regular file (existing or not) at this resolved path, replaced by rename.
    Replace {
        target: PathBuf,
        previous: Option<fs::Metadata>,
    },
    /// A device, FIFO or descriptor (its metadata, through any link), written in place.
    InPlace(fs::Metadata),
}

/// The most symbolic links followed for one output path (as Linux's ELOOP limit).
const MAX_LINKS: usize = 40;

/// Decides where `path`'s bytes go. A symbolic link is followed to its target (a dangling link
/// to the file it names); a link under `/proc` (`/dev/stdout` and `/dev/fd/N` lead there) names
/// an open descriptor, which is written in place like a device.
fn resolve(path: &Path) -> io::Result<Target> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        let meta = match fs::symlink_metadata(&current) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                return Ok(Target::Replace {
                    target: current,
                    previous: None,
                });
            }
            other => other?,
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            if is_descriptor_link(&current) {
                return Ok(Target::InPlace(fs::metadata(path)?));
            }
            refuse_planted_link(path, &current, &meta)?;
            let link = fs::read_link(&current)?;
            current = directory_of(&current).join(link);
        } else if kind.is_dir() {
            return Err(io::Error::from(io::ErrorKind::IsADirectory));
        } else if kind.is_file() {
            return Ok(Target::Replace {
                target: current,
                previous: Some(meta),
            });
        } else {
            return Ok(Target::InPlace(meta));
        }
    }
    Err(io::Error::other(format!(
        "more than {MAX_LINKS} symbolic links"
    )))
}

/// Whether the kernel's `fs.protected_symlinks` rule lets `follower` follow a link owned by
/// `link_owner` in a directory of mode `dir_mode` owned by `dir_owner`: a link in a sticky,
/// world-writable directory (`/tmp`) is followed only by its owner or when the directory's owner
/// owns it too. Anyone else following it is the classic planted-link attack: the link makes the
/// victim's write land on a file of the attacker's choosing.
///
/// rodimpact follows an output path's final links itself (to replace the target and keep the
/// link), which the kernel's own check never sees, so it applies the same rule whatever the
/// sysctl says.
///
/// # Examples
/// ```
/// use rodimpact::io::may_follow_link;
/// let tmp = 0o41777; // a sticky, world-writable directory (as /tmp), owned by root (0)
/// assert!(may_follow_link(tmp, 0, 1000, 1000)); // my own link
/// assert!(may_follow_link(tmp, 0, 0, 1000)); // the directory owner's link
/// assert!(!may_follow_link(tmp, 0, 65534, 1000)); // planted by another user
/// assert!(!may_follow_link(tmp, 0, 65534, 0)); // not even for root
/// assert!(may_follow_link(0o40777, 0, 65534, 1000)); // world-writable, not sticky
/// assert!(may_follow_link(0o41775, 0, 65534, 1000)); // sticky, not world-writable
/// ```
pub fn may_follow_link(dir_mode: u32, dir_owner: u32, link_owner: u32, follower: u32) -> bool {
    let shared = dir_mode & 0o1002 == 0o1002;
    !shared || link_owner == follower || link_owner == dir_owner
}

/// Refuses to follow the link at `link` (met while resolving the output path `path`) when
/// [`may_follow_link`] forbids it.
#[cfg(unix)]
fn refuse_planted_link(path: &Path, link: &Path, meta: &fs::Metadata) -> io::Result<()> {
    use std::os::unix::fs::MetadataExt;
    let dir = fs::metadata(directory_of(link))?;
    let me = rustix::process::geteuid().as_raw();
    if may_follow_link(dir.mode(), dir.uid(), meta.uid(), me) {
        return Ok(());
    }
    let which = if link == path {
        String::from("it is a symbolic link")
    } else {
        format!("{} is a symbolic link", echo_path(link))
    };
    Err(io::Error::other(format!(
        "{which} in a sticky world-writable directory, owned by uid {}, neither yours nor the \
         directory's owner's: not followed (the rule of the kernel's fs.protected_symlinks)",
        meta.uid()
    )))
}

#[cfg(not(unix))]
fn refuse_planted_link(_: &Path, _: &Path, _: &fs::Metadata) -> io::Result<()> {
    Ok(())
}

/// Follows `path`'s final symbolic links (as [`resolve`] does, at most [`MAX_LINKS`]) only to
/// refuse a planted one; the caller then lets the kernel follow them. Used for the directory of
/// `paper --out DIR`.
pub(super) fn check_links(path: &Path) -> io::Result<()> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&current) {
            Ok(meta) if meta.file_type().is_symlink() => {
                refuse_planted_link(path, &current, &meta)?;
                let link = fs::read_link(&current)?;
                current = directory_of(&current).join(link);
            }
            _ => return Ok(()),
        }
    }
    Err(io::Error::other(format!(
        "more than {MAX_LINKS} symbolic links"
    )))
}

/// The directory holding `path`'s last component (`.` for a bare name).
fn directory_of(path: &Path) -> &Path {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    }
}

/// A link in `/proc` (`/proc/self/fd/1`): it names an open descriptor, not a path to replace.
fn is_descriptor_link(link: &Path) -> bool {
    fs::canonicalize(directory_of(link)).is_ok_and(|dir| dir.starts_with("/proc"))
}

/// How many bytes of the target's name the temporary file's name repeats.
const NAME_BYTES: usize = 32;

/// Creates the temporary file beside `target`, exclusively, under a random name, registered
/// for removal on a signal. Its mode is the previous target's (a new file gets 0666 less the
/// umask, as any new file), never more open than that while the data is written.
fn create_temporary(
    target: &Path,
    previous: Option<&fs::Metadata>,
) -> io::Result<tempfile::NamedTempFile> {
    let name = target.file_name().unwrap_or_default().to_string_lossy();
    let mut cut = NAME_BYTES.min(name.len());
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    let prefix = format!(".{}.", &name[..cut]);
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp").rand_bytes(8);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = previous.map_or(0o666, |m| m.permissions().mode() & 0o777);
        builder.permissions(fs::Permissions::from_mode(mode));
    }
    #[cfg(not(unix))]
    let _ = previous;
    // Created and registered under the lock, so a signal handler that holds it sees every
    // temporary file that exists.
    let mut live = temporaries();
    let file = builder.tempfile_in(directory_of(target))?;
    live.push(file.path().to_path_buf());
    Ok(file)
}

/// Flushes and syncs the temporary file, gives it the previous target's owner and mode, and
/// renames it over `target`; on failure it is removed.
fn persist(
    writer: BufWriter<tempfile::NamedTempFile>,
    target: &Path,
    previous: Option<&fs::Metadata>,
) -> io::Result<()> {
    let path = writer.get_ref().path().to_path_buf();
    let mut live = temporaries();
    live.retain(|p| *p != path);
    let file = writer.into_inner().map_err(|e| e.into_error())?;
    finish(&file, previous)?;
    file.persist(target).map(drop).map_err(|e| e.error)
}

/// Gives the complete temporary file the previous target's owner and mode, and syncs it.
fn finish(file: &tempfile::NamedTempFile, previous: Option<&fs::Metadata>) -> io::Result<()> {
    #[cfg(unix)]
    if let Some(previous) = previous {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        // The owner first (changing it clears set-id bits); only root may give a file away,
        // so a failure leaves the file to whoever runs the command, as any new file.
        let _ =
            std::os::unix::fs::fchown(file.as_file(), Some(previous.uid()), Some(previous.gid()));
        let mode = previous.permissions().mode() & 0o7777;
        file.as_file()
            .set_permissions(fs::Permissions::from_mode(mode))?;
    }
    #[cfg(not(unix))]
    let _ = previous;
    file.as_file().sync_all()
}

/// One file of a set (`paper --out DIR`), complete and synced in its registered temporary beside
/// its target, not yet in place: [`install`] renames the whole set in. Dropped uninstalled, the
/// temporary file is removed.
pub(super) struct Staged {
    target: PathBuf,
    /// `None` once installed (or given back by a failed install, which removes it).
    temporary: Option<tempfile::TempPath>,
}

impl Staged {
    /// Writes `contents` into a new temporary beside `target` (exclusively created, registered
    /// for removal on a signal), with the mode and, where allowed, the owner of `previous` (the
    /// regular file it will replace), and syncs it.
    pub(super) fn write(
        target: &Path,
        previous: Option<&fs::Metadata>,
        contents: &[u8],
    ) -> io::Result<Staged> {
        let mut file = create_temporary(target, previous)?;
        let written = file
            .write_all(contents)
            .and_then(|()| finish(&file, previous));
        if let Err(why) = written {
            let path = file.path().to_path_buf();
            let mut live = temporaries();
            drop(file);
            live.retain(|p| *p != path);
            return Err(why);
        }
        Ok(Staged {
            target: target.to_path_buf(),
            temporary: Some(file.into_temp_path()),
        })
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if let Some(temporary) = self.temporary.take() {
            let path = temporary.to_path_buf();
            let mut live = temporaries();
            drop(temporary);
            live.retain(|p| *p != path);
        }
    }
}

/// How one staged file was put in place, so that a later failure can undo it.
enum Placed {
    /// The target did not exist: renamed in; undone by removing it.
    New,
    /// The previous entry was exchanged with the new file and now sits at the temporary name;
    /// undone by exchanging back.
    Exchanged,
    /// The previous file was replaced by a plain rename (a system without an atomic exchange):
    /// cannot be undone.
    Replaced,
}

/// Puts every staged file in place, all or nothing as far as the system allows: a previous
/// target is atomically exchanged with its new file (Linux `renameat2(RENAME_EXCHANGE)`), so
/// that if a later file fails, every earlier one is exchanged back and the directory is as it
/// was. The old contents are removed only once all are in. Where the exchange is not supported,
/// a plain rename replaces the target, and that file cannot be undone.
///
/// The registry of temporaries is held throughout: a signal waits until the set is in place (or
/// undone), then removes what is left, so it never leaves half a set.
///
/// # Errors
/// The target that failed, and why.
pub(super) fn install(staged: &mut [Staged]) -> Result<(), (PathBuf, io::Error)> {
    let mut live = temporaries();
    let mut placed: Vec<(usize, Placed)> = Vec::new();
    let mut failure = None;
    for (i, file) in staged.iter().enumerate() {
        let temporary = file.temporary.as_deref().expect("staged until installed");
        match place(temporary, &file.target) {
            Ok(how) => placed.push((i, how)),
            Err(why) => {
                failure = Some((file.target.clone(), why));
                break;
            }
        }
    }
    if failure.is_some() {
        for (i, how) in placed.iter().rev() {
            let file = &staged[*i];
            let temporary = file.temporary.as_deref().expect("staged until installed");
            let _ = match how {
                Placed::New => fs::remove_file(&file.target),
                Placed::Exchanged => exchange(temporary, &file.target),
                Placed::Replaced => Ok(()),
            };
        }
    }
    for (i, file) in staged.iter_mut().enumerate() {
        let temporary = file.temporary.take().expect("staged until installed");
        let path = temporary.to_path_buf();
        // Renamed into place: its temporary name no longer exists.
        let kept = failure.is_none() && !matches!(placed[i].1, Placed::Exchanged);
        if kept {
            let _ = temporary.keep();
        } else {
            // The old contents after an exchange, or a file never placed (or undone).
            drop(temporary);
        }
        live.retain(|p| *p != path);
    }
    match failure {
        Some(failure) => Err(failure),
        None => Ok(()),
    }
}

/// Puts the complete `temporary` at `target`.
fn place(temporary: &Path, target: &Path) -> io::Result<Placed> {
    let Ok(before) = fs::symlink_metadata(target) else {
        fs::rename(temporary, target)?;
        return Ok(Placed::New);
    };
    if before.is_dir() {
        return Err(io::Error::from(io::ErrorKind::IsADirectory));
    }
    match exchange(temporary, target) {
        Ok(()) => {
            // A directory that appeared at the name since the check goes back where it was.
            if fs::symlink_metadata(temporary).is_ok_and(|m| m.is_dir()) {
                exchange(temporary, target)?;
                return Err(io::Error::from(io::ErrorKind::IsADirectory));
            }
            Ok(Placed::Exchanged)
        }
        Err(why) if why.kind() == io::ErrorKind::Unsupported => {
            fs::rename(temporary, target)?;
            Ok(Placed::Replaced)
        }
        Err(why) => Err(why),
    }
}

/// Atomically exchanges the entries at `a` and `b` (both must exist); `Unsupported` where the
/// system or file system cannot.
#[cfg(any(target_os = "linux", target_os = "android"))]
fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    use rustix::fs::{CWD, RenameFlags, renameat_with};
    match renameat_with(CWD, a, CWD, b, RenameFlags::EXCHANGE) {
        Ok(()) => Ok(()),
        Err(rustix::io::Errno::NOSYS | rustix::io::Errno::INVAL | rustix::io::Errno::OPNOTSUPP) => {
            Err(io::Error::from(io::ErrorKind::Unsupported))
        }
        Err(why) => Err(why.into()),
    }
}

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn exchange(_: &Path, _: &Path) -> io::Result<()> {
    Err(io::Error::from(io::ErrorKind::Unsupported))
}

/// Registers `path`, a directory this run created for its outputs, for removal on a signal
/// (only while it is empty: the handler never removes what it holds).
pub(super) fn register_directory(path: &Path) {
    temporaries().insert(0, path.to_path_buf());
}

/// Whether `path` is registered for removal on a signal (for tests).
#[cfg(test)]
pub(super) fn is_registered(path: &Path) -> bool {
    temporaries().iter().any(|p| p == path)
}

/// Forgets a path registered with [`register_directory`].
pub(super) fn forget_directory(path: &Path) {
    temporaries().retain(|p| p != path);
}

/// The temporary files that exist now.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARIES.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Makes SIGINT, SIGTERM and SIGHUP remove every temporary output file before the process
/// ends; it then ends by the same signal (exit status 130, 143 or 129 in a shell). Called once
/// by the command-line tool at start; later calls do nothing.
///
/// # Errors
/// `signal: ...` when the handlers cannot be installed.
///
/// Only with the feature `signals` (part of `cli`, the default): a program embedding the library
/// where its host owns the signals (Python, a browser) leaves it out.
///
/// # Examples
/// ```
/// rodimpact::io::remove_temporaries_on_signals().unwrap();
/// rodimpact::io::remove_temporaries_on_signals().unwrap(); // once is enough
/// ```
#[cfg(feature = "signals")]
pub fn remove_temporaries_on_signals() -> Result<(), Error> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    use std::sync::OnceLock;
    static INSTALLED: OnceLock<Result<(), String>> = OnceLock::new();
    INSTALLED
        .get_or_init(|| {
            // A signal the process was started with ignored (`nohup` ignores SIGHUP, a shell
            // ignores SIGINT for background jobs) stays ignored.
            let ignored = ignored_signals();
            let caught = [SIGINT, SIGTERM, SIGHUP]
                .into_iter()
                .filter(|&s| ignored & (1 << (s - 1)) == 0);
            let mut signals =
                signal_hook::iterator::Signals::new(caught).map_err(|e| e.to_string())?;
            std::thread::Builder::new()
                .name("signal clean-up".into())
                .spawn(move || {
                    if let Some(signal) = signals.forever().next() {
                        // Held until the end: no temporary file appears after the clean-up.
                        let live = temporaries();
                        // Newest first: temporary files, then a directory the run created
                        // for them, removed only if empty (never anything else in it).
                        for path in live.iter().rev() {
                            let _ = fs::remove_file(path).or_else(|_| fs::remove_dir(path));
                        }
                        let _ = signal_hook::low_level::emulate_default_handler(signal);
                        std::process::exit(128 + signal);
                    }
                })
                .map(drop)
                .map_err(|e| e.to_string())
        })
        .clone()
        .map_err(|why| Error::io("signal", "", io::Error::other(why)))
}

#[cfg(feature = "signals")]
/// The signals this process ignores, as a mask (bit n-1 for signal n), from the `SigIgn` line
/// of `/proc/self/status`; none where that cannot be read.
fn ignored_signals() -> u64 {
    let status = fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|line| line.strip_prefix("SigIgn:"))
        .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("rodimpact-files-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn temporary_names_are_short_hidden_and_unpredictable() {
        let dir = scratch("names");
        let long = "n".repeat(255);
        let a = AtomicFile::create("out", &dir.join(&long)).unwrap();
        let b = AtomicFile::create("out", &dir.join(&long)).unwrap();
        let listed = names(&dir);
        assert_eq!(listed.len(), 2);
        for name in &listed {
            assert!(name.starts_with(&format!(".{}.", "n".repeat(32))), "{name}");
            assert!(
                name.ends_with(".tmp") && name.len() == 1 + 32 + 1 + 8 + 4,
                "{name}"
            );
        }
        assert_ne!(listed[0], listed[1]);
        drop((a, b));
        assert!(names(&dir).is_empty());
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_directory_is_refused_and_a_missing_one_named() {
        let dir = scratch("dir");
        let err = write_atomic("out", &dir, "x").unwrap_err().to_string();
        assert!(err.starts_with("out: cannot write "), "{err}");
        assert!(
            err.contains("is a directory") || err.contains("Is a directory"),
            "{err}"
        );
        let missing = dir.join("no/such/x.csv");
        let err = write_atomic("out", &missing, "x").unwrap_err().to_string();
        assert!(err.contains("No such file or directory"), "{err}");
        assert!(names(&dir).is_empty());
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_link_loop_is_refused() {
        let dir = scratch("loop");
        std::os::unix::fs::symlink("b", dir.join("a")).unwrap();
        std::os::unix::fs::symlink("a", dir.join("b")).unwrap();
        let err = write_atomic("out", &dir.join("a"), "x")
            .unwrap_err()
            .to_string();
        assert!(err.contains("symbolic links"), "{err}");
        fs::remove_dir_all(&dir).unwrap();
    }
}
