//! Objectives and constraints in one language, shared by `sweep` and
//! `optimize` (docs/guide-design.md, "Objectives and constraints"): an
//! [`Output`] is anything a design point's study or check gives, read in
//! SI units from its [`DesignReport`]:
//!
//! * `sigma:POINT:DOF` and `pm3sigma:POINT:DOF`: sigma (or 3 sigma) of a
//!   DOF (`x`, ..., `phi_z`; m or rad) or of a named direction of the
//!   point (`along NAME` or just `NAME`: m; `about NAME`: rad);
//! * `k_min`: the lowest principal translational stiffness at the first
//!   evaluation point of the nominal seating [N/m];
//! * `sf_p`: the smallest safety factor against the allowable contact
//!   pressure [1];
//! * `friction_margin`: mu_lim - (mu_static + spread) [1] (positive: every
//!   coefficient drawn is below the friction limit for seating);
//! * `drift:POINT:DOF` and `residual:POINT:DOF` (a scene with `[thermal]`):
//!   the largest |mean drift| of the point over the cycle's points, and the
//!   |mean drift| at its last point (back at the seating temperature: the
//!   residual), from each sample's own seated pose [m or rad];
//! * a swept or varied scene field by its TOML path (`preload.force`).
//!
//! An [`Objective`] is `OUTPUT:min` or `OUTPUT:max`; a [`Constraint`] is
//! `OUTPUT<=VALUE` or `OUTPUT>=VALUE` (VALUE in the output's SI unit).

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::design_report::DesignReport;
use toml::Spanned;

use super::ExploreError;
use super::field::SweptValue;
use crate::dof::{Dof, NANO};
use crate::scene::error::ErrorContext;
use crate::scene::{Scene, SceneFile};

/// A quantity a design point gives.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "output", rename_all = "snake_case")]
pub enum Output {
    /// Sigma of `measure` (a DOF's name, `along NAME` or `about NAME`) at
    /// the evaluation point `point`.
    Sigma {
        point: String,
        measure: String,
    },
    /// Three times sigma, the reproducibility of the paper.
    Pm3sigma {
        point: String,
        measure: String,
    },
    /// The largest |mean drift| over a `[thermal]` cycle's points.
    Drift {
        point: String,
        measure: String,
    },
    /// The |mean drift| at the cycle's last point.
    Residual {
        point: String,
        measure: String,
    },
    KMin,
    SfP,
    FrictionMargin,
    /// A scene field the sweep or optimisation sets.
    Field {
        path: String,
    },
}

/// Why an objective or a constraint is not understood.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GoalError {
    #[error("`{0}`: an objective is OUTPUT:min or OUTPUT:max")]
    Sense(String),
    #[error("`{0}`: a constraint is OUTPUT<=VALUE or OUTPUT>=VALUE")]
    Relation(String),
    #[error("`{text}`: the bound `{bound}` is not a finite number")]
    Bound { text: String, bound: String },
    #[error("`{text}`: the scene has no [thermal] cycle to drift along")]
    NoThermal { text: String },
    #[error(
        "`{0}`: unknown output: expected sigma:POINT:DOF, pm3sigma:POINT:DOF, drift:POINT:DOF, \
         residual:POINT:DOF, k_min, sf_p, friction_margin or a scene field such as preload.force"
    )]
    Unknown(String),
    #[error("`{text}`: no evaluation point `{point}` (the scene has {have})")]
    Point { text: String, point: String, have: String },
    #[error(
        "`{text}`: `{measure}` is neither a DOF ({dofs}) nor a direction of `{point}`{directions}"
    )]
    Measure { text: String, point: String, measure: String, dofs: String, directions: String },
    #[error("`{text}`: the field `{path}` is not among those varied ({varied})")]
    NotVaried { text: String, path: String, varied: String },
}

/// Makes an output read at an evaluation point from (point, DOF or direction).
type AtPoint = fn(String, String) -> Output;

