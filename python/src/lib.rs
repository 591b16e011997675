//! `rodimpact._native`: the Rust side of the Python package.
//!
//! Every function takes the scene as `(key, text)` pairs (the keys of
//! `rodimpact::scene::SCENE_KEYS`, spelt as the command-line flags: `m`, `M`, `from-end`, ...),
//! calls the same library functions as the command line and returns the JSON text the command
//! line prints with `--json`, so that Python's `.to_dict()` is the CLI's JSON by construction.
//! Errors become `ValueError` with the CLI's one-line message (`M: must be > 0, got -1`).
//! The Python package (`rodimpact/__init__.py`) turns the JSON into Fractions and surds.

use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use rodimpact::scene::SceneInput;
use rodimpact::{Error, ErrorKind};

mod audit;

/// The library's error as Python's `ValueError`, with the CLI's message; an interrupted
/// computation (Ctrl-C, seen by [`python_interrupted`]) as `KeyboardInterrupt`.
fn value_error(e: Error) -> PyErr {
    if e.kind == ErrorKind::Interrupted {
        return PyKeyboardInterrupt::new_err("rodimpact: interrupted");
    }
    PyValueError::new_err(e.to_string())
}

/// The library's interrupt hook ([`rodimpact::interrupt`]): runs Python's signal handlers
/// (which only the main thread can) and says whether one raised, as Ctrl-C's does.
fn python_interrupted() -> bool {
    Python::attach(|py| py.check_signals().is_err())
}

/// The scene the `(key, text)` pairs give. An unknown key is refused, naming the keys there are.
fn scene_input(pairs: &[(String, String)]) -> Result<SceneInput, Error> {
    let mut input = SceneInput::default();
    for (key, text) in pairs {
        let Some(slot) = input.slot(key) else {
            let known: Vec<&str> = rodimpact::scene::SCENE_KEYS
                .iter()
                .map(|k| k.name)
                .collect();
            return Err(Error::new(
                rodimpact::echo::echo(key),
                ErrorKind::Invalid(format!(
                    "not a scene input (expected one of {})",
                    known.join(", ")
                )),
            ));
        };
        *slot = Some(text.clone());
    }
    Ok(input)
}

fn to_json(value: &serde_json::Value) -> String {
    serde_json::to_string(value).expect("JSON of strings, numbers and bools")
}

/// `solve --json [--digits N]`: the JSON text of one scene's whole answer, whether the
/// conservation laws held (the CLI's exit 0; exit 1 otherwise) and the text report of `solve`
/// (15 digits).
#[pyfunction]
#[pyo3(signature = (pairs, digits=None))]
fn solve_json(
    py: Python<'_>,
    pairs: Vec<(String, String)>,
    digits: Option<String>,
) -> PyResult<(String, bool, String)> {
    py.detach(|| {
        let scene = scene_input(&pairs)?.build()?;
        let digits = rodimpact::report::parse_digits(digits.as_deref(), 30)?;
        let answer = rodimpact::solve::Answer::of(&scene);
        let json = rodimpact::report::solution_json(&answer, digits);
        let text = rodimpact::report::solution_text(&answer, 15);
        Ok::<_, Error>((to_json(&json), answer.laws_hold(), text))
    })
    .map_err(value_error)
}

/// `formula --format json`, `--format latex` and `--format text`: the JSON text of the formulas
/// with their free symbols and defaults, the LaTeX block and the text report.
#[pyfunction]
fn formula_json(
    py: Python<'_>,
    pairs: Vec<(String, String)>,
) -> PyResult<(String, String, String)> {
    py.detach(|| {
        let f = rodimpact::textbook::formula::formulas(&scene_input(&pairs)?)?;
        Ok::<_, Error>((
            to_json(&rodimpact::report::formula_json(&f)),
            rodimpact::report::formula_latex(&f),
            rodimpact::report::formula_text(&f),
        ))
    })
    .map_err(value_error)
}

