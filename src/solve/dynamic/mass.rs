//! Mass properties of the moving half.
//!
//! From the scene's `[dynamics]` table when given (mass, principal moments
//! about the centre of mass along the scene axes, centre of mass), else the
//! default model: the three moving balls plus a plate that carries them,
//! all of steel density rho = 7850 kg/m^3 whatever the scene's materials
//! (the seated pose does not depend on the mass, only the time scale does):
//!
//! ```text
//! balls:  m_b = rho 4/3 pi r^3 at each centre c_b,  I_b = 2/5 m_b r^2 (solid sphere)
//! plate:  disc of radius R_p = L + 2 r_max and thickness h = 2 r_max, axis along z,
//!         its lower face on the top of the balls (z = z_balls + r_max), centred over o
//!         m_p = rho pi R_p^2 h,  I_p = diag(m_p (3 R_p^2 + h^2)/12, same, m_p R_p^2 / 2)
//! ```
//! with o the centroid of the ball centres and L their largest distance from
//! o. The inertia tensor about the common centre of mass follows from the
//! parallel-axis theorem, I_c = sum (I_k + m_k (|d_k|^2 1 - d_k d_k^T)),
//! d_k = centre of part k minus the centre of mass (e.g. Meriam & Kraige,
//! *Engineering Mechanics: Dynamics*, §7.9).

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use crate::assembly::Coupling;

/// Density of the default model [kg/m^3] (steel).
pub const DEFAULT_DENSITY: f64 = 7850.0;

/// Where the mass properties came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MassSource {
    /// The scene's `[dynamics]` table.
    Scene,
    /// Three balls plus a plate (module docs).
    BallsAndPlate,
}

/// Rigid-body mass properties in the body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassModel {
    /// Mass [kg].
    pub mass: f64,
    /// Centre of mass in the body frame [m].
    pub centre_of_mass: Vector3<f64>,
    /// Inertia tensor about the centre of mass, body axes [kg m^2].
    pub inertia: Matrix3<f64>,
    pub source: MassSource,
}

impl MassModel {
    /// The scene's `[dynamics]` table, or the default model.
    pub fn of(coupling: &Coupling) -> Self {
        match coupling.dynamics {
            Some(d) => MassModel {
                mass: d.mass,
                centre_of_mass: d.centre_of_mass,
                inertia: Matrix3::from_diagonal(&d.inertia),
                source: MassSource::Scene,
            },
            None => Self::balls_and_plate(coupling),
        }
    }

    /// The default model: balls plus plate (module docs).
    pub fn balls_and_plate(coupling: &Coupling) -> Self {
        let balls = &coupling.balls;
        let n = balls.len() as f64;
        let o = balls.iter().map(|b| b.centre).sum::<Vector3<f64>>() / n;
        let l = balls
            .iter()
            .map(|b| {
                let d = b.centre - o;
                (d.x * d.x + d.y * d.y).sqrt()
            })
            .fold(0.0, f64::max);
        let r_max = balls.iter().map(|b| b.radius).fold(0.0, f64::max);
        let mut parts: Vec<(f64, Vector3<f64>, Matrix3<f64>)> = balls
            .iter()
            .map(|b| {
                let m = DEFAULT_DENSITY * 4.0 / 3.0 * std::f64::consts::PI * b.radius.powi(3);
                (m, b.centre, Matrix3::identity() * (0.4 * m * b.radius * b.radius))
            })
            .collect();
        let rp = l + 2.0 * r_max;
        let h = 2.0 * r_max;
        let mp = DEFAULT_DENSITY * std::f64::consts::PI * rp * rp * h;
        let ixx = mp * (3.0 * rp * rp + h * h) / 12.0;
        parts.push((
            mp,
            Vector3::new(o.x, o.y, o.z + r_max + 0.5 * h),
            Matrix3::from_diagonal(&Vector3::new(ixx, ixx, 0.5 * mp * rp * rp)),
        ));
        let mass: f64 = parts.iter().map(|p| p.0).sum();
        let com = parts.iter().map(|p| p.1 * p.0).sum::<Vector3<f64>>() / mass;
        let inertia = parts
            .iter()
            .map(|(m, c, i)| {
                let d = c - com;
                i + (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * *m
            })
            .sum();
        MassModel { mass, centre_of_mass: com, inertia, source: MassSource::BallsAndPlate }
    }

    /// Inverse inertia tensor in world axes for a body at `rotation`.
    pub fn world_inverse_inertia(&self, rotation: &UnitQuaternion<f64>) -> Matrix3<f64> {
        let r = rotation.to_rotation_matrix().into_inner();
        let inv = self.inertia.try_inverse().unwrap_or_else(Matrix3::zeros);
        r * inv * r.transpose()
    }

    /// Effective mass of the body for a force along unit `dir` at lever arm
    /// `arm` from the centre of mass (world axes, `inv_inertia` in world axes):
    /// m_eff = 1 / (1/m + (arm x dir)^T I^-1 (arm x dir))
    /// (the inverse of the point's mobility along dir; e.g. Featherstone,
    /// *Rigid Body Dynamics Algorithms*, 2008, §11.4).
    pub fn effective_mass(
        &self,
        inv_inertia: &Matrix3<f64>,
        arm: &Vector3<f64>,
        dir: &Vector3<f64>,
    ) -> f64 {
        let a = arm.cross(dir);
        1.0 / (1.0 / self.mass + a.dot(&(inv_inertia * a)))
    }
}
