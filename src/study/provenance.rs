//! What produced a study's output: kinrepro's version, the output schema,
//! and the study fingerprint that `merge` compares across shard parts.
//!
//! The fingerprint holds every setting a shard's numbers depend on: the
//! resolved scene (its content, hashed, plus the friction and preload values
//! named separately so that a refusal can name them), the solver and its
//! settings, the design (sampler, seed, sample count), the varied inputs and
//! kinrepro's version. Two parts belong to one study exactly when their
//! fingerprints are equal.
//!
//! Hashes and settings are of canonical serialisations, never of Rust's
//! `Debug` text (which a compiler release may change): [`content_hash`] is
//! FNV-1a 64 of the value's serde_json text (fields in declaration order,
//! floats as the shortest decimal that reads back to the same f64, the
//! scene file's line numbers left out). [`FINGERPRINT_VERSION`] names this
//! scheme; a document from before it has none (version 1: `Debug` text).

use serde::{Deserialize, Serialize};

use super::DesignSpec;
use super::inputs::Input;
use super::options::Settings;
use crate::scene::{ForceLaw, PreloadForce, Scene};

/// The fingerprint's scheme: 2, canonical serialisations hashed by
/// FNV-1a 64 ([`content_hash`]); 1 (documents without the field), the
/// `Debug` text of kinrepro before it.
pub const FINGERPRINT_VERSION: u32 = 2;

fn version_one() -> u32 {
    1
}

/// Version of the output schema (docs/output.md). 2: the clocking about z evaluated, JSON
/// records with `inputs_si` and `design_u`, provenance and fingerprint. 3: the fingerprint
/// of canonical serialisations ([`FINGERPRINT_VERSION`] 2).
pub const SCHEMA_VERSION: u32 = 3;

/// The schemas `merge` and `report` read: 2 differs from 3 only in its
/// fingerprints (version 1, `Debug` text), which merge with each other.
pub const READABLE_SCHEMAS: std::ops::RangeInclusive<u32> = 2..=SCHEMA_VERSION;

/// kinrepro's version (Cargo.toml).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The settings one study's numbers depend on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Fingerprint {
    /// The scheme of this fingerprint ([`FINGERPRINT_VERSION`]).
    #[serde(default = "version_one")]
    pub fingerprint_version: u32,
    pub kinrepro_version: String,
    /// [`content_hash`] (hex) of the resolved scene, file path excluded and
    /// the `[study]` defaults replaced by the design actually run.
    pub scene_content: String,
    pub scene_name: String,
    pub solver: String,
    /// The solver's settings (increments, tolerances, ...) as canonical
    /// JSON text.
    pub solver_settings: String,
    pub sampler: String,
    pub seed: u64,
    pub samples: usize,
    /// Independent LHS replicates of the design (1 for MC, corners, a single LHS).
    #[serde(default = "super::sampling::one")]
    pub replicates: usize,
    /// Names of the varied inputs (design columns), in row order.
    pub vary: Vec<String>,
    pub mu_static: f64,
    pub spread: f64,
    pub dynamic_ratio: f64,
    pub tangential_law: String,
    /// The sliding-coefficient reading (`switch` or `decay` with its coefficient).
    #[serde(default)]
    pub friction_law: String,
    /// Preload force [N] (several forces: the magnitude of their resultant).
    pub preload_n: f64,
    /// Preload point [m] (several forces: their force-weighted mean point).
    pub preload_point_m: [f64; 3],
    /// Preload direction (unit vector; several forces: of their resultant).
    pub preload_direction: [f64; 3],
    /// Every preload force, when the preload is not the single constant
    /// force (`[[preload.forces]]`, `gravity`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub preload_forces: Vec<PreloadForceRecord>,
    /// Start-pose bounds (offset [m], tilt [rad]) when the start varies.
    pub start_bounds: Option<[[f64; 3]; 2]>,
}

impl Fingerprint {
    /// The fingerprint's `scene_content` of `scene` run on `design`:
    /// [`content_hash`] of the resolved scene, file path excluded and the
    /// `[study]` defaults replaced by the design.
    pub fn scene_content(scene: &Scene, design: &DesignSpec) -> String {
        let mut resolved = scene.clone();
        resolved.file = String::new();
        resolved.study.sampler = design.sampler;
        resolved.study.samples = design.n;
        resolved.study.seed = design.seed;
        content_hash(&resolved)
    }

    /// The fingerprint of one scene's study run with `s` on `design`.
    pub fn new(scene: &Scene, s: &Settings, design: &DesignSpec) -> Self {
        let p = &scene.preload;
        let f = &scene.friction;
        Fingerprint {
            fingerprint_version: FINGERPRINT_VERSION,
            kinrepro_version: VERSION.to_string(),
            scene_content: Fingerprint::scene_content(scene, design),
            scene_name: scene.name.clone(),
            solver: s.method.name().to_string(),
            solver_settings: canonical_text(&s.method),
            sampler: design.sampler.to_string(),
            seed: design.seed,
            samples: design.n,
            replicates: design.replicates,
            vary: s.variation.inputs(scene).iter().map(Input::name).collect(),
            mu_static: f.mu_static,
            spread: f.spread,
            dynamic_ratio: f.dynamic_ratio,
            tangential_law: f.tangential_law.name().to_string(),
            friction_law: canonical_text(&f.law),
            preload_n: match p.forces.as_slice() {
                [one] => one.force,
                _ => p.resultant().norm(),
            },
            preload_point_m: p.centre().into(),
            preload_direction: p.resultant_direction().into(),
            preload_forces: match p.is_single_constant() {
                true => Vec::new(),
                false => p.forces.iter().map(PreloadForceRecord::new).collect(),
            },
            start_bounds: s.variation.start.map(|b| [b.offset.into(), b.tilt.into()]),
        }
    }

