//! Exact intersection of a ray with any surface, and the inverse of its parametrisation, in f64
//! relative to the surface's anchor (so a scene translated by 1e6 loses nothing): the
//! reference renders with them, and exact coverage resolves the pixels a mesh cannot.

mod cone;
mod paraboloid;
mod plane;
mod quadratic;
mod ray;
mod root;
mod sphere;
mod triangle;
mod wave;

pub(crate) use quadratic::ordered_roots;
pub use ray::{Hit, Ray};

use crate::surface::Surface;
use cone::{cone_uv, intersect_cone};
use glam::{DVec3, Vec2};
use paraboloid::{intersect_paraboloid, paraboloid_uv};
use plane::{intersect_plane, plane_uv};
use sphere::{intersect_sphere, sphere_uv};
use std::ops::RangeInclusive;
use triangle::{intersect_triangle, triangle_uv};
use wave::{intersect_wave, wave_uv};

/// The nearest intersection of the ray (relative to the surface's anchor) with the exact surface,
/// for t in `range`, with the exact (u,v) there.
pub fn intersect(surface: &Surface, ray: &Ray, range: RangeInclusive<f64>) -> Option<Hit> {
    let hit = match surface {
        Surface::Plane(s) => intersect_plane(s, ray, &range),
        Surface::Sphere(s) => intersect_sphere(s, ray, &range),
        Surface::Paraboloid(s) => intersect_paraboloid(s, ray, &range),
        Surface::Cone(s) => intersect_cone(s, ray, &range),
        Surface::Wave(s) => intersect_wave(s, ray, &range),
        Surface::Triangle(s) => intersect_triangle(s, ray, &range),
    }?;
    hit.uv.is_finite().then_some(hit)
}

/// The (u,v) of a point on the surface (relative to its anchor): the inverse of `Surface::frame`.
pub fn surface_uv(surface: &Surface, p: DVec3) -> Vec2 {
    match surface {
        Surface::Plane(s) => plane_uv(s, p),
        Surface::Sphere(_) => sphere_uv(p),
        Surface::Paraboloid(s) => paraboloid_uv(s, p),
        Surface::Cone(s) => cone_uv(s, p),
        Surface::Wave(_) => wave_uv(p),
        Surface::Triangle(s) => triangle_uv(s, p),
    }
}
