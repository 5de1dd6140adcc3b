//! `bumpwork render`: a scene to a PNG (or PPM) still at any size, supersampled, in bands; again
//! from a still's own metadata with `--from`; or as a numbered sequence over a time range.

use super::interrupt::Interrupt;
use super::progress::RenderProgress;
use super::shard::{Shard, parse_shard};
use bumpwork::Error;
use bumpwork::diagnostic::sanitize_lines;
use bumpwork::export::metadata::{ANIMATION, RECIPE, SCENE, SOFTWARE};
use bumpwork::export::{
    AnimationFile, AnimationFormat, GIF_MAX_FPS, PreparedStill, STANDARD_OUTPUT, StillFormat,
    StillPlace, StillStart, check_destination,
};
use bumpwork::overrides::{Override, apply_to_quality, apply_to_scene};
use bumpwork::quality::Quality;
use bumpwork::scene::Camera;
use bumpwork::shade::ShaderMode;
use bumpwork::still::{MAX_DENSITY, MAX_SAMPLES, MAX_TIME_SECONDS, ResolveFilter, StillSettings};
use bumpwork::watch::ReloadOutcome;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct RenderArgs {
    /// A built-in scene name (see --list), a scene file (.toml), a pattern file (.pat) or a model
    /// (.obj, .gltf, .glb; MODEL+PATTERN.pat puts the pattern on it).
    #[arg(required_unless_present_any = ["list", "from"], conflicts_with = "from")]
    scene: Option<String>,
    /// The file to write.
    #[arg(short, long, required_unless_present = "list")]
    output: Option<PathBuf>,
    /// Render again what a still made by bumpwork was made from (its recipe); options given
    /// here override the recorded ones.
    #[arg(long, value_name = "STILL.png")]
    from: Option<PathBuf>,
    /// With --from: also read the pattern and image files the still names outside its own
    /// directory (a still may come from anyone, so by default only files beside it are read).
    #[arg(long, requires = "from")]
    read_outside: bool,
    /// Output size in pixels, WIDTHxHEIGHT [default: 800x600].
    #[arg(long, value_parser = super::parse_size)]
    size: Option<(u32, u32)>,
    /// A quality preset: draft, interactive, high or exact (tessellation, samples and shading
    /// knobs; `bumpwork bench` measures them) [default: interactive].
    #[arg(long, value_parser = Quality::named)]
    quality: Option<Quality>,
    /// Samples per pixel, spread over the pixel and resolved in linear light [default: the
    /// quality's, 1 for interactive].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_SAMPLES as i64))]
    samples: Option<u32>,
    /// Adaptive supersampling: a pass at pixel centres, then every sample only where a pixel and
    /// a neighbour differ in coverage or by more than CONTRAST per channel of √colour (0.02 is
    /// within 1/255 of full supersampling on average); with the box filter, the four samples
    /// nearest the corners first, the rest where they moved the pixel by over 0.4 × CONTRAST
    /// [default: every pixel fully sampled].
    #[arg(long, value_name = "CONTRAST", value_parser = parse_contrast)]
    adaptive: Option<f32>,
    /// How samples are resolved [default: tent].
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(ResolveFilter::NAMES))]
    filter: Option<String>,
    /// Tessellation density: cells per half turn of a curved surface, fixed (no adaptive
    /// refinement) [default: the quality's, 64 for interactive].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_DENSITY as i64))]
    tessellation: Option<u32>,
    /// Scene time in seconds, for animated patterns and scrolling images [default: 0].
    #[arg(long, allow_negative_numbers = true, value_parser = parse_time)]
    time: Option<f64>,
    /// Render frames from START (inclusive) to END (exclusive) as OUTPUT-0000.png, …
    #[arg(long, value_name = "START..END", value_parser = parse_time_range, requires = "fps")]
    time_range: Option<(f64, f64)>,
    /// Frames per second of a --time-range sequence.
    #[arg(long, value_parser = parse_fps, requires = "time_range")]
    fps: Option<f64>,
    /// Render only shard K of N of a --time-range sequence (K from 1): frames K−1, K−1+N, …,
    /// named as without shards, so N runs on any scheduler together write the whole sequence.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, requires = "time_range")]
    shard: Option<Shard>,
    /// What the still shows [default: shaded].
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(mode_names()))]
    mode: Option<String>,
    /// File format, where the output's extension does not say (.png, .ppm, .pov) [default: png].
    #[arg(long, value_enum)]
    format: Option<StillFormat>,
    /// A setting, KEY=VALUE (repeatable): quality.KNOB (tessellation, samples, normal-form,
    /// gradient… as a still's recipe names them), [OBJECT.]bump.PARAM, [OBJECT.]texture.PARAM,
    /// [OBJECT.]bump.strength (the bump's factor), [OBJECT.]bump.params.PARAM (OBJECT counts
    /// from 1; without it, every object that has PARAM).
    #[arg(long = "set", value_name = "KEY=VALUE", value_parser = Override::parse)]
    set: Vec<Override>,
    /// The bump on every object: a shipped pattern or image by name, a pattern file (.pat) or
    /// an image file (grey, lighter is higher).
    #[arg(long, value_name = "NAME|FILE")]
    bump: Option<String>,
    /// The texture on every object: a shipped colour pattern or image by name, a colour pattern
    /// file or an image file.
    #[arg(long, value_name = "NAME|FILE")]
    texture: Option<String>,
    /// Where the camera is, X,Y,Z [default: the scene's].
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_point, allow_hyphen_values = true)]
    eye: Option<[f64; 3]>,
    /// What the camera looks at, X,Y,Z [default: the scene's].
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_point, allow_hyphen_values = true)]
    target: Option<[f64; 3]>,
    /// The camera's vertical field of view in degrees [default: the scene's].
    #[arg(long, value_name = "DEGREES")]
    fov: Option<f64>,
    /// Render again whenever the scene file, or a pattern or image it reads, changes (Ctrl-C
    /// stops); a change that does not load is reported and the last still kept.
    #[arg(long, conflicts_with_all = ["from", "time_range"])]
    watch: bool,
    /// Print the built-in scene names and exit.
    #[arg(long)]
    list: bool,
    /// Refuse to replace existing files: where any of the stills or frames to be written exists,
    /// say which before anything is rendered (without it, frames that replace files are counted).
    #[arg(long, conflicts_with = "watch")]
    no_clobber: bool,
}

