//! What the status line says after the scene: the reload state, a key's answer for a while, or
//! the last error.

use std::time::Duration;

/// How long an `Info` message stays in the status line.
pub const INFO_LIFETIME: Duration = Duration::from_secs(5);

/// The reload state or the last error, shown in the status line.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Message {
    #[default]
    None,
    Info(String),
    Error(String),
}
