//! Points for the tests that a batch sampler gives one sample's bits: over several periods of
//! the texture, both signs, with footprints from magnified to past the coarsest level, and a
//! NaN one.

use super::sampler::Footprint;
use glam::Vec2;

/// `count` texture coordinates and a footprint for each.
pub fn points_and_footprints(count: usize) -> (Vec<Vec2>, Vec<Footprint>) {
    let st = (0..count)
        .map(|k| Vec2::new(k as f32 * 0.0137 - 2.3, 3.1 - k as f32 * 0.0211))
        .collect();
    let footprints = (0..count)
        .map(|k| match k % 7 {
            6 => Footprint::new(f32::NAN, 0.0, 0.0, 0.0),
            step => {
                let d = 0.004 * 2f32.powf(step as f32 * 1.3 + (k % 3) as f32 * 0.4);
                Footprint::new(d, 0.3 * d, -0.2 * d, 0.9 * d)
            }
        })
        .collect();
    (st, footprints)
}
