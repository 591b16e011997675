//! The output-path logic (`io::write_atomic`, as `--out` uses it): a scratch directory of
//! files (with modes), directories and symbolic links (relative, absolute, dangling, looping,
//! through a linked directory, names of 255 bytes or with control characters) built from the
//! input, then one write to a chosen name. Whatever happens: an error is one inert line naming
//! `out`; no temporary file is left; every link and directory stays as it was; at most one
//! regular file changes, the one the path leads to; on success the path reads back as written,
//! with the previous file's mode.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::collections::BTreeMap;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

/// What a directory entry is, not following links.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Entry {
    File(Vec<u8>, u32),
    Dir,
    Link(PathBuf),
}

fn names(long: &str) -> [String; 9] {
    [
        "a".into(),
        "b".into(),
        "c".into(),
        "sub".into(),
        "sub/a".into(),
        "sub/b".into(),
        long.into(),
        "x\ny\u{1b}".into(),
        "link-dir/a".into(),
    ]
}

fn snapshot(root: &Path) -> BTreeMap<PathBuf, Entry> {
    let mut all = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let meta = std::fs::symlink_metadata(&path).unwrap();
            let rel = path.strip_prefix(root).unwrap().to_path_buf();
            let kind = if meta.file_type().is_symlink() {
                Entry::Link(std::fs::read_link(&path).unwrap())
            } else if meta.is_dir() {
                stack.push(path.clone());
                Entry::Dir
            } else {
                Entry::File(std::fs::read(&path).unwrap(), meta.permissions().mode())
            };
            all.insert(rel, kind);
        }
    }
    all
}

/// The end of `path`'s chain of final links (at most 40), its directory made canonical.
fn chain_end(path: &Path) -> Option<PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&current) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let link = std::fs::read_link(&current).ok()?;
                current = current.parent()?.join(link);
            }
            _ => {
                let dir = std::fs::canonicalize(current.parent()?).ok()?;
                return Some(dir.join(current.file_name()?));
            }
        }
    }
    None
}

fuzz_target!(|data: &[u8]| {
    let root = std::env::temp_dir().join(format!("rodimpact-fuzz-out-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("sub")).unwrap();
    let root = std::fs::canonicalize(&root).unwrap();
    let long = "L".repeat(255);
    let names = names(&long);
    // The first byte: how many entries (up to 12), each three bytes (kind, name, argument);
    // then the name to write to, then the contents.
    let Some((&count, rest)) = data.split_first() else {
        return;
    };
    let ops = usize::from(count % 13).min(rest.len() / 3);
    for op in rest[..3 * ops].chunks(3) {
        let (kind, name, arg) = (op[0], op[1], op[2]);
        let path = root.join(&names[usize::from(name) % names.len()]);
        if std::fs::symlink_metadata(&path).is_ok() {
            continue;
        }
        let _ = match kind % 4 {
            0 => std::fs::write(&path, [arg]).and_then(|()| {
                let mode = [0o600, 0o644, 0o640, 0o444, 0o755][usize::from(arg) % 5];
                std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode))
            }),
            1 => std::fs::create_dir(&path),
            2 => {
                // Relative, absolute, dangling, a directory, itself.
                let target = match arg % 6 {
                    0 => PathBuf::from(&names[usize::from(arg / 6) % names.len()]),
                    1 => root.join(&names[usize::from(arg / 6) % names.len()]),
                    2 => PathBuf::from("missing"),
                    3 => PathBuf::from("sub"),
                    4 => path.file_name().map(PathBuf::from).unwrap_or_default(),
                    _ => PathBuf::from("sub/../b"),
                };
                std::os::unix::fs::symlink(target, &path)
            }
            _ => std::os::unix::fs::symlink("sub", root.join("link-dir")),
        };
    }
    let chosen = rest.get(3 * ops).copied().unwrap_or(0);
    let target = root.join(&names[usize::from(chosen) % names.len()]);
    let contents = String::from_utf8_lossy(rest.get(3 * ops + 1..).unwrap_or(&[])).into_owned();

    let before = snapshot(&root);
    let end = chain_end(&target);
    let written = rodimpact::io::write_atomic("out", &target, &contents);
    let after = snapshot(&root);

    match &written {
        Ok(()) => {
            assert_eq!(std::fs::read_to_string(&target).unwrap(), contents);
        }
        Err(e) => {
            let line = e.to_string();
            assert!(line.starts_with("out: cannot write "), "{line}");
            assert!(!line.chars().any(char::is_control), "{line:?}");
        }
    }
    let end_rel = end.as_ref().and_then(|e| e.strip_prefix(&root).ok());
    for (rel, was) in &before {
        let now = after.get(rel);
        if Some(rel.as_path()) == end_rel && matches!(was, Entry::File(..)) && written.is_ok() {
            let Some(Entry::File(_, mode)) = now else {
                panic!("{rel:?}: the written file is {now:?}");
            };
            let Entry::File(_, old_mode) = was else {
                unreachable!()
            };
            assert_eq!(mode, old_mode, "{rel:?}: mode");
        } else {
            assert_eq!(now, Some(was), "{rel:?} changed");
        }
    }
    for (rel, now) in &after {
        if !before.contains_key(rel) {
            // Only the file a dangling chain leads to may appear: never a temporary file.
            assert!(
                written.is_ok() && Some(rel.as_path()) == end_rel,
                "{rel:?} appeared: {now:?}"
            );
            assert!(matches!(now, Entry::File(..)), "{rel:?}: {now:?}");
        }
    }
});
