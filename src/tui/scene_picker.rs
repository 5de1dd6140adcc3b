//! The scene picker (`/`): the scenes given on the command line and every built-in, filtered as
//! you type (the letters in order, nearer together first), Enter to go, Esc to cancel.

use super::action::Action;
use super::overlay::{Overlay, OverlayKind, Reply, WorkbenchState};
use super::popup::{centered, draw_box};
use crate::term::sanitize;
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Modifier, Style};
use ratatui::text::Line;

/// Longest filter typed.
const MAX_QUERY: usize = 64;
/// The picker's widest, in cells.
const MAX_WIDTH: u16 = 60;

#[derive(Default)]
pub struct ScenePicker {
    query: String,
    /// The highlighted place in the filtered list.
    selected: usize,
}

impl Overlay for ScenePicker {
    fn kind(&self) -> OverlayKind {
        OverlayKind::Picker
    }

    fn key(&mut self, key: &KeyEvent, app: &dyn WorkbenchState) -> Reply {
        if crate::term::is_ctrl_c(key) {
            return Reply::Pass;
        }
        let found = matches(&app.pickable_scenes(), &self.query);
        match key.code {
            KeyCode::Esc => return Reply::Close,
            KeyCode::Enter => {
                return match found.get(self.selected) {
                    Some(&index) => Reply::CloseAnd(Action::GoToScene(index)),
                    None => Reply::Taken,
                };
            }
            KeyCode::Up => self.selected = self.selected.saturating_sub(1),
            KeyCode::Down => self.selected = (self.selected + 1).min(found.len().saturating_sub(1)),
            KeyCode::Backspace => {
                self.query.pop();
                self.selected = 0;
            }
            KeyCode::Char(c)
                if !key
                    .modifiers
                    .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT)
                    && self.query.len() < MAX_QUERY =>
            {
                self.query.push(c);
                self.selected = 0;
            }
            _ => {}
        }
        Reply::Taken
    }

    fn draw(&self, app: &dyn WorkbenchState, picture: Rect, style: Style, buffer: &mut Buffer) {
        let names = app.pickable_scenes();
        let found = matches(&names, &self.query);
        let height = (found.len() as u16 + 2).clamp(3, picture.height.max(3));
        let popup = centered(picture, MAX_WIDTH, height);
        let shown = popup.height.saturating_sub(2) as usize;
        let first = (self.selected + 1).saturating_sub(shown.max(1));
        let lines: Vec<Line> = match found.is_empty() {
            true => vec![Line::styled("no scene matches", style)],
            false => (found.iter().enumerate().skip(first))
                .map(|(place, &index)| {
                    let name = sanitize(&names[index]).into_owned();
                    match place == self.selected {
                        true => {
                            Line::styled(format!("▸ {name}"), style.add_modifier(Modifier::BOLD))
                        }
                        false => Line::styled(format!("  {name}"), style),
                    }
                })
                .collect(),
        };
        let title = format!(
            " scene: {}▏ {} of {} ",
            sanitize(&self.query),
            found.len(),
            names.len()
        );
        draw_box(popup, &title, lines, 0, style, buffer);
    }
}

/// The places in `names` that `query` picks, best first: names holding it whole, earliest
/// first, then names holding its letters in order, tightest first; case is ignored.
pub fn matches(names: &[String], query: &str) -> Vec<usize> {
    let query = query.to_lowercase();
    let mut scored: Vec<(usize, usize, usize)> = names
        .iter()
        .enumerate()
        .filter_map(|(index, name)| {
            let name = name.to_lowercase();
            match name.find(&query) {
                Some(at) => Some((0, at, index)),
                None => spread(&name, &query).map(|spread| (1, spread, index)),
            }
        })
        .collect();
    scored.sort();
    scored.into_iter().map(|(_, _, index)| index).collect()
}

/// How many characters of `name` the letters of `query` span, taken in order as early as they
/// come; `None` if they are not all there.
fn spread(name: &str, query: &str) -> Option<usize> {
    let mut letters = query.chars().peekable();
    let (mut first, mut last) = (None, 0);
    for (at, c) in name.chars().enumerate() {
        if letters.peek() == Some(&c) {
            letters.next();
            first.get_or_insert(at);
            last = at;
        }
    }
    match letters.peek() {
        None => Some(first.map_or(0, |first| last - first)),
        Some(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn whole_words_come_before_scattered_letters() {
        let list = names(&["cone-ripples", "plane-ripple", "sphere-on-plane", "cone"]);
        assert_eq!(matches(&list, "cone"), vec![0, 3]);
        assert_eq!(matches(&list, "CONE-R"), vec![0]);
        assert_eq!(matches(&list, "cr"), vec![0]);
        assert_eq!(matches(&list, "plane"), vec![1, 2]);
        assert_eq!(matches(&list, "pl"), vec![1, 0, 2], "earliest first");
        assert_eq!(matches(&list, ""), vec![0, 1, 2, 3]);
        assert!(matches(&list, "zz").is_empty());
    }
}
