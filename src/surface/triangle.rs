//! The triangle with the seed's plane parametrisation, its exact ray hits and the inverse of
//! its parametrisation.

use super::grid_shape::GridShape;
use super::parametric::Parametric;
use super::ray_hits::{Hit, Ray, flat_hit, nearest_hit, project};
use super::{Domain, Frame, Frames, Mesh, Tessellation, flat_frame, flat_frames, normalize_or};
use glam::{DVec2, DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

/// A triangle with the seed's plane parametrisation: U from corner a towards b, V = N × U, and
/// P = a + u·U + v·V in world units. Domain: the triangle's own corners in (u,v), inside the
/// rectangle `domain()` returns.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    pub a: DVec3,
    pub u_axis: Vec3,
    pub v_axis: Vec3,
    pub normal: Vec3,
    /// (u,v) of the corners a, b, c.
    pub corners_uv: [Vec2; 3],
}

impl Triangle {
    pub fn new(a: DVec3, b: DVec3, c: DVec3) -> Triangle {
        let ab = (b - a).as_vec3();
        let ac = (c - a).as_vec3();
        let normal = normalize_or(ab.cross(ac), Vec3::Z);
        let u_axis = normalize_or(ab, normal.any_orthonormal_vector());
        let v_axis = normal.cross(u_axis);
        let uv = |p: Vec3| Vec2::new(p.dot(u_axis), p.dot(v_axis));
        Triangle {
            a,
            u_axis,
            v_axis,
            normal,
            corners_uv: [Vec2::ZERO, uv(ab), uv(ac)],
        }
    }
}

impl Parametric for Triangle {
    fn kind(&self) -> &'static str {
        "triangle"
    }

    fn origin(&self) -> DVec3 {
        self.a
    }

    fn origin_mut(&mut self) -> &mut DVec3 {
        &mut self.a
    }

    /// The rectangle around the triangle's corners.
    fn domain(&self) -> Domain {
        let [a, b, c] = self.corners_uv;
        Domain {
            min: a.min(b).min(c),
            max: a.max(b).max(c),
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

    /// A planar triangle needs no subdivision: perspective-correct interpolation is exact on it.
    fn own_mesh(&self) -> Option<Mesh> {
        let positions = self.corners_uv.map(|uv| self.frame(uv.x, uv.y).p).to_vec();
        Some(Mesh {
            positions,
            uvs: self.corners_uv.to_vec(),
            indices: vec![[0, 1, 2]],
            chord_error: 0.0,
        })
    }

    fn triangle_count(&self, _tessellation: Tessellation) -> u64 {
        1
    }

    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
        let t = flat_hit(self.normal.as_dvec3(), ray)?;
        nearest_hit([t, f64::NAN], range, |t| {
            let uv = self.uv_at(ray.at(t));
            contains(self.corners_uv, uv).then_some(uv)
        })
    }

    fn uv_at(&self, p: DVec3) -> Vec2 {
        project(p, self.u_axis.as_dvec3(), self.v_axis.as_dvec3())
    }
}

/// Inside or on the boundary of the triangle in (u,v), whichever way it winds.
fn contains(corners: [Vec2; 3], uv: Vec2) -> bool {
    let [a, b, c] = corners.map(|c| c.as_dvec2());
    let p = uv.as_dvec2();
    let edge = |from: DVec2, to: DVec2| (to - from).perp_dot(p - from);
    let signs = [edge(a, b), edge(b, c), edge(c, a)];
    signs.iter().all(|&s| s >= 0.0) || signs.iter().all(|&s| s <= 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_map_back_to_their_points() {
        let (a, b, c) = (
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(4.0, 2.0, 3.5),
            DVec3::new(2.0, 5.0, 1.0),
        );
        let t = Triangle::new(a, b, c);
        for (uv, corner) in t.corners_uv.iter().zip([a, b, c]) {
            let p = a + t.frame(uv.x, uv.y).p.as_dvec3();
            assert!((p - corner).length() < 1e-5, "{p:?} vs {corner:?}");
        }
    }
}
