//! `study`, `Study` (the study document) and `merge`.

use kinrepro::dof::Dof;
use kinrepro::scene::point::{ABOUT, ALONG};
use kinrepro::study::{StudyPlan, StudyReport};
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::err;
use crate::options::Keywords;
use crate::whole::Whole;
use kinrepro::error::parse_scene;
use kinrepro::solve::quasistatic::Lanes;
use kinrepro::study::StudyOptions;

/// A reproducibility study: the document of `kinrepro study --format json`
/// (`to_json`), with numpy views of its samples.
#[pyclass(module = "kinrepro", frozen)]
pub struct Study {
    pub report: StudyReport,
}

/// A document as Python objects (dicts, lists, numbers, strings, None),
/// built from its serde form without JSON text: through its JSON data
/// model (`serde_json::Value`: a fixed-size array is a list, a non-finite
/// number None, as in its JSON), so that it equals `json.loads` of its
/// JSON.
pub fn to_python<'py, T: serde::Serialize>(py: Python<'py>, v: &T) -> PyResult<Bound<'py, PyAny>> {
    let value = serde_json::to_value(v).map_err(err)?;
    pythonize::pythonize(py, &value).map_err(err)
}

/// No records are kept: the records a study needs to answer `what`.
fn no_records(what: &str) -> PyErr {
    err(format!(
        "{what}: this study keeps no samples (a Monte Carlo study above 100000 samples is streamed); run it in shards to keep them"
    ))
}

impl Study {
    fn variant(&self, i: usize) -> PyResult<&kinrepro::study::VariantReport> {
        let n = self.report.variants.len();
        self.report
            .variants
            .get(i)
            .ok_or_else(|| err(format!("variant={i}: the study has {n} scene(s)")))
    }
}

