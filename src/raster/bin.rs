//! Binning: which triangles overlap each 64×64 tile, in submission order.

use super::pixel_rect::PixelRect;
use super::setup::{ScreenTriangle, Viewport};

/// Tiles are square; 64×64 keeps a tile's depth and triangle buffers (32 KiB) in L1/L2 cache.
pub const TILE_SIZE: u32 = 64;

/// For each tile, the indices of the triangles whose bounds overlap it, in submission order (so
/// depth ties resolve the same way on any number of threads).
pub struct TileBins {
    pub tiles_x: u32,
    pub tiles_y: u32,
    /// Every tile's triangles, tile after tile: counted first, then placed, so that no tile's
    /// list grows (and is copied) as triangles arrive.
    triangles: Vec<u32>,
    /// Where each tile's triangles start in `triangles`; one more entry than there are tiles.
    starts: Vec<usize>,
}

impl TileBins {
    pub fn new(viewport: Viewport, triangles: &[ScreenTriangle]) -> TileBins {
        let tiles_x = viewport.width.div_ceil(TILE_SIZE);
        let tiles_y = viewport.height.div_ceil(TILE_SIZE);
        let tiles_of = |t: &ScreenTriangle| {
            let (x0, x1) = (t.bounds.x0 / TILE_SIZE, t.bounds.x1 / TILE_SIZE);
            (t.bounds.y0 / TILE_SIZE..=t.bounds.y1 / TILE_SIZE)
                .flat_map(move |ty| (x0..=x1).map(move |tx| (ty * tiles_x + tx) as usize))
        };
        let mut starts = vec![0usize; (tiles_x * tiles_y) as usize + 1];
        for tile in triangles.iter().flat_map(tiles_of) {
            starts[tile + 1] += 1;
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        let mut next = starts.clone();
        let mut binned = vec![0u32; *starts.last().expect("one more than the tiles")];
        for (index, t) in triangles.iter().enumerate() {
            for tile in tiles_of(t) {
                binned[next[tile]] = index as u32;
                next[tile] += 1;
            }
        }
        TileBins {
            tiles_x,
            tiles_y,
            triangles: binned,
            starts,
        }
    }

    /// The triangles overlapping tile (tx, ty), in submission order.
    pub fn bin(&self, tx: u32, ty: u32) -> &[u32] {
        let tile = (ty * self.tiles_x + tx) as usize;
        &self.triangles[self.starts[tile]..self.starts[tile + 1]]
    }

    /// The pixels of tile (tx, ty), cut to the viewport.
    pub fn tile_rect(viewport: Viewport, tx: u32, ty: u32) -> PixelRect {
        PixelRect {
            x0: tx * TILE_SIZE,
            y0: ty * TILE_SIZE,
            x1: ((tx + 1) * TILE_SIZE).min(viewport.width) - 1,
            y1: ((ty + 1) * TILE_SIZE).min(viewport.height) - 1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_tile_holds_the_triangles_overlapping_it_in_order() {
        let viewport = Viewport {
            width: 300,
            height: 200,
        };
        let mut state = 12345u32;
        let mut next = |n: u32| {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            (state >> 8) % n
        };
        let triangles: Vec<ScreenTriangle> = (0..500)
            .map(|_| {
                let (x0, y0) = (next(300), next(200));
                let widest = if next(4) == 0 { 300 } else { 20 };
                let (w, h) = (next(widest), next(40));
                let mut t: ScreenTriangle = bytemuck::Zeroable::zeroed();
                t.bounds = PixelRect {
                    x0,
                    y0,
                    x1: (x0 + w).min(299),
                    y1: (y0 + h).min(199),
                };
                t
            })
            .collect();
        let bins = TileBins::new(viewport, &triangles);
        for ty in 0..bins.tiles_y {
            for tx in 0..bins.tiles_x {
                let tile = TileBins::tile_rect(viewport, tx, ty);
                let overlapping: Vec<u32> = (0..triangles.len() as u32)
                    .filter(|&i| {
                        let b = &triangles[i as usize].bounds;
                        b.x0 <= tile.x1 && tile.x0 <= b.x1 && b.y0 <= tile.y1 && tile.y0 <= b.y1
                    })
                    .collect();
                assert_eq!(bins.bin(tx, ty), overlapping, "tile ({tx}, {ty})");
            }
        }
    }
}
