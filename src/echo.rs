//! Quoting user input in messages: one line, escaped, bounded.
//!
//! Every message that repeats what the user typed (a file path, a flag's value, a CSV header
//! name, a TOML id) passes it through [`echo`] (or [`echo_path`]), so an input with a newline
//! cannot split the one-line error into two, and an ESC, CR or NUL never reaches the terminal
//! raw: they are written as `\u{1b}`, `\r`, `\0`, as Rust's `escape_debug` does. Very long
//! input is cut. [`one_line`] is the last guard on a whole message: it escapes what is still a
//! control character and leaves everything else (including escapes already made) alone.

use std::path::Path;

/// How many characters of an input value a message quotes; longer input is cut and marked
/// with `...`.
pub const ECHO_CHARS: usize = 40;

/// How many characters of a path a message quotes: the last ones are kept (the file name
/// says the most), marked with a leading `...`.
pub const ECHO_PATH_CHARS: usize = 200;

/// `text` as a message quotes it: at most [`ECHO_CHARS`] characters (then `...`), escaped as
/// `escape_debug` does (quotes, backslashes, control and other unprintable characters).
///
/// # Examples
/// ```
/// use rodimpact::echo::echo;
/// assert_eq!(echo("T9"), "T9");
/// assert_eq!(echo("1\n2"), "1\\n2");
/// assert_eq!(echo("\u{1b}[2J\r\0"), "\\u{1b}[2J\\r\\0");
/// assert_eq!(echo(&"7".repeat(100)), format!("{}...", "7".repeat(40)));
/// ```
pub fn echo(text: &str) -> String {
    // Short printable ASCII without quotes or backslashes is its own echo (a batch names every
    // row with a wrong claim by its id).
    let plain = |b: &u8| matches!(b, b' '..=b'~') && !matches!(b, b'\\' | b'\'' | b'"');
    if text.len() <= ECHO_CHARS && text.as_bytes().iter().all(plain) {
        return text.to_string();
    }
    escaped(text)
}

/// [`echo`] character by character.
fn escaped(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars().take(ECHO_CHARS) {
        push_escaped(&mut out, c, true);
    }
    if text.chars().nth(ECHO_CHARS).is_some() {
        out.push_str("...");
    }
    out
}

/// A path as a message quotes it: lossy for bytes that are not UTF-8, escaped like [`echo`],
/// at most [`ECHO_PATH_CHARS`] characters, keeping the end.
///
/// # Examples
/// ```
/// use rodimpact::echo::echo_path;
/// assert_eq!(echo_path("out/res.csv".as_ref()), "out/res.csv");
/// assert_eq!(echo_path("a\nb.csv".as_ref()), "a\\nb.csv");
/// let long = format!("{}/x.csv", "d".repeat(300));
/// assert!(echo_path(long.as_ref()).starts_with("...d"));
/// assert!(echo_path(long.as_ref()).ends_with("d/x.csv"));
/// ```
pub fn echo_path(path: &Path) -> String {
    let text = path.to_string_lossy();
    let count = text.chars().count();
    let mut out = String::new();
    if count > ECHO_PATH_CHARS {
        out.push_str("...");
    }
    for c in text.chars().skip(count.saturating_sub(ECHO_PATH_CHARS)) {
        push_escaped(&mut out, c, false);
    }
    out
}

/// `message` on one line with nothing for the terminal to interpret: every character that
/// `escape_debug` would escape, except quotes and backslashes, is escaped. Text that went
/// through [`echo`] is left as it is, so nothing is escaped twice.
///
/// # Examples
/// ```
/// use rodimpact::echo::{echo, one_line};
/// assert_eq!(one_line("jobs: got '1\n2'"), "jobs: got '1\\n2'");
/// let quoted = format!("got '{}'", echo("a\nb"));
/// assert_eq!(one_line(&quoted), quoted);
/// ```
pub fn one_line(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    for c in message.chars() {
        push_escaped(&mut out, c, false);
    }
    out
}

