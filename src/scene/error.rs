//! Scene errors: the file, the line where the parser knows it, the field and
//! the reason.

use std::fmt;

use toml::Spanned;

use super::file::Numbers;

/// A scene could not be loaded, or describes no valid coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The scene file (as given on the command line).
    pub file: String,
    /// 1-based line, where known.
    pub line: Option<usize>,
    /// Dotted field path, e.g. `coupling.ball_diameter` or `surfaces[3].radius`.
    pub field: String,
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
    /// Byte offsets of the line starts, found on first use: a line lookup
    /// is then a binary search, so that naming the line of every ball and
    /// surface stays linear in the file's size.
    line_starts: std::sync::OnceLock<Vec<usize>>,
}

impl<'a> ErrorContext<'a> {
    pub fn new(file: &'a str, source: &'a str) -> Self {
        ErrorContext { file, source, line_starts: std::sync::OnceLock::new() }
    }

    /// 1-based line of a byte offset; None for the empty span of a default value.
    pub fn line_of(&self, span: &std::ops::Range<usize>) -> Option<usize> {
        if span.start == 0 && span.end == 0 {
            return None;
        }
        let starts = self.line_starts.get_or_init(|| {
            std::iter::once(0)
                .chain(
                    self.source
                        .bytes()
                        .enumerate()
                        .filter(|(_, b)| *b == b'\n')
                        .map(|(i, _)| i + 1),
                )
                .collect()
        });
        let start = span.start.min(self.source.len());
        // The number of line starts at or before `start` is its line.
        Some(starts.partition_point(|&s| s <= start))
    }

    /// A value that must be positive and finite, in `unit`.
    pub fn positive(&self, v: &Spanned<f64>, field: &str, unit: &str) -> Result<f64, SceneError> {
        let x = *v.get_ref();
        if x.is_finite() && x > 0.0 {
            Ok(x)
        } else {
            Err(self.error(Some(&v.span()), field, format!("{x} must be positive ({unit})")))
        }
    }

    /// An array of exactly `N` numbers (integers are read as reals). A
    /// longer or shorter array, or an element that is not a number, is an
    /// error naming the field: nothing is cut off or padded. `what` names
    /// the components, e.g. `[x, y, z]`.
    pub fn numbers<const N: usize>(
        &self,
        v: &Spanned<Numbers>,
        field: &str,
        what: &str,
    ) -> Result<[f64; N], SceneError> {
        let items = &v.get_ref().0;
        if items.len() != N {
            return Err(self.error(
                Some(&v.span()),
                field,
                format!(
                    "expected an array of {N} numbers {what}, found {} element{}",
                    items.len(),
                    if items.len() == 1 { "" } else { "s" }
                ),
            ));
        }
        let mut out = [0.0; N];
        for (k, (o, item)) in out.iter_mut().zip(items).enumerate() {
            *o = match item {
                toml::Value::Float(x) => *x,
                toml::Value::Integer(i) => *i as f64,
                other => {
                    return Err(self.error(
                        Some(&v.span()),
                        field,
                        format!("element {} ({other}) is not a number", k + 1),
                    ));
                }
            };
        }
        Ok(out)
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
