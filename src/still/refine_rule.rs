//! Adaptive supersampling's refinement: a marked pixel's first samples, then the rest only
//! where those moved it from its centre sample; the others settle as a mix of the two.

use crate::raster::{Refine, TileRows};
use glam::Vec3;

/// The passes from `from_pass` on render only those of the wanted pixels whose colour the
/// earlier passes moved by more than `threshold` (in √colour, per channel, as the contrast mask
/// measures) from what the framebuffer held before the group (a still's centre sample). The
/// wanted pixels that stop there are settled as a mix of the two: `centre_weight` of what was
/// before.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefineRule {
    pub from_pass: usize,
    pub threshold: f32,
    pub centre_weight: f32,
}

impl Refine for RefineRule {
    fn first_decided_pass(&self) -> usize {
        self.from_pass
    }

    fn decide(
        &self,
        color: &mut [Vec3],
        before: &[Vec3],
        wanted: Option<&[bool]>,
        refined: &mut [bool],
        rows: &TileRows,
    ) {
        let mut before = before.iter();
        for pixels in rows.each() {
            for i in pixels {
                let is_wanted = wanted.is_none_or(|wanted| wanted[i]);
                let before = *before.next().expect("keep_before kept this tile");
                refined[i] = is_wanted && moved(color[i], before, self.threshold);
                if is_wanted && !refined[i] {
                    color[i] = settled(color[i], before, self.centre_weight);
                }
            }
        }
    }
}

/// A pixel that stops refining: its first samples' mean mixed with its centre sample.
fn settled(mean: Vec3, centre: Vec3, centre_weight: f32) -> Vec3 {
    mean * (1.0 - centre_weight) + centre * centre_weight
}

/// Whether any channel of `now` differs from `before` by more than `threshold` in √colour.
fn moved(now: Vec3, before: Vec3, threshold: f32) -> bool {
    let key = |c: Vec3| c.max(Vec3::ZERO).to_array().map(f32::sqrt);
    let (now, before) = (key(now), key(before));
    (0..3).any(|c| (now[c] - before[c]).abs() > threshold)
}
