//! The coupling assembly: moving balls, fixed surfaces and the contact
//! laws of each pair, in the contact order of docs/model.md (the `--mu` order).

pub mod constraint;
mod contacts;
pub mod friction_limit;
pub mod geometry;
pub mod thermal;

use nalgebra::{Matrix6, Quaternion, UnitQuaternion, Vector3, Vector6};
use thiserror::Error;

use crate::contact::stress::ShearRatios;
use crate::contact::{
    ContactError, ContactLaw, ContactPair, ContactShape, FrictionLaw, SeriesNormal, TangentialLaw,
};
use crate::lane::{Lane, branch, each_lane, gather, lift, splat};
use crate::material::Material;
use crate::scene::{DynamicsSettings, Scene, SurfaceGeometry, ThermalBodies};
pub use constraint::ConstraintReport;
pub use friction_limit::FrictionLimit;
pub use geometry::ContactGeometry;
use simba::simd::SimdValue;

/// Pose of the moving half: world = rotation * body + translation. The body
/// frame coincides with the world frame in the scene as written. Over
/// [`Lane`]s, one pose per lane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyPose<T: Lane = f64> {
    pub rotation: UnitQuaternion<T>,
    pub translation: Vector3<T>,
}

impl Default for BodyPose {
    /// The identity: the body frame on the world frame.
    fn default() -> Self {
        BodyPose::identity()
    }
}

impl BodyPose {
    pub fn identity() -> Self {
        BodyPose { rotation: UnitQuaternion::identity(), translation: Vector3::zeros() }
    }
}

impl<T: Lane> BodyPose<T> {
    /// The pose of lanes whose lane i is `poses[i]`.
    pub fn from_lanes(poses: &[BodyPose]) -> Self {
        BodyPose {
            rotation: gather(poses.iter().map(|p| p.rotation)),
            translation: gather(poses.iter().map(|p| p.translation)),
        }
    }

    /// Lane `i`'s pose.
    pub fn lane(&self, i: usize) -> BodyPose {
        BodyPose { rotation: self.rotation.extract(i), translation: self.translation.extract(i) }
    }

    /// World position of a body point.
    #[inline]
    pub fn apply(&self, p: &Vector3<T>) -> Vector3<T> {
        self.rotation * p + self.translation
    }

    /// This pose moved by a small spatial twist (v, w): rotation exp(w)
    /// about the world origin, then translation v (exact finite rotation).
    #[inline(always)]
    pub fn moved(&self, v: &Vector3<T>, w: &Vector3<T>) -> Self {
        let dq = rotation_exp(w);
        BodyPose { rotation: dq * self.rotation, translation: dq * self.translation + v }
    }
}

/// The unit quaternion exp(w) = (cos(t/2), sin(t/2) w/t), t = |w|, of the
/// rotation vector w. Below t = 1e-3 (the Newton corrections and
/// increments of a seating turn by micro-radians) by the Taylor series
/// cos(t/2) = 1 - t^2/8 + t^4/384, sin(t/2)/t = 1/2 - t^2/48 + t^4/3840,
/// whose first omitted terms (t^6/46080, t^6/645120) are below 1e-22, so
/// that it equals sin and cos to rounding without calling them; above, as
/// nalgebra's `UnitQuaternion::from_scaled_axis`. A turn t <= 2 eps is
/// none, as in nalgebra's: the rounding noise of a symmetric seating's
/// corrections leaves its pose exactly unrotated (`study::verdict` asks
/// whether two seated poses are equal). Each lane by its own turn.
#[inline]
pub fn rotation_exp<T: Lane>(w: &Vector3<T>) -> UnitQuaternion<T> {
    let t2 = w.norm_squared();
    branch::<T, _>(
        t2.simd_ge(splat(1e-6)),
        // nalgebra's sin and cos lane by lane (f64's own).
        |_| each_lane(w, |w: Vector3<f64>| UnitQuaternion::from_scaled_axis(w)),
        |_| {
            branch::<T, _>(
                (splat::<T>(0.25) * t2).simd_le(splat(f64::EPSILON * f64::EPSILON)),
                |_| UnitQuaternion::identity(),
                |_| {
                    let one = T::one();
                    let c = one - t2 / splat(8.0) * (one - t2 / splat(48.0));
                    let s = splat::<T>(0.5) * (one - t2 / splat(24.0) * (one - t2 / splat(80.0)));
                    UnitQuaternion::new_unchecked(Quaternion::from_parts(c, w * s))
                },
            )
        },
    )
}

