//! PNG output: 8-bit sRGB, text chunks before the image data, rows streamed in as they are
//! rendered (`png_image_data`), the file replaced whole when it is complete.

use super::output_file::OutputFile;
use super::png_image_data::ImageData;
use super::writeback::WritebackFile;
use crate::Error;
use crate::raster::Framebuffer;
use crate::still::RowSink;
use std::path::Path;

/// A PNG being written: rows go in top first; `finish` completes it and makes it appear.
pub struct PngStill {
    file: OutputFile,
    rows: ImageData<WritebackFile>,
}

impl PngStill {
    /// Starts `path` as a `width` × `height` RGB PNG carrying `texts` (keyword, UTF-8 text).
    pub fn create(
        path: &Path,
        size: (u32, u32),
        texts: &[(&str, String)],
    ) -> Result<PngStill, Error> {
        let (file, handle) = OutputFile::create(path)?;
        let rows = ImageData::new(WritebackFile::new(handle), size, texts)
            .map_err(|e| Error::write(path, e))?;
        Ok(PngStill { file, rows })
    }

    pub fn finish(self) -> Result<(), Error> {
        let path = self.file.destination().to_path_buf();
        self.rows.finish().map_err(|e| Error::write(&path, e))?;
        self.file.commit()
    }
}

impl RowSink for PngStill {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
        self.rows.write(rgb)
    }
}

/// Writes the framebuffer as an 8-bit sRGB PNG, atomically: a failed or interrupted export
/// leaves no file.
pub fn write_png(framebuffer: &Framebuffer, path: &Path) -> Result<(), Error> {
    write_png_with_text(framebuffer, path, &[])
}

/// `write_png` with text chunks.
pub fn write_png_with_text(
    framebuffer: &Framebuffer,
    path: &Path,
    texts: &[(&str, String)],
) -> Result<(), Error> {
    let pixels: Vec<u8> = framebuffer.to_srgb8().into_iter().flatten().collect();
    let mut png = PngStill::create(path, (framebuffer.width, framebuffer.height), texts)?;
    png.write_rows(&pixels)
        .map_err(|reason| Error::write(path, reason))?;
    png.finish()
}

/// Reads an 8-bit RGB PNG back (as written by `PngStill`): (width, height, rows).
pub fn read_png_rgb8(path: &Path) -> Result<(u32, u32, Vec<u8>), Error> {
    let file = crate::bounded_read::open_regular(path).map_err(|e| Error::read(path, e))?;
    let fail = |e: png::DecodingError| Error::read(path, e);
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .map_err(fail)?;
    let info = reader.info();
    if (info.color_type, info.bit_depth) != (png::ColorType::Rgb, png::BitDepth::Eight) {
        return Err(Error::read(path, "not an 8-bit RGB PNG"));
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| Error::read(path, "image too large"))?;
    let mut rgb = vec![0; size];
    let frame = reader.next_frame(&mut rgb).map_err(fail)?;
    rgb.truncate(frame.buffer_size());
    Ok((frame.width, frame.height, rgb))
}
