//! The command line's test helpers: running the `rodimpact` binary this package builds, with
//! the repository's root as its working directory, and the helpers shared with the library's
//! tests (`tests/common/mod.rs`).
#![allow(dead_code)]

#[path = "../../../../tests/common/mod.rs"]
mod shared;
pub use shared::*;

/// Runs the `rodimpact` binary with `args` and returns what it did, any exit code.
pub fn output<I, A>(args: I) -> std::process::Output
where
    I: IntoIterator<Item = A>,
    A: AsRef<std::ffi::OsStr>,
{
    std::process::Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(args)
        .current_dir(crate::ROOT)
        .output()
        .expect("the binary runs")
}

/// `rodimpact solve --json ARGS`, which must succeed, parsed.
pub fn solve_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["solve", "--json"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = rodimpact(&all);
    assert_eq!(code, 0, "stderr: {stderr}");
    serde_json::from_str(&stdout).expect("solve --json prints JSON")
}

/// Asserts that `rodimpact ARGS` is refused as bad input: exit 2, nothing on standard output,
/// and exactly `message` on standard error.
pub fn assert_refused(args: &[&str], message: &str) {
    let (code, out, err) = rodimpact(args);
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (2, "", message),
        "{args:?}"
    );
}

/// Runs the `rodimpact` binary with `args`: (exit code, stdout, stderr).
pub fn rodimpact(args: &[&str]) -> (i32, String, String) {
    let out = output(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
