//! Fractal sums (fBm) of gradient noise: octave i is `perlin` at 2ⁱ times the frequency and
//! 2⁻ⁱ times the amplitude, and the sum is divided by the amplitudes' total so it stays in
//! about −1..1 whatever the octave count. The gradient is the same sum of the octaves' exact
//! gradients.

use super::perlin::{Graded, perlin2, perlin3};

/// The most octaves summed: the 17th would add under 2⁻¹⁶ of the total, below what an 8-bit
/// height map or a bump can show.
pub const MAX_OCTAVES: f64 = 16.0;

/// fBm at (x, y, z) over `octaves` octaves (whole; a fraction is dropped, more than
/// `MAX_OCTAVES` count as that many); fewer than one, or NaN, is no value (NaN).
pub fn fbm3(point: [f64; 3], octaves: f64) -> Graded<3> {
    fbm(point, octaves, |[x, y, z]| perlin3(x, y, z))
}

/// fBm at (x, y): that at z = 0.
pub fn fbm2(x: f64, y: f64, octaves: f64) -> Graded<2> {
    fbm([x, y], octaves, |[x, y]| perlin2(x, y))
}

fn fbm<const D: usize>(
    point: [f64; D],
    octaves: f64,
    noise: impl Fn([f64; D]) -> Graded<D>,
) -> Graded<D> {
    // NaN too: `min` below would take MAX_OCTAVES over it.
    if octaves.is_nan() || octaves < 1.0 {
        return Graded {
            value: f64::NAN,
            gradient: [f64::NAN; D],
        };
    }
    let count = octaves.floor().min(MAX_OCTAVES);
    let mut sum = Graded {
        value: 0.0,
        gradient: [0.0; D],
    };
    let (mut frequency, mut amplitude, mut total) = (1.0, 1.0, 0.0);
    for _ in 0..count as u32 {
        let octave = noise(point.map(|p| p * frequency));
        sum.value += amplitude * octave.value;
        for (g, o) in sum.gradient.iter_mut().zip(octave.gradient) {
            *g += amplitude * frequency * o;
        }
        total += amplitude;
        frequency *= 2.0;
        amplitude *= 0.5;
    }
    Graded {
        value: sum.value / total,
        gradient: sum.gradient.map(|g| g / total),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points() -> impl Iterator<Item = [f64; 3]> {
        (0..500).map(|i| {
            let i = i as f64;
            [i * 0.0917 - 20.0, 13.0 - i * 0.0531, i * 0.013]
        })
    }

    #[test]
    fn octaves_sum_perlin_noise_at_doubling_frequencies() {
        for p in points() {
            assert_eq!(fbm3(p, 1.0), perlin3(p[0], p[1], p[2]));
            let sum: f64 = (0..4)
                .map(|i| {
                    let f = f64::from(1 << i);
                    perlin3(f * p[0], f * p[1], f * p[2]).value / f
                })
                .sum();
            let value = fbm3(p, 4.0).value;
            assert!(
                (value - sum / 1.875).abs() < 1e-15,
                "{value} vs {}",
                sum / 1.875
            );
            assert!(value.abs() <= 1.1);
        }
    }

    #[test]
    fn octave_counts_are_whole_and_bounded() {
        let p = [1.3, -2.7, 0.4];
        assert_eq!(fbm3(p, 2.9), fbm3(p, 2.0));
        assert_eq!(fbm3(p, 1e9), fbm3(p, MAX_OCTAVES));
        assert_ne!(fbm3(p, MAX_OCTAVES - 1.0), fbm3(p, MAX_OCTAVES));
        for none in [0.99, 0.0, -3.0, f64::NAN, f64::NEG_INFINITY] {
            assert!(fbm3(p, none).value.is_nan(), "{none}");
        }
        assert_eq!(fbm3(p, f64::INFINITY), fbm3(p, MAX_OCTAVES));
        let flat = fbm2(p[0], p[1], 5.0);
        assert_eq!(flat.value, fbm3([p[0], p[1], 0.0], 5.0).value);
    }

    #[test]
    fn gradients_match_central_differences() {
        let h = 1e-7;
        for point in points() {
            let exact = fbm3(point, 6.0).gradient;
            for axis in 0..3 {
                let at = |d: f64| {
                    let mut p = point;
                    p[axis] += d;
                    fbm3(p, 6.0).value
                };
                let difference = (at(h) - at(-h)) / (2.0 * h);
                assert!(
                    (exact[axis] - difference).abs() < 1e-5,
                    "axis {axis} at {point:?}: {} vs {difference}",
                    exact[axis]
                );
            }
        }
    }
}
