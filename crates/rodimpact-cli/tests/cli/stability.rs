//! `rodimpact stability`: every backend in the table, the JSON form, and the SVG plot written.

use std::process::Command;

#[test]
fn stability_prints_every_backend_and_writes_the_plot() {
    let dir = crate::common::scratch("stab");
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("stability.svg");
    let out = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(["stability", "--format", "json", "--plot"])
        .arg(&svg)
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(0));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let names: Vec<&str> = rows
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["backend"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "f64/naive",
            "f64/sq",
            "f64/scomp",
            "f32/naive",
            "f32/sq",
            "f32/scomp",
            "interval",
            "exact"
        ]
    );
    for row in rows.as_array().unwrap() {
        assert_eq!(row["not_enclosed"], 0);
        if row["backend"] == "f64/sq" || row["backend"] == "f64/scomp" {
            assert!(row["max_error_cond_u"].as_f64().unwrap() <= 4.0, "{row}");
            assert_eq!(row["nan"], 0);
            assert_eq!(row["inf"], 0);
        }
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("median time per evaluation (ns)"));
    // NEWCOMER #18: error 0 and an unbounded error in marked bands, not at fake values.
    assert!(text.contains("off scale: error exactly 0"));
    assert!(text.contains("off scale: unbounded"));
    assert!(text.contains(r#"class="legend""#));
    std::fs::remove_dir_all(&dir).unwrap();
}
