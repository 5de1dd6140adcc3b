//! What the last frame cost, as the status line tells it.

use crate::raster::FrameStats;
use std::time::Duration;

/// What the last frame cost.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameReport {
    pub render_time: Duration,
    pub stats: FrameStats,
    pub bytes: usize,
    /// PSNR against the reference, when the error view drew the frame.
    pub psnr_db: Option<f64>,
    /// Passes averaged into the picture on screen (progressive refinement).
    pub passes: u32,
    /// Bytes of the last picture sent as pixels.
    pub picture_bytes: usize,
    /// Whether more passes of this picture are coming.
    pub refining: bool,
    /// Every byte written to the terminal.
    pub bytes_sent: u64,
    /// The link's measured throughput in bytes per second, while it holds the frames back.
    pub link_throughput: Option<f64>,
}
