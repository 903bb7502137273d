//! `[goals]` as written: what `sweep` and `optimize` seek, kept as text
//! with its spans (the language is `explore::goal`'s, which reads it).

use serde::{Deserialize, Serialize};
use toml::Spanned;

/// `[goals]`: objectives (`"sigma:tip:z:min"`) and constraints
/// (`"sf_p>=3"`) in the language of `explore::goal`, checked there.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GoalsFile {
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub objectives: Vec<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub constraints: Vec<Spanned<String>>,
}
