use super::clip::ClipVertex;
use super::pipeline::Interpolation;
use super::scan::PixelRect;
use glam::{DVec3, Vec2};

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
    /// Pixels whose centres may be covered (inclusive ranges), already inside the viewport.
    pub bounds: PixelRect,
    pub edges: [Edge; 3],
    /// Pixel position that attribute planes are relative to: the bounds' top-left corner, inside
    /// the viewport, so per-pixel offsets stay small and exact in f32 even when the triangle's
    /// vertices lie far out in the guard band.
    pub origin: Vec2,
    pub inv_w: AttributePlane,
    pub u_over_w: AttributePlane,
    pub v_over_w: AttributePlane,
    pub object: u32,
}

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
    /// snapped area or no pixel centre in the viewport.
    pub fn new(
        vertices: [ClipVertex; 3],
        viewport: Viewport,
        planes: &TrianglePlanes,
        object: u32,
    ) -> Option<ScreenTriangle> {
        let mut snapped = [(0i64, 0i64); 3];
        for (i, v) in vertices.iter().enumerate() {
            let w = v.position.w as f64;
            if !(w > 0.0 && w.is_finite()) {
                return None;
            }
            let sx = (v.position.x as f64 / w * 0.5 + 0.5) * viewport.width as f64;
            let sy = (0.5 - v.position.y as f64 / w * 0.5) * viewport.height as f64;
            snapped[i] = (snap(sx), snap(sy));
        }
        let area = edge_value(snapped[1], snapped[2], snapped[0]);
        if area == 0 {
            return None;
        }
        if area < 0 {
            snapped.swap(1, 2);
        }
        let bounds = pixel_bounds(&snapped, viewport)?;
        let origin = Vec2::new(bounds.x0 as f32, bounds.y0 as f32);
        Some(ScreenTriangle {
            bounds,
            edges: [0, 1, 2].map(|i| edge(snapped[(i + 1) % 3], snapped[(i + 2) % 3], &bounds)),
            origin,
            inv_w: planes.at(planes.inv_w, origin),
            u_over_w: planes.at(planes.u, origin),
            v_over_w: planes.at(planes.v, origin),
            object,
        })
    }
}

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

fn pixel_bounds(snapped: &[(i64, i64); 3], viewport: Viewport) -> Option<PixelRect> {
    let (mut min, mut max) = (snapped[0], snapped[0]);
    for &(x, y) in &snapped[1..] {
        min = (min.0.min(x), min.1.min(y));
        max = (max.0.max(x), max.1.max(y));
    }
    // Pixel centres at k·ONE + HALF within [min, max].
    let first = |lo: i64| (lo - HALF).div_euclid(ONE) + i64::from((lo - HALF).rem_euclid(ONE) != 0);
    let last = |hi: i64| (hi - HALF).div_euclid(ONE);
    let x0 = first(min.0).max(0);
    let y0 = first(min.1).max(0);
    let x1 = last(max.0).min(viewport.width as i64 - 1);
    let y1 = last(max.1).min(viewport.height as i64 - 1);
    (x0 <= x1 && y0 <= y1).then_some(PixelRect {
        x0: x0 as u32,
        y0: y0 as u32,
        x1: x1 as u32,
        y1: y1 as u32,
    })
}
