//! `sweep`, `Sweep` (the sweep document, with numpy views over its design
//! points) and the merge of sweep shards, as `kinrepro sweep` runs them.

use kinrepro::error::parse_scene;
use kinrepro::explore::goal::Goals;
use kinrepro::explore::run::{run, study_plan};
use kinrepro::explore::{
    DesignKind, SweepReport, SweepSpec, SweptValue, merge_sweeps as lib_merge,
};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;

use crate::err;
use crate::options::Keywords;
use crate::scene::{Scene, pose_rows};
use crate::study::to_python;
use crate::whole::Whole;

/// A sweep over scene fields: the document of `kinrepro sweep --format json`.
#[pyclass(module = "kinrepro", frozen)]
pub struct Sweep {
    report: SweepReport,
}

#[pymethods]
impl Sweep {
    /// Read a sweep document (`kinrepro sweep --format json`).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Sweep> {
        let report = serde_json::from_str(text)
            .map_err(|e| err(format!("not a kinrepro sweep JSON: {e}")))?;
        Ok(Sweep { report })
    }

    /// The document of `kinrepro sweep --format json`.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report).map_err(err)
    }

    /// The whole document as Python objects (`json.loads(to_json())`):
    /// `designs` holds one entry per design point with its values, sigma
    /// (nm, nrad), stiffness, safety and Pareto flag.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report)
    }

    /// The text table of `kinrepro sweep`.
    fn table(&self) -> String {
        self.report.table()
    }

    /// The CSV of `kinrepro sweep --format csv` (one row per design point).
    fn csv(&self) -> String {
        self.report.csv()
    }

    /// The swept fields (TOML paths, e.g. `preload.force`): the columns of
    /// `values()`.
    fn names(&self) -> Vec<String> {
        self.report.sets.iter().map(|s| s.field.clone()).collect()
    }

    /// Value of each swept field per design point, (n_designs, k) in the
    /// scene file's units (SI: N, m, ...); NaN for a field swept over names
    /// (materials, arrangements: see `to_dict()`).
    fn values<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let (d, names) = (&self.report.designs, self.names());
        Array2::from_shape_fn((d.len(), names.len()), |(i, j)| match d[i].values.get(&names[j]) {
            Some(SweptValue::Number(v)) => *v,
            _ => f64::NAN,
        })
        .into_pyarray(py)
    }

    /// Row of each design point in the whole design (a shard holds some).
    fn indices(&self) -> Vec<usize> {
        self.report.designs.iter().map(|d| d.index).collect()
    }

    /// `"ok"`, or why the design point was not evaluated, per design point.
    fn status(&self) -> Vec<String> {
        self.report.designs.iter().map(|d| d.status.clone()).collect()
    }

    /// Sample standard deviation (n - 1) of each DOF at evaluation point
    /// `point` (None: the Pareto point, by default the scene's first) per
    /// design point, (n_designs, 6): x, y, z [m], phi_x, phi_y, phi_z
    /// [rad]; a row of NaN where the point was not evaluated (`status()`).
    #[pyo3(signature = (point = None))]
    fn sigma<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let name = point.unwrap_or(&self.report.pareto_point);
        let d = &self.report.designs;
        let mut rows = Vec::with_capacity(d.len());
        for design in d {
            let row = match design.points.iter().find(|p| p.name == name) {
                Some(p) => p.sigma.si(),
                None if design.points.is_empty() => [f64::NAN; 6],
                None => {
                    let have: Vec<&str> = design.points.iter().map(|p| p.name.as_str()).collect();
                    return Err(err(format!("point {name:?}: not in this sweep (have {have:?})")));
                }
            };
            rows.push(row);
        }
        Ok(pose_rows(rows.into_iter()).into_pyarray(py))
    }

    fn __len__(&self) -> usize {
        self.report.designs.len()
    }

    fn __eq__(&self, other: &Sweep) -> bool {
        self.report == other.report
    }

    fn __reduce__(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, (String,))> {
        let ctor = py.get_type::<Sweep>().getattr("from_json")?.unbind();
        Ok((ctor, (self.to_json()?,)))
    }
}

/// `kinrepro merge` of sweep parts.
pub fn merge_sweeps(py: Python<'_>, parts: &[Bound<'_, PyAny>]) -> PyResult<Py<PyAny>> {
    let docs = crate::study::parts_of(parts, "a Sweep", |s: &Sweep| &s.report)?;
    let merged = py.detach(move || lib_merge(docs)).map_err(err)?;
    Ok(Py::new(py, Sweep { report: merged })?.into_any())
}

/// A sweep (`kinrepro sweep`); `sets`: the swept fields as `FIELD=VALUES`
/// strings. Each design point's study (friction varied, quasi-static) is
/// planned and checked by the library, as the CLI's.
#[pyfunction]
#[pyo3(signature = (
    scene, sets, points = None, pareto_point = None, samples = None, sampler = None,
    seed = None, shard = None, jobs = None, increments = None, path_tolerance = None,
    replicates = None, objectives = Vec::new(), constraints = Vec::new(),
))]
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    py: Python<'_>,
    scene: &Scene,
    sets: Vec<String>,
    points: Option<Whole<usize>>,
    pareto_point: Option<String>,
    samples: Option<Whole<usize>>,
    sampler: Option<String>,
    seed: Option<Whole<u64>>,
    shard: Option<&Bound<'_, PyAny>>,
    jobs: Option<Whole<usize>>,
    increments: Option<Whole<usize>>,
    path_tolerance: Option<f64>,
    replicates: Option<Whole<usize>>,
    objectives: Vec<String>,
    constraints: Vec<String>,
) -> PyResult<Sweep> {
    let points = points.map(Whole::get);
    let samples = samples.map(Whole::get);
    let seed = seed.map(Whole::get);
    let jobs = jobs.map(Whole::get);
    let increments = increments.map(Whole::get);
    let replicates = replicates.map(Whole::get);
    let options =
        Keywords { samples, sampler, seed, shard, increments, path_tolerance, replicates }
            .options()?;
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let report = crate::run::interruptible(py, jobs, move || {
        let (base, coupling) = parse_scene(&text, &file)?;
        let design = DesignKind::new(points, options.seed, &base);
        let spec = SweepSpec::new(&file, &text, &sets, design)?;
        let goals = Goals::asked(
            (&objectives, &constraints),
            (&spec.base, &file, &text),
            &base,
            &spec.paths(),
        )?;
        let plan = study_plan(base, coupling, &options)?;
        let tick = &|| {};
        let report = run(&spec, &plan, options.shard, (pareto_point.as_deref(), &goals), tick)?;
        // No design point evaluated: an error, as the CLI's exit 1, not a
        // table of NaN rows.
        report.check_any_valid()?;
        Ok(report)
    })?;
    Ok(Sweep { report })
}
