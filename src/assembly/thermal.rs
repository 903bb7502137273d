//! The coupling at other temperatures (docs/model.md, "Thermal drift").
//!
//! Each body expands about its origin o: a point p of it goes to
//! o + (1 + alpha dT) (p - o), alpha the body's coefficient and dT its
//! temperature change (`scene::Body::map`). The moving body carries the
//! balls (their centres), the canoe patches and moving pins (through their
//! ball's centre), the evaluation points and the preload points; the fixed
//! body the flats (a point of the plane), the pins and arches (a point of
//! the axis), the fixed balls (their centres) and the springs' anchors.
//! Every element is at its body's temperature and its own shape grows with
//! its own material's coefficient: a ball's radius, and a patch's offset
//! from its ball's centre with its radius, by (1 + alpha_element dT); a
//! pin's, fixed ball's or arch's radius likewise. Directions (plane
//! normals, axes) do not change. A constant preload force keeps its
//! magnitude and direction at its moved point; a spring's length follows
//! its two ends (below).

use nalgebra::Vector3;

use super::contacts::{MovingSurface, place};
use super::{AssemblyError, BodyPose, Coupling, MovingBall};
use crate::scene::{ForceLaw, Preload, SurfaceGeometry, Temperatures, ThermalBodies};

impl Coupling {
    /// The expansion model this coupling was assembled with (`[thermal]`).
    pub fn thermal_bodies(&self) -> Result<&ThermalBodies, AssemblyError> {
        self.thermal.as_ref().ok_or(AssemblyError::NoThermal)
    }

    /// This coupling with its bodies and elements at the temperature
    /// changes `t` (module docs): every contact placed and its laws formed
    /// again with the grown radii. The touching pose, the friction laws
    /// and the mass properties stay; the result carries no expansion
    /// model (it is not expanded again).
    pub fn at_temperatures(&self, t: Temperatures) -> Result<Coupling, AssemblyError> {
        let bodies = self.thermal_bodies()?;
        let (moving, fixed) = (&bodies.moving, &bodies.fixed);
        let balls: Vec<MovingBall> = (self.balls.iter().zip(&bodies.balls))
            .map(|(b, alpha)| MovingBall {
                centre: moving.map(&b.centre, t.moving),
                radius: b.radius * (1.0 + alpha * t.moving),
                material: b.material.clone(),
            })
            .collect();
        let mut contacts = Vec::with_capacity(self.contacts.len());
        for (i, c) in self.contacts.iter().enumerate() {
            let ball = &self.balls[c.ball];
            let own = 1.0 + bodies.balls[c.ball] * t.moving;
            let surface_stretch = 1.0 + bodies.surfaces[i] * t.fixed;
            let surface = match c.surface {
                SurfaceGeometry::Plane { point, normal } => {
                    SurfaceGeometry::Plane { point: fixed.map(&point, t.fixed), normal }
                }
                SurfaceGeometry::Cylinder { axis_point, direction, radius } => {
                    SurfaceGeometry::Cylinder {
                        axis_point: fixed.map(&axis_point, t.fixed),
                        direction,
                        radius: radius * surface_stretch,
                    }
                }
                SurfaceGeometry::Sphere { centre, radius } => SurfaceGeometry::Sphere {
                    centre: fixed.map(&centre, t.fixed),
                    radius: radius * surface_stretch,
                },
                SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius } => {
                    SurfaceGeometry::ConcaveCylinder {
                        axis_point: fixed.map(&axis_point, t.fixed),
                        direction,
                        radius: radius * surface_stretch,
                    }
                }
            };
            let moving_surface = MovingSurface {
                centre: moving.map(&ball.centre, t.moving) + (c.centre - ball.centre) * own,
                radius: c.radius * own,
                axis: c.axis,
            };
            let materials = (c.pair.material1.clone(), c.pair.material2.clone());
            let compliance = (c.normal.compliance, c.law.tangential_support);
            contacts.push(place(i, c.ball, moving_surface, surface, materials, compliance)?);
        }
        Ok(Coupling {
            balls,
            contacts,
            touching_pose: self.touching_pose,
            friction: self.friction,
            dynamics: self.dynamics,
            thermal: None,
        })
    }
}

/// Where the moving body's point `p` (body frame) is at `t`.
pub fn moving_point(bodies: &ThermalBodies, p: &Vector3<f64>, t: Temperatures) -> Vector3<f64> {
    bodies.moving.map(p, t.moving)
}

/// The preload at the temperature changes `t` on the coupling whose
/// touching pose is `touching` (module docs). Each force acts at its
/// point moved with the moving body. A spring lies along its direction d
/// between its anchor A = p_0 - l_0 d on the fixed half (p_0 its point in
/// the touching pose, l_0 its length there) and its point on the moving
/// half; the expansion moves its point by R_0 (p' - p) and its anchor by
/// A' - A, so its length at the touching pose changes by
/// c = (R_0 (p' - p) - (A' - A)) . d and its force there by -k c: the
/// spring of the returned preload has the force F_0 - k c in the touching
/// pose, at full load. The spring's own expansion (its free length) is
/// left out. A magnet's keeper K = p_0 + gap_0 d on the fixed half moves
/// likewise, and its gap in the touching pose becomes gap_0 - c (c with K
/// for A), its force the table's there.
pub fn preload_at(
    bodies: &ThermalBodies,
    preload: &Preload,
    t: Temperatures,
    touching: &BodyPose,
) -> Preload {
    let mut out = preload.clone();
    for f in &mut out.forces {
        let moved = bodies.moving.map(&f.point, t.moving);
        // The change c of the distance along d from the point to the
        // spring's anchor or the magnet's keeper on the fixed half.
        let p0 = touching.apply(&f.point);
        let change = |anchor: Vector3<f64>| {
            let anchor_moved = bodies.fixed.map(&anchor, t.fixed);
            (touching.rotation * (moved - f.point) - (anchor_moved - anchor)).dot(&f.direction)
        };
        match &f.law {
            ForceLaw::Spring { stiffness, free_length } => {
                let c = change(p0 - f.direction * (free_length - f.force / stiffness));
                f.force -= stiffness * c;
            }
            ForceLaw::Magnet(m) => {
                let gap = m.gap - change(p0 + f.direction * m.gap);
                f.force = m.force(gap).0;
                f.law = ForceLaw::Magnet(m.at_gap(gap));
            }
            ForceLaw::Constant | ForceLaw::Weight => {}
        }
        f.point = moved;
    }
    out
}
