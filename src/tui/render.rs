//! The current view rendered: into a framebuffer at any size (for export), or into terminal cells.

use super::resample::{resample_linear, to_srgb8};
use super::view_mode::{RenderedFrame, ViewMode, render_view_mode};
use super::wireframe::draw_wireframe;
use crate::quality::Quality;
use crate::raster::{Framebuffer, Viewport};
use crate::scene::Camera;
use crate::scene::PreparedScene;
use crate::shadow::ShadowCache;
use crate::term::{CellGrid, EncodeOptions, GlyphSet, Picture, encode};
use glam::{Vec2, Vec3};

/// Everything that decides the picture, apart from its size.
pub struct View<'a> {
    pub prepared: &'a PreparedScene,
    pub camera: Camera,
    pub mode: ViewMode,
    /// Scene time in seconds, for animated patterns and scrolling images.
    pub time: f64,
    /// The shading and interpolation knobs (the mesh was made with the same quality).
    pub quality: Quality,
    /// The shadow maps of the last pass, reused while they still hold.
    pub shadows: &'a ShadowCache,
    /// The object whose edges are drawn over the picture, for a moment after `o` chose it.
    pub marked: Option<usize>,
}

/// Renders `view` at `width` × `height` square pixels into `framebuffer`.
pub fn render_frame(
    view: &View,
    width: u32,
    height: u32,
    framebuffer: &mut Framebuffer,
) -> RenderedFrame {
    render_frame_at(view, width, height, Sampling::CENTRE, framebuffer)
}

/// Where a pass samples each pixel, and over what spacing its texture lookups filter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sampling {
    /// From the pixel's centre, in pixels.
    pub offset: Vec2,
    /// In pixels (`RenderTarget::footprint`).
    pub footprint: f32,
}

impl Sampling {
    pub const CENTRE: Sampling = Sampling {
        offset: Vec2::ZERO,
        footprint: 1.0,
    };
}

/// As `render_frame`, each pixel sampled as `sampling` says.
fn render_frame_at(
    view: &View,
    width: u32,
    height: u32,
    sampling: Sampling,
    framebuffer: &mut Framebuffer,
) -> RenderedFrame {
    let mut target = view
        .quality
        .target(&view.camera, Viewport { width, height });
    target.window.offset = sampling.offset;
    target.footprint = sampling.footprint;
    let rendered = render_view_mode(
        view.mode,
        view.time,
        &view.quality,
        (view.prepared, view.shadows),
        &target,
        framebuffer,
    );
    if view.mode == ViewMode::Wireframe {
        draw_wireframe(view.prepared, &target, None, framebuffer);
    } else if let Some(object) = view.marked {
        draw_wireframe(view.prepared, &target, Some(object), framebuffer);
    }
    rendered
}

/// Renders `view` to fill `cols` × `rows` cells of `options.glyphs`, with `supersampling`² samples
/// per sub-pixel. `framebuffer` is reused between frames.
pub fn render_cells(
    view: &View,
    cells: (usize, usize),
    options: EncodeOptions,
    supersampling: usize,
    framebuffer: &mut Framebuffer,
) -> (CellGrid, RenderedFrame) {
    if cells.0 == 0 || cells.1 == 0 {
        return (CellGrid::new(cells.0, cells.1), RenderedFrame::default());
    }
    let shape = CellShape {
        glyphs: options.glyphs,
        aspect: DEFAULT_CELL_ASPECT,
    };
    let pass = render_picture_pass(
        view,
        cells,
        shape,
        supersampling,
        Sampling::CENTRE,
        framebuffer,
    );
    (
        encode_cells(&pass.linear, pass.size, options),
        pass.rendered,
    )
}

/// One pass of the terminal picture: its sub-pixels in linear light, and their number.
pub struct PicturePass {
    pub linear: Vec<Vec3>,
    /// Sub-pixels across and down (`GlyphSet::picture_size`).
    pub size: (usize, usize),
    pub rendered: RenderedFrame,
}

/// Cells twice as tall as wide: most terminal fonts, and what is assumed when the terminal
/// reports no pixel size.
pub const DEFAULT_CELL_ASPECT: f32 = 2.0;

