//! A tile's two passes: resolve which triangle is nearest at each pixel, then shade the visible
//! pixels as one batch.

use super::bin::TILE_SIZE;
use super::fragment::{Fragment, FragmentShader};
use super::framebuffer::{Blend, encode_srgb8, linear_to_srgb8};
use super::pixel_rect::PixelRect;
use super::row_cover::{COVER_LANES, CoverPath, RowNearest, padded_len};
use super::row_runs::{PixelKind, RowRuns};
use super::sample_rays::SampleRays;
use super::scan::triangle_rows;
use super::setup::{AttributePlane, SampleShift, ScreenTriangle};
use super::wanted_spans::WantedSpans;
use glam::{Vec2, Vec3};
use std::ops::Range;

const TILE_PIXELS: usize = (TILE_SIZE * TILE_SIZE) as usize;

/// A tile's visibility: the nearest triangle per pixel, by interpolated 1/w (greater is nearer,
/// and f32 keeps its precision best near 0, i.e. far away: the "reversed-z" trick).
pub struct TileBuffers {
    /// 0 where nothing was drawn.
    inv_w: Vec<f32>,
    /// Meaningful only where `inv_w` is positive (see `nearest`).
    triangle: Vec<u32>,
    /// The batch being shaded, and where each of its fragments goes.
    fragments: Vec<Fragment>,
    /// The framebuffer pixels of the batch's fragments, as runs along rows.
    visible_runs: Vec<Range<usize>>,
    colors: Vec<Vec3>,
    /// A refining group's colours of the tile before its first pass (see `Refinement`).
    pub before: Vec<Vec3>,
}

impl Default for TileBuffers {
    fn default() -> Self {
        TileBuffers {
            // Padded: a row's last lane of depth tests may reach past the tile's last slot.
            inv_w: vec![0.0; TILE_PIXELS + COVER_LANES],
            triangle: vec![0; TILE_PIXELS + COVER_LANES],
            fragments: Vec::with_capacity(TILE_PIXELS),
            visible_runs: Vec::with_capacity(TILE_PIXELS),
            colors: Vec::with_capacity(TILE_PIXELS),
            before: Vec::new(),
        }
    }
}

/// The rows of the framebuffer one tile row writes to.
pub struct StripOutput<'a> {
    pub color: &'a mut [Vec3],
    pub depth: &'a mut [f32],
    /// When given, colours go here as 8-bit sRGB (3 bytes a pixel, row-major) instead of into
    /// `color`: for a lone replacing pass whose only output is the encoded strip.
    pub srgb8: Option<&'a mut [u8]>,
    pub width: u32,
    pub first_row: u32,
    pub background: Vec3,
    /// The strip's pixels to write (`None`: all); see `RenderTarget::mask`.
    pub mask: Option<&'a [bool]>,
    pub blend: Blend,
    /// See `RenderTarget::writes_depth`.
    pub writes_depth: bool,
}