#[pymethods]
impl Study {
    /// Read a study document (`kinrepro study --format json`, a shard or
    /// a merge).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Study> {
        let report = serde_json::from_str(kinrepro::input::without_bom(text))
            .map_err(|e| err(format!("not a kinrepro study JSON: {e}")))?;
        // Checked as `report` and `merge` check a document: ranges, and the
        // statistics against the records they come from.
        kinrepro::study::validate::check_document(&report).map_err(err)?;
        Ok(Study { report })
    }

    /// The document of `kinrepro study --format json` with the same options.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report).map_err(err)
    }

    /// The text table of `kinrepro study` (sigma in nm and nrad).
    fn table(&self) -> String {
        self.report.table()
    }

    /// The summary CSV of `kinrepro study --format csv` (SI).
    fn csv(&self) -> String {
        self.report.csv()
    }

    /// Seated pose of evaluation point `point` (None: the first, the
    /// centre) for every sample, relative to the nominal seating:
    /// (n, 6) array of x, y, z [m], phi_x, phi_y, phi_z [rad], in sample
    /// order. `interchange=True`: the interchangeability outputs
    /// (tolerances varied).
    #[pyo3(signature = (point = None, variant = Whole::of(0), interchange = false))]
    fn poses<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
        variant: Whole<usize>,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let variant = variant.get();
        let v = self.variant(variant)?;
        let point = match point {
            Some(p) => p.to_string(),
            None => match v.output_names.first() {
                Some(n) => n
                    .trim_start_matches(kinrepro::study::runner::INTERCHANGE_PREFIX)
                    .split('/')
                    .next()
                    .unwrap_or_default()
                    .to_string(),
                None => return Err(err("the study has no outputs")),
            },
        };
        let prefix = if interchange { kinrepro::study::runner::INTERCHANGE_PREFIX } else { "" };
        let cols = Dof::ALL
            .iter()
            .map(|d| {
                let name = format!("{prefix}{point}/{}", d.si_key());
                v.output_names
                    .iter()
                    .position(|n| *n == name)
                    .ok_or_else(|| err(format!("point {point:?}: no output {name} in this study")))
            })
            .collect::<PyResult<Vec<usize>>>()?;
        if v.records.is_empty() && v.streamed {
            return Err(no_records("poses"));
        }
        let r = &v.records;
        Ok(Array2::from_shape_fn((r.len(), 6), |(i, j)| r[i].outputs[cols[j]]).into_pyarray(py))
    }

    /// The translation of `point` (None: the first point with the
    /// direction) along its direction `direction` per sample [m] (n,), in
    /// sample order: the projection of the pose on the direction's unit
    /// vector, whose statistics are `stats(point)["directions"]`.
    #[pyo3(signature = (direction, point = None, variant = Whole::of(0), interchange = false))]
    fn along<'py>(
        &self,
        py: Python<'py>,
        direction: &str,
        point: Option<&str>,
        variant: Whole<usize>,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.direction_values(py, (ALONG, direction), point, variant.get(), interchange)
    }

    /// The rotation of the moving half about a frame's axis `direction`
    /// (e.g. `"tool.z"`) at `point` per sample [rad] (n,), as `along`.
    #[pyo3(signature = (direction, point = None, variant = Whole::of(0), interchange = false))]
    fn about<'py>(
        &self,
        py: Python<'py>,
        direction: &str,
        point: Option<&str>,
        variant: Whole<usize>,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        self.direction_values(py, (ABOUT, direction), point, variant.get(), interchange)
    }

    /// A study of a scene with `[thermal]`: each sample's drift of
    /// evaluation point `point` (None: the first) from its own seated pose
    /// at each cycle point, (n, n_cycle_points, 6): x, y, z [m], phi_x,
    /// phi_y, phi_z [rad], in sample order (the cycle's temperatures:
    /// `stats(point)["thermal"][k]["delta_t_k"]`).
    #[pyo3(signature = (point = None, variant = Whole::of(0)))]
    fn drift<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
        variant: Whole<usize>,
    ) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let variant = variant.get();
        let v = self.variant(variant)?;
        let cycle = v.thermal_cycle().len();
        if cycle == 0 {
            return Err(err("the study's scene has no [thermal] cycle"));
        }
        let point = match point {
            Some(p) => p.to_string(),
            None => v.points.first().map(|p| p.name.clone()).unwrap_or_default(),
        };
        let prefix = kinrepro::study::runner::THERMAL_PREFIX;
        let mut cols = Vec::with_capacity(6 * cycle);
        for k in 1..=cycle {
            for d in Dof::ALL {
                let name = format!("{prefix}{k}/{point}/{}", d.si_key());
                let j = v.output_names.iter().position(|n| *n == name);
                cols.push(j.ok_or_else(|| err(format!("point {point:?}: no output {name}")))?);
            }
        }
        if v.records.is_empty() && v.streamed {
            return Err(no_records("drift"));
        }
        let r = &v.records;
        let value = |(i, k, j): (usize, usize, usize)| r[i].outputs[cols[6 * k + j]];
        Ok(Array3::from_shape_fn((r.len(), cycle, 6), value).into_pyarray(py))
    }

    /// The physical value of every varied input per sample, (n, k) in SI
    /// (mu dimensionless, m, rad); columns named by `input_names()`.
    #[pyo3(signature = (variant = Whole::of(0)))]
    fn inputs<'py>(
        &self,
        py: Python<'py>,
        variant: Whole<usize>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let variant = variant.get();
        let v = self.variant(variant)?;
        if v.records.is_empty() && v.streamed {
            return Err(no_records("inputs"));
        }
        let (r, k) = (&v.records, v.inputs.len());
        Ok(Array2::from_shape_fn((r.len(), k), |(i, j)| r[i].physical[j]).into_pyarray(py))
    }

    /// Names of the columns of `inputs()` (`mu_1`, `offset_x_m`, ...).
    #[pyo3(signature = (variant = Whole::of(0)))]
    fn input_names(&self, variant: Whole<usize>) -> PyResult<Vec<String>> {
        let variant = variant.get();
        Ok(self.variant(variant)?.inputs.iter().map(|i| i.name()).collect())
    }

    /// Sample index of every row of `poses()` and `inputs()`.
    #[pyo3(signature = (variant = Whole::of(0)))]
    fn indices(&self, variant: Whole<usize>) -> PyResult<Vec<usize>> {
        let variant = variant.get();
        Ok(self.variant(variant)?.records.iter().map(|r| r.index).collect())
    }

    /// Sample standard deviation (n - 1) of each DOF at `point` (None: the
    /// first): a (6,) array x, y, z [m], phi_x, phi_y, phi_z [rad], as
    /// `Sweep.sigma` and `Prediction.sigma` give theirs (`stats()` has the
    /// JSON's nm and nrad). A shard has none (merge first).
    #[pyo3(signature = (point = None, variant = Whole::of(0), interchange = false))]
    fn sigma<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
        variant: Whole<usize>,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let variant = variant.get();
        let p = self.point_stats_of(point, variant, interchange)?;
        let array = numpy::PyArray1::from_vec(py, p.sigma.si().to_vec());
        // The array answers the old dict keys, deprecated (kinrepro._sigma).
        py.import("kinrepro._sigma")?.getattr("Sigma")?.call1((array,))
    }

    /// All statistics of `point` as in the JSON's `points` entry (n, sigma,
    /// its 90 % interval, three_sigma, mean, min, max; nm and nrad).
    #[pyo3(signature = (point = None, variant = Whole::of(0), interchange = false))]
    fn stats<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
        variant: Whole<usize>,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let variant = variant.get();
        let p = self.point_stats_of(point, variant, interchange)?;
        to_python(py, p)
    }

    /// The whole document as Python objects (`json.loads(to_json())`).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report)
    }

    /// Number of scenes (variants) in the document.
    fn __len__(&self) -> usize {
        self.report.variants.len()
    }

    /// `(index, count)` of this shard ((1, 1): the whole study).
    #[getter]
    fn shard(&self) -> (usize, usize) {
        (self.report.shard.index, self.report.shard.count)
    }

    fn __repr__(&self) -> String {
        let names: Vec<&str> = self.report.variants.iter().map(|v| v.scene.as_str()).collect();
        let r = &self.report;
        let or_none = |v: Option<String>| v.unwrap_or_else(|| "None".into());
        format!(
            "Study(scenes={names:?}, samples={}, sampler={}, seed={}, shard=\"{}\")",
            or_none(r.samples.map(|n| n.to_string())),
            or_none(r.sampler.and_then(|s| serde_json::to_string(&s).ok())),
            or_none(r.seed.map(|n| n.to_string())),
            r.shard
        )
    }

    fn __eq__(&self, other: &Study) -> bool {
        self.report == other.report
    }

    fn __reduce__(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, (String,))> {
        let ctor = py.get_type::<Study>().getattr("from_json")?.unbind();
        Ok((ctor, (self.to_json()?,)))
    }
}

