//! The architecture as `src/lib.rs` draws it, held: every module sits in the layer table, no
//! module imports a module of a lower layer (the table lists layers from the bottom up), no two
//! modules import each other (directly or in a circle, across the crate and inside each folder),
//! and no file of `src/` holds more than 800 lines before its tests. Imports are the `crate::x`
//! and `super::x` paths of code lines; documentation links are not imports.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The lines of a file before its `#[cfg(test)]` module, comments removed.
fn code_lines(text: &str) -> Vec<String> {
    text.lines()
        .take_while(|l| !l.trim_start().starts_with("#[cfg(test)]"))
        .map(|l| match l.find("//") {
            Some(at) => l[..at].to_string(),
            None => l.to_string(),
        })
        .collect()
}

/// The names that follow `prefix` in `line` (`crate::solve::...` gives `solve`).
fn paths_after<'a>(line: &'a str, prefix: &str) -> Vec<&'a str> {
    line.match_indices(prefix)
        .filter(|(at, _)| {
            // Not the tail of a longer path such as `rodimpact::crate`.
            *at == 0 || !line[..*at].ends_with(|c: char| c.is_alphanumeric() || c == '_')
        })
        .map(|(at, _)| {
            let rest = &line[at + prefix.len()..];
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            &rest[..end]
        })
        .filter(|name| !name.is_empty())
        .collect()
}

/// The layer of each top-level module, from the table in `src/lib.rs` (`| 2 model | [`scene`],
/// ... |`).
fn layers() -> BTreeMap<String, usize> {
    let lib = std::fs::read_to_string(src().join("lib.rs")).unwrap();
    let mut layers = BTreeMap::new();
    for row in lib.lines().filter_map(|l| l.strip_prefix("//! | ")) {
        let mut cells = row.split(" | ");
        let Some(layer) = cells
            .next()
            .and_then(|c| c.split(' ').next()?.parse::<usize>().ok())
        else {
            continue;
        };
        let modules = cells.next().unwrap_or_default();
        // The modules of the row: the backticked links outside parentheses.
        let mut depth = 0;
        let mut outside = String::new();
        for c in modules.chars() {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ if depth == 0 => outside.push(c),
                _ => {}
            }
        }
        for name in outside.split("[`").skip(1) {
            let name = name.split('`').next().unwrap();
            layers.insert(name.to_string(), layer);
        }
    }
    layers
}

/// The top-level module a file of `src/` belongs to (`src/solve/answer.rs` is `solve`).
fn top_module(file: &Path) -> String {
    let relative = file.strip_prefix(src()).unwrap();
    let first = relative.components().next().unwrap().as_os_str();
    first.to_string_lossy().trim_end_matches(".rs").to_string()
}

