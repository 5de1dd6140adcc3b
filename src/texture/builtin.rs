//! The shipped images (CC0, see textures/README.md), embedded so built-in scenes work from any
//! directory. A scene names them without a path or extension: `image = "brick"`.

use super::{Encoding, HeightMap, Limits, LoadedImage, Texture, TextureError, decode_image};
use std::path::Path;

pub const BUILTIN_IMAGES: &[(&str, &[u8])] = &[
    ("brick", include_bytes!("../../textures/brick.png")),
    ("chelsea", include_bytes!("../../textures/chelsea.png")),
    ("coffee", include_bytes!("../../textures/coffee.png")),
    ("gravel", include_bytes!("../../textures/gravel.png")),
];

fn builtin_bytes(name: &str) -> Option<&'static [u8]> {
    BUILTIN_IMAGES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, bytes)| *bytes)
}

/// The texels of a built-in image, decoded with `encoding`; `None` if no image has that name.
fn decode_builtin(name: &str, encoding: Encoding) -> Option<Result<LoadedImage, TextureError>> {
    let bytes = builtin_bytes(name)?;
    Some(decode_image(
        bytes,
        Path::new(name),
        &Limits::default(),
        encoding,
    ))
}

/// A colour texture: a built-in name, or a file path.
pub fn load_texture(name_or_path: &str, base: &Path) -> Result<Texture, TextureError> {
    match decode_builtin(name_or_path, Encoding::Srgb) {
        Some(image) => Ok(Texture::from_raster(image?.texels)),
        None => Texture::load(base.join(name_or_path), &Limits::default()),
    }
}

/// A height map (grey values as stored, not sRGB-decoded): a built-in name, or a file path.
pub fn load_height_map(name_or_path: &str, base: &Path) -> Result<HeightMap, TextureError> {
    match decode_builtin(name_or_path, Encoding::Linear) {
        Some(image) => Ok(HeightMap::from_texels(&image?.texels)),
        None => HeightMap::load(base.join(name_or_path), &Limits::default()),
    }
}
