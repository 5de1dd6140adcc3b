//! An image as a bump map: its brightness is a height field, lighter raised.

use std::path::Path;

use glam::{Mat2, Vec2, Vec3, Vec4};

use super::encoding::Encoding;
use super::error::TextureError;
use super::load::{Limits, load_image};
use super::mip::MipChain;
use super::sampler::Footprint;
use super::texel::Texel;
use super::texel_grid::TexelGrid;
use super::wrap::Wrap;

/// Rec. 709 luma weights, applied to the stored values.
const LUMA: Vec3 = Vec3::new(0.2126, 0.7152, 0.0722);

/// Height and its slope along the texture axes, per unit of s and of t
/// (t grows downwards in the image).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeightSample {
    pub height: f32,
    pub dh_ds: f32,
    pub dh_dt: f32,
}

impl HeightSample {
    /// Blinn's `(B_u, B_v)`: the slope along the surface parameters, given the mapping's
    /// Jacobian ∂(s,t)/∂(u,v) (columns ∂/∂u, ∂/∂v), by the chain rule.
    pub fn surface_gradient(&self, jacobian: Mat2) -> Vec2 {
        let slope = Vec2::new(self.dh_ds, self.dh_dt);
        Vec2::new(slope.dot(jacobian.x_axis), slope.dot(jacobian.y_axis))
    }
}

impl std::ops::Add for HeightSample {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self {
            height: self.height + o.height,
            dh_ds: self.dh_ds + o.dh_ds,
            dh_dt: self.dh_dt + o.dh_dt,
        }
    }
}

impl std::ops::Mul<f32> for HeightSample {
    type Output = Self;
    fn mul(self, k: f32) -> Self {
        Self {
            height: self.height * k,
            dh_ds: self.dh_ds * k,
            dh_dt: self.dh_dt * k,
        }
    }
}

/// A height field in `[0, 1]` (black 0, white 1) with a mip chain.
///
/// Heights are the file's stored values, not sRGB-decoded: a height map is data, and a
/// linear ramp in the file must give a constant slope. Colour images use their luma.
#[derive(Debug, Clone)]
pub struct HeightMap {
    pub(super) chain: MipChain<f32>,
}

impl HeightMap {
    pub fn load(path: impl AsRef<Path>, limits: &Limits) -> Result<Self, TextureError> {
        let image = load_image(path.as_ref(), limits, Encoding::Linear)?;
        Ok(Self::from_texels(&image.texels))
    }

    /// Heights from the luma of linear-encoded texels (transparent areas sink to 0).
    pub fn from_texels(texels: &TexelGrid<Texel>) -> Self {
        Self::from_heights(texels.map(|t| t.truncate().dot(LUMA)))
    }

    pub fn from_heights(heights: TexelGrid<f32>) -> Self {
        Self {
            chain: MipChain::build(heights),
        }
    }

    pub fn width(&self) -> u32 {
        self.chain.base().width()
    }

    /// The memory the heights and their mip chain take.
    pub fn bytes(&self) -> u64 {
        self.chain.bytes()
    }

    pub fn height(&self) -> u32 {
        self.chain.base().height()
    }

    /// Height and gradient at `st` from a Catmull-Rom bicubic reconstruction,
    /// differentiated analytically: the slope is continuous between texels, so
    /// magnified bumps show no texel steps, and a linear ramp gives an exactly constant
    /// slope. Minified, the two mip levels around `footprint`'s level are blended.
    pub fn sample_gradient(
        &self,
        st: Vec2,
        wrap_s: Wrap,
        wrap_t: Wrap,
        footprint: Footprint,
    ) -> HeightSample {
        let lod = footprint.level_of_detail(&self.chain);
        let fine = lod.floor();
        let blend = lod - fine;
        let level = fine as usize;
        let near = bicubic(self.chain.level(level), st, wrap_s, wrap_t);
        if blend == 0.0 {
            return near;
        }
        let far = bicubic(self.chain.level(level + 1), st, wrap_s, wrap_t);
        near * (1.0 - blend) + far * blend
    }
}

/// Catmull-Rom on a 4×4 neighbourhood, with the derivatives of its weights.
fn bicubic(level: &TexelGrid<f32>, st: Vec2, wrap_s: Wrap, wrap_t: Wrap) -> HeightSample {
    let across = first_tap(wrap_s, st.x, level.width());
    let down = first_tap(wrap_t, st.y, level.height());
    neighbourhood(level, across, down, wrap_s, wrap_t)
}

