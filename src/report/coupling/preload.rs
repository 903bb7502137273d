//! The preload in words, for `check` and the HTML drawing.

use crate::scene::{ForceLaw, Preload, PreloadForce};

/// One force: `F N along (d) at (p) m`, with its spring or weight.
pub fn force_text(f: &PreloadForce) -> String {
    let (d, p) = (f.direction, f.point);
    let law = match &f.law {
        ForceLaw::Constant => String::new(),
        ForceLaw::Spring { stiffness, free_length } => {
            format!(", spring of {stiffness} N/m, free length {free_length} m")
        }
        ForceLaw::Weight => ", the weight of the moving half".to_string(),
        ForceLaw::Magnet(m) => {
            let (_, slope) = m.force(m.gap);
            format!(
                ", magnet at a gap of {} m (table of {} points; dF/dgap {slope:.4e} N/m there)",
                m.gap,
                m.table.len()
            )
        }
    };
    format!(
        "{:.4} N along ({:.3}, {:.3}, {:.3}) at ({:.4}, {:.4}, {:.4}) m{law}",
        f.force, d.x, d.y, d.z, p.x, p.y, p.z
    )
}

/// The preload on one line: a single force as [`force_text`], several as
/// their number and resultant (each listed by [`force_lines`]).
pub fn summary(p: &Preload) -> String {
    match p.forces.as_slice() {
        [one] => force_text(one),
        _ => {
            let r = p.resultant().map(|v| v + 0.0);
            format!("{} forces, resultant ({:.4}, {:.4}, {:.4}) N", p.forces.len(), r.x, r.y, r.z)
        }
    }
}

/// One indented line per force when there are several (else empty).
pub fn force_lines(p: &Preload, indent: &str) -> String {
    if p.forces.len() < 2 {
        return String::new();
    }
    let lines = p.forces.iter().enumerate();
    lines.map(|(i, f)| format!("{indent}preload force {}: {}\n", i + 1, force_text(f))).collect()
}
