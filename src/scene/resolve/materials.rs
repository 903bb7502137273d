//! `[[materials]]`: the scene's own materials, each validated, and the
//! rules for reusing a name.

use std::collections::HashMap;

use crate::material::{Material, MaterialError};
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::SceneFile;

/// The `[[materials]]` entries, in order; a later entry replaces an earlier
/// one of the same name. Reusing a built-in or an earlier name is an error
/// unless the entry says `override = true`, and `override = true` on a name
/// that replaces nothing is one too (a misspelt name would otherwise define
/// a new material silently).
pub fn user_materials(
    f: &SceneFile,
    ctx: &ErrorContext,
) -> Result<HashMap<String, Material>, SceneError> {
    // name -> (the material, the 1-based entry that first defined it)
    let mut out: HashMap<String, (Material, usize)> = HashMap::new();
    for (i, (m, mat)) in f.materials.iter().zip(material_entries(f, ctx)?).enumerate() {
        let name = m.name.get_ref();
        let field = format!("materials[{}]", i + 1);
        if name.trim().is_empty() {
            return Err(ctx.error(
                Some(&m.name.span()),
                format!("{field}.name"),
                "is empty: a material needs a name the scene can refer to".to_string(),
            ));
        }
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
            .and_then(|mat| {
                mat.with_thermal_expansion(m.thermal_expansion.as_ref().map(|a| *a.get_ref()))
            })
            .map_err(|e| {
                let field = match &e {
                    MaterialError::Invalid { field, .. } => *field,
                    _ => "",
                };
                let span = match field {
                    "youngs_modulus" => Some(m.youngs_modulus.span()),
                    "poisson_ratio" => Some(m.poisson_ratio.span()),
                    "allowable_pressure" => m.allowable_pressure.as_ref().map(|p| p.span()),
                    "allowable_shear_stress" => m.allowable_shear_stress.as_ref().map(|t| t.span()),
                    "thermal_expansion" => m.thermal_expansion.as_ref().map(|a| a.span()),
                    _ => None,
                }
                .unwrap_or_else(|| m.name.span());
                ctx.error(Some(&span), format!("materials[{}]", i + 1), e.to_string())
            })
        })
        .collect()
}