/// Pushes `c`, escaped when it is not printable (and, with `quotes`, when it is a quote or a
/// backslash).
fn push_escaped(out: &mut String, c: char, quotes: bool) {
    if !quotes && matches!(c, '\\' | '\'' | '"') {
        out.push(c);
    } else {
        out.extend(c.escape_debug());
    }
}

/// The candidate `text` most likely misspells, for a message's "did you mean": the nearest by
/// edit distance (insertions, deletions, substitutions and swaps of neighbours), when it is
/// within a third of the candidate's length (at least 1) and no other is as near; `None`
/// otherwise, and for `text` itself.
///
/// # Examples
/// ```
/// use rodimpact::echo::did_you_mean;
/// assert_eq!(did_you_mean("velocty", &["name", "velocity", "omega"]), Some("velocity"));
/// assert_eq!(did_you_mean("flor", &["box", "floor"]), Some("floor"));
/// assert_eq!(did_you_mean("mass", &["name", "velocity"]), None);
/// ```
pub fn did_you_mean<'a>(text: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let typed: Vec<char> = text.chars().take(64).collect();
    let mut best: Option<(usize, &'a str)> = None;
    let mut tied = false;
    for &candidate in candidates {
        let wanted: Vec<char> = candidate.chars().collect();
        let distance = edit_distance(&typed, &wanted);
        if distance == 0 || distance > (wanted.len() / 3).max(1) {
            continue;
        }
        match best {
            Some((d, _)) if d < distance => {}
            Some((d, _)) if d == distance => tied = true,
            _ => {
                best = Some((distance, candidate));
                tied = false;
            }
        }
    }
    best.filter(|_| !tied).map(|(_, candidate)| candidate)
}

/// The optimal-string-alignment distance between `a` and `b`.
fn edit_distance(a: &[char], b: &[char]) -> usize {
    let mut rows = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in rows.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in rows[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut d = (rows[i - 1][j] + 1)
                .min(rows[i][j - 1] + 1)
                .min(rows[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(rows[i - 2][j - 2] + 1);
            }
            rows[i][j] = d;
        }
    }
    rows[a.len()][b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plain_shortcut_is_the_escaping_it_skips() {
        // Every pair of ASCII characters, and lengths either side of the cut.
        for a in 0u8..128 {
            for b in 0u8..128 {
                let text = String::from_utf8(vec![a, b]).unwrap();
                assert_eq!(echo(&text), escaped(&text), "{text:?}");
            }
        }
        for n in [ECHO_CHARS - 1, ECHO_CHARS, ECHO_CHARS + 1] {
            let text = "x".repeat(n);
            assert_eq!(echo(&text), escaped(&text));
        }
    }

    #[test]
    fn nothing_a_terminal_interprets_survives() {
        // ESC (escape sequences), CR (overwrites the line), NUL, a newline, DEL, a bidi
        // override and a C1 control.
        let hostile = "a\u{1b}]0;title\u{7}\r\0\nb\u{7f}\u{202e}\u{9b}";
        for text in [
            echo(hostile),
            one_line(hostile),
            echo_path(hostile.as_ref()),
        ] {
            assert!(
                !text.chars().any(|c| c.is_control() || c == '\u{202e}'),
                "{text:?}"
            );
            assert!(text.starts_with('a'), "{text:?}");
        }
    }

    #[test]
    fn plain_text_and_unicode_pass_unchanged() {
        for text in ["m,M,a", "données/résultat.csv", "ω = 6/5"] {
            assert_eq!(echo(text), text);
            assert_eq!(one_line(text), text);
            assert_eq!(echo_path(text.as_ref()), text);
        }
    }

    #[test]
    fn long_text_is_cut_at_a_character_boundary() {
        let long = "é".repeat(ECHO_CHARS + 1);
        assert_eq!(echo(&long), format!("{}...", "é".repeat(ECHO_CHARS)));
        assert_eq!(echo(&"é".repeat(ECHO_CHARS)), "é".repeat(ECHO_CHARS));
    }
}
