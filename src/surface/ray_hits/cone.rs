//! Exact ray–cone intersection and the cone's (u,v) at the hit.

use super::paraboloid::local;
use super::quadratic::quadratic_roots;
use super::ray::{Hit, Ray, nearest_hit};
use super::sphere::azimuth_u;
use crate::surface::Cone;
use glam::{DVec3, Vec2};
use std::ops::RangeInclusive;

/// ρ² = tan²α·h² along the ray is a quadratic in t; it describes both nappes, so roots with
/// h outside [0, height] are dropped.
pub(super) fn intersect_cone(cone: &Cone, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit> {
    let spread2 = (cone.half_angle as f64).tan().powi(2);
    let o = local(&cone.basis, ray.origin);
    let d = local(&cone.basis, ray.direction);
    let a = d.x * d.x + d.z * d.z - spread2 * d.y * d.y;
    let b = 2.0 * (o.x * d.x + o.z * d.z - spread2 * o.y * d.y);
    let c = o.x * o.x + o.z * o.z - spread2 * o.y * o.y;
    let height = cone.height;
    nearest_hit(quadratic_roots(a, b, c), range, |t| {
        let uv = cone_uv(cone, ray.at(t));
        (uv.y >= 0.0 && uv.y <= height).then_some(uv)
    })
}

/// u from the azimuth about the axis, v = distance from the apex along the axis.
pub(super) fn cone_uv(cone: &Cone, p: DVec3) -> Vec2 {
    let q = local(&cone.basis, p);
    Vec2::new(azimuth_u(q.x, q.z), q.y as f32)
}
