//! The help overlay: every key of the key map, drawn with ratatui over the picture.

use super::keymap::help_lines;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

const KEY_COLUMN: usize = 8;

/// Draws the help centred in `area`. Taller than the area, it shows the lines from `scroll` on
/// (clamped so the last line can be reached, not passed) and says how to scroll.
pub fn draw_help(area: Rect, style: Style, scroll: u16, buffer: &mut Buffer) {
    let lines: Vec<Line> = help_lines()
        .map(|b| {
            Line::from(vec![
                Span::styled(
                    format!("{:<KEY_COLUMN$}", b.keys),
                    style.add_modifier(Modifier::BOLD),
                ),
                Span::styled(b.description, style),
            ])
        })
        .collect();
    let width = lines.iter().map(|l| l.width()).max().unwrap_or(0) as u16 + 4;
    let height = lines.len() as u16 + 2;
    let popup = centered(area, width, height);
    let shown = popup.height.saturating_sub(2);
    let hidden = (lines.len() as u16).saturating_sub(shown);
    let scroll = scroll.min(hidden);
    let title = match hidden {
        0 => " keys ".to_string(),
        _ => format!(
            " keys {}-{} of {}, ↑↓ scroll ",
            scroll + 1,
            scroll + shown,
            lines.len()
        ),
    };
    Clear.render(popup, buffer);
    Paragraph::new(lines)
        .style(style)
        .scroll((scroll, 0))
        .block(
            Block::default()
                .borders(Borders::ALL)
                .title(title)
                .style(style),
        )
        .render(popup, buffer);
}

fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let width = width.min(area.width);
    let height = height.min(area.height);
    Rect {
        x: area.x + (area.width - width) / 2,
        y: area.y + (area.height - height) / 2,
        width,
        height,
    }
}
