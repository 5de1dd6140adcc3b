//! bumpwork: a CPU rasterizer and terminal workbench for Blinn bump maps and texture maps.

pub mod area_average;
pub mod bench;
pub mod bounded_read;
pub mod camera;
pub mod content_hash;
pub mod diagnostic;
mod error;
pub mod export;
mod huge_pages;
pub mod label_font;
pub mod measure;
pub mod memory_budget;
pub mod model;
pub mod overrides;
pub mod palette;
pub mod pattern;
pub mod quality;
pub mod raster;
pub mod reference;
pub mod render;
pub mod scene;
pub mod shade;
pub mod shadow;
pub mod simd;
pub mod still;
pub mod surface;
pub mod sweep;
pub mod term;
pub mod texture;
pub mod tui;
pub mod unfinished_files;
pub mod watch;

pub use error::Error;

/// The program and version, as stills and exported scenes record it.
pub const PROGRAM: &str = concat!("bumpwork ", env!("CARGO_PKG_VERSION"));

use std::path::Path;

/// Reads a UTF-8 text file of at most `limit` bytes (see [`bounded_read`]).
pub fn read_text_limited(path: &Path, limit: u64) -> Result<String, Error> {
    let bytes = bounded_read::read_bounded(path, limit).map_err(|e| Error::read(path, e))?;
    String::from_utf8(bytes).map_err(|e| {
        Error::read(
            path,
            format!(
                "expected UTF-8 text, found an invalid byte at byte {}",
                e.utf8_error().valid_up_to()
            ),
        )
    })
}
