//! A still rendered straight into a file: bands streamed into a PNG (carrying its recipe) or a
//! PPM, so memory is bounded by the band budget whatever the size.

use super::metadata::{FRAME, RECIPE, SCENE, SOFTWARE, SWEEP};
use super::{PngStill, PpmStill};
use crate::Error;
use crate::raster::{FrameStats, Viewport};
use crate::scene::PreparedScene;
use crate::scene::{Camera, Scene};
use crate::shade::Showing;
use crate::still::{
    BAND_BUDGET_BYTES, BandJob, Recipe, RowSink, StillSettings, StillStop, stream_still,
};
use std::path::Path;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum StillFormat {
    /// PNG with the recipe in text chunks (`render --from` reads it back).
    #[default]
    Png,
    /// The seed's binary PPM (P6): pixels only.
    Ppm,
    /// A POV-Ray 3.7 scene of the same meshes, lights and camera, colours and bumps baked into
    /// image maps beside it (for rendering the same scene in POV-Ray).
    Pov,
    /// An animated PNG of a --time-range: every frame exact, the first frame's recipe in it.
    Apng,
    /// An animated GIF of a --time-range: a 256-colour palette per frame.
    Gif,
}

impl StillFormat {
    /// The animation file this format names, if it is one.
    pub fn animation(self) -> Option<super::AnimationFormat> {
        match self {
            StillFormat::Apng => Some(super::AnimationFormat::Apng),
            StillFormat::Gif => Some(super::AnimationFormat::Gif),
            StillFormat::Png | StillFormat::Ppm | StillFormat::Pov => None,
        }
    }
}

/// A scene prepared once for its stills (a still, the frames of a sequence, a sweep's still),
/// with what each still records of where it came from.
pub struct PreparedStill {
    /// The scene as the settings' quality prepares it for this camera and size.
    prepared: PreparedScene,
    camera: Camera,
    /// The scene's name or path, and its text, for each still's recipe.
    source: String,
    scene_text: String,
}

/// Which still of a set this is, kept in its PNG.
#[derive(Clone, Copy, Debug, Default)]
pub struct StillPlace<'a> {
    /// For a frame of a sequence: its index (from 0) and the sequence's length, kept in the
    /// PNG's `bumpwork-frame` text so `bumpwork sheet` can tell which frames are missing.
    pub frame: Option<(u64, u64)>,
    /// For a still of a sweep: its values (`sweep::values_text`), kept in the PNG's
    /// `bumpwork-sweep` text for the contact sheet's labels and the sweep's index.
    pub sweep: Option<&'a str>,
}

/// What writing a still has to tell: its statistics (none for a POV-Ray scene) and warnings.
#[derive(Debug, Default)]
pub struct StillWritten {
    pub stats: FrameStats,
    pub warnings: Vec<String>,
}

/// A still at one moment: the same prepared still, or one prepared again for that moment.
pub enum StillAt<'a> {
    Same(&'a PreparedStill),
    Again(Box<PreparedStill>),
}

impl std::ops::Deref for StillAt<'_> {
    type Target = PreparedStill;

    fn deref(&self) -> &PreparedStill {
        match self {
            StillAt::Same(still) => still,
            StillAt::Again(still) => still,
        }
    }
}

impl PreparedStill {
    /// Prepares `scene` from `source` (text `scene_text`) for stills seen by `camera` at the
    /// size and quality of `settings`, within the memory budget.
    pub fn new(
        (source, scene_text): (&str, &str),
        scene: Scene,
        camera: &Camera,
        settings: &StillSettings,
    ) -> Result<PreparedStill, Error> {
        Ok(PreparedStill {
            prepared: settings.prepare(scene, camera)?,
            camera: camera.clone(),
            source: source.to_string(),
            scene_text: scene_text.to_string(),
        })
    }

