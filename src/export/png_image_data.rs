//! The image data of a PNG after its header: rows of 8-bit RGB in, top first, filtered as the
//! png crate's adaptive filter does (`png_filter`, in AVX2 where there), deflated by fdeflate
//! as its fast compression does, and written out as image-data chunks of `CHUNK_BYTES`; then
//! the image's end. The files are the png crate's to the byte.

use super::png_filter::{FilterPath, RowFilter};
use std::io::Write;
use std::sync::{Arc, Mutex, PoisonError};

/// Compressed bytes per image-data chunk. The png crate's default, 4 KiB, makes a 1080p still a
/// thousand small writes, and on ext4 each write into a new page cache folio zeroes the rest of
/// it; a chunk as large as a whole still would be one write, copied into the page cache after
/// its last row while the other core idles.
const CHUNK_BYTES: usize = 1 << 17;

/// A PNG's image data being written, after its header.
pub(super) struct ImageData<W: Write> {
    filter: RowFilter,
    deflate: fdeflate::Compressor<ImageDataChunks<W>>,
    failure: WriteFailure,
    /// The start of a row whose rest has not come yet.
    partial: Vec<u8>,
    row_len: usize,
    rows_left: u32,
    height: u32,
}

/// The first write that failed under the compressor, if any. fdeflate takes its writer for
/// good and unwraps some of its writes, so the writer under it never fails: it keeps the
/// failure here, drops what comes after, and the rows ask here.
type WriteFailure = Arc<Mutex<Option<String>>>;

fn failed(failure: &WriteFailure) -> Option<String> {
    failure
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .clone()
}

impl<W: Write> ImageData<W> {
    pub(super) fn new(
        png: png::Writer<W>,
        width: u32,
        height: u32,
    ) -> Result<ImageData<W>, String> {
        let failure = WriteFailure::default();
        let chunks = ImageDataChunks {
            png,
            buffer: Vec::with_capacity(2 * CHUNK_BYTES),
            failure: failure.clone(),
        };
        Ok(ImageData {
            filter: RowFilter::new(width as usize, FilterPath::detect()),
            deflate: fdeflate::Compressor::new(chunks).map_err(|e| e.to_string())?,
            failure,
            partial: Vec::new(),
            row_len: 3 * width as usize,
            rows_left: height,
            height,
        })
    }

    /// Takes rows of 8-bit RGB, top first; a write may end within a row.
    pub(super) fn write(&mut self, mut rgb: &[u8]) -> Result<(), String> {
        if !self.partial.is_empty() {
            let wanted = (self.row_len - self.partial.len()).min(rgb.len());
            self.partial.extend_from_slice(&rgb[..wanted]);
            rgb = &rgb[wanted..];
            if self.partial.len() < self.row_len {
                return Ok(());
            }
            let row = std::mem::take(&mut self.partial);
            self.row(&row)?;
            self.partial = row;
            self.partial.clear();
        }
        let mut rows = rgb.chunks_exact(self.row_len.max(1));
        for row in &mut rows {
            self.row(row)?;
        }
        self.partial.extend_from_slice(rows.remainder());
        Ok(())
    }

    fn row(&mut self, row: &[u8]) -> Result<(), String> {
        if self.rows_left == 0 {
            return Err(format!("more than the image's {} rows", self.height));
        }
        self.rows_left -= 1;
        let filtered = self.filter.filter(row);
        // The type byte on its own, as the png crate writes it: fdeflate's output depends on
        // where its inputs are cut.
        let (kind, bytes) = filtered.split_at(1);
        for part in [kind, bytes] {
            self.deflate.write_data(part).map_err(|e| e.to_string())?;
        }
        failed(&self.failure).map_or(Ok(()), Err)
    }

    /// Ends the image data and the file (its last chunk and the image's end).
    pub(super) fn finish(self) -> Result<(), String> {
        if self.rows_left > 0 || !self.partial.is_empty() {
            let whole = self.height - self.rows_left;
            return Err(format!(
                "{whole} of the image's {} rows were written",
                self.height
            ));
        }
        let chunks = self.deflate.finish().map_err(|e| e.to_string())?;
        if let Some(failure) = failed(&self.failure) {
            return Err(failure);
        }
        let ImageDataChunks {
            mut png, buffer, ..
        } = chunks;
        if !buffer.is_empty() {
            png.write_chunk(png::chunk::IDAT, &buffer)
                .map_err(|e| e.to_string())?;
        }
        png.finish().map_err(|e| e.to_string())
    }
}

/// Compressed image data cut into chunks of `CHUNK_BYTES` (the last one shorter).
struct ImageDataChunks<W: Write> {
    png: png::Writer<W>,
    buffer: Vec<u8>,
    failure: WriteFailure,
}

impl<W: Write> Write for ImageDataChunks<W> {
    #[inline]
    fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
        self.buffer.extend_from_slice(data);
        if self.buffer.len() >= CHUNK_BYTES {
            self.write_whole_chunks();
        }
        Ok(data.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl<W: Write> ImageDataChunks<W> {
    #[inline(never)]
    fn write_whole_chunks(&mut self) {
        let mut failure = self.failure.lock().unwrap_or_else(PoisonError::into_inner);
        let whole = self.buffer.len() / CHUNK_BYTES * CHUNK_BYTES;
        if failure.is_none() {
            for chunk in self.buffer[..whole].chunks_exact(CHUNK_BYTES) {
                if let Err(error) = self.png.write_chunk(png::chunk::IDAT, chunk) {
                    *failure = Some(error.to_string());
                    break;
                }
            }
        }
        self.buffer.drain(..whole);
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
        let mut encoder = png::Encoder::new(disk, size.0, size.1);
        encoder.set_color(png::ColorType::Rgb);
        let result = encoder
            .write_header()
            .map_err(|e| e.to_string())
            .and_then(|png| ImageData::new(png, size.0, size.1))
            .and_then(|mut rows| {
                rgb.chunks(piece).try_for_each(|piece| rows.write(piece))?;
                rows.finish()
            });
        let bytes = written.lock().unwrap().clone();
        (result, bytes)
    }

    /// The same image as the png crate writes it with its adaptive filter and fast compression.
    fn png_crate_file(size: (u32, u32), rgb: &[u8]) -> Vec<u8> {
        let written = Arc::new(Mutex::new(Vec::new()));
        let disk = FillsUp {
            written: written.clone(),
            room: usize::MAX,
        };
        let mut encoder = png::Encoder::new(disk, size.0, size.1);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_compression(png::Compression::Fast);
        let mut stream = encoder
            .write_header()
            .and_then(|w| w.into_stream_writer_with_size(CHUNK_BYTES))
            .unwrap();
        stream.write_all(rgb).unwrap();
        stream.finish().unwrap();
        written.lock().unwrap().clone()
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
    fn the_file_is_the_one_the_png_crate_writes() {
        for size in [SIZE, (1, 1), (11, 3), (640, 480)] {
            let rgb = rows(size.0, size.1);
            let (result, ours) = stream(size, &rgb, 4096, usize::MAX);
            assert_eq!(result, Ok(()));
            let theirs = png_crate_file(size, &rgb);
            let chunks = theirs.windows(4).filter(|w| w == b"IDAT").count();
            assert!(size.0 < 640 || chunks > 1, "several image-data chunks");
            assert!(
                ours == theirs,
                "{size:?}: {} against {} bytes",
                ours.len(),
                theirs.len()
            );
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
