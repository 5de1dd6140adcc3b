//! Sampling many points at once, as a fragment batch does: the filter and the wrap modes are
//! dispatched once per batch, and bilinear taps are computed for a chunk of points in plain
//! arrays with branch-free wrapping (which the compiler vectorises) before the texels are
//! gathered. Same arithmetic as one sample at a time, so the same values to the bit.

use glam::Vec2;

use super::mip::{Averageable, MipChain};
use super::sampler::{Filter, Footprint, Sampler, lerp};
use super::texel_grid::TexelGrid;
use super::wrap::Wrap;

/// Points whose taps are computed together.
const CHUNK: usize = 64;

/// Whether `whole_to_i32` is exact for every tap of the level (sides below 2^20; the default
/// image limits allow 16384).
fn fits_taps<T: Copy>(level: &TexelGrid<T>) -> bool {
    level.width().max(level.height()) < 1 << 20
}

impl Filter {
    /// Whether the filter reads the footprint (only a trilinear filter picks a mip level).
    pub fn uses_footprint(self) -> bool {
        self == Filter::Trilinear
    }
}

impl Sampler {
    /// Samples `st[k]` into `out[k]` for every k (`out` as long as `st`). `footprints` is read
    /// only when the filter uses it (`Filter::uses_footprint`), and then holds one per point;
    /// otherwise it may be empty.
    pub fn sample_many<T: Averageable>(
        &self,
        chain: &MipChain<T>,
        st: &[Vec2],
        footprints: &[Footprint],
        out: &mut [T],
    ) {
        assert_eq!(st.len(), out.len(), "one output per point");
        match self.filter {
            Filter::Bilinear if fits_taps(chain.base()) => crate::simd::widest_rounding(
                #[inline(always)]
                || {
                    for (st, out) in st.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
                        self.bilinear_chunk(chain.base(), st, out);
                    }
                },
            ),
            Filter::Bilinear => {
                for (o, &p) in out.iter_mut().zip(st) {
                    *o = self.bilinear(chain.base(), p);
                }
            }
            Filter::Nearest => {
                for (o, &p) in out.iter_mut().zip(st) {
                    *o = self.nearest(chain.base(), p);
                }
            }
            Filter::Trilinear => {
                assert_eq!(st.len(), footprints.len(), "one footprint per point");
                crate::simd::widest_rounding(
                    #[inline(always)]
                    || {
                        let chunks = st.chunks(CHUNK).zip(footprints.chunks(CHUNK));
                        for ((st, footprints), out) in chunks.zip(out.chunks_mut(CHUNK)) {
                            self.trilinear_chunk(chain, st, footprints, out);
                        }
                    },
                );
            }
        }
    }

    /// Trilinear samples of up to `CHUNK` points. Where every footprint of the chunk is
    /// magnified (a close-up's common case) each sample is the base level's bilinear one, so the
    /// chunk takes the bilinear batch: the same bits, its taps vectorised.
    #[inline(always)]
    fn trilinear_chunk<T: Averageable>(
        &self,
        chain: &MipChain<T>,
        st: &[Vec2],
        footprints: &[Footprint],
        out: &mut [T],
    ) {
        let magnified = |f: &Footprint| f.level_of_detail(chain) == 0.0;
        if fits_taps(chain.base()) && footprints.iter().all(magnified) {
            self.bilinear_chunk(chain.base(), st, out);
            return;
        }
        for ((o, &p), &f) in out.iter_mut().zip(st).zip(footprints) {
            *o = self.trilinear(chain, p, f);
        }
    }

    /// Bilinear samples of up to `CHUNK` points: taps first, then the gather.
    #[inline(always)]
    fn bilinear_chunk<T: Averageable>(&self, level: &TexelGrid<T>, st: &[Vec2], out: &mut [T]) {
        let (width, height) = (level.width(), level.height());
        let mut across = AxisTaps::default();
        let mut down = AxisTaps::default();
        across.fill(self.wrap_s, width, st.iter().map(|p| p.x));
        down.fill(self.wrap_t, height, st.iter().map(|p| p.y));
        let texels = level.texels();
        let row = |y: u32| y as usize * width as usize;
        for (k, out) in out.iter_mut().enumerate() {
            let (row0, row1) = (row(down.first[k]), row(down.second[k]));
            let (x0, x1) = (across.first[k] as usize, across.second[k] as usize);
            let top = lerp(texels[row0 + x0], texels[row0 + x1], across.weight[k]);
            let bottom = lerp(texels[row1 + x0], texels[row1 + x1], across.weight[k]);
            *out = lerp(top, bottom, down.weight[k]);
        }
    }
}

/// The two texels around each coordinate of a chunk along one axis, and the second's weight.
struct AxisTaps {
    first: [u32; CHUNK],
    second: [u32; CHUNK],
    weight: [f32; CHUNK],
}

impl Default for AxisTaps {
    fn default() -> Self {
        AxisTaps {
            first: [0; CHUNK],
            second: [0; CHUNK],
            weight: [0.0; CHUNK],
        }
    }
}

impl AxisTaps {
    /// The taps of `coords` (at most `CHUNK`) on an axis of `n` texels; one loop per wrap mode.
    #[inline(always)]
    fn fill(&mut self, wrap: Wrap, n: u32, coords: impl Iterator<Item = f32>) {
        let mut s = [0.0; CHUNK];
        for (s, c) in s.iter_mut().zip(coords) {
            *s = c;
        }
        match wrap {
            Wrap::Repeat => self.fill_with(&s, n, |s| Wrap::Repeat.reduce(s), repeat_near),
            Wrap::Clamp => self.fill_with(&s, n, |s| Wrap::Clamp.reduce(s), clamp_near),
            Wrap::Mirror => self.fill_with(&s, n, |s| Wrap::Mirror.reduce(s), mirror_near),
        }
    }

