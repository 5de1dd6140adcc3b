//! `bumpwork sheet DIR`: a contact sheet of the stills in a directory, made after the shards that
//! rendered them have finished. Frames of a sequence know its length, so a frame missing from
//! the directory (a shard not yet run, or failed) is named, and no sheet is written until all
//! are there.

use bumpwork::Error;
use bumpwork::export::{ContactSheet, SheetLayout, SheetPicture, read_png_rgb8, read_png_text};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct SheetArgs {
    /// The directory of stills.
    directory: PathBuf,
    /// Where the sheet is written [default: DIR/contact-sheet.png].
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Size of each thumbnail, WIDTHxHEIGHT.
    #[arg(long, default_value = "240x180", value_parser = super::parse_size)]
    thumbnail: (u32, u32),
    /// Thumbnails across the sheet.
    #[arg(long, default_value_t = 7, value_parser = clap::value_parser!(u32).range(1..=64))]
    columns: u32,
}

/// The most stills one sheet takes.
const MAX_STILLS: usize = 10_000;
/// Missing frames named in the message, at most.
const NAMED: usize = 10;

/// A still found in the directory.
struct Found {
    path: PathBuf,
    /// Its place in a sequence: index (from 0) and length.
    frame: Option<(u64, u64)>,
}

pub fn run(args: SheetArgs) -> Result<(), Error> {
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| args.directory.join(super::gallery::SHEET_NAME));
    let stills = stills_in(&args.directory, &output)?;
    if stills.is_empty() {
        return Err(Error::InvalidArgument(format!(
            "{} holds no PNG stills",
            super::sanitized(&args.directory.display().to_string())
        )));
    }
    check_complete(&stills)?;
    let largest = stills.iter().try_fold((1, 1), |(w, h), found| {
        png_size(&found.path).map(|(fw, fh)| (w.max(fw), h.max(fh)))
    })?;
    let layout = SheetLayout {
        thumbnail: args.thumbnail,
        columns: args.columns,
    };
    let mut sheet =
        ContactSheet::new(stills.len(), layout, largest).map_err(Error::InvalidArgument)?;
    for (i, found) in stills.iter().enumerate() {
        let (width, height, rgb) = read_png_rgb8(&found.path)?;
        let label = found
            .path
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        sheet.place(
            i,
            &SheetPicture {
                label,
                width,
                height,
                rgb,
            },
        );
    }
    sheet.write(&output)?;
    super::write_line(format_args!(
        "{} stills in {}",
        stills.len(),
        super::sanitized(&output.display().to_string())
    ))
}

/// The PNG files of `directory` but the sheet itself and hidden files, by name.
fn stills_in(directory: &Path, sheet: &Path) -> Result<Vec<Found>, Error> {
    let entries = std::fs::read_dir(directory)
        .map_err(|e| Error::read(directory, bumpwork::bounded_read::io_words(&e)))?;
    let mut paths = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|e| Error::read(directory, e))?;
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        let png = name.to_ascii_lowercase().ends_with(".png");
        if png && !name.starts_with('.') && path != sheet && entry.path().is_file() {
            paths.push(path);
        }
        if paths.len() > MAX_STILLS {
            return Err(Error::InvalidArgument(format!(
                "{} holds over {MAX_STILLS} PNG files; a sheet takes at most that many",
                super::sanitized(&directory.display().to_string())
            )));
        }
    }
    paths.sort();
    paths
        .into_iter()
        .map(|path| {
            let frame = frame_of(&path)?;
            Ok(Found { path, frame })
        })
        .collect()
}

/// A still's `bumpwork-frame` text, `INDEX/COUNT`, if it has one that reads.
fn frame_of(path: &Path) -> Result<Option<(u64, u64)>, Error> {
    let texts = read_png_text(path)?;
    let text = texts
        .iter()
        .find(|(keyword, _)| keyword == bumpwork::export::metadata::FRAME);
    Ok(text.and_then(|(_, text)| {
        let (index, count) = text.split_once('/')?;
        let (index, count) = (index.parse().ok()?, count.parse().ok()?);
        (index < count).then_some((index, count))
    }))
}

/// An error naming the frames of each sequence that are not in the directory.
fn check_complete(stills: &[Found]) -> Result<(), Error> {
    let mut missing = Vec::new();
    let sequences: BTreeSet<(String, u64)> = stills
        .iter()
        .filter_map(|found| Some((sequence_stem(&found.path)?, found.frame?.1)))
        .collect();
    for (stem, count) in &sequences {
        let present: BTreeSet<u64> = stills
            .iter()
            .filter(|found| sequence_stem(&found.path).as_ref() == Some(stem))
            .filter_map(|found| found.frame.filter(|f| f.1 == *count).map(|f| f.0))
            .collect();
        let digits = (count - 1).to_string().len().max(4);
        missing.extend(
            (0..*count)
                .filter(|i| !present.contains(i))
                .map(|i| format!("{stem}-{i:0digits$}.png")),
        );
    }
    if missing.is_empty() {
        return Ok(());
    }
    let named: Vec<String> = missing
        .iter()
        .take(NAMED)
        .map(|m| super::sanitized(m))
        .collect();
    let more = match missing.len() > NAMED {
        true => format!(" and {} more", missing.len() - NAMED),
        false => String::new(),
    };
    Err(Error::InvalidArgument(format!(
        "{} frames are missing: {}{more}; render their shards, then make the sheet",
        missing.len(),
        named.join(", ")
    )))
}

/// `frame` of `frame-0007.png`: the name a sequence's frames share.
fn sequence_stem(path: &Path) -> Option<String> {
    let stem = path.file_stem()?.to_string_lossy().into_owned();
    let (name, number) = stem.rsplit_once('-')?;
    number
        .bytes()
        .all(|b| b.is_ascii_digit())
        .then(|| name.to_string())
}

/// A PNG's width and height, from its header.
fn png_size(path: &Path) -> Result<(u32, u32), Error> {
    let file = bumpwork::bounded_read::open_regular(path).map_err(|e| Error::read(path, e))?;
    let decoder = png::Decoder::new(std::io::BufReader::new(file));
    let reader = decoder
        .read_info()
        .map_err(|e| Error::read(path, format!("not a readable PNG: {e}")))?;
    let info = reader.info();
    Ok((info.width, info.height))
}
