//! The documentation stands on its own in a clone: every relative link of README.md and docs/
//! leads to a file of the repository, nothing refers to files outside it, and the stability
//! suite documented in docs/stability.md is the one the code runs.
//!
//! Regression (issue 12): the tests read their reference batches from a directory beside the
//! clone, and README linked to design notes there, so in a fresh clone `cargo test --release`
//! failed and the links led nowhere.

use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The text files of the repository below `dir` (recursively), skipping `target/`.
fn text_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            if (name != "target" && !name.starts_with('.')) || name == ".ci" {
                text_files(&path, out);
            }
        } else if ["rs", "md", "toml", "sh", "csv", "svg", "tex", "json", "txt"]
            .iter()
            .any(|ext| name.ends_with(&format!(".{ext}")))
            || name == "run"
        {
            out.push(path);
        }
    }
}

/// `[text](target)` links of a Markdown text, without `http(s):` and `#` links.
fn relative_links(markdown: &str) -> Vec<String> {
    let mut links = Vec::new();
    let mut rest = markdown;
    while let Some(start) = rest.find("](") {
        rest = &rest[start + 2..];
        let Some(end) = rest.find(')') else { break };
        let target = rest[..end].split('#').next().unwrap_or_default();
        if !target.is_empty() && !target.contains("://") {
            links.push(target.to_string());
        }
        rest = &rest[end..];
    }
    links
}

#[test]
fn every_relative_link_of_the_docs_leads_to_a_file() {
    let mut pages = vec![
        root().join("README.md"),
        root().join("CONTRIBUTING.md"),
        root().join("engines/README.md"),
        root().join("tests/data/README.md"),
    ];
    for entry in std::fs::read_dir(root().join("docs")).unwrap() {
        let path = entry.unwrap().path();
        // The pages, not the images they show.
        if path.extension().is_some_and(|e| e == "md") {
            pages.push(path);
        }
    }
    pages.push(root().join("proofs/README.md"));
    let mut broken = Vec::new();
    let mut checked = 0;
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        for link in relative_links(&text) {
            checked += 1;
            let target = page.parent().unwrap().join(&link);
            if !target.exists() {
                broken.push(format!("{}: {link}", page.display()));
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    assert!(checked >= 150, "only {checked} links checked");
    for doc in ["conventions.md", "claims.md", "stability.md"] {
        let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
        assert!(
            readme.contains(&format!("(docs/{doc})")),
            "README links docs/{doc}"
        );
    }
}

/// The repository paths written in backticks in `text` (`src/solve/answer.rs`,
/// `crates/rodimpact-cli/tests/cli/console.rs:12`), without a line number; globs and placeholders are left out.
fn backticked_paths(text: &str) -> Vec<String> {
    const TOP: [&str; 10] = [
        "src/",
        "tests/",
        "docs/",
        "examples/",
        "benches/",
        "bench/",
        "engines/",
        "proofs/",
        ".ci/",
        "fuzz/",
    ];
    text.split('`')
        .skip(1)
        .step_by(2)
        .filter(|t| TOP.iter().any(|top| t.starts_with(top)))
        .filter(|t| !t.contains([' ', '*', '<', '{', '$', '|']))
        .map(|t| t.split(':').next().unwrap_or_default().to_string())
        .collect()
}

#[test]
fn every_backticked_repository_path_exists() {
    let mut files = vec![
        root().join("README.md"),
        root().join("CONTRIBUTING.md"),
        root().join("engines/README.md"),
        root().join("tests/data/README.md"),
    ];
    for dir in ["docs", "src", "tests", "benches", "examples"] {
        text_files(&root().join(dir), &mut files);
    }
    let mut stale = Vec::new();
    let mut checked = 0;
    for file in files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "md" || e == "rs"))
    {
        let text = std::fs::read_to_string(file).unwrap();
        for path in backticked_paths(&text) {
            checked += 1;
            if !root().join(&path).exists() {
                stale.push(format!("{}: {path}", file.display()));
            }
        }
    }
    assert!(
        stale.is_empty(),
        "paths that do not exist:\n{}",
        stale.join("\n")
    );
    assert!(checked >= 50, "only {checked} paths checked");
    assert_eq!(
        backticked_paths("see `src/lib.rs:12` and `tests/*.rs`, not `docs/x.md`"),
        ["src/lib.rs", "docs/x.md"]
    );
}

/// The README is an entry point, not the manual: at most 350 lines (the rest is in docs/).
#[test]
fn the_readme_stays_short() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(lines <= 350, "README.md has {lines} lines");
}

#[test]
fn nothing_in_the_repository_refers_to_files_beside_it() {
    // The directory that held them, built from parts so that this file does not name it.
    let outside = ["shared", ""].join("/");
    let mut files = vec![root().join("README.md"), root().join("Cargo.toml")];
    for dir in [
        "src", "tests", "benches", "examples", "bench", "docs", "proofs", ".ci",
    ] {
        text_files(&root().join(dir), &mut files);
    }
    assert!(files.len() > 100, "{} files", files.len());
    let offending: Vec<String> = files
        .iter()
        .filter(|f| {
            std::fs::read_to_string(f)
                .map(|text| text.contains(&outside))
                .unwrap_or(false)
        })
        .map(|f| f.display().to_string())
        .collect();
    assert!(offending.is_empty(), "{offending:?}");
}

#[test]
fn docs_stability_lists_every_suite_scene() {
    let doc = std::fs::read_to_string(root().join("docs/stability.md")).unwrap();
    for case in rodimpact::stability::suite() {
        let row = if case.id.starts_with("22") {
            "| 22a-22f |".to_string()
        } else {
            format!("| {} |", case.id)
        };
        assert!(doc.contains(&row), "scene {} ({})", case.id, case.what);
    }
}
