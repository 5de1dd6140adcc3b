//! Keys to actions: one table, read both by the input handler and by the help overlay, so the
//! help always lists exactly the keys that work.

use super::action::Action;
use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

/// One binding: what the help shows, the keys that trigger it, and the action.
pub struct Binding {
    pub keys: &'static str,
    pub description: &'static str,
    pub codes: &'static [KeyCode],
    pub action: Action,
}

const ORBIT_STEP: f64 = 10.0;
const PAN_STEP: f64 = 0.05;
const ZOOM_STEP: f64 = 1.15;
const LIGHT_STEP: f64 = 15.0;

use KeyCode::{BackTab, Char, Down, Esc, F, Home, Left, Right, Tab, Up};

pub const BINDINGS: &[Binding] = &[
    bind(
        "Tab S-Tab",
        "next / previous scene",
        &[Tab],
        Action::NextScene,
    ),
    bind("", "", &[BackTab], Action::PreviousScene),
    bind(
        "/",
        "pick a scene by name",
        &[Char('/')],
        Action::OpenPicker,
    ),
    bind(
        "←→↑↓ hljk",
        "orbit (mouse: drag)",
        &[Left, Char('h')],
        Action::Orbit(-ORBIT_STEP, 0.0),
    ),
    bind("", "", &[Right, Char('l')], Action::Orbit(ORBIT_STEP, 0.0)),
    bind("", "", &[Up, Char('k')], Action::Orbit(0.0, ORBIT_STEP)),
    bind("", "", &[Down, Char('j')], Action::Orbit(0.0, -ORBIT_STEP)),
    bind("H L K J", "pan", &[Char('H')], Action::Pan(-PAN_STEP, 0.0)),
    bind("", "", &[Char('L')], Action::Pan(PAN_STEP, 0.0)),
    bind("", "", &[Char('K')], Action::Pan(0.0, PAN_STEP)),
    bind("", "", &[Char('J')], Action::Pan(0.0, -PAN_STEP)),
    bind(
        "+ -",
        "zoom (mouse: wheel)",
        &[Char('+'), Char('=')],
        Action::Zoom(1.0 / ZOOM_STEP),
    ),
    bind("", "", &[Char('-'), Char('_')], Action::Zoom(ZOOM_STEP)),
    bind(
        "0 Home",
        "reset camera",
        &[Char('0'), Home],
        Action::ResetCamera,
    ),
    bind(
        "a d r f",
        "light left right up down",
        &[Char('a')],
        Action::MoveLight(-LIGHT_STEP, 0.0),
    ),
    bind("", "", &[Char('d')], Action::MoveLight(LIGHT_STEP, 0.0)),
    bind("", "", &[Char('r')], Action::MoveLight(0.0, LIGHT_STEP)),
    bind("", "", &[Char('f')], Action::MoveLight(0.0, -LIGHT_STEP)),
    bind("R", "reset lights", &[Char('R')], Action::ResetLights),
    bind("S", "shadows on / off", &[Char('S')], Action::ToggleShadows),
    bind(
        "v V",
        "next / previous view mode",
        &[Char('v')],
        Action::NextViewMode,
    ),
    bind("", "", &[Char('V')], Action::PreviousViewMode),
    bind("o", "next object to edit", &[Char('o')], Action::NextObject),
    bind(
        "p P",
        "bump: pattern or image",
        &[Char('p')],
        Action::NextPattern,
    ),
    bind("", "", &[Char('P')], Action::PreviousPattern),
    bind(
        "t T",
        "texture: pattern or image",
        &[Char('t')],
        Action::NextTexture,
    ),
    bind("", "", &[Char('T')], Action::PreviousTexture),
    bind(
        "b B",
        "bump stronger / weaker",
        &[Char('b')],
        Action::ScaleBump(1.25),
    ),
    bind("", "", &[Char('B')], Action::ScaleBump(0.8)),
    bind(
        "i D",
        "invert bump; displace by it",
        &[Char('i')],
        Action::InvertBump,
    ),
    bind("", "", &[Char('D')], Action::ToggleDisplacement),
    bind(
        "[ ]",
        "previous / next parameter",
        &[Char('[')],
        Action::SelectParam(-1),
    ),
    bind("", "", &[Char(']')], Action::SelectParam(1)),
    bind(
        ", .",
        "parameter down / up",
        &[Char(',')],
        Action::AdjustParam(-1.0),
    ),
    bind("", "", &[Char('.')], Action::AdjustParam(1.0)),
    bind(
        "< >",
        "parameter down / up ×10",
        &[Char('<')],
        Action::AdjustParam(-10.0),
    ),
    bind("", "", &[Char('>')], Action::AdjustParam(10.0)),
    bind("m", "parameter panel", &[Char('m')], Action::TogglePanel),
    bind(
        "Space",
        "pause / run animation",
        &[Char(' ')],
        Action::TogglePause,
    ),
    bind(
        "n",
        "step animation one frame",
        &[Char('n')],
        Action::StepClock,
    ),
    bind(
        "Q",
        "next quality preset",
        &[Char('Q')],
        Action::NextQuality,
    ),
    bind("g", "glyphs, then pixels", &[Char('g')], Action::NextGlyphs),
    bind(
        "c",
        "colours: true 256 16 none",
        &[Char('c')],
        Action::NextColors,
    ),
    bind(
        "x",
        "drop live values",
        &[Char('x')],
        Action::DropLiveValues,
    ),
    bind("e", "export the view to PNG", &[Char('e')], Action::Export),
    bind(
        "s",
        "save the view as a scene",
        &[Char('s')],
        Action::SaveScene,
    ),
    bind("M", "message log", &[Char('M')], Action::ToggleLog),
    bind("? F1", "this help", &[Char('?'), F(1)], Action::ToggleHelp),
    bind("Esc", "close the box on top", &[Esc], Action::Back),
    bind("q", "quit", &[Char('q')], Action::Quit),
];

