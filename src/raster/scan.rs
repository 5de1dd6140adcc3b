use super::setup::ScreenTriangle;

/// An inclusive rectangle of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRect {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl PixelRect {
    pub fn intersect(&self, other: &PixelRect) -> Option<PixelRect> {
        let r = PixelRect {
            x0: self.x0.max(other.x0),
            y0: self.y0.max(other.y0),
            x1: self.x1.min(other.x1),
            y1: self.y1.min(other.y1),
        };
        (r.x0 <= r.x1 && r.y0 <= r.y1).then_some(r)
    }
}

/// Calls `covered(x, y)` for every pixel of `clip` whose centre the triangle covers, by stepping
/// the three fixed-point edge functions incrementally along each row.
#[inline]
pub fn scan_triangle(
    triangle: &ScreenTriangle,
    clip: &PixelRect,
    mut covered: impl FnMut(u32, u32),
) {
    let Some(rect) = triangle.bounds.intersect(clip) else {
        return;
    };
    let [e0, e1, e2] = triangle.edges;
    let (skip_x, skip_y) = (
        (rect.x0 - triangle.bounds.x0) as i64,
        (rect.y0 - triangle.bounds.y0) as i64,
    );
    let row_start = |e: &super::setup::Edge| e.at_origin + e.step_x * skip_x + e.step_y * skip_y;
    let (mut r0, mut r1, mut r2) = (row_start(&e0), row_start(&e1), row_start(&e2));
    for y in rect.y0..=rect.y1 {
        let (mut w0, mut w1, mut w2) = (r0, r1, r2);
        for x in rect.x0..=rect.x1 {
            // All three edge functions non-negative <=> the centre is inside (bias folded in).
            if (w0 | w1 | w2) >= 0 {
                covered(x, y);
            }
            w0 += e0.step_x;
            w1 += e1.step_x;
            w2 += e2.step_x;
        }
        r0 += e0.step_y;
        r1 += e1.step_y;
        r2 += e2.step_y;
    }
}
