//! The true surface hits along a batch of fragments' rays, and the working arrays exact
//! shading reuses from batch to batch.

use crate::raster::{Fragment, SampleRays};
use crate::surface::{Surface, TrueHit};
use glam::{DVec3, Vec2, Vec3};

/// Working arrays for `exact_fragments`, reused batch to batch.
#[derive(Default)]
pub struct ExactScratch {
    pub(super) depths: Vec<f32>,
    pub(super) directions: Vec<DVec3>,
    pub(super) hits: Vec<TrueHit>,
    pub(super) found: Vec<bool>,
    /// By fragment of the batch: whether it moved (its derivatives are then recomputed).
    pub(super) moved: Vec<bool>,
    /// By fragment: its ray missed its own true surface (cast against every object, with
    /// exact coverage).
    pub(super) pending: Vec<bool>,
    /// Fragments of a run tested against one neighbour.
    pub(super) candidates: Vec<usize>,
    pub(super) derivatives: DerivativeScratch,
}

/// Working arrays for `true_hit_derivatives`, reused group to group.
#[derive(Default)]
pub(super) struct DerivativeScratch {
    pub(super) rays: Vec<(Vec3, f32)>,
    pub(super) derivatives: Vec<(Vec2, Vec2)>,
}

/// `surface`'s true hits along the rays of `run`'s fragments, near their depths, into
/// `scratch.hits` and `scratch.found`.
pub(super) fn true_hits_along<'f>(
    surface: &Surface,
    eye: DVec3,
    rays: &SampleRays,
    run: impl ExactSizeIterator<Item = &'f Fragment> + Clone,
    scratch: &mut ExactScratch,
) {
    let count = run.len();
    let ExactScratch {
        depths,
        directions,
        hits,
        found,
        ..
    } = scratch;
    directions.clear();
    directions.extend(run.clone().map(|f| rays.exact_through(f.x, f.y)));
    depths.clear();
    depths.extend(run.map(|f| f.depth));
    hits.resize(count, TrueHit::default());
    found.resize(count, false);
    surface.true_hits(eye, directions, depths, hits, found);
}
