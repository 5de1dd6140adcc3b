//! The plane rectangle: P(u,v), its partial derivatives and normal, its exact ray hits and the
//! inverse of its parametrisation.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, flat_hit, nearest_hit, project};
use super::{Domain, Frame, Frames, flat_frame, flat_frames, normalize_or};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

/// A plane rectangle P = origin + u·U + v·V (the seed's P = P0 + a·u + b·v), U and V orthonormal.
/// Domain: u ∈ [0, width], v ∈ [0, height] in world units (the seed's 400-wide plane has u = h).
#[derive(Clone, Debug, PartialEq)]
pub struct Plane {
    pub origin: DVec3,
    pub u_axis: Vec3,
    pub v_axis: Vec3,
    pub normal: Vec3,
    pub size: Vec2,
}

impl Plane {
    /// As the seed builds it: from a normal and a direction in the plane (made orthogonal to the
    /// normal), with V = N × U.
    pub fn new(origin: DVec3, normal: Vec3, u_direction: Vec3, size: Vec2) -> Plane {
        let normal = normalize_or(normal, Vec3::Z);
        let in_plane = u_direction - normal * u_direction.dot(normal);
        let fallback = normal.any_orthonormal_vector();
        let u_axis = normalize_or(in_plane, fallback);
        Plane {
            origin,
            u_axis,
            v_axis: normal.cross(u_axis),
            normal,
            size,
        }
    }
}

impl Parametric for Plane {
    fn kind(&self) -> &'static str {
        "plane"
    }

    fn origin(&self) -> DVec3 {
        self.origin
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.origin
    }

    fn domain(&self) -> Domain {
        Domain {
            min: Vec2::ZERO,
            max: self.size,
        }
    }

    #[inline]
    fn frame(&self, u: f32, v: f32) -> Frame {
        flat_frame([self.u_axis, self.v_axis, self.normal], u, v)
    }

    fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        flat_frames(count, uv, self.frame(0.0, 0.0), out);
    }

    fn is_flat(&self) -> bool {
        true
    }

    fn max_curvature(&self) -> f32 {
        0.0
    }

    fn grid_shape(&self, _density: u32) -> GridShape {
        GridShape::flat(1, 1)
    }

    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let t = flat_hit(self.normal.as_dvec3(), ray)?;
        nearest_hit([t, f64::NAN], range, |t| {
            let uv = self.uv_at(ray.at(t));
            let inside = uv.cmpge(Vec2::ZERO).all() && uv.cmple(self.size).all();
            inside.then_some(uv)
        })
    }

    fn uv_at(&self, p: DVec3) -> Vec2 {
        project(p, self.u_axis.as_dvec3(), self.v_axis.as_dvec3())
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::assert_frame_matches_finite_differences;
    use super::*;

    #[test]
    fn basis_is_orthonormal_and_right_handed() {
        let p = Plane::new(
            DVec3::ZERO,
            Vec3::new(0.3, 1.0, 0.2),
            Vec3::X,
            Vec2::splat(10.0),
        );
        assert!(p.u_axis.dot(p.normal).abs() < 1e-6);
        assert!((p.u_axis.cross(p.v_axis) - p.normal).length() < 1e-6);
        assert_frame_matches_finite_differences(|u, v| p.frame(u, v), p.domain(), 1e-3);
    }

    #[test]
    fn degenerate_directions_still_give_a_basis() {
        let p = Plane::new(DVec3::ZERO, Vec3::ZERO, Vec3::Z, Vec2::ONE);
        assert!(p.u_axis.is_finite() && (p.u_axis.length() - 1.0).abs() < 1e-6);
    }
}
