//! A frame's screen triangles: every object's triangles transformed, culled, clipped and set
//! up, in submission order, in parallel pieces joined in order.

use super::clip::{ClipVertex, clip_triangle, inside_clip_volume};
use super::interpolation::Interpolation;
use super::placed_mesh::PlacedMesh;
use super::render_target::RenderTarget;
use super::setup::{
    PlacedTriangle, ScreenTriangle, ShiftSpan, TrianglePlanes, Viewport, snap_vertex,
};
use crate::surface::Mesh;
use glam::{Mat4, Vec3, Vec4};
use rayon::prelude::*;

/// Transforms, culls, clips and sets up every triangle of the scene, in submission order.
pub fn screen_triangles(objects: &[impl PlacedMesh], target: &RenderTarget) -> Vec<ScreenTriangle> {
    shifted_screen_triangles(objects, target, &ShiftSpan::NONE)
}

/// `screen_triangles` for passes whose sample points are shifted within `span` (see
/// `ScreenTriangle::new`).
pub(super) fn shifted_screen_triangles(
    objects: &[impl PlacedMesh],
    target: &RenderTarget,
    span: &ShiftSpan,
) -> Vec<ScreenTriangle> {
    let view_projection = target.view_projection();
    let pieces = objects
        .iter()
        .enumerate()
        .flat_map(|(index, object)| {
            object_triangle_pieces(object, index as u32, target, view_projection, span)
        })
        .filter(|piece| !piece.is_empty())
        .collect();
    join_in_order(pieces)
}

/// The lists one after another: a lone list is moved, several are copied once into a list of
/// the exact size, on one thread: zeroing it first on every thread, so that its pages' first
/// touch was shared, cost more than it saved.
pub(super) fn join_in_order<T: Copy>(mut lists: Vec<Vec<T>>) -> Vec<T> {
    if lists.len() <= 1 {
        return lists.pop().unwrap_or_default();
    }
    let mut joined = Vec::with_capacity(lists.iter().map(Vec::len).sum());
    for list in &lists {
        joined.extend_from_slice(list);
    }
    joined
}

/// Pieces of a mesh's triangle list each thread sets up, when there are several threads.
const SETUP_PIECES_PER_THREAD: usize = 4;

/// Transforms one object's vertices and turns its triangles into screen triangles, in parallel
/// pieces that hold them in order.
fn object_triangle_pieces(
    object: &impl PlacedMesh,
    index: u32,
    target: &RenderTarget,
    view_projection: Mat4,
    span: &ShiftSpan,
) -> Vec<Vec<ScreenTriangle>> {
    let (mesh, origin) = (object.mesh(), object.origin());
    let (viewport, guard) = (target.viewport, target.viewport.guard_band());
    let (clip_positions, vertices) = mesh
        .positions
        .par_iter()
        .map(|&p| {
            let position = view_projection * (origin + p).extend(1.0);
            // Snapping rounds: a library call per value in baseline x86-64.
            let vertex = crate::simd::widest_rounding(
                #[inline(always)]
                || SetupVertex::new(position, viewport, guard),
            );
            (position, vertex)
        })
        .unzip();
    let setup = ObjectSetup {
        mesh,
        origin,
        index,
        clip_positions,
        vertices,
        cull_back_faces: object.cull_back_faces(),
        viewport,
        interpolation: target.interpolation,
        guard,
        span: *span,
    };
    // Each piece pushes straight into its own list, for the frame's pieces to be joined in order:
    // a flattening iterator moved every clipped polygon (over 200 bytes) several times.
    let pieces = match rayon::current_num_threads() {
        // On one thread one piece, whose list is then moved, not copied.
        1 => 1,
        // Several a thread: the triangles facing the camera are often one half of a mesh's
        // list (a sphere's near side), and with a piece a thread one thread set them all up.
        threads => threads * SETUP_PIECES_PER_THREAD,
    };
    mesh.indices
        .par_chunks(mesh.indices.len().div_ceil(pieces).max(1))
        .map(|piece| {
            let mut out = Vec::with_capacity(piece.len());
            crate::simd::widest(
                #[inline(always)]
                || {
                    piece
                        .iter()
                        .for_each(|triangle| setup.push(triangle, &mut out))
                },
            );
            out
        })
        .collect()
}

