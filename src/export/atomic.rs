//! A file that appears whole or not at all: written under a temporary name in the destination's
//! directory and renamed over the destination only when complete. Dropped before `commit` (an
//! error, a panic, a cancelled render), the temporary file is removed.

use crate::Error;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};
use tempfile::TempPath;

/// A file whose written pages start going to disk a mebibyte at a time as they are written
/// (on Linux), so the sync before `AtomicFile::commit`'s rename waits only for the last of them.
pub struct WritebackFile {
    file: File,
    written: u64,
    /// Bytes already handed to writeback: whole pages, never the one still being filled (a
    /// write into a page under writeback would wait for it).
    started: u64,
    /// `None` where the system does not say (and there is no early writeback).
    page: Option<u64>,
}

const WRITEBACK_STEP: u64 = 1 << 20;

impl WritebackFile {
    pub fn new(file: File) -> WritebackFile {
        WritebackFile {
            file,
            written: 0,
            started: 0,
            page: crate::memory::page_size().map(|page| page as u64),
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
    // head start, and the sync in `commit` reports any failure to write.
    unsafe { libc::sync_file_range(file.as_raw_fd(), offset, len, libc::SYNC_FILE_RANGE_WRITE) };
}

#[cfg(not(target_os = "linux"))]
fn start_writeback(_: &File, _: u64, _: u64) {}

pub struct AtomicFile {
    temporary: TempPath,
    destination: PathBuf,
    /// A second handle on the temporary file, to sync it to disk before the rename.
    sync: File,
}

/// Files as `File::create` makes them (0666 less the umask), not the temporary file's 0600.
#[cfg(unix)]
fn readable_by_all() -> std::fs::Permissions {
    use std::os::unix::fs::PermissionsExt;
    std::fs::Permissions::from_mode(0o666)
}

/// Why the temporary file could not be made, said of the directory (the user never named the
/// temporary file, which tempfile's own message quotes).
fn directory_problem(directory: &Path, error: &std::io::Error) -> String {
    let shown = crate::diagnostic::sanitize(&directory.display().to_string()).into_owned();
    match error.kind() {
        std::io::ErrorKind::NotFound => format!("the directory {shown} does not exist"),
        std::io::ErrorKind::PermissionDenied => {
            format!("the directory {shown} is not writable")
        }
        std::io::ErrorKind::NotADirectory => format!("{shown} is not a directory"),
        _ => format!(
            "cannot create a file in {shown}: {}",
            std::io::Error::from(error.kind())
        ),
    }
}

impl AtomicFile {
    /// Creates the temporary file next to `destination`; returns it and a handle to write into.
    pub fn create(destination: &Path) -> Result<(AtomicFile, File), Error> {
        let directory = match destination.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = destination
            .file_name()
            .map_or("still".into(), |n| n.to_string_lossy().into_owned());
        let (file, temporary) = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .permissions(readable_by_all())
            .tempfile_in(directory)
            .map_err(|e| Error::write(destination, directory_problem(directory, &e)))?
            .into_parts();
        let sync = file.try_clone().map_err(|e| Error::write(destination, e))?;
        let atomic = AtomicFile {
            temporary,
            destination: destination.to_path_buf(),
            sync,
        };
        Ok((atomic, file))
    }

    pub fn destination(&self) -> &Path {
        &self.destination
    }

    /// Syncs the finished file and renames it over the destination.
    pub fn commit(self) -> Result<(), Error> {
        let destination = self.destination;
        self.sync
            .sync_all()
            .map_err(|e| Error::write(&destination, e))?;
        self.temporary
            .persist(&destination)
            .map_err(|e| Error::write(&destination, e.error))
    }
}

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
