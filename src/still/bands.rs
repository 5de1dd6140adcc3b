//! A still rendered a band of rows at a time, each band supersampled by shifted passes and
//! resolved in linear light: memory depends on the band, not on the image.

use super::contrast::contrast_mask;
use super::samples::Supersampling;
use crate::raster::{
    Blend, FragmentShader, FrameOutput, FrameStats, Framebuffer, ImageWindow, Interpolation,
    PreparedScene, RefineRule, Refinement, RenderTarget, ScreenTriangle, Srgb8Strips, TILE_SIZE,
    Viewport, render,
};
use crate::scene::Camera;
use glam::{Vec2, Vec3};
use std::ops::Range;

/// Band memory for a streamed still: a 7680-wide band of 576 rows at 28 bytes a pixel.
pub const BAND_BUDGET_BYTES: u64 = 128 << 20;

/// Bytes a band may hold per pixel: the framebuffer its passes add into (colour and depth), the
/// adaptive mask and the refined pixels. Not counted: the band's 8-bit rows waiting for the
/// still's writer, at most 3 more a pixel and in practice under half of that.
const BYTES_PER_BAND_PIXEL: u64 = 18;

/// Supersampling passes are rendered a group at a time, tile by tile (`raster::render`): the
/// more passes a group holds, the less often a tile's pixels and texels leave the cache, but
/// passes are cancelled and reported a group at a time, and each pass of a group holds its set-up
/// triangles. A group renders at most this many pixels times passes (eight passes of a 1080p
/// band, about a third of a second at 16 samples; adaptive passes count their marked pixels)…
const PIXEL_PASSES_PER_GROUP: usize = 8 * 1920 * 1080;

/// …and its passes' triangles take at most this many bytes.
const TRIANGLE_BYTES_PER_GROUP: usize = 64 << 20;

/// When adaptive supersampling refines (`Supersampling::refining_order`), a marked pixel gets
/// the rest of its samples where its first samples' mean is more than this times the contrast
/// from its centre: the value that took the fewest samples for POV-Ray's error in a
/// simulation on the POV-Ray peer's frame.
const REFINE_CONTRAST: f32 = 0.4;

/// Rows per band for a `width`-wide image within `budget_bytes`: whole tiles, at least one.
pub fn band_rows(width: u32, height: u32, budget_bytes: u64) -> u32 {
    let rows = budget_bytes / (width.max(1) as u64 * BYTES_PER_BAND_PIXEL);
    let tiles = (rows / TILE_SIZE as u64).max(1) as u32;
    (tiles * TILE_SIZE).min(height.max(1))
}

/// What a `width`×`height` still streamed within `BAND_BUDGET_BYTES` holds at most: its band,
/// and that band's 8-bit rows waiting for the writer.
pub fn band_bytes(width: u32, height: u32) -> u64 {
    let rows = band_rows(width, height, BAND_BUDGET_BYTES);
    u64::from(rows) * u64::from(width) * (BYTES_PER_BAND_PIXEL + 3)
}

/// What every band of one still shares.
pub struct BandJob<'a, S> {
    pub prepared: &'a PreparedScene,
    pub camera: &'a Camera,
    pub full: Viewport,
    pub shader: &'a S,
    pub supersampling: Supersampling,
    pub interpolation: Interpolation,
    /// Adaptive supersampling's contrast threshold (`Quality::adaptive_samples`); `None`
    /// supersamples every pixel.
    pub adaptive: Option<f32>,
}

/// Memory reused from band to band.
pub struct BandBuffers {
    /// The band: each pass adds its weighted samples into it, in place (linear RGB, row-major).
    /// Its depth is the last pass's at each pixel.
    frame: Framebuffer,
    /// Adaptive supersampling: the pixels that get every sample, or (when it refines) the
    /// first samples.
    mask: Vec<bool>,
    /// Refining adaptive supersampling: the marked pixels that get the rest of their samples.
    refined: Vec<bool>,
}

impl Default for BandBuffers {
    fn default() -> Self {
        BandBuffers {
            frame: Framebuffer::new(0, 0, Vec3::ZERO),
            mask: Vec::new(),
            refined: Vec::new(),
        }
    }
}

impl BandBuffers {
    /// The last band rendered, resolved: linear RGB, row-major.
    pub fn resolved(&self) -> &[Vec3] {
        self.frame.color()
    }
}