/// Whether the directed graph has a circle; the circle's nodes if so.
fn circle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(node.to_string(), 1);
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            match state.get(next.as_str()).copied().unwrap_or(0) {
                1 => {
                    let from = stack.iter().position(|n| n == next).unwrap();
                    return Some(stack[from..].to_vec());
                }
                0 => {
                    if let Some(c) = visit(next, graph, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(node.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for node in graph.keys() {
        if state.get(node.as_str()).copied().unwrap_or(0) == 0
            && let Some(c) = visit(node, graph, &mut state, &mut Vec::new())
        {
            return Some(c);
        }
    }
    None
}

#[test]
fn layers_hold_and_no_module_imports_in_a_circle() {
    let layers = layers();
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut upward = Vec::new();
    for file in &files {
        let module = top_module(file);
        if ["lib", "main", "commands"].contains(&module.as_str()) {
            continue;
        }
        let layer = *layers
            .get(&module)
            .unwrap_or_else(|| panic!("module {module} is not in src/lib.rs's layer table"));
        let text = std::fs::read_to_string(file).unwrap();
        for line in code_lines(&text) {
            for used in paths_after(&line, "crate::") {
                if used == module || !layers.contains_key(used) {
                    continue;
                }
                graph
                    .entry(module.clone())
                    .or_default()
                    .insert(used.to_string());
                if layers[used] > layer {
                    upward.push(format!("{} uses {used}", file.display()));
                }
            }
        }
    }
    assert!(
        upward.is_empty(),
        "imports of a higher layer:\n{}",
        upward.join("\n")
    );
    assert_eq!(circle(&graph), None, "modules importing each other");
    // The table lists exactly the modules lib.rs declares.
    let lib = std::fs::read_to_string(src().join("lib.rs")).unwrap();
    let declared: BTreeSet<String> = lib
        .lines()
        .filter_map(|l| l.strip_prefix("pub mod "))
        .map(|l| l.trim_end_matches(';').trim_end_matches(" {").to_string())
        .filter(|m| m != "prelude")
        .collect();
    let tabled: BTreeSet<String> = layers.keys().cloned().collect();
    assert_eq!(declared, tabled);
}

#[test]
fn no_folder_holds_files_that_import_each_other_in_a_circle() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut folders: BTreeMap<PathBuf, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for file in &files {
        let folder = file.parent().unwrap().to_path_buf();
        let name = file.file_stem().unwrap().to_string_lossy().into_owned();
        if name == "mod" {
            continue; // mod.rs declares and re-exports: an import through it is its child's
        }
        let text = std::fs::read_to_string(file).unwrap();
        let graph = folders.entry(folder.clone()).or_default();
        graph.entry(name.clone()).or_default();
        for line in code_lines(&text) {
            for used in paths_after(&line, "super::") {
                if folder.join(format!("{used}.rs")).exists() && used != name {
                    graph
                        .entry(name.clone())
                        .or_default()
                        .insert(used.to_string());
                }
            }
        }
    }
    for (folder, graph) in &folders {
        assert_eq!(
            circle(graph),
            None,
            "files of {} in a circle",
            folder.display()
        );
    }
}

#[test]
fn no_source_file_holds_more_than_800_lines_before_its_tests() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            let n = text
                .lines()
                .take_while(|l| !l.trim_start().starts_with("#[cfg(test)]"))
                .count();
            (n > 800).then(|| format!("{}: {n}", f.display()))
        })
        .collect();
    long.sort();
    assert!(
        long.is_empty(),
        "files over 800 non-test lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_checks_see_what_they_claim_to_see() {
    assert_eq!(
        paths_after("use crate::solve::{x}; crate::field::q(1, 1)", "crate::"),
        ["solve", "field"]
    );
    assert!(code_lines("use a; // crate::report\n#[cfg(test)]\nuse crate::b;")[0] == "use a; ");
    let mut g = BTreeMap::new();
    g.insert("a".to_string(), BTreeSet::from(["b".to_string()]));
    g.insert("b".to_string(), BTreeSet::from(["a".to_string()]));
    assert!(circle(&g).is_some());
    g.get_mut("b").unwrap().clear();
    assert!(circle(&g).is_none());
    assert_eq!(layers().get("impact"), Some(&3));
    assert_eq!(layers().get("solve"), Some(&5));
}

/// `report/` renders: it calls no solver. A report receives what it prints (an answer, a
/// working, a table's rows, a figure's samples from `sampling`), computed by the layers below
/// it or by `app/`; the solvers' types (`Outcome`, `Optimum`, `LawAnswer`, ...) are what it
/// reads. A call of any solver entry point in a code line of `src/report/` fails.
#[test]
fn report_calls_no_solver() {
    const SOLVERS: [&str; 18] = [
        "Answer::of(",
        "Impact::of(",
        "Working::of(",
        "solve::with",
        "fast::linear",
        "fast::oblique::solve",
        "fast::oblique::complete",
        "fast::fraction_free",
        "fast::closed_form",
        "optimum::optimum",
        "optimum(&",
        "contact_matrix(",
        "contact_matrix::<",
        "solve_contact",
        "solve_exact",
        "solve_several",
        "contact_path",
        "stability::judge",
    ];
    let mut files = Vec::new();
    rust_files(&src().join("report"), &mut files);
    let mut calls = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for (n, line) in code_lines(&text).iter().enumerate() {
            for solver in SOLVERS {
                if line.contains(solver) {
                    calls.push(format!("{}:{}: {solver}", file.display(), n + 1));
                }
            }
        }
    }
    assert!(
        calls.is_empty(),
        "report calls a solver:\n{}",
        calls.join("\n")
    );
    // The check sees a call where there is one.
    assert!(code_lines("let a = Answer::of(&scene); // Answer::of")[0].contains(SOLVERS[0]));
}
