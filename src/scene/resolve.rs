//! Validation of an explicit scene file into a [`Scene`]: materials resolved,
//! every number checked for range, every surface complete.

use std::collections::HashMap;

use nalgebra::Vector3;
use toml::Spanned;

use super::error::{ErrorContext, SceneError};
use super::file::{
    FrictionFile, FrictionLawName, Numbers, SceneFile, SurfaceFile, SurfaceKind, VariationFile,
};
use super::plausible;
use super::{
    Ball, DEFAULT_RAMP_TIME, DynamicsSettings, EvaluationPoint, FrictionSettings, Preload,
    SamplerChoice, Scene, StudySettings, Surface, SurfaceGeometry, VariationBounds,
};
use crate::contact::{FrictionLaw, TangentialLaw};
use crate::material::{Material, MaterialError};

/// Largest friction coefficient accepted in a scene.
pub const MU_MAX: f64 = 2.0;

pub fn resolve(f: &SceneFile, ctx: &ErrorContext) -> Result<Scene, SceneError> {
    let materials = user_materials(f, ctx)?;
    let material = |name: &Spanned<String>, field: &str| -> Result<Material, SceneError> {
        let n = name.get_ref();
        if let Some(m) = materials.get(n) {
            return Ok(m.clone());
        }
        Material::builtin(n).map_err(|e| ctx.error(Some(&name.span()), field, e.to_string()))
    };
    let positive = |v: &Spanned<f64>, field: &str, unit: &str| ctx.positive(v, field, unit);
    let finite = |v: &Spanned<Numbers>, field: &str| -> Result<Vector3<f64>, SceneError> {
        let a: [f64; 3] = ctx.numbers(v, field, "[x, y, z]")?;
        if a.iter().all(|x| x.is_finite()) {
            Ok(Vector3::new(a[0], a[1], a[2]))
        } else {
            Err(ctx.error(Some(&v.span()), field, "coordinates must be finite numbers"))
        }
    };
    let unit = |v: &Spanned<Numbers>, field: &str| -> Result<Vector3<f64>, SceneError> {
        let x = finite(v, field)?;
        let n = x.norm();
        if n > 0.0 {
            Ok(x / n)
        } else {
            Err(ctx.error(
                Some(&v.span()),
                field,
                "a direction must not be the zero vector",
            ))
        }
    };

    if f.balls.is_empty() {
        return Err(ctx.error(
            None,
            "balls",
            "no moving balls: give a [coupling] table or [[balls]] and [[surfaces]]",
        ));
    }
    let mut balls = Vec::new();
    for (i, b) in f.balls.iter().enumerate() {
        let field = |k: &str| format!("balls[{}].{k}", i + 1);
        balls.push(Ball {
            centre: finite(&b.centre, &field("centre"))?,
            radius: positive(&b.radius, &field("radius"), "m")?,
            material: material(&b.material, &field("material"))?,
            line: ctx.line_of(&b.radius.span()),
        });
    }

    let mut surfaces = Vec::new();
    // Radii are checked positive below; first the magnitudes (millimetres?).
    let centres: Vec<Vector3<f64>> = balls.iter().map(|b| b.centre).collect();
    plausible::check_explicit(f, &centres, ctx)?;
    for (i, s) in f.surfaces.iter().enumerate() {
        let field = |k: &str| format!("surfaces[{}].{k}", i + 1);
        let ball = *s.ball.get_ref();
        if ball < 1 || ball as usize > balls.len() {
            return Err(ctx.error(
                Some(&s.ball.span()),
                field("ball"),
                format!("{ball} names no moving ball (there are {})", balls.len()),
            ));
        }
        let need =
            |v: &Option<Spanned<Numbers>>, k: &str| -> Result<Spanned<Numbers>, SceneError> {
                v.clone().ok_or_else(|| missing(s, ctx, &field(k), k))
            };
        let radius = |s: &SurfaceFile| -> Result<f64, SceneError> {
            let r = s
                .radius
                .as_ref()
                .ok_or_else(|| missing(s, ctx, &field("radius"), "radius"))?;
            positive(r, &field("radius"), "m")
        };
        let geometry = match s.kind.get_ref() {
            SurfaceKind::Plane => SurfaceGeometry::Plane {
                point: finite(&need(&s.point, "point")?, &field("point"))?,
                normal: unit(&need(&s.normal, "normal")?, &field("normal"))?,
            },
            SurfaceKind::Cylinder => SurfaceGeometry::Cylinder {
                axis_point: finite(&need(&s.axis_point, "axis_point")?, &field("axis_point"))?,
                direction: unit(&need(&s.direction, "direction")?, &field("direction"))?,
                radius: radius(s)?,
            },
            SurfaceKind::Sphere => SurfaceGeometry::Sphere {
                centre: finite(&need(&s.centre, "centre")?, &field("centre"))?,
                radius: radius(s)?,
            },
        };
        surfaces.push(Surface {
            geometry,
            material: material(&s.material, &field("material"))?,
            ball: ball as usize - 1,
            line: ctx.line_of(&s.kind.span()),
            support_compliance: match &s.support_compliance {
                Some(v) => compliance(ctx, v, &field("support_compliance"))?,
                None => 0.0,
            },
        });
    }
    // Contacts are numbered ball by ball (the order of --mu).
    surfaces.sort_by_key(|s| s.ball);
    let mut served = vec![false; balls.len()];
    surfaces.iter().for_each(|s| served[s.ball] = true);
    for (k, b) in balls.iter().enumerate() {
        if !served[k] {
            return Err(SceneError {
                file: ctx.file.to_string(),
                line: b.line,
                field: format!("balls[{}]", k + 1),
                reason: "this ball touches no fixed surface (no [[surfaces]] entry has ball = \
                         its number)"
                    .to_string(),
            });
        }
    }

    let p = &f.preload;
    let preload = Preload {
        force: positive(&p.force, "preload.force", "N")?,
        point: match &p.point {
            Some(v) => finite(v, "preload.point")?,
            None => Vector3::zeros(),
        },
        direction: match &p.direction {
            Some(v) => unit(v, "preload.direction")?,
            None => -Vector3::z(),
        },
        ramp_time: match &p.ramp_time {
            Some(v) => positive(v, "preload.ramp_time", "s")?,
            None => DEFAULT_RAMP_TIME,
        },
    };

    let fr = &f.friction;
    let mu = *fr.mu_static.get_ref();
    if !(0.0..=MU_MAX).contains(&mu) {
        return Err(ctx.error(
            Some(&fr.mu_static.span()),
            "friction.mu_static",
            format!("{mu} is outside [0, {MU_MAX}]"),
        ));
    }
    let spread = *fr.spread.get_ref();
    if !(spread >= 0.0 && spread <= mu) {
        return Err(ctx.error(
            Some(&fr.spread.span()),
            "friction.spread",
            format!("{spread} must lie in [0, mu_static = {mu}] (friction cannot be negative)"),
        ));
    }
    if mu + spread > MU_MAX {
        return Err(ctx.error(
            Some(&fr.spread.span()),
            "friction.spread",
            format!("mu_static + spread = {} exceeds {MU_MAX}", mu + spread),
        ));
    }
    let ratio = *fr.dynamic_ratio.get_ref();
    if !(ratio > 0.0 && ratio <= 1.0) {
        return Err(ctx.error(
            Some(&fr.dynamic_ratio.span()),
            "friction.dynamic_ratio",
            format!("{ratio} must lie in (0, 1]: mu_d = ratio * mu_s"),
        ));
    }
    let law = friction_law(fr, ctx)?;

    let st = &f.study;
    let samples = *st.samples.get_ref();
    if samples < 2 {
        return Err(ctx.error(
            Some(&st.samples.span()),
            "study.samples",
            format!("{samples}: a study needs at least 2 samples"),
        ));
    }
    let name = st.sampler.get_ref();
    let sampler = SamplerChoice::parse(name).ok_or_else(|| {
        ctx.error(
            Some(&st.sampler.span()),
            "study.sampler",
            format!("unknown sampler '{name}': expected lhs, mc or corners"),
        )
    })?;

    let mut evaluation_points = Vec::new();
    for (i, e) in f.evaluation_points.iter().enumerate() {
        evaluation_points.push(EvaluationPoint {
            name: e.name.clone(),
            position: finite(
                &e.position,
                &format!("evaluation_points[{}].position", i + 1),
            )?,
        });
    }
    if evaluation_points.is_empty() {
        evaluation_points.push(EvaluationPoint {
            name: "centre".to_string(),
            position: Vector3::zeros(),
        });
    }

    let dynamics = match &f.dynamics {
        None => None,
        Some(d) => {
            let mass = positive(&d.mass, "dynamics.mass", "kg")?;
            let i = finite(&d.inertia, "dynamics.inertia")?;
            let bad =
                |reason: String| ctx.error(Some(&d.inertia.span()), "dynamics.inertia", reason);
            if !i.iter().all(|v| *v > 0.0) {
                return Err(bad(format!(
                    "[{}, {}, {}]: principal moments of inertia must be positive (kg m^2)",
                    i.x, i.y, i.z
                )));
            }
            // Principal moments of a real body obey the triangle inequality
            // (I_a + I_b >= I_c, since I_a + I_b - I_c = 2 int z_c^2 dm >= 0).
            let sum = i.x + i.y + i.z;
            if let Some(k) = (0..3).find(|&k| 2.0 * i[k] > sum * (1.0 + 1e-12)) {
                return Err(bad(format!(
                    "[{}, {}, {}]: no rigid body has these principal moments: the {} moment \
                     exceeds the sum of the other two",
                    i.x,
                    i.y,
                    i.z,
                    ["x", "y", "z"][k]
                )));
            }
            let centre_of_mass = match &d.centre_of_mass {
                Some(v) => finite(v, "dynamics.centre_of_mass")?,
                None => Vector3::zeros(),
            };
            Some(DynamicsSettings {
                mass,
                inertia: i,
                centre_of_mass,
            })
        }
    };

    let variation = match &f.variation {
        None => VariationBounds::default(),
        Some(v) => variation_bounds(v, ctx)?,
    };

    Ok(Scene {
        file: ctx.file.to_string(),
        name: f.name.clone().unwrap_or_else(|| ctx.file.to_string()),
        balls,
        surfaces,
        preload,
        friction: FrictionSettings {
            mu_static: mu,
            spread,
            dynamic_ratio: ratio,
            tangential_law: fr.tangential_law,
            law,
        },
        study: StudySettings {
            samples: samples as usize,
            sampler,
            seed: st.seed,
        },
        evaluation_points,
        dynamics,
        variation,
    })
}

