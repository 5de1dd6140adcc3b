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
        Surface::Model(s) => intersect_model(s, ray, &range),
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
        Surface::Model(s) => model_uv(s, p),
    }
}

/// The nearest hit of the ray with the model's triangles, in its chart's (u,v).
fn intersect_model(
    model: &crate::surface::ModelSurface,
    ray: &Ray,
    range: &RangeInclusive<f64>,
) -> Option<Hit> {
    let data = &*model.data;
    let hit = data
        .bvh
        .intersect(&data.corners, ray.origin, ray.direction, range)?;
    Some(Hit {
        t: hit.t,
        uv: data.chart_uv(hit.triangle, hit.a as f32, hit.b as f32),
    })
}

/// The chart (u,v) of the model's point nearest `p`: a point alone does not name its triangle,
/// so every triangle is tried (for tests and tools, not for rendering).
fn model_uv(model: &crate::surface::ModelSurface, p: DVec3) -> Vec2 {
    let data = &*model.data;
    let nearest = (0..model.triangle_count())
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| data.triangle(t)[k].p.as_dvec3());
            let (weights, distance) = closest_on_triangle(p, a, b, c);
            (distance, t, weights)
        })
        .min_by(|x, y| x.0.total_cmp(&y.0));
    nearest.map_or(Vec2::NAN, |(_, t, (wb, wc))| {
        data.chart_uv(t, wb as f32, wc as f32)
    })
}

/// The weights of b and c at the point of triangle abc nearest `p`, and its distance.
fn closest_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> ((f64, f64), f64) {
    let (e1, e2) = (b - a, c - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (r1, r2) = ((p - a).dot(e1), (p - a).dot(e2));
    let det = d11 * d22 - d12 * d12;
    let (mut wb, mut wc) = if det > 0.0 {
        ((d22 * r1 - d12 * r2) / det, (d11 * r2 - d12 * r1) / det)
    } else {
        (0.0, 0.0)
    };
    // Outside: the nearest point is on an edge; clamping the weights is close enough for a
    // point that lies on the model, which is what this is asked of.
    wb = wb.clamp(0.0, 1.0);
    wc = wc.clamp(0.0, 1.0 - wb);
    let q = a + e1 * wb + e2 * wc;
    ((wb, wc), q.distance(p))
}