impl Output {
    /// Read `text` (module docs).
    pub fn parse(text: &str) -> Result<Output, GoalError> {
        let t = text.trim();
        let point_measure = |rest: &str| {
            let (point, measure) =
                rest.rsplit_once(':').filter(|(p, m)| !p.is_empty() && !m.is_empty())?;
            Some((point.to_string(), measure.trim().to_string()))
        };
        // The outputs read at an evaluation point: `KIND:POINT:DOF`.
        let at_point: [(&str, AtPoint); 4] = [
            ("sigma:", |point, measure| Output::Sigma { point, measure }),
            ("pm3sigma:", |point, measure| Output::Pm3sigma { point, measure }),
            ("drift:", |point, measure| Output::Drift { point, measure }),
            ("residual:", |point, measure| Output::Residual { point, measure }),
        ];
        for (prefix, make) in at_point {
            if let Some(rest) = t.strip_prefix(prefix) {
                let (point, measure) =
                    point_measure(rest).ok_or_else(|| GoalError::Unknown(t.into()))?;
                return Ok(make(point, measure));
            }
        }
        match t {
            "k_min" => Ok(Output::KMin),
            "sf_p" => Ok(Output::SfP),
            "friction_margin" => Ok(Output::FrictionMargin),
            f if f.contains('.') && !f.contains(':') && !f.contains(' ') => {
                Ok(Output::Field { path: f.to_string() })
            }
            _ => Err(GoalError::Unknown(t.into())),
        }
    }

    /// The text form (`sigma:tip:z`, `k_min`, `preload.force`).
    pub fn name(&self) -> String {
        match self {
            Output::Sigma { point, measure } => format!("sigma:{point}:{measure}"),
            Output::Pm3sigma { point, measure } => format!("pm3sigma:{point}:{measure}"),
            Output::Drift { point, measure } => format!("drift:{point}:{measure}"),
            Output::Residual { point, measure } => format!("residual:{point}:{measure}"),
            Output::KMin => "k_min".into(),
            Output::SfP => "sf_p".into(),
            Output::FrictionMargin => "friction_margin".into(),
            Output::Field { path } => path.clone(),
        }
    }

    /// Its SI unit (`m`, `rad`, `N/m`, `1`; a field's: empty).
    pub fn unit(&self) -> &'static str {
        match self {
            Output::Sigma { measure, .. }
            | Output::Pm3sigma { measure, .. }
            | Output::Drift { measure, .. }
            | Output::Residual { measure, .. } => {
                let rotation = Dof::from_name(measure).is_some_and(Dof::is_rotation)
                    || measure.starts_with("about ");
                if rotation { "rad" } else { "m" }
            }
            Output::KMin => "N/m",
            Output::SfP | Output::FrictionMargin => "1",
            Output::Field { .. } => "",
        }
    }

    /// Check it against the base scene and the varied fields: the point
    /// and its DOF or direction exist, a field is varied.
    pub fn check(&self, scene: &Scene, varied: &[String]) -> Result<(), GoalError> {
        let text = self.name();
        match self {
            Output::Drift { .. } | Output::Residual { .. } if scene.thermal.is_none() => {
                Err(GoalError::NoThermal { text })
            }
            Output::Sigma { point, measure }
            | Output::Pm3sigma { point, measure }
            | Output::Drift { point, measure }
            | Output::Residual { point, measure } => {
                let points = &scene.evaluation_points;
                let Some(p) = points.iter().find(|p| p.name == *point) else {
                    let have = points.iter().map(|p| format!("`{}`", p.name)).collect::<Vec<_>>();
                    return Err(GoalError::Point {
                        text,
                        point: point.clone(),
                        have: have.join(", "),
                    });
                };
                let known = Dof::from_name(measure).is_some()
                    || p.directions.iter().any(|d| direction_matches(measure, &d.name, d.rotation));
                if known {
                    return Ok(());
                }
                let names: Vec<String> = p
                    .directions
                    .iter()
                    .map(|d| format!("`{} {}`", if d.rotation { "about" } else { "along" }, d.name))
                    .collect();
                let directions = match names.is_empty() {
                    true => " (it has no directions)".to_string(),
                    false => format!(" ({})", names.join(", ")),
                };
                Err(GoalError::Measure {
                    text,
                    point: point.clone(),
                    measure: measure.clone(),
                    dofs: Dof::names(),
                    directions,
                })
            }
            Output::Field { path } if !varied.contains(path) => {
                Err(GoalError::NotVaried { text, path: path.clone(), varied: varied.join(", ") })
            }
            _ => Ok(()),
        }
    }

    /// Its value for the evaluated design `d` (SI), None where `d` has none
    /// (not evaluated; no allowable pressure; no friction limit).
    pub fn value(&self, d: &DesignReport) -> Option<f64> {
        match self {
            Output::Sigma { point, measure } => point_value(d, point, measure, false),
            Output::Pm3sigma { point, measure } => point_value(d, point, measure, true),
            Output::Drift { point, measure } => drift_value(d, point, measure, false),
            Output::Residual { point, measure } => drift_value(d, point, measure, true),
            Output::KMin => d.principal_stiffness_n_per_m.map(|k| k[0]),
            Output::SfP => d.min_pressure_safety_factor,
            Output::FrictionMargin => d.friction_limit_margin,
            Output::Field { path } => match d.values.get(path)? {
                SweptValue::Number(x) => Some(*x),
                SweptValue::Name(_) => None,
            },
        }
    }
}