    /// This still at the moment `settings` shows: itself, or prepared again where a displaced
    /// object's bump moves with time (its shape is cut at the moment it shows).
    pub fn at(&self, settings: &StillSettings) -> Result<StillAt<'_>, Error> {
        let scene = self.scene();
        let moving_shape =
            (scene.objects.iter()).any(|o| o.displace && o.material.moves_with_time());
        if !moving_shape || scene.time == settings.time {
            return Ok(StillAt::Same(self));
        }
        let source = (self.source.as_str(), self.scene_text.as_str());
        let again = PreparedStill::new(source, scene.clone(), &self.camera, settings)?;
        Ok(StillAt::Again(Box::new(again)))
    }

    /// A scene prepared already (say at a tessellation of its own), seen by `camera`.
    pub fn from_prepared(
        (source, scene_text): (&str, &str),
        prepared: PreparedScene,
        camera: &Camera,
    ) -> PreparedStill {
        PreparedStill {
            prepared,
            camera: camera.clone(),
            source: source.to_string(),
            scene_text: scene_text.to_string(),
        }
    }

    /// The scene as prepared.
    pub fn scene(&self) -> &Scene {
        &self.prepared.scene
    }

    /// The scene with its meshes.
    pub fn prepared(&self) -> &PreparedScene {
        &self.prepared
    }

    /// The scene's text, as each still records it.
    pub fn scene_text(&self) -> &str {
        &self.scene_text
    }

    /// The recipe of a still with `settings`: what `render --from` makes again.
    pub fn recipe(&self, settings: &StillSettings) -> Recipe {
        Recipe::capture(&self.source, &self.prepared.scene, &self.camera, settings)
    }

    /// Renders a still with `settings` (its size the prepared one) into `path` as `format`.
    /// `progress` hears the fraction done; `interrupted` is asked between passes and, when it
    /// names a signal, the render stops and no file is left.
    pub fn write(
        &self,
        settings: StillSettings,
        place: StillPlace,
        (path, format): (&Path, StillFormat),
        progress: &mut dyn FnMut(f64),
        interrupted: &dyn Fn() -> Option<i32>,
    ) -> Result<StillWritten, Error> {
        if format == StillFormat::Pov {
            let (size, time) = (settings.size, settings.time);
            let warnings = super::write_pov(&self.prepared, &self.camera, size, time, path)?;
            return Ok(StillWritten {
                stats: FrameStats::default(),
                warnings,
            });
        }
        let recipe = self.recipe(&settings);
        let request = self.request(settings, &recipe, place);
        let stats = write_still(&request, path, format, progress, interrupted)?;
        Ok(StillWritten {
            stats,
            warnings: Vec::new(),
        })
    }

    /// Renders a still with `settings` into memory: its 8-bit sRGB rows, 3 bytes a pixel, top row
    /// first (an animation's frame; the caller checks the memory). `path` names the file in
    /// messages.
    pub fn rows(
        &self,
        settings: StillSettings,
        path: &Path,
        progress: &mut dyn FnMut(f64),
        interrupted: &dyn Fn() -> Option<i32>,
    ) -> Result<(FrameStats, Vec<u8>), Error> {
        let recipe = self.recipe(&settings);
        let request = self.request(settings, &recipe, StillPlace::default());
        render_rows(&request, path, progress, interrupted)
    }

    fn request<'a>(
        &'a self,
        settings: StillSettings,
        recipe: &'a Recipe,
        place: StillPlace<'a>,
    ) -> StillRequest<'a> {
        StillRequest {
            prepared: &self.prepared,
            camera: &self.camera,
            settings,
            scene_text: &self.scene_text,
            recipe,
            frame: place.frame,
            sweep: place.sweep,
        }
    }
}

/// What to render and what to record about it.
struct StillRequest<'a> {
    prepared: &'a PreparedScene,
    camera: &'a Camera,
    settings: StillSettings,
    scene_text: &'a str,
    recipe: &'a Recipe,
    frame: Option<(u64, u64)>,
    sweep: Option<&'a str>,
}

/// Renders `request` into `path`.
fn write_still(
    request: &StillRequest,
    path: &Path,
    format: StillFormat,
    progress: &mut dyn FnMut(f64),
    interrupted: &dyn Fn() -> Option<i32>,
) -> Result<FrameStats, Error> {
    let settings = &request.settings;
    let mut stream =
        |sink: &mut dyn RowSink| stream_into(request, sink, path, progress, interrupted);
    match format {
        StillFormat::Png => {
            let mut texts = vec![
                (SOFTWARE, request.recipe.program.clone()),
                (SCENE, request.scene_text.to_string()),
                (RECIPE, request.recipe.to_toml()),
            ];
            if let Some((index, count)) = request.frame {
                texts.push((FRAME, format!("{index}/{count}")));
            }
            if let Some(values) = request.sweep {
                texts.push((SWEEP, values.to_string()));
            }
            let mut png = PngStill::create(path, settings.size, &texts)?;
            let stats = stream(&mut png)?;
            png.finish()?;
            Ok(stats)
        }
        StillFormat::Pov | StillFormat::Apng | StillFormat::Gif => Err(Error::InvalidArgument(
            "a POV-Ray scene or an animation is not written as one still".into(),
        )),
        StillFormat::Ppm => {
            let mut ppm = PpmStill::create(path, settings.size)?;
            let stats = stream(&mut ppm)?;
            ppm.finish()?;
            Ok(stats)
        }
    }
}

/// Rows of 8-bit sRGB gathered in memory, for a frame of an animation.
struct RowsInMemory(Vec<u8>);

impl RowSink for RowsInMemory {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
        self.0.extend_from_slice(rgb);
        Ok(())
    }
}

/// Renders `request` into memory.
fn render_rows(
    request: &StillRequest,
    path: &Path,
    progress: &mut dyn FnMut(f64),
    interrupted: &dyn Fn() -> Option<i32>,
) -> Result<(FrameStats, Vec<u8>), Error> {
    let (width, height) = request.settings.size;
    let mut rows = RowsInMemory(Vec::with_capacity(3 * width as usize * height as usize));
    let stats = stream_into(request, &mut rows, path, progress, interrupted)?;
    Ok((stats, rows.0))
}

/// Renders `request` band by band into `sink`.
fn stream_into(
    request: &StillRequest,
    sink: &mut dyn RowSink,
    path: &Path,
    progress: &mut dyn FnMut(f64),
    interrupted: &dyn Fn() -> Option<i32>,
) -> Result<FrameStats, Error> {
    let settings = &request.settings;
    let full = Viewport {
        width: settings.size.0,
        height: settings.size.1,
    };
    let showing = Showing {
        mode: settings.mode,
        time: settings.time,
    };
    let shader = (settings.quality).shader_showing(request.prepared, request.camera, full, showing);
    let job = BandJob {
        prepared: request.prepared,
        camera: request.camera,
        full,
        shader: &shader,
        supersampling: settings.supersampling(),
        interpolation: settings.quality.interpolation,
        adaptive: settings.quality.adaptive_samples,
    };
    let keep_going = || interrupted().is_none();
    stream_still(&job, BAND_BUDGET_BYTES, sink, progress, &keep_going).map_err(|stop| match stop {
        StillStop::Cancelled => Error::Interrupted(interrupted().unwrap_or(2)),
        StillStop::Write(reason) => Error::write(path, reason),
    })
}
