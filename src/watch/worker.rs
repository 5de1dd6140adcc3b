//! The reload worker: debounced events in, rebuilt scenes out.

use super::change_watcher::ChangeWatcher;
use super::outcome::{Reload, ReloadError, ReloadOutcome};
use super::scene_source::SceneSource;
use super::snapshot::Snapshot;
use super::watched_dirs::WatchedDirs;
use crate::scene::Scene;
use notify_debouncer_mini::{DebounceEventResult, Debouncer};
use std::ffi::OsString;
use std::path::PathBuf;
use std::sync::mpsc::{Receiver, Sender};

/// What reaches the worker thread: debounced file events, or the order to stop.
pub(crate) enum Message {
    Touched(Vec<PathBuf>),
    /// The watcher lost track (e.g. its event queue overflowed): any file may have changed.
    Rescan,
    Stop,
}

impl From<DebounceEventResult> for Message {
    fn from(result: DebounceEventResult) -> Self {
        match result {
            Ok(events) => Message::Touched(events.into_iter().map(|e| e.path).collect()),
            Err(_) => Message::Rescan,
        }
    }
}

/// Owns the source, the watcher and what was last read; rebuilds the scene when a dependency's
/// content changes.
pub(crate) struct Worker {
    source: Box<dyn SceneSource>,
    debouncer: Debouncer<ChangeWatcher>,
    watched: WatchedDirs,
    files: Vec<PathBuf>,
    snapshot: Snapshot,
    last_good: Option<Scene>,
}

impl Worker {
    pub fn new(source: Box<dyn SceneSource>, debouncer: Debouncer<ChangeWatcher>) -> Self {
        Worker {
            source,
            debouncer,
            watched: WatchedDirs::default(),
            files: Vec::new(),
            snapshot: Snapshot::default(),
            last_good: None,
        }
    }

    /// Watches the files, then reads them: a save after the watch starts is never missed.
    pub fn load_first(&mut self) -> Result<Scene, ReloadError> {
        self.refresh_files();
        self.snapshot = Snapshot::take(&self.files);
        self.load().map(|reload| reload.scene)
    }

    /// Until told to stop: on each batch of events that touches a dependency, reloads if the
    /// content changed and sends the outcome.
    pub fn run(mut self, inbox: Receiver<Message>, outbox: Sender<ReloadOutcome>) {
        while let Some(touched) = next_batch(&inbox) {
            if !self.concerns(&touched) {
                continue;
            }
            if outbox.send(self.reload_if_changed()).is_err() {
                return;
            }
        }
    }

    /// Whether any touched path names a dependency. File names are compared, not whole paths,
    /// so a path spelt differently by the watcher still matches; an unrelated file of the same
    /// name costs only a hash comparison.
    fn concerns(&self, touched: &Touched) -> bool {
        let Touched::Paths(paths) = touched else {
            return true;
        };
        let names: Vec<OsString> = self
            .files
            .iter()
            .filter_map(|f| f.file_name().map(OsString::from))
            .collect();
        paths
            .iter()
            .filter_map(|p| p.file_name())
            .any(|name| names.iter().any(|n| n == name))
    }

    fn reload_if_changed(&mut self) -> ReloadOutcome {
        self.refresh_files();
        let snapshot = Snapshot::take(&self.files);
        if snapshot == self.snapshot {
            return ReloadOutcome::Unchanged;
        }
        // Hashed before loading: a write racing the load changes the hash again and, through
        // its own event, triggers one more reload, so the last state on disk always wins.
        self.snapshot = snapshot;
        match self.load() {
            Ok(reload) => ReloadOutcome::Reloaded(Box::new(reload)),
            Err(error) => ReloadOutcome::Failed(error),
        }
    }

    fn load(&mut self) -> Result<Reload, ReloadError> {
        let scene = self.source.load()?;
        let previous = self.last_good.replace(scene.clone());
        Ok(Reload { scene, previous })
    }

    fn refresh_files(&mut self) {
        self.files = self.source.dependencies();
        self.watched.update(self.debouncer.watcher(), &self.files);
    }
}

/// What a batch of messages says changed.
enum Touched {
    Paths(Vec<PathBuf>),
    Anything,
}

/// Waits for a message, then takes every one already queued, so that a reload slower than the
/// debounce handles the backlog once. `None` means stop.
fn next_batch(inbox: &Receiver<Message>) -> Option<Touched> {
    let mut touched = Touched::Paths(Vec::new());
    let mut message = inbox.recv().ok()?;
    loop {
        match message {
            Message::Stop => return None,
            Message::Rescan => touched = Touched::Anything,
            Message::Touched(paths) => {
                if let Touched::Paths(all) = &mut touched {
                    all.extend(paths);
                }
            }
        }
        match inbox.try_recv() {
            Ok(next) => message = next,
            Err(_) => return Some(touched),
        }
    }
}
