//! The temporary files being written, so a process that must exit at once (the workbench's
//! shutdown watchdog, when the event loop does not end within its grace) removes them first and
//! a signal never leaves a hidden `.NAME.XXXX.tmp` behind.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

static UNFINISHED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A temporary file on the list until this is dropped (committed or abandoned).
#[derive(Debug)]
pub struct Unfinished(PathBuf);

/// Puts `path` on the list of files to remove on a forced exit.
pub fn track(path: &Path) -> Unfinished {
    let mut list = UNFINISHED.lock().unwrap_or_else(|e| e.into_inner());
    list.push(path.to_path_buf());
    Unfinished(path.to_path_buf())
}

impl Drop for Unfinished {
    fn drop(&mut self) {
        let mut list = UNFINISHED.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(at) = list.iter().position(|p| *p == self.0) {
            list.swap_remove(at);
        }
    }
}

/// Removes every file still on the list, for a process about to exit without unwinding.
pub fn remove_all() {
    let list = UNFINISHED.lock().unwrap_or_else(|e| e.into_inner());
    for path in list.iter() {
        let _ = std::fs::remove_file(path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tracked_files_are_removed_until_they_are_let_go() {
        let dir = tempfile::tempdir().unwrap();
        let (kept, removed) = (dir.path().join("kept"), dir.path().join("removed"));
        std::fs::write(&kept, "done").unwrap();
        std::fs::write(&removed, "half").unwrap();
        drop(track(&kept));
        let _writing = track(&removed);
        remove_all();
        assert!(kept.exists(), "a file let go is not touched");
        assert!(!removed.exists(), "a file still being written is removed");
    }
}
