//! A frame's strips of tiles, each rendered by every pass of `render` tile by tile,
//! and handed on as 8-bit sRGB when asked.

use super::bin::{TILE_SIZE, TileBins};
use super::fragment::FragmentShader;
use super::framebuffer::{Blend, encode_srgb8};
use super::interpolation::Interpolation;
use super::pixel_rect::PixelRect;
use super::placed_mesh::PlacedMesh;
use super::refine::{Refine, keep_before, mark_none};
use super::render_target::{RenderTarget, Srgb8Strips};
use super::sample_rays::SampleRays;
use super::screen_triangles::shifted_screen_triangles;
use super::setup::{SampleShift, ScreenTriangle, ShiftSpan, Viewport};
use super::tile::{StripOutput, TileBuffers, TileFrame};
use super::tile_rows::{TileRows, any_wanted};
use super::view_rays::ViewRays;
use super::wanted_spans::WantedSpans;
use glam::Vec3;

/// Rows in a strip: the unit of work a thread takes and of finished rows handed on. Half a
/// tile's height (a strip's tiles are the top or bottom halves of a row of tiles), so a frame's
/// last strips are short and its threads finish close together: with whole tile rows one
/// thread often rendered the last one alone.
pub const STRIP_ROWS: u32 = TILE_SIZE / 2;
const _: () = assert!(TILE_SIZE.is_multiple_of(STRIP_ROWS));

/// The pixels of strip `strip`'s tile `tx`: the part of tile (tx, its tile row) the strip
/// holds, cut to the viewport.
fn strip_tile_rect(viewport: Viewport, tx: u32, strip: u32) -> PixelRect {
    let y0 = strip * STRIP_ROWS;
    PixelRect {
        y0,
        y1: (y0 + STRIP_ROWS).min(viewport.height) - 1,
        ..TileBins::tile_rect(viewport, tx, y0 / TILE_SIZE)
    }
}

/// What every strip of a render shares.
pub(super) struct StripJob<'a, 'o, S: FragmentShader> {
    pub passes: &'a [Pass<'a, 'o, S>],
    pub last: &'a RenderTarget<'a>,
    pub viewport: Viewport,
    pub background: Vec3,
    pub tiles_x: u32,
    /// Where finished strips go as 8-bit sRGB, if anywhere.
    pub finished_strips: Option<&'a Srgb8Strips<'a>>,
    /// Whether the strips' colours go only into their sRGB bytes (`FrameOutput::Strips`).
    pub bytes_only: bool,
    /// The rule the passes refine by, if they do.
    pub refinement: Option<&'a dyn Refine>,
}

/// One strip's share of the framebuffer (empty colour and depth when `bytes_only`).
pub(super) struct StripBuffers<'a> {
    pub color: &'a mut [Vec3],
    pub depth: &'a mut [f32],
    pub known_background: &'a mut [bool],
    /// The strip's part of `Refinement::refined` (empty without one).
    pub refined: &'a mut [bool],
}

impl<S: FragmentShader> StripJob<'_, '_, S> {
    /// Renders every pass of strip `index`, tile by tile, and hands its bytes on if asked; the
    /// fragments shaded and flattened.
    pub fn render(
        &self,
        index: u32,
        strip: StripBuffers,
        tile: &mut TileBuffers,
        scratch: &mut S::Scratch,
    ) -> (usize, usize) {
        let width = self.viewport.width;
        let rows = (self.viewport.height - index * STRIP_ROWS).min(STRIP_ROWS);
        let first = (index * STRIP_ROWS * width) as usize;
        let pixels = (rows * width) as usize;
        let mask = self.last.mask.map(|m| &m[first..first + pixels]);
        let mut bytes = self.finished_strips.map(|strips| {
            let mut bytes = (strips.buffer)();
            bytes.resize(pixels * 3, 0);
            bytes
        });
        let mut counts = (0, 0);
        let StripBuffers {
            color,
            depth,
            known_background,
            refined,
        } = strip;
        for (tx, known_background) in (0..self.tiles_x).zip(known_background) {
            let rect = strip_tile_rect(self.viewport, tx, index);
            let first_row = rect.y0;
            let tile_rows = TileRows {
                width,
                first_row,
                rect: &rect,
            };
            if any_wanted(mask, &tile_rows) {
                for (k, pass) in self.passes.iter().enumerate() {
                    let mut wanted = mask;
                    if let Some(rule) = self.refinement {
                        if k == 0 {
                            keep_before(color, &tile_rows, &mut tile.before);
                        }
                        if k == rule.first_decided_pass() {
                            rule.decide(color, &tile.before, mask, refined, &tile_rows);
                            if !any_wanted(Some(refined), &tile_rows) {
                                break;
                            }
                        }
                        if k >= rule.first_decided_pass() {
                            wanted = Some(&*refined);
                        }
                    }
                    let out = StripOutput {
                        color: &mut *color,
                        depth: &mut *depth,
                        srgb8: bytes.as_deref_mut().filter(|_| self.bytes_only),
                        width,
                        first_row,
                        background: self.background,
                        mask: wanted,
                        blend: pass.target.blend,
                        writes_depth: pass.target.writes_depth,
                    };
                    let (shaded, flattened) =
                        pass.render_tile(tx, &rect, known_background, tile, scratch, out);
                    counts = (counts.0 + shaded, counts.1 + flattened);
                }
            } else if self.refinement.is_some() {
                mark_none(refined, &tile_rows);
            }
            if let Some(bytes) = bytes.as_deref_mut().filter(|_| !self.bytes_only) {
                encode_tile(color, width, &rect, bytes);
            }
        }
        if let (Some(strips), Some(bytes)) = (self.finished_strips, bytes) {
            (strips.finished)(index as usize, bytes);
        }
        counts
    }
}