/// `bicubic` from its first taps and fractions along s (`across`) and t (`down`).
#[inline(always)]
pub(super) fn neighbourhood(
    level: &TexelGrid<f32>,
    (x, fx): (i32, f32),
    (y, fy): (i32, f32),
    wrap_s: Wrap,
    wrap_t: Wrap,
) -> HeightSample {
    let row = |j| row_taps(level, wrap_s, x, wrap_t.index(y + j, level.height()));
    let rows = [row(0), row(1), row(2), row(3)];
    weigh_rows(level, rows, fx, fy)
}

/// The Catmull-Rom sample from the 4×4 neighbourhood's `rows`, at fractions `fx` along s and
/// `fy` along t. The rows are weighted into one column sum (and its slope along t) four lanes
/// at a time, then the columns are weighted along s: three dot products instead of sixteen
/// scalar taps.
#[inline(always)]
pub(super) fn weigh_rows(
    level: &TexelGrid<f32>,
    rows: [Vec4; 4],
    fx: f32,
    fy: f32,
) -> HeightSample {
    let (wy, dy) = (catmull_rom(fy).to_array(), catmull_rom_slope(fy).to_array());
    let mut column = Vec4::ZERO;
    let mut column_slope = Vec4::ZERO;
    for (row, (w, d)) in rows.into_iter().zip(wy.into_iter().zip(dy)) {
        column += row * w;
        column_slope += row * d;
    }
    let (wx, dx) = (catmull_rom(fx), catmull_rom_slope(fx));
    // Per texel → per unit of texture coordinate.
    HeightSample {
        height: column.dot(wx),
        dh_ds: column.dot(dx) * level.width() as f32,
        dh_dt: column_slope.dot(wx) * level.height() as f32,
    }
}

/// The first of the four taps along an axis of `n` texels (unwrapped: it and the next three
/// go through `wrap`) and the fraction between the second and third.
#[inline(always)]
pub(super) fn first_tap(wrap: Wrap, s: f32, n: u32) -> (i32, f32) {
    let x = wrap.reduce(s) * n as f32 - 0.5;
    let x0 = x.floor();
    (x0 as i32 - 1, x - x0)
}

/// Texels `x .. x + 4` of row `y`, wrapped; away from the edges one unaligned load.
#[inline(always)]
fn row_taps(level: &TexelGrid<f32>, wrap: Wrap, x: i32, y: u32) -> Vec4 {
    let row = level.row(y);
    let n = level.width();
    match usize::try_from(x) {
        Ok(first) if first + 4 <= row.len() => Vec4::from_slice(&row[first..first + 4]),
        _ => Vec4::from_array([0, 1, 2, 3].map(|k| row[wrap.index(x + k, n) as usize])),
    }
}

/// The four Catmull-Rom weights at fraction `f`, 0.5·(−f³ + 2f² − f, 3f³ − 5f² + 2,
/// −3f³ + 4f² + f, f³ − f²), by Horner's rule on all four at once.
#[inline(always)]
fn catmull_rom(f: f32) -> Vec4 {
    const CUBIC: Vec4 = Vec4::new(-0.5, 1.5, -1.5, 0.5);
    const SQUARE: Vec4 = Vec4::new(1.0, -2.5, 2.0, -0.5);
    const LINEAR: Vec4 = Vec4::new(-0.5, 0.0, 0.5, 0.0);
    const CONSTANT: Vec4 = Vec4::new(0.0, 1.0, 0.0, 0.0);
    ((CUBIC * f + SQUARE) * f + LINEAR) * f + CONSTANT
}

