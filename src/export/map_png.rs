//! Texture maps as PNG files other programs read: 16-bit grey heights, 8-bit linear RGB (normal
//! maps: data, so no sRGB chunk tells a reader to decode them) and 8-bit sRGB colours, each
//! written atomically with its text chunks.

use super::output_file::OutputFile;
use crate::Error;
use std::path::Path;

/// The text keyword of a baked map's recipe (TOML).
pub const BAKE_RECIPE: &str = "bumpwork-bake";
/// The text keyword of a height map's range, `LO..HI`: black is LO, white HI.
pub const HEIGHT_RANGE: &str = "bumpwork-height-range";
/// The text keyword of a normal map's convention, `opengl` or `directx`.
pub const NORMAL_CONVENTION: &str = "bumpwork-normal-convention";

/// A map's texels, row by row from the top.
pub enum MapPng<'a> {
    Grey16(&'a [u16]),
    LinearRgb8(&'a [u8]),
    SrgbRgb8(&'a [u8]),
}

/// Heights as 16-bit levels over their finite range (black its lowest, white its highest), and
/// that range; a flat or non-finite map is all black over 0..0.
pub fn height_levels(heights: &[f32]) -> (Vec<u16>, (f32, f32)) {
    let (lo, hi) = heights
        .iter()
        .filter(|h| h.is_finite())
        .fold((f32::MAX, f32::MIN), |(a, b), &h| (a.min(h), b.max(h)));
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };
    let range = hi - lo;
    let levels = heights
        .iter()
        .map(|&h| match range > 0.0 && h.is_finite() {
            true => (((h - lo) / range).clamp(0.0, 1.0) * 65535.0).round() as u16,
            false => 0,
        })
        .collect();
    (levels, (lo, hi))
}

/// Writes `map` of `size` to `path` with `texts` (keyword, text) as iTXt chunks.
pub fn write_map_png(
    path: &Path,
    (width, height): (u32, u32),
    map: MapPng,
    texts: &[(&str, String)],
) -> Result<(), Error> {
    let (file, handle) = OutputFile::create(path)?;
    let fail = |e: png::EncodingError| Error::write(path, e);
    let mut encoder = png::Encoder::new(handle, width, height);
    encoder.set_compression(png::Compression::Fast);
    let bytes = match map {
        MapPng::Grey16(levels) => {
            encoder.set_color(png::ColorType::Grayscale);
            encoder.set_depth(png::BitDepth::Sixteen);
            levels.iter().flat_map(|l| l.to_be_bytes()).collect()
        }
        MapPng::LinearRgb8(rgb) => {
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            rgb.to_vec()
        }
        MapPng::SrgbRgb8(rgb) => {
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
            rgb.to_vec()
        }
    };
    let software = (super::metadata::SOFTWARE, crate::PROGRAM.to_string());
    for (keyword, text) in texts.iter().chain([&software]) {
        encoder
            .add_itxt_chunk(keyword.to_string(), text.clone())
            .map_err(fail)?;
    }
    let mut writer = encoder.write_header().map_err(fail)?;
    writer.write_image_data(&bytes).map_err(fail)?;
    writer.finish().map_err(fail)?;
    file.commit()
}
