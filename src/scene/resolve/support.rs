//! `support_compliance`: the compliance of the mount behind a contact
//! surface (a flexure), in series with the contact [m/N].
//!
//! A number is the normal part only. A table gives the parts by name:
//! `normal` (along the contact normal, in series with Hertz), `tangential`
//! (every direction of the tangent plane, in series with Mindlin), or
//! `along` and `across` an axis of the tangent plane (a blade flexure is
//! compliant across its blade and stiff along it). The axis is the
//! groove's in the `[coupling]` form (`expand` writes it); an explicit
//! surface gives `axis = [x, y, z]` (a pin or a gothic-arch flank defaults
//! to its own direction). Each part defaults to 0 (rigid).

use nalgebra::Vector3;
use toml::Spanned;

use crate::contact::TangentialSupport;
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::number;

/// A support compliance in series with a contact [m/N]: normal (Hertz's
/// direction) and tangential, with the axis of `along` if the table gave
/// one (`None`: the surface's own, [`Support::oriented`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Support {
    pub normal: f64,
    pub tangential: TangentialSupport,
    /// `axis` as written, normalised.
    pub axis: Option<Vector3<f64>>,
}

impl Support {
    /// The tangential support with its axis: the table's, else `default`
    /// (a pin's or a flank's direction); an anisotropic support with
    /// neither is refused at `field`.
    pub fn oriented(
        &self,
        default: Option<Vector3<f64>>,
        ctx: &ErrorContext,
        span: &std::ops::Range<usize>,
        field: &str,
    ) -> Result<TangentialSupport, SceneError> {
        let t = self.tangential;
        if t.is_isotropic() {
            return Ok(TangentialSupport::isotropic(t.along));
        }
        match self.axis.or(default) {
            Some(axis) => Ok(TangentialSupport { axis, ..t }),
            None => Err(ctx.error(
                Some(span),
                format!("{field}.axis"),
                "`along` and `across` differ, so they need the direction of `along`: give \
                 `axis = [x, y, z]` (a plane or a fixed ball has no direction of its own)",
            )),
        }
    }
}

/// `support_compliance` at `field` (module docs): every value finite and
/// at least 0 [m/N], `tangential` or `along`/`across` but not both, `axis`
/// a non-zero vector (allowed where `axis_allowed`, the explicit surfaces).
pub fn support(
    ctx: &ErrorContext,
    v: &Spanned<toml::Value>,
    field: &str,
    axis_allowed: bool,
) -> Result<Support, SceneError> {
    let span = v.span();
    let err = |field: String, why: String| ctx.error(Some(&span), field, why);
    let checked = |x: &toml::Value, field: &str| -> Result<f64, SceneError> {
        let value = number(x).ok_or_else(|| {
            err(field.into(), format!("expected a compliance in m/N, found {}", x.type_str()))
        })?;
        compliance(ctx, &Spanned::new(span.clone(), value), field)
    };
    let t = match v.get_ref() {
        toml::Value::Table(t) => t,
        x => return Ok(Support { normal: checked(x, field)?, ..Support::default() }),
    };
    let mut out = Support::default();
    let (mut tangential, mut along, mut across) = (None, None, None);
    for (key, x) in t {
        let sub = format!("{field}.{key}");
        match key.as_str() {
            "normal" => out.normal = checked(x, &sub)?,
            "tangential" => tangential = Some(checked(x, &sub)?),
            "along" => along = Some(checked(x, &sub)?),
            "across" => across = Some(checked(x, &sub)?),
            "axis" if axis_allowed => {
                out.axis = Some(axis(x).ok_or_else(|| {
                    err(sub, "expected three numbers [x, y, z], not all zero".into())
                })?)
            }
            "axis" => {
                return Err(err(
                    sub,
                    "the [coupling] form orients `along` by each groove's axis (docs/scenes.md); \
                     `axis` belongs to an explicit [[surfaces]] entry"
                        .into(),
                ));
            }
            _ => {
                return Err(err(
                    sub,
                    "unknown key: a support compliance has `normal`, `tangential`, or `along` \
                     and `across` [m/N]"
                        .into(),
                ));
            }
        }
    }
    out.tangential = match (tangential, along.is_some() || across.is_some()) {
        (Some(_), true) => {
            return Err(err(
                format!("{field}.tangential"),
                "give `tangential` (every direction of the tangent plane) or `along` and \
                 `across`, not both"
                    .into(),
            ));
        }
        (Some(c), false) => TangentialSupport::isotropic(c),
        (None, _) => TangentialSupport {
            along: along.unwrap_or(0.0),
            across: across.unwrap_or(0.0),
            axis: Vector3::zeros(),
        },
    };
    Ok(out)
}

/// Three finite numbers, not all zero, normalised.
fn axis(x: &toml::Value) -> Option<Vector3<f64>> {
    let items = x.as_array()?;
    let v: Option<Vec<f64>> = items.iter().map(number).collect();
    let v = v?;
    let v = (v.len() == 3).then(|| Vector3::new(v[0], v[1], v[2]))?;
    let norm = v.norm();
    (norm.is_finite() && norm > 0.0).then(|| v / norm)
}

/// A compliance [m/N]: finite and >= 0.
pub fn compliance(ctx: &ErrorContext, v: &Spanned<f64>, field: &str) -> Result<f64, SceneError> {
    let x = *v.get_ref();
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else {
        Err(ctx.error(
            Some(&v.span()),
            field,
            format!("{x} must be finite and >= 0 (a compliance in m/N)"),
        ))
    }
}
