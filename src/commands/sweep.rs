//! `bumpwork sweep`: a scene rendered at every combination of the values `--vary` gives its
//! settings, then a contact sheet labelled with the values and an index of the stills
//! (`sweep.json`). With `--shard K/N` only every N-th still is rendered, and `bumpwork sheet`
//! makes the sheet and index once every shard has run.

use super::interrupt::Interrupt;
use super::render::render_one;
use super::shard::{Shard, parse_shard};
use bumpwork::Error;
use bumpwork::export::{PreparedStill, StillFormat, StillPlace, StillStart, check_destination};
use bumpwork::overrides::{Override, apply_to_quality, apply_to_scene};
use bumpwork::quality::Quality;
use bumpwork::scene::Scene;
use bumpwork::shade::ShaderMode;
use bumpwork::still::{MAX_SAMPLES, ResolveFilter, StillSettings};
use bumpwork::sweep::{Axis, combination, count, values_text};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct SweepArgs {
    /// A built-in scene name, a scene file (.toml), a pattern file (.pat) or a model
    /// (.obj, .gltf, .glb; MODEL+PATTERN.pat puts the pattern on it).
    scene: String,
    /// A setting to vary, KEY=START..END:COUNT (COUNT values, both ends included) or
    /// KEY=A,B,C, with any key `--set` takes (repeatable: every combination is rendered, the
    /// last --vary changing fastest).
    #[arg(long, required = true, value_name = "KEY=VALUES", value_parser = Axis::parse)]
    vary: Vec<Axis>,
    /// The directory to write into (made if missing): sweep-0000.png, …, contact-sheet.png and
    /// sweep.json.
    #[arg(short, long)]
    output: PathBuf,
    /// Size of each still, WIDTHxHEIGHT.
    #[arg(long, default_value = "640x480", value_parser = super::parse_size)]
    size: (u32, u32),
    /// A quality preset: draft, interactive, high or exact [default: interactive].
    #[arg(long, value_parser = Quality::named)]
    quality: Option<Quality>,
    /// Samples per pixel [default: the quality's].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=MAX_SAMPLES as i64))]
    samples: Option<u32>,
    /// Scene time in seconds [default: the scene's].
    #[arg(long, allow_negative_numbers = true, value_parser = super::render::parse_time)]
    time: Option<f64>,
    /// A setting every still shares, KEY=VALUE (repeatable), as for `render --set`.
    #[arg(long = "set", value_name = "KEY=VALUE", value_parser = Override::parse)]
    set: Vec<Override>,
    /// Render only shard K of N (K from 1): stills K−1, K−1+N, …; then `bumpwork sheet DIR`
    /// once every shard has run.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
    /// Size of each thumbnail on the contact sheet, WIDTHxHEIGHT.
    #[arg(long, default_value = "240x180", value_parser = super::parse_size)]
    thumbnail: (u32, u32),
    /// Thumbnails across the contact sheet [default: the last --vary's count of values, at
    /// most 64].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=64))]
    columns: Option<u32>,
}

/// The name of still `index` of `count` in the sweep's directory.
fn still_path(directory: &Path, index: u64, count: u64) -> PathBuf {
    let digits = (count.max(1) - 1).to_string().len().max(4);
    directory.join(format!("sweep-{index:0digits$}.png"))
}

pub fn run(args: SweepArgs) -> Result<(), Error> {
    let total = count(&args.vary).map_err(Error::InvalidArgument)?;
    let start = StillStart::from_source(&args.scene)?;
    let quality = base_quality(&args, &start)?;
    let shard = args.shard.unwrap_or(Shard::WHOLE);
    let mine: Vec<u64> = (0..total).filter(|&i| shard.takes(i)).collect();
    for &index in &mine {
        sweep_still(&args, &start, quality, index)?;
    }
    super::gallery::make_directory(&args.output)?;
    if shard.is_whole() {
        check_destination(&args.output.join(super::gallery::SHEET_NAME))?;
    }
    let paths: Vec<PathBuf> = mine
        .iter()
        .map(|&i| still_path(&args.output, i, total))
        .collect();
    for path in &paths {
        check_destination(path)?;
    }
    let replaced = paths
        .iter()
        .filter(|p| p.symlink_metadata().is_ok())
        .count();
    let interrupt = Interrupt::watch();
    for (&index, path) in mine.iter().zip(&paths) {
        render_still(&args, &start, quality, (index, total), path, &interrupt)?;
    }
    if replaced > 0 {
        eprintln!(
            "bumpwork: {replaced} of the {} stills replaced files of the same names",
            paths.len()
        );
    }
    finish(&args, shard, mine.len(), total)
}

