//! An animation as one file, written frame by frame as the frames are rendered, never
//! half-written (see `output_file`): APNG, every frame exact in 8-bit sRGB, or GIF, each frame
//! with a 256-colour palette of its own, dithered (`palette`, as sixel pictures are). Both carry the first
//! frame's recipe: APNG in the text chunks a still has, GIF in a comment.

use super::output_file::OutputFile;
use super::writeback::WritebackFile;
use crate::Error;
use crate::palette::{self, Precision};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// Which animation file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AnimationFormat {
    Apng,
    Gif,
}

/// The fastest frame rate a GIF plays as asked: its frame times are whole hundredths of a
/// second, and browsers show frames of under two hundredths for a tenth.
pub const GIF_MAX_FPS: f64 = 50.0;

/// An animation being written: frames go in in order; `finish` completes it and makes it appear.
pub struct AnimationFile {
    file: OutputFile,
    encoder: Encoder,
    size: (u32, u32),
    fps: f64,
    frames_written: u32,
}

enum Encoder {
    Apng(png::Writer<WritebackFile>),
    Gif(gif::Encoder<BufWriter<File>>),
}

impl AnimationFile {
    /// Starts `path` as a `frames`-frame animation of `size` at `fps` frames a second, carrying
    /// `texts` (keyword, text), looping forever.
    pub fn create(
        path: &Path,
        format: AnimationFormat,
        (size, frames, fps): ((u32, u32), u32, f64),
        texts: &[(&str, String)],
    ) -> Result<AnimationFile, Error> {
        check_memory(size, frames)?;
        let (file, handle) = OutputFile::create(path)?;
        let encoder = match format {
            AnimationFormat::Apng => Encoder::Apng(apng_writer(handle, size, frames, fps, texts)?),
            AnimationFormat::Gif => Encoder::Gif(gif_encoder(handle, size, texts, path)?),
        };
        Ok(AnimationFile {
            file,
            encoder,
            size,
            fps,
            frames_written: 0,
        })
    }

    /// Adds the next frame: `size` rows of 8-bit sRGB, 3 bytes a pixel, top row first.
    pub fn add_frame(&mut self, rgb: &[u8]) -> Result<(), Error> {
        let path = self.file.destination().to_path_buf();
        let index = self.frames_written;
        match &mut self.encoder {
            Encoder::Apng(writer) => writer
                .write_image_data(rgb)
                .map_err(|e| Error::write(&path, e)),
            Encoder::Gif(encoder) => {
                let (width, height) = (self.size.0 as u16, self.size.1 as u16);
                let picture = palette::indexed(rgb, usize::from(width), Precision::Fine);
                let palette = picture.palette.concat();
                let mut frame =
                    gif::Frame::from_palette_pixels(width, height, picture.indices, palette, None);
                frame.delay = gif_delay(index, self.fps);
                encoder
                    .write_frame(&frame)
                    .map_err(|e| Error::write(&path, e))
            }
        }?;
        self.frames_written += 1;
        Ok(())
    }

    pub fn finish(self) -> Result<(), Error> {
        let path = self.file.destination().to_path_buf();
        let fail = |e: String| Error::write(&path, e);
        match self.encoder {
            Encoder::Apng(writer) => writer.finish().map_err(|e| fail(e.to_string()))?,
            Encoder::Gif(encoder) => {
                let mut out = encoder.into_inner().map_err(|e| fail(e.to_string()))?;
                out.flush().map_err(|e| fail(e.to_string()))?;
            }
        }
        self.file.commit()
    }
}

