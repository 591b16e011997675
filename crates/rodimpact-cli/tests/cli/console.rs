//! Every ```` ```console ```` transcript of the documentation (README.md, CONTRIBUTING.md,
//! docs/*.md) is what the tool prints: each `$ command` line (a `\` continues it) runs in a
//! shell from the repository root with `rodimpact` meaning the binary under test, and its
//! standard output and error must equal the lines after it, up to the next `$` line or the
//! block's end. A line that is exactly `...` stands for any run of lines (an elision, marked
//! as such). A `NAME=value` line sets a variable for the block's later commands. Output a run
//! cannot reproduce (timings) is shown as an illustration, without a `$`.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The Markdown pages whose console blocks are checked.
fn pages() -> Vec<PathBuf> {
    let root = Path::new(crate::ROOT);
    let mut pages = vec![root.join("README.md"), root.join("CONTRIBUTING.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    pages.extend(docs);
    pages
}

/// The console blocks of `text`: (line number of the block's first line, its lines).
fn blocks(text: &str) -> Vec<(usize, Vec<&str>)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if lines[i].trim() == "```console" {
            let start = i + 1;
            let mut j = start;
            while lines[j].trim() != "```" {
                j += 1;
            }
            out.push((start + 1, lines[start..j].to_vec()));
            i = j + 1;
        } else {
            i += 1;
        }
    }
    out
}

/// The (command, expected output lines) transcripts of one block.
fn transcripts(block: &[&str]) -> Vec<(String, Vec<String>)> {
    let mut out = Vec::new();
    let mut k = 0;
    while k < block.len() {
        let Some(first) = block[k].strip_prefix("$ ") else {
            k += 1;
            continue;
        };
        let mut command = first.to_string();
        while let Some(head) = command.strip_suffix('\\') {
            k += 1;
            command = format!("{head} {}", block[k].trim());
        }
        k += 1;
        let mut expected = Vec::new();
        while k < block.len() && !block[k].starts_with("$ ") {
            expected.push(block[k].to_string());
            k += 1;
        }
        out.push((command, expected));
    }
    out
}

/// Whether `actual` matches `expected`, a `...` line matching any run of lines.
fn matches(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if e == "..." => (0..=actual.len()).any(|k| matches(rest, &actual[k..])),
        Some((e, rest)) => actual.first() == Some(&e.as_str()) && matches(rest, &actual[1..]),
    }
}

/// A name for the variable assignment `NAME=value`, if the command is one.
fn is_assignment(command: &str) -> bool {
    command.split_once('=').is_some_and(|(name, value)| {
        !name.is_empty()
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && !value.contains(' ')
    })
}

#[test]
fn every_console_transcript_is_what_the_tool_prints() {
    let binary = Path::new(env!("CARGO_BIN_EXE_rodimpact"));
    let bin_dir = binary.parent().expect("the binary's directory");
    let path = format!(
        "{}:{}",
        bin_dir.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    // Files the transcripts write land in a scratch directory: the shell runs there, with the
    // repository's files reachable through symbolic links.
    let scratch = crate::common::scratch("console");
    let root = Path::new(crate::ROOT);
    for entry in std::fs::read_dir(root).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name();
        if name != ".git" && name != "target" {
            std::os::unix::fs::symlink(entry.path(), scratch.join(&name)).unwrap();
        }
    }
    let (mut checked, mut failures) = (0, Vec::new());
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let name = page.strip_prefix(root).unwrap().display().to_string();
        for (line, block) in blocks(&text) {
            let mut assignments = Vec::new();
            for (command, expected) in transcripts(&block) {
                if is_assignment(&command) && expected.is_empty() {
                    assignments.push(command);
                    continue;
                }
                let script = format!("{}\n( {command} ) 2>&1", assignments.join("\n"));
                let out = Command::new("sh")
                    .args(["-c", &script])
                    .current_dir(&scratch)
                    .env("PATH", &path)
                    .output()
                    .expect("sh runs");
                let actual = String::from_utf8_lossy(&out.stdout);
                let actual: Vec<&str> = actual.lines().collect();
                checked += 1;
                if !matches(&expected, &actual) {
                    failures.push(format!(
                        "{name}:{line}: $ {command}\n--- expected\n{}\n--- printed\n{}",
                        expected.join("\n"),
                        actual.join("\n")
                    ));
                }
            }
        }
    }
    std::fs::remove_dir_all(&scratch).unwrap();
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    // README 12, docs and CONTRIBUTING the rest: a page losing its transcripts is seen here.
    assert!(checked >= 25, "only {checked} transcripts found");
}

#[test]
fn the_transcript_matcher_takes_elisions_and_nothing_else() {
    let e = |lines: &[&str]| lines.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert!(matches(&e(&["a", "...", "d"]), &["a", "b", "c", "d"]));
    assert!(matches(&e(&["a", "..."]), &["a"]));
    assert!(!matches(&e(&["a", "d"]), &["a", "b", "d"]));
    assert!(!matches(&e(&["a"]), &["a", "b"]));
    assert!(is_assignment("R=rodimpact") && !is_assignment("rodimpact solve --m 1"));
}
