//! Exact ray–paraboloid intersection and the paraboloid's (u,v) at the hit.

use super::quadratic::quadratic_roots;
use super::ray::{Hit, Ray, nearest_hit};
use super::sphere::azimuth_u;
use crate::surface::{AxisBasis, Paraboloid};
use glam::{DVec3, Vec2};
use std::ops::RangeInclusive;

/// h = k·ρ² along the ray (h along the axis, ρ the distance from it) is a quadratic in t.
pub(super) fn intersect_paraboloid(
    paraboloid: &Paraboloid,
    ray: &Ray,
    range: &RangeInclusive<f64>,
) -> Option<Hit> {
    let k = paraboloid.curvature as f64;
    let o = local(&paraboloid.basis, ray.origin);
    let d = local(&paraboloid.basis, ray.direction);
    let a = k * (d.x * d.x + d.z * d.z);
    let b = 2.0 * k * (o.x * d.x + o.z * d.z) - d.y;
    let c = k * (o.x * o.x + o.z * o.z) - o.y;
    let radius = paraboloid.radius;
    nearest_hit(quadratic_roots(a, b, c), range, |t| {
        let uv = paraboloid_uv(paraboloid, ray.at(t));
        (uv.y <= radius).then_some(uv)
    })
}

/// u from the azimuth about the axis, v = ρ.
pub(super) fn paraboloid_uv(paraboloid: &Paraboloid, p: DVec3) -> Vec2 {
    let q = local(&paraboloid.basis, p);
    Vec2::new(azimuth_u(q.x, q.z), q.x.hypot(q.z) as f32)
}

/// Coordinates along (e1, axis, e2).
pub(super) fn local(basis: &AxisBasis, p: DVec3) -> DVec3 {
    DVec3::new(
        p.dot(basis.e1.as_dvec3()),
        p.dot(basis.axis.as_dvec3()),
        p.dot(basis.e2.as_dvec3()),
    )
}
