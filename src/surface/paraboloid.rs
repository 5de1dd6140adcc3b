//! The paraboloid (the seed's "parabola"): P(u,v), its partial derivatives and normal, its exact
//! ray hits and the inverse of its parametrisation.

use super::grid_shape::GridShape;
use super::hull::past_edge;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, Rays, TrueHit, nearest_hit, quadratic_roots};
use super::seed_angles::{SEED_UNITS_PER_RADIAN, azimuth, azimuth_u, azimuth_u_f32};
use super::true_hit::{Quadric, quadric_hits};
use super::{AxisBasis, Domain, Frame, normalize_or};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

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

impl Parametric for Paraboloid {
    fn kind(&self) -> &'static str {
        "paraboloid"
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
            max: Vec2::new(720.0, self.radius),
        }
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
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

    fn max_curvature(&self) -> f32 {
        2.0 * self.curvature
    }

    fn grid_shape(&self, density: u32) -> GridShape {
        GridShape {
            cells_u: 2 * density,
            cells_v: (density / 2).max(2),
            collapsed_v_min: true,
            collapsed_v_max: false,
        }
    }

    /// The normal points into the bowl, its concave side.
    fn hull_outwards(&self, uv: Vec2, frame: &Frame) -> Vec3 {
        -frame.n + past_edge(frame.pv, false, uv.y == self.radius)
    }

    /// h = k·ρ² along the ray (h along the axis, ρ the distance from it) is a quadratic in t.
    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let k = self.curvature as f64;
        let o = self.basis.local(ray.origin);
        let d = self.basis.local(ray.direction);
        let a = k * (d.x * d.x + d.z * d.z);
        let b = 2.0 * k * (o.x * d.x + o.z * d.z) - d.y;
        let c = k * (o.x * o.x + o.z * o.z) - o.y;
        let radius = self.radius;
        nearest_hit(quadratic_roots(a, b, c), range, |t| {
            let uv = self.uv_at(ray.at(t));
            (uv.y <= radius).then_some(uv)
        })
    }

    /// u from the azimuth about the axis, v = ρ.
    fn uv_at(&self, p: DVec3) -> Vec2 {
        let q = self.basis.local(p);
        Vec2::new(azimuth_u(q.x, q.z), q.x.hypot(q.z) as f32)
    }

    fn true_hits(&self, rays: &Rays, hits: &mut [TrueHit], found: &mut [bool]) {
        quadric_hits(&ParaboloidQuadric(self), rays, hits, found);
    }
}

/// h = k·ρ² (h along the axis, ρ from it).
struct ParaboloidQuadric<'a>(&'a Paraboloid);

impl Quadric for ParaboloidQuadric<'_> {
    #[inline(always)]
    fn local(&self, v: DVec3) -> DVec3 {
        self.0.basis.local(v)
    }

    #[inline(always)]
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3] {
        let k = self.0.curvature as f64;
        [
            k * (d.x * d.x + d.z * d.z),
            2.0 * k * (q.x * d.x + q.z * d.z) - d.y,
            k * (q.x * q.x + q.z * q.z) - q.y,
        ]
    }

    /// Past the rim the quadric is not the surface.
    #[inline(always)]
    fn contains(&self, p: DVec3) -> bool {
        let radius = self.0.radius as f64;
        p.x * p.x + p.z * p.z <= radius * radius
    }

    #[inline(always)]
    fn uv(&self, p: Vec3) -> Vec2 {
        Vec2::new(azimuth_u_f32(p.x, p.z), (p.x * p.x + p.z * p.z).sqrt())
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
