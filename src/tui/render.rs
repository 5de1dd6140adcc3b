//! The current view rendered: into a framebuffer at any size (for export), or into terminal cells.

use super::app::App;
use super::resample::resample_to_srgb;
use super::view_mode::{RenderedFrame, ViewMode, render_view_mode};
use super::wireframe::draw_wireframe;
use crate::quality::Quality;
use crate::raster::{Framebuffer, PreparedScene, Viewport};
use crate::scene::Camera;
use crate::term::{CellGrid, EncodeOptions, GlyphSet, Picture, encode};
use glam::Vec3;

/// Everything that decides the picture, apart from its size.
pub struct View<'a> {
    pub prepared: &'a PreparedScene,
    pub camera: Camera,
    pub mode: ViewMode,
    /// Scene time in seconds, for animated patterns and scrolling images.
    pub time: f64,
    /// The shading and interpolation knobs (the mesh was made with the same quality).
    pub quality: Quality,
}

impl<'a> View<'a> {
    pub fn of(app: &'a App) -> View<'a> {
        View {
            prepared: &app.prepared,
            camera: app.camera(),
            mode: app.view_mode,
            time: app.clock.time(),
            quality: app.quality.quality(),
        }
    }
}

/// Renders `view` at `width` × `height` square pixels into `framebuffer`.
pub fn render_frame(
    view: &View,
    width: u32,
    height: u32,
    framebuffer: &mut Framebuffer,
) -> RenderedFrame {
    let target = view
        .quality
        .target(&view.camera, Viewport { width, height });
    let rendered = render_view_mode(
        view.mode,
        view.time,
        &view.quality,
        view.prepared,
        &target,
        framebuffer,
    );
    if view.mode == ViewMode::Wireframe {
        draw_wireframe(view.prepared, &target, framebuffer);
    }
    rendered
}

/// Renders `view` to fill `cols` × `rows` cells of `options.glyphs`, with `supersampling`² samples
/// per sub-pixel. `framebuffer` is reused between frames.
pub fn render_cells(
    view: &View,
    (cols, rows): (usize, usize),
    options: EncodeOptions,
    supersampling: usize,
    framebuffer: &mut Framebuffer,
) -> (CellGrid, RenderedFrame) {
    if cols == 0 || rows == 0 {
        return (CellGrid::new(cols, rows), RenderedFrame::default());
    }
    let (width, height) = options.glyphs.picture_size(cols, rows);
    let (render_w, render_h) = square_render_size(options.glyphs, cols, rows, supersampling);
    let rendered = render_frame(view, render_w as u32, render_h as u32, framebuffer);
    let pixels = resample_to_srgb(framebuffer, width, height);
    let picture = Picture::new(&pixels, width, height).expect("resampled to the picture size");
    (encode(&picture, options), rendered)
}

/// The render size in square pixels for cells twice as tall as wide: sub-pixels of quadrant and
/// sextant cells are not square, so the frame is rendered square and averaged to their shape.
fn square_render_size(
    glyphs: GlyphSet,
    cols: usize,
    rows: usize,
    supersampling: usize,
) -> (usize, usize) {
    let (across, _) = glyphs.cell_pixels();
    (
        cols * across * supersampling,
        rows * 2 * across * supersampling,
    )
}

/// A framebuffer to reuse between frames.
pub fn empty_framebuffer() -> Framebuffer {
    Framebuffer::new(0, 0, Vec3::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn render_sizes_keep_pixels_square() {
        assert_eq!(square_render_size(GlyphSet::HalfBlock, 10, 5, 1), (10, 10));
        assert_eq!(square_render_size(GlyphSet::Quadrant, 10, 5, 1), (20, 20));
        assert_eq!(square_render_size(GlyphSet::Sextant, 10, 5, 2), (40, 40));
    }
}