/// d/df of `catmull_rom`: 0.5·(−3f² + 4f − 1, 9f² − 10f, −9f² + 8f + 1, 3f² − 2f).
#[inline(always)]
fn catmull_rom_slope(f: f32) -> Vec4 {
    const SQUARE: Vec4 = Vec4::new(-1.5, 4.5, -4.5, 1.5);
    const LINEAR: Vec4 = Vec4::new(2.0, -5.0, 4.0, -1.0);
    const CONSTANT: Vec4 = Vec4::new(-0.5, 0.0, 0.5, 0.0);
    (SQUARE * f + LINEAR) * f + CONSTANT
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_gradient_applies_the_chain_rule() {
        let sample = HeightSample {
            height: 0.0,
            dh_ds: 2.0,
            dh_dt: -1.0,
        };
        // s = 3u + v, t = 5v  =>  B_u = 2·3, B_v = 2·1 − 1·5.
        let jacobian = Mat2::from_cols(Vec2::new(3.0, 0.0), Vec2::new(1.0, 5.0));
        assert_eq!(sample.surface_gradient(jacobian), Vec2::new(6.0, -3.0));
    }

    #[test]
    fn weights_partition_unity_and_slopes_sum_to_zero() {
        for f in [0.0, 0.3, 0.5, 0.99] {
            assert!((catmull_rom(f).element_sum() - 1.0).abs() < 1e-6);
            assert!(catmull_rom_slope(f).element_sum().abs() < 1e-6);
        }
    }

    #[test]
    fn weights_are_the_catmull_rom_polynomials() {
        for k in 0..=100 {
            let f = k as f64 / 100.0;
            let (f2, f3) = (f * f, f * f * f);
            let weights = [
                0.5 * (-f3 + 2.0 * f2 - f),
                0.5 * (3.0 * f3 - 5.0 * f2 + 2.0),
                0.5 * (-3.0 * f3 + 4.0 * f2 + f),
                0.5 * (f3 - f2),
            ];
            let slopes = [
                0.5 * (-3.0 * f2 + 4.0 * f - 1.0),
                0.5 * (9.0 * f2 - 10.0 * f),
                0.5 * (-9.0 * f2 + 8.0 * f + 1.0),
                0.5 * (3.0 * f2 - 2.0 * f),
            ];
            let (w, d) = (catmull_rom(f as f32), catmull_rom_slope(f as f32));
            for i in 0..4 {
                assert!((f64::from(w[i]) - weights[i]).abs() < 1e-6, "w{i}({f})");
                assert!((f64::from(d[i]) - slopes[i]).abs() < 1e-6, "d{i}({f})");
            }
        }
    }

    /// The sixteen taps one at a time, as the weights define the reconstruction.
    fn bicubic_by_taps(
        level: &TexelGrid<f32>,
        st: Vec2,
        wrap_s: Wrap,
        wrap_t: Wrap,
    ) -> HeightSample {
        let (x, fx) = first_tap(wrap_s, st.x, level.width());
        let (y, fy) = first_tap(wrap_t, st.y, level.height());
        let (wx, dx) = (catmull_rom(fx), catmull_rom_slope(fx));
        let (wy, dy) = (catmull_rom(fy), catmull_rom_slope(fy));
        let mut out = HeightSample::default();
        for j in 0..4 {
            for i in 0..4 {
                let tx = wrap_s.index(x + i as i32, level.width());
                let ty = wrap_t.index(y + j as i32, level.height());
                let h = f64::from(level.at(tx, ty));
                out.height += (f64::from(wx[i] * wy[j]) * h) as f32;
                out.dh_ds += (f64::from(dx[i] * wy[j]) * h) as f32;
                out.dh_dt += (f64::from(wx[i] * dy[j]) * h) as f32;
            }
        }
        out.dh_ds *= level.width() as f32;
        out.dh_dt *= level.height() as f32;
        out
    }

    #[test]
    fn vectorised_taps_agree_with_tap_by_tap_sums_across_every_edge() {
        let level = TexelGrid::from_fn(7, 5, |x, y| ((x * 13 + y * 29) % 11) as f32 / 10.0);
        let wraps = [Wrap::Repeat, Wrap::Clamp, Wrap::Mirror];
        let mut checked = 0;
        for k in 0..4000 {
            // Coordinates over several periods, both signs, edges included.
            let st = Vec2::new(k as f32 * 0.00137 - 2.3, 3.1 - k as f32 * 0.00211);
            for (wrap_s, wrap_t) in wraps.into_iter().flat_map(|a| wraps.map(|b| (a, b))) {
                let (fast, taps) = (
                    bicubic(&level, st, wrap_s, wrap_t),
                    bicubic_by_taps(&level, st, wrap_s, wrap_t),
                );
                let close = |a: f32, b: f32| (a - b).abs() <= 2e-5 * b.abs().max(1.0);
                assert!(
                    close(fast.height, taps.height)
                        && close(fast.dh_ds, taps.dh_ds)
                        && close(fast.dh_dt, taps.dh_dt),
                    "{st} {wrap_s:?} {wrap_t:?}: {fast:?} against {taps:?}"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 4000 * 9);
    }

    #[test]
    fn slope_matches_finite_differences_of_height() {
        let map = HeightMap::from_heights(TexelGrid::from_fn(8, 8, |x, y| {
            ((x * 7 + y * 3) % 5) as f32 / 4.0
        }));
        let (s, t, e) = (0.41, 0.57, 1e-3);
        let at = |s: f32, t: f32| {
            map.sample_gradient(
                Vec2::new(s, t),
                Wrap::Repeat,
                Wrap::Repeat,
                Footprint::POINT,
            )
        };
        let g = at(s, t);
        let ds = (at(s + e, t).height - at(s - e, t).height) / (2.0 * e);
        let dt = (at(s, t + e).height - at(s, t - e).height) / (2.0 * e);
        assert!(
            (g.dh_ds - ds).abs() < 0.05 * ds.abs().max(1.0),
            "{g:?} {ds}"
        );
        assert!(
            (g.dh_dt - dt).abs() < 0.05 * dt.abs().max(1.0),
            "{g:?} {dt}"
        );
    }
}
