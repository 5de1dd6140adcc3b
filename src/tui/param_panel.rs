//! The parameter panel: every pattern parameter of the edited object (the bump's, then the
//! texture's) with its value, range and default, the selected one marked; a click on a row
//! selects it and the wheel over a row changes it.

use super::app::App;
use super::material_controls::{ParamRow, ParamSlot};
use crate::term::sanitize;
use ratatui::buffer::Buffer;
use ratatui::layout::{Position, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;

/// The panel's widest, in cells (borders included).
const MAX_WIDTH: u16 = 52;

/// One line of the panel: a binding's heading, or a parameter (its place in `param_rows`).
struct PanelLine {
    param: Option<usize>,
    text: String,
}

fn lines(app: &App) -> Vec<PanelLine> {
    let rows = app.param_rows();
    if rows.is_empty() {
        let text = "no pattern parameters: p adds a bump pattern, t a texture".to_string();
        return vec![PanelLine { param: None, text }];
    }
    let mut lines = Vec::new();
    let mut heading = None;
    for (index, row) in rows.iter().enumerate() {
        if heading != Some((row.slot, &row.pattern)) {
            heading = Some((row.slot, &row.pattern));
            let slot = match row.slot {
                ParamSlot::Bump => "bump",
                ParamSlot::Texture => "texture",
            };
            let text = format!("{slot} {}", sanitize(&row.pattern));
            lines.push(PanelLine { param: None, text });
        }
        lines.push(PanelLine {
            param: Some(index),
            text: row_text(row, index == app.param),
        });
    }
    lines
}

/// `▸ period   30.000  2..100 (30)`: the marker, name, value, range and default.
fn row_text(row: &ParamRow, selected: bool) -> String {
    let marker = if selected { '▸' } else { ' ' };
    format!(
        "{marker} {:<10} {:>9.3}  {}..{} ({})",
        sanitize(&row.name),
        row.value,
        row.min,
        row.max,
        row.default
    )
}

/// Where the panel goes in `picture`: its top right corner.
fn area(lines: &[PanelLine], picture: Rect) -> Rect {
    let widest = lines.iter().map(|l| l.text.chars().count()).max();
    let width = (widest.unwrap_or(0) as u16 + 4)
        .min(MAX_WIDTH)
        .min(picture.width);
    let height = (lines.len() as u16 + 2).min(picture.height);
    Rect {
        x: picture.x + picture.width - width,
        y: picture.y,
        width,
        height,
    }
}

/// Draws the panel over `picture`.
pub fn draw_panel(app: &App, picture: Rect, style: Style, buffer: &mut Buffer) {
    let lines = lines(app);
    let popup = area(&lines, picture);
    let shown: Vec<Line> = lines
        .into_iter()
        .map(|line| match line.param {
            Some(index) if index == app.param => {
                Line::styled(line.text, style.add_modifier(Modifier::BOLD))
            }
            _ => Line::styled(line.text, style),
        })
        .collect();
    let title = format!(" object {}: parameters (m closes) ", app.object + 1);
    super::help::draw_box(popup, &title, shown, 0, style, buffer);
}

/// The parameter (its place in `param_rows`) on the panel's line at `column`, `row` of the
/// screen, if the panel is open over `picture` and a parameter is there.
pub fn param_at(app: &App, picture: Rect, column: u16, row: u16) -> Option<usize> {
    let lines = lines(app);
    let popup = area(&lines, picture);
    if !app.panel || !popup.contains(Position::new(column, row)) {
        return None;
    }
    let line = row.checked_sub(popup.y + 1)?;
    lines.get(line as usize)?.param
}

/// Whether `column`, `row` is on the open panel.
pub fn covers(app: &App, picture: Rect, column: u16, row: u16) -> bool {
    app.panel && area(&lines(app), picture).contains(Position::new(column, row))
}
