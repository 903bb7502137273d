//! The rapier3d-f64 world of a dynamic seating: the moving half as one
//! dynamic rigid body (mass properties from [`MassModel`], its balls as
//! colliders), the fixed surfaces as parry shapes on one fixed body.
//!
//! rapier's own rigid contact is off for every coupling pair: all colliders
//! carry collision groups whose filter is empty
//! (`InteractionGroups::new(GROUP_1, Group::NONE, And)`). The contact forces
//! come only from the compliant contact layer, applied as user forces.
//!
//! A step is rapier's own integrator of the body, without the physics
//! pipeline ([`integrate`]): with no contact pair and no constraint, the
//! pipeline's broad phase, narrow phase, islands and constraint solver had
//! nothing to do, yet they were 60 % of a dynamic seating's instructions.
//! (The colliders therefore stay where [`build`] put them: nothing reads
//! their poses; the contact geometry is `assembly::geometry`'s, at the
//! body's pose.)
//! The step is the semi-implicit (symplectic) Euler update
//! v+ = v + dt M^-1 F(x),  x+ = x + dt v+ (Hairer, Lubich & Wanner,
//! *Geometric Numerical Integration*, 2006, §VI.3), as the pipeline's one
//! sub-step per step gave; the sigmas of scenes 01 and 06 moved by 3.4e-11
//! of themselves (rounding; the time step's own error is 1e-4).
//! Settings, and why:
//! - no gravity: the preload is the load, as in the quasi-static model
//!   and the paper's FE model (the weight of the moving half is part of the
//!   preload, `[preload] gravity`);
//! - no linear or angular damping from rapier: all damping is in the
//!   contact layer, where it is documented; no gyroscopic term (the
//!   pipeline's default).

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};
use rapier3d_f64::math::{Pose as DPose3, Rotation as DQuat, Vector as DVec3};
use rapier3d_f64::prelude::{
    ColliderBuilder, Group, InteractionGroups, InteractionTestMode, MassProperties, PhysicsWorld,
    RigidBody, RigidBodyBuilder, RigidBodyForces, RigidBodyHandle,
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

/// rapier's mass properties of a body of mass `mass` [kg] with its centre
/// of mass at `centre` and the inertia tensor `inertia` about it, both in
/// the body frame.
fn mass_properties(mass: f64, centre: &Vector3<f64>, inertia: &Matrix3<f64>) -> MassProperties {
    let column = |j: usize| DVec3::new(inertia[(0, j)], inertia[(1, j)], inertia[(2, j)]);
    let matrix = rapier3d_f64::math::Matrix::from_cols(column(0), column(1), column(2));
    MassProperties::with_inertia_matrix(dvec(centre), mass, matrix)
}

/// Collision groups that interact with nothing: rapier's rigid contact off.
fn no_contact() -> InteractionGroups {
    InteractionGroups::new(Group::GROUP_1, Group::NONE, InteractionTestMode::And)
}

/// Build the world with the moving half at `start` (at rest).
pub(crate) fn build(
    coupling: &Coupling,
    mass: &MassModel,
    start: &BodyPose,
) -> (PhysicsWorld, RigidBodyHandle) {
    let mut world = PhysicsWorld::new();
    let props = mass_properties(mass.mass, &mass.centre_of_mass, &mass.inertia);
    let body = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(to_rapier(start))
            .additional_mass_properties(props)
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
    // The pipeline would form the mass properties at its first step.
    let PhysicsWorld { bodies, colliders, .. } = &mut world;
    bodies[body].recompute_mass_properties_from_colliders(colliders);
    (world, body)
}

/// One time step of the free body under its user force and torque, by
/// rapier's own symplectic Euler: v+ = v + dt M^-1 F, w+ = w + dt I^-1 tau
/// (`RigidBodyForces::integrate`), then the pose moved by dt v+, dt w+
/// about the centre of mass (`RigidBodyVelocity::integrate`).
pub(crate) fn integrate(rb: &mut RigidBody, dt: f64) {
    let forces = RigidBodyForces {
        force: rb.user_force(),
        torque: rb.user_torque(),
        ..RigidBodyForces::default()
    };
    let mprops = rb.mass_properties();
    let vels = forces.integrate(dt, rb.vels(), mprops);
    let pose = vels.integrate(dt, rb.position(), &mprops.local_mprops.local_com);
    rb.set_vels(vels, false);
    rb.set_position(pose, false);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step of [`integrate`] is the symplectic Euler update, formed here
    /// by hand: a body of mass m and inertia I (not diagonal) about an
    /// off-origin centre of mass c, turned and moving, under a force F at a world point p:
    /// v+ = v + dt F/m, w+ = w + dt I_w^-1 ((p - c_w) x F) with
    /// I_w = R I R^T, then the centre moved by dt v+ and the body turned by
    /// exp(dt w+) about it. Two steps, so that the second starts from the
    /// pose, velocity and world inertia the first left.
    #[test]
    fn a_step_is_symplectic_euler() {
        let (m, c) = (0.7, Vector3::new(0.01, -0.02, 0.005));
        // Not diagonal in the body frame (the principal axes turned).
        #[rustfmt::skip]
        let inertia = Matrix3::new(
            2e-4, 1e-5, -2e-5,
            1e-5, 3e-4, 3e-5,
            -2e-5, 3e-5, 4.5e-4,
        );
        let start = BodyPose {
            rotation: UnitQuaternion::from_scaled_axis(Vector3::new(0.2, -0.1, 0.4)),
            translation: Vector3::new(0.3, 0.1, -0.2),
        };
        let (mut v, mut w) = (Vector3::new(0.01, 0.0, -0.02), Vector3::new(0.5, -0.3, 0.1));
        let mut world = PhysicsWorld::new();
        let props = mass_properties(m, &c, &inertia);
        let handle = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(to_rapier(&start))
                .additional_mass_properties(props)
                .linvel(dvec(&v))
                .angvel(dvec(&w)),
        );
        let PhysicsWorld { bodies, colliders, .. } = &mut world;
        bodies[handle].recompute_mass_properties_from_colliders(colliders);
        let (f, p, dt) = (Vector3::new(3.0, -1.0, 2.0), Vector3::new(0.35, 0.05, -0.1), 1e-3);
        let mut pose = start;
        for _ in 0..2 {
            let rb = &mut bodies[handle];
            rb.reset_forces(false);
            rb.reset_torques(false);
            rb.add_force_at_point(dvec(&f), dvec(&p), false);
            integrate(rb, dt);
            // By hand.
            let r = pose.rotation.to_rotation_matrix().into_inner();
            let com = pose.rotation * c + pose.translation;
            let i_world = r * inertia * r.transpose();
            v += f * (dt / m);
            w += i_world.try_inverse().unwrap() * ((p - com).cross(&f)) * dt;
            let turn = UnitQuaternion::from_scaled_axis(w * dt);
            let rotation = turn * pose.rotation;
            let com_next = com + v * dt;
            pose = BodyPose { rotation, translation: com_next - rotation * c };
            let got = from_rapier(bodies[handle].position());
            let rb = &bodies[handle];
            assert!((nvec(rb.linvel()) - v).norm() <= 1e-14 * v.norm(), "{:?} {v:?}", rb.linvel());
            assert!((nvec(rb.angvel()) - w).norm() <= 1e-12 * w.norm(), "{:?} {w:?}", rb.angvel());
            assert!((got.translation - pose.translation).norm() <= 1e-15, "{got:?} {pose:?}");
            assert!(got.rotation.angle_to(&pose.rotation) <= 1e-14, "{got:?} {pose:?}");
        }
    }
}