/// `check --json` with scene flags and `--claim`s: the JSON text, whether every claim agrees
/// (the CLI's exit 0), and the text table with its summary line.
#[pyfunction]
#[pyo3(signature = (pairs, claims, sig=None))]
fn check_json(
    py: Python<'_>,
    pairs: Vec<(String, String)>,
    claims: Vec<String>,
    sig: Option<u32>,
) -> PyResult<(String, bool, String)> {
    py.detach(|| {
        let check = rodimpact::textbook::check_claims(&scene_input(&pairs)?, &claims, sig)?;
        let text = format!(
            "{}{}\n",
            rodimpact::report::check_table(&check),
            rodimpact::report::check_summary(&check)
        );
        Ok::<_, Error>((
            to_json(&rodimpact::report::check_json(&check)),
            check.all_agree(),
            text,
        ))
    })
    .map_err(value_error)
}

/// `check PROBLEMS.toml --json`: the JSON text, whether every claim agrees, and the text report.
#[pyfunction]
#[pyo3(signature = (path, sig=None))]
fn check_file_json(
    py: Python<'_>,
    path: std::path::PathBuf,
    sig: Option<u32>,
) -> PyResult<(String, bool, String)> {
    use rodimpact::textbook::problems::{check_problems, parse_problems, read_problem_file};
    py.detach(|| {
        let label = rodimpact::echo::echo_path(&path);
        let text = read_problem_file(&label, &path)?;
        let problems = parse_problems(&label, &text)?;
        let checks = check_problems(&label, &problems, sig)?;
        Ok::<_, Error>((
            to_json(&rodimpact::report::problems_json(&checks)),
            checks.iter().all(|p| p.check.all_agree()),
            rodimpact::report::problems_text(&checks),
        ))
    })
    .map_err(value_error)
}

/// `impact FILE --format json`: the scene from a file (`path`) or from the JSON text of a
/// dict with the file's structure (`scene`, named `label` in errors); the JSON text, whether
/// the file's claims all agree, and the text report.
#[pyfunction]
#[pyo3(signature = (path, scene, label, law=None, model=None, digits=None, engine=None))]
#[allow(clippy::too_many_arguments)]
fn impact_json(
    py: Python<'_>,
    path: Option<std::path::PathBuf>,
    scene: Option<String>,
    label: String,
    law: Option<String>,
    model: Option<String>,
    digits: Option<String>,
    engine: Option<String>,
) -> PyResult<(String, bool, String)> {
    use rodimpact::app::impact::{answer_impact, parse_engine, parse_law, read_scene_file};
    py.detach(|| {
        let (value, label) = match (&path, &scene) {
            (Some(path), _) => {
                let label = rodimpact::echo::echo_path(path);
                (read_scene_file(&label, path)?, label)
            }
            (None, Some(text)) => {
                let value: serde_json::Value = serde_json::from_str(text).map_err(|e| {
                    Error::new(label.clone(), ErrorKind::Invalid(format!("not JSON: {e}")))
                })?;
                (value, label)
            }
            (None, None) => {
                return Err(Error::new(label, ErrorKind::Missing));
            }
        };
        let law = match law.as_deref() {
            None => None,
            Some(text) => parse_law(text)?,
        };
        let engine = engine.as_deref().map(parse_engine).transpose()?;
        let digits_json = rodimpact::report::parse_digits(digits.as_deref(), 30)?;
        let digits_text = rodimpact::report::parse_digits(digits.as_deref(), 6)?;
        let run = answer_impact(&value, &label, law, model.as_deref(), engine.as_ref())?;
        Ok::<_, Error>((
            to_json(&rodimpact::report::impact_run_json(&run, digits_json)),
            run.all_agree(),
            rodimpact::report::impact_run_text(&run, digits_text),
        ))
    })
    .map_err(value_error)
}

