//! The message log (`M`): every message of the run, the start-up note included, newest last,
//! errors marked.

use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::popup::{centered, clamp_scroll, draw_box, scrolled};
use super::status_message::Message;
use crossterm::event::{KeyCode, KeyEvent};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;
use std::cell::Cell;

/// The log's overlay: opens on the newest messages.
pub struct LogView {
    scroll: u16,
    /// Rows shown when last drawn: a page, and how far scrolling can go.
    shown: Cell<(u16, usize)>,
}

impl Default for LogView {
    fn default() -> Self {
        LogView {
            scroll: u16::MAX,
            shown: Cell::new((1, 0)),
        }
    }
}

impl Overlay for LogView {
    fn kind(&self) -> OverlayKind {
        OverlayKind::Log
    }

    fn key(&mut self, key: &KeyEvent, _app: &dyn WorkbenchState) -> Reply {
        let (page, total) = self.shown.get();
        if let Some(scroll) = scrolled(clamp_scroll(self.scroll, total, page), key, page) {
            self.scroll = clamp_scroll(scroll, total, page);
            return Reply::Taken;
        }
        match key.code {
            KeyCode::Esc | KeyCode::Char('M') => Reply::Close,
            _ => Reply::Pass,
        }
    }

    fn draw(&self, app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer) {
        let entries = app.log().entries();
        let width = picture.width.saturating_sub(2).max(1) as usize;
        let lines: Vec<Line> = match entries.is_empty() {
            true => vec![Line::styled("no messages yet", style)],
            false => (entries.iter())
                .flat_map(|entry| entry_lines(entry, width, style))
                .collect(),
        };
        let popup = centered(picture, picture.width, lines.len() as u16 + 2);
        let page = popup.height.saturating_sub(2);
        self.shown.set((page, lines.len()));
        let scroll = clamp_scroll(self.scroll, lines.len(), page);
        let title = format!(" messages: {} (Esc closes, ↑↓ scroll) ", entries.len());
        draw_box(popup, &title, lines, scroll, style, buffer);
    }
}

/// An entry's lines, folded at `width`: its time and first line, then any further lines (a
/// caret diagram).
fn entry_lines<'a>(
    (seconds, message): &(f64, Message),
    width: usize,
    style: Style,
) -> Vec<Line<'a>> {
    let (text, style) = match message {
        Message::Error(text) => (text.as_str(), super::status_message::error_style(style)),
        Message::Info(text) => (text.as_str(), style),
        Message::None => ("", style),
    };
    let text = crate::term::sanitize(text).into_owned();
    let lines = text.lines().enumerate().map(|(i, line)| match i {
        0 => format!("{seconds:7.1}s {line}"),
        _ => format!("{:9}{line}", ""),
    });
    lines
        .flat_map(|line| fold(&line, width))
        .map(|line| Line::styled(line, style.remove_modifier(Modifier::DIM)))
        .collect()
}

/// `line` in pieces of at most `width` characters, each after the first indented as the text.
fn fold(line: &str, width: usize) -> Vec<String> {
    let chars: Vec<char> = line.chars().collect();
    let indent = 9.min(width.saturating_sub(1));
    let mut pieces = vec![chars.iter().take(width).collect::<String>()];
    let mut rest = &chars[chars.len().min(width)..];
    while !rest.is_empty() {
        let take = rest.len().min(width - indent);
        pieces.push(" ".repeat(indent) + &rest[..take].iter().collect::<String>());
        rest = &rest[take..];
    }
    pieces
}