/// The quality before any `--set`: the preset (with the scene file's `[quality]` over it) and
/// `--samples`.
fn base_quality(args: &SweepArgs, start: &StillStart) -> Result<Quality, Error> {
    let mut quality = match args.quality {
        Some(preset) => preset
            .with_settings(&start.quality_table)
            .map_err(Error::Diagnostic)?,
        None => start.settings.quality,
    };
    if let Some(samples) = args.samples {
        quality.samples = samples;
    }
    Ok(quality)
}

/// One still of the sweep, ready to render.
struct SweepStill {
    scene: Scene,
    settings: StillSettings,
    /// Its `(key, value)` per `--vary`.
    values: Vec<(String, String)>,
}

/// Still `index`'s scene, settings and values, with `--set` and then its values applied; a
/// value no object takes, or a quality it makes invalid, is an error naming the `--vary`.
fn sweep_still(
    args: &SweepArgs,
    start: &StillStart,
    quality: Quality,
    index: u64,
) -> Result<SweepStill, Error> {
    let values = combination(&args.vary, index);
    let mut overrides = args.set.clone();
    for (key, value) in &values {
        overrides.push(Override::parse(&format!("{key}={value}")).map_err(Error::InvalidArgument)?);
    }
    let vary_error = |e: String| Error::InvalidArgument(e.replace("--set", "--vary"));
    let mut scene = start.scene.clone();
    apply_to_scene(&overrides, &mut scene).map_err(vary_error)?;
    let settings = StillSettings {
        size: args.size,
        quality: apply_to_quality(&overrides, quality).map_err(vary_error)?,
        resolve: ResolveFilter::default(),
        time: args.time.unwrap_or(start.settings.time),
        mode: ShaderMode::Shaded,
    };
    Ok(SweepStill {
        scene,
        settings,
        values,
    })
}

fn render_still(
    args: &SweepArgs,
    start: &StillStart,
    quality: Quality,
    (index, total): (u64, u64),
    path: &Path,
    interrupt: &Interrupt,
) -> Result<(), Error> {
    let SweepStill {
        scene,
        settings,
        values,
    } = sweep_still(args, start, quality, index)?;
    let camera = scene.camera.clone();
    let source = (start.source.as_str(), start.scene_text.as_str());
    let prepared = PreparedStill::new(source, scene, &camera, &settings)?;
    let values = values_text(&values);
    let place = StillPlace {
        frame: Some((index, total)),
        sweep: Some(&values),
    };
    render_one(
        &prepared,
        (settings, place),
        (path, StillFormat::Png),
        interrupt,
    )
}

/// The sheet and index once the whole sweep is rendered; a shard says what is left to do.
fn finish(args: &SweepArgs, shard: Shard, rendered: usize, total: u64) -> Result<(), Error> {
    let directory = super::sanitized(&args.output.display().to_string());
    if !shard.is_whole() {
        say!(
            "shard {}/{}: {rendered} of the sweep's {total} stills in {directory}; \
             `bumpwork sheet {directory}` makes the sheet and index once every shard has run",
            shard.index,
            shard.count
        );
        return Ok(());
    }
    let sheet = args.output.join(super::gallery::SHEET_NAME);
    let paths = (0..total)
        .map(|i| still_path(&args.output, i, total))
        .collect();
    let assembled =
        super::sheet::assemble_paths(&args.output, paths, &sheet, args.columns, args.thumbnail)?;
    say!(
        "{} stills, {} and {} in {directory}",
        assembled.stills,
        super::gallery::SHEET_NAME,
        super::sheet::SWEEP_INDEX
    );
    Ok(())
}