impl<S: FragmentShader> BandJob<'_, S> {
    /// The contrast threshold when this job shades pixel centres first and supersamples only
    /// where they differ (adaptive, and more than one sample).
    fn adaptive_threshold(&self) -> Option<f32> {
        self.adaptive.filter(|_| self.supersampling.samples > 1)
    }

    /// Passes per band: one per sample, and the centre pass of adaptive supersampling.
    pub fn passes_per_band(&self) -> usize {
        self.supersampling.offsets().len() + usize::from(self.adaptive_threshold().is_some())
    }

    /// Renders rows `rows` into `buffers` (read back with `resolved`), one pass per sample, the
    /// supersampling passes a group at a time (`passes_per_group`), calling `on_pass` once per
    /// pass as each group ends. `keep_going` is asked before every group; when it says no, the
    /// band is abandoned and `None` returned. `finished_strips` hears each strip of the band
    /// as the last pass finishes it (see `FrameOutput`); a caller that takes
    /// the strips does not get the band's depth (no pass writes it but an adaptive centre pass,
    /// whose depth the contrast mask reads). Otherwise the depth is the last pass's: the only
    /// supersampling pass that writes it is the last.
    pub fn render(
        &self,
        rows: Range<u32>,
        buffers: &mut BandBuffers,
        keep_going: &dyn Fn() -> bool,
        on_pass: &mut dyn FnMut(),
        finished_strips: Option<&Srgb8Strips<'_>>,
    ) -> Option<FrameStats> {
        let viewport = Viewport {
            width: self.full.width,
            height: rows.end - rows.start,
        };
        let offsets = self.supersampling.offsets();
        let target = |offset, footprint, mask, blend| RenderTarget {
            window: ImageWindow {
                full: self.full,
                x0: 0,
                y0: rows.start,
                offset,
            },
            footprint,
            mask,
            blend,
            ..RenderTarget::new(self.camera, viewport).with_interpolation(self.interpolation)
        };
        // The pass that finishes the band hands its strips on and, when nobody takes them,
        // leaves the band's depth; supersampling passes before it write no depth.
        let finishing = |target| RenderTarget {
            writes_depth: finished_strips.is_none(),
            ..target
        };
        let adaptive = self.adaptive_threshold();
        if offsets.len() == 1 && adaptive.is_none() {
            if !keep_going() {
                return None;
            }
            let footprint = self.supersampling.footprint();
            let target = finishing(target(offsets[0], footprint, None, Blend::Replace));
            // One pass handing its strips on needs no framebuffer.
            let output = match finished_strips {
                Some(strips) => FrameOutput::Strips(strips),
                None => FrameOutput::Framebuffer(&mut buffers.frame),
            };
            let stats = render(self.prepared, &[target], self.shader, output, None);
            on_pass();
            return Some(stats);
        }
        let mut stats = FrameStats::default();
        let mut mask = std::mem::take(&mut buffers.mask);
        let refining = adaptive.and(self.supersampling.refining_order());
        let footprint = self.supersampling.footprint();
        if let Some(threshold) = adaptive {
            if !keep_going() {
                return None;
            }
            // A refining still mixes the centre with its samples, and leaves it where it marks
            // nothing as their stand-in: it samples textures as they do (less error than a
            // pixel-wide footprint, simulated on the POV-Ray peer's frame). The tent's samples
            // spread over two pixels' width.
            let centre_footprint = if refining.is_some() { footprint } else { 1.0 };
            let centre = target(Vec2::ZERO, centre_footprint, None, Blend::Replace);
            let output = FrameOutput::Framebuffer(&mut buffers.frame);
            stats = render(self.prepared, &[centre], self.shader, output, None);
            contrast_mask(&buffers.frame, threshold, &mut mask);
            // A band's outer rows cannot see across the band's border: sample them fully
            // where another band lies beyond (at most 2 rows in 64).
            let (width, pixels) = (viewport.width as usize, mask.len());
            if rows.start > 0 {
                mask[..width].fill(true);
            }
            if rows.end < self.full.height {
                mask[pixels - width..].fill(true);
            }
            on_pass();
        }
        let (offsets, first_samples, centre_weight) = match refining {
            Some(order) => (order.offsets, Some(order.first), order.centre_weight),
            None => (offsets, None, 0.0),
        };
        let count = offsets.len();
        let only = adaptive.map(|_| &mask[..]);
        let blend = |k: usize| pass_blend(k, count, first_samples);
        let pass = |k: usize| {
            let pass = target(offsets[k], footprint, None, blend(k));
            if k == count - 1 {
                finishing(pass)
            } else {
                RenderTarget {
                    writes_depth: false,
                    ..pass
                }
            }
        };
        // Passes render only the marked pixels when adaptive: groups are sized by those.
        let rendered = match adaptive {
            Some(_) => mask.iter().filter(|&&marked| marked).count(),
            None => viewport.width as usize * viewport.height as usize,
        };
        let per_group = passes_per_group(rendered, self.prepared.triangle_count());
        let mut refined = std::mem::take(&mut buffers.refined);
        let mut start = 0;
        while start < count {
            if !keep_going() {
                return None;
            }
            // A refinement is decided within the group that holds its first samples and the
            // first of the rest; later groups refine the pixels it recorded.
            let size = match first_samples {
                Some(first) if start == 0 => per_group.max(first + 1),
                _ => per_group,
            };
            let end = (start + size).min(count);
            let mut group: Vec<RenderTarget> = (start..end).map(pass).collect();
            let (prepared, shader, frame) = (self.prepared, self.shader, &mut buffers.frame);
            let output = match finished_strips.filter(|_| end == count) {
                Some(strips) => FrameOutput::FramebufferAndStrips(frame, strips),
                None => FrameOutput::Framebuffer(frame),
            };
            let done = match first_samples {
                Some(first) if start == 0 => {
                    group.iter_mut().for_each(|pass| pass.mask = only);
                    let refinement = Refinement {
                        rule: RefineRule {
                            from_pass: first,
                            threshold: adaptive.unwrap_or_default() * REFINE_CONTRAST,
                            centre_weight,
                        },
                        refined: &mut refined,
                    };
                    render(prepared, &group, shader, output, Some(refinement))
                }
                later => {
                    // Groups after a refining one render the pixels it refined.
                    let mask = if later.is_some() {
                        Some(&refined[..])
                    } else {
                        only
                    };
                    group.iter_mut().for_each(|pass| pass.mask = mask);
                    render(prepared, &group, shader, output, None)
                }
            };
            stats = add_stats(stats, done);
            (start..end).for_each(|_| on_pass());
            start = end;
        }
        buffers.refined = refined;
        buffers.mask = mask;
        Some(stats)
    }
}

