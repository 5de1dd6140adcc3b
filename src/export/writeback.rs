//! Early writeback for stills, so the sync before an output file is committed waits only
//! for its last pages.

use std::fs::File;
use std::io::Write;

/// A file whose written pages start going to disk `WRITEBACK_STEP` at a time as they are written
/// (on Linux), so the sync before `OutputFile::commit`'s rename waits only for the last of them.
pub struct WritebackFile {
    file: File,
    written: u64,
    /// Bytes already handed to writeback: whole pages, never the one still being filled (a
    /// write into a page under writeback would wait for it).
    started: u64,
    /// `None` where the system does not say (and there is no early writeback).
    page: Option<u64>,
}

/// As large as a PNG still's image-data chunk (its writes come that size): a 1080p PNG is
/// about a mebibyte, so with a step of a mebibyte its whole file waited for the sync.
const WRITEBACK_STEP: u64 = 1 << 17;

impl WritebackFile {
    pub fn new(file: File) -> WritebackFile {
        WritebackFile {
            file,
            written: 0,
            started: 0,
            page: crate::huge_pages::page_size().map(|page| page as u64),
        }
    }
}

impl Write for WritebackFile {
    fn write(&mut self, data: &[u8]) -> std::io::Result<usize> {
        let n = self.file.write(data)?;
        self.written += n as u64;
        let Some(page) = self.page else {
            return Ok(n);
        };
        let whole_pages = self.written / page * page;
        if whole_pages - self.started >= WRITEBACK_STEP {
            start_writeback(&self.file, self.started, whole_pages - self.started);
            self.started = whole_pages;
        }
        Ok(n)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.file.flush()
    }
}

#[cfg(target_os = "linux")]
fn start_writeback(file: &File, offset: u64, len: u64) {
    use std::os::fd::AsRawFd;
    let (Ok(offset), Ok(len)) = (i64::try_from(offset), i64::try_from(len)) else {
        return;
    };
    // SAFETY: sync_file_range reads only its arguments; with SYNC_FILE_RANGE_WRITE alone it
    // starts writeback of the range and returns. The result is ignored on purpose: this is a
    // head start, and the sync in `OutputFile::commit` reports any failure to write.
    unsafe { libc::sync_file_range(file.as_raw_fd(), offset, len, libc::SYNC_FILE_RANGE_WRITE) };
}

#[cfg(not(target_os = "linux"))]
fn start_writeback(_: &File, _: u64, _: u64) {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_written_back_early_holds_every_byte_in_order() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("rows.bin");
        let bytes: Vec<u8> = (0..3 * WRITEBACK_STEP + 12_345)
            .map(|i| (i * 31 % 251) as u8)
            .collect();
        let mut file = WritebackFile::new(File::create(&path).unwrap());
        let page = file.page.expect("this system's page size");
        // Uneven writes, so writeback starts at page boundaries between them.
        for piece in bytes.chunks(100_003) {
            file.write_all(piece).unwrap();
            assert!(file.started <= file.written / page * page);
            assert_eq!(file.started % page, 0);
        }
        assert!(
            file.started >= 2 * WRITEBACK_STEP,
            "writeback started along the way"
        );
        drop(file);
        assert!(std::fs::read(&path).unwrap() == bytes);
    }
}
