//! The frame pipeline: prepared scenes, per-frame objects, screen triangles and the render entry
//! points.

use super::clip::{ClipVertex, clip_triangle, inside_clip_volume};
use super::fragment::{FragmentShader, FrameObject};
use super::framebuffer::{Blend, Framebuffer};
use super::refine::Refinement;
use super::setup::{
    PlacedTriangle, ScreenTriangle, ShiftSpan, TrianglePlanes, Viewport, snap_vertex,
};
use super::strips::{Pass, STRIP_ROWS, SetUp, StripBuffers, StripJob};
use super::tile::TileBuffers;
use super::top_first::map_top_first;
use super::window::ImageWindow;
use crate::scene::Camera;
use crate::scene::{Material, Scene};
use crate::surface::{Mesh, Surface, Tessellation};
use glam::{Mat4, Vec4};
use rayon::prelude::*;

/// A scene's objects tessellated once, reused for every frame until the scene or density changes.
pub struct PreparedScene {
    pub scene: Scene,
    pub objects: Vec<PreparedObject>,
}

pub struct PreparedObject {
    pub surface: Surface,
    pub material: Material,
    pub mesh: Mesh,
}

impl PreparedScene {
    pub fn new(scene: Scene, tessellation: Tessellation) -> PreparedScene {
        let objects = scene
            .objects
            .par_iter()
            .map(|o| PreparedObject {
                surface: o.surface.clone(),
                material: o.material.clone(),
                mesh: o.surface.tessellate(tessellation),
            })
            .collect();
        PreparedScene { scene, objects }
    }

    pub fn triangle_count(&self) -> usize {
        self.objects.iter().map(|o| o.mesh.indices.len()).sum()
    }
}

/// What one frame cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Triangles of the tessellated scene.
    pub triangles: usize,
    /// Screen triangles after culling and clipping that reached scan conversion.
    pub rasterized_triangles: usize,
    /// Pixels shaded (each visible pixel exactly once).
    pub fragments: usize,
    /// Fragments drawn flat because a pattern gave no finite value there (division by zero…).
    pub flattened: usize,
}

/// Where a frame goes and how it is seen.
pub struct RenderTarget<'a> {
    pub camera: &'a Camera,
    /// The size of the frame rendered (the window's size when rendering part of an image).
    pub viewport: Viewport,
    pub interpolation: Interpolation,
    /// The part of the image this frame covers and where it samples in each pixel.
    pub window: ImageWindow,
    /// The spacing of samples in pixels, scaling the (u,v) derivatives that pick texture detail:
    /// 1 for one sample per pixel, ½ for 4 samples, so supersampled stills keep their detail.
    pub footprint: f32,
    /// Only these pixels (row-major over the viewport) are rendered; the rest of the
    /// framebuffer is left as it was, and tiles with none of them are skipped whole.
    pub mask: Option<&'a [bool]>,
    pub blend: Blend,
    /// Whether the framebuffer's depth is written. When not, it keeps what it held: a pass whose
    /// depth nobody reads skips the stores, and a fresh framebuffer's depth is never touched
    /// (so never mapped).
    pub writes_depth: bool,
}

/// Where a render's pixels go.
pub enum FrameOutput<'o> {
    /// Into the framebuffer (resized to the viewport).
    Framebuffer(&'o mut Framebuffer),
    /// Into the framebuffer, and each strip of `STRIP_ROWS` rows handed on as 8-bit sRGB once
    /// every pass has finished it: a still encodes its rows while the rest renders.
    FramebufferAndStrips(&'o mut Framebuffer, &'o Srgb8Strips<'o>),
    /// Only as 8-bit sRGB strips, no framebuffer at all (none is allocated, zeroed or touched):
    /// for one pass that replaces every pixel, unmasked, keeping no depth.
    Strips(&'o Srgb8Strips<'o>),
}

/// A render's strips handed on as 8-bit sRGB (3 bytes a pixel, row-major), each tile converted
/// as soon as it is finished, while its colours are still in cache.
pub struct Srgb8Strips<'a> {
    /// A buffer to fill with a strip's bytes (its contents are overwritten: pass one back).
    pub buffer: &'a (dyn Fn() -> Vec<u8> + Sync),
    /// Strip `index` (from the top) and its bytes, on the thread that rendered it, in no set
    /// order.
    pub finished: &'a (dyn Fn(usize, Vec<u8>) + Sync),
}

impl<'a> RenderTarget<'a> {
    /// The whole `viewport` seen by `camera`, one perspective-correct sample at each pixel centre.
    pub fn new(camera: &'a Camera, viewport: Viewport) -> RenderTarget<'a> {
        RenderTarget {
            camera,
            viewport,
            interpolation: Interpolation::PerspectiveCorrect,
            window: ImageWindow::whole(viewport),
            footprint: 1.0,
            mask: None,
            blend: Blend::Replace,
            writes_depth: true,
        }
    }

    pub fn with_interpolation(self, interpolation: Interpolation) -> RenderTarget<'a> {
        RenderTarget {
            interpolation,
            ..self
        }
    }

