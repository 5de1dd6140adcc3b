//! Reading image files into linear texels, with size limits checked from the header
//! before anything large is allocated.

use std::io::{self, Cursor};
use std::panic::{self, AssertUnwindSafe};
use std::path::Path;

use crate::bounded_read::{ReadFailure, read_bounded};

use glam::{Vec3, Vec4};
use image::{DynamicImage, ImageDecoder, ImageError, ImageFormat, ImageReader};

use super::encoding::Encoding;
use super::error::{Reason, TextureError};
use super::plain_pnm;
use super::texel::Texel;
use super::texel_grid::TexelGrid;

/// Bounds on what a file may make us allocate. All are checked from the header.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    pub max_width: u32,
    pub max_height: u32,
    /// Decoded bytes + linear texels + mip chain, estimated before decoding.
    pub max_bytes: u64,
}

impl Default for Limits {
    /// 16384 per side, and at most the whole memory budget (`BUMPWORK_MEMORY_MIB`).
    fn default() -> Self {
        Self::within(crate::memory_budget::budget_bytes())
    }
}

impl Limits {
    /// 16384 per side and at most `max_bytes`.
    pub fn within(max_bytes: u64) -> Self {
        Self {
            max_width: 16_384,
            max_height: 16_384,
            max_bytes,
        }
    }
}

/// What the file holds, as reported by `bumpwork check IMAGE`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ImageInfo {
    pub width: u32,
    pub height: u32,
    pub format: &'static str,
    /// As decoded: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA (palette images report what
    /// they expand to).
    pub channels: u8,
    /// As decoded: 8 or 16 (1-, 2- and 4-bit files expand to 8).
    pub bits_per_channel: u8,
}

impl ImageInfo {
    pub fn has_alpha(&self) -> bool {
        self.channels.is_multiple_of(2)
    }

    pub fn is_grey(&self) -> bool {
        self.channels <= 2
    }
}

impl std::fmt::Display for ImageInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kind = match self.channels {
            1 => "grey",
            2 => "grey+alpha",
            3 => "RGB",
            _ => "RGBA",
        };
        write!(
            f,
            "{}×{} {} {} {}-bit",
            self.width, self.height, self.format, kind, self.bits_per_channel
        )
    }
}

/// A decoded image: its description and its texels in linear light.
#[derive(Debug, Clone)]
pub struct LoadedImage {
    pub info: ImageInfo,
    pub texels: TexelGrid<Texel>,
}

/// Validates `path` exactly as the renderer loads it, keeping only the description.
pub fn check_image(path: impl AsRef<Path>) -> Result<ImageInfo, TextureError> {
    load_image(path.as_ref(), &Limits::default(), Encoding::Srgb).map(|image| image.info)
}

/// Reads and decodes `path`; every failure names the file and the reason.
pub fn load_image(
    path: &Path,
    limits: &Limits,
    encoding: Encoding,
) -> Result<LoadedImage, TextureError> {
    let bytes = read_file(path, limits).map_err(|reason| TextureError::new(path, reason))?;
    decode_image(&bytes, path, limits, encoding)
}

/// Decodes an image already in memory; `name` is used for the format guess and messages.
pub fn decode_image(
    bytes: &[u8],
    name: &Path,
    limits: &Limits,
    encoding: Encoding,
) -> Result<LoadedImage, TextureError> {
    // The decoders are meant to be panic-free; this is the backstop so a bad file is
    // an error message, never a crashed workbench.
    let decoded = panic::catch_unwind(AssertUnwindSafe(|| decode(bytes, name, limits)))
        .unwrap_or_else(|_| Err(Reason::Corrupt("the decoder failed on this data".into())));
    let (info, image) = decoded.map_err(|reason| TextureError::new(name, reason))?;
    let texels = to_linear_texels(&image, encoding);
    Ok(LoadedImage { info, texels })
}

/// Reads at most `max_bytes` (+1 to notice more): the size in the metadata is not
/// trusted, since devices and pipes report 0 and would otherwise be read forever.
pub(super) fn read_file(path: &Path, limits: &Limits) -> Result<Vec<u8>, Reason> {
    read_bounded(path, limits.max_bytes).map_err(|failure| match failure {
        failure if failure.is_missing() => Reason::Missing,
        ReadFailure::TooLarge { .. } => Reason::Oversized {
            detail: format!(
                "the file is larger than the {} of the memory budget left for it (raise {})",
                crate::memory_budget::size_words(limits.max_bytes),
                crate::memory_budget::MEMORY_BUDGET_VAR
            ),
        },
        other => Reason::Unreadable(other.to_string()),
    })
}

