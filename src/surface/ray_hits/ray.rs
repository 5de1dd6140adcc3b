//! A ray relative to a surface's anchor and the hit it finds; a fragment's rays and the true
//! surface points they reach.

use glam::{DVec3, Vec2};
use std::ops::RangeInclusive;

/// A ray relative to a surface's anchor: points origin + t·direction for t in a range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    pub origin: DVec3,
    /// Not normalised: the caster scales it so that t is the view depth.
    pub direction: DVec3,
}

impl Ray {
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.direction * t
    }
}

/// The nearest intersection in a range: its ray parameter and the exact surface (u,v) there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub t: f64,
    pub uv: Vec2,
}

/// The true surface's point along a fragment's ray.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TrueHit {
    /// The surface's (u,v) there.
    pub uv: Vec2,
    /// The ray parameter there: the hit is `eye + depth·direction`.
    pub depth: f32,
}

/// Rays from one eye (relative to a surface's anchor), each with the parameter where it meets
/// the surface's tessellation.
#[derive(Clone, Copy)]
pub struct Rays<'a> {
    pub eye: DVec3,
    pub directions: &'a [DVec3],
    pub depths: &'a [f32],
}

impl Rays<'_> {
    /// Where ray `k` meets the tessellation.
    #[inline(always)]
    pub fn chord(&self, k: usize) -> DVec3 {
        self.eye + self.directions[k] * self.depths[k] as f64
    }
}

/// The first of `candidates` (at most two, any order) inside `range` that `accept` keeps, as a
/// hit. No allocation: exact coverage calls this for pixels as they are shaded.
pub fn nearest_hit(
    candidates: [f64; 2],
    range: &RangeInclusive<f64>,
    mut accept: impl FnMut(f64) -> Option<Vec2>,
) -> Option<Hit> {
    let [a, b] = candidates;
    let in_order = if b < a { [b, a] } else { [a, b] };
    in_order
        .into_iter()
        .filter(|t| range.contains(t))
        .find_map(|t| accept(t).map(|uv| Hit { t, uv }))
}
