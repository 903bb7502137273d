//! The rapier3d-f64 world of a dynamic seating: the moving half as one
//! dynamic rigid body (mass properties from [`MassModel`], its balls as
//! colliders), the fixed surfaces as parry shapes on one fixed body.
//!
//! rapier's own rigid contact is off for every coupling pair: all colliders
//! carry collision groups whose filter is empty
//! (`InteractionGroups::new(GROUP_1, Group::NONE, And)`), so the broad phase
//! never creates a pair and the narrow phase and constraint solver never see
//! one (a test checks the narrow phase stays empty). The contact forces come
//! only from the compliant contact layer, applied as user forces.
//!
//! Integration settings, and why:
//! - gravity zero: the preload is the load, as in the quasi-static model
//!   and the paper's FE model (the weight of the moving half is part of, or
//!   negligible against, the preload);
//! - `num_solver_iterations = 1`: rapier runs one sub-step per step, so a
//!   step is exactly the semi-implicit (symplectic) Euler update
//!   v+ = v + dt M^-1 F(x),  x+ = x + dt v+ (Hairer, Lubich & Wanner,
//!   *Geometric Numerical Integration*, 2006, §VI.3). With the default four
//!   sub-steps the user force would be held over sub-steps of dt/4, which
//!   is no longer symplectic and lets the energy grow;
//! - `num_internal_stabilization_iterations = 0` and `max_ccd_substeps = 0`:
//!   with no constraint and no contact pair, rapier's stabilisation pass
//!   has nothing to solve and its continuous collision detection nothing
//!   to detect; both passes are skipped (the same poses bit for bit, 4 %
//!   fewer instructions per step);
//! - `can_sleep(false)`: rapier would put the body to sleep at the um/s
//!   speeds of the final settling;
//! - no linear or angular damping from rapier: all damping is in the
//!   contact layer, where it is documented.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use rapier3d_f64::math::{Pose as DPose3, Rotation as DQuat, Vector as DVec3};
use rapier3d_f64::prelude::{
    ColliderBuilder, Group, InteractionGroups, InteractionTestMode, MassProperties, PhysicsWorld,
    RigidBodyBuilder, RigidBodyHandle,
};

use super::mass::MassModel;
use crate::assembly::geometry::parry_shape;
use crate::assembly::{BodyPose, Coupling};

pub(crate) fn dvec(v: &Vector3<f64>) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

pub(crate) fn nvec(v: DVec3) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

/// BodyPose -> rapier pose (same convention: world = R body + t).
pub(crate) fn to_rapier(pose: &BodyPose) -> DPose3 {
    let q = pose.rotation.quaternion();
    DPose3::from_parts(dvec(&pose.translation), DQuat::from_xyzw(q.i, q.j, q.k, q.w))
}

/// rapier pose -> BodyPose.
pub(crate) fn from_rapier(pose: &DPose3) -> BodyPose {
    let q = pose.rotation;
    BodyPose {
        rotation: UnitQuaternion::new_normalize(Quaternion::new(q.w, q.x, q.y, q.z)),
        translation: nvec(pose.translation),
    }
}

/// Collision groups that interact with nothing: rapier's rigid contact off.
fn no_contact() -> InteractionGroups {
    InteractionGroups::new(Group::GROUP_1, Group::NONE, InteractionTestMode::And)
}

/// Build the world with the moving half at `start` (at rest) and time step `dt`.
pub(crate) fn build(
    coupling: &Coupling,
    mass: &MassModel,
    start: &BodyPose,
    dt: f64,
) -> (PhysicsWorld, RigidBodyHandle) {
    let mut world = PhysicsWorld::new();
    world.gravity = DVec3::ZERO;
    world.integration_parameters.dt = dt;
    world.integration_parameters.num_solver_iterations = 1;
    world.integration_parameters.num_internal_stabilization_iterations = 0;
    world.integration_parameters.max_ccd_substeps = 0;
    let i = mass.inertia;
    let props = MassProperties::with_inertia_matrix(
        dvec(&mass.centre_of_mass),
        mass.mass,
        rapier3d_f64::math::Matrix::from_cols(
            DVec3::new(i[(0, 0)], i[(1, 0)], i[(2, 0)]),
            DVec3::new(i[(0, 1)], i[(1, 1)], i[(2, 1)]),
            DVec3::new(i[(0, 2)], i[(1, 2)], i[(2, 2)]),
        ),
    );
    let body = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(to_rapier(start))
            .additional_mass_properties(props)
            .can_sleep(false)
            .linear_damping(0.0)
            .angular_damping(0.0),
    );
    for b in &coupling.balls {
        world.insert_collider(
            ColliderBuilder::ball(b.radius)
                .position(DPose3::from_translation(dvec(&b.centre)))
                .density(0.0)
                .collision_groups(no_contact())
                .solver_groups(no_contact()),
            Some(body),
        );
    }
    let ground = world.insert_body(RigidBodyBuilder::fixed());
    for c in &coupling.contacts {
        let ball = &coupling.balls[c.ball];
        let reach = 4.0 * (ball.radius + c.pair.nominal_radii().1.unwrap_or(0.0).abs());
        let (shape, pose) = parry_shape(&c.surface, &ball.centre, reach);
        world.insert_collider(
            ColliderBuilder::new(shape)
                .position(pose)
                .density(0.0)
                .collision_groups(no_contact())
                .solver_groups(no_contact()),
            Some(ground),
        );
    }
    (world, body)
}
