//! The view on screen as a scene file of its own: the source scene's file with the camera, the
//! lights and every material value changed live written in, so the workbench's `s` keeps a
//! tweak that otherwise lives only in an exported still's recipe.

use super::recipe::{absolute_name, object_state, source_directory};
use crate::Error;
use crate::quality::Quality;
use crate::scene::Camera;
use crate::scene::{
    BindingFile, CameraFile, Direction, FieldOfView, LightFile, Point, Positive, Scene, SceneFile,
    SceneTime, written_table,
};
use std::path::Path;

/// The scene file that renders `scene` (as shown, from `source`) through `camera` at `quality`
/// and `time`. Its file names are absolute, so it can be saved anywhere.
pub fn saved_view(
    source: &str,
    scene: &Scene,
    camera: &Camera,
    quality: &Quality,
    time: f64,
) -> Result<SceneFile, Error> {
    let text = crate::scene::source_text(source)?;
    let mut file: SceneFile = toml::from_str(&text)
        .map_err(|e| Error::Diagnostic(format!("{source}: {}", e.message())))?;
    let base = source_directory(source);
    file.camera = camera_file(camera)?;
    file.lights = scene.lights.iter().map(LightFile::of).collect();
    file.shadows = (!scene.shadows).then_some(false);
    file.quality = written_table(toml::Table::try_from(quality).expect("a quality is a table"));
    file.time = Some(SceneTime::try_from(time).map_err(Error::InvalidArgument)?);
    for (written, shown) in file.objects.iter_mut().zip(&scene.objects) {
        let state = object_state(&shown.material, &base);
        written.bump = merged(written.bump.take(), state.bump, &base);
        written.texture = merged(written.texture.take(), state.texture, &base);
    }
    Ok(file)
}

/// The binding to write: the live pattern binding where there is one; else the file's (an image)
/// with the live strength and sign, its image named absolutely.
fn merged(
    in_file: Option<BindingFile>,
    live: Option<BindingFile>,
    base: &Path,
) -> Option<BindingFile> {
    match (in_file, live) {
        (_, Some(live)) if live.pattern.is_some() || live.image.is_some() => Some(live),
        (Some(mut image), live) => {
            image.image = image.image.map(|name| absolute_name(&name, base));
            if let Some(live) = live {
                image.strength = live.strength.or(image.strength);
                image.invert = live.invert.or(image.invert);
            }
            Some(image)
        }
        (None, live) => live,
    }
}

fn camera_file(camera: &Camera) -> Result<CameraFile, Error> {
    let refuse = |e: String| Error::InvalidArgument(format!("the camera: {e}"));
    Ok(CameraFile {
        eye: Point::try_from(camera.eye.to_array().to_vec()).map_err(refuse)?,
        target: Point::try_from(camera.target.to_array().to_vec()).map_err(refuse)?,
        up: Direction::try_from(camera.up.as_dvec3().to_array().to_vec()).map_err(refuse)?,
        fov: FieldOfView::try_from(f64::from(camera.vfov_degrees)).map_err(refuse)?,
        near: Some(Positive::try_from(f64::from(camera.near)).map_err(refuse)?),
        far: Some(Positive::try_from(f64::from(camera.far)).map_err(refuse)?),
    })
}
