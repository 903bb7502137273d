//! `Scene` (a validated scene file's text), `seat` and `stiffness`.

use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::error::parse_scene;
use kinrepro::explore::field::{kind_of, set};
use kinrepro::explore::{FieldKind, SweptValue};
use kinrepro::report::coupling::analysis::StiffnessReport;
use kinrepro::report::seating::run::RunReport;
use kinrepro::scene::SceneFile;
use kinrepro::solve::{Load, SolverOptions};
use nalgebra::Vector3;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::prelude::*;

use crate::err;
use crate::run::Failure;
use crate::whole::Whole;

/// A kinematic coupling scene: the text of a scene file (TOML), validated
/// and assembled exactly like `kinrepro check` does. Immutable: `set`
/// returns a new scene.
#[pyclass(module = "kinrepro", frozen)]
#[derive(Clone)]
pub struct Scene {
    /// The TOML text.
    pub text: String,
    /// The file name used in messages and in the study document.
    pub file: String,
    name: String,
    points: Vec<String>,
}

impl Scene {
    pub fn new(text: String, file: String) -> PyResult<Scene> {
        let (s, _) = parse_scene(&text, &file).map_err(err)?;
        Ok(Scene {
            name: s.name.clone(),
            points: s.evaluation_points.iter().map(|p| p.name.clone()).collect(),
            text,
            file,
        })
    }
}

