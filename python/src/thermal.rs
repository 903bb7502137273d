//! `thermal`: the thermal path after a seating (`kinrepro thermal`).

use kinrepro::error::parse_scene;
use kinrepro::report::thermal::ThermalReport;
use kinrepro::scene::thermal::cycle_of;
use kinrepro::solve::Load;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray2, PyArray3};
use pyo3::prelude::*;

use crate::err;
use crate::run::Failure;
use crate::scene::Scene;
use crate::whole::Whole;

/// A thermal path (`kinrepro thermal --json`): per cycle point the drift
/// of every evaluation point from where it was seated, SI and kelvin.
#[pyclass(module = "kinrepro", frozen)]
pub struct ThermalPath {
    report: ThermalReport,
}

#[pymethods]
impl ThermalPath {
    /// Names of the evaluation points (the second axis of `drift`).
    #[getter]
    fn point_names(&self) -> Vec<String> {
        let first = self.report.cycle.first();
        first.map_or_else(Vec::new, |c| c.points.iter().map(|p| p.name.clone()).collect())
    }

    /// (n_cycle_points, 2): the temperature changes [K] of the moving and
    /// the fixed body at each cycle point.
    #[getter]
    fn delta_t_k<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let c = &self.report.cycle;
        let t = |i: usize, j: usize| {
            let d = c[i].delta_t_k;
            if j == 0 { d.moving } else { d.fixed }
        };
        Array2::from_shape_fn((c.len(), 2), |(i, j)| t(i, j)).into_pyarray(py)
    }

    /// (n_cycle_points, n_points, 6): each evaluation point's drift from
    /// where it was seated, x, y, z [m] (rigid motion and the body's own
    /// expansion), phi_x, phi_y, phi_z [rad]. The last cycle point back at
    /// [0, 0] is the residual.
    #[getter]
    fn drift<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray3<f64>> {
        let c = &self.report.cycle;
        let n = c.first().map_or(0, |c| c.points.len());
        let value = |(k, p, j): (usize, usize, usize)| {
            let d = &c[k].points[p];
            if j < 3 { d.displacement_m[j] } else { d.rotation_rad[j - 3] }
        };
        Array3::from_shape_fn((c.len(), n, 6), value).into_pyarray(py)
    }

    /// The larger in size of the two temperature changes at which the
    /// first contact slides [K]; None when nothing slides.
    #[getter]
    fn first_slip_delta_t_k(&self) -> Option<f64> {
        self.report.first_slip_delta_t_k
    }

    /// The contacts (1-based) that slid on the way to each cycle point.
    #[getter]
    fn slipping_contacts(&self) -> Vec<Vec<usize>> {
        self.report.cycle.iter().map(|c| c.slipping_contacts.clone()).collect()
    }

    /// Each cycle point's estimated path error (None: fixed increments).
    #[getter]
    fn path_error(&self) -> Vec<Option<f64>> {
        self.report.cycle.iter().map(|c| c.path_error).collect()
    }

    /// The document of `kinrepro thermal --json`.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.report).map_err(err)
    }

    /// The text table of `kinrepro thermal`.
    fn table(&self) -> String {
        self.report.table()
    }

    fn __repr__(&self) -> String {
        format!(
            "ThermalPath(scene={:?}, cycle_points={}, first_slip_delta_t_k={:?})",
            self.report.scene,
            self.report.cycle.len(),
            self.report.first_slip_delta_t_k
        )
    }
}

/// Seat the coupling and follow its `[thermal]` temperature cycle
/// (`kinrepro thermal`): `mu` the static coefficient of each contact
/// (None: the scene's mu_static everywhere), `cycle` the temperature
/// changes [(dT_moving, dT_fixed), ...] in K (None: the scene's).
#[pyfunction]
#[pyo3(signature = (scene, mu = None, cycle = None, increments = None, path_tolerance = None))]
pub fn thermal(
    py: Python<'_>,
    scene: &Scene,
    mu: Option<Vec<f64>>,
    cycle: Option<Vec<[f64; 2]>>,
    increments: Option<Whole<usize>>,
    path_tolerance: Option<f64>,
) -> PyResult<ThermalPath> {
    let increments = increments.map(Whole::get);
    let method = crate::options::method("quasi-static", increments, path_tolerance)?;
    let tolerance = method.path_tolerance();
    let (text, file) = (scene.text.clone(), scene.file.clone());
    let report = py.detach(move || -> Result<ThermalReport, Failure> {
        let (scene, c) = parse_scene(&text, &file)?;
        let mut load = Load::nominal(&scene);
        if let Some(mu) = mu {
            load = load.with_mu(&mu);
        }
        if let Some(cycle) = cycle {
            load.cycle = cycle_of(&cycle)?;
        }
        let (seating, path) =
            method.seat_and_cycle(&c, &load).map_err(|e| Failure(format!("{file}: {e}")))?;
        ThermalReport::new((&scene, &c), &load, &seating, &path, tolerance)
            .map_err(|e| Failure(format!("{file}: {e}")))
    });
    Ok(ThermalPath { report: report.map_err(|Failure(m)| err(m))? })
}