/// What the help lists beside the bindings: keys read before the key map, and the keys of the
/// overlays (which take them first while open).
const MORE_HELP: &[(&str, &str)] = &[
    ("C-c", "quit at once"),
    ("C-z", "suspend (fg resumes)"),
    ("C-l", "draw everything again"),
    ("m: ↑ ↓", "select (mouse: click)"),
    ("m: ← →", "fine step (mouse: wheel)"),
    ("m: Enter", "type a value"),
    ("/: type", "filter; ↑ ↓ Enter go"),
    ("M: ↑ ↓", "scroll the log"),
];

const fn bind(
    keys: &'static str,
    description: &'static str,
    codes: &'static [KeyCode],
    action: Action,
) -> Binding {
    Binding {
        keys,
        description,
        codes,
        action,
    }
}

/// The action for a key press (repeats count; releases do not).
pub fn action_for(key: &KeyEvent) -> Option<Action> {
    if key.kind == KeyEventKind::Release {
        return None;
    }
    if crate::term::is_ctrl_c(key) {
        return Some(Action::QuitNow);
    }
    if key
        .modifiers
        .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT)
    {
        return None;
    }
    BINDINGS
        .iter()
        .find(|b| b.codes.contains(&key.code))
        .map(|b| b.action)
}

/// What the help lists, keys and words: the bindings with a label (the unlabeled ones share the
/// line above), then the keys outside the key map.
pub fn help_entries() -> impl Iterator<Item = (&'static str, &'static str)> {
    let bound = BINDINGS.iter().filter(|b| !b.keys.is_empty());
    (bound.map(|b| (b.keys, b.description))).chain(MORE_HELP.iter().copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn press(code: KeyCode) -> Option<Action> {
        action_for(&KeyEvent::new(code, KeyModifiers::NONE))
    }

    #[test]
    fn tab_is_next_scene_and_q_quits() {
        assert_eq!(press(Tab), Some(Action::NextScene));
        assert_eq!(press(Char('q')), Some(Action::Quit));
        let ctrl_c = KeyEvent::new(Char('c'), KeyModifiers::CONTROL);
        assert_eq!(action_for(&ctrl_c), Some(Action::QuitNow));
    }

    #[test]
    fn no_key_is_bound_twice() {
        let mut seen = std::collections::HashSet::new();
        for code in BINDINGS.iter().flat_map(|b| b.codes) {
            assert!(seen.insert(*code), "{code:?} bound twice");
        }
    }

    #[test]
    fn shift_letters_arrive_as_capitals() {
        // Terminals send Shift+l as 'L' with the SHIFT modifier: it must still match.
        let key = KeyEvent::new(Char('L'), KeyModifiers::SHIFT);
        assert_eq!(action_for(&key), Some(Action::Pan(PAN_STEP, 0.0)));
    }
}
