//! A still rendered straight into a file: bands streamed into a PNG (carrying its recipe) or a
//! PPM, so memory is bounded by the band budget whatever the size.

use super::metadata::{FRAME, RECIPE, SCENE, SOFTWARE, SWEEP};
use super::{PngStill, PpmStill};
use crate::Error;
use crate::raster::{FrameStats, PreparedScene, Viewport};
use crate::scene::Camera;
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

/// What to render and what to record about it.
pub struct StillRequest<'a> {
    /// The scene as `settings.quality` prepares it for this camera and size.
    pub prepared: &'a PreparedScene,
    pub camera: &'a Camera,
    pub settings: StillSettings,
    /// The scene as text and the recipe, for the PNG's metadata.
    pub scene_text: &'a str,
    pub recipe: &'a Recipe,
    /// For a frame of a sequence: its index (from 0) and the sequence's length, kept in the
    /// PNG's `bumpwork-frame` text so `bumpwork sheet` can tell which frames are missing.
    pub frame: Option<(u64, u64)>,
    /// For a still of a sweep: its values (`sweep::values_text`), kept in the PNG's
    /// `bumpwork-sweep` text for the contact sheet's labels and the sweep's index.
    pub sweep: Option<&'a str>,
}

/// Renders `request` into `path`. `progress` hears the fraction done; `interrupted` is asked between
/// passes and, when it names a signal, the render stops and no file is left.
pub fn write_still(
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

/// Renders `request` into memory: its 8-bit sRGB rows, 3 bytes a pixel, top row first (an
/// animation's frame; the caller checks the memory). `path` names the file in messages.
pub fn render_rows(
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
    let mut shader = settings
        .quality
        .shader(request.prepared, request.camera, full);
    shader.mode = settings.mode;
    shader.time = settings.time;
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