/// One contact: a moving ball (or its patch) against a fixed surface.
#[derive(Debug, Clone)]
pub struct Contact {
    /// Index of the moving ball (0-based).
    pub ball: usize,
    /// The moving surface at this contact: the ball's sphere, the scene's
    /// patch (a canoe ball's face) or a moving pin. Its centre of curvature
    /// (a point of a pin's axis) in the body frame [m] and its radius [m].
    pub centre: Vector3<f64>,
    pub radius: f64,
    /// A moving pin's unit axis in the body frame; `None`: a sphere.
    pub axis: Option<Vector3<f64>>,
    /// The major axis of the contact ellipse in the world frame at the
    /// scene pose (Mindlin's K_t is oriented by its projection into the
    /// tangent plane); zero for a circular contact.
    pub major_axis: Vector3<f64>,
    pub surface: SurfaceGeometry,
    pub shape: ContactShape,
    pub pair: ContactPair,
    pub law: ContactLaw,
    /// The normal law: Hertz in series with the surface's support compliance.
    pub normal: SeriesNormal,
    /// tau_max/p0 of the two bodies (for the stress check).
    pub shear: ShearRatios,
}

#[derive(Debug, Clone)]
pub struct MovingBall {
    /// Centre in the body frame [m].
    pub centre: Vector3<f64>,
    pub radius: f64,
    pub material: Material,
}

/// The friction laws every contact follows (the scene's `[friction]`
/// without the coefficients, which each seating is given: `solve::Load`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLaws {
    /// mu_d = dynamic_ratio * mu_s.
    pub dynamic_ratio: f64,
    /// The sliding coefficient: sudden switch or decay with slip velocity.
    pub law: FrictionLaw,
    pub tangential: TangentialLaw,
}

/// An assembled coupling: its geometry, materials and laws. What a seating
/// varies (friction coefficients, preload, start) is not here: the solvers
/// take it as an argument (`solve::Load`). It is made from a scene and
/// does not follow later edits of the scene: change both, or assemble
/// again (as `calibrate::params::Param::set` does for a fitted parameter).
#[derive(Debug, Clone)]
pub struct Coupling {
    pub balls: Vec<MovingBall>,
    pub contacts: Vec<Contact>,
    /// The unloaded touching pose: every contact at zero gap.
    pub touching_pose: BodyPose,
    pub friction: FrictionLaws,
    /// Mass properties of the moving half given by the scene (`[dynamics]`;
    /// `None`: the dynamic solver's default model).
    pub dynamics: Option<DynamicsSettings>,
    /// The expansion model of the scene's `[thermal]` table, if any (the
    /// coupling at other temperatures: [`Coupling::at_temperatures`]).
    pub thermal: Option<ThermalBodies>,
}

/// The assembly failed: the scene describes no working coupling.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AssemblyError {
    #[error("contact {contact}: {source}")]
    Contact {
        contact: usize,
        #[source]
        source: ContactError,
    },
    #[error(
        "contact {contact} (ball {ball}): the ball does not touch its surface: gap {gap_m:.3e} m \
         (a ball must touch every surface it is assigned at zero force; |gap| must be below {tol_m:.1e} m)"
    )]
    NotTouching { contact: usize, ball: usize, gap_m: f64, tol_m: f64 },
    #[error("the coupling is not exactly constrained: {0}")]
    NotExactlyConstrained(String),
    #[error(
        "the preload cannot seat the coupling: contact {contact} would need a pulling force \
         ({force_n:.4} N) to balance it"
    )]
    PreloadLifts { contact: usize, force_n: f64 },
    #[error("the scene has no [thermal] table: thermal drift needs the bodies and their cycle")]
    NoThermal,
}

/// Ball centres are placed at most this far from touching (before the
/// touching pose is solved) [m].
pub const TOUCH_TOLERANCE: f64 = 1e-6;

impl Coupling {
    /// Assemble a validated scene: laws, exact-constraint check,
    /// touching pose, and the check that the scene's preload loads every
    /// contact.
    pub fn new(scene: &Scene) -> Result<Coupling, AssemblyError> {
        Coupling::assemble(scene, TOUCH_TOLERANCE)
    }

    /// Assemble geometry perturbed by manufacturing tolerances (a study's
    /// `--vary tolerances`): the balls may miss their surfaces at the
    /// scene's pose by up to `max_gap` [m]; the touching-pose solve then
    /// finds where the moving half first touches all six surfaces, and that
    /// solve must close every gap (to 1e-12 m). Scene files keep the strict
    /// [`TOUCH_TOLERANCE`] of [`Coupling::new`].
    pub fn new_perturbed(scene: &Scene, max_gap: f64) -> Result<Coupling, AssemblyError> {
        let c = Coupling::assemble(scene, max_gap.max(TOUCH_TOLERANCE))?;
        for (i, contact) in c.contacts.iter().enumerate() {
            let gap = c.geometry(i, &c.touching_pose).gap;
            if gap.abs() > 1e-12 {
                return Err(AssemblyError::NotTouching {
                    contact: i + 1,
                    ball: contact.ball + 1,
                    gap_m: gap,
                    tol_m: 1e-12,
                });
            }
        }
        Ok(c)
    }

