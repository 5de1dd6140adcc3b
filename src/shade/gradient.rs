//! How the bump gradient (Bu, Bv) is obtained: the trade between the exact derivative and
//! cheaper or older ways of estimating it.

use crate::raster::Fragment;
use glam::Vec2;

/// Where (Bu, Bv) comes from. Slope patterns (`slope = (BU, BV)`) give the gradient directly and
/// have no height to difference, so every method uses their slope as written.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case", deny_unknown_fields)]
pub enum GradientMethod {
    /// The exact derivative: automatic differentiation of height patterns, the differentiated
    /// bicubic reconstruction of height images.
    #[default]
    Exact,
    /// (B(u+h, v) − B(u−h, v)) / 2h and likewise along v, with `step` h in (u,v) units: four
    /// height evaluations, each with the surface frame at its own (u,v).
    CentralDifference { step: f32 },
    /// The seed lecture's slope form: its dimples code truncates (u,v) to integers (`(int)uu`)
    /// before computing the slope, so the gradient is constant over each unit cell of (u,v).
    /// Here: the exact gradient taken at ⌊u⌋, ⌊v⌋.
    SeedLattice,
}

impl GradientMethod {
    pub fn name(self) -> String {
        match self {
            GradientMethod::Exact => "exact".into(),
            GradientMethod::CentralDifference { step } => format!("central(h={step})"),
            GradientMethod::SeedLattice => "seed-lattice".into(),
        }
    }
}

/// Copies of a group's fragments moved in (u,v): the inputs of one shifted height evaluation.
/// The screen derivatives stay, so a filtered image keeps its mip level.
pub fn shifted_fragments(
    fragments: &[Fragment],
    group: &[u32],
    shift: impl Fn(Vec2) -> Vec2,
    out: &mut Vec<Fragment>,
) {
    out.clear();
    out.extend(group.iter().map(|&i| {
        let fragment = fragments[i as usize];
        Fragment {
            uv: shift(fragment.uv),
            ..fragment
        }
    }));
}

/// The central-difference gradient from the four shifted heights, in the order +u, −u, +v, −v.
#[inline]
pub fn central_difference(heights: [f32; 4], step: f32) -> Vec2 {
    Vec2::new(heights[0] - heights[1], heights[2] - heights[3]) / (2.0 * step)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn central_difference_is_exact_for_a_linear_height() {
        // B = 3u − 2v + 7 around (10, 20) with h = 0.5.
        let b = |u: f32, v: f32| 3.0 * u - 2.0 * v + 7.0;
        let h = 0.5;
        let heights = [b(10.5, 20.0), b(9.5, 20.0), b(10.0, 20.5), b(10.0, 19.5)];
        let g = central_difference(heights, h);
        assert!((g - Vec2::new(3.0, -2.0)).length() < 1e-5, "{g:?}");
    }

    #[test]
    fn shifting_moves_only_uv() {
        let fragments = [Fragment {
            uv: Vec2::new(1.5, 2.5),
            duv_dx: Vec2::X,
            x: 3,
            ..Fragment::default()
        }];
        let mut out = Vec::new();
        shifted_fragments(&fragments, &[0], |uv| uv.floor(), &mut out);
        assert_eq!(out[0].uv, Vec2::new(1.0, 2.0));
        assert_eq!((out[0].duv_dx, out[0].x), (Vec2::X, 3));
    }
}
