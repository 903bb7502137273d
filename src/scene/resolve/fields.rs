//! The checks every table of a scene shares: a material by name (the
//! scene's own `[[materials]]` first, then the built-ins), a positive
//! number, a finite point and a unit direction, each naming its field.

use std::collections::HashMap;

use nalgebra::Vector3;
use toml::Spanned;

use crate::material::Material;
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::Numbers;

/// One scene file's context and its user materials.
pub struct Fields<'a> {
    pub ctx: &'a ErrorContext<'a>,
    pub materials: HashMap<String, Material>,
}

impl Fields<'_> {
    /// A material by name: the scene's own, else a built-in.
    pub fn material(&self, name: &Spanned<String>, field: &str) -> Result<Material, SceneError> {
        let n = name.get_ref();
        if let Some(m) = self.materials.get(n) {
            return Ok(m.clone());
        }
        Material::builtin(n).map_err(|e| self.ctx.error(Some(&name.span()), field, e.to_string()))
    }

    /// A positive, finite number in `unit`.
    pub fn positive(&self, v: &Spanned<f64>, field: &str, unit: &str) -> Result<f64, SceneError> {
        self.ctx.positive(v, field, unit)
    }

    /// Three finite coordinates.
    pub fn finite(&self, v: &Spanned<Numbers>, field: &str) -> Result<Vector3<f64>, SceneError> {
        let a: [f64; 3] = self.ctx.numbers(v, field, "[x, y, z]")?;
        if a.iter().all(|x| x.is_finite()) {
            Ok(Vector3::new(a[0], a[1], a[2]))
        } else {
            Err(self.ctx.error(Some(&v.span()), field, "coordinates must be finite numbers"))
        }
    }

    /// A direction, normalised; the zero vector is an error.
    pub fn unit(&self, v: &Spanned<Numbers>, field: &str) -> Result<Vector3<f64>, SceneError> {
        let x = self.finite(v, field)?;
        let n = x.norm();
        if n > 0.0 {
            Ok(x / n)
        } else {
            Err(self.ctx.error(Some(&v.span()), field, "a direction must not be the zero vector"))
        }
    }
}
