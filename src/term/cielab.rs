//! CIELAB, the yardstick the terminal pictures are judged by: distances there (ΔE) and hue angles
//! stand for how different two colours look. f64, as a measure is read to two decimals.

/// CIELAB (L*, a*, b*) of an 8-bit sRGB colour, D65 white.
pub fn cielab(rgb: [u8; 3]) -> [f64; 3] {
    let [r, g, b] = rgb.map(linear);
    let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    let f = |t: f64| {
        if t > 216.0 / 24389.0 {
            t.cbrt()
        } else {
            (24389.0 / 27.0 * t + 16.0) / 116.0
        }
    };
    let (fx, fy, fz) = (f(x), f(y), f(z));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// The linear-light value of an 8-bit sRGB channel (IEC 61966-2-1).
fn linear(v: u8) -> f64 {
    let c = f64::from(v) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The CIE76 colour difference ΔE*ab between two sRGB colours.
pub fn delta_e(p: [u8; 3], q: [u8; 3]) -> f64 {
    let (p, q) = (cielab(p), cielab(q));
    (0..3).map(|i| (p[i] - q[i]).powi(2)).sum::<f64>().sqrt()
}

/// Chroma C*ab and hue angle h (degrees, 0..360) of an sRGB colour.
pub fn chroma_and_hue(rgb: [u8; 3]) -> (f64, f64) {
    let [_, a, b] = cielab(rgb);
    (a.hypot(b), b.atan2(a).to_degrees().rem_euclid(360.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn white_and_black_are_the_ends_of_lightness_without_colour() {
        let white = cielab([255; 3]);
        assert!(
            white
                .iter()
                .zip([100.0, 0.0, 0.0])
                .all(|(v, want)| (v - want).abs() < 0.05)
        );
        assert!(cielab([0; 3]).iter().all(|v| v.abs() < 1e-9));
    }

    #[test]
    fn primaries_have_their_published_hues() {
        // sRGB red is at h ≈ 40°, green ≈ 136°, blue ≈ 306° (CIELAB, D65).
        for (rgb, hue) in [
            ([255, 0, 0], 40.0),
            ([0, 255, 0], 136.0),
            ([0, 0, 255], 306.3),
        ] {
            let (chroma, h) = chroma_and_hue(rgb);
            assert!(chroma > 100.0 && (h - hue).abs() < 1.0, "{rgb:?}: {h}");
        }
    }
}
