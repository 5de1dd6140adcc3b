//! Refinement inside a group of passes: the later passes take only the pixels a rule decides
//! on, tile by tile, from what the earlier passes did.

pub use super::tile_rows::TileRows;
use glam::Vec3;

/// Which pixels the later passes of a group take, decided tile by tile while the tile is in
/// cache: after the passes before `from_pass`, from the tile's colours then and before the
/// group's first pass. The still's adaptive refinement is one (`still::RefineRule`).
pub trait Refine: Sync {
    /// The first pass that takes only the decided pixels.
    fn first_decided_pass(&self) -> usize;

    /// Records in `decided` which pixels of the tile at `rows` the later passes take, of those
    /// `wanted` (all when `None`), from their colours now (`color`, which it may settle) and
    /// `before` the group (row after row, as `keep_before` copied them).
    fn decide(
        &self,
        color: &mut [Vec3],
        before: &[Vec3],
        wanted: Option<&[bool]>,
        decided: &mut [bool],
        rows: &TileRows,
    );
}

/// A `Refine` and where it records its decisions.
pub struct Refinement<'a> {
    pub rule: &'a dyn Refine,
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

/// Marks every pixel of the tile at `rows` as not refined.
pub(super) fn mark_none(refined: &mut [bool], rows: &TileRows) {
    for pixels in rows.each() {
        refined[pixels].fill(false);
    }
}