/// `[friction] law` and `decay_coefficient`: the decay law needs a finite
/// coefficient >= 0 [s/m] and the Coulomb tangential law; the switch law takes none.
fn friction_law(fr: &FrictionFile, ctx: &ErrorContext) -> Result<FrictionLaw, SceneError> {
    let name = fr.law.as_ref().map(|l| *l.get_ref());
    match (name, &fr.decay_coefficient) {
        (None | Some(FrictionLawName::Switch), None) => Ok(FrictionLaw::Switch),
        (None | Some(FrictionLawName::Switch), Some(c)) => Err(ctx.error(
            Some(&c.span()),
            "friction.decay_coefficient",
            "only the decay law uses it: set law = \"decay\" or remove it",
        )),
        (Some(FrictionLawName::Decay), None) => Err(ctx.error(
            fr.law.as_ref().map(|l| l.span()).as_ref(),
            "friction.decay_coefficient",
            "missing: law = \"decay\" needs decay_coefficient [s/m]",
        )),
        (Some(FrictionLawName::Decay), Some(c)) => {
            let v = *c.get_ref();
            if !(v.is_finite() && v >= 0.0) {
                return Err(ctx.error(
                    Some(&c.span()),
                    "friction.decay_coefficient",
                    format!("{v} must be finite and >= 0 (s/m)"),
                ));
            }
            if fr.tangential_law != TangentialLaw::Coulomb {
                return Err(ctx.error(
                    fr.law.as_ref().map(|l| l.span()).as_ref(),
                    "friction.law",
                    "law = \"decay\" works with tangential_law = \"coulomb\" only",
                ));
            }
            Ok(FrictionLaw::Decay { coefficient: v })
        }
    }
}