/// One `Scene` or a list of them (`what`: the argument's name).
pub fn scenes(arg: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Scene>> {
    let list: Vec<Scene> = match arg.extract::<Scene>() {
        Ok(s) => vec![s],
        Err(_) => arg
            .extract()
            .map_err(|_| err(format!("{what}: give a kinrepro.Scene or a list of them")))?,
    };
    if list.is_empty() {
        return Err(err(format!("{what}: an empty list; give at least one kinrepro.Scene")));
    }
    Ok(list)
}

#[pymethods]
impl Scene {
    /// Read and validate a scene file (TOML).
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Scene> {
        let file = path.display().to_string();
        let text = kinrepro::input::read_to_string(&path)
            .map_err(|e| err(format!("{file}: cannot read the file: {e}")))?;
        Scene::new(text, file)
    }

    /// A scene from TOML text; `file` names it in messages and outputs.
    #[staticmethod]
    #[pyo3(signature = (text, file = "<string>".to_string()))]
    fn from_toml(text: String, file: String) -> PyResult<Scene> {
        Scene::new(text, file)
    }

    /// The scene's TOML text (as loaded, or as rewritten by `set`).
    fn to_toml(&self) -> String {
        self.text.clone()
    }

    /// The explicit form of the scene (`kinrepro expand`): balls,
    /// surfaces and evaluation points written out.
    fn expand(&self) -> PyResult<String> {
        kinrepro::scene::Scene::expand_text(&self.text, &self.file).map_err(err)
    }

    /// A new scene with the field at TOML path `field` set to `value` (a
    /// number in SI units or a material name): the paths of
    /// `kinrepro sweep --set`, e.g. `preload.force` [N],
    /// `friction.mu_static`, `coupling.ball_radius` [m], `materials.NAME.KEY`.
    fn set(&self, field: &str, value: &Bound<'_, PyAny>) -> PyResult<Scene> {
        let mut typed = SceneFile::parse(&self.text, &self.file).map_err(err)?;
        let kind = kind_of(field, &typed).map_err(err)?;
        let v = match kind {
            // A bool is an int to Python (True == 1): not a number of a scene.
            FieldKind::Number if value.is_instance_of::<pyo3::types::PyBool>() => {
                return Err(err(format!("{field}: needs a number, got {value}")));
            }
            FieldKind::Number => SweptValue::Number(
                value
                    .extract::<f64>()
                    .map_err(|_| err(format!("{field}: needs a number, got {value}")))?,
            ),
            FieldKind::Material | FieldKind::Text => SweptValue::Name(
                value
                    .extract::<String>()
                    .map_err(|_| err(format!("{field}: needs a name, got {value}")))?,
            ),
        };
        set(&mut typed, field, &v).map_err(|e| err(format!("{field}: {e}")))?;
        let text = toml::to_string(&typed).map_err(err)?;
        // The set scene is new text: its line numbers are not the user's
        // file's, so an error names the set instead of a line.
        let (scene, _) = parse_scene(&text, &self.file).map_err(|e| match e {
            kinrepro::error::Error::Scene(s) => {
                err(format!("{}: after set({field:?}, {value}): {}: {}", s.file, s.field, s.reason))
            }
            other => err(format!("after set({field:?}, {value}): {other}")),
        })?;
        Ok(Scene {
            name: scene.name.clone(),
            points: scene.evaluation_points.iter().map(|p| p.name.clone()).collect(),
            text,
            file: self.file.clone(),
        })
    }

    /// The file name given at load (or `<string>`).
    #[getter]
    fn file(&self) -> String {
        self.file.clone()
    }

    /// The scene's `name`.
    #[getter]
    fn name(&self) -> String {
        self.name.clone()
    }

    /// Names of the evaluation points, the centre of the moving half first.
    #[getter]
    fn evaluation_points(&self) -> Vec<String> {
        self.points.clone()
    }

    fn __repr__(&self) -> String {
        format!("Scene(file={:?}, name={:?})", self.file, self.name)
    }

    fn __eq__(&self, other: &Scene) -> bool {
        self.text == other.text && self.file == other.file
    }

    fn __reduce__(&self, py: Python<'_>) -> PyResult<(Py<PyAny>, (String, String))> {
        let ctor = py.get_type::<Scene>().getattr("from_toml")?.unbind();
        Ok((ctor, (self.text.clone(), self.file.clone())))
    }
}

/// One seating (`kinrepro run --json`): poses of the evaluation points,
/// contact forces and stick/slip states, all SI.
#[pyclass(module = "kinrepro", frozen)]
pub struct Seating {
    report: RunReport,
}

/// Rows of six DOFs (SI) as an (n, 6) array.
pub(crate) fn pose_rows(rows: impl Iterator<Item = [f64; 6]>) -> Array2<f64> {
    let v: Vec<[f64; 6]> = rows.collect();
    Array2::from_shape_fn((v.len(), 6), |(i, j)| v[i][j])
}

fn six(p: &kinrepro::dof::PointPose) -> [f64; 6] {
    [p.x_m, p.y_m, p.z_m, p.phi_x_rad, p.phi_y_rad, p.phi_z_rad]
}

#[pymethods]
impl Seating {
    /// Names of the evaluation points (rows of `poses`).
    #[getter]
    fn point_names(&self) -> Vec<String> {
        self.report.points.iter().map(|p| p.name.clone()).collect()
    }

    /// Pose of every evaluation point relative to the touching pose,
    /// (n_points, 6): x, y, z [m], phi_x, phi_y, phi_z [rad].
    #[getter]
    fn poses<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        pose_rows(self.report.points.iter().map(|p| six(&p.pose))).into_pyarray(py)
    }

    /// Pose of every evaluation point relative to the nominal seating
    /// (nominal friction), (n_points, 6), m and rad.
    #[getter]
    fn poses_rel_nominal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        pose_rows(self.report.points.iter().map(|p| six(&p.pose_rel_nominal))).into_pyarray(py)
    }

    /// Normal force of each contact [N], (n_contacts,).
    #[getter]
    fn normal_forces<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        let v: Vec<f64> = self.report.contacts.iter().map(|c| c.normal_force_n).collect();
        PyArray1::from_vec(py, v)
    }

    /// Tangential (friction) force on the moving half at each contact [N],
    /// (n_contacts, 3).
    #[getter]
    fn tangential_forces<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let c = &self.report.contacts;
        Array2::from_shape_fn((c.len(), 3), |(i, j)| c[i].tangential_force[j]).into_pyarray(py)
    }

    /// `"stick"` or `"slip"` per contact.
    #[getter]
    fn states(&self) -> Vec<String> {
        let c = &self.report.contacts;
        c.iter().map(|c| c.state.name().to_string()).collect()
    }

    /// Static friction coefficient of each contact used.
    #[getter]
    fn mu_static(&self) -> Vec<f64> {
        self.report.mu_static.clone()
    }

    /// The document of `kinrepro run --json`.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report).map_err(err)
    }

    /// The text table of `kinrepro run`.
    fn table(&self) -> String {
        self.report.table()
    }

    fn __repr__(&self) -> String {
        format!(
            "Seating(scene={:?}, contacts={}, states={:?})",
            self.report.scene,
            self.report.contacts.len(),
            self.states()
        )
    }
}

