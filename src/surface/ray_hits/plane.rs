//! Exact ray–plane intersection and the plane's (u,v) at the hit.

use super::ray::{Hit, Ray, nearest_hit};
use crate::surface::Plane;
use glam::{DVec3, Vec2};
use std::ops::RangeInclusive;

pub(super) fn intersect_plane(
    plane: &Plane,
    ray: &Ray,
    range: &RangeInclusive<f64>,
) -> Option<Hit> {
    let t = flat_hit(plane.normal.as_dvec3(), ray)?;
    nearest_hit([t, f64::NAN], range, |t| {
        let uv = plane_uv(plane, ray.at(t));
        let inside = uv.cmpge(Vec2::ZERO).all() && uv.cmple(plane.size).all();
        inside.then_some(uv)
    })
}

/// The ray parameter where the ray meets the plane through the anchor with this normal.
pub(super) fn flat_hit(normal: DVec3, ray: &Ray) -> Option<f64> {
    let along = ray.direction.dot(normal);
    let t = -ray.origin.dot(normal) / along;
    (along != 0.0 && t.is_finite()).then_some(t)
}

/// P = u·U + v·V with U, V orthonormal: projection recovers (u,v).
pub(super) fn plane_uv(plane: &Plane, p: DVec3) -> Vec2 {
    project(p, plane.u_axis.as_dvec3(), plane.v_axis.as_dvec3())
}

pub(super) fn project(p: DVec3, u_axis: DVec3, v_axis: DVec3) -> Vec2 {
    Vec2::new(p.dot(u_axis) as f32, p.dot(v_axis) as f32)
}
