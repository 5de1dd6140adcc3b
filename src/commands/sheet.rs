//! `bumpwork sheet DIR`: a contact sheet of the stills in a directory, made after the shards that
//! rendered them have finished. Frames of a sequence know its length, so a frame missing from
//! the directory (a shard not yet run, or failed) is named, and no sheet is written until all
//! are there. A sweep's stills are labelled with their values, and its index written.

use bumpwork::Error;
use bumpwork::export::{
    ContactSheet, SheetLayout, SheetPicture, metadata, read_png_rgb8, read_png_text,
};
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
    /// Thumbnails across the sheet [default: for a sweep, its last setting's count of values;
    /// else 7].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=64))]
    columns: Option<u32>,
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
    /// A sweep's still: the values it was rendered with.
    sweep: Option<Vec<(String, String)>>,
    /// The hash of its recipe, if it carries one.
    recipe: Option<String>,
}

/// What `assemble` made.
pub struct Assembled {
    pub stills: usize,
    /// Where the sweep's index went, if the stills are a sweep's.
    pub index: Option<PathBuf>,
}

pub fn run(args: SheetArgs) -> Result<(), Error> {
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| args.directory.join(super::gallery::SHEET_NAME));
    let assembled = assemble(&args.directory, &output, args.columns, args.thumbnail)?;
    say!(
        "{} stills in {}",
        assembled.stills,
        super::sanitized(&output.display().to_string())
    );
    if let Some(index) = assembled.index {
        say!(
            "the sweep's index in {}",
            super::sanitized(&index.display().to_string())
        );
    }
    Ok(())
}

/// The contact sheet of the stills in `directory`, written to `output` once every frame of
/// each sequence there is; for a sweep's stills, labelled with their values, and the sweep's
/// index written beside them as `sweep.json`.
pub fn assemble(
    directory: &Path,
    output: &Path,
    columns: Option<u32>,
    thumbnail: (u32, u32),
) -> Result<Assembled, Error> {
    assemble_stills(
        directory,
        stills_in(directory, output)?,
        output,
        columns,
        thumbnail,
    )
}

/// `assemble` of the stills `paths` alone.
pub fn assemble_paths(
    directory: &Path,
    paths: Vec<PathBuf>,
    output: &Path,
    columns: Option<u32>,
    thumbnail: (u32, u32),
) -> Result<Assembled, Error> {
    assemble_stills(directory, read_stills(paths)?, output, columns, thumbnail)
}

