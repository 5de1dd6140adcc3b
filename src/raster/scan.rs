//! Scan conversion: the pixel rows a triangle's bounds cover within a clip rectangle.

use super::pixel_rect::PixelRect;
use super::setup::{SampleShift, ScreenTriangle};

/// One row of a triangle's bounds cut to a clip rectangle: pixels `x0..=x1` of row `y`, and the
/// three fixed-point edge functions at the centre of pixel `x0`. Pixel `x0 + k` is covered when
/// all three of `edges[i] + k·steps[i]` are non-negative (see `EdgeWalk`).
#[derive(Clone, Copy, Debug)]
pub struct RowSpan {
    pub y: u32,
    pub x0: u32,
    pub x1: u32,
    pub edges: EdgeWalk,
}

/// The edge functions at one pixel centre and their steps to the next pixel on the row.
#[derive(Clone, Copy, Debug)]
pub struct EdgeWalk {
    pub at: [i64; 3],
    pub steps: [i64; 3],
}

impl EdgeWalk {
    /// Whether the current pixel centre is inside: all three edge functions non-negative (the
    /// top-left bias is folded in). Branch-free, so row loops over it vectorise.
    #[inline(always)]
    pub fn inside(&self) -> bool {
        (self.at[0] | self.at[1] | self.at[2]) >= 0
    }

    /// On to the next pixel of the row.
    #[inline(always)]
    pub fn advance(&mut self) {
        for (at, step) in self.at.iter_mut().zip(self.steps) {
            *at += step;
        }
    }

    /// The edge functions `pixels` further along the row.
    #[inline(always)]
    pub fn skipped(self, pixels: u32) -> EdgeWalk {
        let mut at = self.at;
        for (at, step) in at.iter_mut().zip(self.steps) {
            *at += step * i64::from(pixels);
        }
        EdgeWalk { at, ..self }
    }
}

impl RowSpan {
    /// The part of the row within columns `first..=last`, if any.
    #[inline(always)]
    pub fn within(self, first: u32, last: u32) -> Option<RowSpan> {
        let (x0, x1) = (self.x0.max(first), self.x1.min(last));
        (x0 <= x1).then(|| RowSpan {
            x0,
            x1,
            edges: self.edges.skipped(x0 - self.x0),
            ..self
        })
    }
}

/// Calls `row` for every row of the triangle's bounds within `clip`, top to bottom, with the
/// fixed-point edge functions at the pixels' sample points moved by `shift` (the triangle set
/// up with a margin for it), stepped incrementally from row to row.
#[inline(always)]
pub fn triangle_rows(
    triangle: &ScreenTriangle,
    clip: &PixelRect,
    shift: &SampleShift,
    mut row: impl FnMut(RowSpan),
) {
    let Some(rect) = triangle.bounds.intersect(clip) else {
        return;
    };
    let (skip_x, skip_y) = (
        (rect.x0 - triangle.bounds.x0) as i64,
        (rect.y0 - triangle.bounds.y0) as i64,
    );
    let mut at = triangle
        .edges
        .map(|e| e.at_origin + shift.edge_change(&e) + e.step_x * skip_x + e.step_y * skip_y);
    let steps = triangle.edges.map(|e| e.step_x);
    if misses_every_sample(triangle, at, &rect) {
        return;
    }
    for y in rect.y0..=rect.y1 {
        row(RowSpan {
            y,
            x0: rect.x0,
            x1: rect.x1,
            edges: EdgeWalk { at, steps },
        });
        for (at, e) in at.iter_mut().zip(&triangle.edges) {
            *at += e.step_y;
        }
    }
}

/// Whether one of the triangle's edges has every sample point of `rect` outside it: then it
/// covers none of them, and its rows need not be walked. `at` is the edge functions at the
/// rect's first sample. Edge functions are linear, so an edge negative at the four corner
/// samples is negative at every sample between (exact: the integers `triangle_rows` steps).
/// Big triangles' bounds cover whole tiles they do not touch: a plane's two halves share their
/// bounds, so each tile of one half held the other too.
#[inline(always)]
fn misses_every_sample(triangle: &ScreenTriangle, at: [i64; 3], rect: &PixelRect) -> bool {
    let (w, h) = ((rect.x1 - rect.x0) as i64, (rect.y1 - rect.y0) as i64);
    (0..3).any(|i| {
        let (e, at) = (&triangle.edges[i], at[i]);
        let (right, down) = (e.step_x * w, e.step_y * h);
        (at & (at + right) & (at + down) & (at + right + down)) < 0
    })
}

/// Calls `covered(x, y)` for every pixel of `clip` whose centre the triangle covers.
#[inline]
pub fn scan_triangle(triangle: &ScreenTriangle, clip: &PixelRect, covered: impl FnMut(u32, u32)) {
    scan_shifted(triangle, clip, &SampleShift::NONE, covered);
}

/// Calls `covered(x, y)` for every pixel of `clip` whose sample point, moved by `shift` from its
/// centre, the triangle covers (set up with a margin for the shift).
#[inline]
pub fn scan_shifted(
    triangle: &ScreenTriangle,
    clip: &PixelRect,
    shift: &SampleShift,
    mut covered: impl FnMut(u32, u32),
) {
    triangle_rows(triangle, clip, shift, |row| {
        let mut edges = row.edges;
        for x in row.x0..=row.x1 {
            if edges.inside() {
                covered(x, row.y);
            }
            edges.advance();
        }
    });
}
