//! The types every tangential law shares: which law, the friction
//! coefficients, the state a contact carries between increments (with the
//! Mindlin-Deresiewicz spring row), the inputs of one update and the
//! response. The laws themselves (`coulomb`, `mindlin_deresiewicz`) import
//! only this module (and Mindlin's stiffness); `tangential` dispatches
//! between them, each law's `update` having the one signature
//! `(old, input, tangent, out)`.

use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};

use super::friction::FrictionLaw;
use super::mindlin::PrincipalStiffness;
use crate::lane::{Lane, branch, splat};

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
    type Err = UnknownLaw;
    fn from_str(s: &str) -> Result<Self, UnknownLaw> {
        if s == "cattaneo-mindlin" {
            return Err(UnknownLaw::Removed);
        }
        TangentialLaw::ALL
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| UnknownLaw::Unknown(s.to_string()))
    }
}

impl TryFrom<String> for TangentialLaw {
    type Error = UnknownLaw;
    fn try_from(s: String) -> Result<Self, UnknownLaw> {
        s.parse()
    }
}

/// A tangential law name that is none of [`TangentialLaw::ALL`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum UnknownLaw {
    #[error(
        "tangential law `cattaneo-mindlin` was removed (it applied the constant-load Cattaneo curve to a changing normal load, 1.5x too stiff under proportional loading): use `mindlin-deresiewicz`"
    )]
    Removed,
    #[error("unknown tangential law `{0}` (expected coulomb or mindlin-deresiewicz)")]
    Unknown(String),
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
        Friction { mu_s, mu_d, law: FrictionLaw::Switch, duration: 1.0 }
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

impl SlipState {
    /// `stick` or `slip`, as in JSON.
    pub fn name(self) -> &'static str {
        match self {
            SlipState::Stick => "stick",
            SlipState::Slip => "slip",
        }
    }
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
    /// k_t over an increment from it to the trial force, see `solve::contact_layer`).
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

impl TangentialResponse {
    /// The response of an open contact (F_n <= 0): no force, a fresh
    /// sticking state tangent to `normal`, a zero tangent.
    pub fn open(normal: Vector3<f64>) -> Self {
        TangentialResponse {
            force: Vector3::zeros(),
            state: TangentialState::new(normal),
            slip: SlipState::Stick,
            d_force_d_du: Matrix3::zeros(),
            d_force_d_fn: Vector3::zeros(),
        }
    }
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
    /// plane), the same by its principal values and axes (the Coulomb
    /// return mapping projects in them), and dK_t/dF_n [1/m].
    pub stiffness: Matrix3<f64>,
    pub principal: PrincipalStiffness,
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

    /// Set `self` to `old` with a new force, sliding flag and slip velocity
    /// (the struct update `TangentialState { force, sliding, slip_velocity,
    /// row: old.row.clone(), ..*old }` in place, the row into `self`'s box).
    #[inline]
    pub fn assign_from(
        &mut self,
        old: &TangentialState,
        force: Vector3<f64>,
        sliding: bool,
        slip_velocity: f64,
    ) {
        self.normal = old.normal;
        self.force = force;
        self.sliding = sliding;
        self.row.clone_from(&old.row);
        self.normal_force = old.normal_force;
        self.slip_velocity = slip_velocity;
    }

    /// This state with its vectors rotated into the tangent plane of `normal`
    /// by the smallest rotation that takes the old normal to the new one
    /// (Rodrigues), so magnitudes are kept exactly.
    #[inline]
    pub fn rotated_to(&self, normal: &Vector3<f64>) -> Self {
        if *normal == self.normal {
            return self.clone();
        }
        let rot = Rotation::between(&self.normal, normal);
        TangentialState {
            normal: *normal,
            force: rot.apply(&self.force),
            row: self
                .row
                .as_ref()
                .map(|row| Box::new(SpringRow { frame: rot.apply(&row.frame), ..**row })),
            ..*self
        }
    }
}

/// Springs in the row (0 <= x <= a): 128 (96 to 128 carry a contact at
/// constant load, 64 to 128 while it grows) keep Cattaneo's curve within
/// 2.3e-3 at every step (tests/it/contact_laws.rs).
pub const SPRINGS: usize = 128;

/// The MDR row of one contact: cell width and each cell's 2-D value
/// q = C u (u the cell average displacement times the fraction in contact),
/// in the frame (t1, n x t1) of the tangent plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringRow {
    /// First tangent direction of the frame (zero until first contact).
    pub frame: Vector3<f64>,
    /// Cell width h [m] (0 until first contact).
    pub h: f64,
    /// q per cell [m].
    pub q: [[f64; 2]; SPRINGS],
}

impl Default for SpringRow {
    fn default() -> Self {
        SpringRow { frame: Vector3::zeros(), h: 0.0, q: [[0.0; 2]; SPRINGS] }
    }
}

/// The smallest rotation taking unit vector `from` to unit vector `to`,
/// applied by Rodrigues' formula v' = v + w x v + w x (w x v) / (1 + c),
/// w = from x to, c = from . to.
#[derive(Debug, Clone, Copy)]
pub struct Rotation<T: Lane = f64> {
    w: Vector3<T>,
    c: T,
}

impl<T: Lane> Rotation<T> {
    #[inline]
    pub fn between(from: &Vector3<T>, to: &Vector3<T>) -> Self {
        Rotation { w: from.cross(to), c: from.dot(to) }
    }

    /// Per lane for lanes.
    #[inline]
    pub fn apply(&self, v: &Vector3<T>) -> Vector3<T> {
        branch::<T, _>(
            self.c.simd_le(splat(-1.0 + 1e-12)),
            // Opposite normals never occur between two steps of a seating;
            // keep the vector rather than pick an arbitrary axis.
            |_| *v,
            |_| {
                let wv = self.w.cross(v);
                v + wv + self.w.cross(&wv) / (T::one() + self.c)
            },
        )
    }
}
