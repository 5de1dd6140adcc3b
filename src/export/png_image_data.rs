//! The image data of a PNG: the header and text chunks, then rows of 8-bit RGB in, top first,
//! through the png crate's stream writer with its adaptive filter and fast (fdeflate)
//! compression, in image-data chunks of `CHUNK_BYTES`; then the image's end. Every failed write
//! is reported, the image's end too, which the png crate writes when its writer is dropped.

use std::io::Write;
use std::sync::{Arc, Mutex, PoisonError};

/// Compressed bytes per image-data chunk. The png crate's default, 4 KiB, makes a 1080p still a
/// thousand small writes, and on ext4 each write into a new page cache folio zeroes the rest of
/// it; a chunk as large as a whole still would be one write, copied into the page cache after
/// its last row while the other core idles.
const CHUNK_BYTES: usize = 1 << 17;

/// A PNG being written into `W`, its rows streamed in.
pub(super) struct ImageData<W: Write + 'static> {
    rows: png::StreamWriter<'static, Recorded<W>>,
    failure: WriteFailure,
    row_len: usize,
    bytes_left: usize,
    height: u32,
}

/// The first write that failed, if any: the png crate drops the error of the image's end.
type WriteFailure = Arc<Mutex<Option<String>>>;

fn failed(failure: &WriteFailure) -> Option<String> {
    failure
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .clone()
}

impl<W: Write + 'static> ImageData<W> {
    /// Starts a `width` × `height` 8-bit sRGB PNG in `out` carrying `texts` (keyword, UTF-8
    /// text).
    pub(super) fn new(
        out: W,
        (width, height): (u32, u32),
        texts: &[(&str, String)],
    ) -> Result<ImageData<W>, String> {
        let failure = WriteFailure::default();
        let out = Recorded {
            inner: out,
            failure: failure.clone(),
        };
        let mut encoder = png::Encoder::new(out, width, height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        encoder.set_compression(png::Compression::Fast);
        for (keyword, text) in texts {
            (encoder.add_itxt_chunk(keyword.to_string(), text.clone()))
                .map_err(|e| e.to_string())?;
        }
        let rows = (encoder.write_header())
            .and_then(|writer| writer.into_stream_writer_with_size(CHUNK_BYTES))
            .map_err(|e| failed(&failure).unwrap_or_else(|| e.to_string()))?;
        let row_len = 3 * width as usize;
        Ok(ImageData {
            rows,
            failure,
            row_len,
            bytes_left: row_len * height as usize,
            height,
        })
    }

    /// Takes rows of 8-bit RGB, top first; a write may end within a row.
    pub(super) fn write(&mut self, rgb: &[u8]) -> Result<(), String> {
        if rgb.len() > self.bytes_left {
            return Err(format!("more than the image's {} rows", self.height));
        }
        self.bytes_left -= rgb.len();
        (self.rows.write_all(rgb)).map_err(|e| failed(&self.failure).unwrap_or(e.to_string()))
    }

    /// Ends the image data and the file (its last chunk and the image's end).
    pub(super) fn finish(self) -> Result<(), String> {
        if self.bytes_left > 0 {
            let written = self.height as usize - self.bytes_left.div_ceil(self.row_len.max(1));
            return Err(format!(
                "{written} of the image's {} rows were written",
                self.height
            ));
        }
        let finished = self.rows.finish().map_err(|e| e.to_string());
        failed(&self.failure).map_or(finished, Err)
    }
}

/// A writer that keeps its first failure.
struct Recorded<W: Write> {
    inner: W,
    failure: WriteFailure,
}

impl<W: Write> Recorded<W> {
    fn record(&self, error: std::io::Error) -> std::io::Error {
        let mut failure = self.failure.lock().unwrap_or_else(PoisonError::into_inner);
        failure.get_or_insert_with(|| error.to_string());
        error
    }
}

impl<W: Write> Write for Recorded<W> {
    fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
        self.inner.write(data).map_err(|e| self.record(e))
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.inner.flush().map_err(|e| self.record(e))
    }
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

    /// Noise (which deflates poorly, so the image data spans several chunks), a ramp and a
    /// flat band: `width` × `height` RGB.
    fn rows(width: u32, height: u32) -> Vec<u8> {
        let mut state = 0x2545_f491u32;
        (0..width * height * 3)
            .map(|i| match i / (width * 3) % 3 {
                0 => {
                    state ^= state << 13;
                    state ^= state >> 17;
                    state ^= state << 5;
                    state as u8
                }
                1 => (i * 7 % 251) as u8,
                _ => 200,
            })
            .collect()
    }

    /// Streams `rgb` as a still does, in writes of `piece` bytes, into a disk with `room`
    /// bytes: the result of finishing, and the bytes that reached the disk.
    fn stream(
        size: (u32, u32),
        rgb: &[u8],
        piece: usize,
        room: usize,
    ) -> (Result<(), String>, Vec<u8>) {
        let written = Arc::new(Mutex::new(Vec::new()));
        let disk = FillsUp {
            written: written.clone(),
            room,
        };
        let result = ImageData::new(disk, size, &[]).and_then(|mut rows| {
            rgb.chunks(piece).try_for_each(|piece| rows.write(piece))?;
            rows.finish()
        });
        let bytes = written.lock().unwrap().clone();
        (result, bytes)
    }

    const SIZE: (u32, u32) = (300, 200);

    #[test]
    fn a_streamed_png_holds_its_rows_however_they_are_cut() {
        let rgb = rows(SIZE.0, SIZE.1);
        for piece in [rgb.len(), 900, 7, 1000] {
            let (result, bytes) = stream(SIZE, &rgb, piece, usize::MAX);
            assert_eq!(result, Ok(()));
            let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
                .read_info()
                .unwrap();
            let mut decoded = vec![0; reader.output_buffer_size().unwrap()];
            reader.next_frame(&mut decoded).unwrap();
            assert!(decoded == rgb, "in writes of {piece} bytes");
        }
    }

    #[test]
    fn too_many_or_too_few_rows_are_refused() {
        let rgb = rows(SIZE.0, SIZE.1);
        let (result, _) = stream(SIZE, &rgb[..rgb.len() - 5], 4096, usize::MAX);
        let reason = result.expect_err("a row short");
        assert!(reason.contains("199 of the image's 200 rows"), "{reason}");
        let mut more = rgb.clone();
        more.extend_from_slice(&rgb[..900]);
        let (result, _) = stream(SIZE, &more, 4096, usize::MAX);
        assert!(
            result
                .expect_err("a row more")
                .contains("more than the image's 200 rows")
        );
    }

    #[test]
    fn a_write_failing_anywhere_is_reported() {
        let rgb = rows(SIZE.0, SIZE.1);
        let whole = stream(SIZE, &rgb, 4096, usize::MAX).1.len();
        assert!(whole > CHUNK_BYTES, "several chunks");
        // The image's end (12 bytes), the last image-data chunk, a whole chunk, the header.
        for room in [whole - 1, whole - 12, whole - 20, CHUNK_BYTES, 100] {
            let (result, bytes) = stream(SIZE, &rgb, 4096, room);
            assert!(bytes.len() < whole);
            let reason = result.expect_err(&format!("room for {room} of {whole} bytes"));
            assert!(reason.contains("no space"), "{reason}");
        }
    }
}
