//! The paraboloid (the seed's "parabola"): P(u,v), its partial derivatives and normal.

use super::sphere::{SEED_UNITS_PER_RADIAN, azimuth};
use super::{AxisBasis, Domain, Frame, normalize_or};
use glam::{DVec3, Vec2};

/// The seed's "parabola": a paraboloid of revolution, height = curvature·ρ² along the axis.
/// Domain: u ∈ [0, 720) azimuth in the sphere's seed units, v = ρ ∈ [0, radius] in world units.
/// The normal points to the concave side (into the bowl); at the apex it is the axis.
#[derive(Clone, Debug, PartialEq)]
pub struct Paraboloid {
    pub apex: DVec3,
    pub basis: AxisBasis,
    pub curvature: f32,
    pub radius: f32,
}

impl Paraboloid {
    pub fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: Vec2::new(720.0, self.radius),
        }
    }

    #[inline]
    pub fn frame(&self, u: f32, v: f32) -> Frame {
        let b = &self.basis;
        let (sin_phi, cos_phi) = super::sin_cos(azimuth(u));
        let radial = b.to_world(sin_phi, 0.0, cos_phi);
        let tangent = b.to_world(cos_phi, 0.0, -sin_phi);
        let rho = v;
        let slope = 2.0 * self.curvature * rho;
        Frame {
            p: radial * rho + b.axis * (self.curvature * rho * rho),
            pu: tangent * (rho / SEED_UNITS_PER_RADIAN),
            pv: radial + b.axis * slope,
            n: normalize_or(b.axis - radial * slope, b.axis),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;
    use glam::Vec3;

    #[test]
    fn frame_is_consistent_and_apex_is_smooth() {
        let p = Paraboloid {
            apex: DVec3::ZERO,
            basis: AxisBasis::from_axis(Vec3::new(0.0, 1.0, 0.5)),
            curvature: 0.01,
            radius: 100.0,
        };
        assert_frame_matches_finite_differences(|u, v| p.frame(u, v), p.domain(), 0.02);
        let apex = p.frame(77.0, 0.0);
        assert!((apex.n - p.basis.axis).length() < 1e-6);
        assert_eq!(apex.pu, Vec3::ZERO);
    }
}
