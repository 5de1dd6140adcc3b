//! Depth-testing one triangle along one row of a tile's visibility buffers.
//!
//! Rows of small triangles are a few pixels long: the compiler's vectorised loop over exactly
//! the row's pixels spent them in its scalar remainder, and its i64 edge functions filled a
//! vector register with four. Where the CPU has AVX2 and the row's edge functions fit in i32
//! from its first slot to its last, the row is walked eight pixels to an instruction in i32 (the
//! same integers), the pixels past its end masked off: the buffers are padded for it.

use super::scan::{EdgeWalk, RowSpan};
use super::setup::ScreenTriangle;
use glam::Vec2;

/// Pixels depth-tested at once on the AVX2 path.
pub const COVER_LANES: usize = 8;

/// One row's slots of the tile's visibility buffers, each padded to a whole number of lanes
/// (`padded_len`): the slots past the row's end are read and written back unchanged.
pub struct RowNearest<'a> {
    pub inv_w: &'a mut [f32],
    pub triangle: &'a mut [u32],
}

/// The slots a row of `pixels` pixels spans, padded to whole lanes.
#[inline(always)]
pub fn padded_len(pixels: usize) -> usize {
    pixels.next_multiple_of(COVER_LANES)
}

/// Which path rows may take: the AVX2 one only where the CPU has been seen to have AVX2 (so a
/// safe caller cannot ask for it elsewhere). Looked up once per tile, not per row.
#[derive(Clone, Copy, Debug)]
pub struct CoverPath {
    avx2: bool,
}

impl CoverPath {
    /// One pixel at a time, on any CPU.
    pub const PORTABLE: CoverPath = CoverPath { avx2: false };

    /// The fastest path this CPU has.
    #[inline(always)]
    pub fn detect() -> CoverPath {
        #[cfg(target_arch = "x86_64")]
        if std::is_x86_feature_detected!("avx2") {
            return CoverPath { avx2: true };
        }
        CoverPath::PORTABLE
    }
}

