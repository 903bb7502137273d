//! Validation of the contact pairs of real scenes: each distinct pair (shape,
//! radii, materials) at the largest normal load its contacts reach in the
//! nominal seating, FE against kinrepro's Hertz law.

use serde::Serialize;

use super::{
    ConvergenceRow, FeCase, FeError, Gap, MeshOptions, convergence_study, hertz, solve_case,
};
use crate::assembly::Coupling;
use crate::contact::{ContactPair, ContactShape};
use crate::scene::Scene;
use crate::solve::quasistatic::seat;
use crate::solve::{Load, SolveError, SolverOptions};

/// A distinct contact pair and the load to check it at.
#[derive(Debug, Clone, PartialEq)]
pub struct PairCase {
    pub pair: ContactPair,
    /// Largest normal force of this pair in the nominal seatings [N].
    pub load: f64,
    pub scenes: Vec<String>,
}

/// FE against Hertz for one pair (SI units; the keys of `validate-hertz --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairValidation {
    pub shape: ContactShape,
    /// [ball radius, fixed element radius (null for a plane)].
    pub radii_m: [Option<f64>; 2],
    pub materials: [String; 2],
    pub scenes: Vec<String>,
    pub load_n: f64,
    pub fe_approach_m: f64,
    pub hertz_approach_m: f64,
    pub approach_error_rel: f64,
    /// Semi-axes along the profile's x (radius Rx) and y (radius Ry).
    pub fe_semi_axes_m: [f64; 2],
    pub hertz_semi_axes_m: [f64; 2],
    pub semi_axes_error_rel: [f64; 2],
    pub fe_peak_pressure_pa: f64,
    pub hertz_peak_pressure_pa: f64,
    /// FE force-approach curve [(approach m, force N)].
    pub fe_curve: Vec<(f64, f64)>,
    pub element_size_m: f64,
    pub dofs: usize,
    pub seconds: f64,
    /// Mesh convergence table, when asked for.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub convergence: Vec<ConvergenceRow>,
}

/// The distinct pairs of the scenes' couplings (each scene with its
/// coupling), with the largest load each reaches in the nominal
/// quasi-static seating.
pub fn distinct_pairs(models: &[(Scene, Coupling)]) -> Result<Vec<PairCase>, (String, SolveError)> {
    let mut out: Vec<PairCase> = Vec::new();
    for (scene, c) in models {
        let s = seat(c, &Load::nominal(scene), &SolverOptions::default())
            .map_err(|e| (scene.file.clone(), e))?;
        for (k, r) in c.contacts.iter().zip(&s.contacts) {
            match out.iter_mut().find(|p| p.pair == k.pair) {
                Some(p) => {
                    p.load = p.load.max(r.normal_force_n);
                    if !p.scenes.contains(&scene.file) {
                        p.scenes.push(scene.file.clone());
                    }
                }
                None => out.push(PairCase {
                    pair: k.pair.clone(),
                    load: r.normal_force_n,
                    scenes: vec![scene.file.clone()],
                }),
            }
        }
    }
    Ok(out)
}

/// The FE case of a pair at `load`: its relative radii and E* from
/// kinrepro's contact law, with Hertz's quadratic gap or, if `exact`, the
/// exact separation of its two surfaces ([`Gap::exact`]).
pub fn fe_case(pair: &ContactPair, load: f64, exact: bool) -> Result<FeCase, FeError> {
    let law = pair.law().map_err(|e| FeError::InvalidInput(e.to_string()))?;
    let [rx, ry] = law.hertz.radii;
    let gap = if exact { Gap::exact(&pair.curvature, rx, ry)? } else { Gap::Quadratic };
    Ok(FeCase { rx, ry, e_star: law.hertz.e_star, load, gap })
}

/// Run the FE check of one pair; `levels` (element size / semi-axis) adds a
/// convergence table.
pub fn validate_pair(
    case: &PairCase,
    mesh: &MeshOptions,
    levels: &[f64],
) -> Result<PairValidation, FeError> {
    let fe_case = fe_case(&case.pair, case.load, false)?;
    let fe = solve_case(&fe_case, mesh)?;
    let hz = hertz(fe_case.rx, fe_case.ry, fe_case.e_star, case.load)?;
    let rel = |a: f64, b: f64| a / b - 1.0;
    Ok(PairValidation {
        shape: case.pair.shape,
        radii_m: {
            let (r1, r2) = case.pair.nominal_radii();
            [Some(r1), r2]
        },
        materials: [case.pair.material1.name.clone(), case.pair.material2.name.clone()],
        scenes: case.scenes.clone(),
        load_n: case.load,
        fe_approach_m: fe.approach,
        hertz_approach_m: hz.approach,
        approach_error_rel: rel(fe.approach, hz.approach),
        fe_semi_axes_m: fe.semi_axes,
        hertz_semi_axes_m: hz.semi_axes,
        semi_axes_error_rel: [0, 1].map(|k| rel(fe.semi_axes[k], hz.semi_axes[k])),
        fe_peak_pressure_pa: fe.peak_pressure,
        hertz_peak_pressure_pa: hz.peak_pressure,
        fe_curve: fe.curve,
        element_size_m: fe.element_size,
        dofs: fe.dofs,
        seconds: fe.seconds,
        convergence: convergence_study(&fe_case, levels)?,
    })
}