impl StripOutput<'_> {
    /// Writes the background over the wanted pixels of `rect`.
    pub fn fill_background(mut self, rect: &PixelRect) {
        const NOTHING_DRAWN: [f32; TILE_SIZE as usize] = [0.0; TILE_SIZE as usize];
        let width = (rect.x1 - rect.x0 + 1) as usize;
        for y in rect.y0..=rect.y1 {
            let row = ((y - self.first_row) * self.width) as usize + rect.x0 as usize;
            let wanted = self.mask.map(|mask| &mask[row..row + width]);
            for (_, xs) in RowRuns::new(&NOTHING_DRAWN[..width], wanted) {
                self.background_run(row + xs.start as usize..row + xs.end as usize);
            }
        }
    }

    /// Writes the background over `pixels`.
    fn background_run(&mut self, pixels: Range<usize>) {
        if let Some(bytes) = self.srgb8.as_deref_mut() {
            let encoded = self.background.to_array().map(linear_to_srgb8);
            for pixel in bytes[pixels.start * 3..pixels.end * 3].chunks_exact_mut(3) {
                pixel.copy_from_slice(&encoded);
            }
            return;
        }
        let colors = &mut self.color[pixels.clone()];
        match self.blend {
            Blend::Replace => fill_colour(colors, self.background),
            Blend::Scale(weight) => fill_colour(colors, self.background * weight),
            Blend::Add(weight) => {
                let added = self.background * weight;
                colors.iter_mut().for_each(|c| *c += added);
            }
            Blend::Rescale { kept, weight } => {
                let added = self.background * weight;
                colors.iter_mut().for_each(|c| *c = *c * kept + added);
            }
        }
        if self.writes_depth {
            self.depth[pixels].fill(f32::INFINITY);
        }
    }

    /// Writes shaded fragments over `runs` of pixels, as many as the runs hold, in order.
    fn shaded_runs(&mut self, runs: &[Range<usize>], fragments: &[Fragment], colors: &[Vec3]) {
        if let Some(bytes) = self.srgb8.as_deref_mut() {
            debug_assert!(self.blend == Blend::Replace && !self.writes_depth);
            // The runs take the colours in order, one per pixel.
            let mut first = 0;
            for pixels in runs {
                let n = pixels.len().min(colors.len() - first);
                let linear = bytemuck::cast_slice(&colors[first..first + n]);
                let start = pixels.start * 3;
                encode_srgb8(linear, &mut bytes[start..start + 3 * n]);
                first += n;
            }
            return;
        }
        match self.blend {
            Blend::Replace => self.put_runs(runs, fragments, colors, |pixel, c| *pixel = c),
            Blend::Scale(weight) => {
                self.put_runs(runs, fragments, colors, |pixel, c| *pixel = c * weight)
            }
            Blend::Add(weight) => {
                self.put_runs(runs, fragments, colors, |pixel, c| *pixel += c * weight)
            }
            Blend::Rescale { kept, weight } => {
                self.put_runs(runs, fragments, colors, |pixel, c| {
                    *pixel = *pixel * kept + c * weight
                })
            }
        }
    }

    /// `put_shaded`, compiled with or without the depth stores as the render asks.
    #[inline(always)]
    fn put_runs(
        &mut self,
        runs: &[Range<usize>],
        fragments: &[Fragment],
        colors: &[Vec3],
        put: impl Fn(&mut Vec3, Vec3),
    ) {
        if self.writes_depth {
            self.put_shaded::<true>(runs, fragments, colors, put)
        } else {
            self.put_shaded::<false>(runs, fragments, colors, put)
        }
    }

    /// Puts the colours (and, with `DEPTH`, the depths) of the fragments over the runs.
    #[inline(always)]
    fn put_shaded<const DEPTH: bool>(
        &mut self,
        runs: &[Range<usize>],
        fragments: &[Fragment],
        colors: &[Vec3],
        put: impl Fn(&mut Vec3, Vec3),
    ) {
        let mut shaded = fragments.iter().zip(colors);
        for pixels in runs {
            let pixels = self.color[pixels.clone()]
                .iter_mut()
                .zip(&mut self.depth[pixels.clone()]);
            for ((pixel, depth), (fragment, &colour)) in pixels.zip(&mut shaded) {
                put(pixel, colour);
                if DEPTH {
                    *depth = fragment.depth;
                }
            }
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
    /// Finds the nearest triangle of `bin` at each pixel of `rect`, or only at the `wanted`
    /// spans of its rows when given (the other slots are then left as they were).
    pub fn resolve_visibility(
        &mut self,
        triangles: &[ScreenTriangle],
        bin: &[u32],
        rect: &PixelRect,
        shift: &SampleShift,
        wanted: Option<&WantedSpans>,
    ) {
        // A triangle is recorded only where it wins, which needs 1/w > 0: the triangle slots
        // are read only where `inv_w` says one was drawn, so they need no clearing. Only the
        // rect's rows are read (a strip's tile is half a tile high), and of a masked pass's
        // only the wanted pixels.
        let clip = match wanted {
            None => {
                let rows = (rect.y1 - rect.y0 + 1) as usize;
                self.inv_w[..rows * TILE_SIZE as usize].fill(0.0);
                *rect
            }
            Some(spans) => {
                spans.slots().for_each(|slots| self.inv_w[slots].fill(0.0));
                let Some(bounds) = spans.bounds() else {
                    return;
                };
                bounds
            }
        };
        let path = CoverPath::detect();
        // AVX2 compares four of the i64 edge functions at once; SSE2 has no 64-bit compare.
        crate::simd::widest(
            #[inline(always)]
            || {
                for &index in bin {
                    let t = &triangles[index as usize];
                    if let Some(spans) = wanted {
                        let reached = t.bounds.intersect(&clip);
                        if !reached.is_some_and(|rect| spans.any_in(&rect)) {
                            continue;
                        }
                    }
                    // Inlined, or its coverage loop stays SSE2 (the compiler left it out of
                    // line in some builds).
                    triangle_rows(
                        t,
                        &clip,
                        shift,
                        #[inline(always)]
                        |row| {
                            let Some(row) = wanted.map_or(Some(row), |spans| spans.clip(row))
                            else {
                                return;
                            };
                            let first =
                                ((row.y - rect.y0) * TILE_SIZE + (row.x0 - rect.x0)) as usize;
                            let pixels = (row.x1 - row.x0 + 1) as usize;
                            let slots = first..first + padded_len(pixels);
                            let nearest = RowNearest {
                                inv_w: &mut self.inv_w[slots.clone()],
                                triangle: &mut self.triangle[slots],
                            };
                            nearest.cover(t, &row, index, sample_origin(t.origin, shift), path);
                        },
                    );
                }
            },
        );
    }

    /// The nearest triangle at `slot`, if one was drawn there.
    #[cfg(test)]
    fn nearest(&self, slot: usize) -> Option<u32> {
        (self.inv_w[slot] > 0.0).then(|| self.triangle[slot])
    }

    /// Turns the tile's visible pixels into fragments, shades them as one batch and writes the
    /// tile (background where nothing is visible). Returns the fragments shaded and flattened.
    pub fn shade<S: FragmentShader>(
        &mut self,
        triangles: &[ScreenTriangle],
        frame: &TileFrame<S>,
        scratch: &mut S::Scratch,
        rect: &PixelRect,
        mut out: StripOutput,
    ) -> (usize, usize) {
        self.fragments.clear();
        self.visible_runs.clear();
        let width = (rect.x1 - rect.x0 + 1) as usize;
        for y in rect.y0..=rect.y1 {
            let first_slot = ((y - rect.y0) * TILE_SIZE) as usize;
            let slots = &self.triangle[first_slot..first_slot + width];
            let row = ((y - out.first_row) * out.width) as usize + rect.x0 as usize;
            let wanted = out.mask.map(|mask| &mask[row..row + width]);
            for (kind, xs) in RowRuns::new(&self.inv_w[first_slot..first_slot + width], wanted) {
                let pixels = row + xs.start as usize..row + xs.end as usize;
                match kind {
                    PixelKind::Background => out.background_run(pixels),
                    PixelKind::Visible => {
                        let first = rect.x0 + xs.start;
                        let run_slots = &slots[xs.start as usize..xs.end as usize];
                        for (index, run) in same_triangle(run_slots) {
                            let make = FragmentMaker::new(&triangles[index as usize], frame, y);
                            let x0 = first + run.start as u32;
                            make.push_run(x0..x0 + run.len() as u32, &mut self.fragments);
                        }
                        self.visible_runs.push(pixels);
                    }
                }
            }
        }
        self.colors.resize(self.fragments.len(), Vec3::ZERO);
        let flattened = frame.shader.shade(
            frame.objects,
            &frame.rays,
            &mut self.fragments,
            scratch,
            &mut self.colors,
        );
        out.shaded_runs(&self.visible_runs, &self.fragments, &self.colors);
        (self.fragments.len(), flattened)
    }
}

/// What every tile of a frame shares.
pub struct TileFrame<'a, 'o, S: FragmentShader> {
    pub objects: &'a [S::Object<'o>],
    pub shader: &'a S,
    pub perspective: bool,
    /// Sample spacing in pixels: scales the (u,v) derivatives (see `RenderTarget::footprint`).
    pub footprint: f32,
    /// By object: whether the shader reads the (u,v) derivatives of its fragments
    /// (`FragmentShader::reads_derivatives`).
    pub derivatives: &'a [bool],
    /// Where this pass samples in each pixel.
    pub shift: SampleShift,
    /// The view ray through each pixel's sample point.
    pub rays: SampleRays,
}

