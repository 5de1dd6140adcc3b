//! The nearest and farthest depth of each 8 × 8 block of a shadow map, so a lookup whose
//! receiver lies wholly in front of every caster around it (most of a lit floor) or wholly
//! behind them (deep in a shadow) is answered without its taps.

use crate::raster::DepthMap;
use rayon::prelude::*;

/// Texels on a side of a block.
const BLOCK: u32 = 8;

/// Per block, the least and greatest depth of its texels (infinity for a texel with nothing).
pub struct DepthBlocks {
    across: u32,
    least: Vec<f32>,
    greatest: Vec<f32>,
}

impl DepthBlocks {
    pub fn new(map: &DepthMap) -> DepthBlocks {
        let size = map.size as usize;
        let across = map.size.div_ceil(BLOCK);
        let mut least = vec![f32::INFINITY; (across * across) as usize];
        let mut greatest = vec![f32::NEG_INFINITY; least.len()];
        let band = (BLOCK as usize * size).max(1);
        least
            .par_chunks_mut(across.max(1) as usize)
            .zip(greatest.par_chunks_mut(across.max(1) as usize))
            .zip(map.depth.par_chunks(band))
            .for_each(|((least, greatest), rows)| {
                for row in rows.chunks(size.max(1)) {
                    for ((least, greatest), texels) in least
                        .iter_mut()
                        .zip(greatest.iter_mut())
                        .zip(row.chunks(BLOCK as usize))
                    {
                        for &d in texels {
                            *least = least.min(d);
                            *greatest = greatest.max(d);
                        }
                    }
                }
            });
        DepthBlocks {
            across,
            least,
            greatest,
        }
    }

    /// The least and greatest depth over the texels from (x0, y0) to (x1, y1), inclusive, or
    /// more (whole blocks).
    pub fn range(&self, (x0, y0): (u32, u32), (x1, y1): (u32, u32)) -> (f32, f32) {
        let (mut least, mut greatest) = (f32::INFINITY, f32::NEG_INFINITY);
        for by in y0 / BLOCK..=y1 / BLOCK {
            for bx in x0 / BLOCK..=x1 / BLOCK {
                let block = (by * self.across + bx) as usize;
                least = least.min(self.least[block]);
                greatest = greatest.max(self.greatest[block]);
            }
        }
        (least, greatest)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_bounds_every_texel_in_it() {
        let size = 37;
        let depth = (0..size * size)
            .map(|k| match k % 11 {
                0 => f32::INFINITY,
                r => (k as f32 * 0.37).sin() * 10.0 + r as f32,
            })
            .collect();
        let map = DepthMap { size, depth };
        let blocks = DepthBlocks::new(&map);
        for (a, b) in [
            ((0, 0), (36, 36)),
            ((3, 5), (4, 9)),
            ((30, 30), (36, 31)),
            ((8, 8), (8, 8)),
        ] {
            let (least, greatest) = blocks.range(a, b);
            for y in a.1..=b.1 {
                for x in a.0..=b.0 {
                    let d = map.at(x, y);
                    assert!(
                        least <= d && d <= greatest,
                        "{x},{y}: {d} outside {least}..{greatest}"
                    );
                }
            }
        }
    }
}
