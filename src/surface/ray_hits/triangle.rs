//! Exact ray–triangle intersection within the triangle's (u,v) corners.

use super::plane::{flat_hit, project};
use super::ray::{Hit, Ray, nearest_hit};
use crate::surface::Triangle;
use glam::{DVec2, DVec3, Vec2};
use std::ops::RangeInclusive;

pub(super) fn intersect_triangle(
    triangle: &Triangle,
    ray: &Ray,
    range: &RangeInclusive<f64>,
) -> Option<Hit> {
    let t = flat_hit(triangle.normal.as_dvec3(), ray)?;
    nearest_hit([t, f64::NAN], range, |t| {
        let uv = triangle_uv(triangle, ray.at(t));
        contains(triangle.corners_uv, uv).then_some(uv)
    })
}

pub(super) fn triangle_uv(triangle: &Triangle, p: DVec3) -> Vec2 {
    project(p, triangle.u_axis.as_dvec3(), triangle.v_axis.as_dvec3())
}

/// Inside or on the boundary of the triangle in (u,v), whichever way it winds.
fn contains(corners: [Vec2; 3], uv: Vec2) -> bool {
    let [a, b, c] = corners.map(|c| c.as_dvec2());
    let p = uv.as_dvec2();
    let edge = |from: DVec2, to: DVec2| (to - from).perp_dot(p - from);
    let signs = [edge(a, b), edge(b, c), edge(c, a)];
    signs.iter().all(|&s| s >= 0.0) || signs.iter().all(|&s| s <= 0.0)
}
