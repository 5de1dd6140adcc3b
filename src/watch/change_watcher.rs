//! The platform's file watcher, passing on only events that can change content.

use notify::event::{AccessKind, AccessMode};
use notify::{Config, Event, EventHandler, EventKind, RecommendedWatcher, RecursiveMode, Watcher};
use std::path::Path;

/// The platform's watcher, passing on only events that can change a file's content. Reads are
/// dropped before they reach the debouncer: the reloader reads every file it hashes, and inotify
/// reports opens, so otherwise each reload would schedule another one. (The debouncer forgets
/// event kinds, hence the filter here, below it.)
pub(crate) struct ChangeWatcher(RecommendedWatcher);

impl Watcher for ChangeWatcher {
    fn new<F: EventHandler>(mut handler: F, config: Config) -> notify::Result<Self> {
        let changes_only = move |event: notify::Result<Event>| {
            if !matches!(&event, Ok(e) if is_read(&e.kind)) {
                handler.handle_event(event);
            }
        };
        RecommendedWatcher::new(changes_only, config).map(ChangeWatcher)
    }

    fn watch(&mut self, path: &Path, recursive_mode: RecursiveMode) -> notify::Result<()> {
        self.0.watch(path, recursive_mode)
    }

    fn unwatch(&mut self, path: &Path) -> notify::Result<()> {
        self.0.unwatch(path)
    }

    fn kind() -> notify::WatcherKind {
        RecommendedWatcher::kind()
    }
}

/// Accesses other than closing a file opened for writing (which marks a finished write).
fn is_read(kind: &EventKind) -> bool {
    matches!(kind, EventKind::Access(access) if *access != AccessKind::Close(AccessMode::Write))
}
