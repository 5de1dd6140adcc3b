//! Triangle setup: snapped fixed-point vertices, edge functions and the planes of 1/w, u/w, v/w.

use super::clip::ClipVertex;
use super::interpolation::Interpolation;
use super::pixel_rect::PixelRect;
use glam::{DVec3, Vec2, Vec4};

/// Sub-pixel precision of snapped vertex positions: 1/256 of a pixel.
pub const SUBPIXEL_BITS: u32 = 8;
const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;
/// Snapped coordinates stay within ±2^20 pixels (the guard band), so edge functions, products of
/// two 30-bit differences, fit comfortably in i64.
const GUARD_PIXELS: f32 = (1 << 20) as f32;

/// The output image size in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub width: u32,
    pub height: u32,
}

impl Viewport {
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height.max(1) as f32
    }

    /// The guard band half-width in NDC units: how far past the screen edge triangles may reach
    /// before they are clipped in x and y.
    pub fn guard_band(&self) -> f32 {
        (GUARD_PIXELS / self.width.max(self.height).max(1) as f32).max(1.0)
    }
}

/// An edge function E(p) = step_x·(px − x0) + step_y·(py − y0) + at_origin over pixel centres,
/// in fixed point, with the top-left bias folded in so that "inside" is exactly E ≥ 0.
#[derive(Clone, Copy, Debug)]
pub struct Edge {
    pub step_x: i64,
    pub step_y: i64,
    pub at_origin: i64,
}

/// Where a pass samples in each pixel, as the rasteriser applies it: the same set-up triangles
/// serve every supersampling pass, each pass moving its sample points by `pixels` from the
/// pixel centres. In whole sub-pixel steps, so an edge function moves by an exact integer and
/// the attribute planes' sample positions stay exact in f32.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SampleShift {
    /// The shift in sub-pixel steps (1/256 of a pixel).
    steps: (i64, i64),
    /// The same shift in pixels (exact).
    pub pixels: Vec2,
}

impl SampleShift {
    pub const NONE: SampleShift = SampleShift {
        steps: (0, 0),
        pixels: Vec2::ZERO,
    };

    /// The shift nearest `offset` pixels, at most a pixel each way.
    pub fn new(offset: Vec2) -> SampleShift {
        let step = |o: f32| (o.clamp(-1.0, 1.0) * ONE as f32).round() as i64;
        let steps = (step(offset.x), step(offset.y));
        SampleShift {
            steps,
            pixels: Vec2::new(steps.0 as f32, steps.1 as f32) / ONE as f32,
        }
    }

    /// `edge` at a pixel's shifted sample point, less its value at the pixel centre: exact, as
    /// the steps per pixel are whole multiples of the sub-pixel scale.
    #[inline(always)]
    pub fn edge_change(&self, edge: &Edge) -> i64 {
        (edge.step_x / ONE) * self.steps.0 + (edge.step_y / ONE) * self.steps.1
    }
}

/// The least and most shift, along each axis, of the passes that share set-up triangles: a
/// triangle's bounds hold the pixels whose sample point, under any of the shifts, may fall in
/// its box (with none, the pixels whose centres do).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShiftSpan {
    least: (i64, i64),
    most: (i64, i64),
}

impl ShiftSpan {
    pub const NONE: ShiftSpan = ShiftSpan {
        least: (0, 0),
        most: (0, 0),
    };

    /// The span of `shifts` (none: `NONE`).
    pub fn of(shifts: impl IntoIterator<Item = SampleShift>) -> ShiftSpan {
        let mut shifts = shifts.into_iter().map(|s| s.steps);
        let Some(first) = shifts.next() else {
            return ShiftSpan::NONE;
        };
        let (least, most) = shifts.fold((first, first), |(least, most), s| {
            (
                (least.0.min(s.0), least.1.min(s.1)),
                (most.0.max(s.0), most.1.max(s.1)),
            )
        });
        ShiftSpan { least, most }
    }
}