/// A support compliance [m/N]: finite and >= 0.
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

/// `[variation]`: every bound finite and >= 0.
fn variation_bounds(v: &VariationFile, ctx: &ErrorContext) -> Result<VariationBounds, SceneError> {
    fn check<const N: usize>(
        ctx: &ErrorContext,
        v: &Option<Spanned<Numbers>>,
        key: &str,
        unit: &str,
    ) -> Result<[f64; N], SceneError> {
        let Some(s) = v else {
            return Ok([0.0; N]);
        };
        let what = if N == 2 { "[x, y]" } else { "[x, y, z]" };
        let a: [f64; N] = ctx.numbers(s, &format!("variation.{key}"), what)?;
        if let Some(x) = a.iter().find(|x| !(x.is_finite() && **x >= 0.0)) {
            return Err(ctx.error(
                Some(&s.span()),
                format!("variation.{key}"),
                format!(
                    "{x}: a tolerance or variation bound is a half-width and must be finite \
                     and >= 0 ({unit})"
                ),
            ));
        }
        Ok(a)
    }
    let scalar = |v: &Option<Spanned<f64>>, key: &str, unit: &str| -> Result<f64, SceneError> {
        let arr = v
            .as_ref()
            .map(|s| Spanned::new(s.span(), Numbers::of(&[*s.get_ref()])));
        Ok(check::<1>(ctx, &arr, key, unit)?[0])
    };
    Ok(VariationBounds {
        preload_offset_m: check(ctx, &v.preload_offset, "preload_offset", "m")?,
        preload_tilt_rad: scalar(&v.preload_tilt, "preload_tilt", "rad")?,
        ball_diameter_m: scalar(&v.ball_diameter, "ball_diameter", "m")?,
        ball_position_m: check(ctx, &v.ball_position, "ball_position", "m")?,
        surface_normal_m: scalar(&v.surface_normal, "surface_normal", "m")?,
        surface_tilt_rad: scalar(&v.surface_tilt, "surface_tilt", "rad")?,
        groove_position_m: check(ctx, &v.groove_position, "groove_position", "m")?,
    })
}

