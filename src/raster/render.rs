//! The rasterizer's front door: `render` turns the frame's objects into pixels for one or more
//! passes, with any fragment program: transform, cull, clip and set up the triangles
//! (`screen_triangles`), bin them to tiles, then tile by tile resolve visibility and run the
//! program once for each visible pixel (`strips`, `tile`).

use super::fragment::FragmentShader;
use super::frame_stats::FrameStats;
use super::framebuffer::{Blend, Framebuffer};
use super::placed_mesh::PlacedMesh;
use super::refine::Refinement;
use super::render_target::{FrameOutput, RenderTarget};
use super::setup::Viewport;
use super::strips::{Pass, STRIP_ROWS, SetUp, StripBuffers, StripJob};
use super::tile::TileBuffers;
use super::top_first::map_top_first;
use glam::Vec3;

/// Renders `passes` of a frame of `objects` (the program's own, each giving its mesh) over
/// `background` with any fragment program into `output`: transform, cull, clip,
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
pub fn render<S: FragmentShader>(
    objects: &[S::Object<'_>],
    background: Vec3,
    passes: &[RenderTarget],
    shader: &S,
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
        assert_strips_alone_can_be(targets, refinement.as_ref());
    }
    let viewport = last.viewport;
    let derivatives: Vec<bool> = objects
        .iter()
        .map(|o| shader.reads_derivatives(o))
        .collect();
    let set_up = SetUp::new(objects, targets, last);
    let passes: Vec<Pass<_>> = targets
        .iter()
        .map(|target| Pass::new(objects, &set_up, target, shader, &derivatives))
        .collect();
    let tiles_x = passes[0].bins.tiles_x;
    let job = StripJob {
        passes: &passes,
        last,
        viewport,
        background,
        tiles_x,
        finished_strips,
        bytes_only: framebuffer.is_none(),
        refinement: refinement.as_ref().map(|r| r.rule),
    };
    let mut no_framebuffer_known = Vec::new();
    let strips = strip_buffers(
        framebuffer.ok_or(&mut no_framebuffer_known),
        (viewport, tiles_x, background),
        refinement,
    );
    let (fragments, flattened) = map_top_first(
        strips,
        // Once per thread, not per strip: the buffers keep their grown capacity.
        || (TileBuffers::default(), shader.scratch()),
        |(tile, scratch), index, strip| job.render(index as u32, strip, tile, scratch),
    )
    .into_iter()
    .fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    FrameStats {
        triangles: objects.iter().map(|o| o.mesh().indices.len()).sum(),
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

/// Checks that a frame with no framebuffer, only strips of bytes, is one unmasked pass that
/// replaces and keeps no depth (nothing to add into, nothing to test against).
fn assert_strips_alone_can_be(targets: &[RenderTarget], refinement: Option<&Refinement>) {
    let last = targets.last().expect("a pass");
    let alone = targets.len() == 1 && refinement.is_none();
    let replaces = last.mask.is_none() && last.blend == Blend::Replace && !last.writes_depth;
    assert!(
        alone && replaces,
        "strips alone come of one unmasked pass that keeps no depth"
    );
}

/// Each strip's share of `output`: the framebuffer's rows (resized to `viewport`, the
/// background known tile by tile), or, without a framebuffer, no pixels and a record of known
/// background kept in the given vector; and its share of the refinement's record.
fn strip_buffers<'f>(
    output: Result<&'f mut Framebuffer, &'f mut Vec<bool>>,
    (viewport, tiles_x, background): (Viewport, u32, Vec3),
    refinement: Option<Refinement<'f>>,
) -> Vec<StripBuffers<'f>> {
    let strips_y = viewport.height.div_ceil(STRIP_ROWS);
    let (colour_and_depth, known_background) = match output {
        Err(no_framebuffer_known) => {
            no_framebuffer_known.resize((tiles_x * strips_y) as usize, false);
            let nothing = (0..strips_y).map(|_| (&mut [][..], &mut [][..])).collect();
            (nothing, &mut no_framebuffer_known[..])
        }
        Ok(framebuffer) => {
            framebuffer.resize(viewport.width, viewport.height);
            let (color, depth, known) = framebuffer.tiles_mut((tiles_x, strips_y), background);
            let pixels = (STRIP_ROWS * viewport.width) as usize;
            let strips: Vec<_> = color
                .chunks_mut(pixels)
                .zip(depth.chunks_mut(pixels))
                .collect();
            (strips, known)
        }
    };
    let mut refined = refined_strips(refinement, viewport);
    refined.resize_with(colour_and_depth.len(), || &mut []);
    colour_and_depth
        .into_iter()
        .zip(known_background.chunks_mut(tiles_x.max(1) as usize))
        .zip(refined)
        .map(
            |(((color, depth), known_background), refined)| StripBuffers {
                color,
                depth,
                known_background,
                refined,
            },
        )
        .collect()
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
pub fn render_pass<S: FragmentShader>(
    objects: &[S::Object<'_>],
    background: Vec3,
    target: &RenderTarget,
    shader: &S,
    framebuffer: &mut Framebuffer,
) -> FrameStats {
    let output = FrameOutput::Framebuffer(framebuffer);
    render(
        objects,
        background,
        std::slice::from_ref(target),
        shader,
        output,
        None,
    )
}
