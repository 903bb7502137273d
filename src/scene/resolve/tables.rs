//! The scalar tables of a scene: `[friction]`, `[study]`,
//! `[[evaluation_points]]`, `[dynamics]` and `[variation]`, one validator each.

use nalgebra::Vector3;
use toml::Spanned;

use super::fields::Fields;
use crate::contact::{FrictionLaw, TangentialLaw};
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::{
    Distribution, DynamicsFile, FrictionFile, FrictionLawName, Numbers, StudyFile, VariationFile,
    number,
};
use crate::scene::{
    DynamicsSettings, FrictionSettings, MuDistribution, Sampler, StudyDefaults, VariationBounds,
};

/// Largest friction coefficient accepted in a scene.
pub const MU_MAX: f64 = 2.0;

/// `[friction]`: 0 <= mu_s <= [`MU_MAX`], 0 <= spread <= mu_s with
/// mu_s + spread <= [`MU_MAX`], 0 < dynamic_ratio <= 1, and the law.
/// One number of `friction.<key>`, one per contact (a list in contact
/// order), or one per ball (a table `{ 1 = 0.5, 2 = 0.15, 3 = 0.5 }` by
/// ball number, every ball given, each ball's value at all its
/// contacts); `ball_of[k]` is contact k's ball (0-based). The values per
/// contact and whether they may differ (a list or a table was given).
fn per_contact(
    v: &Spanned<toml::Value>,
    key: &str,
    ball_of: &[usize],
    ctx: &ErrorContext,
) -> Result<(Vec<f64>, bool), SceneError> {
    let contacts = ball_of.len();
    let field = format!("friction.{key}");
    let bad = |why: String| ctx.error(Some(&v.span()), field.clone(), why);
    match v.get_ref() {
        toml::Value::Array(items) => {
            if items.len() != contacts {
                return Err(bad(format!(
                    "{} values for {contacts} contacts: give one per contact, in contact order \
                     (docs/model.md, \"Axes and contact numbering\"), or one number",
                    items.len()
                )));
            }
            let values: Option<Vec<f64>> = items.iter().map(number).collect();
            let values = values.ok_or_else(|| bad("every value must be a number".into()))?;
            Ok((values, true))
        }
        toml::Value::Table(t) => Ok((by_ball(t, ball_of, &bad)?, true)),
        x => match number(x) {
            Some(n) => Ok((vec![n; contacts], false)),
            None => Err(bad(format!(
                "expected a number, a list with one per contact or a table by ball, found {}",
                x.type_str()
            ))),
        },
    }
}

/// The values per contact of a table by ball number (1-based; module docs
/// of [`per_contact`]).
fn by_ball(
    t: &toml::Table,
    ball_of: &[usize],
    bad: &dyn Fn(String) -> SceneError,
) -> Result<Vec<f64>, SceneError> {
    let balls = ball_of.iter().max().map_or(0, |b| b + 1);
    let mut value = vec![None; balls];
    for (key, x) in t {
        let b = key.parse::<usize>().ok().filter(|b| (1..=balls).contains(b)).ok_or_else(|| {
            bad(format!("'{key}' is not a ball: the keys are ball numbers 1 to {balls}"))
        })?;
        let n = number(x);
        value[b - 1] = Some(n.ok_or_else(|| bad(format!("ball {b}: the value must be a number")))?);
    }
    if let Some(b) = value.iter().position(Option::is_none) {
        return Err(bad(format!("ball {} is missing: give every ball of the {balls}", b + 1)));
    }
    Ok(ball_of.iter().map(|&b| value[b].unwrap_or(0.0)).collect())
}

/// [mu_static, spread] of each contact, in contact order.
pub type ContactFriction = Vec<[f64; 2]>;