    /// Camera-relative world positions to this frame's clip space.
    pub fn view_projection(&self) -> Mat4 {
        self.window.clip_transform(self.viewport)
            * self.camera.view_projection(self.window.full.aspect())
    }
}

/// How (u,v) is interpolated across a triangle in screen space.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Interpolation {
    /// Exact for the triangle's plane: u/w, v/w and 1/w are affine in screen space.
    #[default]
    PerspectiveCorrect,
    /// Linear in screen space, as early hardware did: cheaper, wrong under perspective.
    Affine,
}

/// The objects of a prepared scene placed relative to the camera for one frame.
pub fn frame_objects<'a>(prepared: &'a PreparedScene, camera: &Camera) -> Vec<FrameObject<'a>> {
    prepared
        .objects
        .iter()
        .map(|o| FrameObject {
            prepared: o,
            origin: (o.surface.origin() - camera.eye).as_vec3(),
            eye: camera.eye - o.surface.origin(),
        })
        .collect()
}

/// Transforms, culls, clips and sets up every triangle of the scene, in submission order.
pub fn screen_triangles(objects: &[FrameObject], target: &RenderTarget) -> Vec<ScreenTriangle> {
    shifted_screen_triangles(objects, target, &ShiftSpan::NONE)
}

/// `screen_triangles` for passes whose sample points are shifted within `span` (see
/// `ScreenTriangle::new`).
pub(super) fn shifted_screen_triangles(
    objects: &[FrameObject],
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

/// Renders `passes` of a frame with any fragment program into `output`: transform, cull, clip,
/// set up, bin, then per tile resolve visibility and run the program once for each visible
/// pixel. Every pixel ends shaded or background, so no separate clear pass is needed; tiles that
/// were all background in the last render into a framebuffer, and still are, are not
/// rewritten.
///
/// Several passes come out as rendering them one after another would, to the bit, but tile by
/// tile: every pass of a tile before the next tile, so the tile's pixels (which supersampling
/// passes add into) and the texels its fragments read stay in cache from pass to pass. The
/// passes share the viewport, camera, mask, window position and interpolation, so the triangles
/// are set up once for them all; they differ in where they sample (the window's offset),
/// footprint, blend and depth writes. With a `refinement`, the passes from its `from_pass` on
/// render only the pixels the earlier passes moved (see `Refinement`), decided tile by tile as
/// each tile's earlier passes finish.
pub fn render(
    prepared: &PreparedScene,
    passes: &[RenderTarget],
    shader: &impl FragmentShader,
    output: FrameOutput,
    refinement: Option<Refinement>,
) -> FrameStats {
    let targets = passes;
    let Some(last) = targets.last() else {
        return FrameStats::default();
    };
    assert_renderable_together(targets, refinement.as_ref());
    let (framebuffer, finished_strips) = match output {
        FrameOutput::Framebuffer(framebuffer) => (Some(framebuffer), None),
        FrameOutput::FramebufferAndStrips(framebuffer, strips) => (Some(framebuffer), Some(strips)),
        FrameOutput::Strips(strips) => (None, Some(strips)),
    };
    if framebuffer.is_none() {
        let alone = targets.len() == 1 && refinement.is_none();
        let replaces = last.mask.is_none() && last.blend == Blend::Replace && !last.writes_depth;
        assert!(
            alone && replaces,
            "strips alone come of one unmasked pass that keeps no depth"
        );
    }
    let viewport = last.viewport;
    let objects = frame_objects(prepared, last.camera);
    let derivatives: Vec<bool> = objects
        .iter()
        .map(|o| shader.reads_derivatives(o))
        .collect();
    let set_up = SetUp::new(&objects, targets, last);
    let passes: Vec<Pass<_>> = targets
        .iter()
        .map(|target| Pass::new(&objects, &set_up, target, shader, &derivatives))
        .collect();
    let tiles_x = passes[0].bins.tiles_x;
    let strips_y = viewport.height.div_ceil(STRIP_ROWS);
    let job = StripJob {
        passes: &passes,
        last,
        viewport,
        background: prepared.scene.background,
        tiles_x,
        finished_strips,
        bytes_only: framebuffer.is_none(),
        refinement: refinement.as_ref().map(|r| r.rule),
    };
    let mut no_framebuffer_known = Vec::new();
    let (strips, known_background) = match framebuffer {
        None => {
            no_framebuffer_known.resize((tiles_x * strips_y) as usize, false);
            let nothing = (0..strips_y).map(|_| (&mut [][..], &mut [][..])).collect();
            (nothing, &mut no_framebuffer_known[..])
        }
        Some(framebuffer) => {
            framebuffer.resize(viewport.width, viewport.height);
            let (color, depth, known) = framebuffer.tiles_mut((tiles_x, strips_y), job.background);
            let pixels = (STRIP_ROWS * viewport.width) as usize;
            let strips: Vec<_> = color
                .chunks_mut(pixels)
                .zip(depth.chunks_mut(pixels))
                .collect();
            (strips, known)
        }
    };
    let mut refined = refined_strips(refinement, viewport);
    refined.resize_with(strips.len(), || &mut []);
    let strips: Vec<_> = strips
        .into_iter()
        .zip(known_background.chunks_mut(tiles_x.max(1) as usize))
        .zip(refined)
        .collect();
    let (fragments, flattened) = map_top_first(
        strips,
        // Once per thread, not per strip: the buffers keep their grown capacity.
        || (TileBuffers::default(), shader.scratch()),
        |(tile, scratch), index, (((color, depth), known_background), refined)| {
            let strip = StripBuffers {
                color,
                depth,
                known_background,
                refined,
            };
            job.render(index as u32, strip, tile, scratch)
        },
    )
    .into_iter()
    .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    FrameStats {
        triangles: prepared.triangle_count(),
        rasterized_triangles: passes.iter().map(|p| p.triangles.len()).sum(),
        fragments,
        flattened,
    }
}

/// Checks that `targets` can be rendered as one group: they share the last one's viewport,
/// camera, mask, window and interpolation, and a refinement decides at one of them.
fn assert_renderable_together(targets: &[RenderTarget], refinement: Option<&Refinement>) {
    let last = targets.last().expect("a pass");
    assert!(
        refinement.is_none_or(|r| r.rule.first_decided_pass() < targets.len()),
        "a refinement starts at one of the group's passes"
    );
    let shared = |t: &RenderTarget| {
        t.viewport == last.viewport
            && std::ptr::eq(t.camera, last.camera)
            && t.mask.map(<[bool]>::as_ptr) == last.mask.map(<[bool]>::as_ptr)
            && (t.window.full, t.window.x0, t.window.y0)
                == (last.window.full, last.window.x0, last.window.y0)
            && t.interpolation == last.interpolation
    };
    assert!(
        targets.iter().all(shared),
        "passes rendered together share viewport, camera, mask, window and interpolation"
    );
}

/// The refinement's record of refined pixels, sized to the viewport and cut into strips (none
/// without a refinement).
fn refined_strips<'r>(
    refinement: Option<Refinement<'r>>,
    viewport: Viewport,
) -> Vec<&'r mut [bool]> {
    let Some(refinement) = refinement else {
        return Vec::new();
    };
    let pixels = viewport.width as usize * viewport.height as usize;
    crate::huge_pages::resize_for_overwrite(refinement.refined, pixels);
    let rows = (STRIP_ROWS * viewport.width).max(1) as usize;
    refinement.refined.chunks_mut(rows).collect()
}

