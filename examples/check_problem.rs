//! Check a textbook problem's printed answers against the exact ones:
//! `cargo run --example check_problem`.
//!
//! The problem: a 50 g ball at 4.0 m/s strikes a 0.30 kg rod, 80 cm long, lying on a smooth
//! table, 10 cm from its end, and bounces back elastically; the book prints the ball's speed
//! after as 1.5 m/s and the rod's spin as 5.2 rad/s.

use rodimpact::report::agreement_label;
use rodimpact::textbook::problems::{check_problems, parse_problems};

const PROBLEM: &str = r#"
[[problem]]
id = "ball-on-rod"
source = "written for this example"
[problem.given]
m = "50 g"
M = "0.30 kg"
length = "80 cm"
from_end = "10 cm"
v0 = "4.0 m/s"
[problem.claims]
v = "-1.5 m/s"
omega = "5.2 rad/s"
"#;

fn main() -> Result<(), rodimpact::Error> {
    let problems = parse_problems("example", PROBLEM)?;
    for checked in check_problems("example", &problems, None)? {
        for answer in &checked.check.answers {
            println!(
                "{}: {} claimed {}, exact {}: {}",
                checked.id,
                answer.name,
                answer.claim,
                answer.exact,
                agreement_label(answer.agreement)
            );
        }
        println!(
            "{}: every claim agrees: {}",
            checked.id,
            checked.check.all_agree()
        );
    }
    Ok(())
}
