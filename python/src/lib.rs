//! `kinrepro._kinrepro`: the Python bindings of the kinrepro library
//! (docs/python.md). No physics and no statistics here: every function
//! calls the library's public API the way the CLI does
//! (`src/bin/kinrepro/commands`), every document is the library's serde
//! form (JSON text, or Python objects built from it directly), and the
//! options of a study are checked by the library's study plan, as the
//! CLI's flags are; the library's messages name the keywords (its own
//! spelling of a parameter, `samples=7`). Long runs (study, sweep,
//! calibrate, predict) run on a worker thread with the GIL released
//! ([`run::interruptible`]); Ctrl-C stops them through the library's stop
//! request and raises `KeyboardInterrupt`.

mod calibrate;
mod optimize;
mod options;
mod run;
mod scene;
mod study;
mod sweep;
mod thermal;
mod whole;

use pyo3::prelude::*;

pyo3::create_exception!(
    kinrepro,
    KinreproError,
    pyo3::exceptions::PyValueError,
    "A bad input to kinrepro (scene, option, JSON document): the library's message."
);

/// `KinreproError` with the library's message.
pub(crate) fn err(e: impl std::fmt::Display) -> PyErr {
    KinreproError::new_err(e.to_string())
}

#[pymodule]
fn _kinrepro(m: &Bound<'_, PyModule>) -> PyResult<()> {
    // Built for the CPU it was built on: on an older one, say so at import
    // rather than stop on an illegal instruction later.
    if let Some(why) = kinrepro::lane::cpu_mismatch() {
        return Err(pyo3::exceptions::PyImportError::new_err(format!(
            "{why}; build it here (pip install ./python), or for the oldest machine it must run \
             on, e.g. with RUSTFLAGS=\"-C target-cpu=x86-64-v2\""
        )));
    }
    m.add("__version__", kinrepro::study::provenance::VERSION)?;
    m.add("SCHEMA_VERSION", kinrepro::study::provenance::SCHEMA_VERSION)?;
    m.add("KinreproError", m.py().get_type::<KinreproError>())?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<scene::Seating>()?;
    m.add_class::<thermal::ThermalPath>()?;
    m.add_class::<study::Study>()?;
    m.add_class::<sweep::Sweep>()?;
    m.add_class::<optimize::Optimization>()?;
    m.add_class::<calibrate::Calibration>()?;
    m.add_class::<calibrate::Prediction>()?;
    m.add_function(wrap_pyfunction!(scene::seat, m)?)?;
    m.add_function(wrap_pyfunction!(scene::stiffness, m)?)?;
    m.add_function(wrap_pyfunction!(thermal::thermal, m)?)?;
    m.add_function(wrap_pyfunction!(study::study, m)?)?;
    m.add_function(wrap_pyfunction!(study::merge, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(optimize::optimize, m)?)?;
    m.add_function(wrap_pyfunction!(calibrate::calibrate, m)?)?;
    m.add_function(wrap_pyfunction!(calibrate::predict, m)?)?;
    Ok(())
}
