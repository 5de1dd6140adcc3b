//! Shading at the true surface point: each fragment of a curved surface is moved along its own
//! ray from its triangle (the chord) to the surface the triangle stands for, so patterns,
//! textures, bumps and lights see the (u,v) the surface has there, not the chord's. With exact
//! coverage (`exact_coverage`) the fragment may move to another surface, or to none.

use super::exact_coverage::{Neighbours, cast_dropped, nearer_neighbours};
use super::exact_hits::{DerivativeScratch, ExactScratch, true_hits_along};
use super::frame_object::FrameObject;
use crate::raster::{Fragment, SampleRays};
use crate::surface::{Frames, Surface, uv_derivatives};
use glam::Vec2;

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
    /// With exact coverage: fragments whose ray meets another object's true surface first.
    pub reassigned: usize,
    /// With exact coverage: fragments whose ray meets no true surface at all.
    pub background: usize,
}

/// Moves each fragment of a curved surface, in place, to its ray's true hit: (u,v) and depth,
/// marking it in `scratch.moved` (its (u,v) derivatives are then the mesh's until
/// `true_hit_derivatives` works them out). With `coverage`, a fragment whose ray misses its own
/// true surface is cast against every object (and becomes the nearest one's, or background:
/// object `objects.len()`), and one whose ray meets a neighbour's true surface first becomes
/// that neighbour's.
pub fn exact_fragments(
    objects: &[FrameObject],
    coverage: Option<&Neighbours>,
    rays: &SampleRays,
    fragments: &mut [Fragment],
    scratch: &mut ExactScratch,
) -> ExactPoints {
    let mut count = ExactPoints::default();
    for flags in [&mut scratch.moved, &mut scratch.pending] {
        flags.clear();
        flags.resize(fragments.len(), false);
    }
    // Each run is measured before any of its fragments moves; moving touches only the run.
    let mut start = 0;
    while start < fragments.len() {
        let end = run_end(fragments, start);
        let index = fragments[start].object;
        let object = &objects[index as usize];
        let surface = &object.prepared.surface;
        if !surface.is_its_own_mesh() {
            let moved = move_run(object, rays, &mut fragments[start..end], scratch);
            count.moved += moved;
            for (k, &found) in (start..end).zip(&scratch.found) {
                scratch.moved[k] = found;
                scratch.pending[k] = !found;
            }
        }
        if let Some(neighbours) = coverage {
            let run = start..end;
            let nearer =
                nearer_neighbours(objects, neighbours, index, rays, fragments, run, scratch);
            count.reassigned += nearer;
        }
        start = end;
    }
    match coverage {
        Some(_) => {
            let (reassigned, background) = cast_dropped(objects, rays, fragments, scratch);
            count.reassigned += reassigned;
            count.background += background;
        }
        None => count.kept = scratch.pending.iter().filter(|&&p| p).count(),
    }
    count
}

/// Moves one object's run of fragments to its true surface where their rays meet it (marked in
/// `scratch.found`); how many moved.
fn move_run(
    object: &FrameObject,
    rays: &SampleRays,
    run: &mut [Fragment],
    scratch: &mut ExactScratch,
) -> usize {
    let surface = &object.prepared.surface;
    true_hits_along(surface, object.eye, rays, run.iter(), scratch);
    let mut moved = 0;
    for ((fragment, hit), &found) in run.iter_mut().zip(&scratch.hits).zip(&scratch.found) {
        if found {
            fragment.uv = hit.uv;
            fragment.depth = hit.depth;
            moved += 1;
        }
    }
    moved
}

/// The (u,v) derivatives of each fragment of `group` (one object's, by index into `fragments`)
/// that `moved` marks, from ray differentials at its true hit, whose frame is `frames` (by
/// position in the group), as the reference computes them.
pub(super) fn true_hit_derivatives(
    surface: &Surface,
    rays: &SampleRays,
    fragments: &mut [Fragment],
    group: &[u32],
    frames: &Frames,
    moved: &[bool],
    scratch: &mut DerivativeScratch,
) {
    // Nothing moved (a plane's fragments, unless recast onto it): nothing to work out.
    if !group.iter().any(|&i| moved[i as usize]) {
        return;
    }
    let (dx, dy) = (
        rays.per_pixel_x * rays.footprint,
        rays.per_pixel_y * rays.footprint,
    );
    let domain = surface.domain();
    let rays_and_depths = group.iter().map(|&i| {
        let fragment = &fragments[i as usize];
        (rays.through(fragment.x, fragment.y), fragment.depth)
    });
    scratch.rays.clear();
    scratch.rays.extend(rays_and_depths);
    scratch
        .derivatives
        .resize(group.len(), (Vec2::ZERO, Vec2::ZERO));
    crate::simd::widest(
        #[inline(always)]
        || {
            let frames = frames.slices();
            let n = frames.len;
            let (rays, out) = (&scratch.rays[..n], &mut scratch.derivatives[..n]);
            for k in 0..n {
                let (frame, (direction, t)) = (frames.at(k), rays[k]);
                out[k] = (
                    uv_derivatives(&frame, t, direction, dx, domain),
                    uv_derivatives(&frame, t, direction, dy, domain),
                );
            }
        },
    );
    for (&i, &(du, dv)) in group.iter().zip(&scratch.derivatives) {
        if moved[i as usize] {
            let fragment = &mut fragments[i as usize];
            (fragment.duv_dx, fragment.duv_dy) = (du, dv);
        }
    }
}

/// Where the run of consecutive fragments of one object that begins at `start` ends (a tile's
/// fragments come in runs of one triangle).
fn run_end(fragments: &[Fragment], start: usize) -> usize {
    let object = fragments[start].object;
    let length = fragments[start..]
        .iter()
        .take_while(|f| f.object == object)
        .count();
    start + length
}