    /// As `linear_taps`, over the whole chunk (lanes past the points are computed and unused),
    /// with the wrap's reduction and branch-free index inlined into the loop.
    #[inline(always)]
    fn fill_with(
        &mut self,
        coords: &[f32; CHUNK],
        n: u32,
        reduce: impl Fn(f32) -> f32,
        index: impl Fn(i32, i32) -> i32,
    ) {
        let (texels, n) = (n as f32, n as i32);
        let taps = self
            .first
            .iter_mut()
            .zip(&mut self.second)
            .zip(&mut self.weight);
        for (((first, second), weight), &s) in taps.zip(coords) {
            let x = reduce(s) * texels - 0.5;
            let x0 = x.floor();
            let i0 = whole_to_i32(x0);
            *first = index(i0, n) as u32;
            *second = index(i0 + 1, n) as u32;
            *weight = x - x0;
        }
    }
}

/// A whole `x` of magnitude below 2^22 as an `i32`, read from the bits of x + 1.5·2^23 (whose
/// last mantissa bits then hold x): a saturating `as i32` costs several instructions more per
/// lane. Tap coordinates lie in `-n - 1 ..= 2n`, and images are far narrower than 2^21.
#[inline(always)]
fn whole_to_i32(x: f32) -> i32 {
    const SHIFT: f32 = 12_582_912.0; // 1.5·2^23
    (x + SHIFT).to_bits() as i32 - SHIFT.to_bits() as i32
}

/// `Wrap::Repeat.index` for the taps of a reduced coordinate, `-1 ..= n`.
#[inline(always)]
fn repeat_near(i: i32, n: i32) -> i32 {
    let i = if i < 0 { i + n } else { i };
    if i >= n { i - n } else { i }
}

/// `Wrap::Clamp.index`, for any `i`.
#[inline(always)]
fn clamp_near(i: i32, n: i32) -> i32 {
    i.clamp(0, n - 1)
}

/// `Wrap::Mirror.index` for the taps of a reduced coordinate, `-1 ..= 2n`.
#[inline(always)]
fn mirror_near(i: i32, n: i32) -> i32 {
    let m = if i < 0 { i + 2 * n } else { i };
    let m = if m >= 2 * n { m - 2 * n } else { m };
    if m < n { m } else { 2 * n - 1 - m }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Through every filter and pair of wraps, the batch (its taps and floors in the widest SIMD
    /// the CPU has) gives one sample's bits at `points_and_footprints`.
    #[test]
    fn the_batch_samples_as_one_point_at_a_time() {
        use glam::Vec4;
        let chain = MipChain::build(TexelGrid::from_fn(37, 20, |x, y| {
            let c = |k: u32| ((x * k + y * 29) % 11) as f32 / 10.0;
            Vec4::new(c(13), c(7), c(3), 1.0 - c(5))
        }));
        let count = 3 * CHUNK + 17;
        let (st, footprints) = super::super::batch_test_points::points_and_footprints(count);
        let wraps = [Wrap::Repeat, Wrap::Clamp, Wrap::Mirror];
        let filters = [Filter::Nearest, Filter::Bilinear, Filter::Trilinear];
        for (filter, (wrap_s, wrap_t)) in filters.into_iter().flat_map(|f| {
            wraps
                .into_iter()
                .flat_map(move |a| wraps.map(|b| (f, (a, b))))
        }) {
            let sampler = Sampler {
                filter,
                wrap_s,
                wrap_t,
            };
            let mut batch = vec![Vec4::ZERO; count];
            sampler.sample_many(&chain, &st, &footprints, &mut batch);
            for k in 0..count {
                let one = match filter {
                    Filter::Nearest => sampler.nearest(chain.base(), st[k]),
                    Filter::Bilinear => sampler.bilinear(chain.base(), st[k]),
                    Filter::Trilinear => sampler.trilinear(&chain, st[k], footprints[k]),
                };
                let bits = |v: Vec4| v.to_array().map(f32::to_bits);
                assert_eq!(
                    bits(batch[k]),
                    bits(one),
                    "point {k} {filter:?} {wrap_s:?} {wrap_t:?}"
                );
            }
        }
    }

    #[test]
    fn whole_numbers_convert_exactly() {
        for i in (-4_194_303..=4_194_303)
            .step_by(997)
            .chain([-1, 0, 1, -4_194_303, 4_194_303])
        {
            assert_eq!(whole_to_i32(i as f32), i);
        }
        assert_eq!(whole_to_i32(-0.0), 0);
    }

    #[test]
    fn branch_free_indices_agree_with_the_wrap_over_reduced_taps() {
        for n in [1, 2, 3, 7, 64] {
            for i in -1..=n {
                assert_eq!(repeat_near(i, n) as u32, Wrap::Repeat.index(i, n as u32));
            }
            for i in -1..=2 * n {
                assert_eq!(mirror_near(i, n) as u32, Wrap::Mirror.index(i, n as u32));
            }
            for i in -n - 1..=2 * n {
                assert_eq!(clamp_near(i, n) as u32, Wrap::Clamp.index(i, n as u32));
            }
        }
    }
}
