//! A still streamed band by band into a sink of 8-bit sRGB rows, which the render's last pass
//! hands on strip by strip (`FrameOutput::FramebufferAndStrips`, or `Strips` alone) once the
//! samples are resolved.

use super::bands::{BandBuffers, BandJob, band_rows};
use super::in_order::{InOrderWriter, SpareRows};
use super::row_sink::RowSink;
use crate::raster::{FrameStats, STRIP_ROWS, Srgb8Strips};
use crate::render::SceneShader;
use std::ops::Range;

/// Why a still stopped before its last row.
#[derive(Debug, PartialEq, Eq)]
pub enum StillStop {
    /// `keep_going` said no (Ctrl-C, SIGTERM…).
    Cancelled,
    /// The sink could not take the rows.
    Write(String),
}

/// Renders `job` band by band within `budget_bytes` of band memory, handing each band's rows to
/// `sink` and the fraction done (0 to 1, after every pass) to `progress`.
pub fn stream_still<S: SceneShader>(
    job: &BandJob<S>,
    budget_bytes: u64,
    sink: &mut dyn RowSink,
    progress: &mut dyn FnMut(f64),
    keep_going: &dyn Fn() -> bool,
) -> Result<FrameStats, StillStop> {
    let rows_per_band = band_rows(job.full.width, job.full.height, budget_bytes);
    let passes = job.full.height.div_ceil(rows_per_band) as f64 * job.passes_per_band() as f64;
    let mut passes_done = 0.0;
    let mut buffers = BandBuffers::default();
    let spare = SpareRows::default();
    let mut stats = FrameStats::default();
    for start in (0..job.full.height).step_by(rows_per_band as usize) {
        let end = (start + rows_per_band).min(job.full.height);
        let mut on_pass = || {
            passes_done += 1.0;
            progress(passes_done / passes);
        };
        let (band, written) = render_and_write(
            job,
            start..end,
            &mut buffers,
            &spare,
            sink,
            keep_going,
            &mut on_pass,
        );
        let band = band.ok_or(StillStop::Cancelled)?;
        written.map_err(StillStop::Write)?;
        stats.triangles = band.triangles;
        stats.fragments += band.fragments;
        stats.flattened += band.flattened;
        stats.rasterized_triangles += band.rasterized_triangles;
    }
    Ok(stats)
}

/// Renders one band, writing it to `sink` as it goes: the last pass converts each tile to 8-bit
/// sRGB as it finishes it (still in cache) and hands on each strip of `STRIP_ROWS` rows, which
/// the rendering threads write in order between strips (see `InOrderWriter`), so a PNG's
/// deflate (serial) runs within the render instead of after it. The band's render and the
/// writing's result.
fn render_and_write<S: SceneShader>(
    job: &BandJob<S>,
    rows: Range<u32>,
    buffers: &mut BandBuffers,
    spare: &SpareRows,
    sink: &mut dyn RowSink,
    keep_going: &dyn Fn() -> bool,
    on_pass: &mut dyn FnMut(),
) -> (Option<FrameStats>, Result<(), String>) {
    let strip_count = (rows.end - rows.start).div_ceil(STRIP_ROWS) as usize;
    let writer = InOrderWriter::new(sink, spare);
    let buffer = || writer.buffer();
    let finished = |strip: usize, bytes: Vec<u8>| writer.finished(strip, bytes);
    let srgb8 = Srgb8Strips {
        buffer: &buffer,
        finished: &finished,
    };
    let band = job.render(rows, buffers, keep_going, on_pass, Some(&srgb8));
    (band, writer.finish(strip_count))
}
