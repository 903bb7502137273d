//! Tangential contact: the types shared by the tangential laws, the
//! dispatcher, and the history-dependent Coulomb stick/slip law (return
//! mapping with its consistent tangent). The Mindlin-Deresiewicz partial-slip
//! law lives in `mindlin_deresiewicz` and shares only the types.
//!
//! Elastic stiffness: Mindlin's exact 2x2 tangential stiffness of the contact
//! ellipse (`contact::mindlin`), as the 3x3 tensor
//! K_t = k_major e1 e1^T + k_minor e2 e2^T in the tangent plane (e1 the major
//! axis; K_t = 8 G* a (I - n n^T) for a circle).
//!
//! Coulomb return mapping (Simo & Hughes, *Computational Inelasticity*,
//! 1998, §2.2 applied to the tangential force; Wriggers, *Computational
//! Contact Mechanics*, 2006, §5.2):
//! ```text
//! F_trial = R F_old + K_t du_t           (R rotates the old force into the new tangent plane)
//! stick  if |F_trial| <= mu F_n,   mu = mu_s (was sticking) or mu_d (was sliding)
//! slip   otherwise: F = the point of |F| = mu_d F_n closest to F_trial in the
//!        complementary-energy norm of K_t (mu_d F_n F_trial/|F_trial| for a circle)
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

use super::friction::{FrictionLaw, SlideInput, Sliding};
use super::mindlin::{PrincipalStiffness, project_tangential};
use super::mindlin_deresiewicz::{self, SpringRow};

/// Which tangential law a contact follows (scene key `tangential_law`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", try_from = "String")]
pub enum TangentialLaw {
    /// Linear Mindlin spring with Coulomb stick/slip (the paper's model).
    #[default]
    Coulomb,
    /// Mindlin-Deresiewicz partial slip for any P-Q history (stick core,
    /// slip annulus, Masing unloading), by the method of dimensionality
    /// reduction; Coulomb gross slip with the same static-to-dynamic switch.
    MindlinDeresiewicz,
}

impl TangentialLaw {
    pub const ALL: [TangentialLaw; 2] = [TangentialLaw::Coulomb, TangentialLaw::MindlinDeresiewicz];

    /// Kebab-case name, as in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            TangentialLaw::Coulomb => "coulomb",
            TangentialLaw::MindlinDeresiewicz => "mindlin-deresiewicz",
        }
    }
}

impl std::str::FromStr for TangentialLaw {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        if s == "cattaneo-mindlin" {
            return Err(
                "tangential law `cattaneo-mindlin` was removed (it applied the \
                 constant-load Cattaneo curve to a changing normal load, 1.5x too stiff \
                 under proportional loading): use `mindlin-deresiewicz`"
                    .to_string(),
            );
        }
        TangentialLaw::ALL
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| {
                format!("unknown tangential law `{s}` (expected coulomb or mindlin-deresiewicz)")
            })
    }
}

