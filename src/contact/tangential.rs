//! Tangential contact: Mindlin's elastic stiffness and the history-dependent
//! Coulomb stick/slip law (return mapping with its consistent tangent).
//!
//! Mindlin (1949); Johnson, *Contact Mechanics* (1985), §7.2:
//! ```text
//! k_t = 8 G* a                      (circle, radius a, no slip)
//! k_t = 8 G* sqrt(a b)              (ellipse: equivalent circle of equal area)
//! ```
//! For an ellipse the exact Mindlin compliance depends on the direction of
//! the load (it differs by at most ~15 % between the axes for the pin
//! contacts of the bundled scenes); kinrepro uses the isotropic
//! equal-area circle so that the stick/slip law stays isotropic. Every
//! elliptical contact of the bundled scenes slides during seating, where k_t
//! does not enter the result (MODEL.md §3).
//!
//! Coulomb return mapping (Simo & Hughes, *Computational Inelasticity*,
//! 1998, §2.2 applied to the tangential force; Wriggers, *Computational
//! Contact Mechanics*, 2006, §5.2):
//! ```text
//! F_trial = R F_old + k_t du_t           (R rotates the old force into the new tangent plane)
//! stick  if |F_trial| <= mu F_n,   mu = mu_s (was sticking) or mu_d (was sliding)
//! slip   otherwise: F = mu_d F_n F_trial / |F_trial|
//! ```
//! The change from mu_s to mu_d is sudden, as in the paper's FE model
//! (`law = "switch"`); `law = "decay"` makes the sliding coefficient depend
//! on the slip velocity of the increment ([`super::friction`]).
//!
//! Sign convention: `du` is the tangential displacement of the moving body
//! relative to the fixed surface at the contact, and the law's force is the
//! tangential force along it that the moving body exerts on the fixed
//! surface (a spring stretched by du). The friction force on the moving
//! body is its negative.

use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};

use super::cattaneo;
use super::friction::{FrictionLaw, SlideInput, Sliding};

/// Mindlin's tangential stiffness k_t = 8 G* sqrt(a b) [N/m].
pub fn mindlin_stiffness(g_star: f64, semi_axes: [f64; 2]) -> f64 {
    8.0 * g_star * (semi_axes[0] * semi_axes[1]).sqrt()
}

/// Which tangential law a contact follows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TangentialLaw {
    /// Linear Mindlin spring with Coulomb stick/slip (the paper's model).
    #[default]
    Coulomb,
    /// Cattaneo-Mindlin partial slip (stick core, slip annulus) with
    /// Masing unloading, and Coulomb gross slip.
    CattaneoMindlin,
}

/// Static and dynamic friction coefficients of one contact, the law between
/// them, and the duration of the current increment (the time base of the
/// slip velocity; only the decay law uses it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    pub mu_s: f64,
    pub mu_d: f64,
    pub law: FrictionLaw,
    /// Duration of the increment [s].
    pub duration: f64,
}

impl Friction {
    /// The paper's sudden switch from `mu_s` to `mu_d`.
    pub fn switch(mu_s: f64, mu_d: f64) -> Self {
        Friction {
            mu_s,
            mu_d,
            law: FrictionLaw::Switch,
            duration: 1.0,
        }
    }

    /// The same friction over an increment lasting `duration` [s].
    pub fn during(self, duration: f64) -> Self {
        Friction { duration, ..self }
    }
}

/// Stick or slip at the end of an update.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SlipState {
    Stick,
    Slip,
}