/// The scene's nominal load, with the static coefficients `mu` if given.
fn load_of(scene: &kinrepro::scene::Scene, mu: Option<Vec<f64>>) -> Load {
    let nominal = Load::nominal(scene);
    match mu {
        Some(mu) => nominal.with_mu(&mu),
        None => nominal,
    }
}

/// Seat the coupling once (`kinrepro run`): `mu` the static friction
/// coefficient of each contact (None: the scene's mu_static everywhere).
#[pyfunction]
#[pyo3(signature = (
    scene, mu = None, solver = "quasi-static", increments = None, path_tolerance = None
))]
pub fn seat(
    py: Python<'_>,
    scene: &Scene,
    mu: Option<Vec<f64>>,
    solver: &str,
    increments: Option<Whole<usize>>,
    path_tolerance: Option<f64>,
) -> PyResult<Seating> {
    let increments = increments.map(Whole::get);
    let method = crate::options::method(solver, increments, path_tolerance)?;
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let report = py.detach(move || -> Result<RunReport, Failure> {
        let (scene, c) = parse_scene(&text, &file)?;
        let (nominal, load) = (Load::nominal(&scene), load_of(&scene, mu));
        let seat = |l: &Load| method.seat(&c, l).map_err(|e| Failure(format!("{file}: {e}")));
        let seating = seat(&load)?;
        let nominal = seat(&nominal)?;
        let model = (&scene, &c);
        Ok(RunReport::new(model, &load.mu, &seating, &nominal, method.name()))
    });
    Ok(Seating { report: report.map_err(|Failure(m)| err(m))? })
}

/// The 6x6 stiffness of the seated coupling (`kinrepro stiffness`) at an
/// evaluation point (a name; None: the first, the centre) or at a point
/// (x, y, z) [m] of the moving half: (u [m], phi [rad]) -> (F [N], M [N m])
/// about that point.
#[pyfunction]
#[pyo3(signature = (scene, at = None, mu = None))]
pub fn stiffness<'py>(
    py: Python<'py>,
    scene: &Scene,
    at: Option<&Bound<'py, PyAny>>,
    mu: Option<Vec<f64>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let (sc, c) = parse_scene(&scene.text, &scene.file).map_err(err)?;
    let point = match at {
        None => {
            let p = &sc.evaluation_points[0];
            (p.name.clone(), p.position)
        }
        Some(a) => match a.extract::<String>() {
            Ok(name) => {
                let found = sc.evaluation_points.iter().find(|p| p.name == name);
                let p = found.ok_or_else(|| {
                    err(format!("at={name:?}: no such evaluation point, have {:?}", scene.points))
                })?;
                (p.name.clone(), p.position)
            }
            Err(_) => {
                let v: [f64; 3] = a
                    .extract()
                    .map_err(|_| err("at: give an evaluation point's name or (x, y, z) in m"))?;
                if v.iter().any(|x| !x.is_finite()) {
                    return Err(err(format!("at: need three finite numbers, got {v:?}")));
                }
                ("at".to_string(), Vector3::from(v))
            }
        },
    };
    let file = scene.file.clone();
    let report = py.detach(move || -> Result<StiffnessReport, Failure> {
        let load = load_of(&sc, mu);
        let fail = |e: &dyn std::fmt::Display| Failure(format!("{file}: {e}"));
        let seating = kinrepro::solve::quasistatic::seat(&c, &load, &SolverOptions::default())
            .map_err(|e| fail(&e))?;
        let k = CouplingStiffness::new(&c, &seating, &load).map_err(|e| fail(&e))?;
        StiffnessReport::new(&sc, &load.mu, &seating, &k, &[point]).map_err(|e| fail(&e))
    });
    let m = report.map_err(|Failure(m)| err(m))?.points[0].matrix;
    Ok(Array2::from_shape_fn((6, 6), |(i, j)| m[i][j]).into_pyarray(py))
}
