//! The columns a masked pass wants on each row of a tile, so that its visibility is resolved
//! only there: an adaptive still's later passes want a few pixels of most tiles, and resolving
//! every pixel of each tile for them was a large share of the still's work.

use super::bin::TILE_SIZE;
use super::pixel_rect::PixelRect;
use super::row_runs::{RowBits, true_bits};
use super::scan::RowSpan;
use super::tile_rows::TileRows;
use std::ops::RangeInclusive;

/// The wanted pixels of a tile's rows (from the first row of its rect).
pub struct WantedSpans {
    /// Per row, the wanted pixels as bits from the rect's first column.
    bits: [RowBits; TILE_SIZE as usize],
    /// The rect's first row and column.
    first_row: u32,
    first_column: u32,
    /// The smallest rect holding every span.
    bounds: Option<PixelRect>,
}

impl WantedSpans {
    /// The wanted spans of the tile at `rows`, from `mask` over its strip.
    pub fn of(mask: &[bool], rows: &TileRows) -> WantedSpans {
        let first_row = rows.rect.y0;
        let mut spans = WantedSpans {
            bits: [0; TILE_SIZE as usize],
            first_row,
            first_column: rows.rect.x0,
            bounds: None,
        };
        for ((row_bits, pixels), y) in spans.bits.iter_mut().zip(rows.each()).zip(first_row..) {
            *row_bits = true_bits(&mask[pixels]);
            let Some((first, last)) = ends(*row_bits) else {
                continue;
            };
            let row = PixelRect {
                x0: spans.first_column + first,
                y0: y,
                x1: spans.first_column + last,
                y1: y,
            };
            spans.bounds = Some(spans.bounds.map_or(row, |b| b.union(&row)));
        }
        spans
    }

    /// The smallest rect holding every wanted pixel; `None` when none is.
    pub fn bounds(&self) -> Option<PixelRect> {
        self.bounds
    }

    /// Whether any pixel of `rect` (within the tile) is wanted.
    #[inline(always)]
    pub fn any_in(&self, rect: &PixelRect) -> bool {
        let rows = (rect.y0 - self.first_row) as usize..=(rect.y1 - self.first_row) as usize;
        let wanted = self.bits[rows].iter().fold(0, |any, &bits| any | bits);
        wanted & self.columns(rect.x0, rect.x1) != 0
    }

    /// The part of `row` (within the tile) from its first to its last wanted pixel, if any.
    #[inline(always)]
    pub fn clip(&self, row: RowSpan) -> Option<RowSpan> {
        let bits = self.bits[(row.y - self.first_row) as usize] & self.columns(row.x0, row.x1);
        let (first, last) = ends(bits)?;
        row.within(self.first_column + first, self.first_column + last)
    }

    /// The bits of columns `x0..=x1` (within the tile).
    #[inline(always)]
    fn columns(&self, x0: u32, x1: u32) -> RowBits {
        let (first, last) = (x0 - self.first_column, x1 - self.first_column);
        (RowBits::MAX >> (RowBits::BITS - 1 - last)) & (RowBits::MAX << first)
    }

    /// The slots from each row's first to its last wanted pixel, in a tile buffer of
    /// `TILE_SIZE`-slot rows whose first slot is the rect's first pixel; one range per row with
    /// any.
    pub fn slots(&self) -> impl Iterator<Item = RangeInclusive<usize>> + '_ {
        (0..).zip(&self.bits).filter_map(|(row, &bits)| {
            let (first, last) = ends(bits)?;
            let start = (row * TILE_SIZE + first) as usize;
            Some(start..=start + (last - first) as usize)
        })
    }
}

/// The first and last set bit of a row, if any.
#[inline(always)]
fn ends(bits: RowBits) -> Option<(u32, u32)> {
    (bits != 0).then(|| {
        (
            bits.trailing_zeros(),
            RowBits::BITS - 1 - bits.leading_zeros(),
        )
    })
}
