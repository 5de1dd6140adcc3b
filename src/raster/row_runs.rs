//! A tile row split into runs of pixels handled alike, found from bit sets: one word per row
//! instead of a test per pixel, and work per run rather than per pixel.

use super::bin::TILE_SIZE;
use std::ops::Range;

/// A row's pixels as bits: bit i is the row's i-th pixel from the tile's left edge.
pub(super) type RowBits = u64;
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
        let drawn = positive_bits(drawn);
        let wanted = wanted.map_or(RowBits::MAX, true_bits);
        RowRuns {
            visible: wanted & drawn,
            background: wanted & !drawn,
            width,
            at: 0,
        }
    }
}

/// Elements per whole tile row.
const ROW: usize = RowBits::BITS as usize;

/// The bit set of a row's positive elements (at most 64). A whole tile row, the usual case,
/// takes one SSE2 compare and mask move per four: the compiler's own vectorisation of the
/// loop moves each lane's bit separately, which shows in adaptive stills, whose masked passes
/// make bit sets of every row.
#[inline(always)]
fn positive_bits(row: &[f32]) -> RowBits {
    #[cfg(target_arch = "x86_64")]
    if let Ok(row) = <&[f32; ROW]>::try_from(row) {
        use std::arch::x86_64::{_mm_cmpgt_ps, _mm_loadu_ps, _mm_movemask_ps, _mm_setzero_ps};
        let mut set = 0;
        for (i, four) in row.chunks_exact(4).enumerate() {
            // SAFETY: SSE and SSE2 are part of x86-64; `four` holds four f32s, and an
            // unaligned load needs no alignment.
            let positive = unsafe {
                let lanes = _mm_loadu_ps(four.as_ptr());
                _mm_movemask_ps(_mm_cmpgt_ps(lanes, _mm_setzero_ps()))
            };
            set |= RowBits::from(positive as u32) << (4 * i);
        }
        return set;
    }
    bits(row, |&x| x > 0.0)
}

/// The bit set of a row's true elements (at most 64); a whole tile row, sixteen at a time.
#[inline(always)]
pub(super) fn true_bits(row: &[bool]) -> RowBits {
    #[cfg(target_arch = "x86_64")]
    if let Ok(row) = <&[bool; ROW]>::try_from(row) {
        use std::arch::x86_64::{
            __m128i, _mm_cmpgt_epi8, _mm_loadu_si128, _mm_movemask_epi8, _mm_setzero_si128,
        };
        let bytes: &[u8] = bytemuck::cast_slice(row);
        let mut set = 0;
        for (i, sixteen) in bytes.chunks_exact(16).enumerate() {
            // SAFETY: SSE2 is part of x86-64; `sixteen` holds 16 bytes, and an unaligned load
            // needs no alignment. A bool's byte is 0 or 1.
            let set_bytes = unsafe {
                let lanes = _mm_loadu_si128(sixteen.as_ptr().cast::<__m128i>());
                _mm_movemask_epi8(_mm_cmpgt_epi8(lanes, _mm_setzero_si128()))
            };
            set |= RowBits::from(set_bytes as u32) << (16 * i);
        }
        return set;
    }
    bits(row, |&w| w)
}

/// The bit set of the elements of `row` (at most 64) that pass `test`.
#[inline(always)]
fn bits<T>(row: &[T], test: impl Fn(&T) -> bool) -> RowBits {
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
                // Every kind of 1/w a slot holds, and signed zeros and subnormals besides.
                let value = next() as usize;
                drawn.push(if d {
                    [0.5, f32::MIN_POSITIVE, 1e-45, f32::INFINITY][value % 4]
                } else {
                    [0.0, -0.0, -1.0][value % 3]
                });
                wanted.push(w);
            }
            for mask in [None, Some(&wanted[..])] {
                let runs: Vec<_> = RowRuns::new(&drawn, mask).collect();
                assert_eq!(runs, runs_by_pixel(&drawn, mask), "{drawn:?} {mask:?}");
            }
        }
    }
}
