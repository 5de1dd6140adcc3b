//! PNG output with the `png` crate: 8-bit sRGB, text chunks before the image data, rows
//! streamed in as they are rendered.

use super::output_file::OutputFile;
use super::writeback::WritebackFile;
use crate::Error;
use crate::raster::Framebuffer;
use crate::still::RowSink;
use std::io::Write;
use std::path::Path;
use std::sync::{Arc, Mutex, PoisonError};

/// Compressed bytes per image-data chunk. The encoder's default, 4 KiB, makes a 1080p still a
/// thousand small writes, and on ext4 each write into a new page cache folio zeroes the rest of
/// it; a chunk as large as a whole still would be one write, copied into the page cache after
/// its last row while the other core idles.
const CHUNK_BYTES: usize = 1 << 17;

/// A PNG being written: rows go in top first; `finish` completes it and makes it appear.
pub struct PngStill {
    file: OutputFile,
    writer: png::StreamWriter<'static, CheckedWriter<WritebackFile>>,
    failure: WriteFailure,
}

/// The first write that failed under the encoder, if any.
type WriteFailure = Arc<Mutex<Option<String>>>;

/// A writer that keeps its first failure. The encoder writes the last image-data chunk and the
/// image's end when it is dropped, where a failed write is ignored: `finish` asks here.
struct CheckedWriter<W> {
    inner: W,
    failure: WriteFailure,
}

impl<W: Write> CheckedWriter<W> {
    fn keep<T>(&self, result: std::io::Result<T>) -> std::io::Result<T> {
        if let Err(error) = &result {
            let mut failure = self.failure.lock().unwrap_or_else(PoisonError::into_inner);
            failure.get_or_insert_with(|| error.to_string());
        }
        result
    }
}

impl<W: Write> Write for CheckedWriter<W> {
    fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
        let result = self.inner.write(data);
        self.keep(result)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        let result = self.inner.flush();
        self.keep(result)
    }
}

/// Finishes the stream and reports a failed write, also one made as the encoder was dropped.
fn finish_stream<W: Write>(
    writer: png::StreamWriter<'static, CheckedWriter<W>>,
    failure: &WriteFailure,
) -> Result<(), String> {
    writer.finish().map_err(|e| e.to_string())?;
    let failure = failure.lock().unwrap_or_else(PoisonError::into_inner);
    failure.clone().map_or(Ok(()), Err)
}

impl PngStill {
    /// Starts `path` as a `width` × `height` RGB PNG carrying `texts` (keyword, UTF-8 text).
    pub fn create(
        path: &Path,
        (width, height): (u32, u32),
        texts: &[(&str, String)],
    ) -> Result<PngStill, Error> {
        let (file, handle) = OutputFile::create(path)?;
        let fail = |e: png::EncodingError| Error::write(path, e);
        let failure = WriteFailure::default();
        let handle = CheckedWriter {
            inner: WritebackFile::new(handle),
            failure: failure.clone(),
        };
        let mut encoder = png::Encoder::new(handle, width, height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        encoder.set_compression(png::Compression::Fast);
        for (keyword, text) in texts {
            encoder
                .add_itxt_chunk(keyword.to_string(), text.clone())
                .map_err(fail)?;
        }
        let writer = encoder
            .write_header()
            .and_then(|w| w.into_stream_writer_with_size(CHUNK_BYTES))
            .map_err(fail)?;
        Ok(PngStill {
            file,
            writer,
            failure,
        })
    }

    pub fn finish(self) -> Result<(), Error> {
        let path = self.file.destination().to_path_buf();
        finish_stream(self.writer, &self.failure).map_err(|e| Error::write(&path, e))?;
        self.file.commit()
    }
}

impl RowSink for PngStill {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
        self.writer.write_all(rgb).map_err(|e| e.to_string())
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Takes `room` bytes into `written`, then fails every write as a full disk does.
    struct FillsUp {
        written: Arc<Mutex<Vec<u8>>>,
        room: usize,
    }

    impl Write for FillsUp {
        fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
            let mut written = self.written.lock().unwrap();
            if written.len() + data.len() > self.room {
                return Err(std::io::Error::other("no space left on device"));
            }
            written.extend_from_slice(data);
            Ok(data.len())
        }

        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    const SIZE: (u32, u32) = (64, 48);

    fn rows() -> Vec<u8> {
        (0..SIZE.0 * SIZE.1 * 3)
            .map(|i| (i * 7 % 251) as u8)
            .collect()
    }

    /// Streams `rows()` as `PngStill` does into a disk with `room` bytes: the result of
    /// finishing, and the bytes that reached the disk.
    fn stream(room: usize) -> (Result<(), String>, Vec<u8>) {
        let written = Arc::new(Mutex::new(Vec::new()));
        let failure = WriteFailure::default();
        let sink = CheckedWriter {
            inner: FillsUp {
                written: written.clone(),
                room,
            },
            failure: failure.clone(),
        };
        let mut encoder = png::Encoder::new(sink, SIZE.0, SIZE.1);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_compression(png::Compression::Fast);
        let result = encoder
            .write_header()
            .and_then(|w| w.into_stream_writer_with_size(CHUNK_BYTES))
            .map_err(|e| e.to_string())
            .and_then(|mut stream| {
                stream.write_all(&rows()).map_err(|e| e.to_string())?;
                finish_stream(stream, &failure)
            });
        let bytes = written.lock().unwrap().clone();
        (result, bytes)
    }

    #[test]
    fn a_streamed_png_holds_its_rows() {
        let (result, bytes) = stream(usize::MAX);
        assert_eq!(result, Ok(()));
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let mut decoded = vec![0; reader.output_buffer_size().unwrap()];
        reader.next_frame(&mut decoded).unwrap();
        assert!(decoded == rows());
    }

    #[test]
    fn a_write_failing_as_the_encoder_finishes_is_reported() {
        let whole = stream(usize::MAX).1.len();
        // The image's end (12 bytes), then the last image-data chunk: both are written only
        // as the encoder is dropped.
        for room in [whole - 1, whole - 12, whole - 20, 100] {
            let (result, bytes) = stream(room);
            assert!(bytes.len() < whole);
            let reason = result.expect_err(&format!("room for {room} of {whole} bytes"));
            assert!(reason.contains("no space"), "{reason}");
        }
    }
}
