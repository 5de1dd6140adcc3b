//! Content hashes of a scene's files, to tell a real change from a save of the same bytes.

use crate::content_hash::{fnv1a64, hash_file};
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

/// The hash of what a load would read (see [`hash_file`]); a missing file has none. Anything
/// a load refuses (a FIFO, a device, a file past the limit) hashes as the reason with the
/// file's size, so the watcher never blocks or reads forever, and the load that follows says
/// what is wrong.
fn content_hash(path: &Path) -> Option<u64> {
    match hash_file(path) {
        Ok(hash) => Some(hash),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => None,
        Err(error) => {
            let size = path.metadata().map_or(0, |m| m.len());
            Some(fnv1a64(format!("{error} {size}").as_bytes()))
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
