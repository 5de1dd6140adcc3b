//! Why hot reload could not start.

/// The file watcher could not be set up (for example, the system's limit on inotify instances
/// is reached). The workbench can go on without hot reload.
#[derive(Debug, thiserror::Error)]
#[error("cannot watch files for changes: {0}")]
pub struct WatchError(#[from] pub notify::Error);
