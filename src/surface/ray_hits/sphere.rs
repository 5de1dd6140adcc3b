//! Exact ray–sphere intersection and the sphere's (u,v) at the hit, in the seed's units.

use super::quadratic::quadratic_roots;
use super::ray::{Hit, Ray, nearest_hit};
use crate::surface::Sphere;
use glam::{DVec3, Vec2};
use std::f64::consts::PI;
use std::ops::RangeInclusive;

/// Seed units per radian (the surface module's constant, in f64).
const UNITS_PER_RADIAN: f64 = 360.0 / PI;

pub(super) fn intersect_sphere(
    sphere: &Sphere,
    ray: &Ray,
    range: &RangeInclusive<f64>,
) -> Option<Hit> {
    let r = sphere.radius as f64;
    let (o, d) = (ray.origin, ray.direction);
    let roots = quadratic_roots(d.dot(d), 2.0 * o.dot(d), o.dot(o) - r * r);
    nearest_hit(roots, range, |t| Some(sphere_uv(ray.at(t))))
}

/// u from the azimuth (φ = atan2(x, z), u = (φ + π/2)·360/π in [0, 720)), v from the polar angle
/// (acos(y/r)·360/π), as the seed computes them.
pub(super) fn sphere_uv(p: DVec3) -> Vec2 {
    let n = p.normalize_or(DVec3::Y);
    let v = n.y.clamp(-1.0, 1.0).acos() * UNITS_PER_RADIAN;
    Vec2::new(azimuth_u(n.x, n.z), v as f32)
}

/// The seed's u of a direction whose components along the azimuth's sine and cosine axes are
/// (x, z): u = (atan2(x, z) + π/2)·360/π, wrapped into [0, 720).
pub(super) fn azimuth_u(x: f64, z: f64) -> f32 {
    let u = ((x.atan2(z) + PI / 2.0) * UNITS_PER_RADIAN).rem_euclid(720.0);
    // rem_euclid can round up to exactly 720 for a tiny negative input.
    (u as f32).min(720.0f32.next_down())
}
