//! How stored sample values relate to light: sRGB-encoded colour or plain data.

/// How to interpret an image's stored values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Encoding {
    /// Colour pictures: sRGB-decoded to linear light so shading and filtering add light correctly.
    #[default]
    Srgb,
    /// Data such as height maps: the stored value is used as is (0 = black, 1 = white),
    /// so a linear ramp in the file stays a linear ramp of heights.
    Linear,
}

impl Encoding {
    /// Decodes one colour channel value in `[0, 1]`.
    pub fn decode(self, value: f32) -> f32 {
        match self {
            Encoding::Srgb => srgb_to_linear(value),
            Encoding::Linear => value,
        }
    }

    /// The decoded value of every 8-bit code, so 8-bit images avoid a `powf` per channel.
    pub fn table_u8(self) -> [f32; 256] {
        std::array::from_fn(|code| self.decode(code as f32 / 255.0))
    }
}

/// The IEC 61966-2-1 sRGB transfer function, inverted.
pub fn srgb_to_linear(encoded: f32) -> f32 {
    if encoded <= 0.04045 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// The sRGB transfer function, for tests and for callers writing images back out.
pub fn linear_to_srgb(linear: f32) -> f32 {
    if linear <= 0.003_130_8 {
        linear * 12.92
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_round_trips_and_hits_known_points() {
        assert_eq!(srgb_to_linear(0.0), 0.0);
        assert!((srgb_to_linear(1.0) - 1.0).abs() < 1e-6);
        assert!((srgb_to_linear(0.5) - 0.214_041).abs() < 1e-5);
        for code in 0..=255 {
            let v = code as f32 / 255.0;
            assert!((linear_to_srgb(srgb_to_linear(v)) - v).abs() < 1e-5);
        }
    }
}
