//! What the overlays read of the workbench.

use super::App;
use crate::tui::material_controls::{ParamRow, param_rows};
use crate::tui::message_history::Log;
use crate::tui::overlay::{OverlayKind, WorkbenchState};

impl WorkbenchState for App {
    fn log(&self) -> &Log {
        &self.log
    }

    /// Those given, then every built-in not among them.
    fn pickable_scenes(&self) -> Vec<String> {
        let builtins = crate::scene::PRESET_NAMES.iter().map(|n| n.to_string());
        let mut names = self.scenes.clone();
        names.extend(builtins.filter(|n| !self.scenes.contains(n)));
        names
    }

    /// The pattern parameters of the edited object (the bump's, then the texture's).
    fn param_rows(&self) -> Vec<ParamRow> {
        self.material().map_or_else(Vec::new, param_rows)
    }

    /// The selected parameter's place in `param_rows`.
    fn param(&self) -> usize {
        self.param
    }

    /// The edited object as a person names it: its surface's kind, or the model's file name.
    fn object_name(&self) -> String {
        match self.scene().objects.get(self.object) {
            Some(object) => format!("{} {}", self.object + 1, object.surface.kind_name()),
            None => "no object".into(),
        }
    }

    fn is_open(&self, kind: OverlayKind) -> bool {
        self.overlays.iter().any(|o| o.kind() == kind)
    }
}
