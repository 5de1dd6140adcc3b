//! The cone: P(u,v), its partial derivatives and normal, its exact ray hits and the inverse of
//! its parametrisation.

use super::grid_shape::GridShape;
use super::hull::past_edge;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, Rays, TrueHit, nearest_hit, quadratic_roots};
use super::seed_angles::{SEED_UNITS_PER_RADIAN, azimuth, azimuth_u, azimuth_u_f32};
use super::true_hit::{Quadric, quadric_hits};
use super::{AxisBasis, Domain, Frame};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

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

impl Parametric for Cone {
    fn kind(&self) -> &'static str {
        "cone"
    }

    fn origin(&self) -> DVec3 {
        self.apex
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.apex
    }

    fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: Vec2::new(720.0, self.height),
        }
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
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

    /// A cone's curvature grows without bound towards its apex; its value half way along the
    /// side is given.
    fn max_curvature(&self) -> f32 {
        let radius_half_way = 0.5 * self.height * self.half_angle.tan();
        self.half_angle.cos() / radius_half_way.max(f32::MIN_POSITIVE)
    }

    /// A cone is ruled, so a single cell along v would be exact in position; but the apex fan's
    /// vertex sits at mid-cell u, and u interpolated from it is off by up to half a cell across
    /// the whole fan row. Rows along v confine that to the first one.
    fn grid_shape(&self, density: u32) -> GridShape {
        GridShape {
            cells_u: 2 * density,
            cells_v: (density / 2).max(2),
            collapsed_v_min: true,
            collapsed_v_max: false,
        }
    }

    /// At the apex every vertex moves back along the axis: the offset cone's apex.
    fn hull_outwards(&self, uv: Vec2, frame: &Frame) -> Vec3 {
        if uv.y == 0.0 {
            -self.basis.axis / self.half_angle.sin()
        } else {
            frame.n + past_edge(frame.pv, false, uv.y == self.height)
        }
    }

    /// ρ² = tan²α·h² along the ray is a quadratic in t; it describes both nappes, so roots with
    /// h outside [0, height] are dropped.
    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let spread2 = (self.half_angle as f64).tan().powi(2);
        let o = self.basis.local(ray.origin);
        let d = self.basis.local(ray.direction);
        let a = d.x * d.x + d.z * d.z - spread2 * d.y * d.y;
        let b = 2.0 * (o.x * d.x + o.z * d.z - spread2 * o.y * d.y);
        let c = o.x * o.x + o.z * o.z - spread2 * o.y * o.y;
        let height = self.height;
        nearest_hit(quadratic_roots(a, b, c), range, |t| {
            let uv = self.uv_at(ray.at(t));
            (uv.y >= 0.0 && uv.y <= height).then_some(uv)
        })
    }

    /// u from the azimuth about the axis, v = distance from the apex along the axis.
    fn uv_at(&self, p: DVec3) -> Vec2 {
        let q = self.basis.local(p);
        Vec2::new(azimuth_u(q.x, q.z), q.y as f32)
    }

    fn true_hits(&self, rays: &Rays, hits: &mut [TrueHit], found: &mut [bool]) {
        quadric_hits(&ConeQuadric::new(self), rays, hits, found);
    }
}

/// ρ² = tan²α·h²; the nappe behind the apex (h < 0) is not the surface.
struct ConeQuadric<'a> {
    cone: &'a Cone,
    spread2: f64,
}

impl ConeQuadric<'_> {
    fn new(cone: &Cone) -> ConeQuadric<'_> {
        let spread2 = (cone.half_angle as f64).tan().powi(2);
        ConeQuadric { cone, spread2 }
    }
}

impl Quadric for ConeQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        self.cone.basis.local(v)
    }

    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let t2 = self.spread2;
        [
            d.x * d.x + d.z * d.z - t2 * d.y * d.y,
            2.0 * (q.x * d.x + q.z * d.z - t2 * q.y * d.y),
            q.x * q.x + q.z * q.z - t2 * q.y * q.y,
        ]
    }

    /// The nappe behind the apex, and the quadric past the base, are not the surface.
    #[inline(always)]
    fn contains(&self, p: DVec3) -> bool {
        p.y >= 0.0 && p.y <= self.cone.height as f64
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        Vec2::new(azimuth_u_f32(p.x, p.z), p.y)
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
