use crate::Error;
use crate::raster::Framebuffer;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes the framebuffer as an 8-bit sRGB PNG, atomically: into a temporary file in the same
/// directory, then renamed over the destination, so a failed or interrupted export leaves no file.
pub fn write_png(framebuffer: &Framebuffer, path: &Path) -> Result<(), Error> {
    let pixels: Vec<u8> = framebuffer.to_srgb8().into_iter().flatten().collect();
    let temporary = temporary_path(path);
    let result = write_png_to(&temporary, framebuffer.width, framebuffer.height, &pixels)
        .and_then(|()| std::fs::rename(&temporary, path).map_err(|e| e.to_string()));
    result.map_err(|reason| {
        let _ = std::fs::remove_file(&temporary);
        Error::write(path, reason)
    })
}

fn write_png_to(path: &Path, width: u32, height: u32, pixels: &[u8]) -> Result<(), String> {
    let mut encoded = Vec::new();
    let mut encoder = png::Encoder::new(&mut encoded, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    writer.write_image_data(pixels).map_err(|e| e.to_string())?;
    writer.finish().map_err(|e| e.to_string())?;
    let mut file = std::fs::File::create(path).map_err(|e| e.to_string())?;
    file.write_all(&encoded).map_err(|e| e.to_string())?;
    file.sync_all().map_err(|e| e.to_string())
}

fn temporary_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}