/// The tangential history of one contact, owned by the solver and passed
/// in to each update. All vectors lie in the tangent plane of `normal`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialState {
    /// Contact normal the vectors below are tangent to.
    pub normal: Vector3<f64>,
    /// Tangential force the moving body exerts on the fixed surface [N]
    /// (the force on the moving body is its negative).
    pub force: Vector3<f64>,
    /// Gross sliding at the end of the last step.
    pub sliding: bool,
    /// Cattaneo-Mindlin: force at the last load reversal [N].
    pub reversal_force: Vector3<f64>,
    /// Cattaneo-Mindlin: tangential displacement since the last reversal [m].
    pub since_reversal: Vector3<f64>,
    /// Cattaneo-Mindlin: Masing factor, 1 on the virgin curve, 2 after a reversal.
    pub masing: f64,
    /// Normal force when this state was committed [N] (the solvers integrate
    /// k_t at the mean normal force of an increment, see `solve::contact_layer`).
    pub normal_force: f64,
    /// Slip velocity of the committed increment [m/s] (0 while sticking; the
    /// decay friction law's velocity, `contact::friction`).
    pub slip_velocity: f64,
}

/// What the law returns for a trial increment: the new force, the state to
/// commit if the increment is accepted, and the consistent tangent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialResponse {
    pub force: Vector3<f64>,
    pub state: TangentialState,
    pub slip: SlipState,
    /// dF/d(du) [N/m].
    pub d_force_d_du: Matrix3<f64>,
    /// dF/dF_n [-].
    pub d_force_d_fn: Vector3<f64>,
}

/// Inputs of one update besides the state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialInput {
    /// Current contact normal (unit).
    pub normal: Vector3<f64>,
    /// Relative tangential displacement increment of the moving body [m]
    /// (any normal component is removed).
    pub du: Vector3<f64>,
    /// Current normal force [N].
    pub normal_force: f64,
    /// Current Mindlin stiffness k_t [N/m] and its derivative dk_t/dF_n [1/m].
    pub stiffness: f64,
    pub d_stiffness_d_fn: f64,
    /// Current semi-axes (Cattaneo-Mindlin uses sqrt(a b)) and G* [Pa].
    pub contact_radius: f64,
    pub g_star: f64,
    pub friction: Friction,
}

impl TangentialState {
    /// Zero force, sticking, tangent to `normal`.
    pub fn new(normal: Vector3<f64>) -> Self {
        TangentialState {
            normal,
            force: Vector3::zeros(),
            sliding: false,
            reversal_force: Vector3::zeros(),
            since_reversal: Vector3::zeros(),
            masing: 1.0,
            normal_force: 0.0,
            slip_velocity: 0.0,
        }
    }

    /// This state with its vectors rotated into the tangent plane of `normal`
    /// by the smallest rotation that takes the old normal to the new one
    /// (Rodrigues), so magnitudes are kept exactly.
    pub fn rotated_to(&self, normal: &Vector3<f64>) -> Self {
        if *normal == self.normal {
            return *self;
        }
        let rot = Rotation::between(&self.normal, normal);
        TangentialState {
            normal: *normal,
            force: rot.apply(&self.force),
            reversal_force: rot.apply(&self.reversal_force),
            since_reversal: rot.apply(&self.since_reversal),
            ..*self
        }
    }

    /// Evaluate the chosen law for a trial increment. Pure: `self` is not changed.
    pub fn update(&self, law: TangentialLaw, input: &TangentialInput) -> TangentialResponse {
        let n = input.normal;
        let open = TangentialResponse {
            force: Vector3::zeros(),
            state: TangentialState::new(n),
            slip: SlipState::Stick,
            d_force_d_du: Matrix3::zeros(),
            d_force_d_fn: Vector3::zeros(),
        };
        if input.normal_force <= 0.0 {
            return open; // no normal force, no friction; history is lost when a contact opens
        }
        let old = self.rotated_to(&n);
        let proj = Matrix3::identity() - n * n.transpose();
        let du = proj * input.du;
        match law {
            TangentialLaw::Coulomb => coulomb(&old, &proj, &du, input),
            TangentialLaw::CattaneoMindlin => cattaneo::update(&old, &proj, &du, input),
        }
    }
}

