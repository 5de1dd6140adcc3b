//! `bumpwork gallery`: every built-in scene (the seed's figures) as a still carrying its recipe,
//! and a contact sheet of them all.

use super::interrupt::Interrupt;
use super::progress::RenderProgress;
use super::shard::{Shard, parse_shard};
use bumpwork::Error;
use bumpwork::export::{
    ContactSheet, PreparedStill, SheetLayout, SheetPicture, StillFormat, StillPlace,
    check_destination, read_png_rgb8,
};
use bumpwork::overrides::{Override, apply_to_quality, apply_where_known};
use bumpwork::quality::Quality;
use bumpwork::shade::ShaderMode;
use bumpwork::still::{MAX_SAMPLES, ResolveFilter, StillSettings};
use std::path::{Path, PathBuf};

pub const SHEET_NAME: &str = "contact-sheet.png";

#[derive(clap::Args)]
pub struct GalleryArgs {
    /// The directory to write into (made if missing).
    #[arg(short, long)]
    output: PathBuf,
    /// Size of each still, WIDTHxHEIGHT.
    #[arg(long, default_value = "640x480", value_parser = super::parse_size)]
    size: (u32, u32),
    /// Samples per pixel of each still.
    #[arg(long, default_value_t = 4,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SAMPLES as i64))]
    samples: u32,
    /// Size of each thumbnail on the contact sheet, WIDTHxHEIGHT.
    #[arg(long, default_value = "240x180", value_parser = super::parse_size)]
    thumbnail: (u32, u32),
    /// Thumbnails across the contact sheet.
    #[arg(long, default_value_t = 7, value_parser = clap::value_parser!(u32).range(1..=64))]
    columns: u32,
    /// Only these built-in scenes, comma-separated [default: all].
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    /// A setting, KEY=VALUE (repeatable), as for `render --set`; a scene setting applies to the
    /// scenes that have it, and one no scene has is an error.
    #[arg(long = "set", value_name = "KEY=VALUE", value_parser = Override::parse)]
    set: Vec<Override>,
    /// Render only shard K of N of the scenes (K from 1): scenes K−1, K−1+N, … in gallery
    /// order, and no contact sheet; `bumpwork sheet DIR` makes it once every shard has run.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    shard: Option<Shard>,
}

/// The gallery's directory, made if missing; anything else of that name is refused.
pub(super) fn make_directory(directory: &Path) -> Result<(), Error> {
    if std::fs::metadata(directory).is_ok_and(|m| !m.is_dir()) {
        return Err(Error::write(
            directory,
            "it exists and is not a directory; -o names the directory to write into",
        ));
    }
    std::fs::create_dir_all(directory)
        .map_err(|e| Error::write(directory, bumpwork::bounded_read::io_words(&e)))
}

pub fn run(args: GalleryArgs) -> Result<(), Error> {
    let names = scene_names(&args.scenes)?;
    check_settings(&names, &args.set)?;
    if let Some(shard) = args.shard.filter(|shard| !shard.is_whole()) {
        return run_shard(&args, &names, shard);
    }
    let layout = SheetLayout {
        thumbnail: args.thumbnail,
        columns: args.columns,
    };
    let mut sheet =
        ContactSheet::new(names.len(), layout, args.size).map_err(Error::InvalidArgument)?;
    make_directory(&args.output)?;
    for name in &names {
        check_destination(&args.output.join(format!("{name}.png")))?;
    }
    let sheet_path = args.output.join(SHEET_NAME);
    check_destination(&sheet_path)?;
    let interrupt = Interrupt::watch();
    let mut progress = RenderProgress::new("gallery");
    for (i, name) in names.iter().enumerate() {
        let path = args.output.join(format!("{name}.png"));
        let mut report = |f: f64| progress.update((i as f64 + f) / names.len() as f64);
        let place = (i as u64, names.len() as u64);
        render_scene(name, &args, (&path, place), &mut report, &interrupt)?;
        let (width, height, rgb) = read_png_rgb8(&path)?;
        let picture = SheetPicture {
            label: name.clone(),
            width,
            height,
            rgb,
        };
        sheet.place(i, &picture);
    }
    progress.finish();
    sheet.write(&sheet_path)?;
    say!(
        "{} stills and {} in {}",
        names.len(),
        SHEET_NAME,
        super::sanitized(&args.output.display().to_string())
    );
    Ok(())
}

