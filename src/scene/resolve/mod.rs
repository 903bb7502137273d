//! Validation of an explicit scene file into a [`Scene`]: materials resolved,
//! every number checked for range, every surface complete. One validator
//! per TOML table (`geometry`: balls and surfaces, `preload`, `tables`:
//! the other scalar tables, `materials`), in the order the errors are reported.

mod fields;
pub mod geometry;
pub mod materials;
pub mod points;
pub mod preload;
pub mod support;
pub mod tables;
pub mod thermal;

use fields::Fields;
pub use support::{Support, compliance, support};
pub use tables::MU_MAX;

use super::error::{ErrorContext, SceneError};
use super::file::SceneFile;
use super::{Scene, VariationBounds};
use crate::contact::TangentialLaw;

pub fn resolve(f: &SceneFile, ctx: &ErrorContext) -> Result<Scene, SceneError> {
    let fx = Fields { ctx, materials: materials::user_materials(f, ctx)? };
    let balls = geometry::balls(f, &fx)?;
    let surfaces = geometry::surfaces(f, &fx, &balls)?;
    let preload = preload::preload(&f.preload, f.dynamics.as_ref(), &fx, f.allow_large_values)?;
    let ball_of: Vec<usize> = surfaces.iter().map(|s| s.ball).collect();
    let (friction, contact_friction, mu_distribution) =
        tables::friction(&f.friction, &ball_of, ctx)?;
    let tangential = surfaces.iter().position(|s| !s.tangential_support.is_rigid());
    if let (Some(i), TangentialLaw::MindlinDeresiewicz) = (tangential, friction.tangential_law) {
        return Err(ctx.error(
            None,
            "friction.tangential_law",
            format!(
                "mindlin-deresiewicz does not take a tangential support compliance (surface {} \
                 has one): use coulomb, or give the support compliance without `tangential`",
                i + 1
            ),
        ));
    }
    let study = tables::study(&f.study, ctx)?;
    let evaluation_points = points::evaluation_points(f, &fx)?;
    let dynamics = match &f.dynamics {
        None => None,
        Some(d) => Some(tables::dynamics(d, &fx)?),
    };
    let variation = match &f.variation {
        None => VariationBounds::default(),
        Some(v) => {
            let bounds = tables::variation_bounds(v, ctx)?;
            if !f.allow_large_values {
                let r_min = balls.iter().map(|b| b.radius).fold(f64::INFINITY, f64::min);
                let reach = balls.iter().map(|b| b.centre.xy().norm()).fold(0.0, f64::max);
                super::plausible::check_variation(v, &bounds, (r_min, reach), ctx)?;
            }
            bounds
        }
    };
    let thermal = thermal::thermal(f, &fx, &balls, &surfaces)?;
    Ok(Scene {
        file: ctx.file.to_string(),
        name: f.name.clone().unwrap_or_else(|| ctx.file.to_string()),
        balls,
        surfaces,
        preload,
        friction,
        contact_friction,
        mu_distribution,
        mu_correlation: tables::correlation(&f.friction, ctx)?,
        study,
        evaluation_points,
        dynamics,
        variation,
        thermal,
    })
}
