//! Builds the WebAssembly module the web pages compute with (`wasm/`, the library compiled for
//! `wasm32-unknown-unknown`) and leaves it, compressed (zlib) and in base64, in
//! `$OUT_DIR/pages.wasm.b64`, which `explore` inlines in every page it writes.
//!
//! Only with the feature `pages` (on by default). The module is built by a nested `cargo build
//! --release` in its own target directory beside this build's (`<target>/wasm-pages`), so it
//! reuses its work from one build to the next. This script belongs to the command-line tool,
//! not to the library: `cargo test -p rodimpact` and `cargo check -p rodimpact` never run it.
//!
//! `RODIMPACT_PAGES_WASM=FILE` takes a module already built instead (packagers, or a build
//! without the wasm32 target); `RODIMPACT_PAGES_WASM=none` builds the tool without a module
//! (the page commands then refuse), for a quick `cargo check` or an editor's checks of the
//! whole workspace. Without the target, the build adds it with `rustup target add` when rustup
//! is there; when that fails too, the build goes on with a warning and the page commands refuse
//! with a message that names the fix.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const TARGET: &str = "wasm32-unknown-unknown";

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let destination = out.join("pages.wasm.b64");
    println!("cargo:rerun-if-env-changed=RODIMPACT_PAGES_WASM");
    let wanted = env::var_os("CARGO_FEATURE_PAGES").is_some();
    let module = if wanted { module(&out) } else { None };
    let text = module.map(|bytes| base64(&miniz_oxide::deflate::compress_to_vec_zlib(&bytes, 10)));
    fs::write(&destination, text.unwrap_or_default()).expect("OUT_DIR is writable");
}

/// The module's bytes: the file `RODIMPACT_PAGES_WASM` names, or the nested build's; `None`
/// when `RODIMPACT_PAGES_WASM=none`, or (with a warning) when it cannot be built.
fn module(out: &Path) -> Option<Vec<u8>> {
    if env::var_os("RODIMPACT_PAGES_WASM").is_some_and(|v| v == "none") {
        return None;
    }
    if let Some(file) = env::var_os("RODIMPACT_PAGES_WASM") {
        println!("cargo:rerun-if-changed={}", Path::new(&file).display());
        return Some(fs::read(&file).unwrap_or_else(|e| {
            panic!("RODIMPACT_PAGES_WASM={}: {e}", Path::new(&file).display())
        }));
    }
    // The repository's root: this package is crates/rodimpact-cli.
    let root =
        PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it")).join("../..");
    for watched in [
        "src",
        "wasm/src",
        "wasm/Cargo.toml",
        "wasm/Cargo.lock",
        "Cargo.toml",
    ] {
        println!("cargo:rerun-if-changed={}", root.join(watched).display());
    }
    if !has_target() {
        let added = Command::new("rustup")
            .args(["target", "add", TARGET])
            .status()
            .is_ok_and(|s| s.success());
        if !added || !has_target() {
            println!(
                "cargo:warning=no {TARGET} target (rustup target add {TARGET}): the web pages \
                 (explore) are left out of this build"
            );
            return None;
        }
    }
    let target_dir = nested_target_dir(out);
    let cargo = env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut build = Command::new(cargo);
    build
        .args([
            "build",
            "--release",
            "--locked",
            "--target",
            TARGET,
            "--manifest-path",
        ])
        .arg(root.join("wasm/Cargo.toml"))
        .arg("--target-dir")
        .arg(&target_dir);
    // This build's flags are for the host, not the module.
    for host_only in [
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_TARGET",
        "RUSTFLAGS",
        "CARGO_ENCODED_RUSTFLAGS",
        "CARGO_MAKEFLAGS",
        "RUSTC_WORKSPACE_WRAPPER",
    ] {
        build.env_remove(host_only);
    }
    let status = build.status().expect("cargo runs");
    assert!(
        status.success(),
        "the WebAssembly module for the pages (wasm/) did not build"
    );
    let file = target_dir.join(TARGET).join("release/rodimpact_wasm.wasm");
    Some(fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display())))
}

/// Whether the toolchain has the standard library for WebAssembly.
fn has_target() -> bool {
    let rustc = env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    Command::new(rustc)
        .args(["--print", "target-libdir", "--target", TARGET])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .is_some_and(|dir| Path::new(dir.trim()).is_dir())
}

/// `<target>/wasm-pages`: beside this build's profile directories (OUT_DIR is
/// `<target>/<profile>/build/<package>-<hash>/out`), so that every build of the package (test,
/// clippy, doc) shares one nested build; inside OUT_DIR when the layout is another.
fn nested_target_dir(out: &Path) -> PathBuf {
    out.ancestors()
        .find(|dir| dir.file_name().is_some_and(|name| name == "build"))
        .and_then(|build| build.parent()?.parent())
        .map_or_else(
            || out.join("wasm-pages"),
            |target| target.join("wasm-pages"),
        )
}

/// Standard base64 with padding (RFC 4648), as `atob` reads it.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let word = chunk
            .iter()
            .enumerate()
            .fold(0u32, |w, (i, &b)| w | u32::from(b) << (16 - 8 * i));
        for i in 0..4 {
            text.push(if i <= chunk.len() {
                char::from(ALPHABET[(word >> (18 - 6 * i) & 63) as usize])
            } else {
                '='
            });
        }
    }
    text
}
