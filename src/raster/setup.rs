use super::clip::ClipVertex;
use super::pipeline::Interpolation;
use super::scan::PixelRect;
use glam::Vec2;

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
    /// Pixel position that attribute planes are relative to (the first snapped vertex).
    pub origin: Vec2,
    pub inv_w: AttributePlane,
    pub u_over_w: AttributePlane,
    pub v_over_w: AttributePlane,
    pub object: u32,
}

impl ScreenTriangle {
    /// Snaps a clipped triangle to fixed point and sets up its edge functions and attribute
    /// planes. `None` for triangles with zero snapped area or no pixel centre in the viewport.
    /// With affine interpolation the (u,v) planes hold u and v themselves rather than u/w, v/w.
    pub fn new(
        vertices: [ClipVertex; 3],
        viewport: Viewport,
        interpolation: Interpolation,
        object: u32,
    ) -> Option<ScreenTriangle> {
        let mut snapped = [(0i64, 0i64); 3];
        let mut attributes = [[0f64; 3]; 3];
        for (i, v) in vertices.iter().enumerate() {
            let w = v.position.w as f64;
            if !(w > 0.0 && w.is_finite()) {
                return None;
            }
            let inv_w = 1.0 / w;
            let sx = (v.position.x as f64 * inv_w * 0.5 + 0.5) * viewport.width as f64;
            let sy = (0.5 - v.position.y as f64 * inv_w * 0.5) * viewport.height as f64;
            snapped[i] = (snap(sx), snap(sy));
            let uv_weight = match interpolation {
                Interpolation::PerspectiveCorrect => inv_w,
                Interpolation::Affine => 1.0,
            };
            attributes[i] = [inv_w, v.uv.x as f64 * uv_weight, v.uv.y as f64 * uv_weight];
        }
        let mut area = edge_value(snapped[1], snapped[2], snapped[0]);
        if area == 0 {
            return None;
        }
        if area < 0 {
            snapped.swap(1, 2);
            attributes.swap(1, 2);
            area = -area;
        }
        let bounds = pixel_bounds(&snapped, viewport)?;
        let origin = snapped[0];
        let planes = attribute_planes(&snapped, &attributes, area);
        Some(ScreenTriangle {
            bounds,
            edges: [0, 1, 2].map(|i| edge(snapped[(i + 1) % 3], snapped[(i + 2) % 3], &bounds)),
            origin: Vec2::new(origin.0 as f32, origin.1 as f32) / ONE as f32,
            inv_w: planes[0],
            u_over_w: planes[1],
            v_over_w: planes[2],
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

/// Plane equations for the per-vertex attributes, in f64 from the snapped positions (so they
/// agree exactly with coverage), relative to the first vertex.
fn attribute_planes(
    snapped: &[(i64, i64); 3],
    values: &[[f64; 3]; 3],
    area: i64,
) -> [AttributePlane; 3] {
    let px = |i: usize| {
        (
            snapped[i].0 as f64 / ONE as f64,
            snapped[i].1 as f64 / ONE as f64,
        )
    };
    let (p0, p1, p2) = (px(0), px(1), px(2));
    let (e1, e2) = ((p1.0 - p0.0, p1.1 - p0.1), (p2.0 - p0.0, p2.1 - p0.1));
    // The same orientation as `edge_value`: det = e1.x·e2.y − e1.y·e2.x = area / ONE².
    let det = area as f64 / (ONE * ONE) as f64;
    [0, 1, 2].map(|k| {
        let (d1, d2) = (values[1][k] - values[0][k], values[2][k] - values[0][k]);
        AttributePlane {
            at_origin: values[0][k] as f32,
            dx: ((d1 * e2.1 - d2 * e1.1) / det) as f32,
            dy: ((d2 * e1.0 - d1 * e2.0) / det) as f32,
        }
    })
}