/// An APNG writer whose header, texts and animation control are written; each frame after
/// the first has its own delay set as it is written.
fn apng_writer(
    handle: File,
    (width, height): (u32, u32),
    frames: u32,
    fps: f64,
    texts: &[(&str, String)],
) -> Result<png::Writer<WritebackFile>, Error> {
    let mut encoder = png::Encoder::new(WritebackFile::new(handle), width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    encoder.set_compression(png::Compression::Fast);
    let fail = |e: png::EncodingError| Error::InvalidArgument(format!("APNG: {e}"));
    for (keyword, text) in texts {
        encoder
            .add_itxt_chunk(keyword.to_string(), text.clone())
            .map_err(fail)?;
    }
    encoder.set_animated(frames, 0).map_err(fail)?;
    let (numerator, denominator) = apng_delay(fps);
    encoder
        .set_frame_delay(numerator, denominator)
        .map_err(fail)?;
    encoder.write_header().map_err(fail)
}

/// A GIF encoder that loops forever, its texts in one comment.
fn gif_encoder(
    handle: File,
    (width, height): (u32, u32),
    texts: &[(&str, String)],
    path: &Path,
) -> Result<gif::Encoder<BufWriter<File>>, Error> {
    let fail = |e: gif::EncodingError| Error::write(path, e);
    let (Ok(width), Ok(height)) = (u16::try_from(width), u16::try_from(height)) else {
        return Err(Error::InvalidArgument(
            "a GIF is at most 65535 pixels on a side".into(),
        ));
    };
    let mut encoder =
        gif::Encoder::new(BufWriter::new(handle), width, height, &[]).map_err(fail)?;
    encoder.set_repeat(gif::Repeat::Infinite).map_err(fail)?;
    let comment: String = texts
        .iter()
        .map(|(keyword, text)| format!("{keyword}:\n{text}\n"))
        .collect();
    encoder
        .write_raw_extension(gif::Extension::Comment.into(), &[comment.as_bytes()])
        .map_err(|e| Error::write(path, e))?;
    Ok(encoder)
}

/// The APNG frame delay, seconds as a fraction: exact for a whole number of frames a second,
/// else to a ten-thousandth.
fn apng_delay(fps: f64) -> (u16, u16) {
    if fps.fract() == 0.0 && fps <= f64::from(u16::MAX) {
        return (1, fps as u16);
    }
    (
        (10_000.0 / fps).round().clamp(1.0, f64::from(u16::MAX)) as u16,
        10_000,
    )
}

/// Frame `index`'s time on screen in hundredths: the rounded clock at its end less that at its
/// start, so the animation's length is kept whatever the rounding.
fn gif_delay(index: u32, fps: f64) -> u16 {
    let at = |frame: u32| (100.0 * f64::from(frame) / fps).round();
    (at(index + 1) - at(index)).clamp(0.0, f64::from(u16::MAX)) as u16
}

/// The memory one frame takes while it is encoded: its rows, and for a GIF the RGBA copy and
/// indices the quantizer makes. Checked against the budget before the file is made.
fn check_memory((width, height): (u32, u32), frames: u32) -> Result<(), Error> {
    let bytes = u64::from(width) * u64::from(height) * 12;
    let budget = crate::memory_budget::budget_bytes();
    if bytes > budget {
        return Err(Error::InvalidArgument(format!(
            "each of the animation's {frames} frames takes {} while it is encoded, over the {} \
             memory budget; use a smaller --size or raise {}",
            crate::memory_budget::size_words(bytes),
            crate::memory_budget::size_words(budget),
            crate::memory_budget::MEMORY_BUDGET_VAR
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gif_delays_add_up_to_the_animation_length() {
        for fps in [24.0, 30.0, 12.5, 7.0, 29.97, 50.0] {
            let frames = (fps * 3.0) as u32;
            let total: u32 = (0..frames).map(|i| u32::from(gif_delay(i, fps))).sum();
            let length = (100.0 * f64::from(frames) / fps).round() as u32;
            assert_eq!(total, length, "{fps} fps");
            assert!((0..frames).all(|i| gif_delay(i, fps) >= 2), "{fps} fps");
        }
    }

    #[test]
    fn apng_delays_are_exact_for_whole_rates() {
        assert_eq!(apng_delay(24.0), (1, 24));
        assert_eq!(apng_delay(29.97), (334, 10_000));
        assert_eq!(apng_delay(0.5), (20_000, 10_000));
    }
}
