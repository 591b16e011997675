//! Counts and limits as the reports write them: digits grouped in threes.

/// A whole number with a comma between each group of three digits, as the reports write
/// counts and limits.
///
/// # Examples
/// ```
/// use rodimpact::field::count::grouped;
/// assert_eq!(grouped(3_000_000_000), "3,000,000,000");
/// assert_eq!(grouped(999), "999");
/// ```
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}
