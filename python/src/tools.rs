//! `sweep` (with `Sweep` and its merge), `calibrate` (with `Calibration`)
//! and `predict`, as the CLI's verbs run them.

use kinrepro::calibrate::Measurement;
use kinrepro::calibrate::fit::Calibration as LibCalibration;
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED};
use kinrepro::explore::run::run;
use kinrepro::explore::{DesignKind, SweepReport, SweepSpec, merge_sweeps as lib_merge_sweeps};
use kinrepro::report::calibration::PredictionReport;
use kinrepro::solve::Method;
use pyo3::prelude::*;

use crate::err;
use crate::options::StudyArgs;
use crate::scene::{Scene, coupling};

fn json_loads<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}

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
        json_loads(py, &self.to_json()?)
    }

    /// The text table of `kinrepro sweep`.
    fn table(&self) -> String {
        self.report.table()
    }

    /// The CSV of `kinrepro sweep --format csv` (one row per design point).
    fn csv(&self) -> String {
        self.report.csv()
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
    let docs = parts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let s = p
                .cast::<Sweep>()
                .map_err(|_| err(format!("merge: part {i} is not a Sweep")))?;
            Ok((format!("part {}", i + 1), s.get().report.clone()))
        })
        .collect::<PyResult<Vec<_>>>()?;
    let merged = py.detach(move || lib_merge_sweeps(docs)).map_err(err)?;
    Ok(Py::new(py, Sweep { report: merged })?.into_any())
}

/// A sweep (`kinrepro sweep`); `sets`: the `--set` arguments as
/// `FIELD=VALUES` strings.
#[pyfunction]
#[pyo3(signature = (
    scene, sets, points = None, pareto_point = None, samples = None, sampler = None,
    seed = None, shard = None, jobs = None, increments = 20, replicates = None,
))]
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    py: Python<'_>,
    scene: &Scene,
    sets: Vec<String>,
    points: Option<usize>,
    pareto_point: Option<String>,
    samples: Option<usize>,
    sampler: Option<String>,
    seed: Option<u64>,
    shard: Option<&Bound<'_, PyAny>>,
    jobs: Option<usize>,
    increments: usize,
    replicates: Option<usize>,
) -> PyResult<Sweep> {
    let opts = StudyArgs {
        samples,
        sampler,
        seed,
        vary: vec!["friction".to_string()],
        shard: crate::options::shard(shard)?,
        solver: "quasi-static".to_string(),
        increments,
        replicates,
        sensitivity: false,
        offset_bounds: None,
        tilt_bounds: None,
    }
    .options()?;
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let report = crate::run::interruptible(py, jobs, move |tick| {
        let base = coupling(&text, &file)?;
        let design = match points {
            None => DesignKind::Grid,
            Some(points) => DesignKind::Lhs {
                points,
                seed: opts.seed.unwrap_or(base.scene.study.seed),
            },
        };
        let spec = SweepSpec::new(&file, &text, &sets, design).map_err(|e| e.to_string())?;
        run(&spec, &base, &opts, pareto_point.as_deref(), tick).map_err(|e| e.to_string())
    })?;
    Ok(Sweep { report })
}

/// A calibration (`kinrepro calibrate`): the fitted friction parameters
/// with their intervals; `to_json()` is the file `calibrate --out` writes.
#[pyclass(module = "kinrepro", frozen)]
pub struct Calibration {
    cal: LibCalibration,
    file: String,
}

#[pymethods]
impl Calibration {
    /// Read a calibration file's text (`kinrepro calibrate --out`).
    #[staticmethod]
    #[pyo3(signature = (text, file = "<string>".to_string()))]
    fn from_json(text: &str, file: String) -> PyResult<Calibration> {
        let cal = LibCalibration::parse(text, &file).map_err(err)?;
        Ok(Calibration { cal, file })
    }

    /// Read a calibration file.
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Calibration> {
        let file = path.display().to_string();
        let text = kinrepro::input::read_to_string(&path)
            .map_err(|e| err(format!("{file}: cannot read the file: {e}")))?;
        Calibration::from_json(&text, file)
    }

