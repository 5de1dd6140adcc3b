//! A bordered box of text over the picture: what every overlay is drawn in.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Widget};

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

/// A `width` × `height` box in the middle of `area`, shrunk to fit it.
pub fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let width = width.min(area.width);
    let height = height.min(area.height);
    Rect {
        x: area.x + (area.width - width) / 2,
        y: area.y + (area.height - height) / 2,
        width,
        height,
    }
}

/// The first line to show of `total` lines in a box `shown` lines tall, asked to start at
/// `scroll`: the last line can be reached, not passed.
pub fn clamp_scroll(scroll: u16, total: usize, shown: u16) -> u16 {
    scroll.min((total as u16).saturating_sub(shown))
}

/// The next scroll position for a key in a list `total` lines long shown `page` at a time: `↑`
/// `↓`, PageUp, PageDown, Home, End; `None` for other keys.
pub fn scrolled(scroll: u16, key: &crossterm::event::KeyEvent, page: u16) -> Option<u16> {
    use crossterm::event::KeyCode;
    let page = page.max(1);
    Some(match key.code {
        KeyCode::Up => scroll.saturating_sub(1),
        KeyCode::Down => scroll.saturating_add(1),
        KeyCode::PageUp => scroll.saturating_sub(page),
        KeyCode::PageDown => scroll.saturating_add(page),
        KeyCode::Home => 0,
        KeyCode::End => u16::MAX,
        _ => return None,
    })
}
