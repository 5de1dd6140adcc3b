//! The framebuffer: linear-light colour and view depth per pixel, and how a render blends into it.

use super::setup::Viewport;
use crate::huge_pages::resize_for_overwrite;
use glam::Vec3;
use std::sync::OnceLock;

/// The rendered image: linear-light RGB (f32: shading sums many small terms, and exports
/// average samples before the one conversion to sRGB) and the view depth per pixel.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    pub width: u32,
    pub height: u32,
    color: Vec<Vec3>,
    /// Distance along the view direction of the visible surface, +∞ for background.
    depth: Vec<f32>,
    known_background: KnownBackground,
}

impl Framebuffer {
    /// The memory one pixel takes: its colour and its depth.
    pub const BYTES_PER_PIXEL: u64 =
        (std::mem::size_of::<Vec3>() + std::mem::size_of::<f32>()) as u64;

    /// The memory a framebuffer of `viewport`'s size takes.
    pub fn bytes_for(viewport: Viewport) -> u64 {
        u64::from(viewport.width) * u64::from(viewport.height) * Framebuffer::BYTES_PER_PIXEL
    }
}

/// How a render's colours meet what the framebuffer holds; depth, where written, is replaced.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Blend {
    #[default]
    Replace,
    /// Replaces with colour × weight: the first of supersampling's passes, so their sum starts
    /// from no zeroed framebuffer (the same bits as adding to zero, but for the sign of a zero).
    Scale(f32),
    /// Adds colour × weight: supersampling's passes summed in place, in pass order. The
    /// framebuffer must already be the render's size and hold what is to be added to.
    Add(f32),
    /// Scales what the pixel holds by `kept`, then adds colour × `weight`: the first pass of a
    /// refinement (`Refinement`), turning the mean of a pixel's first samples into their share
    /// of the mean of all its samples.
    Rescale { kept: f32, weight: f32 },
}

/// The tiles the last render left holding only background, so the next render of the same
/// size and background need not write them again: most of a frame is background, and
/// rewriting 16 bytes a pixel of it was a sixth of a 1080p frame. Forgotten on any mutable
/// access to the pixels, so it can never hide a change.
#[derive(Clone, Debug, Default)]
struct KnownBackground {
    colour: Vec3,
    grid: (u32, u32),
    tiles: Vec<bool>,
}

impl Framebuffer {
    pub fn new(width: u32, height: u32, background: Vec3) -> Framebuffer {
        let n = width as usize * height as usize;
        Framebuffer::from_parts(width, height, vec![background; n], vec![f32::INFINITY; n])
    }

    /// A framebuffer holding `color` and `depth`, row-major, `width` × `height` of each.
    pub fn from_parts(width: u32, height: u32, color: Vec<Vec3>, depth: Vec<f32>) -> Framebuffer {
        let n = width as usize * height as usize;
        assert!(
            color.len() == n && depth.len() == n,
            "a {width}×{height} framebuffer needs {n} colours and depths"
        );
        Framebuffer {
            width,
            height,
            color,
            depth,
            known_background: KnownBackground::default(),
        }
    }

    /// Linear RGB per pixel, row-major, top row first.
    pub fn color(&self) -> &[Vec3] {
        &self.color
    }

    /// View depth per pixel, +∞ where nothing was drawn.
    pub fn depth(&self) -> &[f32] {
        &self.depth
    }

    pub fn color_mut(&mut self) -> &mut [Vec3] {
        self.parts_mut().0
    }

    /// Colour and depth for writing.
    pub fn parts_mut(&mut self) -> (&mut [Vec3], &mut [f32]) {
        self.known_background.tiles.clear();
        (&mut self.color, &mut self.depth)
    }

    /// Takes the depth out, leaving the framebuffer empty (for reuse by the next `resize`).
    pub fn take_depth(&mut self) -> Vec<f32> {
        self.known_background.tiles.clear();
        std::mem::take(&mut self.depth)
    }

    /// Makes the framebuffer `width` × `height`, keeping its allocation when it is large enough.
    /// The contents are unspecified until the next render writes every pixel.
    pub fn resize(&mut self, width: u32, height: u32) {
        let n = width as usize * height as usize;
        if (width, height) != (self.width, self.height)
            || self.color.len() != n
            || self.depth.len() != n
        {
            self.known_background.tiles.clear();
        }
        self.width = width;
        self.height = height;
        resize_for_overwrite(&mut self.color, n);
        resize_for_overwrite(&mut self.depth, n);
    }

    /// For a render in tiles of a `grid` (tiles across, strips down) over a `background`: colour,
    /// depth and, per tile, whether it holds only that background already. The caller keeps
    /// the flags true exactly for the tiles it leaves (or makes) all background.
    pub(super) fn tiles_mut(
        &mut self,
        grid: (u32, u32),
        background: Vec3,
    ) -> (&mut [Vec3], &mut [f32], &mut [bool]) {
        let known = &mut self.known_background;
        let tiles = (grid.0 * grid.1) as usize;
        if known.grid != grid || known.colour != background || known.tiles.len() != tiles {
            *known = KnownBackground {
                colour: background,
                grid,
                tiles: vec![false; tiles],
            };
        }
        (&mut self.color, &mut self.depth, &mut known.tiles)
    }