/// Frames a sequence may have.
const MAX_FRAMES: u64 = 100_000;

pub fn run(args: RenderArgs) -> Result<(), Error> {
    if args.list {
        for name in bumpwork::scene::PRESET_NAMES {
            say!("{name}");
        }
        return Ok(());
    }
    let output = args.output.clone().expect("clap requires -o unless --list");
    let format = output_format(&output, args.format)?;
    check_outputs(&args, &output, format)?;
    let interrupt = Interrupt::watch();
    if args.watch {
        return watch_and_render(&args, &output, format, &interrupt);
    }
    let start = match &args.from {
        Some(still) => StillStart::from_still(still, args.read_outside)?,
        None => StillStart::from_source(args.scene.as_deref().expect("clap requires a scene"))?,
    };
    for warning in &start.warnings {
        eprintln!("bumpwork: warning: {}", sanitize_lines(warning));
    }
    render_start(&args, &start, &output, format, &interrupt)
}

impl RenderArgs {
    /// `--bump` and `--texture`.
    fn choice(&self) -> bumpwork::scene::MaterialChoice {
        bumpwork::scene::MaterialChoice {
            bump: self.bump.clone(),
            texture: self.texture.clone(),
        }
    }
}

/// Renders `start` with the command line's options and settings to `output` (each frame of a
/// sequence).
fn render_start(
    args: &RenderArgs,
    start: &StillStart,
    output: &Path,
    format: StillFormat,
    interrupt: &Interrupt,
) -> Result<(), Error> {
    let mut settings = override_settings(start, args)?;
    settings.quality =
        apply_to_quality(&args.set, settings.quality).map_err(Error::InvalidArgument)?;
    let mut scene = start.scene.clone();
    args.choice().apply(&mut scene)?;
    apply_to_scene(&args.set, &mut scene).map_err(Error::InvalidArgument)?;
    for warning in scene.displacement_warnings() {
        eprintln!("bumpwork: warning: {}", sanitize_lines(&warning));
    }
    scene.camera = camera_from_options(args, &scene.camera)?;
    let camera = scene.camera.clone();
    let frames = frames(args, settings.time, output)?;
    if frames.is_empty() {
        // Only a shard past the sequence's length has none; a scheduler's run of it succeeds.
        eprintln!("bumpwork: this shard has none of the sequence's frames; nothing to render");
        return Ok(());
    }
    let source = (start.source.as_str(), start.scene_text.as_str());
    let prepared = PreparedStill::new(source, scene, &camera, &settings)?;
    for notice in &prepared.prepared().notices {
        eprintln!("bumpwork: warning: {}", sanitize_lines(notice));
    }
    if args.time_range.is_some() {
        warn_if_still(prepared.scene(), frames.len());
    }
    if let Some(animation) = format.animation() {
        let destination = (output, animation);
        return render_animation(args, &prepared, (&frames, settings), destination, interrupt);
    }
    let existing = existing_files(&frames, args.no_clobber)?;
    for frame in &frames {
        let settings = StillSettings {
            time: frame.time,
            ..settings
        };
        let place = StillPlace {
            frame: frame.place,
            sweep: None,
        };
        render_one(
            &*prepared.at(&settings)?,
            (settings, place),
            (&frame.path, format),
            interrupt,
        )?;
    }
    if frames.len() > 1 && existing > 0 {
        eprintln!(
            "bumpwork: {existing} of the {} frames replaced files of the same names \
             (--no-clobber refuses to)",
            frames.len()
        );
    }
    Ok(())
}

