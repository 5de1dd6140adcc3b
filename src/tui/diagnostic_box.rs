//! A failed reload's whole diagnostic (the `file:line:column` line, the source line, the caret)
//! in a box at the top of the picture, until the file loads again or Esc closes it.

use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::popup::{centered, draw_box};
use crossterm::event::{KeyCode, KeyEvent};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};

pub struct DiagnosticBox {
    pub message: String,
}

impl Overlay for DiagnosticBox {
    fn kind(&self) -> OverlayKind {
        OverlayKind::Diagnostic
    }

    fn key(&mut self, key: &KeyEvent, _app: &dyn WorkbenchState) -> Reply {
        match key.code {
            KeyCode::Esc => Reply::Close,
            _ => Reply::Pass,
        }
    }

    fn draw(&self, _app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer) {
        let lines: Vec<Line> = self
            .message
            .lines()
            .map(|line| {
                Line::from(Span::styled(
                    crate::term::sanitize(line).into_owned(),
                    style,
                ))
            })
            .collect();
        let width = lines.iter().map(|l| l.width()).max().unwrap_or(0) as u16 + 4;
        let height = lines.len() as u16 + 2;
        let mut popup = centered(picture, width, height);
        popup.y = picture.y;
        let title = " the file does not load (Esc hides this) ";
        draw_box(popup, title, lines, 0, style, buffer);
    }
}
