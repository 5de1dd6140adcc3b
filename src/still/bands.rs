//! A still rendered a band of rows at a time, each band supersampled by shifted passes and
//! resolved in linear light: memory depends on the band, not on the image.

use super::contrast::contrast_mask;
use super::refine_rule::RefineRule;
use super::samples::Supersampling;
use crate::raster::{
    Blend, FrameOutput, FrameStats, Framebuffer, ImageWindow, Interpolation, Refinement,
    RenderTarget, ScreenTriangle, Srgb8Strips, TILE_SIZE, Viewport,
};
use crate::render::{SceneShader, render_scene};
use crate::scene::Camera;
use crate::scene::PreparedScene;
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

impl<S: SceneShader> BandJob<'_, S> {
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
        let band = Band {
            job: self,
            viewport: Viewport {
                width: self.full.width,
                height: rows.end - rows.start,
            },
            rows,
            finished_strips,
        };
        let samples = self.sample_order();
        let mut stats = FrameStats::default();
        let mut marked = None;
        match self.opening() {
            Opening::Single | Opening::Centre { .. } if !keep_going() => return None,
            Opening::Single => {
                let stats = band.single(samples.offsets[0], buffers);
                on_pass();
                return Some(stats);
            }
            Opening::Centre { footprint } => {
                let (centre, count) = band.centre(footprint, buffers);
                (stats, marked) = (centre, Some(count));
                on_pass();
            }
            Opening::SamplesOnly => {}
        }
        let rendered =
            marked.unwrap_or(band.viewport.width as usize * band.viewport.height as usize);
        let per_group = passes_per_group(rendered, self.prepared.triangle_count());
        for group in sample_groups(&samples, marked.is_some(), per_group) {
            if !keep_going() {
                return None;
            }
            stats = add_stats(stats, band.passes(&group, &samples, buffers));
            group.passes.for_each(|_| on_pass());
        }
        Some(stats)
    }

    /// The sample passes' order and how they meet: the supersampling offsets, or the refining
    /// order of adaptive supersampling that refines.
    fn sample_order(&self) -> SampleOrder {
        let refining = self
            .adaptive_threshold()
            .and(self.supersampling.refining_order());
        match refining {
            Some(order) => SampleOrder {
                offsets: order.offsets,
                first: Some(order.first),
                centre_weight: order.centre_weight,
            },
            None => SampleOrder {
                offsets: self.supersampling.offsets(),
                first: None,
                centre_weight: 0.0,
            },
        }
    }

    /// How the band's render begins: the whole band in one pass, the centre pass of adaptive
    /// supersampling, or straight with the sample passes.
    fn opening(&self) -> Opening {
        let footprint = self.supersampling.footprint();
        match self.adaptive_threshold() {
            None if self.supersampling.offsets().len() == 1 => Opening::Single,
            None => Opening::SamplesOnly,
            // A refining still mixes the centre with its samples, and leaves it where it marks
            // nothing as their stand-in: it samples textures as they do (less error than a
            // pixel-wide footprint, simulated on the POV-Ray peer's frame). The tent's samples
            // spread over two pixels' width.
            Some(_) if self.supersampling.refining_order().is_some() => {
                Opening::Centre { footprint }
            }
            Some(_) => Opening::Centre { footprint: 1.0 },
        }
    }
}

/// How a band's render begins.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Opening {
    /// One pass at the only sample, replacing every pixel: the whole band.
    Single,
    /// A pass at pixel centres, whose contrast marks the pixels the samples go to.
    Centre { footprint: f32 },
    /// Nothing before the sample passes.
    SamplesOnly,
}

/// Sample passes `passes` of the sample order, rendered together over `pixels`; with
/// `refine_from`, the passes from that one on take only the pixels the earlier ones moved.
#[derive(Clone, Debug, PartialEq)]
struct SampleGroup {
    passes: Range<usize>,
    pixels: Pixels,
    refine_from: Option<usize>,
}