/// The frames of `frames` as one animation file: each rendered into memory and added as it is
/// finished, the first frame's recipe and the sequence's times in the file.
fn render_animation(
    args: &RenderArgs,
    prepared: &PreparedStill,
    (frames, settings): (&[Frame], StillSettings),
    (output, format): (&Path, AnimationFormat),
    interrupt: &Interrupt,
) -> Result<(), Error> {
    if args.no_clobber && output.symlink_metadata().is_ok() {
        return Err(Error::InvalidArgument(format!(
            "--no-clobber: {} exists; nothing was rendered",
            super::sanitized(&output.display().to_string())
        )));
    }
    let fps = args.fps.expect("checked: an animation has a time range");
    let at = |time| StillSettings { time, ..settings };
    let first = prepared.recipe(&at(frames[0].time));
    let (time_start, time_end) = args.time_range.expect("checked");
    let texts = [
        (SOFTWARE, first.program.clone()),
        (SCENE, prepared.scene_text().to_string()),
        (RECIPE, first.to_toml()),
        (
            ANIMATION,
            format!(
                "time-range = {time_start}..{time_end}, fps = {fps}, frames = {}",
                frames.len()
            ),
        ),
    ];
    let shape = (settings.size, frames.len() as u32, fps);
    let mut file = AnimationFile::create(output, format, shape, &texts)?;
    let mut progress = RenderProgress::new(&output.display().to_string());
    let mut flattened = 0;
    for (i, frame) in frames.iter().enumerate() {
        let mut report = |f: f64| progress.update((i as f64 + f) / frames.len() as f64);
        let interrupted = || interrupt.received();
        let settings = at(frame.time);
        let prepared = prepared.at(&settings)?;
        let (stats, rgb) = prepared.rows(settings, output, &mut report, &interrupted)?;
        flattened += stats.flattened;
        file.add_frame(&rgb)?;
    }
    progress.finish();
    file.finish()?;
    if flattened > 0 {
        eprintln!(
            "bumpwork: warning: {flattened} fragments had no finite bump or colour value and were drawn flat"
        );
    }
    Ok(())
}

/// Says, before any frame is written, when every frame of a sequence will be the same picture.
fn warn_if_still(scene: &bumpwork::scene::Scene, frames: usize) {
    if frames > 1 && !scene.moves_with_time() {
        eprintln!(
            "bumpwork: warning: all {frames} frames are the same picture: nothing in the scene \
             moves with time (no pattern moves with t at its parameter values, e.g. a speed of 0, \
             and no image scrolls)"
        );
    }
}

/// How many of the files `frames` are to be written to exist already; with `no_clobber`, an
/// error naming the first where any does.
fn existing_files(frames: &[Frame], no_clobber: bool) -> Result<usize, Error> {
    let existing: Vec<&Path> = frames
        .iter()
        .map(|frame| frame.path.as_path())
        .filter(|path| path.symlink_metadata().is_ok())
        .collect();
    match (no_clobber, existing.first()) {
        (true, Some(first)) => Err(Error::InvalidArgument(format!(
            "--no-clobber: {} exists{}; nothing was rendered",
            super::sanitized(&first.display().to_string()),
            match existing.len() {
                1 => String::new(),
                n => format!(
                    " (and {} more of the {} files to write)",
                    n - 1,
                    frames.len()
                ),
            }
        ))),
        _ => Ok(existing.len()),
    }
}