/// Makes the fragments of one triangle along one row: what is the same for all of them
/// (the triangle's planes, its object's flags, the row) is looked up once, and held by value,
/// so the per-pixel loop is straight arithmetic (through a reference, it was reloaded for every
/// fragment: the fragments' writes might have changed it, for all the compiler knew).
#[derive(Clone, Copy)]
struct FragmentMaker {
    t: FragmentPlanes,
    y: u32,
    perspective: bool,
    /// Whether the shader reads the (u,v) derivatives (see `TileFrame::derivatives`).
    derivatives: bool,
    footprint: f32,
}

/// What a fragment reads of its triangle.
#[derive(Clone, Copy)]
struct FragmentPlanes {
    object: u32,
    origin: Vec2,
    inv_w: AttributePlane,
    u_over_w: AttributePlane,
    v_over_w: AttributePlane,
}

impl FragmentMaker {
    #[inline(always)]
    fn new<S: FragmentShader>(t: &ScreenTriangle, frame: &TileFrame<S>, y: u32) -> FragmentMaker {
        FragmentMaker {
            t: FragmentPlanes {
                object: t.object,
                origin: sample_origin(t.origin, &frame.shift),
                inv_w: t.inv_w,
                u_over_w: t.u_over_w,
                v_over_w: t.v_over_w,
            },
            y,
            perspective: frame.perspective,
            derivatives: frame.derivatives[t.object as usize],
            footprint: frame.footprint,
        }
    }

