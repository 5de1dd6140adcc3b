//! The program's one error type: every way a user's input can be wrong, each one message.

use crate::diagnostic::sanitize;
use std::path::Path;

/// Every way a user's input can be wrong. Each displays as one clear message; the binary prints
/// it and exits with status 1.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    #[error("unknown scene '{}'{}; `bumpwork render --list` prints the built-in names",
        crate::diagnostic::shown_input(name), suggestion.as_ref().map(|s| format!(" (did you mean '{s}'?)")).unwrap_or_default())]
    UnknownScene {
        name: String,
        suggestion: Option<String>,
    },
    /// A located problem in a file, already rendered with line:column and a caret.
    #[error("{0}")]
    Diagnostic(String),
    #[error("cannot read {}: {}", sanitize(&path.display().to_string()), reason)]
    Read {
        path: std::path::PathBuf,
        reason: String,
    },
    #[error("cannot write {}: {}", sanitize(&path.display().to_string()), reason)]
    Write {
        path: std::path::PathBuf,
        reason: String,
    },
    #[error("{0}")]
    InvalidArgument(String),
    #[error("{0}")]
    OverBudget(#[from] crate::memory_budget::OverBudget),
    /// Every message was printed as it was found (`check` of one file): only the exit status is
    /// left to give.
    #[error("the error was reported")]
    Reported,
    /// A signal stopped the work; nothing partial was left behind. Exit status 128 + signal.
    #[error("interrupted by signal {0}; no file was written")]
    Interrupted(i32),
}

impl Error {
    pub fn read(path: &Path, reason: impl std::fmt::Display) -> Error {
        Error::Read {
            path: path.to_path_buf(),
            reason: reason.to_string(),
        }
    }

    pub fn write(path: &Path, reason: impl std::fmt::Display) -> Error {
        Error::Write {
            path: path.to_path_buf(),
            reason: reason.to_string(),
        }
    }
}
