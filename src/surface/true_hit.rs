//! Where a view ray meets the true surface near the point where it meets the tessellation.
//!
//! A fragment's ray crosses its triangle at the chord point; the true surface lies a chord
//! error away along the same ray. The quadrics (sphere, cone, paraboloid) are solved in closed
//! form around the chord point, the wave by safeguarded Newton steps from it; the others (flat
//! surfaces, models, the torus) take their exact first hit from the eye.
//!
//! Numerics: the rays are f64 and the quadratics are formed and solved in f64 around the chord
//! point, so their constant term (how far the chord point is from the surface) keeps its digits
//! when the surface is large; the angles of the (u,v) are f32 (`atan2`, within 3e-7 rad).

use super::ray_hits::{Rays, TrueHit, ordered_roots};
use super::{Surface, parametric::Parametric};
use glam::{DVec3, Vec2, Vec3};

/// Fragments whose hits are computed together, in plain arrays the compiler turns into SIMD.
const CHUNK: usize = 64;

impl Surface {
    /// Where the ray `eye + t·direction` (relative to the surface's anchor), which meets the
    /// surface's tessellation at t = `depth`, meets the true surface: the first hit in front of
    /// the eye for the quadrics and flat surfaces (as the reference sees it), the hit the Newton
    /// steps reach from the tessellation's point for the wave. `None` where the ray misses the
    /// true surface, and where the wave's steps do not settle.
    pub fn true_hit(&self, eye: DVec3, direction: DVec3, depth: f32) -> Option<TrueHit> {
        let (mut hit, mut found) = ([TrueHit::default()], [false]);
        self.true_hits(eye, &[direction], &[depth], &mut hit, &mut found);
        found[0].then_some(hit[0])
    }

    /// `true_hit` of each (direction, depth) pair from one eye, into `hits` where `found` is set.
    pub fn true_hits(
        &self,
        eye: DVec3,
        directions: &[DVec3],
        depths: &[f32],
        hits: &mut [TrueHit],
        found: &mut [bool],
    ) {
        let n = directions.len();
        assert!(depths.len() == n && hits.len() == n && found.len() == n);
        let rays = Rays {
            eye,
            directions,
            depths,
        };
        each_kind!(self, s => s.true_hits(&rays, hits, found));
    }
}

/// A surface that is a quadratic along any ray: its coordinates, the quadratic's coefficients,
/// which points of the quadric are the surface, and the (u,v) of a point on it.
pub(super) trait Quadric {
    fn local(&self, v: DVec3) -> DVec3;
    fn coefficients(&self, q: DVec3, d: DVec3) -> [f64; 3];
    fn contains(&self, _p: DVec3) -> bool {
        true
    }
    fn uv(&self, p: Vec3) -> Vec2;
}

/// The first usable root of each ray's quadratic, solved around its chord point.
pub(super) fn quadric_hits<Q: Quadric>(
    quadric: &Q,
    rays: &Rays,
    hits: &mut [TrueHit],
    found: &mut [bool],
) {
    let eye = quadric.local(rays.eye);
    let chunks = rays.directions.chunks(CHUNK).zip(rays.depths.chunks(CHUNK));
    let outputs = hits.chunks_mut(CHUNK).zip(found.chunks_mut(CHUNK));
    for ((directions, depths), (hits, found)) in chunks.zip(outputs) {
        crate::simd::widest(
            #[inline(always)]
            || quadric_chunk(quadric, eye, directions, depths, hits, found),
        );
    }
}

/// One chunk, branch-free so that it vectorises. The quadratic is in s from the chord point
/// q (t = depth + s), so its constant term is the chord point's small distance from the surface.
#[inline(always)]
fn quadric_chunk<Q: Quadric>(
    quadric: &Q,
    eye: DVec3,
    directions: &[DVec3],
    depths: &[f32],
    hits: &mut [TrueHit],
    found: &mut [bool],
) {
    let n = directions
        .len()
        .min(depths.len())
        .min(hits.len())
        .min(found.len());
    for k in 0..n {
        let d = quadric.local(directions[k]);
        let depth = depths[k] as f64;
        let q = eye + d * depth;
        let [a, b, c] = quadric.coefficients(q, d);
        let (first, second, real) = ordered_roots(a, b, c);
        let usable =
            |s: f64| real & s.is_finite() & (depth + s > 0.0) & quadric.contains(q + d * s);
        let (first_usable, second_usable) = (usable(first), usable(second));
        let s = if first_usable { first } else { second };
        let s = if first_usable | second_usable { s } else { 0.0 };
        hits[k] = TrueHit {
            uv: quadric.uv((q + d * s).as_vec3()),
            depth: (depth + s) as f32,
        };
        found[k] = first_usable | second_usable;
    }
}