/// `impact --batch`: every JSON line of the file at `path`, or of `lines` (named `label` in
/// errors), audited as the command line audits it; the audit of each line as JSON text, the
/// summary as JSON text (`--summary-json`), the summary's text (what the CLI prints on standard
/// error) and whether the audit passed (the CLI's exit 0).
#[pyfunction]
#[pyo3(signature = (path, lines, label, rtol=None, atol=None, ulps=None, float=None, engine=None, expect=None))]
#[allow(clippy::too_many_arguments)]
fn impact_audit_json(
    py: Python<'_>,
    path: Option<std::path::PathBuf>,
    lines: Option<String>,
    label: String,
    rtol: Option<String>,
    atol: Option<String>,
    ulps: Option<String>,
    float: Option<String>,
    engine: Option<String>,
    expect: Option<std::path::PathBuf>,
) -> PyResult<(Vec<String>, String, String, bool)> {
    use rodimpact::app::batch::BatchOptions;
    use rodimpact::app::impact_batch::{ImpactBatchOptions, read_known_findings, run};
    use rodimpact::report::{impact_audit_json, impact_batch_json, impact_batch_text};
    py.detach(|| {
        let float = BatchOptions::float_of(float.as_deref())?;
        let expected = expect.as_deref().map(read_known_findings).transpose()?;
        let options = ImpactBatchOptions::parse(
            rtol.as_deref(),
            atol.as_deref(),
            ulps.as_deref(),
            float,
            engine.as_deref(),
            expected,
        )?;
        let mut audits = Vec::new();
        let collect = |audit: &rodimpact::batch::ImpactAudit| {
            audits.push(to_json(&impact_audit_json(audit)));
            Ok(())
        };
        let summary = match (&path, &lines) {
            (Some(path), _) => {
                let name = rodimpact::echo::echo_path(path);
                let file = std::fs::File::open(path)
                    .map_err(|e| Error::io(name.clone(), "cannot read", e))?;
                run(std::io::BufReader::new(file), &name, &options, collect)?
            }
            (None, Some(text)) => run(text.as_bytes(), &label, &options, collect)?,
            (None, None) => return Err(Error::new(label, ErrorKind::Missing)),
        };
        let expect_name = expect.as_deref().map(rodimpact::echo::echo_path);
        let with_expected = options.expected.is_some();
        let text = impact_batch_text(
            &summary,
            options.expected.as_ref().zip(expect_name.as_deref()),
        );
        Ok::<_, Error>((
            audits,
            to_json(&impact_batch_json(&summary, with_expected)),
            text,
            summary.passed(with_expected),
        ))
    })
    .map_err(value_error)
}

/// The scene keys, in the order a scene is read: `(name, is a batch column, help)`.
#[pyfunction]
fn scene_keys() -> Vec<(&'static str, bool, &'static str)> {
    rodimpact::scene::SCENE_KEYS
        .iter()
        .map(|k| (k.name, k.column, k.help))
        .collect()
}

/// A Rust panic that reached the binding (a bug: the library never panics on input) as
/// `RuntimeError`, never an abort of the interpreter.
fn internal(why: impl std::fmt::Display) -> PyErr {
    PyRuntimeError::new_err(format!("rodimpact internal error: {why}"))
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    rodimpact::interrupt::set_hook(python_interrupted);
    m.add_function(wrap_pyfunction!(solve_json, m)?)?;
    m.add_function(wrap_pyfunction!(formula_json, m)?)?;
    m.add_function(wrap_pyfunction!(scene_keys, m)?)?;
    m.add_function(wrap_pyfunction!(check_json, m)?)?;
    m.add_function(wrap_pyfunction!(check_file_json, m)?)?;
    m.add_function(wrap_pyfunction!(impact_json, m)?)?;
    m.add_function(wrap_pyfunction!(impact_audit_json, m)?)?;
    audit::register(m)?;
    Ok(())
}
