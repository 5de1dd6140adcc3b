//! How the workbench sets a scene up to be shown: the `--bump`, `--texture` and `--set` choices
//! put on it, checked for every scene before the terminal is taken, and the scene tessellated for
//! the preset's quality.

use super::image_shelf::ImageShelf;
use crate::Error;
use crate::overrides::{Override, apply_to_quality, apply_where_known};
use crate::quality::Preset;
use crate::quality::Quality;
use crate::raster::{Framebuffer, Viewport};
use crate::scene::PreparedScene;
use crate::scene::{MaterialChoice, Scene};

/// The picture size adaptive tessellation plans for: about a 160×50-cell terminal in half
/// blocks. The terminal's own size changes with every resize and the mesh is kept across them.
const PLANNED_VIEWPORT: Viewport = Viewport {
    width: 160,
    height: 100,
};

/// The quality to show `scene` at (`preset` with the scene file's `[quality]` settings and the
/// `--set` ones over it), and the scene tessellated for it, planning adaptive density for the
/// scene's own camera, within the memory budget (a terminal's picture is small beside it; the
/// plan counts a large one).
pub(super) fn prepare(
    scene: Scene,
    preset: Preset,
    settings: &[Override],
) -> Result<(PreparedScene, Quality), Error> {
    let quality = preset
        .quality()
        .with_settings(&scene.quality)
        .map_err(Error::Diagnostic)?;
    let quality = apply_to_quality(settings, quality).map_err(Error::InvalidArgument)?;
    let camera = scene.camera.clone();
    let output_bytes = PLANNED_OUTPUT_PIXELS * Framebuffer::BYTES_PER_PIXEL;
    let prepared = quality.prepare(scene, &camera, PLANNED_VIEWPORT, output_bytes)?;
    Ok((prepared, quality))
}

/// The images offered on `scene`, loaded from `source`.
pub(super) fn shelf_for(scene: &Scene, source: &str) -> ImageShelf {
    ImageShelf::of(scene, crate::still::source_directory(source))
}

/// Pixels of the largest picture a terminal is expected to show: 500×150 cells in sextants.
const PLANNED_OUTPUT_PIXELS: u64 = 1000 * 450;

/// Every scene opens, and every `--set` is one the workbench takes: quality knobs, and scene
/// settings each taken by at least one of the scenes.
pub(super) fn check_settings(
    scenes: &[String],
    settings: &[Override],
    choice: &MaterialChoice,
) -> Result<(), Error> {
    apply_to_quality(settings, Quality::interactive()).map_err(Error::InvalidArgument)?;
    let mut taken = vec![false; settings.len()];
    for name in scenes {
        let mut scene = crate::scene::load_source(name)?;
        choice.apply(&mut scene)?;
        (Quality::interactive().with_settings(&scene.quality)).map_err(Error::Diagnostic)?;
        let here = apply_where_known(settings, &mut scene).map_err(Error::InvalidArgument)?;
        taken.iter_mut().zip(here).for_each(|(t, h)| *t |= h);
    }
    let untaken = |(o, taken): &(&Override, &bool)| o.is_binding() && !**taken;
    match settings.iter().zip(&taken).find(untaken) {
        Some((o, _)) => Err(Error::InvalidArgument(format!(
            "--set {}: no scene shown has that parameter",
            o.shown()
        ))),
        None => Ok(()),
    }
}

/// `--bump` and `--texture`, then the scene settings `scene` has places for (checked at start:
/// the values are valid).
pub(super) fn dress(
    settings: &[Override],
    choice: &MaterialChoice,
    scene: &mut Scene,
) -> Result<(), Error> {
    choice.apply(scene)?;
    let _ = apply_where_known(settings, scene);
    Ok(())
}

/// The first object with a bump map, else the first: what the material keys start on.
pub(super) fn first_bumped_object(scene: &Scene) -> usize {
    scene
        .objects
        .iter()
        .position(|o| o.material.bump.is_some())
        .unwrap_or(0)
}
