//! Directory outputs (`paper --out DIR`, `prove --write DIR`, `prove --export FORMAT DIR`) and
//! planted links: the findings G2, G8, G9 and G10 of the third hostile-input review.
//!
//! DIR is written in place, file by file (each staged beside its target, all staged before any
//! is renamed in), under an advisory lock on DIR: it keeps its inode, mode, owner and group, and
//! nothing this run did not write is moved or removed. Several tests hold that lock themselves,
//! so that a run stops, fully staged, exactly where the test wants it: no timing is involved.

use crate::common::{DEADLOCK, rodimpact, scratch};
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

fn hidden(dir: &Path) -> Vec<String> {
    names(dir)
        .into_iter()
        .filter(|n| n.starts_with('.'))
        .collect()
}

fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Takes the advisory lock rodimpact takes on an output directory; held until dropped.
fn hold_lock(dir: &Path) -> std::fs::File {
    let handle = std::fs::File::open(dir).unwrap();
    rustix::fs::flock(
        &handle,
        rustix::fs::FlockOperation::NonBlockingLockExclusive,
    )
    .expect("the directory is not locked yet");
    handle
}

/// Waits until the process `pid` is blocked waiting for a `flock` (a `->` line of
/// `/proc/locks`): it has staged every file and waits for the lock the test holds.
fn wait_until_blocked(child: &mut Child) {
    let pid = child.id().to_string();
    let start = Instant::now();
    loop {
        let locks = std::fs::read_to_string("/proc/locks").unwrap();
        let waiting = locks.lines().any(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            fields.get(1) == Some(&"->")
                && fields.get(2) == Some(&"FLOCK")
                && fields.get(5) == Some(&pid.as_str())
        });
        if waiting {
            return;
        }
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the run ended ({status:?}) without waiting for the directory's lock");
        }
        if start.elapsed() > DEADLOCK {
            child.kill().unwrap();
            panic!("the run never waited for the directory's lock");
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Regression (G2): `prove C1 --write V` moved every entry of V into a staging directory and
/// swapped the directories, so files another process created in V meanwhile were deleted
/// (hundreds of a writer's files, with exit 0). Now nothing the run did not write is touched.
#[test]
fn files_another_process_writes_into_dir_meanwhile_survive() {
    let dir = scratch("g2-writer");
    for i in 0..3000 {
        std::fs::write(dir.join(format!("old{i}")), "x").unwrap();
    }
    for _ in 0..3 {
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let writer = {
            let (dir, stop) = (dir.clone(), stop.clone());
            std::thread::spawn(move || {
                let mut created = Vec::new();
                let mut i = 0;
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    let name = format!("new{}-{i}", created.len() + i);
                    if std::fs::write(dir.join(&name), "w").is_ok() {
                        created.push(name);
                    }
                    i += 1;
                }
                created
            })
        };
        let (code, _, stderr) = rodimpact(&["prove", "C1", "--write", dir.to_str().unwrap()]);
        stop.store(true, std::sync::atomic::Ordering::Relaxed);
        let created = writer.join().unwrap();
        assert_eq!(code, 0, "{stderr}");
        let now = names(&dir);
        let lost: Vec<&String> = created
            .iter()
            .filter(|n| now.binary_search(n).is_err())
            .collect();
        assert!(
            lost.is_empty(),
            "{} of {} files lost: {:?}",
            lost.len(),
            created.len(),
            &lost[..lost.len().min(5)]
        );
        for i in 0..3000 {
            assert!(now.binary_search(&format!("old{i}")).is_ok(), "old{i} lost");
        }
        assert!(now.contains(&"C1.md".to_string()));
        assert!(hidden(&dir).is_empty(), "{:?}", hidden(&dir));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Regression (G8): the swap made a new DIR with the default mode, owned by whoever ran the
/// command: a 0700 directory became 0755 (its 0644 files readable by all), a setgid group
/// directory lost its group. Now DIR is never replaced: same inode, mode, owner, group, files.
#[test]
fn dir_keeps_its_inode_mode_owner_group_and_files() {
    let root = scratch("g8-mode");
    let runs: [&[&str]; 3] = [
        &["prove", "C1", "--write"],
        &["prove", "C1", "--export", "sympy"],
        &["paper", "--out"],
    ];
    let as_root = rustix::process::geteuid().is_root();
    for (i, run) in runs.iter().enumerate() {
        let dir = root.join(format!("d{i}"));
        std::fs::create_dir(&dir).unwrap();
        std::fs::write(dir.join("notes.txt"), "private\n").unwrap();
        let mode = if as_root {
            // Another owner and group, setgid: only root can set this up.
            std::os::unix::fs::chown(&dir, Some(65534), Some(65534)).unwrap();
            0o2770
        } else {
            0o700
        };
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(mode)).unwrap();
        let before = std::fs::metadata(&dir).unwrap();

        let mut args: Vec<&str> = run.to_vec();
        args.push(dir.to_str().unwrap());
        let (code, _, stderr) = rodimpact(&args);
        assert_eq!(code, 0, "{args:?}: {stderr}");

        let after = std::fs::metadata(&dir).unwrap();
        assert_eq!(after.ino(), before.ino(), "{args:?}: DIR replaced");
        assert_eq!(
            after.mode(),
            before.mode(),
            "{args:?}: mode {:o}",
            after.mode()
        );
        assert_eq!(
            (after.uid(), after.gid()),
            (before.uid(), before.gid()),
            "{args:?}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
            "private\n"
        );
        assert!(names(&dir).len() > 1, "{args:?}: nothing written");
        assert!(hidden(&dir).is_empty(), "{args:?}: {:?}", hidden(&dir));
    }
    // Nothing beside the directories (no staging or backup directory).
    assert_eq!(names(&root), ["d0", "d1", "d2"]);
    std::fs::remove_dir_all(&root).unwrap();
}

/// Regression (G2): two runs into one DIR (as `make -j` starts them) raced: one failed with
/// "Directory not empty", or both exited 0 while the other's file and the user's were deleted.
/// Now they serialise on DIR's lock. Both are held fully staged behind the test's own lock, then
/// released together: both succeed and every file of both (and the user's) is there.
#[test]
fn two_runs_into_one_dir_serialise_and_keep_every_file() {
    let dir = scratch("g2-two-runs");
    std::fs::write(dir.join("notes.txt"), "keep\n").unwrap();
    let lock = hold_lock(&dir);
    let path = dir.to_str().unwrap();
    let mut first = spawn(&["prove", "C1", "--write", path]);
    let mut second = spawn(&["prove", "C2", "--write", path]);
    wait_until_blocked(&mut first);
    wait_until_blocked(&mut second);
    // Both staged, neither installed while the lock is held.
    assert_eq!(hidden(&dir).len(), 2, "{:?}", names(&dir));
    assert_eq!(names(&dir).len(), 3, "{:?}", names(&dir));
    drop(lock);
    for child in [first, second] {
        let out = child.wait_with_output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    assert_eq!(names(&dir), ["C1.md", "C2.md", "notes.txt"]);
    assert_eq!(
        std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
        "keep\n"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Regression (G9): SIGINT, SIGTERM or SIGHUP during a directory output left the hidden staging
/// directory `.DIR.tmp-*` (with part of the user's files moved into it). Each run here is
/// stopped with every file staged (it waits for the lock the test holds), then signalled: it
/// ends by the signal, and DIR holds exactly the user's files, nothing hidden.
#[test]
fn a_signal_while_staged_leaves_dir_as_it_was() {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let ignored = status
        .lines()
        .find_map(|line| line.strip_prefix("SigIgn:"))
        .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok())
        .unwrap_or(0);
    let root = scratch("g9-signals");
    let cases: [(&str, i32, &[&str]); 3] = [
        ("INT", 2, &["paper", "--out"]),
        ("TERM", 15, &["prove", "--export", "sympy"]),
        ("HUP", 1, &["prove", "--write"]),
    ];
    for (signal, number, run) in cases {
        if ignored & (1 << (number - 1)) != 0 {
            eprintln!("SIG{signal} is ignored by this test process (inherited): not tested");
            continue;
        }
        let dir = root.join(signal);
        std::fs::create_dir(&dir).unwrap();
        for i in 0..200 {
            std::fs::write(dir.join(format!("mine{i}")), "x").unwrap();
        }
        std::fs::write(dir.join("README.md"), "the previous index\n").unwrap();
        let before = names(&dir);
        let lock = hold_lock(&dir);
        let mut args = run.to_vec();
        args.push(dir.to_str().unwrap());
        let mut child = spawn(&args);
        wait_until_blocked(&mut child);
        assert!(
            hidden(&dir).len() > 5,
            "SIG{signal}: staged {:?}",
            hidden(&dir)
        );
        let sent = Command::new("kill")
            .args([format!("-{signal}"), child.id().to_string()])
            .status()
            .unwrap();
        assert!(sent.success());
        let status = child.wait().unwrap();
        drop(lock);
        assert!(
            status.signal() == Some(number) || status.code() == Some(128 + number),
            "SIG{signal}: {status:?}"
        );
        assert_eq!(names(&dir), before, "SIG{signal}");
        assert_eq!(
            std::fs::read_to_string(dir.join("README.md")).unwrap(),
            "the previous index\n"
        );
    }
    assert_eq!(
        names(&root).len(),
        3 - cases
            .iter()
            .filter(|c| ignored & (1 << (c.1 - 1)) != 0)
            .count()
    );
    std::fs::remove_dir_all(&root).unwrap();
}

/// Regression (G10): a symbolic link planted in a shared sticky directory (`/tmp`) by another
/// user was followed, and the file it points at replaced (the classic /tmp link attack; the
/// kernel's `fs.protected_symlinks` never sees a link rodimpact resolves itself). Now such a
/// link is refused with exit 2, naming the path and the rule, for a single `--out FILE` and for
/// a directory output; a link of the caller's own, or of the directory's owner, is followed as
/// before. Creating a link owned by another user needs root: otherwise the CLI part is skipped
/// (the rule itself, `rodimpact::io::may_follow_link`, is tested in its documentation).
#[test]
fn a_link_planted_in_a_sticky_shared_directory_is_refused() {
    use std::os::unix::fs::{lchown, symlink};
    if !rustix::process::geteuid().is_root() {
        eprintln!("not root: cannot plant a link owned by another user; not tested");
        return;
    }
    let root = scratch("g10-planted");
    let shared = root.join("shared");
    std::fs::create_dir(&shared).unwrap();
    std::fs::set_permissions(&shared, std::fs::Permissions::from_mode(0o1777)).unwrap();
    let secret = root.join("secret");
    std::fs::write(&secret, "secret\n").unwrap();
    let victim = root.join("victim");
    std::fs::create_dir(&victim).unwrap();
    let (file_link, dir_link) = (shared.join("out.csv"), shared.join("certs"));
    symlink(&secret, &file_link).unwrap();
    symlink(&victim, &dir_link).unwrap();
    for link in [&file_link, &dir_link] {
        lchown(link, Some(65534), Some(65534)).unwrap();
    }

    let runs: [(&Path, &[&str]); 2] = [
        (&file_link, &["scenes", "--suite", "engines", "--out"]),
        (&dir_link, &["prove", "C1", "--write"]),
    ];
    for (link, run) in runs {
        let mut args = run.to_vec();
        args.push(link.to_str().unwrap());
        let (code, stdout, stderr) = rodimpact(&args);
        let field = if run[0] == "scenes" { "out" } else { "write" };
        assert_eq!(code, 2, "{args:?}: {stdout}{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(
            stderr.starts_with(&format!(
                "error: {field}: cannot write {}: ",
                link.display()
            )),
            "{stderr}"
        );
        assert!(
            stderr.contains("sticky world-writable directory, owned by uid 65534")
                && stderr.contains("fs.protected_symlinks"),
            "{stderr}"
        );
    }
    assert_eq!(std::fs::read_to_string(&secret).unwrap(), "secret\n");
    assert!(names(&victim).is_empty());
    assert_eq!(names(&shared), ["certs", "out.csv"]);

    // The directory's owner's link is followed (the kernel's rule), and so is the caller's own.
    std::os::unix::fs::chown(&shared, Some(65534), Some(65534)).unwrap();
    let (code, _, stderr) = rodimpact(&["prove", "C1", "--write", dir_link.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(names(&victim), ["C1.md"]);
    std::os::unix::fs::chown(&shared, Some(0), Some(0)).unwrap();
    lchown(&file_link, Some(0), Some(0)).unwrap();
    let (code, _, stderr) = rodimpact(&[
        "scenes",
        "--suite",
        "engines",
        "--out",
        file_link.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(std::fs::read_to_string(&secret).unwrap().starts_with("id,"));
    assert!(
        std::fs::symlink_metadata(&file_link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    std::fs::remove_dir_all(&root).unwrap();
}