impl Study {
    /// The values of the output `<point>/<kind><direction>_<unit>` per
    /// sample (`along`, `about`).
    fn direction_values<'py>(
        &self,
        py: Python<'py>,
        (kind, direction): (&str, &str),
        point: Option<&str>,
        variant: usize,
        interchange: bool,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let v = self.variant(variant)?;
        let prefix = if interchange { kinrepro::study::runner::INTERCHANGE_PREFIX } else { "" };
        let unit = if kind == ABOUT { "rad" } else { "m" };
        let tail = format!("/{kind}{direction}_{unit}");
        let column = v.output_names.iter().position(|n| {
            n.strip_prefix(prefix).and_then(|n| n.strip_suffix(&tail)).is_some_and(|p| {
                point.map_or(!p.contains("thermal/") && !p.starts_with("interchange/"), |q| p == q)
            })
        });
        let Some(k) = column else {
            let at = point.map_or("any point".to_string(), |p| format!("point {p:?}"));
            let what = kind.trim_end_matches('/');
            return Err(err(format!(
                "{what} {direction:?}: no such direction at {at} in this study"
            )));
        };
        if v.records.is_empty() && v.streamed {
            return Err(no_records(kind.trim_end_matches('/')));
        }
        let values: Vec<f64> =
            v.records.iter().filter(|r| r.centred()).map(|r| r.outputs[k]).collect();
        Ok(PyArray1::from_vec(py, values))
    }

    fn point_stats_of(
        &self,
        point: Option<&str>,
        variant: usize,
        interchange: bool,
    ) -> PyResult<&kinrepro::study::PointStats> {
        let v = self.variant(variant)?;
        let list = if interchange { &v.interchangeability } else { &v.points };
        if v.partial {
            return Err(err(
                "this is one shard of a study: its statistics wait for kinrepro.merge of all shards",
            ));
        }
        match point {
            None => list.first(),
            Some(p) => list.iter().find(|s| s.name == p),
        }
        .ok_or_else(|| {
            let have: Vec<&str> = list.iter().map(|s| s.name.as_str()).collect();
            err(format!("point {point:?}: not in this study (have {have:?})"))
        })
    }
}

