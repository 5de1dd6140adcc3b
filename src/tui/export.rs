//! The export key: the current view, camera and view mode included, as a PNG under a new name.

use super::app::App;
use super::render::{View, empty_framebuffer, render_frame};
use crate::Error;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

/// Renders the app's current view at `size` and writes it to a new file in `dir`; returns its path.
pub fn export_view(app: &App, size: (u32, u32), dir: &Path) -> Result<PathBuf, Error> {
    let view = View::of(app);
    let mut framebuffer = empty_framebuffer();
    render_frame(&view, size.0, size.1, &mut framebuffer);
    let stem = format!("bumpwork-{}-{}", slug(&app.scene().name), view.mode.name());
    let path = unique_path(dir, &stem);
    crate::export::write_png(&framebuffer, &path)?;
    Ok(path)
}

/// `dir/stem-SECONDS.png`, or with `-2`, `-3`… added if that exists: never overwrites a file.
fn unique_path(dir: &Path, stem: &str) -> PathBuf {
    let seconds = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let base = format!("{stem}-{seconds}");
    (1..)
        .map(|n| match n {
            1 => dir.join(format!("{base}.png")),
            n => dir.join(format!("{base}-{n}.png")),
        })
        .find(|path| !path.exists())
        .expect("some suffix is free")
}

/// A scene name (which may come from a file) made safe for a file name.
fn slug(name: &str) -> String {
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
        let dir = std::env::temp_dir().join(format!("bumpwork-export-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let first = unique_path(&dir, "a");
        std::fs::write(&first, b"").unwrap();
        assert_ne!(unique_path(&dir, "a"), first);
        assert_eq!(slug("../x y\u{1b}"), "---x-y-");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