/// Every `--set` is valid for the gallery: its quality knobs, and each scene setting taken by at
/// least one of the scenes.
fn check_settings(names: &[String], settings: &[Override]) -> Result<(), Error> {
    apply_to_quality(settings, Quality::interactive()).map_err(Error::InvalidArgument)?;
    let mut taken = vec![false; settings.len()];
    for name in names {
        let mut scene = bumpwork::scene::load_source(name)?;
        let here = apply_where_known(settings, &mut scene).map_err(Error::InvalidArgument)?;
        taken.iter_mut().zip(here).for_each(|(t, h)| *t |= h);
    }
    match settings
        .iter()
        .zip(&taken)
        .find(|(o, taken)| o.is_binding() && !**taken)
    {
        Some((o, _)) => Err(Error::InvalidArgument(format!(
            "--set {}: no scene of the gallery has that parameter",
            o.shown()
        ))),
        None => Ok(()),
    }
}

fn scene_names(asked: &[String]) -> Result<Vec<String>, Error> {
    if asked.is_empty() {
        return Ok(bumpwork::scene::PRESET_NAMES
            .iter()
            .map(|s| s.to_string())
            .collect());
    }
    asked
        .iter()
        .map(|name| match bumpwork::scene::preset(name) {
            Some(_) => Ok(name.clone()),
            None => Err(Error::UnknownScene {
                name: name.clone(),
                suggestion: None,
            }),
        })
        .collect()
}

/// `--shard K/N`: this shard's scenes, each still keeping its place in the gallery for `sheet`.
fn run_shard(args: &GalleryArgs, names: &[String], shard: Shard) -> Result<(), Error> {
    make_directory(&args.output)?;
    let mine: Vec<(usize, &String)> = (names.iter().enumerate())
        .filter(|&(i, _)| shard.takes(i as u64))
        .collect();
    for (_, name) in &mine {
        check_destination(&args.output.join(format!("{name}.png")))?;
    }
    let interrupt = Interrupt::watch();
    let mut progress = RenderProgress::new("gallery");
    for (done, &(i, name)) in mine.iter().enumerate() {
        let path = args.output.join(format!("{name}.png"));
        let mut report = |f: f64| progress.update((done as f64 + f) / mine.len() as f64);
        let place = (i as u64, names.len() as u64);
        render_scene(name, args, (&path, place), &mut report, &interrupt)?;
    }
    progress.finish();
    let directory = super::sanitized(&args.output.display().to_string());
    say!(
        "shard {}/{}: {} of the gallery's {} stills in {directory}; `bumpwork sheet {directory}` \
         makes the contact sheet once every shard has run",
        shard.index,
        shard.count,
        mine.len(),
        names.len()
    );
    Ok(())
}

/// Renders scene `name` into `path`, recording its `place` (index, count) in the gallery.
fn render_scene(
    name: &str,
    args: &GalleryArgs,
    (path, place): (&Path, (u64, u64)),
    progress: &mut dyn FnMut(f64),
    interrupt: &Interrupt,
) -> Result<(), Error> {
    let mut scene = bumpwork::scene::load_source(name)?;
    apply_where_known(&args.set, &mut scene).map_err(Error::InvalidArgument)?;
    let camera = scene.camera.clone();
    let quality = Quality {
        samples: args.samples,
        ..Quality::interactive()
    };
    let settings = StillSettings {
        size: args.size,
        quality: apply_to_quality(&args.set, quality).map_err(Error::InvalidArgument)?,
        resolve: ResolveFilter::default(),
        time: 0.0,
        mode: ShaderMode::Shaded,
    };
    let scene_text = bumpwork::scene::source_text(name)?;
    let prepared = PreparedStill::new((name, &scene_text), scene, &camera, &settings)?;
    let place = StillPlace {
        frame: Some(place),
        sweep: None,
    };
    let destination = (path, StillFormat::Png);
    let interrupted = || interrupt.received();
    prepared.write(settings, place, destination, progress, &interrupted)?;
    Ok(())
}
