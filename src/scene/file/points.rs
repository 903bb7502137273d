//! `[[evaluation_points]]` as written: a name, a position and the
//! directions the point is read along (`directions`, `frame`).

use serde::{Deserialize, Serialize};
use toml::Spanned;

use super::Numbers;

/// One `[[evaluation_points]]` entry.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EvaluationPointFile {
    pub name: Spanned<String>,
    /// Position in the moving half [m] (world frame in the touching pose).
    pub position: Spanned<Numbers>,
    /// Named directions the point's translation is read along.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub directions: Vec<DirectionFile>,
    /// A frame at the point: translations along and rotations about its axes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame: Option<FrameFile>,
}

/// `directions = [{ name = "optical axis", vector = [0, 0, 1] }]`: any
/// non-zero vector, normalised.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DirectionFile {
    pub name: Spanned<String>,
    pub vector: Spanned<Numbers>,
}

/// `frame = { name = "tool", z = [0, 0, 1], x = [1, 0, 0] }`: z its first
/// axis, x made normal to it, y = z x x.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrameFile {
    pub name: Spanned<String>,
    pub z: Spanned<Numbers>,
    pub x: Spanned<Numbers>,
}
