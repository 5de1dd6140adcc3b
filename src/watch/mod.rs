//! Hot reload: watch the files a scene is built from and rebuild it when their content changes.
//!
//! ```no_run
//! use bumpwork::watch::{ReloadOutcome, Reloader, SceneFileSource};
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let (reloader, first) = Reloader::start(SceneFileSource::new("scenes/sphere-on-plane.toml"))?;
//! let mut scene = first?;
//! // Once per turn of the event loop, never blocking:
//! while let Some(outcome) = reloader.poll() {
//!     match outcome {
//!         ReloadOutcome::Reloaded(reload) => scene = reload.keep_live_params(&scene),
//!         ReloadOutcome::Failed(error) => eprintln!("{}", error.first_line()),
//!         ReloadOutcome::Unchanged => {}
//!     }
//! }
//! # Ok(()) }
//! ```
//!
//! Directories are watched rather than files, so saves that replace the file (write a temporary
//! file and rename it over, delete and re-create) are seen as well as in-place rewrites. Events
//! are debounced, and a reload happens only when the content hash of some dependency changed.
//! A failed reload leaves the last good scene in place; dropping the [`Reloader`] stops its
//! thread and its watcher.

mod change_watcher;
mod error;
mod live_params;
mod open_watched;
mod outcome;
mod reloader;
mod scene_source;
mod snapshot;
mod watched_dirs;
mod worker;

pub use error::WatchError;
pub use live_params::{KeptValue, carry_live_params};
pub use open_watched::open_watched;
pub use outcome::{Reload, ReloadError, ReloadOutcome};
pub use reloader::{DEBOUNCE, Reloader};
pub use scene_source::{FileSetSource, SceneFileSource, SceneSource};