/// One pass of `target` into `framebuffer` (resized to it), depth kept: `render` for the
/// commonest case.
pub fn render_pass(
    prepared: &PreparedScene,
    target: &RenderTarget,
    shader: &impl FragmentShader,
    framebuffer: &mut Framebuffer,
) -> FrameStats {
    let output = FrameOutput::Framebuffer(framebuffer);
    render(prepared, std::slice::from_ref(target), shader, output, None)
}

/// Pieces of a mesh's triangle list each thread sets up, when there are several threads.
const SETUP_PIECES_PER_THREAD: usize = 4;

/// Transforms one object's vertices and turns its triangles into screen triangles, in parallel
/// pieces that hold them in order.
fn object_triangle_pieces(
    object: &FrameObject,
    index: u32,
    target: &RenderTarget,
    view_projection: Mat4,
    span: &ShiftSpan,
) -> Vec<Vec<ScreenTriangle>> {
    let mesh = &object.prepared.mesh;
    let (viewport, guard) = (target.viewport, target.viewport.guard_band());
    let (clip_positions, vertices) = mesh
        .positions
        .par_iter()
        .map(|&p| {
            let position = view_projection * (object.origin + p).extend(1.0);
            // Snapping rounds: a library call per value in baseline x86-64.
            let vertex = crate::simd::widest_rounding(
                #[inline(always)]
                || SetupVertex::new(position, viewport, guard),
            );
            (position, vertex)
        })
        .unzip();
    let setup = ObjectSetup {
        object,
        index,
        clip_positions,
        vertices,
        cull_back_faces: object.prepared.surface.encloses(target.camera.eye) == Some(true),
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
    object: &'a FrameObject<'a>,
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
        let mesh = &self.object.prepared.mesh;
        if self.cull_back_faces {
            let p = corners.map(|i| mesh.positions[i as usize]);
            let facing_away = (p[1] - p[0])
                .cross(p[2] - p[0])
                .dot(self.object.origin + p[0])
                >= 0.0;
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
