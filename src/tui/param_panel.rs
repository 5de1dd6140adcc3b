//! The parameter panel: every pattern parameter of the edited object (the bump's, then the
//! texture's) with its value, range and default, the selected one marked. `↑` `↓` select, `←`
//! `→` take fine steps, Enter types a value; a click on a row selects it and the wheel over a row
//! changes it.

use super::action::Action;
use super::material_controls::{ParamRow, ParamSlot};
use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::popup::draw_box;
use crate::term::sanitize;
use crossterm::event::{KeyCode, KeyEvent};
use ratatui::buffer::Buffer;
use ratatui::layout::{Position, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;

/// A fine step, in the keys' steps.
const FINE_STEP: f32 = 0.1;
/// Longest value typed.
const MAX_TYPED: usize = 24;

#[derive(Default)]
pub struct ParamPanel {
    /// The value being typed, from Enter to Enter.
    typing: Option<String>,
    /// Why the last value typed was not taken.
    refused: Option<String>,
}

impl Overlay for ParamPanel {
    fn kind(&self) -> OverlayKind {
        OverlayKind::Panel
    }

    fn key(&mut self, key: &KeyEvent, app: &dyn WorkbenchState) -> Reply {
        if let Some(typed) = &mut self.typing {
            return match key.code {
                KeyCode::Esc => {
                    self.typing = None;
                    Reply::Taken
                }
                KeyCode::Enter => self.take_typed(app),
                KeyCode::Backspace => {
                    typed.pop();
                    Reply::Taken
                }
                KeyCode::Char(c) if typed.len() < MAX_TYPED && is_number_char(c) => {
                    typed.push(c);
                    Reply::Taken
                }
                _ if crate::term::is_ctrl_c(key) => Reply::Pass,
                _ => Reply::Taken,
            };
        }
        match key.code {
            KeyCode::Esc | KeyCode::Char('m') => Reply::Close,
            KeyCode::Up => Reply::Act(Action::SelectParam(-1)),
            KeyCode::Down => Reply::Act(Action::SelectParam(1)),
            KeyCode::Left => Reply::Act(Action::AdjustParam(-FINE_STEP)),
            KeyCode::Right => Reply::Act(Action::AdjustParam(FINE_STEP)),
            KeyCode::Enter if !app.param_rows().is_empty() => {
                self.typing = Some(String::new());
                self.refused = None;
                Reply::Taken
            }
            _ => Reply::Pass,
        }
    }

    fn draw(&self, app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer) {
        let mut lines = lines(app);
        let note = match (&self.typing, &self.refused) {
            (Some(typed), _) => Some(format!("value: {typed}▏ Enter sets, Esc cancels")),
            (None, Some(refused)) => Some(refused.clone()),
            (None, None) => None,
        };
        lines.extend(note.map(|text| PanelLine { param: None, text }));
        let popup = area(&lines, picture);
        let shown: Vec<Line> = lines
            .into_iter()
            .map(|line| match line.param {
                Some(index) if index == app.param() => {
                    Line::styled(line.text, style.add_modifier(Modifier::BOLD))
                }
                _ => Line::styled(line.text, style),
            })
            .collect();
        let title = format!(" {}: parameters (m closes) ", app.object_name());
        draw_box(popup, &title, shown, 0, style, buffer);
    }
}

impl ParamPanel {
    /// The value typed for the selected parameter, if it is a number in its range; else the
    /// panel says why and nothing changes.
    fn take_typed(&mut self, app: &dyn WorkbenchState) -> Reply {
        let typed = self.typing.take().unwrap_or_default();
        let Some(row) = app.param_rows().into_iter().nth(app.param()) else {
            return Reply::Taken;
        };
        match checked_value(&typed, &row) {
            Ok(value) => {
                self.refused = None;
                Reply::Act(Action::SetParam(app.param(), value))
            }
            Err(why) => {
                self.refused = Some(why);
                Reply::Taken
            }
        }
    }
}

fn is_number_char(c: char) -> bool {
    c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E')
}

/// `typed` as a value of `row`'s parameter, or why it is not one.
fn checked_value(typed: &str, row: &ParamRow) -> Result<f32, String> {
    let name = sanitize(&row.name);
    let value: f32 = match typed.trim().parse() {
        Ok(value) if f32::is_finite(value) => value,
        _ => return Err(format!("{name}: expected a number, found `{typed}`")),
    };
    if !(row.min..=row.max).contains(&value) {
        return Err(format!(
            "{name}: expected {}..{}, found {value}",
            row.min, row.max
        ));
    }
    Ok(value)
}

/// The panel's widest, in cells (borders included).
const MAX_WIDTH: u16 = 52;

/// One line of the panel: a binding's heading, or a parameter (its place in `param_rows`).
struct PanelLine {
    param: Option<usize>,
    text: String,
}

fn lines(app: &dyn WorkbenchState) -> Vec<PanelLine> {
    let selected = app.param();
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
            text: row_text(row, index == selected),
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

/// The parameter (its place in `param_rows`) on the panel's line at `column`, `row` of the
/// screen, if the panel is open over `picture` and a parameter is there.
pub fn param_at(app: &dyn WorkbenchState, picture: Rect, column: u16, row: u16) -> Option<usize> {
    let lines = lines(app);
    let popup = area(&lines, picture);
    if !app.is_open(OverlayKind::Panel) || !popup.contains(Position::new(column, row)) {
        return None;
    }
    let line = row.checked_sub(popup.y + 1)?;
    lines.get(line as usize)?.param
}

/// Whether `column`, `row` is on the open panel.
pub fn covers(app: &dyn WorkbenchState, picture: Rect, column: u16, row: u16) -> bool {
    app.is_open(OverlayKind::Panel)
        && area(&lines(app), picture).contains(Position::new(column, row))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row() -> ParamRow {
        ParamRow {
            slot: ParamSlot::Bump,
            pattern: "p".into(),
            name: "period".into(),
            value: 30.0,
            min: 4.0,
            max: 300.0,
            default: 30.0,
        }
    }

    #[test]
    fn a_typed_value_is_taken_only_as_a_number_in_range() {
        assert_eq!(checked_value("199.2", &row()), Ok(199.2));
        assert_eq!(checked_value(" 4 ", &row()), Ok(4.0));
        assert!(
            checked_value("3.9", &row())
                .unwrap_err()
                .contains("expected 4..300")
        );
        assert!(checked_value("1e9", &row()).is_err());
        assert!(
            checked_value("", &row())
                .unwrap_err()
                .contains("expected a number")
        );
        assert!(checked_value("--", &row()).is_err());
        assert!(checked_value("1e99", &row()).is_err(), "overflows f32");
    }
}