/// `[friction]` for `contacts` contacts: the settings (one mu0 and spread,
/// the means where lists are given) and the per-contact pairs when lists
/// are given; each contact's mu0 in [0, MU_MAX], spread in [0, mu0] and
/// mu0 + spread <= MU_MAX.
pub fn friction(
    fr: &FrictionFile,
    ball_of: &[usize],
    ctx: &ErrorContext,
) -> Result<(FrictionSettings, Option<ContactFriction>, MuDistribution), SceneError> {
    let contacts = ball_of.len();
    let (mus, mu_list) = per_contact(&fr.mu_static, "mu_static", ball_of, ctx)?;
    let (spreads, spread_list) = per_contact(&fr.spread, "spread", ball_of, ctx)?;
    let at =
        |list: bool, k: usize| if list { format!(" (contact {})", k + 1) } else { String::new() };
    for (k, (&mu, &spread)) in mus.iter().zip(&spreads).enumerate() {
        if !(0.0..=MU_MAX).contains(&mu) {
            return Err(ctx.error(
                Some(&fr.mu_static.span()),
                "friction.mu_static",
                format!("{mu}{} is outside [0, {MU_MAX}]", at(mu_list, k)),
            ));
        }
        if !(spread >= 0.0 && spread <= mu) {
            return Err(ctx.error(
                Some(&fr.spread.span()),
                "friction.spread",
                format!(
                    "{spread}{} must lie in [0, mu_static = {mu}] (friction cannot be negative)",
                    at(spread_list || mu_list, k)
                ),
            ));
        }
        if mu + spread > MU_MAX {
            return Err(ctx.error(
                Some(&fr.spread.span()),
                "friction.spread",
                format!("mu_static + spread = {}{} exceeds {MU_MAX}", mu + spread, at(true, k)),
            ));
        }
    }
    let n = contacts.max(1) as f64;
    let mean = |v: &[f64]| if v.is_empty() { 0.0 } else { v.iter().sum::<f64>() / n };
    let (mu, spread) = if mu_list || spread_list {
        (mean(&mus), mean(&spreads))
    } else {
        (mus.first().copied().unwrap_or(0.0), spreads.first().copied().unwrap_or(0.0))
    };
    let lists =
        (mu_list || spread_list).then(|| mus.iter().zip(&spreads).map(|(&m, &s)| [m, s]).collect());
    let has_spread = spread_list || spreads.iter().any(|&s| s > 0.0);
    let distribution = distribution(fr, &mus, ball_of, has_spread, ctx)?;
    let ratio = *fr.dynamic_ratio.get_ref();
    if !(ratio > 0.0 && ratio <= 1.0) {
        return Err(ctx.error(
            Some(&fr.dynamic_ratio.span()),
            "friction.dynamic_ratio",
            format!("{ratio} must lie in (0, 1]: mu_d = ratio * mu_s"),
        ));
    }
    let settings = FrictionSettings {
        mu_static: mu,
        spread,
        dynamic_ratio: ratio,
        tangential_law: fr.tangential_law,
        law: friction_law(fr, ctx)?,
    };
    Ok((settings, lists, distribution))
}

/// `[friction] distribution` with its keys (`scene::mu`): `sd` for a
/// normal or lognormal (each >= 0; a lognormal's mu_static > 0 where its
/// sd is), `values` for an empirical one (at least 2, each in
/// [0, MU_MAX]); `spread` (`has_spread`: given non-zero) only for a
/// uniform one, and each key only with its distribution.
fn distribution(
    fr: &FrictionFile,
    mus: &[f64],
    ball_of: &[usize],
    has_spread: bool,
    ctx: &ErrorContext,
) -> Result<MuDistribution, SceneError> {
    let kind = fr.distribution;
    let name = kind.name();
    let refuse = |span: std::ops::Range<usize>, field: &str, why: String| {
        Err(ctx.error(Some(&span), field, why))
    };
    if kind != Distribution::Uniform && has_spread {
        let why = format!(
            "the half-width of a uniform distribution; a {name} one takes {} (give spread = 0 or leave it out)",
            if kind == Distribution::Empirical { "values" } else { "sd" }
        );
        return refuse(fr.spread.span(), "friction.spread", why);
    }
    if let (Some(sd), Distribution::Uniform | Distribution::Empirical) = (&fr.sd, kind) {
        let why = format!(
            "a standard deviation, for distribution = \"normal\" or \"lognormal\" (here {name})"
        );
        return refuse(sd.span(), "friction.sd", why);
    }
    if let (Some(v), Distribution::Uniform | Distribution::Normal | Distribution::Lognormal) =
        (&fr.values, kind)
    {
        let why = format!("measured coefficients, for distribution = \"empirical\" (here {name})");
        return refuse(v.span(), "friction.values", why);
    }
    match kind {
        Distribution::Uniform => Ok(MuDistribution::Uniform),
        Distribution::Normal | Distribution::Lognormal => {
            let Some(sd) = &fr.sd else {
                let why = format!("a {name} distribution needs sd, the standard deviation of mu_s");
                return Err(ctx.error(Some(&fr.mu_static.span()), "friction.sd", why));
            };
            let (sd, _) = per_contact(sd, "sd", ball_of, ctx)?;
            for (k, (&s, &mu)) in sd.iter().zip(mus).enumerate() {
                let at = format!(" (contact {})", k + 1);
                if !(s.is_finite() && s >= 0.0) {
                    return refuse(
                        fr.sd.as_ref().unwrap().span(),
                        "friction.sd",
                        format!("{s}{at} must be finite and >= 0"),
                    );
                }
                if kind == Distribution::Lognormal && s > 0.0 && mu <= 0.0 {
                    let why = format!("{mu}{at}: a lognormal's mean must be > 0");
                    return refuse(fr.mu_static.span(), "friction.mu_static", why);
                }
            }
            Ok(match kind {
                Distribution::Normal => MuDistribution::Normal { sd },
                _ => MuDistribution::Lognormal { sd },
            })
        }
        Distribution::Empirical => empirical(fr, ctx),
    }
}

