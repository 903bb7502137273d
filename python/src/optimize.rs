//! `optimize` and `Optimization` (its document), as `kinrepro optimize`
//! runs them.

use kinrepro::error::parse_scene;
use kinrepro::explore::goal::Goals;
use kinrepro::explore::optimize::{
    MAX_ITERATIONS, OptimizeReport, OptimizeSpec, merge_optimizations as lib_merge, optimize as run,
};
use kinrepro::explore::run::study_plan;
use pyo3::prelude::*;

use crate::err;
use crate::options::Keywords;
use crate::scene::Scene;
use crate::study::to_python;
use crate::whole::Whole;

/// An optimisation: the document of `kinrepro optimize --json`.
#[pyclass(module = "kinrepro", frozen)]
pub struct Optimization {
    report: OptimizeReport,
}

#[pymethods]
impl Optimization {
    /// Read an optimisation document (`kinrepro optimize --json`).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Optimization> {
        let report = serde_json::from_str(text)
            .map_err(|e| err(format!("not a kinrepro optimize JSON: {e}")))?;
        Ok(Optimization { report })
    }

    /// The document of `kinrepro optimize --json`.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report).map_err(err)
    }

    /// The whole document as Python objects (`json.loads(to_json())`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report)
    }

    /// The text table of `kinrepro optimize`.
    fn table(&self) -> String {
        self.report.table()
    }

    /// The optimum as Python objects (`fields`, `objective`,
    /// `constraint_margins`, `design`, `statistical_error`), None when no
    /// candidate met every constraint.
    #[getter]
    fn optimum<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report.optimum)
    }

    fn __reduce__(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, (String,))> {
        let ctor = py.get_type::<Optimization>().getattr("from_json")?.unbind();
        Ok((ctor, (self.to_json()?,)))
    }

    fn __eq__(&self, other: &Optimization) -> bool {
        self.report == other.report
    }

    fn __repr__(&self) -> String {
        let r = &self.report;
        format!(
            "Optimization(scene={:?}, candidates={}, feasible_optimum={})",
            r.scene,
            r.history.len(),
            if r.optimum.is_some() { "True" } else { "False" }
        )
    }
}

/// `kinrepro merge` of optimisation parts.
pub fn merge_optimizations(py: Python<'_>, parts: &[Bound<'_, PyAny>]) -> PyResult<Py<PyAny>> {
    let docs = crate::study::parts_of(parts, "an Optimization", |o: &Optimization| &o.report)?;
    let merged = py.detach(move || lib_merge(docs)).map_err(err)?;
    Ok(Py::new(py, Optimization { report: merged })?.into_any())
}

/// Optimise one objective under constraints over the varied fields
/// (`kinrepro optimize`); `vary`: `FIELD=VALUES` strings.
#[pyfunction]
#[pyo3(signature = (
    scene, vary, objective = None, constraints = Vec::new(), samples = None, sampler = None,
    seed = None, jobs = None, increments = None, path_tolerance = None, replicates = None,
    max_iterations = Whole::of(MAX_ITERATIONS), starts = Whole::of(1), shard = None,
))]
#[allow(clippy::too_many_arguments)]
pub fn optimize(
    py: Python<'_>,
    scene: &Scene,
    vary: Vec<String>,
    objective: Option<String>,
    constraints: Vec<String>,
    samples: Option<Whole<usize>>,
    sampler: Option<String>,
    seed: Option<Whole<u64>>,
    jobs: Option<Whole<usize>>,
    increments: Option<Whole<usize>>,
    path_tolerance: Option<f64>,
    replicates: Option<Whole<usize>>,
    max_iterations: Whole<u64>,
    starts: Whole<usize>,
    shard: Option<&Bound<'_, PyAny>>,
) -> PyResult<Optimization> {
    let samples = samples.map(Whole::get);
    let seed = seed.map(Whole::get);
    let jobs = jobs.map(Whole::get);
    let increments = increments.map(Whole::get);
    let replicates = replicates.map(Whole::get);
    let max_iterations = max_iterations.get();
    let starts = starts.get();
    let options =
        Keywords { samples, sampler, seed, shard, increments, path_tolerance, replicates }
            .options()?;
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let report = crate::run::interruptible(py, jobs, move || {
        let (base, coupling) = parse_scene(&text, &file)?;
        let varied: Vec<String> =
            vary.iter().filter_map(|v| v.split_once('=').map(|(p, _)| p.trim().into())).collect();
        let mut spec = OptimizeSpec::new(&file, &text, &vary, Goals::default(), max_iterations)?;
        spec.starts = starts;
        spec.shard = options.shard;
        let objectives: Vec<String> = objective.into_iter().collect();
        let asked = (objectives.as_slice(), constraints.as_slice());
        spec.goals = Goals::asked(asked, (&spec.base, &file, &text), &base, &varied)?;
        let plan = study_plan(base, coupling, &options)?;
        Ok(run(&spec, &plan, &|| {})?)
    })?;
    Ok(Optimization { report })
}