/// An attribute a(x, y) = at_origin + dx·(x − origin.x) + dy·(y − origin.y), affine in screen space.
/// Only 1/w, u/w and v/w are affine in screen space; u and v are recovered per pixel by division.
#[derive(Clone, Copy, Debug)]
pub struct AttributePlane {
    pub at_origin: f32,
    pub dx: f32,
    pub dy: f32,
}

impl AttributePlane {
    #[inline]
    pub fn at(&self, offset: Vec2) -> f32 {
        self.at_origin + self.dx * offset.x + self.dy * offset.y
    }
}

/// A triangle ready for scan conversion and shading.
#[derive(Clone, Copy, Debug)]
pub struct ScreenTriangle {
    /// Pixels whose sample points may be covered (inclusive ranges; see `ScreenTriangle::new`),
    /// already inside the viewport.
    pub bounds: PixelRect,
    pub edges: [Edge; 3],
    /// Pixel position that attribute planes are relative to: at most a pixel from the bounds'
    /// top-left corner (`attribute_origin`), inside the viewport, so per-pixel offsets stay
    /// small and exact in f32 even when the triangle's vertices lie far out in the guard band.
    pub origin: Vec2,
    pub inv_w: AttributePlane,
    pub u_over_w: AttributePlane,
    pub v_over_w: AttributePlane,
    pub object: u32,
}

// SAFETY: every field is an integer, a float or a plain struct of them (`PixelRect`, `Edge`,
// `Vec2`, `AttributePlane`), for which all-zero bytes are a valid value. Only tests make
// triangles from zeros.
#[cfg(test)]
unsafe impl bytemuck::Zeroable for ScreenTriangle {}

/// The screen-space planes of 1/w and of the (u,v) attributes of one scene triangle, in f64
/// over absolute pixel coordinates: value(x, y) = c[0]·x + c[1]·y + c[2].
///
/// They come from the original triangle's homogeneous coordinates (2D homogeneous
/// interpolation), not from the clipped vertices: so every piece of a clipped triangle shares the
/// exact planes, and precision does not suffer from clip vertices computed near the eye.
#[derive(Clone, Copy, Debug)]
pub struct TrianglePlanes {
    inv_w: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
}

impl TrianglePlanes {
    /// `None` when the triangle's plane passes through the eye (it is seen edge-on).
    pub fn new(
        vertices: &[ClipVertex; 3],
        viewport: Viewport,
        interpolation: Interpolation,
    ) -> Option<TrianglePlanes> {
        let (width, height) = (viewport.width as f64, viewport.height as f64);
        let homogeneous = vertices.map(|v| {
            let [x, y, _, w] = v.position.as_dvec4().to_array();
            DVec3::new((0.5 * x + 0.5 * w) * width, (0.5 * w - 0.5 * y) * height, w)
        });
        let inverse = inverse_rows(homogeneous)?;
        let combine = |values: [f64; 3], rows: &[DVec3; 3]| {
            (rows[0] * values[0] + rows[1] * values[1] + rows[2] * values[2]).to_array()
        };
        let us = vertices.map(|v| v.uv.x as f64);
        let vs = vertices.map(|v| v.uv.y as f64);
        let affine_rows = match interpolation {
            Interpolation::Affine if homogeneous.iter().all(|h| h.z > 0.0) => {
                inverse_rows(homogeneous.map(|h| DVec3::new(h.x / h.z, h.y / h.z, 1.0)))
            }
            // Affine is undefined for a triangle crossing the camera plane: keep it correct there.
            _ => None,
        };
        let uv_rows = affine_rows.as_ref().unwrap_or(&inverse);
        Some(TrianglePlanes {
            inv_w: combine([1.0; 3], &inverse),
            u: combine(us, uv_rows),
            v: combine(vs, uv_rows),
        })
    }

