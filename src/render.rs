//! How a scene becomes pixels: the renderer's front door, in the order every caller follows.
//!
//! 1. **Prepare.** `Quality::prepare` (`src/quality/`) tessellates each object as finely as the
//!    view needs, within the memory budget, into a `PreparedScene` (`src/scene/`), kept frame
//!    after frame until the scene or the density changes. Each surface's tessellation, exact
//!    ray hit and (u,v) live in its own file of `src/surface/`.
//! 2. **Program.** `Quality::shader_showing` builds the fragment program, `shade::LitShader`:
//!    the lights placed for the camera, shadow maps drawn by the rasterizer (`src/shadow/`),
//!    the quality's shading knobs, and what it shows at which moment (`Showing`). It is built
//!    once for a frame and not changed afterwards.
//! 3. **Raster.** `render_scene` places the objects for the camera (`shade::FrameObject`) and
//!    hands them to `raster::render` (`src/raster/render.rs`), which knows meshes, not scenes:
//!    it transforms, clips and sets up the triangles, bins them into tiles, resolves visibility
//!    per tile and runs the program once for each visible pixel, for one or more passes
//!    (`RenderTarget`: camera, viewport, the window of the image, sample offset, blend).
//! 4. **Output.** A `Framebuffer` of linear colour, 8-bit sRGB strips, or both. Stills
//!    (`src/still/`, `src/export/`) stream strips into PNG files; the workbench (`src/tui/`)
//!    turns the framebuffer into cells or terminal pixels; the reference (`src/reference/`)
//!    casts exact rays through the same program to judge every other frame.
//!
//! `frame` takes the four steps for one frame. Callers that keep pieces between frames (the
//! workbench keeps the prepared scene and its shadow maps; stills render in bands) take the
//! steps themselves, in this order.

use crate::memory_budget::OverBudget;
use crate::quality::Quality;
use crate::raster::{
    FragmentShader, FrameOutput, FrameStats, Framebuffer, Refinement, RenderTarget, Viewport,
};
use crate::scene::{PreparedScene, Scene};
use crate::shade::{FrameObject, LitShader, Showing, frame_objects};
use glam::Vec3;

/// One frame of `scene` seen by its camera at `quality`, showing `showing`, into a new
/// framebuffer: prepare, program, raster. An error when the tessellation the view needs is
/// over the memory budget.
pub fn frame(
    scene: &Scene,
    quality: &Quality,
    viewport: Viewport,
    showing: Showing,
) -> Result<(Framebuffer, FrameStats), OverBudget> {
    let camera = &scene.camera;
    let output_bytes = Framebuffer::bytes_for(viewport);
    let prepared = quality.prepare(scene.clone(), camera, viewport, output_bytes)?;
    let shader = quality.shader_showing(&prepared, camera, viewport, showing);
    Ok(render_with(
        &prepared,
        &quality.target(camera, viewport),
        &shader,
    ))
}

/// A fragment program that shades a prepared scene's objects, placed for the frame.
pub trait SceneShader: for<'o> FragmentShader<Object<'o> = FrameObject<'o>> {}

impl<S: for<'o> FragmentShader<Object<'o> = FrameObject<'o>>> SceneShader for S {}

/// `raster::render` for a prepared scene: its objects placed for the passes' camera, over its
/// background.
pub fn render_scene(
    prepared: &PreparedScene,
    passes: &[RenderTarget],
    shader: &impl SceneShader,
    output: FrameOutput,
    refinement: Option<Refinement>,
) -> FrameStats {
    let Some(last) = passes.last() else {
        return FrameStats::default();
    };
    let objects = frame_objects(prepared, last.camera);
    let background = prepared.scene.background;
    crate::raster::render(&objects, background, passes, shader, output, refinement)
}

/// One pass of `target` into `framebuffer` (resized to it), depth kept: `render_scene` for the
/// commonest case.
pub fn render_scene_pass(
    prepared: &PreparedScene,
    target: &RenderTarget,
    shader: &impl SceneShader,
    framebuffer: &mut Framebuffer,
) -> FrameStats {
    let output = FrameOutput::Framebuffer(framebuffer);
    render_scene(prepared, std::slice::from_ref(target), shader, output, None)
}

/// One pass of any program into a new framebuffer.
pub fn render_with(
    prepared: &PreparedScene,
    target: &RenderTarget,
    shader: &impl SceneShader,
) -> (Framebuffer, FrameStats) {
    let mut framebuffer = Framebuffer::new(0, 0, Vec3::ZERO);
    let stats = render_scene_pass(prepared, target, shader, &mut framebuffer);
    (framebuffer, stats)
}

/// One pass of the scene's own lit program, with the scene's settings and no quality knobs.
pub fn render_lit(prepared: &PreparedScene, target: &RenderTarget) -> (Framebuffer, FrameStats) {
    render_with(
        prepared,
        target,
        &LitShader::new(&prepared.scene, target.camera),
    )
}