/// How many supersampling passes of a band of `pixels` are rendered together, for a scene of
/// `triangles` triangles: at least one.
fn passes_per_group(pixels: usize, triangles: usize) -> usize {
    let by_pixels = PIXEL_PASSES_PER_GROUP / pixels.max(1);
    let by_triangles = TRIANGLE_BYTES_PER_GROUP / (triangles * size_of::<ScreenTriangle>()).max(1);
    by_pixels.min(by_triangles).max(1)
}

/// How pass `k` of `count` meets the band: the first replaces (marked) pixels with its weighted
/// sample and the others add theirs, so unmarked pixels keep their centre. When the first
/// `first` samples come before a refinement, they make their own mean, and the pass after them
/// turns it into their share of the mean of all (`Blend::Rescale`).
fn pass_blend(k: usize, count: usize, first_samples: Option<usize>) -> Blend {
    let weight = |n: usize| 1.0 / n as f32;
    match first_samples {
        Some(first) if k == 0 => Blend::Scale(weight(first)),
        Some(first) if k < first => Blend::Add(weight(first)),
        Some(first) if k == first => Blend::Rescale {
            kept: first as f32 / count as f32,
            weight: weight(count),
        },
        _ if k == 0 => Blend::Scale(weight(count)),
        _ => Blend::Add(weight(count)),
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
        .render(0..job.full.height, buffers, &|| true, &mut || {}, None)
        .expect("never cancelled");
    let framebuffer = std::mem::replace(&mut buffers.frame, Framebuffer::new(0, 0, Vec3::ZERO));
    (framebuffer, stats)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_hold_fewer_passes_as_bands_and_meshes_grow() {
        let hd = 1920 * 1080;
        // The POV-Ray peer's scene (16 130 triangles) at 1080p, then in an 8K still's bands.
        assert_eq!(passes_per_group(hd, 16_130), 8);
        assert_eq!(passes_per_group(7680 * 1024, 16_130), 2);
        // An adaptive 1080p still marking a fifth of its pixels: all 16 passes in one group.
        assert!(passes_per_group(hd / 5, 16_130) >= 16);
        // A sphere tessellated at the densest setting: one pass at a time.
        assert_eq!(passes_per_group(hd, 4096 * 2048 * 2), 1);
        assert_eq!(
            passes_per_group(0, 0),
            PIXEL_PASSES_PER_GROUP.min(TRIANGLE_BYTES_PER_GROUP)
        );
        assert!(passes_per_group(64 * 64, 100) >= 16);
    }
}
