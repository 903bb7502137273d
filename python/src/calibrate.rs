//! `calibrate` (with `Calibration`) and `predict` (with `Prediction`), as
//! `kinrepro calibrate` and `kinrepro predict` run them; the measured
//! cycles come from a file or from a numpy array in SI.

use kinrepro::calibrate::fit::{CalibrateOptions, Calibration as LibCalibration};
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED, check_model_samples};
use kinrepro::calibrate::{Measurement, predict as predict_one};
use kinrepro::dof::{Dof, Dofs};
use kinrepro::error::parse_scene;
use kinrepro::param::Param;
use kinrepro::report::calibration::PredictionReport;
use kinrepro::solve::Solver;
use kinrepro::study::PointStats;
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray2, PyArray3, PyReadonlyArray2};
use pyo3::prelude::*;

use crate::err;
use crate::run::Failure;
use crate::scene::{Scene, pose_rows};
use crate::study::to_python;
use crate::whole::Whole;

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
        to_python(py, &self.cal)
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

/// The measured cycles of `measured`: a file (read by the library, with
/// `delimiter`), or an (n, k) array of readings in m and rad whose columns
/// are the DOFs `dofs` (None: all six, x, y, z, phi_x, phi_y, phi_z).
enum Measured {
    File(std::path::PathBuf, Option<u8>),
    Array(Box<Measurement>),
}

impl Measured {
    fn new(
        measured: &Bound<'_, PyAny>,
        dofs: Option<Vec<String>>,
        delimiter: Option<String>,
        point: Option<String>,
    ) -> PyResult<Measured> {
        let delimiter = (delimiter.as_deref())
            .map(kinrepro::delimited::delimiter_named)
            .transpose()
            .map_err(err)?;
        if let Ok(path) = measured.extract::<std::path::PathBuf>() {
            if dofs.is_some() {
                return Err(err(
                    "dofs: names the columns of an array; a file's header names its own",
                ));
            }
            return Ok(Measured::File(path, delimiter));
        }
        if delimiter.is_some() {
            return Err(err(format!(
                "{}: applies to a measurement file, not to an array",
                Param::Delimiter
            )));
        }
        let np = measured.py().import("numpy")?;
        let array = np.call_method1("asarray", (measured, "float64"))?;
        let a: PyReadonlyArray2<f64> = array.extract().map_err(|_| {
            err("measured: give a measurement file's path or an (n, k) array of readings in m and rad")
        })?;
        let a = a.as_array();
        let dofs = match dofs {
            None if a.ncols() == 6 => Dof::ALL.to_vec(),
            None => {
                return Err(err(format!(
                    "dofs: name the DOF of each of the {} columns (any of {})",
                    a.ncols(),
                    Dof::names()
                )));
            }
            Some(names) => names
                .iter()
                .map(|n| {
                    Dof::from_name(n).ok_or_else(|| {
                        err(format!("dofs: unknown DOF `{n}` (one of {})", Dof::names()))
                    })
                })
                .collect::<PyResult<Vec<_>>>()?,
        };
        let rows = a.rows().into_iter().map(|r| r.to_vec()).collect();
        Measurement::from_cycles("measured array", point, &dofs, rows, [None; 6])
            .map(|m| Measured::Array(Box::new(m)))
            .map_err(err)
    }

    fn load(self) -> Result<Measurement, Failure> {
        match self {
            Measured::File(path, delimiter) => Ok(Measurement::load(&path, delimiter)?),
            Measured::Array(m) => Ok(*m),
        }
    }
}

/// Fit the scale of the friction distribution (spread or sd, the default)
/// and optionally mu_static, dynamic_ratio, support_compliance to a
/// measured scatter (`kinrepro calibrate`): a
/// file, or an (n, k) array of readings per cycle in m and rad.
#[pyfunction]
#[pyo3(signature = (
    scene, measured, fit = Vec::new(), noise = None, point = None,
    model_samples = Whole::of(MODEL_SAMPLES), seed = Whole::of(MODEL_SEED), delimiter = None, jobs = None, dofs = None,
))]
#[allow(clippy::too_many_arguments)]
pub fn calibrate(
    py: Python<'_>,
    scene: &Scene,
    measured: &Bound<'_, PyAny>,
    fit: Vec<String>,
    noise: Option<String>,
    point: Option<String>,
    model_samples: Whole<usize>,
    seed: Whole<u64>,
    delimiter: Option<String>,
    jobs: Option<Whole<usize>>,
    dofs: Option<Vec<String>>,
) -> PyResult<Calibration> {
    let model_samples = model_samples.get();
    let seed = seed.get();
    let jobs = jobs.map(Whole::get);
    let samples = check_model_samples(Param::ModelSamples, model_samples).map_err(err)?;
    let mut noise_si = [None; 6];
    if let Some(n) = &noise {
        kinrepro::calibrate::units::parse_noise(n, &mut noise_si)
            .map_err(|e| err(format!("{}: {e}", Param::Noise)))?;
    }
    let measured = Measured::new(measured, dofs, delimiter, point.clone())?;
    let options = CalibrateOptions {
        fit: fit.iter().map(|s| s.trim().to_string()).collect(),
        noise: noise_si,
        point,
        samples,
        seed,
        solver: Solver::QuasiStatic,
    };
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let cal = crate::run::interruptible(py, jobs, move || {
        let (scene, c) = parse_scene(&text, &file)?;
        let m = measured.load()?;
        Ok(kinrepro::calibrate::calibrate(&scene, &c, &m, &options)?)
    })?;
    Ok(Calibration { cal, file: "<calibrate>".into() })
}