fn decode(bytes: &[u8], name: &Path, limits: &Limits) -> Result<(ImageInfo, DynamicImage), Reason> {
    if bytes.is_empty() {
        return Err(Reason::Truncated);
    }
    let format = guess_format(bytes, name)?;
    let bytes = plain_pnm::strip_comments(bytes);
    let mut reader = ImageReader::new(Cursor::new(&bytes[..]));
    reader.set_format(format);
    reader.limits(decoder_limits(limits));
    let decoder = reader.into_decoder().map_err(classify)?;
    let (width, height) = decoder.dimensions();
    check_size(width, height, decoder.total_bytes(), limits)?;
    let colour = decoder.color_type();
    let info = ImageInfo {
        width,
        height,
        format: format_name(format),
        channels: colour.channel_count(),
        bits_per_channel: colour.bytes_per_pixel() / colour.channel_count() * 8,
    };
    let image = DynamicImage::from_decoder(decoder).map_err(classify)?;
    Ok((info, image))
}

/// The content decides (a misnamed PNG still loads). TGA has no signature, so only
/// its extension can name it; a known extension on unrecognised content is corrupt.
fn guess_format(bytes: &[u8], name: &Path) -> Result<ImageFormat, Reason> {
    if let Ok(format) = image::guess_format(bytes) {
        return Ok(format);
    }
    let signature = describe_signature(bytes);
    match ImageFormat::from_path(name) {
        Ok(ImageFormat::Tga) => Ok(ImageFormat::Tga),
        Ok(
            format @ (ImageFormat::Png | ImageFormat::Jpeg | ImageFormat::Pnm | ImageFormat::Bmp),
        ) => Err(Reason::Corrupt(format!(
            "not a valid {} file: {signature}",
            format_name(format)
        ))),
        _ => Err(Reason::Unsupported(signature)),
    }
}

fn describe_signature(bytes: &[u8]) -> String {
    let head: String = bytes
        .iter()
        .take(8)
        .map(|&b| if b.is_ascii_graphic() { b as char } else { '.' })
        .collect();
    format!("unrecognised signature \"{head}\"")
}

/// Image's own limits are a second line of defence for allocations inside a decoder;
/// width and height are left to `check_size` so the message can quote them.
fn decoder_limits(limits: &Limits) -> image::Limits {
    let mut decoder_limits = image::Limits::no_limits();
    decoder_limits.max_alloc = Some(limits.max_bytes);
    decoder_limits
}

/// Rejects zero-sized and oversized images from the header alone.
fn check_size(width: u32, height: u32, decoded_bytes: u64, limits: &Limits) -> Result<(), Reason> {
    if width == 0 || height == 0 {
        return Err(Reason::ZeroSize { width, height });
    }
    if width > limits.max_width || height > limits.max_height {
        return Err(Reason::Oversized {
            detail: format!(
                "{width}×{height} exceeds the {}×{} limit",
                limits.max_width, limits.max_height
            ),
        });
    }
    let needed = estimated_bytes(width, height, decoded_bytes);
    if needed > limits.max_bytes {
        return Err(Reason::Oversized {
            detail: format!(
                "{width}×{height} needs about {}, over the {} of the memory budget left for it \
                 (use a smaller image, or raise {})",
                crate::memory_budget::size_words(needed),
                crate::memory_budget::size_words(limits.max_bytes),
                crate::memory_budget::MEMORY_BUDGET_VAR
            ),
        });
    }
    Ok(())
}

/// Decoder output, plus the linear texels, plus the mip chain (a third of the base).
fn estimated_bytes(width: u32, height: u32, decoded_bytes: u64) -> u64 {
    let texel_bytes =
        (u64::from(width) * u64::from(height)).saturating_mul(std::mem::size_of::<Texel>() as u64);
    decoded_bytes
        .saturating_add(texel_bytes)
        .saturating_add(texel_bytes / 3)
}

fn classify(error: ImageError) -> Reason {
    match error {
        ImageError::Unsupported(e) => Reason::Unsupported(e.to_string()),
        ImageError::Limits(e) => Reason::Oversized {
            detail: e.to_string(),
        },
        ImageError::IoError(e) if e.kind() == io::ErrorKind::UnexpectedEof => Reason::Truncated,
        ImageError::Decoding(e) if mentions_early_end(&e) => Reason::Truncated,
        other => Reason::Corrupt(other.to_string()),
    }
}

