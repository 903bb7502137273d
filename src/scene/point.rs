//! Evaluation points of the moving half and the directions a designer
//! reads them along: [`EvaluationPoint`] (`[[evaluation_points]]`) with its
//! [`Direction`]s, and the outputs a study records per point, named and
//! computed in one place ([`EvaluationPoint::output_names`],
//! [`EvaluationPoint::outputs`]).
//!
//! The displacement of a point along a unit direction u is the projection
//! u . (x, y, z) of its translation; the rotation about u is u . phi, with
//! phi the body's rotation vector (both linear in the pose, so their sigma
//! is sqrt(u^T C u) of the covariance C of the three components).

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::dof::{Dof, PointPose};

/// Prefix of a translation along a direction in an output name
/// (`<point>/along/<direction>_m`).
pub const ALONG: &str = "along/";
/// Prefix of a rotation about a direction (`<point>/about/<direction>_rad`).
pub const ABOUT: &str = "about/";

/// A named direction at an evaluation point: the translation of the point
/// along `vector` (or, for a frame's rotation axes, the rotation about it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Direction {
    pub name: String,
    /// The unit vector in the moving half (world frame in the touching pose).
    pub vector: Vector3<f64>,
    /// True: the rotation about `vector` [rad]; false: the translation along it [m].
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub rotation: bool,
}

impl Direction {
    /// The value of this direction in `pose` (m or rad).
    pub fn value(&self, pose: &PointPose) -> f64 {
        let c = pose.components();
        let k = if self.rotation { 3 } else { 0 };
        self.vector.dot(&Vector3::new(c[k], c[k + 1], c[k + 2]))
    }

    /// The SI unit: `m` or `rad`.
    pub fn si_unit(&self) -> &'static str {
        if self.rotation { "rad" } else { "m" }
    }

    /// `along/<name>_m` or `about/<name>_rad`: the last part of the output name.
    pub fn key(&self) -> String {
        let kind = if self.rotation { ABOUT } else { ALONG };
        format!("{kind}{}_{}", self.name, self.si_unit())
    }
}

/// A point of the moving half whose pose is reported, with the
/// directions it is read along.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EvaluationPoint {
    pub name: String,
    /// Position in the moving half [m].
    pub position: Vector3<f64>,
    /// `directions` and `frame` of the point, in file order (a frame gives
    /// three translations and three rotations).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub directions: Vec<Direction>,
}

impl EvaluationPoint {
    /// A point without directions.
    pub fn at(name: &str, position: Vector3<f64>) -> Self {
        EvaluationPoint { name: name.to_string(), position, directions: Vec::new() }
    }

    /// The names of the outputs of this point: `<name>/<dof>_<SI unit>`
    /// over [`Dof::ALL`], then `<name>/<direction key>` per direction.
    pub fn output_names(&self) -> impl Iterator<Item = String> + '_ {
        let dofs = Dof::ALL.into_iter().map(|d| format!("{}/{}", self.name, d.si_key()));
        dofs.chain(self.directions.iter().map(|d| format!("{}/{}", self.name, d.key())))
    }

    /// The values of [`EvaluationPoint::output_names`] for the pose `p` of
    /// this point (m, rad).
    pub fn outputs(&self, p: PointPose) -> impl Iterator<Item = f64> + '_ {
        p.components().into_iter().chain(self.directions.iter().map(move |d| d.value(&p)))
    }
}

/// What one output measures: a DOF, or the translation along (rotation
/// about) a named direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Measure<'a> {
    Dof(Dof),
    Along(&'a str),
    About(&'a str),
}

impl Measure<'_> {
    /// `x`, ..., `phi_z` (`symbol`: `x`, ..., `φz`), `along <direction>`
    /// or `about <direction>`.
    pub fn label(&self, symbol: bool) -> String {
        match self {
            Measure::Dof(d) if symbol => d.symbol().to_string(),
            Measure::Dof(d) => d.name().to_string(),
            Measure::Along(n) => format!("along {n}"),
            Measure::About(n) => format!("about {n}"),
        }
    }
}

/// An output name split into its head (`[prefix]<point>`) and what it
/// measures: `<head>/<dof>_<unit>`, `<head>/along/<direction>_m` or
/// `<head>/about/<direction>_rad` (a direction's name holds no `/`).
pub fn split_output(name: &str) -> Option<(&str, Measure<'_>)> {
    for (kind, unit) in [(ALONG, "_m"), (ABOUT, "_rad")] {
        let Some(k) = name.rfind(&format!("/{kind}")) else { continue };
        let rest = &name[k + 1 + kind.len()..];
        if let Some(d) = rest.strip_suffix(unit).filter(|d| !d.contains('/')) {
            let m = if kind == ALONG { Measure::Along(d) } else { Measure::About(d) };
            return Some((&name[..k], m));
        }
    }
    Dof::ALL.into_iter().find_map(|d| {
        let head = name.strip_suffix(&d.si_key())?.strip_suffix('/')?;
        Some((head, Measure::Dof(d)))
    })
}

/// The label of what an output measures ([`Measure::label`]), or the name
/// itself if it is not an output name.
pub fn output_label(name: &str, symbol: bool) -> String {
    split_output(name).map_or_else(|| name.to_string(), |(_, m)| m.label(symbol))
}
