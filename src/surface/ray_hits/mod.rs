//! Exact intersection of a ray with any surface, and the inverse of its parametrisation, in f64
//! relative to the surface's anchor (so a scene translated by 1e6 loses nothing): the
//! reference renders with them, and exact coverage resolves the pixels a mesh cannot. Each
//! surface solves its own (`Parametric::intersect`); the root finders they share live here.

mod flat;
mod polynomial;
mod quadratic;
mod ray;
mod root;
mod sine_sheet;

pub use flat::{flat_hit, project};
pub use polynomial::polynomial_roots_in;
pub(crate) use quadratic::ordered_roots;
pub use quadratic::quadratic_roots;
pub use ray::{Hit, Ray, Rays, TrueHit, nearest_hit};
pub use sine_sheet::SineSheet;

use super::Surface;
use super::parametric::Parametric;
use glam::{DVec3, Vec2};
use std::ops::RangeInclusive;

/// The nearest intersection of the ray (relative to the surface's anchor) with the exact surface,
/// for t in `range`, with the exact (u,v) there.
pub fn intersect(surface: &Surface, ray: &Ray, range: RangeInclusive<f64>) -> Option<Hit> {
    let hit = each_kind!(surface, s => s.intersect(ray, &range))?;
    hit.uv.is_finite().then_some(hit)
}

/// The (u,v) of a point on the surface (relative to its anchor): the inverse of `Surface::frame`.
pub fn surface_uv(surface: &Surface, p: DVec3) -> Vec2 {
    each_kind!(surface, s => s.uv_at(p))
}