impl RowNearest<'_> {
    /// Makes `index` the nearest triangle wherever it covers the row and is strictly nearer
    /// (so the first of two equal depths stays: deterministic). `origin` is the triangle's
    /// attribute origin moved by the pass's sample shift.
    #[inline(always)]
    pub fn cover(
        self,
        t: &ScreenTriangle,
        row: &RowSpan,
        index: u32,
        origin: Vec2,
        path: CoverPath,
    ) {
        let pixels = (row.x1 - row.x0 + 1) as usize;
        debug_assert_eq!(self.inv_w.len(), padded_len(pixels));
        #[cfg(target_arch = "x86_64")]
        if path.avx2
            && let Some(narrow) = NarrowEdges::new(&row.edges, self.inv_w.len())
        {
            // SAFETY: `path` says the CPU has AVX2; the slices are whole lanes long.
            unsafe { self.cover_avx2(t, row, index, origin, pixels, narrow) };
            return;
        }
        self.cover_each(t, row, index, origin, pixels);
    }

    /// One pixel at a time in i64, branch-free (so it vectorises for long rows).
    #[inline(always)]
    fn cover_each(
        self,
        t: &ScreenTriangle,
        row: &RowSpan,
        index: u32,
        origin: Vec2,
        pixels: usize,
    ) {
        let offset_y = (row.y as f32 + 0.5) - origin.y;
        let mut edges = row.edges;
        let slots = self.inv_w[..pixels]
            .iter_mut()
            .zip(&mut self.triangle[..pixels]);
        for (x, (nearest_inv_w, nearest)) in (row.x0 as i32..).zip(slots) {
            // As `pixel_offset` and `AttributePlane::at`, term by term: the same bits.
            let offset_x = (x as f32 + 0.5) - origin.x;
            let inv_w = t.inv_w.at_origin + t.inv_w.dx * offset_x + t.inv_w.dy * offset_y;
            let nearer = edges.inside() & (inv_w > *nearest_inv_w);
            *nearest_inv_w = if nearer { inv_w } else { *nearest_inv_w };
            *nearest = if nearer { index } else { *nearest };
            edges.advance();
        }
    }

    /// Eight pixels at a time in i32, with the same arithmetic as `cover_each` (no FMA).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[inline]
    fn cover_avx2(
        self,
        t: &ScreenTriangle,
        row: &RowSpan,
        index: u32,
        origin: Vec2,
        pixels: usize,
        edges: NarrowEdges,
    ) {
        use std::arch::x86_64::*;
        let NarrowEdges { at, steps } = edges;
        let offset_y = (row.y as f32 + 0.5) - origin.y;
        let lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        let mut edge = [0, 1, 2].map(|i| {
            let step = _mm256_mullo_epi32(_mm256_set1_epi32(steps[i]), lane);
            _mm256_add_epi32(_mm256_set1_epi32(at[i]), step)
        });
        let lane_step = steps.map(|s| _mm256_set1_epi32(s.wrapping_mul(COVER_LANES as i32)));
        let first_x = row.x0 as f32 + 0.5;
        let mut centre_x = _mm256_add_ps(_mm256_set1_ps(first_x), _mm256_cvtepi32_ps(lane));
        let (at_origin, dx) = (
            _mm256_set1_ps(t.inv_w.at_origin),
            _mm256_set1_ps(t.inv_w.dx),
        );
        let dy_offset = _mm256_set1_ps(t.inv_w.dy * offset_y);
        let origin_x = _mm256_set1_ps(origin.x);
        let index = _mm256_castsi256_ps(_mm256_set1_epi32(index as i32));
        let mut remaining = _mm256_set1_epi32(pixels as i32);
        let lanes = self.inv_w.as_chunks_mut::<COVER_LANES>().0.iter_mut();
        let lanes = lanes.zip(self.triangle.as_chunks_mut::<COVER_LANES>().0);
        for (n, (inv_ws, triangles)) in lanes.enumerate() {
            if n > 0 {
                for (edge, step) in edge.iter_mut().zip(&lane_step) {
                    *edge = _mm256_add_epi32(*edge, *step);
                }
                centre_x = _mm256_add_ps(centre_x, _mm256_set1_ps(COVER_LANES as f32));
                remaining = _mm256_sub_epi32(remaining, _mm256_set1_epi32(COVER_LANES as i32));
            }
            let outside = _mm256_or_si256(_mm256_or_si256(edge[0], edge[1]), edge[2]);
            let outside = _mm256_castsi256_ps(_mm256_srai_epi32::<31>(outside));
            let on_row = _mm256_castsi256_ps(_mm256_cmpgt_epi32(remaining, lane));
            let offset_x = _mm256_sub_ps(centre_x, origin_x);
            let depth = _mm256_add_ps(
                _mm256_add_ps(at_origin, _mm256_mul_ps(dx, offset_x)),
                dy_offset,
            );
            // SAFETY: each chunk holds eight f32 or u32; unaligned loads and stores need no
            // alignment.
            unsafe {
                let nearest = _mm256_loadu_ps(inv_ws.as_ptr());
                let nearer = _mm256_cmp_ps::<_CMP_GT_OQ>(depth, nearest);
                let wins = _mm256_andnot_ps(outside, _mm256_and_ps(nearer, on_row));
                _mm256_storeu_ps(inv_ws.as_mut_ptr(), _mm256_blendv_ps(nearest, depth, wins));
                let triangle = triangles.as_mut_ptr().cast::<f32>();
                let held = _mm256_loadu_ps(triangle);
                _mm256_storeu_ps(triangle, _mm256_blendv_ps(held, index, wins));
            }
        }
    }
}

/// A row's edge walk in i32. Every value it takes on the row's slots fits, so sums and products
/// that wrap modulo 2³² on the way still give the exact values there.
#[derive(Clone, Copy)]
struct NarrowEdges {
    at: [i32; 3],
    /// Modulo 2³².
    steps: [i32; 3],
}