/// `values` of an empirical distribution: at least 2, each in [0, MU_MAX],
/// kept ascending.
fn empirical(fr: &FrictionFile, ctx: &ErrorContext) -> Result<MuDistribution, SceneError> {
    let refuse = |span: std::ops::Range<usize>, why: String| {
        Err(ctx.error(Some(&span), "friction.values", why))
    };
    let Some(v) = &fr.values else {
        let why = "an empirical distribution needs values, the measured coefficients";
        return Err(ctx.error(Some(&fr.mu_static.span()), "friction.values", why));
    };
    let mut values = v.get_ref().clone();
    if values.len() < 2 {
        return refuse(v.span(), format!("{} values: give at least 2", values.len()));
    }
    if let Some(x) = values.iter().find(|x| !(0.0..=MU_MAX).contains(*x)) {
        return refuse(v.span(), format!("{x} is outside [0, {MU_MAX}]"));
    }
    values.sort_by(f64::total_cmp);
    Ok(MuDistribution::Empirical { values })
}

/// `[friction] correlation`: in [0, 1] (0 where not given).
pub fn correlation(fr: &FrictionFile, ctx: &ErrorContext) -> Result<f64, SceneError> {
    let Some(c) = &fr.correlation else { return Ok(0.0) };
    let rho = *c.get_ref();
    if !(0.0..=1.0).contains(&rho) {
        let why = format!(
            "{rho} must lie in [0, 1]: the correlation between the coefficients of one ball's contacts"
        );
        return Err(ctx.error(Some(&c.span()), "friction.correlation", why));
    }
    Ok(rho)
}

/// `[study]`: at least 2 samples and a known sampler name.
pub fn study(st: &StudyFile, ctx: &ErrorContext) -> Result<StudyDefaults, SceneError> {
    let samples = *st.samples.get_ref();
    if samples < 2 {
        return Err(ctx.error(
            Some(&st.samples.span()),
            "study.samples",
            format!("{samples}: a study needs at least 2 samples"),
        ));
    }
    let name = st.sampler.get_ref();
    let sampler = Sampler::parse(name).ok_or_else(|| {
        ctx.error(
            Some(&st.sampler.span()),
            "study.sampler",
            format!("unknown sampler '{name}': expected lhs, mc or corners"),
        )
    })?;
    Ok(StudyDefaults { samples: samples as usize, sampler, seed: st.seed })
}

/// `[dynamics]`: a positive mass and principal moments of inertia that a
/// rigid body can have.
pub fn dynamics(d: &DynamicsFile, fx: &Fields) -> Result<DynamicsSettings, SceneError> {
    let mass = fx.positive(&d.mass, "dynamics.mass", "kg")?;
    let i = fx.finite(&d.inertia, "dynamics.inertia")?;
    let bad = |reason: String| fx.ctx.error(Some(&d.inertia.span()), "dynamics.inertia", reason);
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
            crate::dof::Dof::axis(k)
        )));
    }
    let centre_of_mass = match &d.centre_of_mass {
        Some(v) => fx.finite(v, "dynamics.centre_of_mass")?,
        None => Vector3::zeros(),
    };
    Ok(DynamicsSettings { mass, inertia: i, centre_of_mass })
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

/// `[variation]`: every bound finite and >= 0.
pub fn variation_bounds(
    v: &VariationFile,
    ctx: &ErrorContext,
) -> Result<VariationBounds, SceneError> {
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
        let arr = v.as_ref().map(|s| Spanned::new(s.span(), Numbers::of(&[*s.get_ref()])));
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
