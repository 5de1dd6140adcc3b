//! Filters (nearest, bilinear, trilinear) composed with per-axis wrap modes.

use glam::Vec2;

use super::mip::{Averageable, MipChain};
use super::texel_grid::TexelGrid;
use super::wrap::Wrap;

/// How texels are combined into one value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Filter {
    /// The texel containing the point, from the full-size level.
    Nearest,
    /// Four texels of the full-size level, texel-centre correct (`x = s·width − 0.5`).
    #[default]
    Bilinear,
    /// Bilinear on the two mip levels around the footprint's level, blended.
    Trilinear,
}

/// A filter with a wrap mode per axis (s across, t down).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Sampler {
    pub filter: Filter,
    pub wrap_s: Wrap,
    pub wrap_t: Wrap,
}

impl Sampler {
    /// The same wrap mode on both axes.
    pub fn new(filter: Filter, wrap: Wrap) -> Self {
        Self {
            filter,
            wrap_s: wrap,
            wrap_t: wrap,
        }
    }

    /// Filters `chain` at texture coordinates `st` (`[0,1)²` spans the image, t = 0 at
    /// the top row). `footprint` only matters for `Trilinear`.
    #[inline]
    pub fn sample<T: Averageable>(&self, chain: &MipChain<T>, st: Vec2, footprint: Footprint) -> T {
        match self.filter {
            Filter::Nearest => self.nearest(chain.base(), st),
            Filter::Bilinear => self.bilinear(chain.base(), st),
            Filter::Trilinear => self.trilinear(chain, st, footprint),
        }
    }

    #[inline(always)]
    pub fn nearest<T: Averageable>(&self, level: &TexelGrid<T>, st: Vec2) -> T {
        let x = self.wrap_s.texel(st.x, level.width());
        let y = self.wrap_t.texel(st.y, level.height());
        level.at(x, y)
    }

    #[inline(always)]
    pub fn bilinear<T: Averageable>(&self, level: &TexelGrid<T>, st: Vec2) -> T {
        let (x0, x1, fx) = linear_taps(self.wrap_s, st.x, level.width());
        let (y0, y1, fy) = linear_taps(self.wrap_t, st.y, level.height());
        let top = lerp(level.at(x0, y0), level.at(x1, y0), fx);
        let bottom = lerp(level.at(x0, y1), level.at(x1, y1), fx);
        lerp(top, bottom, fy)
    }

    #[inline(always)]
    pub fn trilinear<T: Averageable>(
        &self,
        chain: &MipChain<T>,
        st: Vec2,
        footprint: Footprint,
    ) -> T {
        let lod = footprint.level_of_detail(chain);
        let fine = lod.floor();
        let blend = lod - fine;
        let fine = fine as usize;
        let near = self.bilinear(chain.level(fine), st);
        if blend == 0.0 {
            return near;
        }
        lerp(near, self.bilinear(chain.level(fine + 1), st), blend)
    }
}

/// The two texels around `s` on an axis of `n` texels and the weight of the second.
#[inline(always)]
pub(crate) fn linear_taps(wrap: Wrap, s: f32, n: u32) -> (u32, u32, f32) {
    let x = wrap.reduce(s) * n as f32 - 0.5;
    let x0 = x.floor();
    let i0 = x0 as i32;
    (wrap.index(i0, n), wrap.index(i0 + 1, n), x - x0)
}

#[inline(always)]
pub(crate) fn lerp<T: Averageable>(a: T, b: T, t: f32) -> T {
    a * (1.0 - t) + b * t
}

/// The screen-space derivatives of the texture coordinates at a pixel:
/// `dx = (ds/dx, dt/dx)`, `dy = (ds/dy, dt/dy)`. Zero means "magnified": level 0.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Footprint {
    pub dx: Vec2,
    pub dy: Vec2,
}

impl Footprint {
    pub const POINT: Footprint = Footprint {
        dx: Vec2::ZERO,
        dy: Vec2::ZERO,
    };

    pub fn new(ds_dx: f32, dt_dx: f32, ds_dy: f32, dt_dy: f32) -> Self {
        Self {
            dx: Vec2::new(ds_dx, dt_dx),
            dy: Vec2::new(ds_dy, dt_dy),
        }
    }

    /// The mip level (fractional) for `chain`: log2 of the longer footprint side in
    /// texels, clamped to the chain. Always finite: NaN derivatives give level 0,
    /// infinite ones the coarsest level.
    #[inline]
    pub fn level_of_detail<T>(&self, chain: &MipChain<T>) -> f32
    where
        T: Averageable,
    {
        let base = chain.base();
        let texels = Vec2::new(base.width() as f32, base.height() as f32);
        let longest_sq = (self.dx * texels)
            .length_squared()
            .max((self.dy * texels).length_squared());
        if longest_sq <= 1.0 {
            return 0.0; // magnified: the common close-up case needs no logarithm
        }
        // f32::max/min return the non-NaN operand, so NaN ends at 0 and ±inf at the ends.
        (0.5 * log2(longest_sq))
            .max(0.0)
            .min(chain.coarsest_level() as f32)
    }
}

/// log2 to about 3e-5 (plenty for a mip level) without a libm call: the exponent bits
/// plus a quintic on the mantissa. Zero, subnormal and non-finite inputs use `f32::log2`.
#[inline(always)]
fn log2(x: f32) -> f32 {
    if !(f32::MIN_POSITIVE..f32::INFINITY).contains(&x) {
        return x.log2();
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    let t = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000) - 1.0; // mantissa − 1, [0, 1)
    // Least-squares fit of log2(1 + t); exact at t = 0 so powers of two are exact.
    let log_m = t
        * (1.441_825_1
            + t * (-0.708_674_9 + t * (0.415_397_75 + t * (-0.194_390_42 + t * 0.045_870_744))));
    exponent as f32 + log_m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp() -> MipChain<f32> {
        MipChain::build(TexelGrid::from_fn(4, 2, |x, y| (x + 10 * y) as f32))
    }

    #[test]
    fn bilinear_halfway_between_centres_is_the_mean() {
        let sampler = Sampler::new(Filter::Bilinear, Wrap::Clamp);
        let v = sampler.sample(&ramp(), Vec2::new(0.25, 0.25), Footprint::POINT);
        assert!((v - 0.5).abs() < 1e-6);
    }

    #[test]
    fn fast_log2_is_within_a_ten_thousandth() {
        let mut x = 1e-30f32;
        while x < 1e30 {
            assert!(
                (log2(x) - x.log2()).abs() < 1e-4,
                "{x}: {} vs {}",
                log2(x),
                x.log2()
            );
            x *= 1.37;
        }
        assert!(log2(0.0) == f32::NEG_INFINITY && log2(f32::INFINITY) == f32::INFINITY);
        assert!(log2(f32::NAN).is_nan());
    }

    #[test]
    fn level_of_detail_is_finite_for_any_derivatives() {
        let chain = ramp();
        let coarsest = chain.coarsest_level() as f32;
        for d in [
            0.0,
            1e-30,
            0.25,
            1e30,
            f32::INFINITY,
            f32::NAN,
            -f32::INFINITY,
        ] {
            let lod = Footprint::new(d, d, -d, d).level_of_detail(&chain);
            assert!(
                lod.is_finite() && (0.0..=coarsest).contains(&lod),
                "{d}: {lod}"
            );
        }
    }
}
