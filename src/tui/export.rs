//! The export key: the current view (camera, time, view mode and live pattern parameters) as a
//! still under a new name, rendered on a background thread through the same band pipeline as
//! `bumpwork render`, with its recipe, so `render --from` makes it again at any size.

use super::render::{View, empty_framebuffer, render_frame};
use super::view_mode::ViewMode;
use crate::Error;
use crate::export::{PreparedStill, StillFormat, StillPlace, write_png};
use crate::quality::Quality;
use crate::scene::Camera;
use crate::scene::Scene;
use crate::still::{ResolveFilter, StillSettings};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::mpsc::{Receiver, TryRecvError, channel};
use std::thread::JoinHandle;
use std::time::{SystemTime, UNIX_EPOCH};

/// What an export needs, owned, so it can render while the workbench goes on.
struct ExportOrder {
    source: String,
    scene: Scene,
    camera: Camera,
    mode: ViewMode,
    settings: StillSettings,
    path: PathBuf,
}

/// An export rendering in the background. Dropped while running (quit, panic), it is cancelled
/// and waited for, so its temporary file is removed and no partial file is left.
pub struct ExportJob {
    pub path: PathBuf,
    /// Whether the still carries a recipe (`render --from` can make it again).
    pub has_recipe: bool,
    cancel: Arc<AtomicBool>,
    /// Thousandths of the still written.
    progress: Arc<AtomicU32>,
    done: Receiver<Result<(), Error>>,
    thread: Option<JoinHandle<()>>,
}

impl ExportJob {
    /// Starts exporting `view` of the scene from `source` at `size` with `samples` into a new
    /// file in `dir`.
    pub fn start(
        source: &str,
        view: &View,
        (size, samples): ((u32, u32), u32),
        dir: &Path,
    ) -> ExportJob {
        let scene = &view.prepared.scene;
        let stem = format!("bumpwork-{}-{}", slug(&scene.name), view.mode.name());
        let order = ExportOrder {
            source: source.to_string(),
            scene: scene.clone(),
            camera: view.camera.clone(),
            mode: view.mode,
            settings: StillSettings {
                size,
                quality: Quality {
                    samples,
                    ..view.quality
                },
                resolve: ResolveFilter::default(),
                time: view.time,
                mode: view.mode.shader_mode(),
            },
            path: unique_path(dir, &stem, "png"),
        };
        let cancel = Arc::new(AtomicBool::new(false));
        let (sender, done) = channel();
        let path = order.path.clone();
        let has_recipe = carries_recipe(order.mode);
        let stop = Arc::clone(&cancel);
        let progress = Arc::new(AtomicU32::new(0));
        let written = Arc::clone(&progress);
        let thread = std::thread::spawn(move || {
            let _ = sender.send(export(order, &stop, &written));
        });
        ExportJob {
            path,
            has_recipe,
            cancel,
            progress,
            done,
            thread: Some(thread),
        }
    }

    /// How much of the still is written, in per cent.
    pub fn percent_done(&self) -> u32 {
        self.progress.load(Ordering::Relaxed) / 10
    }

    /// The outcome once the export has finished.
    pub fn finished(&mut self) -> Option<Result<(), Error>> {
        match self.done.try_recv() {
            Ok(result) => Some(result),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(Err(Error::write(
                &self.path,
                "the export stopped unexpectedly",
            ))),
        }
    }
}

impl Drop for ExportJob {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The wireframe is drawn over the picture and the error view is a heat map against the
/// reference, not shading: no recipe can make them again.
fn carries_recipe(mode: ViewMode) -> bool {
    !matches!(mode, ViewMode::Wireframe | ViewMode::Error)
}

fn export(order: ExportOrder, cancel: &AtomicBool, progress: &AtomicU32) -> Result<(), Error> {
    if !carries_recipe(order.mode) {
        return export_picture(order);
    }
    let scene_text = crate::scene::source_text(&order.source)?;
    let source = (order.source.as_str(), scene_text.as_str());
    let prepared = PreparedStill::new(source, order.scene, &order.camera, &order.settings)?;
    let interrupted = || cancel.load(Ordering::Relaxed).then_some(0);
    prepared.write(
        order.settings,
        StillPlace::default(),
        (&order.path, StillFormat::Png),
        &mut |done| progress.store((done.clamp(0.0, 1.0) * 1000.0) as u32, Ordering::Relaxed),
        &interrupted,
    )?;
    Ok(())
}

/// A view no recipe makes again (wireframe, error heat map), rendered whole at the export size.
fn export_picture(order: ExportOrder) -> Result<(), Error> {
    let (width, height) = order.settings.size;
    // A whole framebuffer, the error view's reference beside it, and the 8-bit rows.
    let pixels = u64::from(width) * u64::from(height);
    let output_bytes = pixels * (2 * crate::raster::Framebuffer::BYTES_PER_PIXEL + 3);
    let prepared = order
        .settings
        .prepare_with_output(order.scene, &order.camera, output_bytes)?;
    let shadows = crate::shadow::ShadowCache::default();
    let view = View {
        prepared: &prepared,
        camera: order.camera,
        mode: order.mode,
        time: order.settings.time,
        quality: order.settings.quality,
        shadows: &shadows,
        marked: None,
    };
    let mut framebuffer = empty_framebuffer();
    render_frame(&view, width, height, &mut framebuffer);
    write_png(&framebuffer, &order.path)
}

/// `dir/stem-SECONDS.png`, or with `-2`, `-3`… added if that exists: never overwrites a file.
pub(super) fn unique_path(dir: &Path, stem: &str, extension: &str) -> PathBuf {
    let seconds = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let base = format!("{stem}-{seconds}");
    (1..)
        .map(|n| match n {
            1 => dir.join(format!("{base}.{extension}")),
            n => dir.join(format!("{base}-{n}.{extension}")),
        })
        .find(|path| !path.exists())
        .expect("some suffix is free")
}

/// A scene name (which may come from a file) made safe for a file name.
pub(super) fn slug(name: &str) -> String {
    let slug: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .take(48)
        .collect();
    if slug.is_empty() {
        "scene".into()
    } else {
        slug
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_safe() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let dir = dir.path();
        let first = unique_path(dir, "a", "png");
        std::fs::write(&first, b"").unwrap();
        assert_ne!(unique_path(dir, "a", "png"), first);
        assert_eq!(slug("../x y\u{1b}"), "---x-y-");
    }
}
