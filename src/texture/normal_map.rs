//! A tangent-space normal map: an RGB image whose texels are unit normals, each channel mapped
//! from −1..1 to 0..1 (read as stored, not sRGB-decoded). Red points along +s, green along −t
//! (up the image) in the OpenGL convention Blender and Godot bake, along +t in DirectX's; blue
//! out of the surface. Sampled bilinearly, so a map baked at the picture's resolution or finer
//! shades as its source did.

use super::{LoadedImage, TexelGrid, Wrap};
use glam::{Vec2, Vec3};

/// Which way a normal map's green channel points.
#[derive(
    Clone,
    Copy,
    Debug,
    Default,
    PartialEq,
    Eq,
    serde::Serialize,
    serde::Deserialize,
    clap::ValueEnum,
    strum::IntoStaticStr,
)]
#[serde(rename_all = "kebab-case")]
#[strum(serialize_all = "lowercase")]
pub enum NormalConvention {
    /// Green up the image (+Y): Blender, Godot, glTF.
    #[default]
    Opengl,
    /// Green down the image (−Y): Unity's import of DirectX maps, Unreal, 3ds Max.
    Directx,
}

impl NormalConvention {
    /// The green channel's value for a normal whose component up the image is `up`.
    pub fn green(self, up: f32) -> f32 {
        match self {
            NormalConvention::Opengl => up,
            NormalConvention::Directx => -up,
        }
    }

    pub fn name(self) -> &'static str {
        self.into()
    }
}

/// The decoded vectors of a normal map, as stored (green as the file has it).
#[derive(Debug)]
pub struct NormalMap {
    normals: TexelGrid<Vec3>,
}

impl NormalMap {
    /// From a linear-decoded image.
    pub fn from_image(image: LoadedImage) -> NormalMap {
        let normals = image.texels.map(|texel| texel.truncate() * 2.0 - Vec3::ONE);
        NormalMap { normals }
    }

    /// The memory the map takes.
    pub fn bytes(&self) -> u64 {
        self.normals.texels().len() as u64 * std::mem::size_of::<Vec3>() as u64
    }

    /// The unit normal at `st` (t down the image, as every image here), bilinear between the
    /// four nearest texels, in the frame (+s, up the image, out) for a map made in `convention`.
    pub fn sample(
        &self,
        st: Vec2,
        (wrap_s, wrap_t): (Wrap, Wrap),
        convention: NormalConvention,
    ) -> Vec3 {
        let (width, height) = (self.normals.width(), self.normals.height());
        let x = st.x * width as f32 - 0.5;
        let y = st.y * height as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let at = |i: f32, j: f32| {
            let column = wrap_s.index(i as i32, width);
            let row = wrap_t.index(j as i32, height);
            self.normals.at(column, row)
        };
        let top = at(x0, y0) * (1.0 - fx) + at(x0 + 1.0, y0) * fx;
        let bottom = at(x0, y0 + 1.0) * (1.0 - fx) + at(x0 + 1.0, y0 + 1.0) * fx;
        let stored = top * (1.0 - fy) + bottom * fy;
        let n = Vec3::new(stored.x, convention.green(stored.y), stored.z).normalize_or(Vec3::Z);
        if n.is_finite() { n } else { Vec3::Z }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{Encoding, decode_image};

    fn map_of(rgb: [u8; 3]) -> NormalMap {
        let mut png = Vec::new();
        let mut encoder = png::Encoder::new(&mut png, 1, 1);
        encoder.set_color(png::ColorType::Rgb);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&rgb).unwrap();
        writer.finish().unwrap();
        let limits = crate::texture::Limits::default();
        let image = decode_image(
            &png,
            std::path::Path::new("n.png"),
            &limits,
            Encoding::Linear,
        );
        NormalMap::from_image(image.unwrap())
    }

    #[test]
    fn the_flat_colour_is_straight_out_and_green_follows_the_convention() {
        let wraps = (Wrap::Repeat, Wrap::Repeat);
        let flat =
            map_of([128, 128, 255]).sample(Vec2::splat(0.5), wraps, NormalConvention::Opengl);
        assert!((flat - Vec3::Z).length() < 0.01, "{flat}");
        let up = map_of([128, 218, 218]);
        let gl = up.sample(Vec2::ZERO, wraps, NormalConvention::Opengl);
        let dx = up.sample(Vec2::ZERO, wraps, NormalConvention::Directx);
        assert!(gl.y > 0.6 && dx.y < -0.6, "{gl} {dx}");
        assert!((gl.x - dx.x).abs() < 1e-6 && (gl.z - dx.z).abs() < 1e-6);
    }
}
