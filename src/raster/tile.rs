//! A tile's two passes: resolve which triangle is nearest at each pixel, then shade the visible
//! pixels as one batch.

use super::bin::TILE_SIZE;
use super::fragment::{Fragment, FragmentShader, FrameObject};
use super::scan::{PixelRect, scan_triangle};
use super::setup::ScreenTriangle;
use glam::{Vec2, Vec3};

const NO_TRIANGLE: u32 = u32::MAX;
const TILE_PIXELS: usize = (TILE_SIZE * TILE_SIZE) as usize;

/// A tile's visibility: the nearest triangle per pixel, by interpolated 1/w (greater is nearer,
/// and f32 keeps its precision best near 0, i.e. far away: the "reversed-z" trick).
pub struct TileBuffers {
    inv_w: Vec<f32>,
    triangle: Vec<u32>,
    /// The batch being shaded, and where each of its fragments goes.
    fragments: Vec<Fragment>,
    pixels: Vec<u32>,
    colors: Vec<Vec3>,
}

impl Default for TileBuffers {
    fn default() -> Self {
        TileBuffers {
            inv_w: vec![0.0; TILE_PIXELS],
            triangle: vec![NO_TRIANGLE; TILE_PIXELS],
            fragments: Vec::with_capacity(TILE_PIXELS),
            pixels: Vec::with_capacity(TILE_PIXELS),
            colors: Vec::with_capacity(TILE_PIXELS),
        }
    }
}

/// The rows of the framebuffer one tile row writes to.
pub struct StripOutput<'a> {
    pub color: &'a mut [Vec3],
    pub depth: &'a mut [f32],
    pub width: u32,
    pub first_row: u32,
    pub background: Vec3,
    /// The strip's pixels to write (`None`: all); see `RenderTarget::mask`.
    pub mask: Option<&'a [bool]>,
}

impl StripOutput<'_> {
    /// Whether any pixel of `rect` is to be written.
    pub fn any_wanted(&self, rect: &PixelRect) -> bool {
        let Some(mask) = self.mask else {
            return true;
        };
        (rect.y0..=rect.y1).any(|y| {
            let row = ((y - self.first_row) * self.width) as usize;
            mask[row + rect.x0 as usize..=row + rect.x1 as usize].contains(&true)
        })
    }

    #[inline]
    fn wanted(&self, pixel: usize) -> bool {
        self.mask.is_none_or(|mask| mask[pixel])
    }

    pub fn fill_background(self, rect: &PixelRect) {
        for y in rect.y0..=rect.y1 {
            let row = ((y - self.first_row) * self.width) as usize;
            let span = row + rect.x0 as usize..=row + rect.x1 as usize;
            fill_colour(&mut self.color[span.clone()], self.background);
            self.depth[span].fill(f32::INFINITY);
        }
    }
}

/// Most of a frame is background: a grey one is written as plain f32s, which compiles to wide
/// stores instead of one 12-byte store per pixel.
fn fill_colour(pixels: &mut [Vec3], colour: Vec3) {
    if colour.x == colour.y && colour.y == colour.z {
        bytemuck::cast_slice_mut::<Vec3, f32>(pixels).fill(colour.x);
    } else {
        pixels.fill(colour);
    }
}

impl TileBuffers {
    pub fn resolve_visibility(
        &mut self,
        triangles: &[ScreenTriangle],
        bin: &[u32],
        rect: &PixelRect,
    ) {
        self.inv_w.fill(0.0);
        self.triangle.fill(NO_TRIANGLE);
        for &index in bin {
            let t = &triangles[index as usize];
            let (inv_w, triangle) = (&mut self.inv_w, &mut self.triangle);
            scan_triangle(t, rect, |x, y| {
                let depth = t.inv_w.at(pixel_offset(t, x, y));
                let slot = ((y - rect.y0) * TILE_SIZE + (x - rect.x0)) as usize;
                // Strictly nearer wins, so the first of two equal depths stays: deterministic.
                if depth > inv_w[slot] {
                    inv_w[slot] = depth;
                    triangle[slot] = index;
                }
            });
        }
    }

    /// Turns the tile's visible pixels into fragments, shades them as one batch and writes the
    /// tile (background where nothing is visible). Returns the fragments shaded and flattened.
    pub fn shade<S: FragmentShader>(
        &mut self,
        triangles: &[ScreenTriangle],
        frame: &TileFrame<S>,
        scratch: &mut S::Scratch,
        rect: &PixelRect,
        out: StripOutput,
    ) -> (usize, usize) {
        self.fragments.clear();
        self.pixels.clear();
        for y in rect.y0..=rect.y1 {
            for x in rect.x0..=rect.x1 {
                let slot = ((y - rect.y0) * TILE_SIZE + (x - rect.x0)) as usize;
                let pixel = ((y - out.first_row) * out.width + x) as usize;
                if !out.wanted(pixel) {
                    continue;
                }
                match self.triangle[slot] {
                    NO_TRIANGLE => {
                        out.color[pixel] = out.background;
                        out.depth[pixel] = f32::INFINITY;
                    }
                    index => {
                        let t = &triangles[index as usize];
                        self.fragments
                            .push(fragment(t, x, y, frame.perspective, frame.footprint));
                        self.pixels.push(pixel as u32);
                    }
                }
            }
        }
        self.colors.resize(self.fragments.len(), Vec3::ZERO);
        let flattened =
            frame
                .shader
                .shade(frame.objects, &self.fragments, scratch, &mut self.colors);
        for ((&pixel, fragment), &color) in
            self.pixels.iter().zip(&self.fragments).zip(&self.colors)
        {
            out.color[pixel as usize] = color;
            out.depth[pixel as usize] = fragment.depth;
        }
        (self.fragments.len(), flattened)
    }
}

/// What every tile of a frame shares.
pub struct TileFrame<'a, S> {
    pub objects: &'a [FrameObject<'a>],
    pub shader: &'a S,
    pub perspective: bool,
    /// Sample spacing in pixels: scales the (u,v) derivatives (see `RenderTarget::footprint`).
    pub footprint: f32,
}

/// The fragment at pixel (x, y) of a triangle: (u,v) and its screen derivatives from the
/// interpolated planes (for u = U/Q with U = u/w and Q = 1/w: ∂u/∂x = (U_x − u·Q_x)/Q).
#[inline]
fn fragment(t: &ScreenTriangle, x: u32, y: u32, perspective: bool, footprint: f32) -> Fragment {
    let offset = pixel_offset(t, x, y);
    let q = t.inv_w.at(offset);
    let w = 1.0 / q;
    let plane_uv = Vec2::new(t.u_over_w.at(offset), t.v_over_w.at(offset));
    let plane_dx = Vec2::new(t.u_over_w.dx, t.v_over_w.dx);
    let plane_dy = Vec2::new(t.u_over_w.dy, t.v_over_w.dy);
    let (uv, duv_dx, duv_dy) = if perspective {
        let uv = plane_uv * w;
        (
            uv,
            (plane_dx - uv * t.inv_w.dx) * w,
            (plane_dy - uv * t.inv_w.dy) * w,
        )
    } else {
        (plane_uv, plane_dx, plane_dy)
    };
    Fragment {
        object: t.object,
        uv,
        duv_dx: duv_dx * footprint,
        duv_dy: duv_dy * footprint,
        depth: w,
        x,
        y,
    }
}

/// The pixel centre relative to the triangle's attribute origin.
#[inline]
fn pixel_offset(t: &ScreenTriangle, x: u32, y: u32) -> Vec2 {
    Vec2::new(x as f32 + 0.5, y as f32 + 0.5) - t.origin
}