/// True if `measure` names the direction `name` (`NAME` or `along NAME`
/// for a translation, `about NAME` for a rotation).
pub(crate) fn direction_matches(measure: &str, name: &str, rotation: bool) -> bool {
    match rotation {
        true => measure.strip_prefix("about ") == Some(name),
        false => measure == name || measure.strip_prefix("along ") == Some(name),
    }
}

/// Sigma (or 3 sigma) of `measure` at `point` of `d` [m or rad].
fn point_value(d: &DesignReport, point: &str, measure: &str, three: bool) -> Option<f64> {
    let p = d.points.iter().find(|p| p.name == point)?;
    if let Some(dof) = Dof::from_name(measure) {
        let s = if three { p.three_sigma } else { p.sigma };
        return Some(s.values()[dof.index()] / NANO);
    }
    let s = p.directions.iter().find(|s| direction_matches(measure, &s.name, s.kind == "about"))?;
    Some(if three { s.three_sigma } else { s.sigma } / NANO)
}

/// The largest |mean drift| of `measure` at `point` of `d` over the cycle
/// points, or (`last`) the |mean drift| at the last [m or rad].
fn drift_value(d: &DesignReport, point: &str, measure: &str, last: bool) -> Option<f64> {
    let p = d.points.iter().find(|p| p.name == point)?;
    let mean = |c: &crate::study::record::CycleStats| -> Option<f64> {
        if let Some(dof) = Dof::from_name(measure) {
            return Some(c.drift.mean.values()[dof.index()].abs() / NANO);
        }
        let s = (c.drift.directions.iter())
            .find(|s| direction_matches(measure, &s.name, s.kind == "about"))?;
        Some(s.mean.abs() / NANO)
    };
    match last {
        true => mean(p.thermal.last()?),
        false => {
            p.thermal.iter().map(mean).collect::<Option<Vec<f64>>>()?.into_iter().reduce(f64::max)
        }
    }
}

/// One list of goals, each parsed and checked by `check`: `given` where
/// given, else the scene's `[goals]` list `key`, whose errors name the
/// item's line.
fn one_list<T>(
    given: &[String],
    (listed, key): (&[Spanned<String>], &str),
    ctx: &ErrorContext,
    parse: fn(&str) -> Result<T, GoalError>,
    check: impl Fn(&T) -> Result<(), GoalError>,
) -> Result<Vec<T>, ExploreError> {
    if !given.is_empty() {
        let each = given.iter().map(|g| parse(g).and_then(|p| check(&p).map(|()| p)));
        return Ok(each.collect::<Result<_, _>>()?);
    }
    let mut out = Vec::new();
    for (k, item) in listed.iter().enumerate() {
        let parsed = parse(item.get_ref()).and_then(|p| check(&p).map(|()| p));
        let field = format!("goals.{key}[{}]", k + 1);
        out.push(parsed.map_err(|e| {
            ExploreError::Scene(ctx.error(Some(&item.span()), field, e.to_string()))
        })?);
    }
    Ok(out)
}

/// Lower or higher is better.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Sense {
    Min,
    Max,
}

/// `OUTPUT:min` or `OUTPUT:max`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Objective {
    #[serde(flatten)]
    pub output: Output,
    pub sense: Sense,
}

impl Objective {
    pub fn parse(text: &str) -> Result<Objective, GoalError> {
        let t = text.trim();
        let (output, sense) = t.rsplit_once(':').ok_or_else(|| GoalError::Sense(t.into()))?;
        let sense = match sense.trim() {
            "min" => Sense::Min,
            "max" => Sense::Max,
            _ => return Err(GoalError::Sense(t.into())),
        };
        Ok(Objective { output: Output::parse(output)?, sense })
    }

