//! The cone: P(u,v), its partial derivatives and normal.

use super::sphere::{SEED_UNITS_PER_RADIAN, azimuth};
use super::{AxisBasis, Domain, Frame};
use glam::{DVec3, Vec2};

/// A right circular cone without its base. Domain: u ∈ [0, 720) azimuth in the sphere's seed
/// units, v ∈ [0, height] distance from the apex along the axis (which points from the apex to the
/// base). The outward normal depends only on u, so it is defined at the apex too (where Pu = 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Cone {
    pub apex: DVec3,
    pub basis: AxisBasis,
    /// Angle between the axis and the side, in radians, in (0, π/2).
    pub half_angle: f32,
    pub height: f32,
}

impl Cone {
    pub fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: Vec2::new(720.0, self.height),
        }
    }

    #[inline]
    pub fn frame(&self, u: f32, v: f32) -> Frame {
        let b = &self.basis;
        let (sin_phi, cos_phi) = super::sin_cos(azimuth(u));
        let radial = b.to_world(sin_phi, 0.0, cos_phi);
        let tangent = b.to_world(cos_phi, 0.0, -sin_phi);
        let (sin_a, cos_a) = self.half_angle.sin_cos();
        let spread = sin_a / cos_a;
        Frame {
            p: (b.axis + radial * spread) * v,
            pu: tangent * (v * spread / SEED_UNITS_PER_RADIAN),
            pv: b.axis + radial * spread,
            n: radial * cos_a - b.axis * sin_a,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;
    use glam::Vec3;

    #[test]
    fn frame_is_consistent_and_normal_is_outward() {
        let c = Cone {
            apex: DVec3::ZERO,
            basis: AxisBasis::from_axis(-Vec3::Y),
            half_angle: 0.4,
            height: 200.0,
        };
        assert_frame_matches_finite_differences(|u, v| c.frame(u, v), c.domain(), 0.02);
        for u in [0.0, 200.0, 500.0] {
            let f = c.frame(u, 100.0);
            let radial_part = f.p - c.basis.axis * f.p.dot(c.basis.axis);
            assert!(f.n.dot(radial_part) > 0.0, "normal points outward");
            let at_apex = c.frame(u, 0.0);
            assert!(at_apex.n.is_finite() && (at_apex.n.length() - 1.0).abs() < 1e-5);
        }
    }
}