/// How cells are split and how tall one is for its width.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellShape {
    pub glyphs: GlyphSet,
    /// Cell height / cell width, as the terminal draws them.
    pub aspect: f32,
}

/// Renders `view` for `cols` × `rows` cells of `shape`: `supersampling` square pixels across each
/// sub-pixel (as many down as the cell's aspect gives), each sampled as `sampling` says, averaged
/// over each sub-pixel's area.
pub fn render_picture_pass(
    view: &View,
    (cols, rows): (usize, usize),
    shape: CellShape,
    supersampling: usize,
    sampling: Sampling,
    framebuffer: &mut Framebuffer,
) -> PicturePass {
    let size = shape.glyphs.picture_size(cols, rows);
    if cols == 0 || rows == 0 {
        return PicturePass {
            linear: Vec::new(),
            size: (0, 0),
            rendered: RenderedFrame::default(),
        };
    }
    let render_size = square_render_size(shape, cols, rows, supersampling);
    render_resampled(view, render_size, size, sampling, framebuffer)
}

/// Renders `view` at `size` square pixels, `supersampling` × `supersampling` rendered pixels to
/// each, sampled as `sampling` says and averaged over each pixel's area (the picture of a
/// terminal that shows pixels).
pub fn render_pixels_pass(
    view: &View,
    size: (usize, usize),
    supersampling: usize,
    sampling: Sampling,
    framebuffer: &mut Framebuffer,
) -> PicturePass {
    if size.0 == 0 || size.1 == 0 {
        return PicturePass {
            linear: Vec::new(),
            size: (0, 0),
            rendered: RenderedFrame::default(),
        };
    }
    let render_size = (size.0 * supersampling, size.1 * supersampling);
    render_resampled(view, render_size, size, sampling, framebuffer)
}

/// Renders `view` at `render_size` square pixels and averages them over the areas of a `size`
/// picture.
fn render_resampled(
    view: &View,
    (render_w, render_h): (usize, usize),
    size: (usize, usize),
    sampling: Sampling,
    framebuffer: &mut Framebuffer,
) -> PicturePass {
    let rendered = render_frame_at(
        view,
        render_w as u32,
        render_h as u32,
        sampling,
        framebuffer,
    );
    PicturePass {
        linear: resample_linear(framebuffer, size.0, size.1),
        size,
        rendered,
    }
}

/// The cells showing `linear`, a picture of `size` sub-pixels.
pub fn encode_cells(linear: &[Vec3], size: (usize, usize), options: EncodeOptions) -> CellGrid {
    let pixels = to_srgb8(linear);
    let picture = Picture::new(&pixels, size.0, size.1).expect("one colour per sub-pixel");
    encode(&picture, options)
}

/// The render size in square pixels: sub-pixels are square only in some cells of some fonts,
/// so the frame is rendered square, `across` pixels a cell wide and as many down as the cell's
/// aspect gives, and averaged to the sub-pixels' shape (which keeps circles round).
fn square_render_size(
    shape: CellShape,
    cols: usize,
    rows: usize,
    supersampling: usize,
) -> (usize, usize) {
    let (across, _) = shape.glyphs.cell_pixels();
    let per_cell_down = shape.aspect * (across * supersampling) as f32;
    let down = (rows as f32 * per_cell_down).round().max(1.0) as usize;
    (cols * across * supersampling, down)
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
        let shape = |glyphs, aspect| CellShape { glyphs, aspect };
        let usual = |glyphs| shape(glyphs, DEFAULT_CELL_ASPECT);
        assert_eq!(
            square_render_size(usual(GlyphSet::HalfBlock), 10, 5, 1),
            (10, 10)
        );
        assert_eq!(
            square_render_size(usual(GlyphSet::Quadrant), 10, 5, 1),
            (20, 20)
        );
        assert_eq!(
            square_render_size(usual(GlyphSet::Sextant), 10, 5, 2),
            (40, 40)
        );
        // kitty's default font: cells of 10 × 22 pixels.
        let kitty = shape(GlyphSet::HalfBlock, 2.2);
        assert_eq!(square_render_size(kitty, 160, 50, 1), (160, 110));
    }
}
