//! The minimum Rust version, stated and tested with the one toolchain a machine has: Cargo.toml
//! says `rust-version = "1.88"`; every crate the default build (and the tests) resolve declares
//! a minimum no higher than that, and the optional `malachite` feature's crates no higher than
//! 1.90 (the README states both). rodimpact's own code is held to 1.88 by clippy's
//! `incompatible_msrv` lint, which `.ci/run` runs with `-D warnings`: it refuses any standard
//! library item stabilised after the `rust-version`.

use std::process::Command;

/// `1.85.0` or `1.85` as (1, 85).
fn version(text: &str) -> (u32, u32) {
    let mut parts = text.split('.').map(|p| p.parse::<u32>().unwrap_or(0));
    (parts.next().unwrap_or(0), parts.next().unwrap_or(0))
}

/// The host's target triple, as `cargo -vV` states it (`host: x86_64-unknown-linux-gnu`).
fn host_triple(cargo: &str) -> String {
    let out = Command::new(cargo)
        .arg("-vV")
        .output()
        .expect("cargo -vV runs");
    let text = String::from_utf8_lossy(&out.stdout);
    text.lines()
        .find_map(|l| l.strip_prefix("host: "))
        .expect("cargo -vV names the host")
        .trim()
        .to_string()
}

#[test]
fn every_dependency_builds_with_the_stated_rust_version() {
    let manifest =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml")).unwrap();
    let stated = manifest
        .lines()
        .find_map(|l| l.strip_prefix("rust-version = \""))
        .and_then(|l| l.strip_suffix('"'))
        .expect("Cargo.toml states rust-version");
    assert_eq!(stated, "1.88");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    // Only this machine's platform: `--offline` can resolve no more than what the build itself
    // fetched, and on a fresh machine that is the host's crates alone (a Windows-only crate
    // such as anstyle-wincon is in the lock file but was never downloaded).
    let host = host_triple(&cargo);
    let out = Command::new(&cargo)
        .args(["metadata", "--format-version", "1", "--offline"])
        .args(["--filter-platform", &host])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo metadata runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let metadata: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut too_new = Vec::new();
    let packages = metadata["packages"].as_array().unwrap();
    for package in packages {
        let name = package["name"].as_str().unwrap();
        let Some(needs) = package["rust_version"].as_str() else {
            continue;
        };
        if version(needs) > version(stated) {
            too_new.push(format!("{name} {} needs {needs}", package["version"]));
        }
    }
    assert!(too_new.is_empty(), "{}", too_new.join("\n"));
    assert!(packages.len() > 50, "{} packages resolved", packages.len());
}