/// Which pixels a group of sample passes renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Pixels {
    All,
    /// Those the centre pass marked.
    Marked,
    /// Those an earlier group's refinement refined.
    Refined,
}

/// The sample passes in the order they are rendered.
struct SampleOrder {
    offsets: Vec<Vec2>,
    /// Refining: how many samples come before the decision to take the rest.
    first: Option<usize>,
    /// Refining: the centre's share in a pixel that stops after its first samples.
    centre_weight: f32,
}

/// The groups of sample passes, `per_group` passes each (the first of a refining order holds
/// its first samples and the pass after them, where the refinement is decided), over the
/// marked pixels when `adaptive`.
fn sample_groups(order: &SampleOrder, adaptive: bool, per_group: usize) -> Vec<SampleGroup> {
    let count = order.offsets.len();
    let mut groups = Vec::new();
    let mut start = 0;
    while start < count {
        let size = match order.first {
            Some(first) if start == 0 => per_group.max(first + 1),
            _ => per_group,
        };
        let end = (start + size).min(count);
        let (pixels, refine_from) = match (order.first, start) {
            (Some(first), 0) => (Pixels::Marked, Some(first)),
            (Some(_), _) => (Pixels::Refined, None),
            (None, _) if adaptive => (Pixels::Marked, None),
            (None, _) => (Pixels::All, None),
        };
        groups.push(SampleGroup {
            passes: start..end,
            pixels,
            refine_from,
        });
        start = end;
    }
    groups
}

/// One band of a job, rendering its steps.
struct Band<'a, 'j, S> {
    job: &'a BandJob<'j, S>,
    rows: Range<u32>,
    viewport: Viewport,
    finished_strips: Option<&'a Srgb8Strips<'a>>,
}

