//! A material's bump as the height field of a displaced surface: B(u,v), strength and sign
//! applied, evaluated by the same pattern and image code that shades the bump.

use super::bake::sample_bump;
use super::pattern_batch::{PatternBatch, Sites};
use crate::raster::Fragment;
use crate::scene::Bump;
use crate::surface::{Frames, HeightField};
use glam::Vec2;

/// A bump at a moment, as heights.
#[derive(Debug)]
pub struct BumpHeights {
    bump: Bump,
    time: f64,
}

impl BumpHeights {
    /// The bump's heights at `time`, or `None` when it defines only a slope.
    pub fn new(bump: &Bump, time: f64) -> Option<BumpHeights> {
        bump.has_height().then(|| BumpHeights {
            bump: bump.clone(),
            time,
        })
    }
}

impl HeightField for BumpHeights {
    fn sample(
        &self,
        uvs: &[Vec2],
        frames: &Frames,
        heights: &mut Vec<f32>,
        gradients: &mut Vec<Vec2>,
    ) {
        let fragments: Vec<Fragment> = uvs
            .iter()
            .map(|&uv| Fragment {
                uv,
                depth: 1.0,
                ..Fragment::default()
            })
            .collect();
        let group: Vec<u32> = (0..uvs.len() as u32).collect();
        let at = Sites {
            fragments: &fragments,
            group: &group,
            frames,
        };
        heights.clear();
        heights.resize(uvs.len(), 0.0);
        gradients.clear();
        gradients.resize(uvs.len(), Vec2::ZERO);
        let mut batch = PatternBatch::default();
        sample_bump(&self.bump, at, self.time, &mut batch, (heights, gradients));
        let scale = self.bump.scale();
        for (h, g) in heights.iter_mut().zip(gradients.iter_mut()) {
            // A pattern with no finite value there leaves the surface where it was.
            (*h, *g) = if h.is_finite() && g.is_finite() {
                (*h * scale, *g * scale)
            } else {
                (0.0, Vec2::ZERO)
            };
        }
    }
}