/// Decoders report running out of data in their own words; look through the chain.
fn mentions_early_end(error: &(dyn std::error::Error + 'static)) -> bool {
    let mut current = Some(error);
    while let Some(e) = current {
        if e.downcast_ref::<io::Error>()
            .is_some_and(|io| io.kind() == io::ErrorKind::UnexpectedEof)
        {
            return true;
        }
        let text = e.to_string().to_ascii_lowercase();
        if [
            "unexpected end",
            "unexpected eof",
            "truncated",
            "too short",
            "no more data",
            "not enough bytes",
            "not enough data",
        ]
        .iter()
        .any(|phrase| text.contains(phrase))
        {
            return true;
        }
        current = e.source();
    }
    false
}

fn format_name(format: ImageFormat) -> &'static str {
    match format {
        ImageFormat::Png => "PNG",
        ImageFormat::Jpeg => "JPEG",
        ImageFormat::Pnm => "PNM",
        ImageFormat::Bmp => "BMP",
        ImageFormat::Tga => "TGA",
        _ => "image",
    }
}

/// Converts to premultiplied linear RGBA (see `Texel`); grey is replicated to RGB.
/// Every colour file is taken as sRGB: PNG gAMA/iCCP chunks are not applied.
fn to_linear_texels(image: &DynamicImage, encoding: Encoding) -> TexelGrid<Texel> {
    let (width, height) = (image.width(), image.height());
    let channels = usize::from(image.color().channel_count());
    let texels = match image {
        DynamicImage::ImageLuma8(_)
        | DynamicImage::ImageLumaA8(_)
        | DynamicImage::ImageRgb8(_)
        | DynamicImage::ImageRgba8(_) => {
            let table = encoding.table_u8();
            let samples = image.as_bytes();
            convert(samples, channels, |c| table[usize::from(c)], unit_u8)
        }
        DynamicImage::ImageLuma16(b) => convert16(b.as_raw(), channels, encoding),
        DynamicImage::ImageLumaA16(b) => convert16(b.as_raw(), channels, encoding),
        DynamicImage::ImageRgb16(b) => convert16(b.as_raw(), channels, encoding),
        DynamicImage::ImageRgba16(b) => convert16(b.as_raw(), channels, encoding),
        other => {
            let rgba = other.to_rgba32f();
            convert(rgba.as_raw(), 4, |c| encoding.decode(c), |a| a)
        }
    };
    TexelGrid::new(width, height, texels).expect("decoder output matches its dimensions")
}

fn unit_u8(code: u8) -> f32 {
    f32::from(code) / 255.0
}

fn convert16(samples: &[u16], channels: usize, encoding: Encoding) -> Vec<Texel> {
    let unit = |v: u16| f32::from(v) / 65535.0;
    convert(samples, channels, |c| encoding.decode(unit(c)), unit)
}

fn convert<S: Copy>(
    samples: &[S],
    channels: usize,
    colour: impl Fn(S) -> f32,
    alpha: impl Fn(S) -> f32,
) -> Vec<Texel> {
    samples
        .chunks_exact(channels)
        .map(|px| {
            let rgb = if channels >= 3 {
                Vec3::new(colour(px[0]), colour(px[1]), colour(px[2]))
            } else {
                Vec3::splat(colour(px[0]))
            };
            let a = if channels.is_multiple_of(2) {
                alpha(px[channels - 1])
            } else {
                1.0
            };
            Vec4::from((rgb * a, a))
        })
        .collect()
}

/// The file name endings of the images bumpwork reads.
pub const IMAGE_EXTENSIONS: &[&str] = &[
    "png", "jpg", "jpeg", "ppm", "pgm", "pbm", "pnm", "bmp", "tga",
];

/// Whether `name` ends as an image file bumpwork reads does (any case).
pub fn is_image_name(name: &str) -> bool {
    let extension = std::path::Path::new(name)
        .extension()
        .and_then(|e| e.to_str());
    extension.is_some_and(|e| IMAGE_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_estimate_saturates_instead_of_overflowing() {
        assert_eq!(estimated_bytes(u32::MAX, u32::MAX, u64::MAX), u64::MAX);
    }

    #[test]
    fn zero_and_oversized_are_rejected_before_decoding() {
        let limits = Limits::default();
        assert!(matches!(
            check_size(0, 5, 0, &limits),
            Err(Reason::ZeroSize { .. })
        ));
        assert!(matches!(
            check_size(100_000, 100_000, 0, &limits),
            Err(Reason::Oversized { .. })
        ));
        assert!(check_size(512, 512, 512 * 512 * 3, &limits).is_ok());
    }
}
