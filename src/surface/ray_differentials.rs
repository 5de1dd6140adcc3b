//! Ray differentials: the exact screen-space derivatives of (u,v) at a hit.

use super::{Domain, Frame};
use glam::{Vec2, Vec3};

/// ∂(u,v)/∂x and ∂(u,v)/∂y at a hit, analytically, from ray differentials (Igehy 1999): moving
/// one pixel changes the direction D by dD, and the hit point slides on the tangent plane by
/// dP = t·(dD − D·(n·dD)/(n·D)); (u,v) follow through the dual basis of (Pu, Pv). This is what
/// the rasterizer's perspective-correct planes compute for a flat triangle.
///
/// Where it has no finite answer (a pole, where Pu vanishes, or a ray grazing the surface) each
/// component is clamped to the domain's extent: the texture footprint is then the whole domain,
/// the honest answer for a pixel that sees all of it. f32: the derivatives pick mip levels and
/// filter footprints, where a relative error of 1e-6 is far below what a level step shows.
#[inline(always)]
pub fn uv_derivatives(
    frame: &Frame,
    t: f32,
    direction: Vec3,
    per_pixel: Vec3,
    domain: Domain,
) -> Vec2 {
    let n = frame.n;
    let slide = (per_pixel - direction * (n.dot(per_pixel) / n.dot(direction))) * t;
    let (pu, pv) = (frame.pu, frame.pv);
    let area = pu.cross(pv).dot(n);
    let du = slide.dot(pv.cross(n)) / area;
    let dv = slide.dot(n.cross(pu)) / area;
    let extent = (domain.max - domain.min).abs();
    // Selects rather than `f32::clamp` (which checks its bounds), so batches vectorise.
    let clamp = |d: f32, limit: f32| {
        if d.is_nan() {
            limit
        } else {
            d.max(-limit).min(limit)
        }
    };
    Vec2::new(clamp(du, extent.x), clamp(dv, extent.y))
}
