//! Terminal events to actions: keys through the key map, mouse drags and the wheel directly.

use super::action::Action;
use crossterm::event::{
    Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

/// Degrees of orbit per cell dragged: cells are twice as tall as wide, so rows turn twice as far.
const DRAG_DEGREES_PER_COLUMN: f64 = 2.0;
const DRAG_DEGREES_PER_ROW: f64 = 4.0;
const WHEEL_ZOOM: f64 = 1.1;

/// What an event asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Input {
    /// A key press, for the topmost overlay or the key map (`App::key`).
    Key(KeyEvent),
    Action(Action),
    /// A click or the wheel at a cell: what it does depends on what is drawn there.
    Pointer(Pointer),
    Resize(u16, u16),
    /// The terminal may have drawn over us (focus regained, Ctrl-L): draw everything again.
    Redraw,
    /// Ctrl-Z: give the terminal back and stop until continued.
    Suspend,
    Nothing,
}

/// A mouse press or wheel turn at a cell of the screen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pointer {
    pub column: u16,
    pub row: u16,
    pub kind: PointerKind,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointerKind {
    Press,
    WheelUp,
    WheelDown,
}

/// Whether `key` is a press of Ctrl and `letter` (raw mode delivers these as keys, not signals).
fn is_ctrl(key: &KeyEvent, letter: char) -> bool {
    key.kind != KeyEventKind::Release
        && key.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(key.code, KeyCode::Char(c) if c.eq_ignore_ascii_case(&letter))
}

/// Remembers where a mouse drag was, to turn the next position into an orbit step.
#[derive(Debug, Default)]
pub struct InputState {
    drag_from: Option<(u16, u16)>,
}

impl InputState {
    pub fn translate(&mut self, event: Event) -> Input {
        match event {
            Event::Key(key) if is_ctrl(&key, 'z') => Input::Suspend,
            Event::Key(key) if is_ctrl(&key, 'l') => Input::Redraw,
            Event::Key(key) if key.kind == KeyEventKind::Release => Input::Nothing,
            Event::Key(key) => Input::Key(key),
            Event::Resize(cols, rows) => Input::Resize(cols, rows),
            Event::Mouse(mouse) => self.mouse(mouse),
            Event::FocusGained => Input::Redraw,
            _ => Input::Nothing,
        }
    }

    fn mouse(&mut self, mouse: MouseEvent) -> Input {
        let at = (mouse.column, mouse.row);
        let pointer = |kind| {
            Input::Pointer(Pointer {
                column: mouse.column,
                row: mouse.row,
                kind,
            })
        };
        match mouse.kind {
            MouseEventKind::Down(MouseButton::Left) => {
                self.drag_from = Some(at);
                pointer(PointerKind::Press)
            }
            MouseEventKind::Drag(MouseButton::Left) => {
                let Some(from) = self.drag_from.replace(at) else {
                    return Input::Nothing;
                };
                let columns = at.0 as f64 - from.0 as f64;
                let rows = at.1 as f64 - from.1 as f64;
                Input::Action(Action::Orbit(
                    -columns * DRAG_DEGREES_PER_COLUMN,
                    rows * DRAG_DEGREES_PER_ROW,
                ))
            }
            MouseEventKind::Up(_) => {
                self.drag_from = None;
                Input::Nothing
            }
            MouseEventKind::ScrollUp => pointer(PointerKind::WheelUp),
            MouseEventKind::ScrollDown => pointer(PointerKind::WheelDown),
            _ => Input::Nothing,
        }
    }
}

impl Pointer {
    /// What the pointer asks of the picture (`picture` is its area): over the open parameter
    /// panel a press selects the row's parameter and the wheel changes it; elsewhere the wheel
    /// zooms.
    pub fn action(self, app: &super::app::App, picture: ratatui::layout::Rect) -> Option<Action> {
        use super::param_panel::{covers, param_at};
        if covers(app, picture, self.column, self.row) {
            let row = param_at(app, picture, self.column, self.row)?;
            return Some(match self.kind {
                PointerKind::Press => Action::SelectParamAt(row),
                PointerKind::WheelUp => Action::AdjustParamAt(row, 1.0),
                PointerKind::WheelDown => Action::AdjustParamAt(row, -1.0),
            });
        }
        match self.kind {
            PointerKind::Press => None,
            PointerKind::WheelUp => Some(Action::Zoom(1.0 / WHEEL_ZOOM)),
            PointerKind::WheelDown => Some(Action::Zoom(WHEEL_ZOOM)),
        }
    }
}
