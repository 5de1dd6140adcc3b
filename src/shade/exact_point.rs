//! Shading at the true surface point: each fragment of a curved surface is moved along its own
//! ray from its triangle (the chord) to the surface the triangle stands for, so patterns,
//! textures, bumps and lights see the (u,v) the surface has there, not the chord's.

use crate::raster::{Fragment, FrameObject, SampleRays};
use crate::surface::{Frame, Surface, TrueHit, uv_derivatives};
use glam::Vec3;

/// Where a fragment of a curved surface is shaded.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SurfacePointSource {
    /// At the (u,v) interpolated across its triangle: a point on the chord's own ray, but on
    /// the chord, so up to a cell's curvature away from the surface.
    #[default]
    Interpolated,
    /// Where the fragment's ray meets the true surface nearest its triangle.
    Exact,
}

/// What moving fragments to their true surface did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExactPoints {
    /// Fragments of curved surfaces moved to the true surface.
    pub moved: usize,
    /// Fragments of curved surfaces that kept their tessellated (u,v): the ray missed the true
    /// surface near its triangle (past a rim), or the wave's Newton steps did not settle.
    pub kept: usize,
}

/// Working arrays for `exact_fragments`, reused batch to batch.
#[derive(Default)]
pub struct ExactScratch {
    pub fragments: Vec<Fragment>,
    depths: Vec<f32>,
    directions: Vec<Vec3>,
    hits: Vec<TrueHit>,
    found: Vec<bool>,
    frames: Vec<Frame>,
}

/// `fragments` with each curved surface's (u,v), depth and (where `derivatives` says the shader
/// reads them, by object) (u,v) derivatives taken at its ray's true hit, into
/// `scratch.fragments`.
pub fn exact_fragments(
    objects: &[FrameObject],
    derivatives: impl Fn(&FrameObject) -> bool,
    rays: &SampleRays,
    fragments: &[Fragment],
    scratch: &mut ExactScratch,
) -> ExactPoints {
    let mut out = std::mem::take(&mut scratch.fragments);
    out.clear();
    out.extend_from_slice(fragments);
    let mut count = ExactPoints::default();
    let mut rest = &mut out[..];
    while let Some(first) = rest.first() {
        let index = first.object;
        let length = rest.iter().take_while(|f| f.object == index).count();
        let (run, after) = rest.split_at_mut(length);
        let object = &objects[index as usize];
        let surface = &object.prepared.surface;
        if !surface.is_flat() {
            let moved = move_run(surface, object.origin, rays, run, scratch);
            count.moved += moved;
            count.kept += run.len() - moved;
            if derivatives(object) {
                exact_derivatives(surface, run, rays, &mut scratch.frames);
            }
        }
        rest = after;
    }
    scratch.fragments = out;
    count
}

/// Moves one object's run of fragments to its true surface; how many moved.
fn move_run(
    surface: &Surface,
    origin: Vec3,
    rays: &SampleRays,
    run: &mut [Fragment],
    scratch: &mut ExactScratch,
) -> usize {
    let ExactScratch {
        depths,
        directions,
        hits,
        found,
        ..
    } = scratch;
    directions.clear();
    directions.extend(run.iter().map(|f| rays.through(f.x, f.y)));
    depths.clear();
    depths.extend(run.iter().map(|f| f.depth));
    hits.resize(run.len(), TrueHit::default());
    found.resize(run.len(), false);
    surface.true_hits(-origin, directions, depths, hits, found);
    let mut moved = 0;
    for ((fragment, hit), &found) in run.iter_mut().zip(hits.iter()).zip(found.iter()) {
        if found {
            fragment.uv = hit.uv;
            fragment.depth = hit.depth;
            moved += 1;
        }
    }
    moved
}

/// The (u,v) derivatives of each fragment from ray differentials at its (u,v), which are now
/// the true surface's, as the reference computes them.
fn exact_derivatives(
    surface: &Surface,
    run: &mut [Fragment],
    rays: &SampleRays,
    frames: &mut Vec<Frame>,
) {
    frames.clear();
    surface.frames(run.len(), |k| run[k].uv, frames);
    let domain = surface.domain();
    let (dx, dy) = (
        rays.per_pixel_x * rays.footprint,
        rays.per_pixel_y * rays.footprint,
    );
    crate::simd::widest(
        #[inline(always)]
        || {
            for (fragment, frame) in run.iter_mut().zip(frames.iter()) {
                let direction = rays.through(fragment.x, fragment.y);
                let t = fragment.depth;
                fragment.duv_dx = uv_derivatives(frame, t, direction, dx, domain);
                fragment.duv_dy = uv_derivatives(frame, t, direction, dy, domain);
            }
        },
    );
}
