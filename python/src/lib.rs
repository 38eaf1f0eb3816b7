//! `periodic_contact._native`: the PyO3 bindings of [`periodic_contact::api`]. Each function
//! returns the CLI's JSON as text (Python's `json.loads` reads it); the Python package
//! `periodic_contact` (`periodic_contact/__init__.py`) turns it into typed objects (coefficients
//! as `Fraction`, `Decimal` or SymPy-ready expressions; solutions with numbers as attributes and
//! numpy arrays at the points). Errors become typed Python exceptions carrying the CLI's message
//! (what `periodic-contact` prints after `error: `). Every computation runs on its own thread
//! with the GIL released, and Ctrl-C (KeyboardInterrupt) returns control at once (the abandoned
//! computation finishes in the background and its answer is dropped); a panic becomes `Error`.

use periodic_contact::api::{self, ApiError, ErrorKind, SolveOptions};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(_native, Error, PyException, "Base class of every periodic-contact error.");
create_exception!(
    _native,
    InputError,
    Error,
    "Invalid input (the CLI's exit code 2): names the parameter, its value and the valid range."
);
create_exception!(
    _native,
    SceneError,
    InputError,
    "The scene itself is invalid (TOML, unknown key, value out of range)."
);
create_exception!(_native, NoSolutionError, Error, "The equations have no solution at these inputs.");
create_exception!(_native, NotPhysicalError, Error, "A solution exists but is not physical.");
create_exception!(_native, NoConvergenceError, Error, "A method did not converge to the accuracy asked.");
create_exception!(_native, SeriesError, Error, "The exact series engine failed (e.g. a vanishing denominator).");

fn to_py(e: ApiError) -> PyErr {
    let message = e.to_string();
    match (&e, e.kind()) {
        (ApiError::Scene(_), _) => SceneError::new_err(message),
        (_, Some(ErrorKind::Input)) => InputError::new_err(message),
        (_, Some(ErrorKind::NoSolution)) => NoSolutionError::new_err(message),
        (_, Some(ErrorKind::NotPhysical)) => NotPhysicalError::new_err(message),
        (_, Some(ErrorKind::NoConvergence)) => NoConvergenceError::new_err(message),
        (_, None) => SeriesError::new_err(message),
    }
}

/// Runs `work` on its own thread with the GIL released, checking Python's signals every 50 ms:
/// Ctrl-C raises KeyboardInterrupt at once; a panic of `work` becomes [`Error`].
fn interruptible<T: Send + 'static>(py: Python<'_>, work: impl FnOnce() -> T + Send + 'static) -> PyResult<T> {
    use std::sync::mpsc::{channel, RecvTimeoutError};
    let (tx, rx) = channel();
    std::thread::Builder::new()
        .name("periodic-contact".into())
        .stack_size(64 << 20)
        .spawn(move || {
            let _ = tx.send(work());
        })
        .map_err(|e| Error::new_err(format!("cannot start the computation: {e}")))?;
    let mut rx = rx;
    loop {
        // The receiver moves into the GIL-free wait and back (it is Send, not Sync).
        let (got, back) = py.detach(move || (rx.recv_timeout(std::time::Duration::from_millis(50)), rx));
        rx = back;
        match got {
            Ok(v) => return Ok(v),
            Err(RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(RecvTimeoutError::Disconnected) => {
                return Err(Error::new_err("the computation stopped without an answer (an internal error)"))
            }
        }
    }
}

/// `periodic-contact series OBJECT --order ORDER --KEY VALUE ... --format json`, as JSON text.
#[pyfunction]
fn series_json(py: Python<'_>, object: String, order: usize, options: Vec<(String, String)>) -> PyResult<String> {
    interruptible(py, move || {
        let request = api::SeriesRequest { object, order: order.to_string(), options, pade: false };
        api::derive(&request).map(|d| api::json_text(&d.json()))
    })?
    .map_err(to_py)
}

/// `periodic-contact solve SCENE --json [--digits N] [--method M] [--order N] [--convention C]`
/// on the scene's TOML text, as JSON text.
#[pyfunction]
#[pyo3(signature = (scene, digits=None, method=None, order=None, convention=None))]
fn solve_json(
    py: Python<'_>,
    scene: String,
    digits: Option<u32>,
    method: Option<String>,
    order: Option<usize>,
    convention: Option<String>,
) -> PyResult<String> {
    interruptible(py, move || {
        let opts = SolveOptions { digits, method, order, convention };
        api::solve_toml(&scene, &opts).map(|a| api::json_text(&a.json))
    })?
    .map_err(to_py)
}

/// The version of the Rust crate.
#[pyfunction]
fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_function(wrap_pyfunction!(series_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve_json, m)?)?;
    m.add_function(wrap_pyfunction!(version, m)?)?;
    m.add("Error", py.get_type::<Error>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("SceneError", py.get_type::<SceneError>())?;
    m.add("NoSolutionError", py.get_type::<NoSolutionError>())?;
    m.add("NotPhysicalError", py.get_type::<NotPhysicalError>())?;
    m.add("NoConvergenceError", py.get_type::<NoConvergenceError>())?;
    m.add("SeriesError", py.get_type::<SeriesError>())?;
    Ok(())
}
