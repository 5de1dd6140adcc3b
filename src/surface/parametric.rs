//! What a surface defines: its (u,v) domain and frame, how finely it is cut into triangles, how
//! its mesh is pushed out to cover it, and where a ray meets it exactly. Each surface implements
//! this in its own file; `Surface` dispatches to them, so adding a surface is one file (its
//! `impl Parametric`, its tests) and one arm in `Surface` and in `each_kind!`.

use super::grid_shape::GridShape;
use super::ray_hits::{Hit, Ray, Rays, TrueHit};
use super::{Domain, Frame, Frames, Mesh, Tessellation};
use glam::{DVec3, Vec2, Vec3};
use std::ops::RangeInclusive;

/// A parametric surface P(u,v) relative to its f64 anchor.
pub trait Parametric {
    /// What a person calls the kind of surface.
    fn kind(&self) -> &'static str;

    /// The world-space anchor that frames are relative to.
    fn origin(&self) -> DVec3;

    /// The anchor, to move the surface by.
    fn origin_mut(&mut self) -> &mut DVec3;

    /// The rectangle of (u,v) the surface is defined on.
    fn domain(&self) -> Domain;

    /// The exact frame at (u,v).
    fn frame(&self, u: f32, v: f32) -> Frame;

    /// The exact frames at `uv(0) … uv(count − 1)`, appended to `out`: indexed rather than an
    /// iterator, so the loop inlines the same way in every build.
    #[inline]
    fn frames(&self, count: usize, uv: impl Fn(usize) -> Vec2, out: &mut Frames) {
        out.extend((0..count).map(|k| {
            let uv = uv(k);
            self.frame(uv.x, uv.y)
        }));
    }

    /// Whether Pu, Pv and n are the same at every (u,v) (only the point varies).
    fn is_flat(&self) -> bool {
        false
    }

    /// Whether the rasterizer's triangles are the surface itself, so its fragments lie on it.
    fn is_its_own_mesh(&self) -> bool {
        self.is_flat()
    }

    /// The largest normal curvature anywhere on the surface, 1/length: how far it can bend from
    /// a tangent plane (by about κ·d²/2 at distance d).
    fn max_curvature(&self) -> f32;

    /// For a surface that closes a volume: whether the eye (relative to the anchor) is outside
    /// it, so back faces may be culled. `None` for an open surface.
    fn encloses_eye_at(&self, _eye_from_anchor: DVec3) -> Option<bool> {
        None
    }

    /// Grid resolution and collapsed rows at a tessellation density (`density` cells per π
    /// radians of turning).
    fn grid_shape(&self, density: u32) -> GridShape;

    /// The rasterizer's triangles where they are not a (u,v) grid (`grid_shape`).
    fn own_mesh(&self) -> Option<Mesh> {
        None
    }

    /// The triangles the mesh has, counted without making them.
    fn triangle_count(&self, tessellation: Tessellation) -> u64 {
        self.grid_shape(tessellation.density.max(1))
            .triangle_count()
    }

    /// The direction a mesh vertex at `uv` (with the surface's `frame` there) moves so that the
    /// mesh's chords lie on the convex side of the surface and past its boundary: zero for
    /// surfaces whose meshes are exact.
    fn hull_outwards(&self, _uv: Vec2, _frame: &Frame) -> Vec3 {
        Vec3::ZERO
    }

    /// The nearest intersection of the ray (relative to the anchor) with the exact surface, for
    /// t in `range`, with the exact (u,v) there.
    fn intersect(&self, ray: &Ray, range: &RangeInclusive<f64>) -> Option<Hit>;

    /// The (u,v) of a point on the surface (relative to its anchor): the inverse of `frame`.
    fn uv_at(&self, p: DVec3) -> Vec2;

    /// Where each of `rays` meets the true surface, into `hits` where `found` is set: by
    /// default its first hit in front of the eye (see `Surface::true_hits`).
    fn true_hits(&self, rays: &Rays, hits: &mut [TrueHit], found: &mut [bool]) {
        for k in 0..rays.directions.len() {
            let ray = Ray {
                origin: rays.eye,
                direction: rays.directions[k],
            };
            let hit = self.intersect(&ray, &(f64::MIN_POSITIVE..=f64::INFINITY));
            let hit = hit.filter(|hit| hit.uv.is_finite());
            found[k] = hit.is_some();
            hits[k] = hit.map_or(TrueHit::default(), |hit| TrueHit {
                uv: hit.uv,
                depth: hit.t as f32,
            });
        }
    }
}
