//! A still streamed band by band into a sink of 8-bit sRGB rows: the one conversion from linear
//! light happens here, after the samples are resolved.

use super::bands::{BandBuffers, BandJob, band_rows};
use crate::raster::{FragmentShader, FrameStats, TILE_SIZE, encode_srgb8};
use glam::Vec3;

/// Where finished rows go (a PNG or PPM encoder): 3 bytes per pixel, top row first. `Send`, so
/// it can take one chunk of rows while the next is converted on another thread.
pub trait RowSink: Send {
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
    let mut bytes = [Vec::new(), Vec::new()];
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
        write_srgb(buffers.resolved(), rows, sink, &mut bytes).map_err(StillStop::Write)?;
    }
    Ok(stats)
}

/// Hands `linear` to `sink` as 8-bit sRGB, `pixels_per_write` pixels at a time. Each chunk is
/// converted while the sink takes the one before (a PNG's deflate is serial), on another thread
/// when rayon has one; `bytes` are the two chunks' buffers, reused.
fn write_srgb(
    linear: &[Vec3],
    pixels_per_write: usize,
    sink: &mut dyn RowSink,
    bytes: &mut [Vec<u8>; 2],
) -> Result<(), String> {
    let [ready, next] = bytes;
    let mut chunks = linear.chunks(pixels_per_write);
    let Some(first) = chunks.next() else {
        return Ok(());
    };
    to_srgb_bytes(first, ready);
    for chunk in chunks {
        let (written, ()) = rayon::join(|| sink.write_rows(ready), || to_srgb_bytes(chunk, next));
        written?;
        std::mem::swap(ready, next);
    }
    sink.write_rows(ready)
}

fn to_srgb_bytes(linear: &[Vec3], bytes: &mut Vec<u8>) {
    bytes.resize(linear.len() * 3, 0);
    encode_srgb8(bytemuck::cast_slice(linear), bytes);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::linear_to_srgb8;

    /// Rows as the sink received them, a write at a time; fails on write number `fail_at`.
    struct Writes {
        writes: Vec<Vec<u8>>,
        fail_at: Option<usize>,
    }

    impl RowSink for Writes {
        fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
            if self.fail_at == Some(self.writes.len()) {
                return Err("disk full".into());
            }
            self.writes.push(rgb.to_vec());
            Ok(())
        }
    }

    fn gradient(n: usize) -> Vec<Vec3> {
        let level = |i: usize, k: usize| ((i * k) % 1001) as f32 / 1000.0;
        (0..n)
            .map(|i| Vec3::new(level(i, 7), level(i, 13), level(i, 29)))
            .collect()
    }

    #[test]
    fn chunks_reach_the_sink_in_order_as_their_srgb_bytes() {
        let linear = gradient(1000);
        let mut sink = Writes {
            writes: Vec::new(),
            fail_at: None,
        };
        let result = write_srgb(&linear, 300, &mut sink, &mut [Vec::new(), Vec::new()]);
        assert_eq!(result, Ok(()));
        let sizes: Vec<usize> = sink.writes.iter().map(Vec::len).collect();
        assert_eq!(sizes, [900, 900, 900, 300]);
        let expected: Vec<u8> = linear
            .iter()
            .flat_map(|c| c.to_array().map(linear_to_srgb8))
            .collect();
        assert_eq!(sink.writes.concat(), expected);
    }

    #[test]
    fn a_failing_sink_stops_the_rows_with_its_reason() {
        let linear = gradient(1000);
        let mut sink = Writes {
            writes: Vec::new(),
            fail_at: Some(1),
        };
        let result = write_srgb(&linear, 300, &mut sink, &mut [Vec::new(), Vec::new()]);
        assert_eq!(result, Err("disk full".to_string()));
        assert_eq!(sink.writes.len(), 1, "nothing written after the failure");
    }
}