/// What setting up one object's triangles for a frame needs.
struct ObjectSetup<'a> {
    mesh: &'a Mesh,
    /// The mesh's anchor relative to the eye.
    origin: Vec3,
    index: u32,
    clip_positions: Vec<Vec4>,
    /// By vertex, as `clip_positions`: a vertex is shared by several triangles.
    vertices: Vec<SetupVertex>,
    cull_back_faces: bool,
    viewport: Viewport,
    interpolation: Interpolation,
    guard: f32,
    /// See `ScreenTriangle::new`.
    span: ShiftSpan,
}

/// What triangle setup reads of a vertex before clipping.
#[derive(Clone, Copy)]
struct SetupVertex {
    /// Its position snapped to the screen, where it lies in front of the eye.
    snapped: Option<(i64, i64)>,
    /// Whether it lies inside every clip plane (a triangle of three such needs no clipping).
    inside_clip_volume: bool,
}

impl SetupVertex {
    #[inline(always)]
    fn new(position: Vec4, viewport: Viewport, guard: f32) -> SetupVertex {
        SetupVertex {
            snapped: snap_vertex(position, viewport),
            inside_clip_volume: inside_clip_volume(position, guard),
        }
    }
}

impl ObjectSetup<'_> {
    /// Culls, clips and sets up the mesh triangle `corners`, pushing what is left onto `out`.
    #[inline(always)]
    fn push(&self, corners: &[u32; 3], out: &mut Vec<ScreenTriangle>) {
        let mesh = self.mesh;
        if self.cull_back_faces {
            let p = corners.map(|i| mesh.positions[i as usize]);
            let facing_away = (p[1] - p[0]).cross(p[2] - p[0]).dot(self.origin + p[0]) >= 0.0;
            if facing_away {
                return;
            }
        }
        let vertices = corners.map(|i| ClipVertex {
            position: self.clip_positions[i as usize],
            uv: mesh.uvs[i as usize],
        });
        let planes = || TrianglePlanes::new(&vertices, self.viewport, self.interpolation);
        let setup_vertices = corners.map(|i| self.vertices[i as usize]);
        if setup_vertices.iter().all(|v| v.inside_clip_volume) {
            // Placed first: many of a fine mesh's triangles reach no pixel centre, and their
            // planes would go unused.
            if let [Some(a), Some(b), Some(c)] = setup_vertices.map(|v| v.snapped)
                && let Some(placed) =
                    PlacedTriangle::from_snapped([a, b, c], self.viewport, &self.span)
                && let Some(planes) = planes()
            {
                out.push(placed.with(&planes, self.index));
            }
        } else if let (Some(polygon), Some(planes)) =
            (clip_triangle(vertices, self.guard), planes())
        {
            let v = polygon.as_slice();
            let screen = |v| ScreenTriangle::new(v, self.viewport, &planes, self.index, &self.span);
            out.extend((1..v.len() - 1).filter_map(|k| screen([v[0], v[k], v[k + 1]])));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::join_in_order;

    #[test]
    fn joined_lists_are_the_lists_one_after_another() {
        let cases: Vec<Vec<Vec<u64>>> = vec![
            vec![],
            vec![vec![]],
            vec![vec![7, 8]],
            vec![vec![1, 2, 3], vec![], vec![4], vec![5, 6, 7, 8, 9]],
            (0..40)
                .map(|n| (0..n * 13).map(|i| i * 1000 + n).collect())
                .collect(),
        ];
        for lists in cases {
            let expected = lists.concat();
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(3)
                .build()
                .unwrap();
            assert_eq!(pool.install(|| join_in_order(lists.clone())), expected);
            assert_eq!(join_in_order(lists), expected);
        }
    }
}
