//! Where a tile's pixels sit in a strip of rows.

use super::pixel_rect::PixelRect;
use std::ops::Range;

/// Where a tile's pixels sit in a strip of `width`-pixel rows starting at row `first_row`.
pub struct TileRows<'r> {
    pub width: u32,
    pub first_row: u32,
    pub rect: &'r PixelRect,
}

impl TileRows<'_> {
    /// The strip's pixels of each of the rect's rows, top to bottom.
    pub fn each(&self) -> impl Iterator<Item = Range<usize>> + '_ {
        let n = (self.rect.x1 - self.rect.x0 + 1) as usize;
        (self.rect.y0..=self.rect.y1).map(move |y| {
            let start = ((y - self.first_row) * self.width + self.rect.x0) as usize;
            start..start + n
        })
    }
}

/// Whether `mask` (over the strip; `None`: every pixel) wants any pixel of the tile at `rows`.
pub(super) fn any_wanted(mask: Option<&[bool]>, rows: &TileRows) -> bool {
    let Some(mask) = mask else {
        return true;
    };
    rows.each().any(|pixels| mask[pixels].contains(&true))
}