/// The scene's camera with `--eye`, `--target` and `--fov` applied, checked as a scene file's.
fn camera_from_options(args: &RenderArgs, camera: &Camera) -> Result<Camera, Error> {
    if args.eye.is_none() && args.target.is_none() && args.fov.is_none() {
        return Ok(camera.clone());
    }
    bumpwork::scene::camera_looking(
        args.eye.unwrap_or(camera.eye.to_array()),
        args.target.unwrap_or(camera.target.to_array()),
        camera.up.as_dvec3().to_array(),
        args.fov.unwrap_or(f64::from(camera.vfov_degrees)),
    )
    .map_err(|e| Error::InvalidArgument(format!("--eye, --target, --fov: {e}")))
}

/// `X,Y,Z`: three numbers (a command-line value parser).
fn parse_point(text: &str) -> Result<[f64; 3], String> {
    let numbers: Vec<f64> = text
        .split(',')
        .map(|part| part.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| {
            format!(
                "expected three numbers X,Y,Z, found '{}'",
                bumpwork::diagnostic::shown_input(text)
            )
        })?;
    numbers.try_into().map_err(|_| {
        format!(
            "expected three numbers X,Y,Z, found '{}'",
            bumpwork::diagnostic::shown_input(text)
        )
    })
}

/// How often `--watch` looks for a reload.
const WATCH_POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// `--watch`: renders, then renders again on every change of the files the scene reads, until
/// Ctrl-C (a quiet end while waiting; during a render it is an interruption as ever).
fn watch_and_render(
    args: &RenderArgs,
    output: &Path,
    format: StillFormat,
    interrupt: &Interrupt,
) -> Result<(), Error> {
    let name = args.scene.as_deref().expect("clap requires a scene");
    let (scene, reloader) = bumpwork::watch::open_watched(name, true)?;
    let Some(reloader) = reloader else {
        return Err(Error::InvalidArgument(format!(
            "--watch follows a scene or pattern file; the built-in scene '{}' never changes",
            super::sanitized(name)
        )));
    };
    render_start(
        args,
        &StillStart::of_scene(name, scene)?,
        output,
        format,
        interrupt,
    )?;
    let shown = super::sanitized(&output.display().to_string());
    eprintln!(
        "bumpwork: rendered {shown}; watching {} for changes (Ctrl-C stops)",
        super::sanitized(name)
    );
    while interrupt.received().is_none() {
        match reloader.poll() {
            Some(ReloadOutcome::Reloaded(reload)) => {
                let rendered = StillStart::of_scene(name, reload.scene)
                    .and_then(|start| render_start(args, &start, output, format, interrupt));
                match rendered {
                    Ok(()) => eprintln!("bumpwork: rendered {shown} again"),
                    Err(Error::Interrupted(signal)) => return Err(Error::Interrupted(signal)),
                    Err(e) => eprintln!("bumpwork: error: {}", sanitize_lines(&e.to_string())),
                }
            }
            Some(ReloadOutcome::Failed(error)) => {
                eprintln!("bumpwork: error: {}", sanitize_lines(&error.message));
                eprintln!("bumpwork: {shown} is kept until the next change loads");
            }
            Some(ReloadOutcome::Unchanged) | None => std::thread::sleep(WATCH_POLL),
        }
    }
    Ok(())
}

/// The format the output's extension names, checked against `--format`; `--format` (else PNG)
/// where the extension names none.
fn output_format(output: &Path, asked: Option<StillFormat>) -> Result<StillFormat, Error> {
    let extension = output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let named = match extension.as_deref() {
        Some("png") => Some(StillFormat::Png),
        Some("ppm") => Some(StillFormat::Ppm),
        Some("pov") => Some(StillFormat::Pov),
        Some("apng") => Some(StillFormat::Apng),
        Some("gif") => Some(StillFormat::Gif),
        Some("jpg" | "jpeg") => {
            return Err(Error::InvalidArgument(
                "stills are not written as JPEG: it would lose the picture's precision and its \
                 recipe; name a .png (or .ppm) file"
                    .into(),
            ));
        }
        _ => None,
    };
    match (named, asked) {
        (Some(named), Some(asked)) if named != asked => Err(Error::InvalidArgument(format!(
            "-o {} names a {} file but --format says {}; drop one of them",
            super::sanitized(&output.display().to_string()),
            format_name(named),
            format_name(asked)
        ))),
        (Some(format), _) | (None, Some(format)) => Ok(format),
        (None, None) => Ok(StillFormat::Png),
    }
}

