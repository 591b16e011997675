//! `rodimpact._native`: the Rust side of the Python package.
//!
//! Every function takes the scene as `(key, text)` pairs (the keys of
//! `rodimpact::scene::SCENE_KEYS`, spelt as the command-line flags: `m`, `M`, `from-end`, ...),
//! calls the same library functions as the command line and returns the JSON text the command
//! line prints with `--json`, so that Python's `.to_dict()` is the CLI's JSON by construction.
//! Errors become `ValueError` with the CLI's one-line message (`M: must be > 0, got -1`).
//! The Python package (`rodimpact/__init__.py`) turns the JSON into Fractions and surds.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use rodimpact::scene::SceneInput;
use rodimpact::{Error, ErrorKind};

mod audit;

/// The library's error as Python's `ValueError`, with the CLI's message.
fn value_error(e: Error) -> PyErr {
    PyValueError::new_err(e.to_string())
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
    m.add_function(wrap_pyfunction!(solve_json, m)?)?;
    m.add_function(wrap_pyfunction!(formula_json, m)?)?;
    m.add_function(wrap_pyfunction!(scene_keys, m)?)?;
    audit::register(m)?;
    Ok(())
}
