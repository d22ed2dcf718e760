//! The extension module `chatter._native` of the Python package `chatter` (python/chatter/ wraps
//! it; docs/python.md describes the API). Every function takes exact numbers as text (the
//! package turns `Fraction` and `int` into canonical text), runs without the GIL, and returns
//! JSON text that the package turns into Python objects, canonical rationals into `Fraction`s.
//! Each result is one `serde_json::Value`: the library's typed report of the command (module
//! `reports`, docs/json.md), or for `certify`/`verify` the certificate and the verdict.
//! Errors become the exception classes of `chatter._errors`, with the rejection code.

mod check;
mod fail;
mod inputs;
mod pipeline;
mod reports;

use fail::run;
use pyo3::prelude::*;

/// Finds, exactifies and kernel-checks a cone; JSON with the certificate's RON and JSON texts.
#[pyfunction]
#[pyo3(signature = (n, kappa, gamma, claim=None))]
fn certify(py: Python<'_>, n: u64, kappa: String, gamma: String, claim: Option<String>) -> PyResult<String> {
    run(py, move || pipeline::certify(n, &kappa, &gamma, claim.as_deref()))
}

/// Verifies the certificate (or refutation) file at `path`; JSON of the verdict.
#[pyfunction]
fn verify_path(py: Python<'_>, path: String) -> PyResult<String> {
    run(py, move || check::verify_path(&path))
}

/// Verifies certificate (or refutation) text, RON or JSON; JSON of the verdict.
#[pyfunction]
fn verify_text(py: Python<'_>, text: String) -> PyResult<String> {
    run(py, move || check::verify_text(&text))
}

/// Every exact criterion at one body, with its evidence (the fields of `chatter classify --json`).
#[pyfunction]
#[pyo3(signature = (n, kappa, gamma, velocity=None, digits=12))]
fn classify(
    py: Python<'_>,
    n: u64,
    kappa: String,
    gamma: String,
    velocity: Option<Vec<String>>,
    digits: usize,
) -> PyResult<String> {
    let args = reports::classify::Args { n, kappa, gamma, velocity, digits };
    run(py, move || reports::classify::value(&args))
}

/// One simulated drop, or a batch (`runs`); the fields of `chatter simulate --json`.
#[pyfunction]
#[pyo3(signature = (n, kappa, gamma, seed=0, impacts=200, exact=false, runs=None, position=None, velocity=None))]
#[allow(clippy::too_many_arguments)]
fn simulate(
    py: Python<'_>,
    n: u64,
    kappa: String,
    gamma: String,
    seed: u64,
    impacts: usize,
    exact: bool,
    runs: Option<u64>,
    position: Option<Vec<String>>,
    velocity: Option<Vec<String>>,
) -> PyResult<String> {
    let args = reports::simulate::Args { n, kappa, gamma, seed, impacts, exact, runs, position, velocity };
    run(py, move || reports::simulate::value(&args))
}

/// The catalogue of bodies (the rows of `chatter bodies --json`).
#[pyfunction]
#[pyo3(signature = (digits=12))]
fn bodies(py: Python<'_>, digits: usize) -> PyResult<String> {
    run(py, move || reports::bodies::value(digits))
}

/// A map over (rho or kappa, gamma) as columns (the columns of points.csv).
#[pyfunction]
#[pyo3(signature = (n, variable, x, gamma, certify=false, refute=false, simulate=None))]
#[allow(clippy::too_many_arguments)]
fn map(
    py: Python<'_>,
    n: u64,
    variable: String,
    x: String,
    gamma: String,
    certify: bool,
    refute: bool,
    simulate: Option<u64>,
) -> PyResult<String> {
    let args = reports::map::Args { n, variable, x, gamma, certify, refute, simulate };
    run(py, move || reports::map::value(&args))
}

/// The module `chatter._native`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(certify, m)?)?;
    m.add_function(wrap_pyfunction!(verify_path, m)?)?;
    m.add_function(wrap_pyfunction!(verify_text, m)?)?;
    m.add_function(wrap_pyfunction!(classify, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(bodies, m)?)?;
    m.add_function(wrap_pyfunction!(map, m)?)?;
    Ok(())
}

/// JSON text of a value (the one format every function returns).
fn text(v: &serde_json::Value) -> String {
    v.to_string()
}
