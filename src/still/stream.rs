//! A still streamed band by band into a sink of 8-bit sRGB rows, which the render's last pass
//! hands on strip by strip (`RenderTarget::finished_strips`) once the samples are resolved.

use super::bands::{BandBuffers, BandJob, band_rows};
use crate::raster::{FragmentShader, FrameStats, STRIP_ROWS, Srgb8Strips};
use std::collections::BTreeMap;
use std::ops::Range;
use std::sync::mpsc::{Receiver, channel};
use std::sync::{Mutex, PoisonError};

/// Where finished rows go (a PNG or PPM encoder): 3 bytes per pixel, top row first. `Send`, so
/// a thread of its own can write a band's first rows while the rest of the band renders.
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

/// Renders one band while a thread of its own writes it to `sink`: the last pass converts each
/// tile to 8-bit sRGB as it finishes it (still in cache) and hands on each strip of `STRIP_ROWS`
/// rows, and the writer takes the strips in order, so a PNG's deflate (serial) runs beside the
/// render instead of after it. The band's render and the writing's result.
fn render_and_write<S: FragmentShader>(
    job: &BandJob<S>,
    rows: Range<u32>,
    buffers: &mut BandBuffers,
    spare: &SpareRows,
    sink: &mut dyn RowSink,
    keep_going: &dyn Fn() -> bool,
    on_pass: &mut dyn FnMut(),
) -> (Option<FrameStats>, Result<(), String>) {
    let strip_count = (rows.end - rows.start).div_ceil(STRIP_ROWS) as usize;
    let (strips, finished) = channel();
    std::thread::scope(|scope| {
        let writer = scope.spawn(move || write_in_order(finished, strip_count, sink, spare));
        let buffer = || spare.take();
        let finished = move |strip: usize, bytes: Vec<u8>| {
            // Refused only once the writer has stopped on a failed write, which it reports.
            let _ = strips.send((strip, bytes));
        };
        let srgb8 = Srgb8Strips {
            buffer: &buffer,
            finished: &finished,
        };
        let band = job.render(rows, buffers, keep_going, on_pass, Some(&srgb8));
        drop(finished); // closes the channel: the writer ends with the last strip
        let written = writer
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        (band, written)
    })
}

/// Buffers of 8-bit rows already written, for the next strips to fill: a fresh one would be
/// zeroed, and its pages first touched, for every strip.
#[derive(Default)]
struct SpareRows(Mutex<Vec<Vec<u8>>>);

impl SpareRows {
    fn take(&self) -> Vec<u8> {
        let mut spare = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        spare.pop().unwrap_or_default()
    }

    fn put(&self, rows: Vec<u8>) {
        let mut spare = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        spare.push(rows);
    }
}

/// Writes strips (index from the top, 8-bit rows) to `sink` in order of their index, however
/// they arrive, handing each written buffer to `spare`; stops at the first failed write. Every
/// one of `strip_count` strips must come.
fn write_in_order(
    strips: Receiver<(usize, Vec<u8>)>,
    strip_count: usize,
    sink: &mut dyn RowSink,
    spare: &SpareRows,
) -> Result<(), String> {
    let mut waiting = BTreeMap::new();
    let mut next = 0;
    for (index, bytes) in strips {
        waiting.insert(index, bytes);
        while let Some(bytes) = waiting.remove(&next) {
            sink.write_rows(&bytes)?;
            spare.put(bytes);
            next += 1;
        }
    }
    if next == strip_count {
        Ok(())
    } else {
        Err(format!(
            "{next} of {strip_count} strips of rows were rendered"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::mpsc::Sender;

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

    fn sink(fail_at: Option<usize>) -> Writes {
        Writes {
            writes: Vec::new(),
            fail_at,
        }
    }

    /// Sends strips `order` (strip k holds the byte k, k + 1 times) and closes the channel.
    fn send(order: &[usize]) -> Receiver<(usize, Vec<u8>)> {
        let (strips, finished): (Sender<_>, _) = channel();
        for &k in order {
            strips.send((k, vec![k as u8; k + 1])).unwrap();
        }
        finished
    }

    #[test]
    fn strips_arriving_in_any_order_are_written_top_first() {
        let mut rows = sink(None);
        let spare = SpareRows::default();
        let result = write_in_order(send(&[2, 0, 4, 1, 3]), 5, &mut rows, &spare);
        assert_eq!(result, Ok(()));
        let expected: Vec<Vec<u8>> = (0..5).map(|k| vec![k as u8; k + 1]).collect();
        assert_eq!(rows.writes, expected);
        let spare = spare.0.into_inner().unwrap();
        assert_eq!(spare.len(), 5, "every written buffer back for reuse");
    }

    #[test]
    fn a_failing_sink_stops_the_rows_with_its_reason() {
        let mut rows = sink(Some(1));
        let result = write_in_order(send(&[0, 1, 2]), 3, &mut rows, &SpareRows::default());
        assert_eq!(result, Err("disk full".to_string()));
        assert_eq!(rows.writes.len(), 1, "nothing written after the failure");
    }

    #[test]
    fn a_missing_strip_is_an_error_not_a_shorter_image() {
        let mut rows = sink(None);
        let result = write_in_order(send(&[0, 2]), 3, &mut rows, &SpareRows::default());
        assert!(result.is_err());
        assert_eq!(rows.writes.len(), 1, "only the rows before the gap");
    }
}
