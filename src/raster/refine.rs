//! Refinement inside a group of passes: a pixel's first samples, then the rest only where
//! those moved it from what it held before the group.

use super::tile::TileRows;
use glam::Vec3;

/// Adaptive refinement within one group of passes (`raster::render` with a `Refinement`): the
/// passes from `from_pass` on render only those of the wanted pixels whose colour the earlier
/// passes moved by more than `threshold` (in √colour, per channel, as the contrast mask
/// measures) from what the framebuffer held before the group (a still's centre sample). The
/// wanted pixels that stop there are settled as a mix of the two: `centre_weight` of what was
/// before.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefineRule {
    pub from_pass: usize,
    pub threshold: f32,
    pub centre_weight: f32,
}

/// A `RefineRule` and where it records its decisions.
pub struct Refinement<'a> {
    pub rule: RefineRule,
    /// Which pixels were refined, row-major over the viewport; every entry is written. The
    /// mask of any later group that goes on refining the same pixels.
    pub refined: &'a mut Vec<bool>,
}

/// Copies the colours of the tile at `rows` into `before`, row after row.
pub(super) fn keep_before(color: &[Vec3], rows: &TileRows, before: &mut Vec<Vec3>) {
    before.clear();
    for pixels in rows.each() {
        before.extend_from_slice(&color[pixels]);
    }
}

/// Records in `refined` which pixels of the tile at `rows` are to be refined: those `wanted`
/// (all when `None`) whose colour moved by more than the rule's threshold from `before`
/// (`keep_before`'s copy). Settles the other wanted pixels (see `RefineRule`).
pub(super) fn mark_refined(
    color: &mut [Vec3],
    before: &[Vec3],
    wanted: Option<&[bool]>,
    refined: &mut [bool],
    rows: &TileRows,
    rule: &RefineRule,
) {
    let mut before = before.iter();
    for pixels in rows.each() {
        for i in pixels {
            let is_wanted = wanted.is_none_or(|wanted| wanted[i]);
            let before = *before.next().expect("keep_before kept this tile");
            refined[i] = is_wanted && moved(color[i], before, rule.threshold);
            if is_wanted && !refined[i] {
                color[i] = settled(color[i], before, rule.centre_weight);
            }
        }
    }
}

/// A pixel that stops refining: its first samples' mean mixed with its centre sample.
fn settled(mean: Vec3, centre: Vec3, centre_weight: f32) -> Vec3 {
    mean * (1.0 - centre_weight) + centre * centre_weight
}

/// Marks every pixel of the tile at `rows` as not refined.
pub(super) fn mark_none(refined: &mut [bool], rows: &TileRows) {
    for pixels in rows.each() {
        refined[pixels].fill(false);
    }
}

/// Whether any channel of `now` differs from `before` by more than `threshold` in √colour.
fn moved(now: Vec3, before: Vec3, threshold: f32) -> bool {
    let key = |c: Vec3| c.max(Vec3::ZERO).to_array().map(f32::sqrt);
    let (now, before) = (key(now), key(before));
    (0..3).any(|c| (now[c] - before[c]).abs() > threshold)
}
