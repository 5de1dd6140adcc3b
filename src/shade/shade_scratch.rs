//! A shading thread's working memory, reused for every batch: the arrays each stage of the
//! scene's fragment program (colour, bump, lighting) reads and writes.

use super::exact_hits::ExactScratch;
use super::pattern_batch::PatternBatch;
use crate::raster::Fragment;
use crate::surface::Frames;
use crate::texture::{Footprint, HeightSample, Texel};
use glam::{Mat2, Vec2, Vec3};

/// Per-thread working memory, reused for every batch.
#[derive(Default)]
pub struct ShadeScratch {
    /// The batch's fragments moved to their true surfaces (`SurfacePointSource::Exact`).
    pub(super) exact: ExactScratch,
    /// Fragment indices grouped by object.
    pub(super) order: Vec<u32>,
    pub(super) group_starts: Vec<usize>,
    pub(super) frames: Frames,
    pub(super) colors: Vec<Vec3>,
    /// Camera-relative positions (for shadows and lighting), facing normals to light, and the
    /// lit colours.
    pub(super) points: Vec<Vec3>,
    pub(super) normals: Vec<Vec3>,
    pub(super) lit: Vec<Vec3>,
    /// Per light, per fragment, the fraction of the light reaching it; empty without shadows.
    pub(super) reach: Vec<f32>,
    /// The fragments' facing geometric normals, for shadows.
    pub(super) shadow_normals: Vec<Vec3>,
    pub(super) heights: Vec<f32>,
    pub(super) gradients: Vec<Vec2>,
    pub(super) patterns: PatternBatch,
    pub(super) texture: TextureBatch,
    pub(super) height_lookups: HeightLookups,
    /// Inputs and outputs of shifted height evaluations (central differences, the seed lattice).
    pub(super) shifted: Shifted,
}

/// A batch's image lookups: texture coordinates, footprints (when the filter reads them) and
/// the texels.
#[derive(Default)]
pub(super) struct TextureBatch {
    pub(super) st: Vec<Vec2>,
    pub(super) footprints: Vec<Footprint>,
    pub(super) texels: Vec<Texel>,
}

/// A batch's bump-map lookups: texture coordinates, footprints, the mapping's Jacobians and
/// the samples.
#[derive(Default)]
pub(super) struct HeightLookups {
    pub(super) st: Vec<Vec2>,
    pub(super) footprints: Vec<Footprint>,
    pub(super) jacobians: Vec<Mat2>,
    pub(super) samples: Vec<HeightSample>,
}

#[derive(Default)]
pub(super) struct Shifted {
    pub(super) fragments: Vec<Fragment>,
    pub(super) identity: Vec<u32>,
    pub(super) frames: Frames,
    pub(super) heights: Vec<f32>,
    pub(super) gradients: Vec<Vec2>,
    /// Heights at +u, −u, +v, −v.
    pub(super) around: [Vec<f32>; 4],
}
