//! bumpwork: a CPU rasterizer and terminal workbench for Blinn bump maps and texture maps.

pub mod bench;
pub mod diagnostic;
mod error;
pub mod export;
pub mod measure;
mod memory;
pub mod pattern;
pub mod quality;
pub mod raster;
pub mod reference;
pub mod scene;
pub mod shade;
mod simd;
pub mod still;
pub mod surface;
pub mod term;
pub mod texture;
pub mod tui;
pub mod watch;

pub use error::Error;

/// The program and version, as stills and exported scenes record it.
pub const PROGRAM: &str = concat!("bumpwork ", env!("CARGO_PKG_VERSION"));

use std::io::Read;
use std::path::Path;

/// Reads a UTF-8 text file, refusing it if it is larger than `limit` bytes (checked while reading,
/// so a file that grows or lies about its size cannot make us allocate more).
pub fn read_text_limited(path: &Path, limit: u64) -> Result<String, Error> {
    let file = std::fs::File::open(path).map_err(|e| Error::read(path, e))?;
    let mut text = String::new();
    file.take(limit + 1)
        .read_to_string(&mut text)
        .map_err(|e| Error::read(path, e))?;
    if text.len() as u64 > limit {
        return Err(Error::read(
            path,
            format!("larger than the limit of {limit} bytes"),
        ));
    }
    Ok(text)
}