fn format_name(format: StillFormat) -> &'static str {
    match format {
        StillFormat::Png => "png",
        StillFormat::Ppm => "ppm",
        StillFormat::Pov => "pov",
        StillFormat::Apng => "apng",
        StillFormat::Gif => "gif",
    }
}

/// Every file the render would write can be written, before any work is done.
fn check_outputs(args: &RenderArgs, output: &Path, format: StillFormat) -> Result<(), Error> {
    if let Some(animation) = format.animation() {
        return check_animation_output(args, output, animation);
    }
    if output.as_os_str() == STANDARD_OUTPUT {
        if args.time_range.is_some() {
            return Err(Error::InvalidArgument(
                "-o - writes one still; a --time-range sequence needs a file name to number".into(),
            ));
        }
        if format == StillFormat::Pov {
            return Err(Error::InvalidArgument(
                "-o - cannot take a POV-Ray scene: its image maps are written beside it".into(),
            ));
        }
        return check_destination(output);
    }
    refuse_to_overwrite_sources(output)?;
    for frame in frames(args, 0.0, output)? {
        check_destination(&frame.path)?;
    }
    Ok(())
}

/// An animation file needs a time range to fill it, is one file (so no shards), and a GIF's
/// frame times are whole hundredths.
fn check_animation_output(
    args: &RenderArgs,
    output: &Path,
    format: AnimationFormat,
) -> Result<(), Error> {
    let shown = super::sanitized(&output.display().to_string());
    if args.time_range.is_none() {
        return Err(Error::InvalidArgument(format!(
            "-o {shown} is an animation: give --time-range START..END and --fps (or name a .png \
             for a still)"
        )));
    }
    if args.shard.is_some() {
        return Err(Error::InvalidArgument(format!(
            "-o {shown} is one file, which shards cannot split: render numbered .png frames \
             with --shard instead"
        )));
    }
    if format == AnimationFormat::Gif && args.fps.is_some_and(|fps| fps > GIF_MAX_FPS) {
        return Err(Error::InvalidArgument(format!(
            "a GIF shows at most {GIF_MAX_FPS} frames a second (its frame times are whole \
             hundredths, and browsers slow shorter ones); lower --fps or write an .apng"
        )));
    }
    if output.as_os_str() != STANDARD_OUTPUT {
        refuse_to_overwrite_sources(output)?;
    }
    check_destination(output)
}

/// Pattern and scene files are the user's work: a still never replaces one, whatever `-o` says.
fn refuse_to_overwrite_sources(output: &Path) -> Result<(), Error> {
    let extension = output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if matches!(extension.as_deref(), Some("pat" | "toml")) {
        return Err(Error::InvalidArgument(format!(
            "refusing to write a still to {}: pattern (.pat) and scene (.toml) files are never \
             overwritten; name a .png, .ppm or .pov file",
            bumpwork::diagnostic::sanitize(&output.display().to_string())
        )));
    }
    Ok(())
}

/// The start's settings with the command line's options over them; a `--quality` preset takes
/// the scene file's `[quality]` settings over it, as the default preset does.
fn override_settings(start: &StillStart, args: &RenderArgs) -> Result<StillSettings, Error> {
    let base = start.settings;
    let mut quality = match args.quality {
        Some(preset) => preset
            .with_settings(&start.quality_table)
            .map_err(Error::Diagnostic)?,
        None => base.quality,
    };
    if let Some(samples) = args.samples {
        quality.samples = samples;
    }
    if let Some(contrast) = args.adaptive {
        quality.adaptive_samples = Some(contrast);
    }
    if let Some(density) = args.tessellation {
        quality.tessellation = density;
        quality.adaptive_tolerance_px = None;
    }
    Ok(StillSettings {
        size: args.size.unwrap_or(base.size),
        quality,
        resolve: args
            .filter
            .as_deref()
            .and_then(ResolveFilter::parse)
            .unwrap_or(base.resolve),
        time: args.time.unwrap_or(base.time),
        mode: args
            .mode
            .as_deref()
            .and_then(|m| ShaderMode::ALL.iter().copied().find(|v| v.name() == m))
            .unwrap_or(base.mode),
    })
}

