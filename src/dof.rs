//! The six degrees of freedom of a pose and their units: [`Dof`] (name,
//! units, scale to nm and nrad), [`PointPose`] (six values in m and rad) and
//! [`Dofs`] (six values in nm and nrad). The only place that spells the DOF
//! names: every table header, CSV column and JSON key derives from here.
//!
//! Translations x, y, z of a point and the rotation vector phi = (phi_x,
//! phi_y, phi_z) of the body (docs/model.md, "The coupling"; phi_z is the
//! clocking about the coupling axis).

use serde::{Deserialize, Serialize};

/// Nanometres per metre and nanoradians per radian.
pub const NANO: f64 = 1e9;

/// A value in m or rad in nm or nrad.
pub fn nano(si: f64) -> f64 {
    si * NANO
}

/// One degree of freedom of a pose; in JSON its [`Dof::name`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Dof {
    X,
    Y,
    Z,
    PhiX,
    PhiY,
    PhiZ,
}

impl Dof {
    /// All six, in output order (the order of every six-value array).
    pub const ALL: [Dof; 6] = [Dof::X, Dof::Y, Dof::Z, Dof::PhiX, Dof::PhiY, Dof::PhiZ];

    /// The position in [`Dof::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The name in files and messages: `x`, ..., `phi_z`.
    pub fn name(self) -> &'static str {
        ["x", "y", "z", "phi_x", "phi_y", "phi_z"][self.index()]
    }

    /// The label on charts: `x`, ..., `φz`.
    pub fn symbol(self) -> &'static str {
        ["x", "y", "z", "φx", "φy", "φz"][self.index()]
    }

    pub fn from_name(name: &str) -> Option<Dof> {
        Dof::ALL.into_iter().find(|d| d.name() == name)
    }

    /// The names of all six, for messages: `x, y, z, phi_x, phi_y, phi_z`.
    pub fn names() -> String {
        Dof::ALL.map(Dof::name).join(", ")
    }

    /// The name of axis `a` (0, 1, 2: x, y, z).
    pub fn axis(a: usize) -> &'static str {
        Dof::ALL[a].name()
    }

    /// True for the rotations.
    pub fn is_rotation(self) -> bool {
        self.index() >= 3
    }

    /// The SI unit: `m` or `rad`.
    pub fn si_unit(self) -> &'static str {
        if self.is_rotation() { "rad" } else { "m" }
    }

    /// The unit of tables and plots: `nm` or `nrad` (the SI value times [`NANO`]).
    pub fn unit(self) -> &'static str {
        if self.is_rotation() { "nrad" } else { "nm" }
    }

    /// The name with its SI unit (`x_m`, `phi_x_rad`): output names, CSV columns.
    pub fn si_key(self) -> String {
        format!("{}_{}", self.name(), self.si_unit())
    }

    /// The name with its table unit (`x_nm`, `phi_x_nrad`): JSON keys, reference files.
    pub fn key(self) -> String {
        format!("{}_{}", self.name(), self.unit())
    }

    /// A text table's column header `<prefix><name> [nm]`; rotations
    /// without the space (`phi_x[nrad]`), which keeps six columns narrow.
    pub fn header(self, prefix: &str) -> String {
        let gap = if self.is_rotation() { "" } else { " " };
        format!("{prefix}{}{gap}[{}]", self.name(), self.unit())
    }
}

/// Pose of an evaluation point relative to a reference pose, SI:
/// translation of the point [m] and rotation vector [rad]
/// (`solve::PointPose::between`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointPose {
    pub x_m: f64,
    pub y_m: f64,
    pub z_m: f64,
    pub phi_x_rad: f64,
    pub phi_y_rad: f64,
    pub phi_z_rad: f64,
}

impl PointPose {
    /// From six values in the order of [`Dof::ALL`] (m, rad).
    pub fn from_components(v: [f64; 6]) -> Self {
        PointPose {
            x_m: v[0],
            y_m: v[1],
            z_m: v[2],
            phi_x_rad: v[3],
            phi_y_rad: v[4],
            phi_z_rad: v[5],
        }
    }

    /// The five components evaluated by the paper's Table 2 (all but phi_z).
    pub fn evaluated(&self) -> [f64; 5] {
        let c = self.components();
        [c[0], c[1], c[2], c[3], c[4]]
    }

    /// All six components in the order of [`Dof::ALL`] (m, rad).
    pub fn components(&self) -> [f64; 6] {
        [self.x_m, self.y_m, self.z_m, self.phi_x_rad, self.phi_y_rad, self.phi_z_rad]
    }
}

/// Six DOFs in table units: x, y, z [nm], rotations [nrad].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Dofs {
    pub x_nm: f64,
    pub y_nm: f64,
    pub z_nm: f64,
    pub phi_x_nrad: f64,
    pub phi_y_nrad: f64,
    pub phi_z_nrad: f64,
}

impl Dofs {
    /// From six SI values (m, m, m, rad, rad, rad).
    pub fn from_si(v: [f64; 6]) -> Self {
        let v = v.map(nano);
        Dofs {
            x_nm: v[0],
            y_nm: v[1],
            z_nm: v[2],
            phi_x_nrad: v[3],
            phi_y_nrad: v[4],
            phi_z_nrad: v[5],
        }
    }

    /// The six values in nm and nrad, in the order of [`Dof::ALL`].
    pub fn values(&self) -> [f64; 6] {
        [self.x_nm, self.y_nm, self.z_nm, self.phi_x_nrad, self.phi_y_nrad, self.phi_z_nrad]
    }

    /// The six values in m and rad.
    pub fn si(&self) -> [f64; 6] {
        self.values().map(|v| v * (1.0 / NANO))
    }
}