fn assemble_stills(
    directory: &Path,
    stills: Vec<Found>,
    output: &Path,
    columns: Option<u32>,
    thumbnail: (u32, u32),
) -> Result<Assembled, Error> {
    if stills.is_empty() {
        return Err(Error::InvalidArgument(format!(
            "{} holds no PNG stills",
            super::sanitized(&directory.display().to_string())
        )));
    }
    check_complete(&stills)?;
    let largest = stills.iter().try_fold((1, 1), |(w, h), found| {
        png_size(&found.path).map(|(fw, fh)| (w.max(fw), h.max(fh)))
    })?;
    let layout = SheetLayout {
        thumbnail,
        columns: columns.unwrap_or_else(|| default_columns(&stills)),
    };
    let mut sheet =
        ContactSheet::new(stills.len(), layout, largest).map_err(Error::InvalidArgument)?;
    for (i, found) in stills.iter().enumerate() {
        let (width, height, rgb) = read_png_rgb8(&found.path)?;
        let label = match &found.sweep {
            Some(values) => bumpwork::sweep::label(values),
            None => found
                .path
                .file_stem()
                .map_or_else(String::new, |s| s.to_string_lossy().into_owned()),
        };
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
    sheet.write(output)?;
    let index = write_sweep_index(directory, &stills)?;
    Ok(Assembled {
        stills: stills.len(),
        index,
    })
}

/// Thumbnails across a sheet: for a sweep, as many as its last setting has values (so rows
/// and columns are a table of the last two), else 7.
fn default_columns(stills: &[Found]) -> u32 {
    let last_values: BTreeSet<&str> = stills
        .iter()
        .filter_map(|found| found.sweep.as_ref()?.last())
        .map(|(_, value)| value.as_str())
        .collect();
    match last_values.len() {
        0 | 1 => 7,
        n => n.min(64) as u32,
    }
}

/// Where a sweep's index goes, beside its stills.
pub const SWEEP_INDEX: &str = "sweep.json";

/// `DIR/sweep.json`: every sweep still's file, values and recipe hash, if there are any.
fn write_sweep_index(directory: &Path, stills: &[Found]) -> Result<Option<PathBuf>, Error> {
    let entries: Vec<serde_json::Value> = stills
        .iter()
        .filter_map(|found| {
            let values = found.sweep.as_ref()?;
            let file = found.path.file_name()?.to_string_lossy().into_owned();
            let values: serde_json::Map<String, serde_json::Value> = values
                .iter()
                .map(|(key, value)| (key.clone(), json_value(value)))
                .collect();
            Some(serde_json::json!({
                "file": file,
                "values": values,
                "recipe": found.recipe,
            }))
        })
        .collect();
    if entries.is_empty() {
        return Ok(None);
    }
    let index = serde_json::json!({ "program": bumpwork::PROGRAM, "stills": entries });
    let path = directory.join(SWEEP_INDEX);
    let mut text = serde_json::to_string_pretty(&index).expect("JSON of strings and numbers");
    text.push('\n');
    bumpwork::export::write_whole(&path, text.as_bytes())?;
    Ok(Some(path))
}

/// A value as a JSON number where it is a finite one (`10`, `0.5`), else as text (`true`).
fn json_value(value: &str) -> serde_json::Value {
    if let Ok(whole) = value.parse::<i64>() {
        return whole.into();
    }
    value
        .parse::<f64>()
        .ok()
        .and_then(serde_json::Number::from_f64)
        .map_or_else(|| serde_json::Value::String(value.to_string()), Into::into)
}

/// The PNG files of `directory` but contact sheets (the one being made, and the default name's)
/// and hidden files, by name.
fn stills_in(directory: &Path, sheet: &Path) -> Result<Vec<Found>, Error> {
    let entries = std::fs::read_dir(directory)
        .map_err(|e| Error::read(directory, bumpwork::bounded_read::io_words(&e)))?;
    let mut paths = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|e| Error::read(directory, e))?;
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        let png = name.to_ascii_lowercase().ends_with(".png");
        let a_sheet = path == sheet || name == super::gallery::SHEET_NAME;
        if png && !name.starts_with('.') && !a_sheet && entry.path().is_file() {
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
    read_stills(paths)
}

/// What each still's text says of it, in the batch's order: by place in its sequence, sweep or
/// gallery where it has one, else by name.
fn read_stills(paths: Vec<PathBuf>) -> Result<Vec<Found>, Error> {
    let mut stills = paths
        .into_iter()
        .map(|path| {
            let texts = read_png_text(&path)?;
            Ok(Found {
                frame: frame_of(&texts),
                sweep: text(&texts, metadata::SWEEP).and_then(bumpwork::sweep::parse_values_text),
                recipe: text(&texts, metadata::RECIPE).map(bumpwork::still::recipe_hash),
                path,
            })
        })
        .collect::<Result<Vec<Found>, Error>>()?;
    stills.sort_by_key(|found| found.frame.map(|(index, _)| index));
    Ok(stills)
}

/// The text of a PNG's chunk `keyword`, if it has one.
fn text<'a>(texts: &'a [(String, String)], keyword: &str) -> Option<&'a str> {
    texts
        .iter()
        .find(|(k, _)| k == keyword)
        .map(|(_, text)| text.as_str())
}

/// A still's `bumpwork-frame` text, `INDEX/COUNT`, if it has one that reads.
fn frame_of(texts: &[(String, String)]) -> Option<(u64, u64)> {
    let (index, count) = text(texts, metadata::FRAME)?.split_once('/')?;
    let (index, count) = (index.parse().ok()?, count.parse().ok()?);
    (index < count).then_some((index, count))
}

/// An error naming the frames of each sequence that are not in the directory.
fn check_complete(stills: &[Found]) -> Result<(), Error> {
    let mut missing = Vec::new();
    // A gallery's stills are named after their scenes: one batch with no common stem.
    let batches: BTreeSet<(Option<String>, u64)> = stills
        .iter()
        .filter_map(|found| Some((sequence_stem(&found.path), found.frame?.1)))
        .collect();
    for (stem, count) in &batches {
        let present: BTreeSet<u64> = stills
            .iter()
            .filter(|found| sequence_stem(&found.path) == *stem)
            .filter_map(|found| found.frame.filter(|f| f.1 == *count).map(|f| f.0))
            .collect();
        let digits = (count - 1).to_string().len().max(4);
        missing.extend(
            (0..*count)
                .filter(|i| !present.contains(i))
                .map(|i| match stem {
                    Some(stem) => format!("{stem}-{i:0digits$}.png"),
                    None => format!("still {} of {count}", i + 1),
                }),
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
    let are = match missing.len() {
        1 => "frame is",
        _ => "frames are",
    };
    Err(Error::InvalidArgument(format!(
        "{} {are} missing: {}{more}; render their shards, then make the sheet",
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