    fn at(&self, coefficients: [f64; 3], origin: Vec2) -> AttributePlane {
        AttributePlane {
            at_origin: (coefficients[0] * origin.x as f64
                + coefficients[1] * origin.y as f64
                + coefficients[2]) as f32,
            dx: coefficients[0] as f32,
            dy: coefficients[1] as f32,
        }
    }
}

/// Rows of the inverse of the matrix whose columns are `h`, or `None` if it is near singular.
fn inverse_rows(h: [DVec3; 3]) -> Option<[DVec3; 3]> {
    let rows = [h[1].cross(h[2]), h[2].cross(h[0]), h[0].cross(h[1])];
    let det = h[0].dot(rows[0]);
    let scale = h[0].length() * h[1].length() * h[2].length();
    (det.abs() > 1e-12 * scale && det.is_finite()).then(|| rows.map(|r| r / det))
}

impl ScreenTriangle {
    /// Snaps a (clipped) triangle to fixed point and sets up its edge functions; its attributes
    /// come from the planes of the scene triangle it belongs to. `None` for triangles with zero
    /// snapped area or no pixel in the viewport (see `PlacedTriangle::new`).
    pub fn new(
        vertices: [ClipVertex; 3],
        viewport: Viewport,
        planes: &TrianglePlanes,
        object: u32,
        span: &ShiftSpan,
    ) -> Option<ScreenTriangle> {
        PlacedTriangle::new(&vertices, viewport, span).map(|placed| placed.with(planes, object))
    }
}

/// A (clipped) triangle snapped to fixed point with the pixels it may cover: a screen triangle
/// but for its attribute planes, which cost more to work out and are needed only by triangles
/// that reach a pixel.
pub struct PlacedTriangle {
    /// In counter-clockwise order on screen (y down).
    snapped: [(i64, i64); 3],
    bounds: PixelRect,
    origin: Vec2,
}

impl PlacedTriangle {
    /// Its bounds hold the pixels whose sample point may fall in its box under a shift of
    /// `span`. `None` for triangles with zero snapped area or no such pixel in the viewport.
    #[inline(always)]
    pub fn new(
        vertices: &[ClipVertex; 3],
        viewport: Viewport,
        span: &ShiftSpan,
    ) -> Option<PlacedTriangle> {
        let mut snapped = [(0i64, 0i64); 3];
        for (snapped, v) in snapped.iter_mut().zip(vertices) {
            *snapped = snap_vertex(v.position, viewport)?;
        }
        PlacedTriangle::from_snapped(snapped, viewport, span)
    }

    /// `new`, from vertices already snapped (by `snap_vertex`).
    #[inline(always)]
    pub fn from_snapped(
        mut snapped: [(i64, i64); 3],
        viewport: Viewport,
        span: &ShiftSpan,
    ) -> Option<PlacedTriangle> {
        let area = edge_value(snapped[1], snapped[2], snapped[0]);
        if area == 0 {
            return None;
        }
        if area < 0 {
            snapped.swap(1, 2);
        }
        let bounds = pixel_bounds(&snapped, viewport, span)?;
        let origin = attribute_origin(&snapped, viewport);
        Some(PlacedTriangle {
            snapped,
            bounds,
            origin,
        })
    }

    /// The screen triangle, its attributes from `planes` (of the scene triangle it belongs to).
    #[inline(always)]
    pub fn with(self, planes: &TrianglePlanes, object: u32) -> ScreenTriangle {
        let PlacedTriangle {
            snapped,
            bounds,
            origin,
        } = self;
        ScreenTriangle {
            bounds,
            edges: [0, 1, 2].map(|i| edge(snapped[(i + 1) % 3], snapped[(i + 2) % 3], &bounds)),
            origin,
            inv_w: planes.at(planes.inv_w, origin),
            u_over_w: planes.at(planes.u, origin),
            v_over_w: planes.at(planes.v, origin),
            object,
        }
    }
}

