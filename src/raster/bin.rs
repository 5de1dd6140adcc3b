//! Binning: which triangles overlap each 64×64 tile, in submission order.

use super::scan::PixelRect;
use super::setup::{ScreenTriangle, Viewport};

/// Tiles are square; 64×64 keeps a tile's depth and triangle buffers (32 KiB) in L1/L2 cache.
pub const TILE_SIZE: u32 = 64;

/// For each tile, the indices of the triangles whose bounds overlap it, in submission order (so
/// depth ties resolve the same way on any number of threads).
pub struct TileBins {
    pub tiles_x: u32,
    pub tiles_y: u32,
    pub bins: Vec<Vec<u32>>,
}

impl TileBins {
    pub fn new(viewport: Viewport, triangles: &[ScreenTriangle]) -> TileBins {
        let tiles_x = viewport.width.div_ceil(TILE_SIZE);
        let tiles_y = viewport.height.div_ceil(TILE_SIZE);
        let mut bins = vec![Vec::new(); (tiles_x * tiles_y) as usize];
        for (index, t) in triangles.iter().enumerate() {
            for ty in t.bounds.y0 / TILE_SIZE..=t.bounds.y1 / TILE_SIZE {
                for tx in t.bounds.x0 / TILE_SIZE..=t.bounds.x1 / TILE_SIZE {
                    bins[(ty * tiles_x + tx) as usize].push(index as u32);
                }
            }
        }
        TileBins {
            tiles_x,
            tiles_y,
            bins,
        }
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
