//! One scene of a planned study ([`Variant`]): what its runs seat.

use std::ops::Range;

use super::DesignSpec;
use crate::assembly::Coupling;
use crate::scene::Scene;

/// One scene of a study: the scene, its coupling, its design and the
/// samples of it this run seats.
#[derive(Debug, Clone)]
pub struct Variant {
    pub scene: Scene,
    pub coupling: Coupling,
    pub design: DesignSpec,
    /// This shard's sample indices.
    pub samples: Range<usize>,
    /// Summarised from streamed moments, keeping no records
    /// (`super::stream`): a whole Monte Carlo design above
    /// `stream::STREAM_ABOVE` samples.
    pub streamed: bool,
}

impl Variant {
    /// The scene file (for messages).
    pub fn file(&self) -> &str {
        &self.scene.file
    }

    /// The same design and samples for another model of the scene with
    /// the same inputs (a sweep's design point, a calibration's parameter
    /// values); `scene` is assembled as `coupling`.
    pub fn with_model(&self, scene: Scene, coupling: Coupling) -> Variant {
        Variant { scene, coupling, ..self.clone() }
    }
}