impl TryFrom<String> for TangentialLaw {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        s.parse()
    }
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
    pub const fn switch(mu_s: f64, mu_d: f64) -> Self {
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
///
/// Not `Copy`: the Mindlin-Deresiewicz spring row (about 2 KB) sits behind
/// a box that the Coulomb law never allocates, so cloning a Coulomb state
/// costs as little as copying its few vectors.
#[derive(Debug, Clone, PartialEq)]
pub struct TangentialState {
    /// Contact normal the vectors below are tangent to.
    pub normal: Vector3<f64>,
    /// Tangential force the moving body exerts on the fixed surface [N]
    /// (the force on the moving body is its negative).
    pub force: Vector3<f64>,
    /// Gross sliding at the end of the last step.
    pub sliding: bool,
    /// Mindlin-Deresiewicz: the row of springs (`None` for Coulomb, and
    /// before a Mindlin-Deresiewicz contact first carries load).
    pub row: Option<Box<SpringRow>>,
    /// Normal force when this state was committed [N] (the solvers integrate
    /// k_t at the mean normal force of an increment, see `solve::contact_layer`).
    pub normal_force: f64,
    /// Slip velocity of the committed increment [m/s] (0 while sticking; the
    /// decay friction law's velocity, `contact::friction`).
    pub slip_velocity: f64,
}

/// What the law returns for a trial increment: the new force, the state to
/// commit if the increment is accepted, and the consistent tangent.
#[derive(Debug, Clone, PartialEq)]
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
    /// Mindlin's tangential stiffness tensor K_t [N/m] (in the tangent
    /// plane) and its derivative dK_t/dF_n [1/m].
    pub stiffness: Matrix3<f64>,
    pub d_stiffness_d_fn: Matrix3<f64>,
    /// Mindlin-Deresiewicz: equal-area radius sqrt(a b) at `normal_force`
    /// [m], G* [Pa] and the shape C = K_t / (8 G* sqrt(a b)) (I - n n^T
    /// for a circle).
    pub contact_radius: f64,
    pub g_star: f64,
    pub mindlin_shape: Matrix3<f64>,
    pub friction: Friction,
}

impl TangentialState {
    /// Zero force, sticking, tangent to `normal`.
    pub fn new(normal: Vector3<f64>) -> Self {
        TangentialState {
            normal,
            force: Vector3::zeros(),
            sliding: false,
            row: None,
            normal_force: 0.0,
            slip_velocity: 0.0,
        }
    }

    /// This state with its vectors rotated into the tangent plane of `normal`
    /// by the smallest rotation that takes the old normal to the new one
    /// (Rodrigues), so magnitudes are kept exactly.
    pub fn rotated_to(&self, normal: &Vector3<f64>) -> Self {
        if *normal == self.normal {
            return self.clone();
        }
        let rot = Rotation::between(&self.normal, normal);
        TangentialState {
            normal: *normal,
            force: rot.apply(&self.force),
            row: self.row.as_ref().map(|row| {
                Box::new(SpringRow {
                    frame: rot.apply(&row.frame),
                    ..**row
                })
            }),
            ..*self
        }
    }

    /// Evaluate the chosen law for a trial increment. Pure: `self` is not changed.
    pub fn update(&self, law: TangentialLaw, input: &TangentialInput) -> TangentialResponse {
        self.update_with(law, input, None)
    }

    /// [`Self::update`] with K_t (`input.stiffness`) also given by its
    /// principal values and axes: the Coulomb return mapping then projects
    /// without an eigen-decomposition, in closed form for a circular
    /// contact ([`PrincipalStiffness::project`], the same map).
    pub fn update_with(
        &self,
        law: TangentialLaw,
        input: &TangentialInput,
        principal: Option<&PrincipalStiffness>,
    ) -> TangentialResponse {
        let n = input.normal;
        if input.normal_force <= 0.0 {
            // No normal force, no friction; history is lost when a contact opens.
            return TangentialResponse {
                force: Vector3::zeros(),
                state: TangentialState::new(n),
                slip: SlipState::Stick,
                d_force_d_du: Matrix3::zeros(),
                d_force_d_fn: Vector3::zeros(),
            };
        }
        let old = self.rotated_to(&n);
        match law {
            TangentialLaw::Coulomb => {
                let du = input.du - n * n.dot(&input.du);
                coulomb(&old, &du, input, principal)
            }
            TangentialLaw::MindlinDeresiewicz => {
                let proj = Matrix3::identity() - n * n.transpose();
                mindlin_deresiewicz::update(&old, &proj, &(proj * input.du), input)
            }
        }
    }
}

