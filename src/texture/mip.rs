//! The mip chain: each level the box-filtered half of the one before, down to 1×1.

use std::ops::{Add, Mul};

use super::texel_grid::TexelGrid;
use crate::area_average::area_weights;

/// What can be averaged: linear texels (`Vec4`) and heights (`f32`).
pub trait Averageable: Copy + Default + Add<Output = Self> + Mul<f32, Output = Self> {}
impl<T: Copy + Default + Add<Output = T> + Mul<f32, Output = T>> Averageable for T {}

/// Levels from full size (0) to 1×1. Sides halve rounding down, never below 1, so
/// non-power-of-two and 1×N images work; odd sides use exact fractional box weights,
/// which keeps every level's average equal to the image's.
#[derive(Debug, Clone)]
pub struct MipChain<T> {
    levels: Vec<TexelGrid<T>>,
}

impl<T: Averageable> MipChain<T> {
    pub fn build(base: TexelGrid<T>) -> Self {
        let mut levels = vec![base];
        while let Some(next) = levels.last().and_then(downsample) {
            levels.push(next);
        }
        Self { levels }
    }

    pub fn levels(&self) -> &[TexelGrid<T>] {
        &self.levels
    }

    pub fn base(&self) -> &TexelGrid<T> {
        &self.levels[0]
    }

    /// `level` is clamped to the chain.
    #[inline]
    pub fn level(&self, level: usize) -> &TexelGrid<T> {
        &self.levels[level.min(self.levels.len() - 1)]
    }

    pub fn coarsest_level(&self) -> usize {
        self.levels.len() - 1
    }

    /// The texels of every level, in bytes.
    pub fn bytes(&self) -> u64 {
        let texels: usize = self.levels.iter().map(|level| level.texels().len()).sum();
        (texels * std::mem::size_of::<T>()) as u64
    }
}

/// The next level, or `None` once the raster is 1×1.
fn downsample<T: Averageable>(src: &TexelGrid<T>) -> Option<TexelGrid<T>> {
    if src.width() == 1 && src.height() == 1 {
        return None;
    }
    let (w, h) = (half(src.width()), half(src.height()));
    let columns = area_weights(src.width() as usize, w as usize);
    let rows = area_weights(src.height() as usize, h as usize);
    Some(TexelGrid::from_fn(w, h, |x, y| {
        let mut sum = T::default();
        for &(j, wy) in &rows[y as usize] {
            for &(i, wx) in &columns[x as usize] {
                sum = sum + src.at(i as u32, j as u32) * (wx * wy);
            }
        }
        sum
    }))
}

fn half(side: u32) -> u32 {
    (side / 2).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mean(raster: &TexelGrid<f32>) -> f32 {
        raster.texels().iter().sum::<f32>() / raster.texels().len() as f32
    }

    #[test]
    fn odd_sizes_keep_the_average_and_end_at_one_texel() {
        let base = TexelGrid::from_fn(7, 3, |x, y| (x * 3 + y * y) as f32);
        let chain = MipChain::build(base.clone());
        let sizes: Vec<_> = chain
            .levels()
            .iter()
            .map(|l| (l.width(), l.height()))
            .collect();
        assert_eq!(sizes, [(7, 3), (3, 1), (1, 1)]);
        for level in chain.levels() {
            assert!((mean(level) - mean(&base)).abs() < 1e-4);
        }
    }

    #[test]
    fn one_by_n_and_one_by_one() {
        let chain = MipChain::build(TexelGrid::from_fn(1, 5, |_, y| y as f32));
        assert_eq!(chain.levels().len(), 3);
        assert_eq!(chain.level(99).texels(), &[2.0]);
        assert_eq!(
            MipChain::build(TexelGrid::from_fn(1, 1, |_, _| 4.0))
                .levels()
                .len(),
            1
        );
    }
}