    /// `sigma:tip:z:min`.
    pub fn name(&self) -> String {
        format!("{}:{}", self.output.name(), if self.sense == Sense::Min { "min" } else { "max" })
    }

    /// The value of `d` oriented so that larger is better (None: no value).
    pub fn better(&self, d: &DesignReport) -> Option<f64> {
        let v = self.output.value(d)?;
        Some(if self.sense == Sense::Min { -v } else { v })
    }
}

/// `<=` or `>=`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    AtMost,
    AtLeast,
}

/// `OUTPUT<=VALUE` or `OUTPUT>=VALUE`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Constraint {
    #[serde(flatten)]
    pub output: Output,
    pub relation: Relation,
    /// The bound, in the output's SI unit.
    pub bound: f64,
}

impl Constraint {
    pub fn parse(text: &str) -> Result<Constraint, GoalError> {
        let t = text.trim();
        let (output, relation, bound) = if let Some((o, b)) = t.split_once("<=") {
            (o, Relation::AtMost, b)
        } else if let Some((o, b)) = t.split_once(">=") {
            (o, Relation::AtLeast, b)
        } else {
            return Err(GoalError::Relation(t.into()));
        };
        let value: f64 = bound
            .trim()
            .parse()
            .ok()
            .filter(|b: &f64| b.is_finite())
            .ok_or_else(|| GoalError::Bound { text: t.into(), bound: bound.trim().into() })?;
        Ok(Constraint { output: Output::parse(output)?, relation, bound: value })
    }

    /// `sf_p>=3`, `sigma:centre:x<=5e-9`.
    pub fn name(&self) -> String {
        let op = if self.relation == Relation::AtMost { "<=" } else { ">=" };
        let b = self.bound;
        let plain = b == 0.0 || (1e-3..1e6).contains(&b.abs());
        let bound = if plain { format!("{b}") } else { format!("{b:e}") };
        format!("{}{op}{bound}", self.output.name())
    }

    /// How far `d` is inside the bound (>= 0: satisfied), in the output's
    /// unit; None where `d` has no value (an unevaluated design, or no
    /// allowable pressure: the constraint cannot be shown to hold).
    pub fn margin(&self, d: &DesignReport) -> Option<f64> {
        let v = self.output.value(d)?;
        Some(match self.relation {
            Relation::AtMost => self.bound - v,
            Relation::AtLeast => v - self.bound,
        })
    }
}

/// The objectives and constraints of a sweep or an optimisation.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Goals {
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub objectives: Vec<Objective>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub constraints: Vec<Constraint>,
}

impl Goals {
    /// True if an objective or a constraint reads the friction margin.
    pub fn reads_friction_limit(&self) -> bool {
        let outputs = self.objectives.iter().map(|o| &o.output);
        outputs
            .chain(self.constraints.iter().map(|c| &c.output))
            .any(|o| *o == Output::FrictionMargin)
    }

    /// The goals asked for: `objectives` and `constraints` as given (the
    /// command line's, the Python call's), each list in place of the base
    /// scene's `[goals]` list of the same kind where given (the file's read
    /// from `source`, named `file` in its errors, which give the line).
    pub fn asked(
        (objectives, constraints): (&[String], &[String]),
        (base, file, source): (&SceneFile, &str, &str),
        scene: &Scene,
        varied: &[String],
    ) -> Result<Goals, ExploreError> {
        let from_file = base.goals.clone().unwrap_or_default();
        let ctx = ErrorContext::new(file, source);
        let check = |o: &Output| o.check(scene, varied);
        let goals = Goals {
            objectives: one_list(
                objectives,
                (&from_file.objectives, "objectives"),
                &ctx,
                Objective::parse,
                |o| check(&o.output),
            )?,
            constraints: one_list(
                constraints,
                (&from_file.constraints, "constraints"),
                &ctx,
                Constraint::parse,
                |c| check(&c.output),
            )?,
        };
        Ok(goals)
    }

    pub fn is_empty(&self) -> bool {
        self.objectives.is_empty() && self.constraints.is_empty()
    }

    /// The constraints `d` breaks (or cannot be shown to meet), by name.
    pub fn broken(&self, d: &DesignReport) -> Vec<String> {
        (self.constraints.iter())
            .filter(|c| c.margin(d).is_none_or(|m| m < 0.0))
            .map(Constraint::name)
            .collect()
    }
}