    /// The fragments of pixels `xs` of the row, pushed in order: one loop for each setting of
    /// the maker's two flags, so that the per-pixel loop tests neither.
    #[inline(always)]
    fn push_run(&self, xs: Range<u32>, fragments: &mut Vec<Fragment>) {
        match (self.perspective, self.derivatives) {
            (true, true) => self.push_each::<true, true>(xs, fragments),
            (true, false) => self.push_each::<true, false>(xs, fragments),
            (false, true) => self.push_each::<false, true>(xs, fragments),
            (false, false) => self.push_each::<false, false>(xs, fragments),
        }
    }

    #[inline(always)]
    fn push_each<const PERSPECTIVE: bool, const DERIVATIVES: bool>(
        &self,
        xs: Range<u32>,
        fragments: &mut Vec<Fragment>,
    ) {
        fragments.reserve(xs.len());
        // A loop, not `extend` with a closure: the compiler left extend's loop out of line, and
        // it reloaded the maker from the stack (wider loads than the stores that had just put
        // it there, which stall) at every run.
        for x in xs {
            fragments.push(self.at::<PERSPECTIVE, DERIVATIVES>(x));
        }
    }

    /// The fragment at pixel (x, y): (u,v) and, if the shader reads them, its screen
    /// derivatives from the interpolated planes (for u = U/Q with U = u/w and Q = 1/w:
    /// ∂u/∂x = (U_x − u·Q_x)/Q). `PERSPECTIVE` and `DERIVATIVES` are the maker's flags.
    #[inline(always)]
    fn at<const PERSPECTIVE: bool, const DERIVATIVES: bool>(&self, x: u32) -> Fragment {
        let t = &self.t;
        let offset = pixel_offset(t.origin, x, self.y);
        let q = t.inv_w.at(offset);
        let w = 1.0 / q;
        let plane_uv = Vec2::new(t.u_over_w.at(offset), t.v_over_w.at(offset));
        let uv = if PERSPECTIVE { plane_uv * w } else { plane_uv };
        let (duv_dx, duv_dy) = if DERIVATIVES {
            let plane_dx = Vec2::new(t.u_over_w.dx, t.v_over_w.dx);
            let plane_dy = Vec2::new(t.u_over_w.dy, t.v_over_w.dy);
            let (dx, dy) = if PERSPECTIVE {
                (
                    (plane_dx - uv * t.inv_w.dx) * w,
                    (plane_dy - uv * t.inv_w.dy) * w,
                )
            } else {
                (plane_dx, plane_dy)
            };
            (dx * self.footprint, dy * self.footprint)
        } else {
            (Vec2::ZERO, Vec2::ZERO)
        };
        Fragment {
            object: t.object,
            uv,
            duv_dx,
            duv_dy,
            depth: w,
            x,
            y: self.y,
        }
    }
}