/// Predictions of other designs from a calibration (`kinrepro predict`):
/// the document of `predict --format json`, with numpy views of sigma.
#[pyclass(module = "kinrepro", frozen)]
pub struct Prediction {
    report: PredictionReport,
}

impl Prediction {
    /// The statistics of `point` (None: the first) for every scene.
    fn points(&self, point: Option<&str>) -> PyResult<Vec<&PointStats>> {
        let p = &self.report.predictions;
        p.iter()
            .map(|p| {
                let pts = &p.variant.points;
                match point {
                    None => pts.first(),
                    Some(name) => pts.iter().find(|s| s.name == name),
                }
                .ok_or_else(|| err(format!("point {point:?}: not in {}", p.variant.scene)))
            })
            .collect()
    }
}

#[pymethods]
impl Prediction {
    /// The document of `kinrepro predict --format json`.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report.document()).map_err(err)
    }

    /// The whole document as Python objects (as `json.loads(to_json())`
    /// reads it).
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        to_python(py, &self.report.document())
    }

    /// The text table of `kinrepro predict`.
    fn table(&self) -> String {
        self.report.table()
    }

    /// The scene file of each prediction (rows of `sigma()`).
    fn scenes(&self) -> Vec<String> {
        let p = &self.report.predictions;
        p.iter().map(|p| p.variant.scene.clone()).collect()
    }

    /// Predicted sigma of each DOF at `point` (None: the first evaluation
    /// point) per scene, (n_scenes, 6): x, y, z [m], phi_x, phi_y, phi_z [rad].
    #[pyo3(signature = (point = None))]
    fn sigma<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        Ok(pose_rows(self.points(point)?.iter().map(|p| p.sigma.si())).into_pyarray(py))
    }

    /// The 90 % prediction interval of sigma at `point` per scene,
    /// (n_scenes, 2, 6): low and high, m and rad (NaN where there is none).
    #[pyo3(signature = (point = None))]
    fn interval<'py>(
        &self,
        py: Python<'py>,
        point: Option<&str>,
    ) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let si = |d: &Option<Dofs>| d.as_ref().map_or([f64::NAN; 6], Dofs::si);
        let rows: Vec<[[f64; 6]; 2]> = (self.points(point)?.iter())
            .map(|p| [si(&p.sigma_ci90_low), si(&p.sigma_ci90_high)])
            .collect();
        Ok(Array3::from_shape_fn((rows.len(), 2, 6), |(i, k, j)| rows[i][k][j]).into_pyarray(py))
    }

    fn __len__(&self) -> usize {
        self.report.predictions.len()
    }
}

/// Predict the scatter of other designs from a calibration
/// (`kinrepro predict`).
#[pyfunction]
#[pyo3(signature = (scenes, calibration, samples = Whole::of(MODEL_SAMPLES), seed = Whole::of(MODEL_SEED), jobs = None))]
pub fn predict(
    py: Python<'_>,
    scenes: &Bound<'_, PyAny>,
    calibration: &Calibration,
    samples: Whole<usize>,
    seed: Whole<u64>,
    jobs: Option<Whole<usize>>,
) -> PyResult<Prediction> {
    let samples = samples.get();
    let seed = seed.get();
    let jobs = jobs.map(Whole::get);
    let samples = check_model_samples(Param::Samples, samples).map_err(err)?;
    let scenes = crate::scene::scenes(scenes, "scenes")?;
    let cal = calibration.cal.clone();
    let file = calibration.file.clone();
    let report = crate::run::interruptible(py, jobs, move || {
        let predictions = scenes
            .iter()
            .map(|s| {
                let (scene, c) = parse_scene(&s.text, &s.file)?;
                let studies = (samples, seed, Solver::QuasiStatic);
                Ok(predict_one(&scene, &c, &cal, &file, studies)?)
            })
            .collect::<Result<Vec<_>, Failure>>()?;
        Ok(PredictionReport { calibration_file: file, calibration: cal, predictions })
    })?;
    Ok(Prediction { report })
}
