//! Tab, Shift-Tab and the scene picker: each scene is kept as it was left and shown again so;
//! the first visit opens it fresh from its source.

use super::{App, Dirty, Message};
use crate::Error;
use crate::tui::kept_scene::KeptScene;
use crate::tui::orbit::Orbit;
use crate::tui::overlay::{OverlayKind, WorkbenchState};
use crate::tui::scene_setup::{dress, first_bumped_object, prepare, shelf_for};
use crate::watch::open_watched;

impl App {
    pub fn switch_scene(&mut self, step: i32) {
        let count = self.scenes.len() as i32;
        let index = (self.scene_index as i32 + step).rem_euclid(count) as usize;
        self.show_scene(index);
    }

    /// The scene at `index` of `pickable_scenes`, added to the scenes Tab goes through if it
    /// is a built-in not among them.
    pub(super) fn go_to_picked(&mut self, index: usize) {
        let Some(name) = self.pickable_scenes().into_iter().nth(index) else {
            return;
        };
        let index = match self.scenes.iter().position(|s| *s == name) {
            Some(index) => index,
            None => {
                self.scenes.push(name);
                self.kept.push(None);
                self.scenes.len() - 1
            }
        };
        self.show_scene(index);
    }

    /// Shows scene `index` as it was left, or fresh from its source the first time; the scene
    /// left is kept as it is.
    pub(super) fn show_scene(&mut self, index: usize) {
        if index == self.scene_index {
            return;
        }
        let next = match self.kept[index].take() {
            Some(kept) => kept,
            None => match self.open_fresh(index) {
                Ok(fresh) => fresh,
                Err(e) => return self.show_error(&e),
            },
        };
        let left = self.swap_in(next);
        self.kept[self.scene_index] = Some(left);
        self.scene_index = index;
        self.close(OverlayKind::Diagnostic);
        self.tell(Message::None);
        self.dirty = Dirty::ALL;
    }

    /// Scene `index` as its source gives it, with the `--set` settings.
    pub(super) fn open_fresh(&self, index: usize) -> Result<KeptScene, Error> {
        let (mut scene, reloader) = open_watched(&self.scenes[index], self.watch)?;
        dress(&self.settings, &self.choice, &mut scene)?;
        let (prepared, quality_in_use) = prepare(scene, self.quality, &self.settings)?;
        Ok(KeptScene {
            images: shelf_for(&prepared.scene, &self.scenes[index]),
            object: first_bumped_object(&prepared.scene),
            param: 0,
            orbit: Orbit::from_camera(&prepared.scene.camera),
            quality: self.quality,
            quality_in_use,
            reloader,
            prepared,
        })
    }

    /// Puts `next` on show; returns what was.
    pub(super) fn swap_in(&mut self, next: KeptScene) -> KeptScene {
        KeptScene {
            prepared: std::mem::replace(&mut self.prepared, next.prepared),
            orbit: std::mem::replace(&mut self.orbit, next.orbit),
            object: std::mem::replace(&mut self.object, next.object),
            param: std::mem::replace(&mut self.param, next.param),
            quality: std::mem::replace(&mut self.quality, next.quality),
            quality_in_use: std::mem::replace(&mut self.quality_in_use, next.quality_in_use),
            images: std::mem::replace(&mut self.images, next.images),
            reloader: std::mem::replace(&mut self.reloader, next.reloader),
        }
    }
}
