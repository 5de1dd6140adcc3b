//! What the workbench keeps of a scene while another is shown, so Tab, Shift-Tab and the picker
//! come back to it as it was left: camera, lights, materials with their live values, the edited
//! object and parameter, the quality, and its files' watcher (whose news wait for its return).

use super::image_shelf::ImageShelf;
use super::orbit::Orbit;
use crate::quality::Preset;
use crate::quality::Quality;
use crate::scene::PreparedScene;
use crate::watch::Reloader;

pub struct KeptScene {
    pub prepared: PreparedScene,
    pub orbit: Orbit,
    pub object: usize,
    pub param: usize,
    pub quality: Preset,
    pub quality_in_use: Quality,
    pub images: ImageShelf,
    pub reloader: Option<Reloader>,
}