/// Coulomb return mapping; the sliding coefficient comes from the friction
/// law ([`super::friction::slide`]: the sudden switch, or the decay law).
/// The decay law's slip increment uses the stiffness along the trial force,
/// k = t^T K_t t (t = F_trial/|F_trial|): exact for a circular contact, the
/// stiffness of the load direction for an elliptical one.
fn coulomb(
    old: &TangentialState,
    du: &Vector3<f64>,
    input: &TangentialInput,
    principal: Option<&PrincipalStiffness>,
) -> TangentialResponse {
    let fr = input.friction;
    let trial = old.force + input.stiffness * du;
    let norm = trial.norm();
    // The switch law reads no stiffness (`friction::slide`).
    let k_along = match fr.law {
        FrictionLaw::Switch => 0.0,
        FrictionLaw::Decay { .. } => {
            let t = if norm > 0.0 { trial / norm } else { trial };
            t.dot(&(input.stiffness * t))
        }
    };
    let sliding = super::friction::slide(&SlideInput {
        mu_s: fr.mu_s,
        mu_d: fr.mu_d,
        law: fr.law,
        duration: fr.duration,
        trial: norm,
        normal_force: input.normal_force,
        stiffness: k_along,
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
                row: old.row.clone(),
                ..*old
            },
            slip: SlipState::Stick,
            d_force_d_du: input.stiffness,
            d_force_d_fn: input.d_stiffness_d_fn * du,
        },
        Some(s) => slide_response(old, &trial, du, input, &s, principal),
    }
}

/// Gross sliding: F on the circle |F| = mu F_n closest to F_trial in the
/// complementary-energy norm of K (`mindlin::project_tangential`; the radial
/// return F = mu F_n F_trial/|F_trial| for a circular contact), so that the
/// friction force opposes the slip also for an elliptical K; mu from the
/// friction law (`s`; constant mu_d for the switch law). Tangent, with
/// T = |F_trial|, t = F_trial/T and L = mu F_n the limit:
/// dF/d(du) = (dF/dF_trial) K + (dF/dL) F_n (dmu/dT) t^T K,
/// dF/dF_n = (dF/dL) (mu + F_n dmu/dF_n) + (dF/dF_trial) (dK/dF_n) du,
/// dmu/dF_n total through T (dT/dF_n = t . K' du), F_n and k (dk/dF_n = t^T K' t).
fn slide_response(
    old: &TangentialState,
    trial: &Vector3<f64>,
    du: &Vector3<f64>,
    input: &TangentialInput,
    s: &Sliding,
    principal: Option<&PrincipalStiffness>,
) -> TangentialResponse {
    let fn_ = input.normal_force;
    let (k, dk) = (&input.stiffness, &input.d_stiffness_d_fn);
    let mu = s.mu;
    let (force, d_trial, d_limit) = match principal {
        Some(p) => p.project(&input.normal, trial, mu * fn_),
        None => project_tangential(k, &input.normal, trial, mu * fn_),
    };
    let dk_du = dk * du;
    let (d_force_d_du, d_force_d_fn) =
        if s.d_mu_d_trial == 0.0 && s.d_mu_d_fn == 0.0 && s.d_mu_d_k == 0.0 {
            // A constant coefficient (the switch law, a sliding decay contact).
            (d_trial * k, mu * d_limit + d_trial * dk_du)
        } else {
            let t = trial.normalize();
            let dmu_dfn =
                s.d_mu_d_trial * t.dot(&dk_du) + s.d_mu_d_fn + s.d_mu_d_k * t.dot(&(dk * t));
            let dt_ddu = k.transpose() * t; // dT/d(du) as a column
            (
                d_trial * k + (d_limit * (fn_ * s.d_mu_d_trial)) * dt_ddu.transpose(),
                (mu + fn_ * dmu_dfn) * d_limit + d_trial * dk_du,
            )
        };
    TangentialResponse {
        force,
        state: TangentialState {
            force,
            sliding: true,
            slip_velocity: s.slip / input.friction.duration,
            row: old.row.clone(),
            ..*old
        },
        slip: SlipState::Slip,
        d_force_d_du,
        d_force_d_fn,
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