/// Coulomb return mapping; the sliding coefficient comes from the friction
/// law ([`super::friction::slide`]: the sudden switch, or the decay law).
fn coulomb(
    old: &TangentialState,
    proj: &Matrix3<f64>,
    du: &Vector3<f64>,
    input: &TangentialInput,
) -> TangentialResponse {
    let fr = input.friction;
    let trial = old.force + input.stiffness * du;
    let sliding = super::friction::slide(&SlideInput {
        mu_s: fr.mu_s,
        mu_d: fr.mu_d,
        law: fr.law,
        duration: fr.duration,
        trial: trial.norm(),
        normal_force: input.normal_force,
        stiffness: input.stiffness,
        was_sliding: old.sliding,
        previous_velocity: old.slip_velocity,
    });
    match sliding {
        None => TangentialResponse {
            force: trial,
            state: TangentialState {
                force: trial,
                sliding: false,
                slip_velocity: 0.0,
                ..*old
            },
            slip: SlipState::Stick,
            d_force_d_du: input.stiffness * proj,
            d_force_d_fn: input.d_stiffness_d_fn * du,
        },
        Some(s) => slide_with(old, proj, &trial, input.stiffness, du, input, &s),
    }
}

/// Gross sliding at the constant coefficient mu_d (see [`slide_with`]).
pub(super) fn slide_response(
    old: &TangentialState,
    proj: &Matrix3<f64>,
    trial: &Vector3<f64>,
    k: f64,
    du: &Vector3<f64>,
    input: &TangentialInput,
) -> TangentialResponse {
    let s = Sliding::constant(input.friction.mu_d);
    slide_with(old, proj, trial, k, du, input, &s)
}

/// Gross sliding: F = mu F_n t, t = F_trial/|F_trial| (T = |F_trial|), with
/// the tangent dF/d(du) = F_n k [dmu/dT t t^T + mu (P - t t^T) / T] (k the
/// trial stiffness) and dF/dF_n = (mu + F_n dmu/dF_n) t + mu F_n (P - t t^T)
/// k' du / T, where dmu/dF_n is total: through T (dT/dF_n = k' t.du), F_n
/// and k (k' = dk/dF_n). For the switch law mu = mu_d and its derivatives vanish.
fn slide_with(
    old: &TangentialState,
    proj: &Matrix3<f64>,
    trial: &Vector3<f64>,
    k: f64,
    du: &Vector3<f64>,
    input: &TangentialInput,
    s: &Sliding,
) -> TangentialResponse {
    let fn_ = input.normal_force;
    let dk = input.d_stiffness_d_fn;
    let mu = s.mu;
    let norm = trial.norm();
    let t = trial / norm;
    let dir_tangent = (proj - t * t.transpose()) / norm;
    let force = mu * fn_ * t;
    let dmu_dfn = s.d_mu_d_trial * dk * t.dot(du) + s.d_mu_d_fn + s.d_mu_d_k * dk;
    TangentialResponse {
        force,
        state: TangentialState {
            force,
            sliding: true,
            reversal_force: force,
            since_reversal: Vector3::zeros(),
            masing: 2.0,
            slip_velocity: s.slip / input.friction.duration,
            ..*old
        },
        slip: SlipState::Slip,
        d_force_d_du: fn_ * k * (s.d_mu_d_trial * t * t.transpose() + mu * dir_tangent),
        d_force_d_fn: (mu + fn_ * dmu_dfn) * t + mu * fn_ * (dir_tangent * (dk * du)),
    }
}

/// The smallest rotation taking unit vector `from` to unit vector `to`,
/// applied by Rodrigues' formula v' = v + w x v + w x (w x v) / (1 + c),
/// w = from x to, c = from . to.
#[derive(Debug, Clone, Copy)]
pub struct Rotation {
    w: Vector3<f64>,
    c: f64,
}

impl Rotation {
    pub fn between(from: &Vector3<f64>, to: &Vector3<f64>) -> Self {
        Rotation {
            w: from.cross(to),
            c: from.dot(to),
        }
    }

    pub fn apply(&self, v: &Vector3<f64>) -> Vector3<f64> {
        if self.c <= -1.0 + 1e-12 {
            // Opposite normals never occur between two steps of a seating;
            // keep the vector rather than pick an arbitrary axis.
            return *v;
        }
        let wv = self.w.cross(v);
        v + wv + self.w.cross(&wv) / (1.0 + self.c)
    }
}