impl<S: SceneShader> Band<'_, '_, S> {
    /// A pass of the band sampling at `offset` with `footprint`.
    fn target(&self, offset: Vec2, footprint: f32, blend: Blend) -> RenderTarget<'_> {
        RenderTarget {
            window: ImageWindow {
                full: self.job.full,
                x0: 0,
                y0: self.rows.start,
                offset,
            },
            footprint,
            blend,
            ..RenderTarget::new(self.job.camera, self.viewport)
                .with_interpolation(self.job.interpolation)
        }
    }

    /// The whole band in one pass: straight into the strips when they are asked for (no
    /// framebuffer needed), else into the band's framebuffer with its depth.
    fn single(&self, offset: Vec2, buffers: &mut BandBuffers) -> FrameStats {
        let footprint = self.job.supersampling.footprint();
        let target = RenderTarget {
            writes_depth: self.finished_strips.is_none(),
            ..self.target(offset, footprint, Blend::Replace)
        };
        let output = match self.finished_strips {
            Some(strips) => FrameOutput::Strips(strips),
            None => FrameOutput::Framebuffer(&mut buffers.frame),
        };
        render_scene(self.job.prepared, &[target], self.job.shader, output, None)
    }

    /// The centre pass and its contrast mask (the band's outer rows marked wholly where another
    /// band lies beyond: they cannot see across the border); the pixels marked.
    fn centre(&self, footprint: f32, buffers: &mut BandBuffers) -> (FrameStats, usize) {
        let threshold = self.job.adaptive_threshold().expect("adaptive");
        let centre = self.target(Vec2::ZERO, footprint, Blend::Replace);
        let output = FrameOutput::Framebuffer(&mut buffers.frame);
        let stats = render_scene(self.job.prepared, &[centre], self.job.shader, output, None);
        contrast_mask(&buffers.frame, threshold, &mut buffers.mask);
        let (width, pixels) = (self.viewport.width as usize, buffers.mask.len());
        if self.rows.start > 0 {
            buffers.mask[..width].fill(true);
        }
        if self.rows.end < self.job.full.height {
            buffers.mask[pixels - width..].fill(true);
        }
        let marked = buffers.mask.iter().filter(|&&m| m).count();
        (stats, marked)
    }

    /// A group of sample passes. Each adds its weighted sample (`pass_blend`); the band's last
    /// pass hands its strips on and, when nobody takes them, leaves the band's depth.
    fn passes(
        &self,
        group: &SampleGroup,
        order: &SampleOrder,
        buffers: &mut BandBuffers,
    ) -> FrameStats {
        let SampleGroup {
            passes,
            pixels,
            refine_from,
        } = group;
        let count = order.offsets.len();
        let footprint = self.job.supersampling.footprint();
        let BandBuffers {
            frame,
            mask,
            refined,
        } = buffers;
        // The refinement writes its decisions into the reused buffer, which no pass of its own
        // group reads (they are over the marked pixels).
        let mut decided = match refine_from {
            Some(_) => std::mem::take(refined),
            None => Vec::new(),
        };
        let wanted = match pixels {
            Pixels::All => None,
            Pixels::Marked => Some(&mask[..]),
            Pixels::Refined => Some(&refined[..]),
        };
        let group: Vec<RenderTarget> = passes
            .clone()
            .map(|k| RenderTarget {
                mask: wanted,
                writes_depth: k == count - 1 && self.finished_strips.is_none(),
                ..self.target(
                    order.offsets[k],
                    footprint,
                    pass_blend(k, count, order.first),
                )
            })
            .collect();
        let output = match self.finished_strips.filter(|_| passes.end == count) {
            Some(strips) => FrameOutput::FramebufferAndStrips(frame, strips),
            None => FrameOutput::Framebuffer(frame),
        };
        let rule = refine_from.map(|from| RefineRule {
            from_pass: from,
            threshold: self.job.adaptive_threshold().unwrap_or_default() * REFINE_CONTRAST,
            centre_weight: order.centre_weight,
        });
        let refinement = rule.as_ref().map(|rule| Refinement {
            rule,
            refined: &mut decided,
        });
        let stats = render_scene(
            self.job.prepared,
            &group,
            self.job.shader,
            output,
            refinement,
        );
        if refine_from.is_some() {
            *refined = decided;
        }
        stats
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
pub fn render_supersampled<S: SceneShader>(
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

    fn order(count: usize, first: Option<usize>) -> SampleOrder {
        SampleOrder {
            offsets: vec![Vec2::ZERO; count],
            first,
            centre_weight: 0.0,
        }
    }

    fn groups(steps: &[SampleGroup]) -> Vec<(Range<usize>, Pixels, Option<usize>)> {
        steps
            .iter()
            .map(|g| (g.passes.clone(), g.pixels, g.refine_from))
            .collect()
    }

    #[test]
    fn sample_passes_are_planned_in_groups_that_cover_every_sample_once() {
        use Pixels::*;
        // Full supersampling: groups of the size asked, over every pixel.
        let full = groups(&sample_groups(&order(16, None), false, 6));
        assert_eq!(
            full,
            [(0..6, All, None), (6..12, All, None), (12..16, All, None)]
        );
        // Adaptive: the same groups over the marked pixels.
        let marked = groups(&sample_groups(&order(16, None), true, 16));
        assert_eq!(marked, [(0..16, Marked, None)]);
        // Refining: the first group holds the first samples and the pass that decides, over
        // the marked pixels; the rest go to the refined ones.
        let refining = groups(&sample_groups(&order(16, Some(4)), true, 2));
        assert_eq!(refining[0], (0..5, Marked, Some(4)));
        assert!(
            refining[1..]
                .iter()
                .all(|(_, p, r)| *p == Refined && r.is_none())
        );
        let covered: Vec<usize> = refining.iter().flat_map(|(r, _, _)| r.clone()).collect();
        assert_eq!(covered, (0..16).collect::<Vec<_>>());
    }

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
