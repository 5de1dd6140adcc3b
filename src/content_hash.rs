//! A file's content as a 64-bit FNV-1a hash: what a still's recipe records of each file it read,
//! and what the watcher compares to tell a real change from a save of the same bytes. Stable
//! across builds and platforms (unlike std's hasher), enough to notice an edited file.

use std::io::{BufRead, BufReader, Error, ErrorKind, Read};
use std::path::Path;

/// FNV-1a's starting value.
pub const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

/// FNV-1a, 64 bits, continued from `hash` (`FNV_OFFSET` to start) over more bytes.
pub fn fnv1a64_from(hash: u64, bytes: &[u8]) -> u64 {
    bytes.iter().fold(hash, |hash, &b| {
        (hash ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

/// FNV-1a, 64 bits, of `bytes`.
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    fnv1a64_from(FNV_OFFSET, bytes)
}

/// The hash of a regular file's bytes, streamed. Files come from recipes anyone may have made:
/// a device (`/dev/zero`), a pipe or a file over the image memory limit (`texture::Limits`,
/// which `BUMPWORK_MEMORY_MIB` sets; no pattern or image the renderer reads is larger) is
/// refused, not read forever.
pub fn hash_file(path: &Path) -> std::io::Result<u64> {
    let max_bytes = crate::texture::Limits::default().max_bytes;
    let file = crate::bounded_read::open_regular(path).map_err(|failure| {
        let kind = match failure.is_missing() {
            true => ErrorKind::NotFound,
            false => ErrorKind::InvalidInput,
        };
        Error::new(kind, failure.to_string())
    })?;
    let length = file.metadata()?.len();
    if length > max_bytes {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            format!("larger than {} MiB", max_bytes >> 20),
        ));
    }
    let mut reader = BufReader::with_capacity(1 << 16, file.take(max_bytes));
    let mut hash = FNV_OFFSET;
    loop {
        let chunk = reader.fill_buf()?;
        if chunk.is_empty() {
            return Ok(hash);
        }
        hash = fnv1a64_from(hash, chunk);
        let n = chunk.len();
        reader.consume(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_matches_the_published_test_vectors() {
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn a_streamed_file_hashes_as_its_bytes_and_devices_and_missing_files_are_errors() {
        let bytes: Vec<u8> = (0..200_000u32).map(|i| (i * 7 % 251) as u8).collect();
        let file = tempfile::NamedTempFile::new().unwrap();
        std::fs::write(file.path(), &bytes).unwrap();
        assert_eq!(hash_file(file.path()).unwrap(), fnv1a64(&bytes));
        #[cfg(unix)]
        assert!(hash_file(Path::new("/dev/zero")).is_err());
        let missing = file.path().with_extension("missing");
        let error = hash_file(&missing).unwrap_err();
        assert_eq!(error.kind(), ErrorKind::NotFound);
    }
}
