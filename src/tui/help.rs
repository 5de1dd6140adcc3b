//! The help overlay: every key and mouse action the workbench takes, from the key map, in two
//! columns where one does not fit (80×24 shows it whole), scrolled where two do not either.

use super::keymap::help_entries;
use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::popup::{centered, clamp_scroll, draw_box, scrolled};
use crossterm::event::{KeyCode, KeyEvent};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use std::cell::Cell;

/// The keys' column, in cells.
const KEY_COLUMN: usize = 11;
/// Cells between the two columns.
const GUTTER: usize = 2;

#[derive(Default)]
pub struct Help {
    /// Rows scrolled past, when it is taller than the screen.
    scroll: u16,
    /// Rows shown when last drawn: a page, and how far scrolling can go.
    shown: Cell<(u16, usize)>,
}

impl Overlay for Help {
    fn kind(&self) -> OverlayKind {
        OverlayKind::Help
    }

    fn key(&mut self, key: &KeyEvent, _app: &dyn WorkbenchState) -> Reply {
        let (page, total) = self.shown.get();
        if let Some(scroll) = scrolled(self.scroll, key, page) {
            self.scroll = clamp_scroll(scroll, total, page);
            return Reply::Taken;
        }
        match key.code {
            KeyCode::Esc | KeyCode::Char('?') | KeyCode::F(1) => Reply::Close,
            _ => Reply::Pass,
        }
    }

    fn draw(&self, _app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer) {
        let entries: Vec<(&str, &str)> = help_entries().collect();
        let entry_width = |&(_, words): &(&str, &str)| KEY_COLUMN + words.chars().count();
        let column = entries.iter().map(entry_width).max().unwrap_or(0);
        let inner = (
            picture.width.saturating_sub(2),
            picture.height.saturating_sub(2),
        );
        let two = entries.len() > inner.1 as usize && 2 * column + GUTTER <= inner.0 as usize;
        let rows = if two {
            entries.len().div_ceil(2)
        } else {
            entries.len()
        };
        let lines: Vec<Line> = (0..rows)
            .map(|row| {
                let right = entries.get(row + rows).filter(|_| two);
                help_line(entries[row], right.copied(), column, style)
            })
            .collect();
        let width = lines.iter().map(Line::width).max().unwrap_or(0) as u16 + 2;
        let popup = centered(picture, width, rows as u16 + 2);
        let page = popup.height.saturating_sub(2);
        self.shown.set((page, rows));
        let scroll = clamp_scroll(self.scroll, rows, page);
        let title = match (rows as u16).saturating_sub(page) {
            0 => " keys (Esc closes) ".to_string(),
            _ => format!(
                " keys {}-{} of {}, ↑↓ scroll ",
                scroll + 1,
                scroll + page,
                rows
            ),
        };
        draw_box(popup, &title, lines, scroll, style, buffer);
    }
}

/// One row: an entry, and the right column's beside it.
fn help_line<'a>(
    left: (&'a str, &'a str),
    right: Option<(&'a str, &'a str)>,
    column: usize,
    style: Style,
) -> Line<'a> {
    let bold = style.add_modifier(Modifier::BOLD);
    let mut spans = vec![
        Span::styled(format!("{:<KEY_COLUMN$}", left.0), bold),
        Span::styled(left.1, style),
    ];
    if let Some((keys, words)) = right {
        let pad = column + GUTTER - KEY_COLUMN - left.1.chars().count();
        spans.push(Span::styled(" ".repeat(pad), style));
        spans.push(Span::styled(format!("{keys:<KEY_COLUMN$}"), bold));
        spans.push(Span::styled(words, style));
    }
    Line::from(spans)
}