/// A clip-space position snapped to fixed-point pixels; `None` unless it lies in front of the
/// eye (w > 0 and finite).
#[inline(always)]
pub fn snap_vertex(position: Vec4, viewport: Viewport) -> Option<(i64, i64)> {
    let w = position.w as f64;
    if !(w > 0.0 && w.is_finite()) {
        return None;
    }
    let sx = (position.x as f64 / w * 0.5 + 0.5) * viewport.width as f64;
    let sy = (0.5 - position.y as f64 / w * 0.5) * viewport.height as f64;
    Some((snap(sx), snap(sy)))
}

#[inline(always)]
fn snap(pixels: f64) -> i64 {
    let limit = (GUARD_PIXELS as f64 * 2.0) * ONE as f64;
    (pixels * ONE as f64).round().clamp(-limit, limit) as i64
}

/// Twice the signed area of (a, b, p); positive when p is to the left of a→b in a y-down image.
fn edge_value(a: (i64, i64), b: (i64, i64), p: (i64, i64)) -> i64 {
    (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
}

/// The edge a→b as a function over pixel centres, starting at the bounds' top-left pixel.
fn edge(a: (i64, i64), b: (i64, i64), bounds: &PixelRect) -> Edge {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    // Top-left rule: a pixel centre exactly on an edge belongs to the triangle only if the edge
    // is a left edge (going up in a y-down image) or a top edge (horizontal, going right).
    // Two triangles sharing an edge see it in opposite directions, so exactly one owns it.
    let owns_boundary = dy < 0 || (dy == 0 && dx > 0);
    let bias = if owns_boundary { 0 } else { -1 };
    let first_centre = (bounds.x0 as i64 * ONE + HALF, bounds.y0 as i64 * ONE + HALF);
    Edge {
        step_x: -dy * ONE,
        step_y: dx * ONE,
        at_origin: edge_value(a, b, first_centre) + bias,
    }
}

/// The snapped triangle's box: least and greatest x and y.
fn snapped_box(snapped: &[(i64, i64); 3]) -> ((i64, i64), (i64, i64)) {
    let (mut min, mut max) = (snapped[0], snapped[0]);
    for &(x, y) in &snapped[1..] {
        min = (min.0.min(x), min.1.min(y));
        max = (max.0.max(x), max.1.max(y));
    }
    (min, max)
}

/// The first pixel whose centre is at or past `lo` (sub-pixel units), along an axis.
fn first_centre(lo: i64) -> i64 {
    (lo - HALF).div_euclid(ONE) + i64::from((lo - HALF).rem_euclid(ONE) != 0)
}

/// The last pixel whose centre is at or before `hi` (sub-pixel units), along an axis.
fn last_centre(hi: i64) -> i64 {
    (hi - HALF).div_euclid(ONE)
}

/// The pixels of the viewport whose sample point, under a shift of `span`, may fall in the box
/// of `snapped`: whose centres lie in the box moved back by the shifts.
fn pixel_bounds(
    snapped: &[(i64, i64); 3],
    viewport: Viewport,
    span: &ShiftSpan,
) -> Option<PixelRect> {
    let (min, max) = snapped_box(snapped);
    let x0 = first_centre(min.0 - span.most.0).max(0);
    let y0 = first_centre(min.1 - span.most.1).max(0);
    let x1 = last_centre(max.0 - span.least.0).min(viewport.width as i64 - 1);
    let y1 = last_centre(max.1 - span.least.1).min(viewport.height as i64 - 1);
    (x0 <= x1 && y0 <= y1).then_some(PixelRect {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}

/// Where the attribute planes are taken from: the first pixel whose centre lies in the
/// triangle's box, moved into the viewport. The same whatever the passes' shifts, so passes
/// set up together or one by one interpolate the same bits.
fn attribute_origin(snapped: &[(i64, i64); 3], viewport: Viewport) -> Vec2 {
    let (min, _) = snapped_box(snapped);
    let x = first_centre(min.0).clamp(0, viewport.width.max(1) as i64 - 1);
    let y = first_centre(min.1).clamp(0, viewport.height.max(1) as i64 - 1);
    Vec2::new(x as f32, y as f32)
}
