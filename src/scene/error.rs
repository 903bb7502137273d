//! Scene errors: the file, the line where the parser knows it, the field and
//! the reason.

use std::fmt;

/// A scene could not be loaded, or describes no valid coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The scene file (as given on the command line).
    pub file: String,
    /// 1-based line, where known.
    pub line: Option<usize>,
    /// Dotted field path, e.g. `coupling.ball_diameter` or `surfaces[3].radius`.
    pub field: String,
    /// Why it is wrong.
    pub reason: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if self.field.is_empty() {
            write!(f, ": {}", self.reason)
        } else {
            write!(f, ": {}: {}", self.field, self.reason)
        }
    }
}

impl std::error::Error for SceneError {}

/// Builds errors for one source text, turning byte spans into line numbers.
pub struct ErrorContext<'a> {
    pub file: &'a str,
    pub source: &'a str,
}

impl ErrorContext<'_> {
    /// 1-based line of a byte offset; None for the empty span of a default value.
    pub fn line_of(&self, span: &std::ops::Range<usize>) -> Option<usize> {
        if span.start == 0 && span.end == 0 {
            return None;
        }
        let start = span.start.min(self.source.len());
        Some(self.source[..start].bytes().filter(|&b| b == b'\n').count() + 1)
    }

    /// A value that must be positive and finite, in `unit`.
    pub fn positive(
        &self,
        v: &toml::Spanned<f64>,
        field: &str,
        unit: &str,
    ) -> Result<f64, SceneError> {
        let x = *v.get_ref();
        if x.is_finite() && x > 0.0 {
            Ok(x)
        } else {
            Err(self.error(
                Some(&v.span()),
                field,
                format!("{x} must be positive ({unit})"),
            ))
        }
    }

    pub fn error(
        &self,
        span: Option<&std::ops::Range<usize>>,
        field: impl Into<String>,
        reason: impl Into<String>,
    ) -> SceneError {
        SceneError {
            file: self.file.to_string(),
            line: span.and_then(|s| self.line_of(s)),
            field: field.into(),
            reason: reason.into(),
        }
    }
}
