//! Overlays: the boxes drawn over the picture (help, parameter panel, scene picker, message log,
//! a failed reload's diagnostic). Each owns its state, takes the keys it wants while it is the
//! topmost, and draws itself; what it asks of the workbench it asks as an `Action`, so the app
//! stays the only place state changes.
//!
//! To add one: a type implementing `Overlay` in a file of its own, an `OverlayKind` for it, and
//! an action (or key) that opens it with `App::open`.

use super::action::Action;
use super::material_controls::ParamRow;
use super::message_history::Log;
use crossterm::event::KeyEvent;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;

/// Which overlay, to find or close it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OverlayKind {
    Help,
    Panel,
    Picker,
    Log,
    Diagnostic,
}

/// What an overlay made of a key.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// Taken: the overlay changed (or not) and stays.
    Taken,
    /// Not the overlay's: the key map has it.
    Pass,
    /// The overlay closes.
    Close,
    /// The workbench does this; the overlay stays.
    Act(Action),
    /// The workbench does this and the overlay closes.
    CloseAnd(Action),
}

/// What overlays read of the workbench; the app is the one implementation.
pub trait WorkbenchState {
    /// Every message of the run.
    fn log(&self) -> &Log;
    /// The scenes the picker offers: those given, then every built-in not among them.
    fn pickable_scenes(&self) -> Vec<String>;
    /// The selected object's material parameters.
    fn param_rows(&self) -> Vec<ParamRow>;
    /// The selected parameter.
    fn param(&self) -> usize;
    /// The selected object, as a person calls it.
    fn object_name(&self) -> String;
    fn is_open(&self, kind: OverlayKind) -> bool;
}

pub trait Overlay {
    fn kind(&self) -> OverlayKind;

    /// A key pressed while this is the topmost overlay; `app` as it is now.
    fn key(&mut self, key: &KeyEvent, app: &dyn WorkbenchState) -> Reply;

    /// Draws the overlay over `picture`, the screen's picture area.
    fn draw(&self, app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer);
}
