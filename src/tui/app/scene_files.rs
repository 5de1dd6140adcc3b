//! The scene's files while the workbench shows it: reloads the watcher finds, the view saved as
//! a new scene file, and the file's own values again.

use super::{App, Message};
use crate::Error;
use crate::quality::Quality;
use crate::scene::Scene;
use crate::tui::diagnostic_box::DiagnosticBox;
use crate::tui::overlay::OverlayKind;
use crate::tui::scene_setup::{dress, prepare, shelf_for};
use crate::watch::ReloadOutcome;

impl App {
    /// Takes what the file watcher found: a changed scene replaces the shown one (keeping the
    /// camera, view, selection and live parameter values); a failed one keeps the last good view
    /// and shows the error.
    pub fn reload_if_changed(&mut self) {
        let Some(reloader) = &self.reloader else {
            return;
        };
        let outcomes: Vec<ReloadOutcome> = std::iter::from_fn(|| reloader.poll()).collect();
        for outcome in outcomes {
            self.dirty.text = true;
            match outcome {
                ReloadOutcome::Reloaded(reload) => {
                    let mut reload = reload;
                    if let Err(e) = dress(&self.settings, &self.choice, &mut reload.scene) {
                        self.show_error(&e);
                        continue;
                    }
                    let (scene, kept) = reload.keep_live_params_telling(&self.prepared.scene);
                    match prepare(scene, self.quality, &self.settings) {
                        Ok((prepared, quality)) => {
                            let source = &self.scenes[self.scene_index];
                            self.images = shelf_for(&prepared.scene, source);
                            self.prepared = prepared;
                            self.quality_in_use = quality;
                            let last = self.prepared.objects.len().saturating_sub(1);
                            self.object = self.object.min(last);
                            self.tell(Message::Info(reloaded_message(&kept)));
                            self.close(OverlayKind::Diagnostic);
                            self.dirty.picture = true;
                        }
                        Err(e) => self.show_error(&e),
                    }
                }
                ReloadOutcome::Failed(error) => {
                    self.tell(Message::Error(error.first_line().to_string()));
                    self.close(OverlayKind::Diagnostic);
                    let message = error.message;
                    self.overlays.push(Box::new(DiagnosticBox { message }));
                }
                ReloadOutcome::Unchanged => {}
            }
        }
    }

    /// Writes the view (camera, lights, live material values) as a new scene file beside the
    /// exports, never over an existing file.
    pub(super) fn save_scene(&mut self) {
        let source = &self.scenes[self.scene_index];
        let stem = format!("bumpwork-{}", crate::tui::export::slug(&self.scene().name));
        let path = crate::tui::export::unique_path(&self.export_dir, &stem, "toml");
        let exported = Quality {
            samples: self.export_samples,
            ..self.quality_in_use
        };
        let (scene, camera, time) = (&self.prepared.scene, self.camera(), self.clock.time());
        let saved = crate::still::saved_view(source, scene, &camera, &exported, time)
            .and_then(|file| write_new_file(&path, file.to_toml().as_bytes()));
        self.tell(match saved {
            Ok(()) => Message::Info(format!("saved the view as {}", path.display())),
            Err(e) => Message::Error(e.to_string()),
        });
    }

    /// The current scene as its source gives it, with the `--set` settings.
    pub(super) fn scene_as_saved(&self) -> Result<Scene, Error> {
        let mut scene = crate::scene::load_source(&self.scenes[self.scene_index])?;
        dress(&self.settings, &self.choice, &mut scene)?;
        Ok(scene)
    }

    /// The scene's materials as its source gives them; the lights and the camera stay.
    pub(super) fn drop_live_values(&mut self) {
        let fresh = self.scene_as_saved().and_then(|mut scene| {
            scene.lights = self.prepared.scene.lights.clone();
            prepare(scene, self.quality, &self.settings)
        });
        match fresh {
            Ok((prepared, quality)) => {
                self.prepared = prepared;
                self.quality_in_use = quality;
                self.object = self
                    .object
                    .min(self.prepared.objects.len().saturating_sub(1));
                self.tell(Message::Info("the file's values again".into()));
            }
            Err(e) => self.show_error(&e),
        }
    }
}

/// Writes `bytes` to `path` whole or not at all.
fn write_new_file(path: &std::path::Path, bytes: &[u8]) -> Result<(), Error> {
    use std::io::Write;
    let (output, mut file) = crate::export::OutputFile::create(path)?;
    file.write_all(bytes)
        .map_err(|e| Error::write(path, crate::bounded_read::io_words(&e)))?;
    output.commit()
}

/// "reloaded", and the live values that stayed over the file's new ones.
fn reloaded_message(kept: &[crate::watch::KeptValue]) -> String {
    if kept.is_empty() {
        return "reloaded".into();
    }
    let values: Vec<String> = kept
        .iter()
        .map(|k| format!("{}={:.3} (the file says {:.3})", k.param, k.live, k.file))
        .collect();
    format!(
        "reloaded; kept the live {}; x takes the file's values",
        values.join(", ")
    )
}
