//! The edited object drawn displaced by its bump, or back as Blinn's bump on the unmoved
//! surface.

use super::App;
use crate::tui::status_message::Message;

impl App {
    /// Whether the edited object is drawn displaced by its bump.
    pub fn is_displaced(&self) -> bool {
        let object = self.prepared.objects.get(self.object);
        object.is_some_and(|o| matches!(o.surface, crate::surface::Surface::Displaced(_)))
    }

    /// Draws the edited object as the surface its bump height moves it to, or back as the
    /// unmoved surface with Blinn's bump; says which, or why it cannot be displaced.
    pub(super) fn toggle_displacement(&mut self) {
        let Some(object) = self.prepared.scene.objects.get_mut(self.object) else {
            return;
        };
        object.displace = !object.displace;
        let refused = match object.material.bump {
            None => Some("it has no bump to displace it by".to_string()),
            Some(_) => object.displacement_refused(),
        };
        let on = object.displace;
        self.reprepare(self.quality);
        self.tell(Message::Info(match (on, refused) {
            (true, Some(why)) => crate::term::sanitize(&why).into_owned(),
            (true, None) => "displaced by its bump".into(),
            (false, _) => "bump only (Blinn)".into(),
        }));
    }
}
