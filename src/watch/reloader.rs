//! The reloader: a worker thread that rebuilds the scene when its files change.

use super::error::WatchError;
use super::outcome::{ReloadError, ReloadOutcome};
use super::scene_source::SceneSource;
use super::worker::{Message, Worker};
use crate::scene::Scene;
use notify_debouncer_mini::{Config, new_debouncer_opt};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;
use std::time::Duration;

/// How long the files must be quiet before a reload. Editors finish a save (temporary file,
/// fsync, rename; or backup, truncate, write) within a few milliseconds, so 20 ms turns one
/// save into one reload, yet leaves most of a 50 ms write-to-frame budget for the reload and
/// the render.
pub const DEBOUNCE: Duration = Duration::from_millis(20);

/// Watches the files of the scene on screen and rebuilds it when they change, on its own thread.
/// Dropping it stops the thread and the watcher; for no hot reload, do not create one.
pub struct Reloader {
    outcomes: Receiver<ReloadOutcome>,
    control: Sender<Message>,
    worker: Option<JoinHandle<()>>,
}

impl Reloader {
    /// Starts watching `source`'s files and loads it once (on this thread), returning that
    /// first load's result. Later changes arrive through [`Reloader::poll`].
    pub fn start(
        source: impl SceneSource,
    ) -> Result<(Reloader, Result<Scene, ReloadError>), WatchError> {
        let (control, inbox) = mpsc::channel();
        let events = control.clone();
        let config = Config::default()
            .with_timeout(DEBOUNCE)
            .with_batch_mode(false);
        let debouncer = new_debouncer_opt(config, move |result| {
            let _ = events.send(Message::from(result));
        })?;
        let mut worker = Worker::new(Box::new(source), debouncer);
        let first = worker.load_first();
        let (outbox, outcomes) = mpsc::channel();
        let handle = std::thread::Builder::new()
            .name("bumpwork reload".into())
            .spawn(move || worker.run(inbox, outbox))
            .map_err(|e| WatchError(notify::Error::io(e)))?;
        let reloader = Reloader {
            outcomes,
            control,
            worker: Some(handle),
        };
        Ok((reloader, first))
    }

    /// The next outcome if one is ready, without blocking. Outcomes come in order; call until
    /// `None` once per turn of the event loop and show the last good scene.
    pub fn poll(&self) -> Option<ReloadOutcome> {
        self.outcomes.try_recv().ok()
    }

    /// The next outcome, waiting up to `timeout` (for tests and benchmarks).
    pub fn wait(&self, timeout: Duration) -> Option<ReloadOutcome> {
        self.outcomes.recv_timeout(timeout).ok()
    }
}

/// How long dropping a [`Reloader`] waits for its thread to finish a reload in progress before
/// leaving it behind: quitting must never wait on a load, however slow its files are.
const STOP_GRACE: Duration = Duration::from_millis(200);

impl Drop for Reloader {
    fn drop(&mut self) {
        let _ = self.control.send(Message::Stop);
        let Some(worker) = self.worker.take() else {
            return;
        };
        let deadline = std::time::Instant::now() + STOP_GRACE;
        while !worker.is_finished() && std::time::Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(2));
        }
        if worker.is_finished() {
            let _ = worker.join();
        }
    }
}
