//! Progressive refinement of the terminal picture: the first frame after a change comes at the
//! interactive cost, then, while nothing changes, further passes sampled at other points of each
//! pixel accumulate, so the cells converge to the average over their area.

use glam::{Vec2, Vec3};

/// Passes after which the picture is left as it is (the stills' `exact` sample count).
pub const MAX_PASSES: u32 = 64;

/// The running sum of the passes at the picture's resolution (its sub-pixels), in linear light.
#[derive(Default)]
pub struct Accumulation {
    sum: Vec<Vec3>,
    size: (usize, usize),
    passes: u32,
}

impl Accumulation {
    /// Starts again from `first`, a pass at the pixel centres of a `size` picture.
    pub fn restart(&mut self, first: Vec<Vec3>, size: (usize, usize)) {
        debug_assert_eq!(first.len(), size.0 * size.1);
        self.sum = first;
        self.size = size;
        self.passes = 1;
    }

    /// Adds a pass of the same size, taken at `next_offset`.
    pub fn add(&mut self, pass: &[Vec3]) {
        debug_assert_eq!(pass.len(), self.sum.len());
        self.sum.iter_mut().zip(pass).for_each(|(s, &p)| *s += p);
        self.passes += 1;
    }

    pub fn passes(&self) -> u32 {
        self.passes
    }

    pub fn size(&self) -> (usize, usize) {
        self.size
    }

    /// Whether another pass would still be taken.
    pub fn wants_more(&self) -> bool {
        (1..MAX_PASSES).contains(&self.passes)
    }

    /// Where in each rendered pixel the next pass samples, in pixels from its centre.
    pub fn next_offset(&self) -> Vec2 {
        sample_offset(self.passes)
    }

    /// The texture footprint of the next pass, in rendered pixels (see `pass_footprint`).
    pub fn next_footprint(&self) -> f32 {
        pass_footprint(self.passes)
    }

    /// The mean of the passes so far.
    pub fn mean(&self) -> Vec<Vec3> {
        let scale = 1.0 / self.passes.max(1) as f32;
        self.sum.iter().map(|&s| s * scale).collect()
    }
}

/// The spacing, in rendered pixels, that pass `index`'s texture lookups filter over: the whole
/// pixel for the first pass, which stands alone, and the spacing of the settled picture's samples
/// for the passes averaged with it (as a still's passes do), so textures settle as sharp as a
/// still's and not blurred by the first pass's wide filter.
pub fn pass_footprint(index: u32) -> f32 {
    if index == 0 {
        1.0
    } else {
        1.0 / (MAX_PASSES as f32).sqrt()
    }
}

/// Pass `index`'s sample point in the pixel, within ±½: the centre first, then the R2
/// low-discrepancy sequence (Roberts 2018), so that every prefix of the passes covers the pixel
/// evenly and the running mean settles without a visible pattern.
pub fn sample_offset(index: u32) -> Vec2 {
    if index == 0 {
        return Vec2::ZERO;
    }
    // 1/φ₂ and 1/φ₂², φ₂ the plastic number: f64 keeps the sequence exact for any index used.
    const A1: f64 = 0.754_877_666_246_692_7;
    const A2: f64 = 0.569_840_290_998_053_3;
    let n = f64::from(index);
    let x = (0.5 + A1 * n).fract() - 0.5;
    let y = (0.5 + A2 * n).fract() - 0.5;
    Vec2::new(x as f32, y as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_stay_in_the_pixel_and_cover_it_evenly() {
        let offsets: Vec<Vec2> = (0..MAX_PASSES).map(sample_offset).collect();
        assert_eq!(offsets[0], Vec2::ZERO);
        assert!(offsets.iter().all(|o| o.abs().max_element() <= 0.5));
        // Each quarter of the pixel gets its share of the samples, within a few.
        for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
            let inside = offsets
                .iter()
                .filter(|o| o.x * sx > 0.0 && o.y * sy > 0.0)
                .count();
            assert!(
                (12..=20).contains(&inside),
                "quarter ({sx}, {sy}): {inside}"
            );
        }
        let mean = offsets.iter().sum::<Vec2>() / offsets.len() as f32;
        // No drift: the settled picture is centred on its pixels to within a 25th of a pixel.
        assert!(mean.length() < 0.04, "{mean}");
    }

    #[test]
    fn the_mean_is_the_average_of_the_passes_and_stops_at_the_maximum() {
        let mut accumulation = Accumulation::default();
        assert!(
            !accumulation.wants_more(),
            "nothing to refine before a first pass"
        );
        accumulation.restart(vec![Vec3::ONE; 2], (2, 1));
        accumulation.add(&[Vec3::ZERO, Vec3::splat(3.0)]);
        assert_eq!(
            accumulation.mean(),
            vec![Vec3::splat(0.5), Vec3::splat(2.0)]
        );
        while accumulation.wants_more() {
            accumulation.add(&[Vec3::ZERO; 2]);
        }
        assert_eq!(accumulation.passes(), MAX_PASSES);
    }
}
