//! The directories holding a scene's files, watched instead of the files themselves.

use notify::{RecursiveMode, Watcher};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The directories holding a scene's files. Watching directories rather than files sees a file
/// that is replaced (renamed over, deleted and re-created), which a watch on the old file's
/// inode would miss.
#[derive(Default)]
pub(crate) struct WatchedDirs(BTreeSet<PathBuf>);

impl WatchedDirs {
    /// Watches the directories of `files` and stops watching those no longer needed. A directory
    /// that cannot be watched (it does not exist) is tried again on the next update; meanwhile
    /// the loader reports the missing file.
    pub fn update(&mut self, watcher: &mut dyn Watcher, files: &[PathBuf]) {
        let wanted: BTreeSet<PathBuf> = files.iter().map(|f| directory_of(f)).collect();
        for gone in self.0.difference(&wanted) {
            let _ = watcher.unwatch(gone);
        }
        self.0.retain(|dir| wanted.contains(dir));
        for dir in wanted {
            if !self.0.contains(&dir) && watcher.watch(&dir, RecursiveMode::NonRecursive).is_ok() {
                self.0.insert(dir);
            }
        }
    }
}

fn directory_of(file: &Path) -> PathBuf {
    let absolute = std::path::absolute(file).unwrap_or_else(|_| file.to_path_buf());
    match absolute.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    }
}
