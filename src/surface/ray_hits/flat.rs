//! Where a ray meets a flat surface through the anchor, and (u,v) by projection onto its axes.

use super::ray::Ray;
use glam::{DVec3, Vec2};

/// The ray parameter where the ray meets the plane through the anchor with this normal.
pub fn flat_hit(normal: DVec3, ray: &Ray) -> Option<f64> {
    let along = ray.direction.dot(normal);
    let t = -ray.origin.dot(normal) / along;
    (along != 0.0 && t.is_finite()).then_some(t)
}

/// P = u·U + v·V with U, V orthonormal: projection recovers (u,v).
pub fn project(p: DVec3, u_axis: DVec3, v_axis: DVec3) -> Vec2 {
    Vec2::new(p.dot(u_axis) as f32, p.dot(v_axis) as f32)
}