/// Run a reproducibility study of one scene or a list of scenes
/// (`kinrepro study`): the library's `StudyPlan` checks the options and
/// runs the study, as for the CLI; see the stub for the arguments.
#[pyfunction]
#[pyo3(signature = (
    scene, samples = None, sampler = None, seed = None, vary = vec!["friction".to_string()],
    shard = None, jobs = None, solver = "quasi-static".to_string(), increments = None,
    path_tolerance = None, replicates = None, sensitivity = false, sobol_samples = None, offset_bounds = None,
    tilt_bounds = None, lanes = "auto".to_string(),
))]
#[allow(clippy::too_many_arguments)]
pub fn study(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    samples: Option<Whole<usize>>,
    sampler: Option<String>,
    seed: Option<Whole<u64>>,
    vary: Vec<String>,
    shard: Option<&Bound<'_, PyAny>>,
    jobs: Option<Whole<usize>>,
    solver: String,
    increments: Option<Whole<usize>>,
    path_tolerance: Option<f64>,
    replicates: Option<Whole<usize>>,
    sensitivity: bool,
    sobol_samples: Option<Whole<usize>>,
    offset_bounds: Option<[f64; 3]>,
    tilt_bounds: Option<[f64; 3]>,
    lanes: String,
) -> PyResult<Study> {
    let samples = samples.map(Whole::get);
    let seed = seed.map(Whole::get);
    let jobs = jobs.map(Whole::get);
    let increments = increments.map(Whole::get);
    let replicates = replicates.map(Whole::get);
    let sobol_samples = sobol_samples.map(Whole::get);
    let scenes = crate::scene::scenes(scene, "scene")?;
    let (solver, vary) = crate::options::solver_and_vary(&solver, &vary)?;
    let options = StudyOptions {
        solver,
        vary,
        offset_bounds,
        tilt_bounds,
        sensitivity,
        sobol_samples,
        lanes: lanes.parse::<Lanes>().map_err(err)?,
        ..Keywords { samples, sampler, seed, shard, increments, path_tolerance, replicates }
            .options()?
    };
    let report = crate::run::interruptible(py, jobs, move || {
        let models =
            scenes.iter().map(|s| parse_scene(&s.text, &s.file)).collect::<Result<Vec<_>, _>>()?;
        let plan = StudyPlan::new(models, &options)?;
        let (report, _) = plan.run::<NoSink>(&|| {}, |_, _| Ok(None))?;
        Ok(report)
    })?;
    Ok(Study { report })
}

/// A streamed study's records are dropped (the moments are kept).
struct NoSink;

impl kinrepro::study::stream::RecordSink for NoSink {
    type Error = std::io::Error;
    fn push(&mut self, _: &kinrepro::study::StudyRecord) -> Result<(), Self::Error> {
        Ok(())
    }
}

/// The parts of a merge as `(label, document)`: each must be a `T` (named
/// `kind` in the error), its document read by `report`.
pub(crate) fn parts_of<T, R>(
    parts: &[Bound<'_, PyAny>],
    kind: &str,
    report: impl Fn(&T) -> &R,
) -> PyResult<Vec<(String, R)>>
where
    T: pyo3::PyClass<Frozen = pyo3::pyclass::boolean_struct::True> + Sync,
    R: Clone,
{
    parts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let part = p.cast::<T>().map_err(|_| err(format!("merge: part {i} is not {kind}")))?;
            Ok((format!("part {}", i + 1), report(part.get()).clone()))
        })
        .collect()
}

/// Merge shards of a study (`kinrepro merge`): a list of `Study` (or JSON
/// texts); the result equals the unsharded run. Sweep shards: a list of
/// `Sweep`; optimisation shards: a list of `Optimization`.
#[pyfunction]
pub fn merge(py: Python<'_>, parts: Vec<Bound<'_, PyAny>>) -> PyResult<Py<PyAny>> {
    if parts.is_empty() {
        return Err(err("merge: give at least one part"));
    }
    if parts[0].extract::<PyRef<crate::sweep::Sweep>>().is_ok() {
        return crate::sweep::merge_sweeps(py, &parts);
    }
    if parts[0].extract::<PyRef<crate::optimize::Optimization>>().is_ok() {
        return crate::optimize::merge_optimizations(py, &parts);
    }
    let docs = parts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let report = if let Ok(s) = p.cast::<Study>() {
                s.get().report.clone()
            } else if let Ok(text) = p.extract::<String>() {
                Study::from_json(&text)?.report
            } else {
                return Err(err(format!("merge: part {i} is neither a Study nor JSON text")));
            };
            Ok((format!("part {}", i + 1), report))
        })
        .collect::<PyResult<Vec<_>>>()?;
    let merged = py.detach(move || kinrepro::study::merge::merge_parts(docs)).map_err(err)?;
    Ok(Py::new(py, Study { report: merged })?.into_any())
}
