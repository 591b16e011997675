//! `rodimpact impact` where exact answers get expensive or open: a model over its work limit is
//! "not answered" beside the others' answers (exit 2 only when none answered), a scene too large
//! to work on is refused before any work, simultaneous Poisson reports every end of an open set
//! of answers, and the audit's output survives a reader that stops early.

use crate::common::{assert_refused, rodimpact, scratch};
use serde_json::Value;
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

/// A rigid bar of mass 3 and length 4 landing flat at (1/4, -7/4) on three points of a floor,
/// with e = `e1` at its left end and 1/2 at its centre and right end.
fn bar_on_three_points(e1: &str) -> String {
    let contact = |x: &str, e: &str| {
        format!(
            "[[contact]]\nbodies = [\"bar\", \"floor\"]\npoint = [\"{x}\", \"0\"]\nnormal = [\"0\", \"1\"]\ne = \"{e}\"\n"
        )
    };
    format!(
        "[[body]]\nname = \"bar\"\nmass = \"3\"\nshape = \"rod\"\nlength = \"4\"\nposition = [\"0\", \"0\"]\nvelocity = [\"1/4\", \"-7/4\"]\n[[body]]\nname = \"floor\"\nfixed = true\n{}{}{}",
        contact("-2", e1),
        contact("0", "1/2"),
        contact("2", "1/2")
    )
}

/// Four discs in a line along (5/13, 12/13), touching, plastic (e = 0), the first and last
/// approaching: sequential impacts pass impulses back and forth with ever longer fractions.
const COLUMN: &str = r#"
[[body]]
name = "b1"
mass = "2"
inertia = "1/4"
position = ["0", "0"]
velocity = ["5/13", "12/13"]
[[body]]
name = "b2"
mass = "4"
inertia = "1/2"
position = ["5/13", "12/13"]
[[body]]
name = "b3"
mass = "7/5"
inertia = "7/40"
position = ["10/13", "24/13"]
[[body]]
name = "b4"
mass = "15/4"
inertia = "15/32"
position = ["15/13", "36/13"]
velocity = ["-4/13", "-48/65"]
[[contact]]
bodies = ["b2", "b1"]
point = ["5/26", "6/13"]
normal = ["5/13", "12/13"]
e = "0"
[[contact]]
bodies = ["b3", "b2"]
point = ["15/26", "18/13"]
normal = ["5/13", "12/13"]
e = "0"
[[contact]]
bodies = ["b4", "b3"]
point = ["25/26", "30/13"]
normal = ["5/13", "12/13"]
e = "0"
"#;

fn json_of(args: &[&str]) -> Value {
    let (code, stdout, stderr) = rodimpact(args);
    assert_eq!(code, 0, "{args:?}: {stderr}");
    serde_json::from_str(&stdout).expect("impact --format json prints JSON")
}