impl NarrowEdges {
    /// The walk is linear, so the values at its first and last slot bound all between.
    #[inline(always)]
    fn new(walk: &EdgeWalk, slots: usize) -> Option<NarrowEdges> {
        let last = slots as i64 - 1;
        let fits = |i: usize| {
            let (first, step) = (walk.at[i], walk.steps[i]);
            let end = step.checked_mul(last).and_then(|d| first.checked_add(d));
            i32::try_from(first).is_ok() && end.is_some_and(|end| i32::try_from(end).is_ok())
        };
        ((0..3).all(fits)).then(|| NarrowEdges {
            at: walk.at.map(|a| a as i32),
            steps: walk.steps.map(|s| s as i32),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::setup::AttributePlane;

    /// A small deterministic generator (xorshift64*), enough to spread test rows.
    struct Numbers(u64);

    impl Numbers {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }

        fn below(&mut self, n: u64) -> u64 {
            self.next() % n
        }

        fn signed(&mut self, magnitude: i64) -> i64 {
            self.below(2 * magnitude as u64 + 1) as i64 - magnitude
        }
    }

    /// Edge functions along a row of `slots`: for a narrow row, within i32 on every slot (some
    /// at its very ends); else anywhere, mostly beyond it.
    fn edge(numbers: &mut Numbers, slots: usize, narrow: bool) -> (i64, i64) {
        let magnitudes = if narrow {
            [1 << 8, 1 << 20, 1 << 24]
        } else {
            [1 << 8, 1 << 20, 1 << 28]
        };
        let magnitude = magnitudes[numbers.below(3) as usize];
        let step = numbers.signed(magnitude);
        let (rise, fall) = (step.max(0) * slots as i64, step.min(0) * slots as i64);
        let at = match (narrow, numbers.below(3)) {
            (false, _) => numbers.signed(1 << 33),
            (true, 0) => i64::from(i32::MIN) + numbers.below(1 << 10) as i64 - fall,
            (true, 1) => i64::from(i32::MAX) - numbers.below(1 << 10) as i64 - rise,
            (true, _) => numbers.signed(1 << 12) - step * numbers.below(slots as u64) as i64,
        };
        (at, step)
    }

    /// What `cover` must do, pixel by pixel in i64 without any stepping.
    fn reference(t: &ScreenTriangle, row: &RowSpan, index: u32, origin: Vec2, slots: RowNearest) {
        for k in 0..=(row.x1 - row.x0) as usize {
            let inside = (0..3).all(|i| row.edges.at[i] + row.edges.steps[i] * k as i64 >= 0);
            let depth = depth_at(t, row, origin, k);
            if inside && depth > slots.inv_w[k] {
                (slots.inv_w[k], slots.triangle[k]) = (depth, index);
            }
        }
    }

    /// The triangle's 1/w at the row's k-th pixel, as `AttributePlane::at` gives it.
    fn depth_at(t: &ScreenTriangle, row: &RowSpan, origin: Vec2, k: usize) -> f32 {
        let offset_x = ((row.x0 as usize + k) as f32 + 0.5) - origin.x;
        let offset_y = (row.y as f32 + 0.5) - origin.y;
        t.inv_w.at_origin + t.inv_w.dx * offset_x + t.inv_w.dy * offset_y
    }

    #[test]
    fn both_paths_depth_test_every_pixel_as_the_per_pixel_definition() {
        let mut numbers = Numbers(0x9e37_79b9_7f4a_7c15);
        let mut narrow_rows = 0;
        for case in 0..4000 {
            let pixels = 1 + numbers.below(70) as usize;
            let padded = padded_len(pixels);
            let x0 = numbers.below(1900) as u32;
            let narrow = case % 2 == 0;
            let row_edges = [0, 1, 2].map(|_| edge(&mut numbers, padded, narrow));
            let row = RowSpan {
                y: numbers.below(1080) as u32,
                x0,
                x1: x0 + pixels as u32 - 1,
                edges: EdgeWalk {
                    at: row_edges.map(|(at, _)| at),
                    steps: row_edges.map(|(_, step)| step),
                },
            };
            narrow_rows += usize::from(NarrowEdges::new(&row.edges, padded).is_some());
            let mut t: ScreenTriangle = bytemuck::Zeroable::zeroed();
            let unit = |numbers: &mut Numbers| numbers.below(1 << 20) as f32 / (1 << 20) as f32;
            t.inv_w = AttributePlane {
                at_origin: unit(&mut numbers),
                dx: (unit(&mut numbers) - 0.5) * 1e-3,
                dy: (unit(&mut numbers) - 0.5) * 1e-3,
            };
            let origin = Vec2::new(x0 as f32 - 0.75, row.y as f32 - 0.25);
            // Nothing drawn, something drawn, or a tie with this triangle (which it loses).
            let own_depth = |k: usize| depth_at(&t, &row, origin, k);
            let depths: Vec<f32> = (0..padded)
                .map(|k| [0.0, unit(&mut numbers), own_depth(k)][numbers.below(3) as usize])
                .collect();
            let triangles: Vec<u32> = (0..padded).map(|_| numbers.next() as u32).collect();
            let covered = |how: &dyn Fn(RowNearest)| {
                let (mut inv_w, mut triangle) = (depths.clone(), triangles.clone());
                how(RowNearest {
                    inv_w: &mut inv_w,
                    triangle: &mut triangle,
                });
                (inv_w, triangle)
            };
            let index = case as u32;
            let expected = covered(&|slots| reference(&t, &row, index, origin, slots));
            for path in [CoverPath::PORTABLE, CoverPath::detect()] {
                let got = covered(&|slots| slots.cover(&t, &row, index, origin, path));
                assert_eq!(got, expected, "case {case}, {path:?}, {row:?}");
            }
        }
        assert!(narrow_rows >= 1900, "only {narrow_rows} rows fit in i32");
    }
}
