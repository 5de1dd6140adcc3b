//! The text chunks a still carries, and reading them back from any PNG.

use crate::Error;
use std::io::{BufRead, BufReader, Seek};
use std::path::Path;

/// The program and version (a registered PNG keyword).
pub const SOFTWARE: &str = "Software";
/// The scene as the text of a scene file.
pub const SCENE: &str = "bumpwork-scene";
/// The recipe: source, settings, camera, live edits, file hashes (TOML).
pub const RECIPE: &str = "bumpwork-recipe";
/// A sequence frame's place in it, `INDEX/COUNT` (index from 0).
pub const FRAME: &str = "bumpwork-frame";
/// An animation's times: `time-range = START..END, fps = FPS, frames = COUNT`.
pub const ANIMATION: &str = "bumpwork-animation";
/// A sweep's still: the values it was rendered with, one `KEY=VALUE` a line.
pub const SWEEP: &str = "bumpwork-sweep";

/// The most text one chunk may hold once inflated: a scene file's limit, since the scene and
/// recipe chunks are scene-file text.
pub const MAX_CHUNK_TEXT_BYTES: usize = crate::scene::MAX_SCENE_FILE_BYTES as usize;

/// What the PNG decoder may allocate for the chunks before the image data.
const MAX_HEADER_BYTES: usize = 16 << 20;

/// A PNG's text chunks (tEXt, zTXt and iTXt) as (keyword, text), in file order by kind.
pub fn read_png_text(path: &Path) -> Result<Vec<(String, String)>, Error> {
    let file = crate::bounded_read::open_regular(path).map_err(|e| Error::read(path, e))?;
    png_text(BufReader::new(file), path)
}

/// The text chunks of a PNG read from `png`; `path` names it in messages. Compressed chunks are
/// inflated no further than [`MAX_CHUNK_TEXT_BYTES`], so a small crafted file cannot fill memory.
pub fn png_text(png: impl BufRead + Seek, path: &Path) -> Result<Vec<(String, String)>, Error> {
    let fail = |e: png::DecodingError| Error::read(path, format!("not a readable PNG: {e}"));
    let too_long = |keyword: &str| {
        Error::read(
            path,
            format!(
                "its '{}' text is longer than the limit of {} MiB",
                crate::diagnostic::sanitize(keyword),
                MAX_CHUNK_TEXT_BYTES >> 20
            ),
        )
    };
    let limits = png::Limits {
        bytes: MAX_HEADER_BYTES,
    };
    let mut decoder = png::Decoder::new_with_limits(png, limits);
    decoder.set_ignore_text_chunk(false);
    let reader = decoder.read_info().map_err(fail)?;
    let info = reader.info();
    let mut texts: Vec<(String, String)> = info
        .uncompressed_latin1_text
        .iter()
        .map(|c| (c.keyword.clone(), c.text.clone()))
        .collect();
    for chunk in &info.compressed_latin1_text {
        let mut chunk = chunk.clone();
        chunk
            .decompress_text_with_limit(MAX_CHUNK_TEXT_BYTES)
            .map_err(|_| too_long(&chunk.keyword))?;
        texts.push((chunk.keyword.clone(), chunk.get_text().map_err(fail)?));
    }
    for chunk in &info.utf8_text {
        let mut chunk = chunk.clone();
        chunk
            .decompress_text_with_limit(MAX_CHUNK_TEXT_BYTES)
            .map_err(|_| too_long(&chunk.keyword))?;
        texts.push((chunk.keyword.clone(), chunk.get_text().map_err(fail)?));
    }
    if let Some((keyword, _)) = texts.iter().find(|(_, t)| t.len() > MAX_CHUNK_TEXT_BYTES) {
        return Err(too_long(keyword));
    }
    Ok(texts)
}

/// The text of `keyword`, or a message saying the PNG is not a bumpwork still.
pub fn text_of<'a>(
    texts: &'a [(String, String)],
    keyword: &str,
    path: &Path,
) -> Result<&'a str, Error> {
    texts
        .iter()
        .find(|(k, _)| k == keyword)
        .map(|(_, t)| t.as_str())
        .ok_or_else(|| {
            Error::read(
                path,
                format!(
                    "no '{keyword}' text chunk: not a still bumpwork can make again \
                     (contact sheets and the workbench's wireframe and error views carry none)"
                ),
            )
        })
}
