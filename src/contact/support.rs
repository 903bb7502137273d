//! A tangential support compliance in series with Mindlin's stiffness: the
//! flexure or the mount behind a contact surface, compliant `along` an axis
//! of the tangent plane and `across` it (equal: isotropic).
//!
//! Springs in series add their compliances. In the tangent plane, with
//! Mindlin's principal stiffness K_m = diag(k1, k2) (Johnson 1985 sec. 7.2,
//! `mindlin`) and the support's compliance C = c_along u u^T + c_across v v^T
//! (u the axis projected into the plane, v = n x u):
//! ```text
//! K = (K_m^-1 + C)^-1 = K_m (I + C K_m)^-1
//! dK/dF_n = K K_m^-1 (dK_m/dF_n) K_m^-1 K = dlog K K_m^-1 K   (dK_m = dlog K_m)
//! ```
//! since the support is linear and K_m scales with the semi-axis a
//! (d ln K_m / dF_n = dlog). Isotropic (c_along = c_across = c_t) this is
//! k' = k / (1 + k c_t) per principal axis of K_m.

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use serde::ser::{Serialize, SerializeMap, Serializer};

use super::mindlin::PrincipalStiffness;

/// The tangential support compliance of a contact [m/N]. Serialised as
/// the entries `tangential_compliance` (`along`; left out at zero) and,
/// when anisotropic, `tangential_compliance_across` and `tangential_axis`
/// (flattened into a scene's surface).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TangentialSupport {
    /// Compliance along `axis` (projected into the tangent plane) [m/N].
    pub along: f64,
    /// Compliance across it, in the tangent plane [m/N].
    pub across: f64,
    /// The unit direction of `along` in the world frame; zero when
    /// `along == across` (isotropic, no axis needed).
    pub axis: Vector3<f64>,
}

/// A support's series tensor in the tangent plane: its principal form, the
/// 3x3 tensor K and K K_m^-1 K, the factor of dlog in dK/dF_n.
pub struct Series {
    pub principal: PrincipalStiffness,
    pub tensor: Matrix3<f64>,
    pub derivative: Matrix3<f64>,
}

impl TangentialSupport {
    /// The same compliance `c` [m/N] in every tangential direction.
    pub fn isotropic(c: f64) -> Self {
        TangentialSupport { along: c, across: c, axis: Vector3::zeros() }
    }

    /// No support compliance: Mindlin's stiffness alone.
    pub fn is_rigid(&self) -> bool {
        self.along == 0.0 && self.across == 0.0
    }

    /// Equal compliances along and across: the plane's every direction.
    pub fn is_isotropic(&self) -> bool {
        self.along == self.across
    }

    /// Mindlin's principal stiffness `k` (about `major_axis`, in the tangent
    /// plane of the unit `normal`) in series with this support (module
    /// docs), for an anisotropic support (`!is_isotropic`).
    pub fn series(&self, k: [f64; 2], normal: &Vector3<f64>, major_axis: &Vector3<f64>) -> Series {
        let mindlin = PrincipalStiffness::new(k, normal, major_axis);
        let u = self.axis - normal * normal.dot(&self.axis);
        // The plane's basis: Mindlin's axes, or the support's for a circle.
        let [e1, e2] = match mindlin.axes {
            Some(axes) => axes,
            None => {
                let e1 = u.normalize();
                [e1, normal.cross(&e1)]
            }
        };
        let u = u.normalize();
        let v = normal.cross(&u);
        let along = Vector2::new(u.dot(&e1), u.dot(&e2));
        let across = Vector2::new(v.dot(&e1), v.dot(&e2));
        let c = along * along.transpose() * self.along + across * across.transpose() * self.across;
        let km = Matrix2::from_diagonal(&Vector2::from(mindlin.k));
        let m = Matrix2::identity() + c * km;
        // det M = 1 + tr(C K_m) + det C det K_m > 0 (C, K_m >= 0).
        let m_inv = m.try_inverse().unwrap_or_else(Matrix2::zeros);
        let kt = km * m_inv;
        let kt = (kt + kt.transpose()) * 0.5;
        // K K_m^-1 K = K M^-1 (K_m^-1 K = M^-1), defined at k = 0 too.
        let d = kt * m_inv;
        let d = (d + d.transpose()) * 0.5;
        let lift = |x: &Matrix2<f64>| {
            let (a, b) = (e1 * e1.transpose(), e2 * e2.transpose());
            let ab = e1 * e2.transpose() + e2 * e1.transpose();
            a * x[(0, 0)] + b * x[(1, 1)] + ab * x[(0, 1)]
        };
        let eig = kt.symmetric_eigen();
        let (i, j) = if eig.eigenvalues[0] >= eig.eigenvalues[1] { (0, 1) } else { (1, 0) };
        let first = eig.eigenvectors.column(i);
        let axis = e1 * first[0] + e2 * first[1];
        let values = [eig.eigenvalues[i].max(0.0), eig.eigenvalues[j].max(0.0)];
        let principal = PrincipalStiffness::new(values, normal, &axis);
        Series { tensor: principal.tensor(normal), principal, derivative: lift(&d) }
    }
}

impl Serialize for TangentialSupport {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        if self.along != 0.0 {
            m.serialize_entry("tangential_compliance", &self.along)?;
        }
        if !self.is_isotropic() {
            m.serialize_entry("tangential_compliance_across", &self.across)?;
            m.serialize_entry("tangential_axis", &self.axis)?;
        }
        m.end()
    }
}