/// A model alone past the work limit is refused (exit 2, one line naming it and the limit); in
/// `--model all` it is "not answered" and the others answer: the sequential orders of a plastic
/// column share one budget and are printed once, simultaneous Newton answers exactly.
#[test]
fn a_model_over_the_work_limit_is_not_answered_beside_the_others() {
    let (code, stdout, stderr) = rodimpact(&[
        "impact",
        "examples/impacts/cradle-3.toml",
        "--model",
        "pgs:10000",
    ]);
    assert_eq!(
        (code, stdout.as_str(), stderr.as_str()),
        (
            2,
            "",
            "error: model: pgs:10000: the exact projected Gauss-Seidel sweeps pass the work limit (1,000,000,000 units; docs/limits.md)\n"
        )
    );
    let dir = scratch("impact-limits-column");
    let path = dir.join("column.toml");
    std::fs::write(&path, COLUMN).unwrap();
    let path = path.to_str().unwrap();
    let (code, text, stderr) = rodimpact(&["impact", path]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        text.contains(
            "sequential:1,2,3 (one contact at a time, in this order, in passes until none approaches)\n  the same in the orders 1,3,2; 2,1,3; 2,3,1; 3,1,2; 3,2,1\n  not answered: the exact sequential impacts pass the work limit (1,000,000,000 units; docs/limits.md)\n"
        ),
        "{text}"
    );
    let json = json_of(&["impact", path, "--format", "json"]);
    let models = json["models"].as_array().unwrap();
    let sequential: Vec<&Value> = models
        .iter()
        .filter(|m| m["model"].as_str().unwrap().starts_with("sequential"))
        .collect();
    assert_eq!(sequential.len(), 6);
    for model in sequential {
        assert_eq!(model["status"], "over the work limit", "{model}");
        assert_eq!(model["answers"], serde_json::json!([]));
        assert!(model["why"].as_str().unwrap().contains("work limit"));
    }
    // Plastic and simultaneous: the four move together with the total momentum over the total
    // mass, 2 + 4 + 7/5 + 15/4 = 223/20: (2 (5/13) - (15/4)(4/13), ...) / (223/20).
    let newton = &models[0];
    assert_eq!(newton["model"], "simultaneous-newton");
    assert_eq!(newton["status"], "unique");
    let v = &newton["answers"][0]["bodies"]["b3"]["velocity"];
    assert_eq!(
        (&v[0]["exact"], &v[1]["exact"]),
        (&"-100/2899".into(), &"-240/2899".into())
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Unequal e with an open compression split: simultaneous Poisson's answers differ by split, and
/// both ends are reported (the independent oracle's, `../shared/reviews/t4/TRUTH.md` F1: the bar
/// at rest in spin, or spinning at 7/32 and losing 1421/384 J); with equal e the velocities are
/// one and only the split is open, which the answer says.
#[test]
fn simultaneous_poisson_reports_every_end_of_an_open_set_of_answers() {
    let dir = scratch("impact-limits-bar");
    let unequal = dir.join("unequal.toml");
    std::fs::write(&unequal, bar_on_three_points("1/3")).unwrap();
    let json = json_of(&[
        "impact",
        unequal.to_str().unwrap(),
        "--model",
        "simultaneous-poisson",
        "--format",
        "json",
    ]);
    let model = &json["models"][0];
    assert_eq!(model["status"], "several");
    let ends: Vec<(String, String, String)> = model["answers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| {
            let bar = &a["bodies"]["bar"];
            (
                bar["velocity"][1]["exact"].as_str().unwrap().to_owned(),
                bar["omega"]["exact"].as_str().unwrap().to_owned(),
                a["ledger"]["energy"]["change"]["exact"]
                    .as_str()
                    .unwrap()
                    .to_owned(),
            )
        })
        .collect();
    let expected = [("7/8", "0", "-441/128"), ("35/48", "7/32", "-1421/384")];
    assert_eq!(
        ends,
        expected.map(|(v, w, e)| (v.to_owned(), w.to_owned(), e.to_owned()))
    );
    let (_, text, _) = rodimpact(&[
        "impact",
        unequal.to_str().unwrap(),
        "--model",
        "simultaneous-poisson",
    ]);
    assert!(
        text.contains("2 answers: the compression's split"),
        "{text}"
    );

    let equal = dir.join("equal.toml");
    std::fs::write(&equal, bar_on_three_points("1/2")).unwrap();
    let json = json_of(&["impact", equal.to_str().unwrap(), "--format", "json"]);
    for model in json["models"].as_array().unwrap() {
        if model["model"].as_str().unwrap().starts_with("simultaneous") {
            assert_eq!(model["status"], "unique", "{model}");
            assert_eq!(model["answers"][0]["split_indeterminate"], true, "{model}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A scene whose numbers hold too many digits is refused before any work, naming the field; a
/// title with a newline or an escape is refused like a name.
#[test]
fn scenes_too_large_or_with_control_characters_are_refused() {
    let dir = scratch("impact-limits-refused");
    let base = std::fs::read_to_string(format!(
        "{}/examples/impacts/tilted-rod-rough-floor.toml",
        crate::ROOT
    ))
    .unwrap();
    let cases = [
        (
            r#"mu = "1/3""#,
            r#"mu = "1e-10000""#,
            "contact[1].mu: the scene's numbers pass 3,000 digits together here (limit",
        ),
        (
            "title = \"A tilted rod",
            "title = \"two\\nlines: A tilted rod",
            "title: no control characters (newlines, escapes), as in names",
        ),
    ];
    for (from, to, expected) in cases {
        assert!(base.contains(from), "{from}");
        let path = dir.join("scene.toml");
        std::fs::write(&path, base.replacen(from, to, 1)).unwrap();
        let (code, stdout, stderr) = rodimpact(&["impact", path.to_str().unwrap()]);
        assert_eq!((code, stdout.as_str()), (2, ""), "{to}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(expected),
            "{to}: {stderr}"
        );
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `impact --batch FILE | head -1`: the reader closing the pipe ends the audit quietly with exit 0
/// (as `batch` does), not with an error about the pipe. The output is larger than a pipe's buffer,
/// so the audit is still writing when the reader leaves.
#[test]
fn the_audit_ends_quietly_when_its_reader_stops() {
    let dir = scratch("impact-limits-pipe");
    let text =
        std::fs::read_to_string(format!("{}/examples/impacts/cradle-3.toml", crate::ROOT)).unwrap();
    let table: toml::Table = toml::from_str(&text).unwrap();
    let line = serde_json::to_string(&table).unwrap();
    let path = dir.join("many.jsonl");
    std::fs::write(&path, format!("{line}\n").repeat(400)).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_rodimpact"))
        .args(["impact", "--batch", path.to_str().unwrap()])
        .current_dir(crate::ROOT)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(first.starts_with('{'), "{first}");
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stderr).as_ref()
        ),
        (Some(0), "")
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A pinned body on a rough wall (RELIABILITY F2): Newton's and Stronge's laws never end the
/// impact (the contact sticks with no room to separate), Poisson's does. `--law all` answers
/// Poisson and says why the others cannot; asking for Newton's alone is refused.
const JAM: &str = r#"
[[body]]
name = "A"
mass = "1"
inertia = "4/3"
position = ["1", "2"]
velocity = ["28/15", "-7/6"]
omega = "-7/3"
[[body]]
name = "B"
fixed = true
[[pin]]
body = "A"
point = ["1/2", "6/5"]
[[contact]]
bodies = ["A", "B"]
point = ["2", "2"]
normal = ["-1/2", "0"]
e = "1"
mu = "2/3"
"#;

/// A law or an engine without an answer is said beside the laws that answer (exit 0), not a
/// refusal of the whole scene: the jammed pin above, and pymunk's replayed steps on the
/// published plastic crate, which keep a contact approaching past their cap (hostile-46 F4).
#[test]
fn a_law_without_an_answer_is_said_beside_the_others() {
    let dir = scratch("impact-limits-jam");
    let path = dir.join("jam.toml");
    std::fs::write(&path, JAM).unwrap();
    let path = path.to_str().unwrap();
    let never_ends = |law: &str| {
        format!(
            "under {law}'s law the impact never ends: after compression the normal relative velocity stops rising (the contact sticks with no room to separate)"
        )
    };
    let (code, text, stderr) = rodimpact(&["impact", path]);
    assert_eq!(code, 0, "{stderr}");
    assert!(text.contains("Poisson (kinetic"), "{text}");
    assert!(
        text.contains(&format!(
            "\nnewton: not answered: {}\n",
            never_ends("newton")
        )),
        "{text}"
    );
    let json = json_of(&["impact", path, "--format", "json"]);
    let laws: Vec<&str> = json["laws"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["law"].as_str().unwrap())
        .collect();
    assert_eq!(laws, ["poisson"]);
    assert_eq!(
        json["not_answered"],
        serde_json::json!([
            {"law": "newton", "why": never_ends("newton")},
            {"law": "energetic", "why": never_ends("energetic")},
        ])
    );
    let (code, stdout, stderr) = rodimpact(&["impact", path, "--law", "newton"]);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert_eq!(stderr, format!("error: {path}: {}\n", never_ends("newton")));
    std::fs::remove_dir_all(&dir).unwrap();

    let (code, text, stderr) = rodimpact(&[
        "impact",
        "examples/impacts/published/bj-crate-corner.toml",
        "--engine",
        "pymunk-7",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(text.contains("Stronge (energetic"), "{text}");
    assert!(
        text.contains("\npymunk-7: not answered: a contact still approaches after 60 of pymunk-7's steps (the cap, not a proof that the steps never stop)\n"),
        "{text}"
    );
}

/// The audit takes an engine by its name and the version rodimpact replays, never by a prefix
/// (hostile-46 F7), refuses a setting of that engine's step that does not parse, a line's
/// `claim` (published answers, or `claimed` misspelt), a non-string id, a key given twice and a
/// claimed body or key the scene does not have (F6, F9, F10), and does not pass when no line has
/// a claimed state.
#[test]
fn the_audit_takes_engines_by_name_and_refuses_what_it_would_drop() {
    let dir = scratch("impact-limits-claims");
    let first = std::fs::read_to_string(format!(
        "{}/tests/data/engines/impacts/box2d-2.3.10.jsonl",
        crate::ROOT
    ))
    .unwrap()
    .lines()
    .next()
    .unwrap()
    .to_owned();
    let run = |line: &str| {
        let path = dir.join("line.jsonl");
        std::fs::write(&path, format!("{line}\n")).unwrap();
        let (code, out, err) = rodimpact(&["impact", "--batch", path.to_str().unwrap()]);
        let path = path.to_str().unwrap().to_owned();
        (code, out, err.replace(&path, "FILE"))
    };
    let engine_of = |line: &str| -> Value {
        let (_, out, err) = run(line);
        let audit: Value = serde_json::from_str(out.lines().next().unwrap()).expect(&err);
        audit["error_split"]["profile"].clone()
    };
    assert_eq!(engine_of(&first), "box2d-2.3:scale=16");
    let renamed = |name: &str| first.replace("\"box2d 2.3.10\"", &format!("\"{name}\""));
    assert_eq!(engine_of(&renamed("Box2D v3.1")), "box2d-3");
    for unknown in ["pymunk 99", "bulletproof-sim 1.0", "box2d 30.0"] {
        assert_eq!(engine_of(&renamed(unknown)), Value::Null, "{unknown}");
    }
    for (from, to, message) in [
        (
            r#""scale": "16.0""#,
            r#""scale": "-16""#,
            "error: FILE: line 1: claimed.settings.scale: must be > 0, got -16\n",
        ),
        (
            r#""claimed""#,
            r#""claim""#,
            "error: FILE: line 1: claim: published answers ([[claim]]) belong in a scene file (rodimpact impact FILE.toml); an engine's bodies after go in \"claimed\"\n",
        ),
    ] {
        assert!(first.contains(from), "{from}");
        let (code, out, err) = run(&first.replacen(from, to, 1));
        assert_eq!((code, out.as_str(), err.as_str()), (2, "", message));
    }
    // A key given twice (hostile-46 F9), a claimed body or key the scene does not have (H9).
    let body = r#""omega": "#;
    assert!(first.contains(body));
    let twice = first.replacen(body, r#""omega": "9", "omega": "#, 1);
    let line: Value = serde_json::from_str(&first).unwrap();
    let name = line["claimed"]["bodies"]
        .as_object()
        .unwrap()
        .keys()
        .next()
        .unwrap()
        .clone();
    let edited = |edit: &dyn Fn(&mut Value)| {
        let mut line = line.clone();
        edit(&mut line);
        line.to_string()
    };
    for (line, message) in [
        (
            edited(&|l| l["id"] = 7.into()),
            "id: expected a string".to_string(),
        ),
        (
            twice,
            format!(
                "claimed.bodies.{name}.omega: given twice (a key may appear once in an object)"
            ),
        ),
        (
            edited(&|l| l["claimed"]["bodies"]["ghost"] = l["claimed"]["bodies"][&name].clone()),
            "claimed.bodies.ghost: no moving body of the scene has this name".to_string(),
        ),
        (
            edited(&|l| l["claimed"]["bodyz"] = 1.into()),
            "claimed.bodyz: unknown key (expected engine, settings, bodies)".to_string(),
        ),
        (
            edited(&|l| l["claimed"]["bodies"][&name]["spin"] = 1.into()),
            format!("claimed.bodies.{name}.spin: unknown key (expected velocity, omega)"),
        ),
    ] {
        let (code, out, err) = run(&line);
        assert_eq!(
            (code, out.as_str(), err),
            (2, "", format!("error: FILE: line 1: {message}\n"))
        );
    }
    let (code, _, err) = rodimpact(&["impact", "--batch", "/dev/null"]);
    assert_eq!(
        (code, err.as_str()),
        (
            1,
            "0 scenes, 0 with a claimed state\nnothing audited: no line has a \"claimed\" state (an engine's bodies after)\n"
        )
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A `--summary-json` path that cannot be written is refused before the audit (nothing on
/// standard output), its message naming the user's path, not a temporary's (hostile-46 F14).
#[test]
fn a_summary_path_that_cannot_be_written_is_refused_first() {
    for command in [
        &[
            "impact",
            "--batch",
            "tests/data/engines/impacts/pymunk-7.3.1.jsonl",
        ][..],
        &["batch", "tests/data/engines/pymunk-7.3.1-f64.csv"][..],
    ] {
        let mut args = command.to_vec();
        args.extend(["--summary-json", "/nonexistent/dir/s.json"]);
        assert_refused(
            &args,
            "error: summary-json: cannot write /nonexistent/dir/s.json: No such file or directory (os error 2)\n",
        );
    }
}

/// Ids are quoted as messages quote input (escaped: a forged id cannot write a line or an
/// escape sequence into the summary, RELIABILITY H7), and a finding names at most its first 100
/// scenes, counting the rest (bounded memory for a long audit, H11).
#[test]
fn the_summary_escapes_ids_and_names_at_most_a_hundred() {
    let dir = scratch("impact-limits-summary");
    let text =
        std::fs::read_to_string(format!("{}/examples/impacts/cradle-3.toml", crate::ROOT)).unwrap();
    let table: toml::Table = toml::from_str(&text).unwrap();
    let mut scene = serde_json::to_value(table).unwrap();
    // Every ball at rest after the impact: momentum is lost, no law or model gives it.
    let rest = serde_json::json!({"velocity": ["0", "0"], "omega": "0"});
    scene["claimed"] = serde_json::json!({"engine": "test 1", "bodies": {
        "ball1": rest, "ball2": rest, "ball3": rest}});
    let forged = "x\nall 1 claims match\u{1b}[2J";
    let mut lines = String::new();
    for k in 0..102 {
        scene["id"] = Value::String(if k == 0 {
            forged.into()
        } else {
            format!("s{k}")
        });
        lines.push_str(&format!("{scene}\n"));
    }
    let path = dir.join("lines.jsonl");
    std::fs::write(&path, lines).unwrap();
    let summary = dir.join("summary.json");
    let (code, _, err) = rodimpact(&[
        "impact",
        "--batch",
        path.to_str().unwrap(),
        "--summary-json",
        summary.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(!err.contains('\u{1b}') && !err.contains("x\nall"), "{err}");
    assert!(err.contains(r"x\nall 1 claims match\u{1b}[2J"), "{err}");
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap();
    let findings = json["findings"].as_object().unwrap();
    assert!(!findings.is_empty());
    for (name, finding) in findings {
        assert_eq!(finding["count"], 102, "{name}");
        let scenes = finding["scenes"].as_array().unwrap();
        assert_eq!(scenes.len(), 100, "{name}");
        assert_eq!(scenes[0], r"x\nall 1 claims match\u{1b}[2J", "{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