    /// 8-bit sRGB, row-major, top row first.
    pub fn to_srgb8(&self) -> Vec<[u8; 3]> {
        let mut rgb = vec![[0; 3]; self.color.len()];
        encode_srgb8(
            bytemuck::cast_slice(&self.color),
            bytemuck::cast_slice_mut(&mut rgb),
        );
        rgb
    }
}

/// The sRGB transfer function, exact to within rounding: a 65536-entry table over [0, 1] (the
/// table's step is 1/20 of an 8-bit step at the steepest part of the curve). NaN maps to 0.
#[inline]
pub fn linear_to_srgb8(linear: f32) -> u8 {
    srgb8_table()[usize::from(table_index(linear))]
}

/// `linear_to_srgb8` of every channel in `linear` into `out` (as long), the table fetched once.
/// A block's indices are worked out together (vector code, AVX2 where the CPU has it), then
/// looked up one by one.
pub fn encode_srgb8(linear: &[f32], out: &mut [u8]) {
    assert_eq!(linear.len(), out.len(), "one byte per channel");
    const BLOCK: usize = 64;
    let table = srgb8_table();
    crate::simd::widest(
        #[inline(always)]
        || {
            let mut indices = [0u16; BLOCK];
            let blocks = linear.chunks(BLOCK).zip(out.chunks_mut(BLOCK));
            for (linear, out) in blocks {
                for (index, &x) in indices.iter_mut().zip(linear) {
                    *index = table_index(x);
                }
                for (o, &index) in out.iter_mut().zip(&indices) {
                    *o = table[usize::from(index)];
                }
            }
        },
    );
}

fn srgb8_table() -> &'static [u8; 1 << 16] {
    static TABLE: OnceLock<Box<[u8; 1 << 16]>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut table = Box::new([0; 1 << 16]);
        for (i, code) in table.iter_mut().enumerate() {
            *code = srgb_encode(i as f64 / 65535.0);
        }
        table
    })
}

/// The table entry nearest `linear`; NaN goes to 0. `as` conversions saturate, and the
/// compiler does that one channel at a time, a large share of a plain still; an unchecked
/// conversion of a value known to be in range is one vector instruction for eight.
#[inline(always)]
fn table_index(linear: f32) -> u16 {
    // NaN fails the comparison and goes to 0 (`clamp` would keep it).
    let within = if linear > 0.0 { linear.min(1.0) } else { 0.0 };
    let index = within * 65535.0 + 0.5;
    // SAFETY: `index` is finite and within [0.5, 65535.5], so it fits an i32.
    unsafe { index.to_int_unchecked::<i32>() as u16 }
}

fn srgb_encode(linear: f64) -> u8 {
    let s = if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round().clamp(0.0, 255.0) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_batch_encodes_as_one_channel_at_a_time() {
        // The odd values both in a whole block and in the last, short one.
        let odd = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -0.0, 1.0, 1e-30];
        let linear: Vec<f32> = odd
            .into_iter()
            .chain((0..5000).map(|i| (i as f32 * 0.7919).sin() * 1.2))
            .chain(odd)
            .collect();
        let mut batch = vec![0; linear.len()];
        encode_srgb8(&linear, &mut batch);
        let single: Vec<u8> = linear.iter().map(|&x| linear_to_srgb8(x)).collect();
        assert_eq!(batch, single);
    }

    #[test]
    fn table_index_is_the_saturating_conversion_for_any_float() {
        let saturating = |x: f32| (x.clamp(0.0, 1.0) * 65535.0 + 0.5) as u16;
        let odd = [
            f32::NAN,
            -f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -0.0,
            0.0,
            f32::MIN_POSITIVE / 2.0,
            1.0,
            1.0 + f32::EPSILON,
            f32::MAX,
            -f32::MAX,
            0.5 / 65535.0,
        ];
        let sweep = (0..200_000).map(|i| i as f32 / 150_000.0 - 0.1);
        for x in odd.into_iter().chain(sweep) {
            assert_eq!(table_index(x), saturating(x), "at {x:e}");
        }
    }

    #[test]
    fn srgb_table_matches_the_exact_curve() {
        for i in 0..=10_000 {
            let x = i as f32 / 10_000.0;
            let exact = srgb_encode(x as f64) as i32;
            assert!((linear_to_srgb8(x) as i32 - exact).abs() <= 1, "at {x}");
        }
        assert_eq!(linear_to_srgb8(f32::NAN), 0);
        assert_eq!(linear_to_srgb8(-1.0), 0);
        assert_eq!(linear_to_srgb8(f32::INFINITY), 255);
        assert_eq!(linear_to_srgb8(0.5), 188);
    }
}