/// A triangle's attribute origin relative to the shifted sample points (exact in f32: both
/// are multiples of 1/256 under 2^14), so that `pixel_offset` from it gives the sample point's
/// offset from the true origin.
#[inline(always)]
fn sample_origin(origin: Vec2, shift: &SampleShift) -> Vec2 {
    origin - shift.pixels
}

/// The pixel centre relative to a triangle's attribute origin.
#[inline]
fn pixel_offset(origin: Vec2, x: u32, y: u32) -> Vec2 {
    Vec2::new(x as f32 + 0.5, y as f32 + 0.5) - origin
}

/// Splits a run of pixels' triangle slots into runs drawn by one triangle: (triangle, range).
fn same_triangle(slots: &[u32]) -> impl Iterator<Item = (u32, Range<usize>)> + '_ {
    let mut start = 0;
    std::iter::from_fn(move || {
        let &index = slots.get(start)?;
        let len = slots[start..].iter().take_while(|&&s| s == index).count();
        let run = start..start + len;
        start += len;
        Some((index, run))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::Interpolation;
    use crate::raster::clip::ClipVertex;
    use crate::raster::scan::scan_triangle;
    use crate::raster::setup::{ShiftSpan, TrianglePlanes, Viewport};
    use crate::raster::tile_rows::TileRows;
    use glam::Vec4;

    #[test]
    fn a_row_splits_into_runs_of_one_triangle() {
        let slots = [4, 4, 7, 7, 7, 4, 9];
        let runs: Vec<(u32, Range<usize>)> = same_triangle(&slots).collect();
        assert_eq!(runs, [(4, 0..2), (7, 2..5), (4, 5..6), (9, 6..7)]);
        assert_eq!(same_triangle(&[]).count(), 0);
    }

    const NO_TRIANGLE: u32 = u32::MAX;

    const VIEWPORT: Viewport = Viewport {
        width: 100,
        height: 90,
    };

    /// A small deterministic generator in [0, 1).
    struct Lcg(u64);

    impl Lcg {
        fn next(&mut self) -> f32 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    /// A triangle with corners at pixel positions and per-corner w (so depth varies across it).
    fn triangle(corners: [(f32, f32, f32); 3]) -> Option<ScreenTriangle> {
        let vertices = corners.map(|(x, y, w)| ClipVertex {
            position: Vec4::new(
                (x / VIEWPORT.width as f32 * 2.0 - 1.0) * w,
                (1.0 - y / VIEWPORT.height as f32 * 2.0) * w,
                0.5 * w,
                w,
            ),
            uv: glam::Vec2::ZERO,
        });
        let planes = TrianglePlanes::new(&vertices, VIEWPORT, Interpolation::PerspectiveCorrect)?;
        ScreenTriangle::new(vertices, VIEWPORT, &planes, 0, &ShiftSpan::NONE)
    }

    /// The visibility rule pixel by pixel: a covering triangle wins where it is strictly nearer.
    fn nearest_by_pixel(triangles: &[ScreenTriangle], rect: &PixelRect) -> Vec<u32> {
        let mut inv_w = vec![0.0f32; TILE_PIXELS];
        let mut nearest = vec![NO_TRIANGLE; TILE_PIXELS];
        for (index, t) in triangles.iter().enumerate() {
            scan_triangle(t, rect, |x, y| {
                let slot = ((y - rect.y0) * TILE_SIZE + (x - rect.x0)) as usize;
                let depth = t.inv_w.at(pixel_offset(t.origin, x, y));
                if depth > inv_w[slot] {
                    inv_w[slot] = depth;
                    nearest[slot] = index as u32;
                }
            });
        }
        nearest
    }

    #[test]
    fn tile_visibility_follows_the_per_pixel_rule() {
        let mut random = Lcg(7);
        let mut corner = |spread: f32| {
            (
                random.next() * spread - 10.0,
                random.next() * spread - 10.0,
                0.5 + random.next() * 4.0,
            )
        };
        let mut triangles: Vec<ScreenTriangle> = (0..300)
            .filter_map(|k| triangle([0; 3].map(|_| corner(if k % 3 == 0 { 120.0 } else { 40.0 }))))
            .collect();
        let mut random = Lcg(11);
        // Exact copies tie at every pixel: the first drawn must stay.
        let copies: Vec<ScreenTriangle> = triangles.iter().step_by(7).copied().collect();
        triangles.extend(copies);
        let bin: Vec<u32> = (0..triangles.len() as u32).collect();
        // A whole tile, and one cut by the viewport's edge.
        // One buffer for both, so nothing from the first tile may show through in the second.
        let mut tile = TileBuffers::default();
        for rect in [
            PixelRect {
                x0: 0,
                y0: 0,
                x1: 63,
                y1: 63,
            },
            PixelRect {
                x0: 64,
                y0: 64,
                x1: 99,
                y1: 89,
            },
        ] {
            tile.resolve_visibility(&triangles, &bin, &rect, &SampleShift::NONE, None);
            // The rect's rows are all that is read (and cleared).
            let slots = (rect.y1 - rect.y0 + 1) as usize * TILE_SIZE as usize;
            let expected = &nearest_by_pixel(&triangles, &rect)[..slots];
            let nearest: Vec<u32> = (0..slots)
                .map(|slot| tile.nearest(slot).unwrap_or(NO_TRIANGLE))
                .collect();
            assert_eq!(nearest, expected, "tile {rect:?}");
            let drawn = expected.iter().filter(|&&t| t != NO_TRIANGLE).count();
            assert!(drawn > 500, "the tile saw triangles: {drawn} pixels");
            // Masked: at every wanted pixel the same, whatever the buffer held before.
            for share in [0.0, 0.02, 0.3, 1.0] {
                let width = VIEWPORT.width;
                let mask: Vec<bool> = (0..width * TILE_SIZE)
                    .map(|_| random.next() < share)
                    .collect();
                let rows = TileRows {
                    width,
                    first_row: rect.y0,
                    rect: &rect,
                };
                let spans = WantedSpans::of(&mask, &rows);
                tile.resolve_visibility(&triangles, &bin, &rect, &SampleShift::NONE, Some(&spans));
                let wanted = rows.each().flat_map(|pixels| mask[pixels].to_vec());
                let slots = (rect.y0..=rect.y1).flat_map(|y| {
                    let first = (y - rect.y0) * TILE_SIZE;
                    first..first + rect.x1 - rect.x0 + 1
                });
                let mut checked = 0;
                for (slot, wanted) in slots.zip(wanted) {
                    if wanted {
                        let slot = slot as usize;
                        let nearest = tile.nearest(slot).unwrap_or(NO_TRIANGLE);
                        assert_eq!(nearest, expected[slot], "slot {slot}, {share} wanted");
                        checked += 1;
                    }
                }
                assert_eq!(spans.bounds().is_some(), checked > 0);
            }
        }
    }
}
