//! Suggestions for a misspelt symbol in an expression (`v_0`, `vo`: did you mean v0?), among
//! the symbols the reader knows.

/// The symbol an unknown name most likely means: the same without underscores or in another
/// case (`v_0` is v0, `V0` of a free rod is V0, `Mu` is mu), or one edit away (`vo` is v0).
pub(super) fn nearest_symbol(name: &str, symbols: &[&'static str]) -> Option<&'static str> {
    let all = || symbols.iter().copied();
    let plain = name.replace('_', "");
    all()
        .find(|s| *s == plain)
        .or_else(|| all().find(|s| s.eq_ignore_ascii_case(&plain)))
        .or_else(|| all().find(|s| s.len() > 1 && one_edit_apart(s, &plain)))
}

/// Whether `a` becomes `b` by one substitution, insertion or deletion.
fn one_edit_apart(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let (short, long) = if a.len() <= b.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    match long.len() - short.len() {
        0 => a.iter().zip(&b).filter(|(x, y)| x != y).count() == 1,
        1 => (0..long.len()).any(|k| {
            let mut shorter = long.clone();
            shorter.remove(k);
            &shorter == short
        }),
        _ => false,
    }
}