    fn assemble(scene: &Scene, touch_tolerance: f64) -> Result<Coupling, AssemblyError> {
        let balls: Vec<MovingBall> = scene
            .balls
            .iter()
            .map(|b| MovingBall {
                centre: b.centre,
                radius: b.radius,
                material: b.material.clone(),
            })
            .collect();
        let contacts = (scene.surfaces.iter().enumerate())
            .map(|(i, s)| contacts::build(i, s, &balls[s.ball]))
            .collect::<Result<Vec<_>, _>>()?;
        let f = &scene.friction;
        let mut coupling = Coupling {
            balls,
            contacts,
            touching_pose: BodyPose::identity(),
            friction: FrictionLaws {
                dynamic_ratio: f.dynamic_ratio,
                law: f.law,
                tangential: f.tangential_law,
            },
            dynamics: scene.dynamics,
            thermal: scene.thermal.as_ref().map(|t| t.bodies.clone()),
        };
        for (i, c) in coupling.contacts.iter().enumerate() {
            let g = coupling.geometry(i, &BodyPose::identity());
            if g.gap.abs() > touch_tolerance {
                return Err(AssemblyError::NotTouching {
                    contact: i + 1,
                    ball: c.ball + 1,
                    gap_m: g.gap,
                    tol_m: touch_tolerance,
                });
            }
        }
        let report = constraint::analyse(&coupling);
        if !report.exactly_constrained {
            return Err(AssemblyError::NotExactlyConstrained(report.describe()));
        }
        coupling.touching_pose = coupling.solve_touching_pose();
        let forces = constraint::frictionless_preload_forces(&coupling, &scene.preload);
        if let Some((i, f)) = forces.iter().enumerate().find(|(_, f)| **f <= 0.0) {
            return Err(AssemblyError::PreloadLifts { contact: i + 1, force_n: *f });
        }
        Ok(coupling)
    }

    /// The coupling radius: the largest distance of a ball centre from the
    /// origin of the touching pose, the length scale of moments [m].
    pub fn length_scale(&self) -> f64 {
        let t = &self.touching_pose;
        self.balls.iter().map(|b| (t.apply(&b.centre) - t.translation).norm()).fold(0.0, f64::max)
    }

    /// The slide-away bound of the solvers: 5 % of the smallest ball radius [m].
    pub fn slide_away_travel(&self) -> f64 {
        0.05 * self.balls.iter().map(|b| b.radius).fold(f64::INFINITY, f64::min)
    }

    /// Geometry of contact `i` with the moving half at `pose`
    /// ([`geometry::contact`], or [`geometry::pin_contact`] for a moving pin).
    #[inline]
    pub fn geometry<T: Lane>(&self, i: usize, pose: &BodyPose<T>) -> ContactGeometry<T> {
        let c = &self.contacts[i];
        let centre = pose.apply(&lift(&c.centre));
        match c.axis {
            None => geometry::contact(&c.surface, &centre, c.radius),
            Some(axis) => {
                geometry::pin_contact(&c.surface, &centre, &(pose.rotation * lift(&axis)), c.radius)
            }
        }
    }

    /// Constraint rows w_i = [n_i; p_i x n_i] at `pose` (p_i the contact
    /// point, on the line of the contact normal), row i of the matrix:
    /// d(gap_i) = w_i . (v, w) for a twist (v, w) about the world origin.
    /// An assembled coupling is exactly constrained: six contacts, six rows.
    pub fn constraint_rows(&self, pose: &BodyPose) -> Matrix6<f64> {
        let mut w = Matrix6::zeros();
        for i in 0..6 {
            let g = self.geometry(i, pose);
            let n = g.normal;
            let m = g.point.cross(&n);
            w.set_row(i, &Vector6::new(n.x, n.y, n.z, m.x, m.y, m.z).transpose());
        }
        w
    }

    /// Newton on the six gaps: the pose at which every contact touches at
    /// zero gap (for exactly placed scenes the identity, to rounding).
    fn solve_touching_pose(&self) -> BodyPose {
        let mut pose = BodyPose::identity();
        for _ in 0..40 {
            let gaps = Vector6::from_iterator((0..6).map(|i| self.geometry(i, &pose).gap));
            if gaps.amax() < 1e-16 {
                break;
            }
            let j = self.constraint_rows(&pose);
            let Some(step) = j.lu().solve(&(-gaps)) else {
                break;
            };
            pose = pose.moved(&step.fixed_rows::<3>(0).into(), &step.fixed_rows::<3>(3).into());
        }
        pose
    }
}
