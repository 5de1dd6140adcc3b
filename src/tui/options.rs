//! How the workbench was asked to start.

use crate::overrides::Override;
use crate::quality::Preset;
use crate::scene::MaterialChoice;
use crate::term::graphics::GraphicsChoice;
use crate::term::{ColorChoice, GlyphSet};
use std::path::PathBuf;

#[derive(Clone, Debug)]
pub struct WorkbenchOptions {
    /// Built-in scene names or scene files; `Tab` moves through them.
    pub scenes: Vec<String>,
    pub colors: ColorChoice,
    pub glyphs: GlyphSet,
    /// Animation frame rate cap.
    pub fps: u32,
    pub mouse: bool,
    /// Pixel size of exported PNGs.
    pub export_size: (u32, u32),
    /// Samples per pixel of exported PNGs.
    pub export_samples: u32,
    /// Where `e` writes stills and `s` saves scenes.
    pub export_dir: PathBuf,
    /// Reload scene, pattern and image files when they change on disk.
    pub watch: bool,
    /// The quality preset to start with (`Q` cycles them).
    pub quality: Preset,
    /// A cell's size in pixels, width × height, for terminals that do not report it.
    pub cell_size: Option<(u32, u32)>,
    /// `--graphics`: real pixels where the terminal shows them, or blocks.
    pub graphics: GraphicsChoice,
    /// `--set` scene settings, applied to every scene shown that has them, at every load.
    pub settings: Vec<Override>,
    /// `--bump` and `--texture`, put on every object of every scene shown, at every load.
    pub choice: MaterialChoice,
}

impl Default for WorkbenchOptions {
    fn default() -> Self {
        WorkbenchOptions {
            scenes: crate::scene::PRESET_NAMES
                .iter()
                .map(|s| s.to_string())
                .collect(),
            colors: ColorChoice::Auto,
            glyphs: GlyphSet::HalfBlock,
            fps: 30,
            mouse: true,
            export_size: (1920, 1080),
            export_samples: 4,
            export_dir: PathBuf::from("."),
            watch: true,
            quality: Preset::default(),
            cell_size: None,
            graphics: GraphicsChoice::Auto,
            settings: Vec::new(),
            choice: MaterialChoice::default(),
        }
    }
}
