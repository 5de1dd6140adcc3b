//! A still streamed band by band into a sink of 8-bit sRGB rows: the one conversion from linear
//! light happens here, after the samples are resolved.

use super::bands::{BandBuffers, BandJob, band_rows};
use crate::raster::{FragmentShader, FrameStats, TILE_SIZE, linear_to_srgb8};
use rayon::prelude::*;

/// Where finished rows go (a PNG or PPM encoder): 3 bytes per pixel, top row first.
pub trait RowSink {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String>;
}

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
pub fn stream_still<S: FragmentShader>(
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
    let mut bytes = Vec::new();
    let mut stats = FrameStats::default();
    for start in (0..job.full.height).step_by(rows_per_band as usize) {
        let end = (start + rows_per_band).min(job.full.height);
        let band = job
            .render(start..end, &mut buffers, keep_going, &mut || {
                passes_done += 1.0;
                progress(passes_done / passes);
            })
            .ok_or(StillStop::Cancelled)?;
        stats.triangles = band.triangles;
        stats.fragments += band.fragments;
        stats.flattened += band.flattened;
        stats.rasterized_triangles += band.rasterized_triangles;
        // A tile's height of rows at a time: the 8-bit copy stays small and in cache.
        let rows = job.full.width as usize * TILE_SIZE as usize;
        for linear in buffers.resolved().chunks(rows) {
            to_srgb_bytes(linear, &mut bytes);
            sink.write_rows(&bytes).map_err(StillStop::Write)?;
        }
    }
    Ok(stats)
}

fn to_srgb_bytes(linear: &[glam::Vec3], bytes: &mut Vec<u8>) {
    bytes.resize(linear.len() * 3, 0);
    bytes
        .par_chunks_mut(3 * 4096)
        .zip(linear.par_chunks(4096))
        .for_each(|(out, pixels)| {
            for (o, p) in out.chunks_exact_mut(3).zip(pixels) {
                o.copy_from_slice(&p.to_array().map(linear_to_srgb8));
            }
        });
}
