//! What a batch of file events led to: a rebuilt scene, an error, or nothing.

use super::live_params::{KeptValue, carry_live_params};
use crate::scene::Scene;

/// What one debounced batch of file events led to.
#[derive(Debug)]
pub enum ReloadOutcome {
    /// The files changed and the scene was rebuilt from them.
    Reloaded(Box<Reload>),
    /// The files changed but the scene could not be built; the last good scene stays.
    Failed(ReloadError),
    /// Files were touched but every dependency holds the same bytes as before.
    Unchanged,
}

/// A rebuilt scene, with the scene as it was loaded before (to tell which parameter values the
/// user has changed live since).
#[derive(Debug)]
pub struct Reload {
    pub scene: Scene,
    /// The previous good scene as loaded from disk; `None` if there was none yet.
    pub previous: Option<Scene>,
}

impl Reload {
    /// The new scene, carrying over the parameter values the user changed in `live` (the
    /// previous scene as shown) wherever the parameter still exists. See [`carry_live_params`].
    pub fn keep_live_params(self, live: &Scene) -> Scene {
        self.keep_live_params_telling(live).0
    }

    /// As `keep_live_params`, with the live values kept where the file's value changed.
    pub fn keep_live_params_telling(self, live: &Scene) -> (Scene, Vec<KeptValue>) {
        let mut scene = self.scene;
        let kept = match &self.previous {
            Some(previous) => carry_live_params(previous, live, &mut scene),
            None => Vec::new(),
        };
        (scene, kept)
    }
}

/// Why a reload failed: the loader's message, naming the file with line:column where it has one.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct ReloadError {
    pub message: String,
}

impl ReloadError {
    /// The `file:line:column: what` line, for a one-line status bar (diagnostics continue with
    /// the offending source line and a caret).
    pub fn first_line(&self) -> &str {
        self.message.lines().next().unwrap_or_default()
    }
}

impl From<crate::Error> for ReloadError {
    fn from(error: crate::Error) -> Self {
        ReloadError {
            message: error.to_string(),
        }
    }
}
