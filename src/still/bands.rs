//! A still rendered a band of rows at a time, each band supersampled by shifted passes and
//! resolved in linear light: memory depends on the band, not on the image.

use super::samples::Supersampling;
use crate::raster::{
    Camera, FragmentShader, FrameStats, Framebuffer, ImageWindow, Interpolation, PreparedScene,
    RenderTarget, TILE_SIZE, Viewport, render_into,
};
use glam::Vec3;
use std::ops::Range;

/// Bytes a band may hold per pixel: the pass framebuffer (colour and depth) and the sum.
const BYTES_PER_BAND_PIXEL: u64 = 28;

/// Rows per band for a `width`-wide image within `budget_bytes`: whole tiles, at least one.
pub fn band_rows(width: u32, height: u32, budget_bytes: u64) -> u32 {
    let rows = budget_bytes / (width.max(1) as u64 * BYTES_PER_BAND_PIXEL);
    let tiles = (rows / TILE_SIZE as u64).max(1) as u32;
    (tiles * TILE_SIZE).min(height.max(1))
}

/// What every band of one still shares.
pub struct BandJob<'a, S> {
    pub prepared: &'a PreparedScene,
    pub camera: &'a Camera,
    pub full: Viewport,
    pub shader: &'a S,
    pub supersampling: Supersampling,
    pub interpolation: Interpolation,
}

/// Memory reused from band to band.
pub struct BandBuffers {
    pass: Framebuffer,
    /// The resolved band: linear RGB, row-major.
    pub resolved: Vec<Vec3>,
}

impl Default for BandBuffers {
    fn default() -> Self {
        BandBuffers {
            pass: Framebuffer::new(0, 0, Vec3::ZERO),
            resolved: Vec::new(),
        }
    }
}

impl<S: FragmentShader> BandJob<'_, S> {
    /// Renders rows `rows` into `buffers.resolved`, one pass per sample, calling `on_pass`
    /// after each. `keep_going` is asked before every pass; when it says no, the band is
    /// abandoned and `None` returned.
    pub fn render(
        &self,
        rows: Range<u32>,
        buffers: &mut BandBuffers,
        keep_going: &dyn Fn() -> bool,
        on_pass: &mut dyn FnMut(),
    ) -> Option<FrameStats> {
        let viewport = Viewport {
            width: self.full.width,
            height: rows.end - rows.start,
        };
        let offsets = self.supersampling.offsets();
        let weight = 1.0 / offsets.len() as f32;
        buffers.resolved.clear();
        buffers.resolved.resize(
            viewport.width as usize * viewport.height as usize,
            Vec3::ZERO,
        );
        let mut stats = FrameStats::default();
        for offset in offsets {
            if !keep_going() {
                return None;
            }
            let target = RenderTarget {
                window: ImageWindow {
                    full: self.full,
                    x0: 0,
                    y0: rows.start,
                    offset,
                },
                footprint: self.supersampling.footprint(),
                ..RenderTarget::new(self.camera, viewport).with_interpolation(self.interpolation)
            };
            let pass = render_into(self.prepared, &target, self.shader, &mut buffers.pass);
            stats = add_stats(stats, pass);
            for (sum, c) in buffers.resolved.iter_mut().zip(&buffers.pass.color) {
                *sum += *c * weight;
            }
            on_pass();
        }
        Some(stats)
    }
}

fn add_stats(a: FrameStats, b: FrameStats) -> FrameStats {
    FrameStats {
        triangles: b.triangles,
        rasterized_triangles: a.rasterized_triangles + b.rasterized_triangles,
        fragments: a.fragments + b.fragments,
        flattened: a.flattened + b.flattened,
    }
}

/// Renders a whole image in memory with supersampling (for views that fit in memory: the
/// workbench's export, benchmarks). The depth is the last pass's.
pub fn render_supersampled<S: FragmentShader>(
    job: &BandJob<S>,
    buffers: &mut BandBuffers,
) -> (Framebuffer, FrameStats) {
    let stats = job
        .render(0..job.full.height, buffers, &|| true, &mut || {})
        .expect("never cancelled");
    let framebuffer = Framebuffer {
        width: job.full.width,
        height: job.full.height,
        color: std::mem::take(&mut buffers.resolved),
        depth: std::mem::take(&mut buffers.pass.depth),
    };
    (framebuffer, stats)
}
