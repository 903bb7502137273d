//! The VALUES of `--set FIELD=VALUES`: a list (`5,10,20`, material names
//! `steel,silicon-carbide`, or keywords `planes,cylinders`), a linear
//! range with a count (`5:40:8`: 8 values from 5 to 40, ends included) or
//! a logarithmic one (`log:1:100:5`: 1, 3.16, 10, 31.6, 100). An LHS
//! design draws from the interval of a range (its count is not used; `a:b`
//! without a count is allowed there) and picks equally often among the
//! values of a list.
//!
//! An item of a list that parses as a number is a number, any other is a
//! string; quotes (`"316"` or `'316'`) make an item a string whatever it
//! holds. Each item must then fit the field: a number for a numeric field,
//! a string for a material or keyword field.

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::ExploreError;
use super::field::{FieldKind, SweptValue, kind_of};
use crate::scene::SceneFile;

/// The discrete values of a `--set` (a grid uses them all).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Levels {
    Numbers(Vec<f64>),
    Names(Vec<String>),
}

impl Levels {
    pub fn len(&self) -> usize {
        match self {
            Levels::Numbers(v) => v.len(),
            Levels::Names(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Value `i`.
    pub fn value(&self, i: usize) -> SweptValue {
        match self {
            Levels::Numbers(v) => SweptValue::Number(v[i]),
            Levels::Names(v) => SweptValue::Name(v[i].clone()),
        }
    }
}

/// A continuous interval for an LHS design: [lo, hi], uniform in the value
/// or (`log`) in its logarithm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Interval {
    pub lo: f64,
    pub hi: f64,
    pub log: bool,
}

impl Interval {
    /// The value at design coordinate u in [0, 1].
    pub fn at(&self, u: f64) -> f64 {
        if self.log {
            (self.lo.ln() + u * (self.hi / self.lo).ln()).exp()
        } else {
            self.lo + u * (self.hi - self.lo)
        }
    }
}

/// Why the VALUES of a `--set` are not understood.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ValuesError {
    #[error("a material or string field takes a list of names, not a range")]
    MaterialRange,
    #[error("\"{0}\" is not a number")]
    NotANumber(String),
    #[error("\"{0}\" is not finite")]
    NotFinite(String),
    #[error("a range is a:b:count or log:a:b:count")]
    RangeSyntax,
    #[error("the range needs a < b, got {lo} and {hi}")]
    Reversed { lo: f64, hi: f64 },
    #[error("a logarithmic range needs positive ends")]
    LogNotPositive,
    #[error("the count \"{0}\" is not a whole number")]
    CountNotWhole(String),
    #[error("the count must lie in 2..={MAX_LEVELS}, got {0}")]
    CountRange(usize),
    #[error("an empty item in the list")]
    EmptyItem,
    #[error("\"{0}\" is listed twice")]
    Twice(String),
    #[error("the field holds a name, \"{0}\" is a number (quote it to give it as a name)")]
    NumberForMaterial(String),
}

/// One `--set`: the field, the VALUES as written, and what they mean.
#[derive(Debug, Clone, PartialEq)]
pub struct Set {
    pub path: String,
    pub spec: String,
    pub kind: FieldKind,
    /// The grid values (empty for `a:b` without a count, LHS only).
    pub levels: Levels,
    /// The interval of a range (None for a list).
    pub interval: Option<Interval>,
}

/// Most values one range may expand to.
pub const MAX_LEVELS: usize = 10_000;

impl Set {
    /// Parse `FIELD=VALUES` against the base scene.
    pub fn parse(arg: &str, scene: &SceneFile) -> Result<Set, ExploreError> {
        let (path, spec) = arg
            .split_once('=')
            .filter(|(p, s)| !p.trim().is_empty() && !s.trim().is_empty())
            .ok_or_else(|| ExploreError::SetSyntax { arg: arg.to_string() })?;
        let (path, spec) = (path.trim().to_string(), spec.trim().to_string());
        let kind = kind_of(&path, scene)?;
        let err = |reason: ValuesError| ExploreError::Values {
            path: path.clone(),
            spec: spec.clone(),
            reason,
        };
        let (levels, interval) = if spec.contains(':') {
            if kind != FieldKind::Number {
                return Err(err(ValuesError::MaterialRange));
            }
            range(&spec).map_err(err)?
        } else {
            (list(&spec, kind).map_err(err)?, None)
        };
        Ok(Set { path, spec, kind, levels, interval })
    }
}

fn number(s: &str) -> Result<f64, ValuesError> {
    let s = s.trim();
    let x: f64 = s.parse().map_err(|_| ValuesError::NotANumber(s.to_string()))?;
    if x.is_finite() { Ok(x) } else { Err(ValuesError::NotFinite(s.to_string())) }
}

/// `a:b:n`, `log:a:b:n`, `a:b`, `log:a:b`.
fn range(spec: &str) -> Result<(Levels, Option<Interval>), ValuesError> {
    let (log, rest) = match spec.strip_prefix("log:") {
        Some(r) => (true, r),
        None => (false, spec),
    };
    let parts: Vec<&str> = rest.split(':').collect();
    if !(2..=3).contains(&parts.len()) {
        return Err(ValuesError::RangeSyntax);
    }
    let (lo, hi) = (number(parts[0])?, number(parts[1])?);
    if lo >= hi {
        return Err(ValuesError::Reversed { lo, hi });
    }
    if log && lo <= 0.0 {
        return Err(ValuesError::LogNotPositive);
    }
    let interval = Interval { lo, hi, log };
    let Some(count) = parts.get(2) else {
        return Ok((Levels::Numbers(Vec::new()), Some(interval)));
    };
    let n: usize =
        count.trim().parse().map_err(|_| ValuesError::CountNotWhole(count.trim().to_string()))?;
    if !(2..=MAX_LEVELS).contains(&n) {
        return Err(ValuesError::CountRange(n));
    }
    let values = (0..n)
        .map(|i| match i {
            0 => lo,
            _ if i == n - 1 => hi,
            _ => interval.at(i as f64 / (n - 1) as f64),
        })
        .collect();
    Ok((Levels::Numbers(values), Some(interval)))
}

/// A comma-separated list of numbers or names, each item as [`item`]
/// reads it, checked against the field's kind.
fn list(spec: &str, kind: FieldKind) -> Result<Levels, ValuesError> {
    let items: Vec<&str> = spec.split(',').map(str::trim).collect();
    if items.iter().any(|s| s.is_empty()) {
        return Err(ValuesError::EmptyItem);
    }
    let values: Vec<SweptValue> = items.iter().map(|s| item(s)).collect();
    for (i, v) in values.iter().enumerate() {
        if values[..i].contains(v) {
            return Err(ValuesError::Twice(items[i].to_string()));
        }
    }
    match kind {
        FieldKind::Number => {
            Ok(Levels::Numbers(items.iter().map(|s| number(s)).collect::<Result<_, _>>()?))
        }
        FieldKind::Material | FieldKind::Text => values
            .into_iter()
            .zip(&items)
            .map(|(v, s)| match v {
                SweptValue::Name(n) => Ok(n),
                SweptValue::Number(_) => Err(ValuesError::NumberForMaterial(s.to_string())),
            })
            .collect::<Result<_, _>>()
            .map(Levels::Names),
    }
}

/// One item of a list: a quoted item (`"..."` or `'...'`) is the string
/// between the quotes; otherwise a number if it parses as one, else the
/// string as written.
pub fn item(s: &str) -> SweptValue {
    let quoted =
        ['"', '\''].iter().find_map(|q| s.strip_prefix(*q).and_then(|r| r.strip_suffix(*q)));
    match (quoted, s.parse::<f64>()) {
        (Some(inner), _) => SweptValue::Name(inner.to_string()),
        (_, Ok(x)) => SweptValue::Number(x),
        _ => SweptValue::Name(s.to_string()),
    }
}
