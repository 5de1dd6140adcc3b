use glam::Vec3;
use std::sync::OnceLock;

/// The rendered image: linear-light RGB (f32: shading sums many small terms, and exports
/// average samples before the one conversion to sRGB) and the view depth per pixel.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    pub width: u32,
    pub height: u32,
    pub color: Vec<Vec3>,
    /// Distance along the view direction of the visible surface, +∞ for background.
    pub depth: Vec<f32>,
}

impl Framebuffer {
    pub fn new(width: u32, height: u32, background: Vec3) -> Framebuffer {
        let n = width as usize * height as usize;
        Framebuffer {
            width,
            height,
            color: vec![background; n],
            depth: vec![f32::INFINITY; n],
        }
    }

    /// Makes the framebuffer `width` × `height`, keeping its allocation when it is large enough.
    /// The contents are unspecified until the next render writes every pixel.
    pub fn resize(&mut self, width: u32, height: u32) {
        let n = width as usize * height as usize;
        self.width = width;
        self.height = height;
        self.color.resize(n, Vec3::ZERO);
        self.depth.resize(n, f32::INFINITY);
    }

    /// 8-bit sRGB, row-major, top row first.
    pub fn to_srgb8(&self) -> Vec<[u8; 3]> {
        self.color
            .iter()
            .map(|c| c.to_array().map(linear_to_srgb8))
            .collect()
    }
}

/// The sRGB transfer function, exact to within rounding: a 65536-entry table over [0, 1] (the
/// table's step is 1/20 of an 8-bit step at the steepest part of the curve). NaN maps to 0.
#[inline]
pub fn linear_to_srgb8(linear: f32) -> u8 {
    static TABLE: OnceLock<Box<[u8]>> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        (0..=u16::MAX)
            .map(|i| srgb_encode(i as f64 / 65535.0))
            .collect()
    });
    let index = (linear.clamp(0.0, 1.0) * 65535.0 + 0.5) as usize; // NaN clamps to NaN, casts to 0
    table[index]
}

fn srgb_encode(linear: f64) -> u8 {
    let s = if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round().clamp(0.0, 255.0) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_table_matches_the_exact_curve() {
        for i in 0..=10_000 {
            let x = i as f32 / 10_000.0;
            let exact = srgb_encode(x as f64) as i32;
            assert!((linear_to_srgb8(x) as i32 - exact).abs() <= 1, "at {x}");
        }
        assert_eq!(linear_to_srgb8(f32::NAN), 0);
        assert_eq!(linear_to_srgb8(-1.0), 0);
        assert_eq!(linear_to_srgb8(f32::INFINITY), 255);
        assert_eq!(linear_to_srgb8(0.5), 188);
    }
}