/// The pixels of `rect` in a strip of `width`-pixel rows starting at the rect's first row, as
/// 8-bit sRGB into the strip's `bytes`.
fn encode_tile(color: &[Vec3], width: u32, rect: &PixelRect, bytes: &mut [u8]) {
    let first_row = rect.y0;
    for y in rect.y0..=rect.y1 {
        let start = ((y - first_row) * width + rect.x0) as usize;
        let pixels = start..start + (rect.x1 - rect.x0 + 1) as usize;
        let linear = bytemuck::cast_slice(&color[pixels.clone()]);
        encode_srgb8(linear, &mut bytes[pixels.start * 3..pixels.end * 3]);
    }
}

/// The triangles of `render` set up once and binned, shared by all its passes, which
/// differ only in where they sample in each pixel: each triangle's bounds hold the pixels
/// whose sample point falls in its box in any of the passes.
pub(super) struct SetUp {
    pub triangles: Vec<ScreenTriangle>,
    pub bins: TileBins,
}

impl SetUp {
    /// For `targets`, passes that share everything with `last` but their sample shifts (see
    /// `render`).
    pub fn new(
        objects: &[impl PlacedMesh],
        targets: &[RenderTarget],
        last: &RenderTarget,
    ) -> SetUp {
        let span = ShiftSpan::of(targets.iter().map(|t| SampleShift::new(t.window.offset)));
        let triangles = shifted_screen_triangles(objects, last, &span);
        let bins = TileBins::new(last.viewport, &triangles);
        SetUp { triangles, bins }
    }
}

/// One pass of `render`: its target and the triangles all its passes share.
pub(super) struct Pass<'a, 'o, S: FragmentShader> {
    pub target: &'a RenderTarget<'a>,
    pub triangles: &'a [ScreenTriangle],
    pub bins: &'a TileBins,
    frame: TileFrame<'a, 'o, S>,
    /// Whether a tile's known background (colour and depth) can be relied on and recorded: only
    /// when this pass writes every pixel, colour and depth, and replaces what was there.
    whole_and_replacing: bool,
}

impl<'a, 'o, S: FragmentShader> Pass<'a, 'o, S> {
    pub fn new(
        objects: &'a [S::Object<'o>],
        set_up: &'a SetUp,
        target: &'a RenderTarget<'a>,
        shader: &'a S,
        derivatives: &'a [bool],
    ) -> Pass<'a, 'o, S> {
        let shift = SampleShift::new(target.window.offset);
        let window = &target.window;
        let view_rays = ViewRays::new(target.camera, window.full);
        let offset = shift.pixels.as_dvec2();
        let corner = (window.x0, window.y0);
        let rays = SampleRays::new(&view_rays, target.camera, corner, offset, target.footprint);
        Pass {
            triangles: &set_up.triangles,
            bins: &set_up.bins,
            target,
            frame: TileFrame {
                objects,
                shader,
                perspective: target.interpolation == Interpolation::PerspectiveCorrect,
                footprint: target.footprint,
                derivatives,
                shift,
                rays,
            },
            whole_and_replacing: target.mask.is_none()
                && target.blend == Blend::Replace
                && target.writes_depth,
        }
    }

    /// Renders `rect`, strip `out`'s part of tile `tx`; the fragments shaded and flattened.
    fn render_tile(
        &self,
        tx: u32,
        rect: &PixelRect,
        known_background: &mut bool,
        tile: &mut TileBuffers,
        scratch: &mut S::Scratch,
        out: StripOutput,
    ) -> (usize, usize) {
        let ty = rect.y0 / TILE_SIZE;
        let bin = self.bins.bin(tx, ty);
        if bin.is_empty() {
            if !(self.whole_and_replacing && *known_background) {
                out.fill_background(rect);
            }
            *known_background = self.whole_and_replacing;
            return (0, 0);
        }
        let rows = TileRows {
            width: out.width,
            first_row: out.first_row,
            rect,
        };
        let wanted = out.mask.map(|mask| WantedSpans::of(mask, &rows));
        tile.resolve_visibility(
            self.triangles,
            bin,
            rect,
            &self.frame.shift,
            wanted.as_ref(),
        );
        let (shaded, flattened) = tile.shade(self.triangles, &self.frame, scratch, rect, out);
        *known_background = shaded == 0 && self.whole_and_replacing;
        (shaded, flattened)
    }
}