fn missing(s: &SurfaceFile, ctx: &ErrorContext, field: &str, key: &str) -> SceneError {
    let kind = match s.kind.get_ref() {
        SurfaceKind::Plane => "plane",
        SurfaceKind::Cylinder => "cylinder",
        SurfaceKind::Sphere => "sphere",
    };
    ctx.error(
        Some(&s.kind.span()),
        field,
        format!("missing: a {kind} needs `{key}`"),
    )
}

/// The `[[materials]]` entries, in order; a later entry replaces an earlier
/// one of the same name. Reusing a built-in or an earlier name is an error
/// unless the entry says `override = true`, and `override = true` on a name
/// that replaces nothing is one too (a misspelt name would otherwise define
/// a new material silently).
fn user_materials(
    f: &SceneFile,
    ctx: &ErrorContext,
) -> Result<HashMap<String, Material>, SceneError> {
    // name -> (the material, the 1-based entry that first defined it)
    let mut out: HashMap<String, (Material, usize)> = HashMap::new();
    for (i, (m, mat)) in f
        .materials
        .iter()
        .zip(material_entries(f, ctx)?)
        .enumerate()
    {
        let name = m.name.get_ref();
        let field = format!("materials[{}]", i + 1);
        let builtin = Material::builtin(name).is_ok();
        let replaces = m.replaces.as_ref().is_some_and(|r| *r.get_ref());
        let first = out.get(name).map(|(_, j)| *j);
        let what = match (first, builtin) {
            (Some(j), _) => Some(format!("`{name}` is already defined in materials[{j}]")),
            (None, true) => Some(format!("`{name}` is a built-in material")),
            (None, false) => None,
        };
        match (what, replaces) {
            (Some(what), false) => {
                return Err(ctx.error(
                    Some(&m.name.span()),
                    format!("{field}.name"),
                    format!(
                        "{what}: give the material another name, or add `override = true` \
                         to this entry if it is meant to replace the other definition"
                    ),
                ));
            }
            (None, true) => {
                let span = m.replaces.as_ref().map(|r| r.span());
                return Err(ctx.error(
                    span.as_ref(),
                    format!("{field}.override"),
                    format!(
                        "`{name}` is neither a built-in material nor defined earlier, so \
                         there is nothing to override (misspelt name?)"
                    ),
                ));
            }
            _ => {}
        }
        out.insert(name.clone(), (mat, first.unwrap_or(i + 1)));
    }
    Ok(out.into_iter().map(|(k, (m, _))| (k, m)).collect())
}

/// Each `[[materials]]` entry validated on its own.
fn material_entries(f: &SceneFile, ctx: &ErrorContext) -> Result<Vec<Material>, SceneError> {
    f.materials
        .iter()
        .enumerate()
        .map(|(i, m)| {
            Material::new(
                m.name.get_ref(),
                *m.youngs_modulus.get_ref(),
                *m.poisson_ratio.get_ref(),
                m.allowable_pressure.as_ref().map(|p| *p.get_ref()),
            )
            .and_then(|mat| {
                mat.with_allowable_shear_stress(
                    m.allowable_shear_stress.as_ref().map(|t| *t.get_ref()),
                )
            })
            .map_err(|e| {
                let span = match &e {
                    MaterialError::Invalid {
                        field: "youngs_modulus",
                        ..
                    } => m.youngs_modulus.span(),
                    MaterialError::Invalid {
                        field: "poisson_ratio",
                        ..
                    } => m.poisson_ratio.span(),
                    MaterialError::Invalid {
                        field: "allowable_pressure",
                        ..
                    } => m
                        .allowable_pressure
                        .as_ref()
                        .map(|p| p.span())
                        .unwrap_or_else(|| m.name.span()),
                    MaterialError::Invalid {
                        field: "allowable_shear_stress",
                        ..
                    } => m
                        .allowable_shear_stress
                        .as_ref()
                        .map(|t| t.span())
                        .unwrap_or_else(|| m.name.span()),
                    _ => m.name.span(),
                };
                ctx.error(Some(&span), format!("materials[{}]", i + 1), e.to_string())
            })
        })
        .collect()
}
