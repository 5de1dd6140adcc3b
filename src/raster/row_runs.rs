//! A tile row split into runs of pixels handled alike, found from bit sets: one word per row
//! instead of a test per pixel, and work per run rather than per pixel.

use super::bin::TILE_SIZE;
use std::ops::Range;

/// A row's pixels as bits: bit i is the row's i-th pixel from the tile's left edge.
type RowBits = u64;
const _: () = assert!(TILE_SIZE <= RowBits::BITS);

/// What the tile does at a pixel; consecutive pixels of one kind are handled as a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelKind {
    Background,
    Visible,
}

/// The runs of one tile row, left to right, skipping pixels outside the render's mask.
pub struct RowRuns {
    visible: RowBits,
    background: RowBits,
    width: u32,
    at: u32,
}

impl RowRuns {
    /// The runs of a row whose `drawn` depth slots (1/w, 0 where nothing was drawn) and
    /// `wanted` mask (`None`: every pixel) are given for its pixels.
    #[inline]
    pub fn new(drawn: &[f32], wanted: Option<&[bool]>) -> RowRuns {
        let width = drawn.len() as u32;
        debug_assert!(width <= RowBits::BITS && wanted.is_none_or(|w| w.len() == drawn.len()));
        let drawn = bits(drawn, |&inv_w| inv_w > 0.0);
        let wanted = wanted.map_or(RowBits::MAX, |wanted| bits(wanted, |&w| w));
        RowRuns {
            visible: wanted & drawn,
            background: wanted & !drawn,
            width,
            at: 0,
        }
    }
}

/// The bit set of the elements of `row` (at most 64) that pass `test`. A whole tile row, the
/// usual case, has a fixed trip count, which the compiler turns into SIMD compares and mask
/// moves (1.5x faster than the loop over a slice of any length; measured).
#[inline(always)]
fn bits<T>(row: &[T], test: impl Fn(&T) -> bool) -> RowBits {
    if let Ok(row) = <&[T; RowBits::BITS as usize]>::try_from(row) {
        return (0..row.len()).fold(0, |set, i| set | RowBits::from(test(&row[i])) << i);
    }
    let mut set = 0;
    for (i, element) in row.iter().enumerate() {
        set |= RowBits::from(test(element)) << i;
    }
    set
}

impl Iterator for RowRuns {
    /// A run's kind and its pixels, counted from the tile's left edge.
    type Item = (PixelKind, Range<u32>);

    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        // Skip unwanted pixels: those in neither set.
        let rest = (self.visible | self.background)
            .checked_shr(self.at)
            .unwrap_or(0);
        self.at += rest.trailing_zeros();
        if self.at >= self.width {
            return None;
        }
        let (kind, set) = if self.visible >> self.at & 1 == 1 {
            (PixelKind::Visible, self.visible)
        } else {
            (PixelKind::Background, self.background)
        };
        let length = (!(set >> self.at)).trailing_zeros();
        let start = self.at;
        self.at = (start + length).min(self.width);
        Some((kind, start..self.at))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The runs by definition: consecutive pixels of one kind, unwanted ones left out.
    fn runs_by_pixel(drawn: &[f32], wanted: Option<&[bool]>) -> Vec<(PixelKind, Range<u32>)> {
        let kind = |i: usize| {
            wanted.is_none_or(|w| w[i]).then_some(if drawn[i] > 0.0 {
                PixelKind::Visible
            } else {
                PixelKind::Background
            })
        };
        let mut runs: Vec<(PixelKind, Range<u32>)> = Vec::new();
        for i in 0..drawn.len() {
            let Some(k) = kind(i) else { continue };
            match runs.last_mut() {
                Some((last, range)) if *last == k && range.end == i as u32 => range.end += 1,
                _ => runs.push((k, i as u32..i as u32 + 1)),
            }
        }
        runs
    }

    #[test]
    fn runs_from_bits_are_the_runs_pixel_by_pixel() {
        let mut state = 7u64;
        let mut next = move || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            (state >> 33) as u32
        };
        for case in 0..2000 {
            let width = [1, 2, 31, 32, 33, 63, 64][case % 7];
            // Long runs and single pixels: a pixel changes kind with probability 1/4 or 3/4.
            let flip = if case % 2 == 0 { 4 } else { 2 };
            let mut drawn = Vec::new();
            let mut wanted = Vec::new();
            let (mut d, mut w) = (false, true);
            for _ in 0..width {
                d ^= next() % flip == 0;
                w ^= next() % flip == 0;
                drawn.push(if d { 0.5 } else { 0.0 });
                wanted.push(w);
            }
            for mask in [None, Some(&wanted[..])] {
                let runs: Vec<_> = RowRuns::new(&drawn, mask).collect();
                assert_eq!(runs, runs_by_pixel(&drawn, mask), "{drawn:?} {mask:?}");
            }
        }
    }
}
