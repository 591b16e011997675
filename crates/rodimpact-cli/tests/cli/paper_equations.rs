//! The paper's Eqs. (v), (V), (omega), (maximal-a-general), (maximal-a-homogeneous) and
//! (maximal-a-gyration), each checked as printed by one `check` command that the README shows:
//! the commands are read here from README.md, so the README cannot drift from what is tested.

/// The `rodimpact check ...` command lines of the README's "paper's equations" block
/// (continuation lines joined), as argument lists.
fn readme_commands() -> Vec<Vec<String>> {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md")).unwrap();
    let start = readme
        .find("**The paper's equations, each checked as printed.**")
        .expect("README section");
    let block = &readme[start..];
    let block = &block[block.find("```console").unwrap()..];
    let block = &block[..block[3..].find("```").unwrap() + 3];
    let mut commands = Vec::new();
    let mut current = String::new();
    for line in block.lines() {
        let line = line.trim();
        if let Some(cmd) = line.strip_prefix("$ rodimpact ") {
            current = cmd.to_string();
        } else if current.is_empty() {
            continue;
        } else {
            current.push(' ');
            current.push_str(line);
        }
        if let Some(stripped) = current.strip_suffix('\\') {
            current = stripped.trim_end().to_string();
        } else if !current.is_empty() {
            commands.push(shell_words(&current));
            current.clear();
        }
    }
    commands
}

/// Splits on spaces outside double quotes (the README's commands quote every formula).
fn shell_words(line: &str) -> Vec<String> {
    let (mut words, mut word, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ' ' if !quoted => {
                if !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
            }
            _ => word.push(c),
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    words
}

fn run(args: &[String]) -> (i32, String) {
    let out = crate::common::output(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
    )
}

#[test]
fn each_equation_of_the_paper_is_checked_as_printed() {
    let commands = readme_commands();
    assert_eq!(commands.len(), 4, "{commands:?}");
    let outputs: Vec<(i32, String)> = commands.iter().map(|c| run(c)).collect();
    for ((code, out), cmd) in outputs.iter().zip(&commands) {
        assert_eq!(*code, 0, "{cmd:?}\n{out}");
        assert!(!out.contains("DISAGREES"), "{cmd:?}\n{out}");
    }
    // Eqs. (v), (V), (omega): identities in every symbol, I free.
    let (_, eqs) = &outputs[0];
    assert!(eqs.contains("free symbols: m, M, l, a, v0, I"));
    assert_eq!(eqs.matches("identity in m, M, l, a, v0, I").count(), 3);
    assert!(eqs.contains("3 of 3 claims agree"));
    // (maximal-a-general), (maximal-a-gyration), (maximal-a-homogeneous) with their domains.
    let on_rod = |i: usize| {
        outputs[i]
            .1
            .lines()
            .find(|l| l.contains("a* lies"))
            .unwrap_or_default()
            .trim()
            .to_string()
    };
    assert_eq!(
        on_rod(1),
        "note: a* lies on the rod (omega is largest there) when I*M + I*m <= M*l^2*m; otherwise omega is largest at a = l"
    );
    assert_eq!(
        on_rod(2),
        "note: a* lies on the rod (omega is largest there) when M*r^2 + m*r^2 <= l^2*m; otherwise omega is largest at a = l"
    );
    assert_eq!(
        on_rod(3),
        "note: a* lies on the rod (omega is largest there) when M <= 2*m; otherwise omega is largest at a = l"
    );
    // The homogeneous rod's output is shown in full in the README.
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md")).unwrap();
    assert!(readme.contains(outputs[3].1.trim_end()), "{}", outputs[3].1);
}

/// The dumbbell (r_G = l): a* is beyond the end whatever the masses, as the paper says.
#[test]
fn the_dumbbell_never_has_a_star_on_the_rod() {
    let args: Vec<String> = [
        "check",
        "--rod",
        "dumbbell",
        "--claim",
        "a_star=sqrt((M+m)/m)*l",
    ]
    .map(String::from)
    .to_vec();
    let (code, out) = run(&args);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains(
        "a* lies beyond the end for every value of the symbols: omega is largest at a = l"
    ));
}
