//! Ray differentials: the exact screen-space derivatives of (u,v) at a hit.

use crate::surface::{Domain, Frame};
use glam::{DVec3, Vec2};

/// ∂(u,v)/∂x and ∂(u,v)/∂y at a hit, analytically, from ray differentials (Igehy 1999): moving
/// one pixel changes the direction D by dD, and the hit point slides on the tangent plane by
/// dP = t·(dD − D·(n·dD)/(n·D)); (u,v) follow through the dual basis of (Pu, Pv). This is what
/// the rasterizer's perspective-correct planes compute for a flat triangle.
///
/// Where it has no finite answer (a pole, where Pu vanishes, or a ray grazing the surface) each
/// component is clamped to the domain's extent: the texture footprint is then the whole domain,
/// the honest answer for a pixel that sees all of it.
pub fn uv_derivatives(
    frame: &Frame,
    t: f64,
    direction: DVec3,
    per_pixel: DVec3,
    domain: Domain,
) -> Vec2 {
    let n = frame.n.as_dvec3();
    let slide = (per_pixel - direction * (n.dot(per_pixel) / n.dot(direction))) * t;
    let (pu, pv) = (frame.pu.as_dvec3(), frame.pv.as_dvec3());
    let area = pu.cross(pv).dot(n);
    let du = slide.dot(pv.cross(n)) / area;
    let dv = slide.dot(n.cross(pu)) / area;
    let extent = (domain.max - domain.min).abs().as_dvec2();
    let clamp = |d: f64, limit: f64| {
        if d.is_nan() {
            limit
        } else {
            d.clamp(-limit, limit)
        }
    };
    Vec2::new(clamp(du, extent.x) as f32, clamp(dv, extent.y) as f32)
}
