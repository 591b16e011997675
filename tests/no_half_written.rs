//! No half-written output: a `rodimpact batch --out` run killed (SIGKILL) midway leaves the
//! previous output file byte for byte intact.
//!
//! Output goes to a temporary sibling (`.<name>.tmp-<pid>`) that is renamed over the target only
//! when complete. SIGKILL runs no destructor, so that hidden temporary file stays behind after a
//! kill (a clean error or a panic removes it); this is accepted and documented in the README: it
//! is hidden, named as temporary, and never mistaken for the output.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A bound only a hang reaches; the run is killed as soon as partial output exists.
const HANG: Duration = Duration::from_secs(20);

fn write_big_csv(path: &Path, rows: usize) {
    let mut text = String::with_capacity(rows * 24);
    text.push_str("m,M,l,a,v0\n");
    for i in 0..rows {
        let (m, big) = (i % 97 + 1, i % 89 + 1);
        text.push_str(&format!("{m},{big},3/2,{}/7,{}\n", i % 10, i % 13 + 1));
    }
    std::fs::write(path, text).unwrap();
}

/// The hidden temporary sibling of `out.csv` in `dir`, with its size, once one exists.
fn temporary(dir: &Path) -> Option<(String, u64)> {
    std::fs::read_dir(dir).unwrap().find_map(|entry| {
        let entry = entry.unwrap();
        let name = entry.file_name().to_string_lossy().into_owned();
        name.starts_with(".out.csv.tmp-")
            .then(|| (name, entry.metadata().unwrap().len()))
    })
}

#[test]
fn a_batch_killed_midway_leaves_the_previous_output_intact() {
    let dir = std::env::temp_dir().join(format!("rodimpact-kill-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (input, out) = (dir.join("in.csv"), dir.join("out.csv"));
    write_big_csv(&input, 400_000);
    let previous = "m,M\n1,1\n(the previous, complete output)\n";
    std::fs::write(&out, previous).unwrap();

    let mut child = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(["batch", input.to_str().unwrap(), "--jobs", "1", "--out"])
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Wait until partial output has reached the disk (more than one buffer), then kill.
    let start = Instant::now();
    let partial = loop {
        if let Some((name, len)) = temporary(&dir)
            && len > 0
        {
            break (name, len);
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it could be killed midway: make the input larger"
        );
        assert!(start.elapsed() < HANG, "no partial output after {HANG:?}");
        std::thread::sleep(Duration::from_millis(1));
    };
    child.kill().unwrap();
    child.wait().unwrap();

    assert!(partial.1 > 0, "killed while partial output existed");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), previous);
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    // Only the input, the untouched output and the hidden temporary file remain.
    assert_eq!(names.len(), 3, "{names:?}");
    assert!(names.contains(&partial.0), "{names:?}");
    assert!(partial.0.starts_with('.') && partial.0.contains(".tmp-"));
    std::fs::remove_dir_all(&dir).unwrap();
}