    /// The calibration file's JSON.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.cal).map_err(err)
    }

    /// The whole document as Python objects.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        json_loads(py, &self.to_json()?)
    }

    /// The fitted value of each parameter (`spread`, ...), SI.
    #[getter]
    fn estimates(&self) -> std::collections::BTreeMap<String, f64> {
        self.cal.estimates()
    }

    /// The text table of `kinrepro calibrate`.
    fn table(&self) -> String {
        kinrepro::report::calibration::calibration_table(&self.cal)
    }
}

/// Fit the friction spread (and optionally mu_static, dynamic_ratio,
/// support_compliance) to a measured scatter (`kinrepro calibrate`).
#[pyfunction]
#[pyo3(signature = (
    scene, measured, fit = vec!["spread".to_string()], noise = None, point = None,
    model_samples = MODEL_SAMPLES, seed = MODEL_SEED, delimiter = None, jobs = None,
))]
#[allow(clippy::too_many_arguments)]
pub fn calibrate(
    py: Python<'_>,
    scene: &Scene,
    measured: std::path::PathBuf,
    fit: Vec<String>,
    noise: Option<String>,
    point: Option<String>,
    model_samples: usize,
    seed: u64,
    delimiter: Option<String>,
    jobs: Option<usize>,
) -> PyResult<Calibration> {
    if model_samples < 100 {
        return Err(err(format!(
            "model_samples={model_samples}: need at least 100 samples"
        )));
    }
    let mut noise_si = [None; 6];
    if let Some(n) = &noise {
        kinrepro::calibrate::units::parse_noise(n, &mut noise_si)
            .map_err(|e| err(format!("noise: {e}")))?;
    }
    let delimiter = match delimiter.as_deref() {
        None => None,
        Some("tab" | "\\t" | "\t") => Some(b'\t'),
        Some("comma") => Some(b','),
        Some("semicolon") => Some(b';'),
        Some(s) if s.len() == 1 && s.is_ascii() && s != "\"" && s != "#" => Some(s.as_bytes()[0]),
        Some(s) => {
            return Err(err(format!(
                "delimiter {s:?}: give one character such as \",\" or \";\", or \"tab\""
            )));
        }
    };
    let options = kinrepro::calibrate::fit::CalibrateOptions {
        fit: fit.iter().map(|s| s.trim().to_string()).collect(),
        noise: noise_si,
        point,
        samples: model_samples,
        seed,
        method: Method::default(),
    };
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let cal = crate::run::interruptible(py, jobs, move |_tick| {
        let c = coupling(&text, &file)?;
        let m = Measurement::load(&measured, delimiter).map_err(|e| e.to_string())?;
        kinrepro::calibrate::calibrate(&c, &m, &options).map_err(|e| e.to_string())
    })?;
    Ok(Calibration {
        cal,
        file: "<calibrate>".into(),
    })
}

/// Predict the scatter of other designs from a calibration
/// (`kinrepro predict --format json`): returns that document as a dict.
#[pyfunction]
#[pyo3(signature = (scenes, calibration, samples = MODEL_SAMPLES, seed = MODEL_SEED, jobs = None))]
pub fn predict<'py>(
    py: Python<'py>,
    scenes: &Bound<'py, PyAny>,
    calibration: &Calibration,
    samples: usize,
    seed: u64,
    jobs: Option<usize>,
) -> PyResult<Bound<'py, PyAny>> {
    if samples < 100 {
        return Err(err(format!("samples={samples}: need at least 100 samples")));
    }
    let scenes: Vec<Scene> = match scenes.extract::<Scene>() {
        Ok(s) => vec![s],
        Err(_) => scenes
            .extract()
            .map_err(|_| err("scenes: give a kinrepro.Scene or a list of them"))?,
    };
    let cal = calibration.cal.clone();
    let file = calibration.file.clone();
    let json = crate::run::interruptible(py, jobs, move |_tick| {
        let predictions = scenes
            .iter()
            .map(|s| {
                let c = coupling(&s.text, &s.file)?;
                kinrepro::calibrate::predict(&c, &cal, samples, seed, Method::default())
                    .map_err(|e| e.to_string())
            })
            .collect::<Result<Vec<_>, String>>()?;
        let report = PredictionReport {
            calibration_file: file,
            calibration: cal,
            predictions,
        };
        let v = report.json().map_err(|e| e.to_string())?;
        serde_json::to_string_pretty(&v).map_err(|e| e.to_string())
    })?;
    json_loads(py, &json)
}
