//! The overlays drawn with ratatui over the picture: the help (every key of the key map) and a
//! failed reload's whole diagnostic.

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
    draw_box(popup, &title, lines, scroll, style, buffer);
}

/// Draws `lines` from line `scroll` on in a bordered box titled `title`, over whatever `popup`
/// covered.
pub fn draw_box(
    popup: Rect,
    title: &str,
    lines: Vec<Line>,
    scroll: u16,
    style: Style,
    buffer: &mut Buffer,
) {
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

/// Draws `message` (a diagnostic: the `file:line:column` line, the source line, the caret) in a
/// box at the top of `area`, clipped to it.
pub fn draw_diagnostic(area: Rect, style: Style, message: &str, buffer: &mut Buffer) {
    let lines: Vec<Line> = message
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
    let mut popup = centered(area, width, height);
    popup.y = area.y;
    let title = " the file does not load (Esc hides this) ";
    draw_box(popup, title, lines, 0, style, buffer);
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