/// One still to render: its scene time, its file and, in a sequence, its index and the
/// sequence's length.
struct Frame {
    time: f64,
    path: PathBuf,
    place: Option<(u64, u64)>,
}

/// Every still to render: one, or a numbered sequence over the time range (this shard's part).
fn frames(args: &RenderArgs, time: f64, output: &Path) -> Result<Vec<Frame>, Error> {
    let (Some((start, end)), Some(fps)) = (args.time_range, args.fps) else {
        let path = output.to_path_buf();
        return Ok(vec![Frame {
            time,
            path,
            place: None,
        }]);
    };
    let count = ((end - start) * fps).ceil();
    if !(count >= 1.0 && count <= MAX_FRAMES as f64) {
        return Err(Error::InvalidArgument(format!(
            "--time-range {start}..{end} at --fps {fps} gives {count} frames; expected 1..={MAX_FRAMES}"
        )));
    }
    let count = count as u64;
    let digits = (count - 1).to_string().len().max(4);
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    Ok((0..count)
        .filter(|&i| shard.takes(i))
        .map(|i| Frame {
            time: start + i as f64 / fps,
            path: numbered(output, i, digits),
            place: Some((i, count)),
        })
        .collect())
}

/// `out.png` → `out-0007.png`.
fn numbered(output: &Path, index: u64, digits: usize) -> PathBuf {
    let stem = output
        .file_stem()
        .map_or("frame".into(), |s| s.to_string_lossy().into_owned());
    let name = match output.extension() {
        Some(ext) => format!("{stem}-{index:0digits$}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{index:0digits$}"),
    };
    output.with_file_name(name)
}

/// Writes one still of `prepared` with a progress bar, and says what it has to warn of.
pub(super) fn render_one(
    prepared: &PreparedStill,
    (settings, place): (StillSettings, StillPlace),
    (path, format): (&Path, StillFormat),
    interrupt: &Interrupt,
) -> Result<(), Error> {
    let mut progress = RenderProgress::new(&path.display().to_string());
    let written = prepared.write(
        settings,
        place,
        (path, format),
        &mut |fraction| progress.update(fraction),
        &|| interrupt.received(),
    );
    progress.finish();
    let written = written?;
    for warning in written.warnings {
        eprintln!("bumpwork: warning: {}", sanitize_lines(&warning));
    }
    let stats = written.stats;
    if stats.flattened > 0 {
        eprintln!(
            "bumpwork: warning: {} of {} fragments had no finite bump or colour value and were drawn flat",
            stats.flattened, stats.fragments
        );
    }
    Ok(())
}

fn mode_names() -> Vec<&'static str> {
    ShaderMode::ALL.iter().map(|m| m.name()).collect()
}

pub(super) fn parse_time(text: &str) -> Result<f64, String> {
    let shown = || bumpwork::diagnostic::shown_input(text);
    let time = text
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|t| t.is_finite())
        .ok_or_else(|| format!("expected a time in seconds, got '{}'", shown()))?;
    match time.abs() <= MAX_TIME_SECONDS {
        true => Ok(time),
        false => Err(format!(
            "the time '{}' is past the longest, ±{MAX_TIME_SECONDS:e} seconds",
            shown()
        )),
    }
}

fn parse_fps(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|f| f.is_finite() && *f > 0.0 && *f <= 1000.0)
        .ok_or_else(|| {
            format!(
                "expected frames per second in (0, 1000], got '{}'",
                bumpwork::diagnostic::shown_input(text)
            )
        })
}

fn parse_time_range(text: &str) -> Result<(f64, f64), String> {
    let shown = || bumpwork::diagnostic::shown_input(text);
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| format!("expected START..END in seconds, got '{}'", shown()))?;
    let start = parse_time(a).map_err(|e| format!("START of '{}': {e}", shown()))?;
    let end = parse_time(b).map_err(|e| format!("END of '{}': {e}", shown()))?;
    match start < end {
        true => Ok((start, end)),
        false => Err(format!("expected START < END, got '{}'", shown())),
    }
}

fn parse_contrast(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(c) if (0.0..=1.0).contains(&c) => Ok(c),
        _ => Err(format!(
            "'{}' is not a contrast from 0 to 1",
            bumpwork::diagnostic::shown_input(text)
        )),
    }
}
