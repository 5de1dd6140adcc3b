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

/// How an error shows: red where there is colour, bold where there is none.
pub fn error_style(base: ratatui::style::Style) -> ratatui::style::Style {
    use ratatui::style::{Color, Modifier};
    match base.fg {
        Some(_) => base.fg(Color::Indexed(9)).add_modifier(Modifier::BOLD),
        None => base.add_modifier(Modifier::BOLD),
    }
}
