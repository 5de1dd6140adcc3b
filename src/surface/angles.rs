//! Sines, cosines and arctangents in f32 without library calls, so batches of them vectorise.

/// (sin x, cos x) in f32 without the two library calls `f32::sin_cos` makes: x is reduced by
/// multiples of π/2 (π/2 split in three parts, so the reduction is exact for the angles frames
/// see, |x| < 2^15) and both come from the Cephes minimax polynomials on [−π/4, π/4]. Within
/// 2.5e-7 of the exact values (about 2 ulp at 1): the frame stays exact to f32 rounding, at a
/// third of the instructions (the sphere's frame was two `sinf` and two `cosf` per fragment).
#[inline(always)]
pub fn sin_cos(x: f32) -> (f32, f32) {
    const PIO2_1: f32 = 1.570_312_5;
    const PIO2_2: f32 = 4.837_513e-4;
    const PIO2_3: f32 = 7.549_79e-8;
    // Round q to the nearest whole number by adding and taking away 1.5·2^23, and read it as an
    // integer from the sum's low mantissa bits (exact for |q| < 2^22): no `roundf` call on
    // baseline x86-64 and no saturating f32 → i32 cast, so batches of angles vectorise.
    const SHIFT: f32 = 12_582_912.0; // 1.5·2^23
    let shifted = x * std::f32::consts::FRAC_2_PI + SHIFT;
    let j = shifted.to_bits() as i32 - SHIFT.to_bits() as i32;
    let jf = shifted - SHIFT;
    let r = ((x - jf * PIO2_1) - jf * PIO2_2) - jf * PIO2_3;
    let r2 = r * r;
    let sin_r = r + r * r2 * (-1.666_665_5e-1 + r2 * (8.332_161e-3 + r2 * -1.951_529_6e-4));
    let cos_r =
        1.0 - 0.5 * r2 + r2 * r2 * (4.166_664_6e-2 + r2 * (-1.388_731_6e-3 + r2 * 2.443_315_7e-5));
    let (s, c) = if j & 1 == 0 {
        (sin_r, cos_r)
    } else {
        (cos_r, sin_r)
    };
    let s = if j & 2 == 0 { s } else { -s };
    let c = if j.wrapping_add(1) & 2 == 0 { c } else { -c };
    (s, c)
}

/// atan2(y, x) in f32, in (−π, π], without the library call: |y|/|x| or its inverse is reduced
/// to [0, tan π/8] (with an offset of π/4 past it) and the Cephes `atanf` minimax polynomial
/// does the rest. Within 3e-7 rad of the exact angle (about an ulp of π; checked over the whole
/// circle below);
/// branch-free selects, so batches vectorise. atan2(0, 0) is 0.
#[inline(always)]
pub fn atan2(y: f32, x: f32) -> f32 {
    use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
    const TAN_PI_8: f32 = 0.414_213_57;
    let (ax, ay) = (x.abs(), y.abs());
    let (small, large) = (ax.min(ay), ax.max(ay));
    let ratio = small / large.max(f32::MIN_POSITIVE);
    let past = ratio > TAN_PI_8;
    let reduced = if past {
        (ratio - 1.0) / (ratio + 1.0)
    } else {
        ratio
    };
    let z = reduced * reduced;
    let poly = (((8.053_744_5e-2 * z - 1.387_768_6e-1) * z + 1.997_771_1e-1) * z - 3.333_295e-1)
        * z
        * reduced
        + reduced;
    let first_octant = if past { poly + FRAC_PI_4 } else { poly };
    let first_quadrant = if ay > ax {
        FRAC_PI_2 - first_octant
    } else {
        first_octant
    };
    let half = if x < 0.0 {
        PI - first_quadrant
    } else {
        first_quadrant
    };
    half.copysign(y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atan2_is_within_3e_7_of_the_library_everywhere() {
        let mut worst = 0.0f64;
        for i in 0..100_000 {
            let angle = (i as f64 / 100_000.0 - 0.5) * std::f64::consts::TAU * 0.999_999;
            for scale in [1e-20, 1e-3, 1.0, 7.5, 1e6] {
                let (y, x) = ((angle.sin() * scale) as f32, (angle.cos() * scale) as f32);
                let exact = (y as f64).atan2(x as f64);
                worst = worst.max((atan2(y, x) as f64 - exact).abs());
            }
        }
        assert!(worst < 3e-7, "{worst}");
        assert_eq!(atan2(0.0, 0.0), 0.0);
        assert_eq!(atan2(0.0, -1.0), std::f32::consts::PI);
        assert!((atan2(-1.0, 0.0) + std::f32::consts::FRAC_PI_2).abs() < 1e-7);
    }

    #[test]
    fn sin_cos_is_within_a_few_ulp() {
        let mut worst = 0.0f64;
        for i in -200_000..=200_000 {
            let x = i as f32 * 1.7e-4 + 0.013 * (i % 7) as f32;
            let (s, c) = sin_cos(x);
            let exact = (x as f64).sin_cos();
            worst = worst
                .max((s as f64 - exact.0).abs())
                .max((c as f64 - exact.1).abs());
        }
        assert!(worst < 2.5e-7, "worst error {worst:e}");
        for x in [
            0.0f32,
            std::f32::consts::FRAC_PI_2,
            std::f32::consts::PI,
            -3.0 * std::f32::consts::FRAC_PI_2,
        ] {
            let (s, c) = sin_cos(x);
            assert!(
                (s as f64 - (x as f64).sin()).abs() < 2.5e-7
                    && (c as f64 - (x as f64).cos()).abs() < 2.5e-7,
                "{x}"
            );
        }
        assert!(sin_cos(f32::NAN).0.is_nan());
    }
}
