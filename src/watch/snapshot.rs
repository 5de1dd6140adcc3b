//! Content hashes of a scene's files, to tell a real change from a save of the same bytes.

use std::hash::{DefaultHasher, Hasher};
use std::io::Read;
use std::path::{Path, PathBuf};

/// The content of a set of files, by hash, to tell a real change from a save of the same bytes.
/// A missing or unreadable file has no hash, which differs from every content.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Snapshot(Vec<(PathBuf, Option<u64>)>);

impl Snapshot {
    pub fn take(files: &[PathBuf]) -> Snapshot {
        Snapshot(files.iter().map(|f| (f.clone(), content_hash(f))).collect())
    }
}

/// Hashes what a load would read: a regular file up to the image limit, the largest any load
/// takes. Anything else (a FIFO, a device, a file past the limit) hashes as its kind and size,
/// so the watcher never blocks or reads forever, and the load that follows says what is wrong.
fn content_hash(path: &Path) -> Option<u64> {
    let limit = crate::texture::Limits::default().max_bytes;
    let mut hasher = DefaultHasher::new();
    let file = match crate::bounded_read::open_regular(path) {
        Ok(file) => file,
        Err(failure) if failure.is_missing() => return None,
        Err(failure) => {
            hasher.write(failure.to_string().as_bytes());
            return Some(hasher.finish());
        }
    };
    let length = file.metadata().ok()?.len();
    hasher.write_u64(length);
    if length > limit {
        return Some(hasher.finish());
    }
    let mut file = file.take(limit);
    let mut buffer = vec![0; 64 * 1024];
    loop {
        match file.read(&mut buffer).ok()? {
            0 => return Some(hasher.finish()),
            n => hasher.write(&buffer[..n]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_bytes_same_snapshot_and_missing_differs_from_empty() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let dir = dir.path();
        let file = dir.join("a.pat");
        let files = [file.clone()];
        std::fs::write(&file, "height = u").unwrap();
        let first = Snapshot::take(&files);
        std::fs::write(&file, "height = u").unwrap();
        assert_eq!(Snapshot::take(&files), first);
        std::fs::write(&file, "").unwrap();
        let empty = Snapshot::take(&files);
        assert_ne!(empty, first);
        std::fs::remove_file(&file).unwrap();
        assert_ne!(Snapshot::take(&files), empty);
    }
}
