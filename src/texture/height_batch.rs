//! Height samples of many points at once, as a fragment batch takes them: each point's mip level
//! and first taps are computed for a chunk of points in plain arrays (which the compiler
//! vectorises), then each point's 4×4 neighbourhood is weighted. The same arithmetic as
//! `HeightMap::sample_gradient`, so the same values to the bit.

use glam::{Vec2, Vec4};

use super::height::{HeightMap, HeightSample, first_tap, neighbourhood, weigh_rows};
use super::sampler::Footprint;
use super::wrap::Wrap;

/// Points whose levels and taps are computed together.
const CHUNK: usize = 64;

impl HeightMap {
    /// `sample_gradient` of every `st[k]` with `footprints[k]` into `out[k]` (all as long).
    pub fn sample_gradient_many(
        &self,
        st: &[Vec2],
        footprints: &[Footprint],
        (wrap_s, wrap_t): (Wrap, Wrap),
        out: &mut [HeightSample],
    ) {
        assert_eq!(st.len(), out.len(), "one output per point");
        assert_eq!(st.len(), footprints.len(), "one footprint per point");
        crate::simd::widest_rounding(
            #[inline(always)]
            || {
                let chunks = st.chunks(CHUNK).zip(footprints.chunks(CHUNK));
                for ((st, footprints), out) in chunks.zip(out.chunks_mut(CHUNK)) {
                    self.gradient_chunk(st, footprints, (wrap_s, wrap_t), out);
                }
            },
        );
    }

    /// Up to `CHUNK` points: the finer level around each footprint for all, then the coarser
    /// one, blended in, for those between two levels.
    #[inline(always)]
    fn gradient_chunk(
        &self,
        st: &[Vec2],
        footprints: &[Footprint],
        wraps: (Wrap, Wrap),
        out: &mut [HeightSample],
    ) {
        let mut levels = [0usize; CHUNK];
        let mut blends = [0.0f32; CHUNK];
        for ((level, blend), footprint) in levels.iter_mut().zip(&mut blends).zip(footprints) {
            let lod = footprint.level_of_detail(&self.chain);
            let fine = lod.floor();
            *blend = lod - fine;
            *level = fine as usize;
        }
        let mut taps = ChunkTaps::default();
        taps.fill(self, &levels, st, wraps);
        for (k, out) in out.iter_mut().enumerate() {
            *out = taps.weigh(self, levels[k], k, wraps);
        }
        if !blends.iter().take(st.len()).any(|&blend| blend != 0.0) {
            return;
        }
        levels.iter_mut().for_each(|level| *level += 1);
        taps.fill(self, &levels, st, wraps);
        for (k, (out, &blend)) in out.iter_mut().zip(&blends).enumerate() {
            if blend != 0.0 {
                let far = taps.weigh(self, levels[k], k, wraps);
                *out = *out * (1.0 - blend) + far * blend;
            }
        }
    }
}

/// Each point's first tap and fraction along s and t on the level it is sampled at, and where
/// its four rows of taps start in the level's texels: `None` where the taps along s wrap.
struct ChunkTaps {
    across: [(i32, f32); CHUNK],
    down: [(i32, f32); CHUNK],
    rows: [Option<[usize; 4]>; CHUNK],
}

impl Default for ChunkTaps {
    fn default() -> Self {
        ChunkTaps {
            across: [(0, 0.0); CHUNK],
            down: [(0, 0.0); CHUNK],
            rows: [None; CHUNK],
        }
    }
}

impl ChunkTaps {
    /// The taps of `st` (at most `CHUNK` points) on the levels `levels` name.
    #[inline(always)]
    fn fill(&mut self, map: &HeightMap, levels: &[usize; CHUNK], st: &[Vec2], wraps: (Wrap, Wrap)) {
        let mut sizes = [[0u32; CHUNK]; 2];
        let mut coords = [[0.0f32; CHUNK]; 2];
        for (k, p) in st.iter().enumerate() {
            let level = map.chain.level(levels[k]);
            sizes[0][k] = level.width();
            sizes[1][k] = level.height();
            (coords[0][k], coords[1][k]) = (p.x, p.y);
        }
        fill_axis(&mut self.across, wraps.0, &coords[0], &sizes[0]);
        fill_axis(&mut self.down, wraps.1, &coords[1], &sizes[1]);
        for (k, rows) in self.rows.iter_mut().enumerate().take(st.len()) {
            let (x, y) = (self.across[k].0, self.down[k].0);
            let (width, height) = (sizes[0][k], sizes[1][k]);
            *rows = if x >= 0 && x + 4 <= width as i32 {
                let start = |j| wraps.1.index(y + j, height) as usize * width as usize + x as usize;
                Some([start(0), start(1), start(2), start(3)])
            } else {
                None
            };
        }
    }

    /// Point `k`'s sample on level `level` from its taps.
    #[inline(always)]
    fn weigh(&self, map: &HeightMap, level: usize, k: usize, wraps: (Wrap, Wrap)) -> HeightSample {
        let level = map.chain.level(level);
        let (across, down) = (self.across[k], self.down[k]);
        match self.rows[k] {
            Some(starts) => {
                let texels = level.texels();
                let row = |start: usize| Vec4::from_slice(&texels[start..start + 4]);
                let rows = [
                    row(starts[0]),
                    row(starts[1]),
                    row(starts[2]),
                    row(starts[3]),
                ];
                weigh_rows(level, rows, across.1, down.1)
            }
            None => neighbourhood(level, across, down, wraps.0, wraps.1),
        }
    }
}

/// `first_tap` of every lane, one loop per wrap mode (lanes past the points are computed and
/// unused).
#[inline(always)]
fn fill_axis(
    taps: &mut [(i32, f32); CHUNK],
    wrap: Wrap,
    coords: &[f32; CHUNK],
    sizes: &[u32; CHUNK],
) {
    let fill = |taps: &mut [(i32, f32); CHUNK], wrap: Wrap| {
        for ((tap, &s), &n) in taps.iter_mut().zip(coords).zip(sizes) {
            *tap = first_tap(wrap, s, n);
        }
    };
    match wrap {
        Wrap::Repeat => fill(taps, Wrap::Repeat),
        Wrap::Clamp => fill(taps, Wrap::Clamp),
        Wrap::Mirror => fill(taps, Wrap::Mirror),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::TexelGrid;

    /// Through every pair of wraps, the batch gives `sample_gradient`'s bits at
    /// `points_and_footprints`.
    #[test]
    fn the_batch_samples_as_one_point_at_a_time() {
        let map = HeightMap::from_heights(TexelGrid::from_fn(37, 20, |x, y| {
            ((x * 13 + y * 29) % 11) as f32 / 10.0
        }));
        let count = 3 * CHUNK + 17;
        let (st, footprints) = super::super::batch_test_points::points_and_footprints(count);
        let wraps = [Wrap::Repeat, Wrap::Clamp, Wrap::Mirror];
        for pair in wraps.into_iter().flat_map(|a| wraps.map(|b| (a, b))) {
            let mut batch = vec![HeightSample::default(); count];
            map.sample_gradient_many(&st, &footprints, pair, &mut batch);
            for k in 0..count {
                let one = map.sample_gradient(st[k], pair.0, pair.1, footprints[k]);
                let bits = |s: HeightSample| [s.height, s.dh_ds, s.dh_dt].map(f32::to_bits);
                assert_eq!(bits(batch[k]), bits(one), "point {k} {pair:?}");
            }
        }
    }
}
