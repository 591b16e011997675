//! Decide claims of the paper with their certificates: `cargo run --example prove_claim [ID ...]`
//! (default: C3, the intuition the paper refutes, and C15).

use rodimpact::claims::{Paper, decide, find};

fn main() {
    let mut ids: Vec<String> = std::env::args().skip(1).collect();
    if ids.is_empty() {
        ids = vec!["C3".into(), "C15".into()];
    }
    let paper = Paper::as_printed();
    for id in &ids {
        let Some(entry) = find(id) else {
            eprintln!(
                "error: {id}: not a claim (C1-C46, X1-X31 and so on: rodimpact prove --help)"
            );
            std::process::exit(2);
        };
        let decided = decide(id, &paper).expect("a registered claim is decided");
        match &decided.verdict {
            Ok(verdict) => println!("{id}  {verdict:?}: {}", entry.statement),
            Err(why) => println!("{id}  certificate rejected: {why}"),
        }
    }
}