    /// The first field in which `other` differs, as `name (this vs other)`.
    pub fn first_difference(&self, other: &Fingerprint) -> Option<String> {
        self.settings()
            .into_iter()
            .zip(other.settings())
            .find(|((_, a), (_, b))| a != b)
            .map(|((name, a), (_, b))| format!("{name} ({a} vs {b})"))
    }

    /// Every field by name, as `first_difference` compares and prints them:
    /// the named settings before the scene content, so that a changed
    /// friction coefficient is named as such.
    fn settings(&self) -> [(&'static str, String); 21] {
        [
            ("fingerprint_version", d(&self.fingerprint_version)),
            ("kinrepro_version", q(&self.kinrepro_version)),
            ("solver", q(&self.solver)),
            ("solver_settings", q(&self.solver_settings)),
            ("sampler", q(&self.sampler)),
            ("seed", d(&self.seed)),
            ("samples", d(&self.samples)),
            ("replicates", d(&self.replicates)),
            ("vary", d(&self.vary)),
            ("mu_static", d(&self.mu_static)),
            ("spread", d(&self.spread)),
            ("dynamic_ratio", d(&self.dynamic_ratio)),
            ("tangential_law", q(&self.tangential_law)),
            ("friction_law", q(&self.friction_law)),
            ("preload force", d(&self.preload_n)),
            ("preload point", d(&self.preload_point_m)),
            ("preload direction", d(&self.preload_direction)),
            ("preload forces", d(&self.preload_forces)),
            ("start_bounds", d(&self.start_bounds)),
            ("scene name", q(&self.scene_name)),
            ("scene content", q(&self.scene_content)),
        ]
    }
}

/// One preload force in the fingerprint (docs/output.md).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PreloadForceRecord {
    /// `constant`, `spring` or `weight`.
    pub law: String,
    /// Magnitude at full load in the touching pose [N].
    pub force_n: f64,
    pub point_m: [f64; 3],
    pub direction: [f64; 3],
    /// Spring stiffness [N/m] and free length [m] (springs only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness_n_per_m: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub free_length_m: Option<f64>,
    /// A magnet's gap in the touching pose [m] and its (gap [m], force [N])
    /// table (magnets only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap_m: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force_table: Option<Vec<[f64; 2]>>,
}

impl PreloadForceRecord {
    fn new(f: &PreloadForce) -> Self {
        let (law, spring, magnet) = match &f.law {
            ForceLaw::Constant => ("constant", None, None),
            ForceLaw::Spring { stiffness, free_length } => {
                ("spring", Some((*stiffness, *free_length)), None)
            }
            ForceLaw::Weight => ("weight", None, None),
            ForceLaw::Magnet(m) => ("magnet", None, Some(m)),
        };
        PreloadForceRecord {
            law: law.to_string(),
            force_n: f.force,
            point_m: f.point.into(),
            direction: f.direction.into(),
            stiffness_n_per_m: spring.map(|s| s.0),
            free_length_m: spring.map(|s| s.1),
            gap_m: magnet.map(|m| m.gap),
            force_table: magnet.map(|m| m.table.clone()),
        }
    }
}

fn q(s: &str) -> String {
    format!("\"{s}\"")
}

fn d<T: Serialize>(v: &T) -> String {
    canonical_text(v)
}

/// The canonical serialisation of `value`: serde_json's compact text.
pub fn canonical_text<T: Serialize>(value: &T) -> String {
    serde_json::to_string(value).expect("the fingerprint's values serialise to JSON")
}

/// FNV-1a 64 (hex) of [`canonical_text`] of `value`, hashed as it is
/// written (a stable content hash: neither `Debug` text nor std's hasher,
/// which may change between Rust releases).
pub fn content_hash<T: Serialize>(value: &T) -> String {
    let mut h = Fnv1a64(FNV_OFFSET);
    serde_json::to_writer(&mut h, value).expect("the fingerprint's values serialise to JSON");
    format!("{:016x}", h.0)
}

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0100_0000_01b3;

/// FNV-1a 64 as an `io::Write` that hashes the bytes written to it.
struct Fnv1a64(u64);

impl std::io::Write for Fnv1a64 {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0 = buf.iter().fold(self.0, |h, &b| (h ^ u64::from(b)).wrapping_mul(FNV_PRIME));
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// FNV-1a, 64 bit (Fowler, Noll, Vo; offset basis 0xcbf29ce484222325,
/// prime 0x100000001b3): a stable content hash (std's hasher may change
/// between Rust releases).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(FNV_OFFSET, |h, &b| (h ^ u64::from(b)).wrapping_mul(FNV_PRIME))
}

/// One line naming what produced an output: version, schema, solver,
/// sampler, seed, samples and the varied quantities.
pub fn produced_by(solver: &str, sampler: &str, seed: &str, samples: &str, vary: &str) -> String {
    format!(
        "kinrepro {VERSION} (output schema {SCHEMA_VERSION}), solver {solver}, sampler {sampler}, seed {seed}, samples {samples}, vary {vary}"
    )
}
