//! Refinement inside a group of passes: a pixel's first samples, then the rest only where
//! those moved it from what it held before the group.

use super::scan::PixelRect;
use glam::Vec3;

/// Adaptive refinement within one group of passes (`render_refining_passes_into`): the passes
/// from `from_pass` on render only those of the wanted pixels whose colour the earlier passes
/// moved by more than `threshold` (in √colour, per channel, as the contrast mask measures) from
/// what the framebuffer held before the group.
pub struct Refinement<'a> {
    pub from_pass: usize,
    pub threshold: f32,
    /// Which pixels were refined, row-major over the viewport; every entry is written. The
    /// mask of any later group that goes on refining the same pixels.
    pub refined: &'a mut Vec<bool>,
}

/// Where a tile's pixels sit in a strip of `width`-pixel rows starting at row `first_row`: the
/// strip index of each row's first pixel in `rect`, and the rect's width.
fn rows(rect: &PixelRect, width: u32, first_row: u32) -> (impl Iterator<Item = usize>, usize) {
    let starts = (rect.y0..=rect.y1).map(move |y| ((y - first_row) * width + rect.x0) as usize);
    (starts, (rect.x1 - rect.x0 + 1) as usize)
}

/// Copies the colours of `rect` (in a strip as `rows` places it) into `before`, row after row.
pub(super) fn keep_before(
    color: &[Vec3],
    width: u32,
    first_row: u32,
    rect: &PixelRect,
    before: &mut Vec<Vec3>,
) {
    before.clear();
    let (starts, n) = rows(rect, width, first_row);
    for start in starts {
        before.extend_from_slice(&color[start..start + n]);
    }
}

/// Records in `refined` which pixels of `rect` are to be refined: those `wanted` (all when
/// `None`) whose colour moved by more than `threshold` from `before` (`keep_before`'s copy).
/// `(width, first_row, rect, threshold)`: where the rect sits (see `rows`) and the threshold.
pub(super) fn mark_refined(
    color: &[Vec3],
    before: &[Vec3],
    wanted: Option<&[bool]>,
    refined: &mut [bool],
    (width, first_row, rect, threshold): (u32, u32, &PixelRect, f32),
) {
    let (starts, n) = rows(rect, width, first_row);
    for (start, before) in starts.zip(before.chunks_exact(n)) {
        let pixels = start..start + n;
        let now = &color[pixels.clone()];
        for (i, (out, (&now, &before))) in refined[pixels.clone()]
            .iter_mut()
            .zip(now.iter().zip(before))
            .enumerate()
        {
            let is_wanted = wanted.is_none_or(|wanted| wanted[start + i]);
            *out = is_wanted && moved(now, before, threshold);
        }
    }
}

/// Marks every pixel of `rect` as not refined.
pub(super) fn mark_none(refined: &mut [bool], width: u32, first_row: u32, rect: &PixelRect) {
    let (starts, n) = rows(rect, width, first_row);
    for start in starts {
        refined[start..start + n].fill(false);
    }
}

/// Whether any channel of `now` differs from `before` by more than `threshold` in √colour.
fn moved(now: Vec3, before: Vec3, threshold: f32) -> bool {
    let key = |c: Vec3| c.max(Vec3::ZERO).to_array().map(f32::sqrt);
    let (now, before) = (key(now), key(before));
    (0..3).any(|c| (now[c] - before[c]).abs() > threshold)
}
