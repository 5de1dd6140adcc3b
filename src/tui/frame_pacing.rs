//! At most one frame in flight. After each frame the terminal is asked where its cursor is (a
//! cursor position report); it answers only once it has drawn everything before the question. The
//! next frame waits for that answer, so over a slow link keys pile up meanwhile and are coalesced
//! into one frame of the newest state, instead of a megabyte of pictures the user has already
//! moved past queuing in the link. The answers also time each frame, which gives the link's
//! throughput.
//!
//! Each question is asked with the (hidden) cursor at a column of its own, so an answer that comes
//! late, after a time-out, is told from the answer to the frame just sent.

use std::io::{self, Write};
use std::time::{Duration, Instant};

/// How long the question asked before the first frame waits for its answer before the terminal
/// is taken to give none (then frames are not paced): crossterm's own time-out for a cursor
/// position report.
const FIRST_ANSWER: Duration = Duration::from_secs(2);

/// The longest a frame waits for its answer from a terminal that has answered before: a frame
/// slower than this has met a link that is not moving, and waiting longer helps no one.
const LONGEST_WAIT: Duration = Duration::from_secs(30);

/// Frames smaller than this are too small to time a link by: the round trip dominates.
const TIMED_FRAME_BYTES: usize = 16 * 1024;

/// A whole picture that takes the link longer than this makes it slow (see [`FramePacer::slow`]):
/// refinement's passes then cost more to send than to render (all 64 take ~70 ms here), and a
/// pass sent on the way only delays the settled picture.
const SLOW_FRAME: Duration = Duration::from_millis(40);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Answers {
    /// Not asked yet.
    Unknown,
    Given,
    /// The first question went unanswered: frames are sent as fast as they come.
    None,
}

/// Waits for each frame to be drawn, and measures the link while doing so.
#[derive(Debug)]
pub struct FramePacer {
    answers: Answers,
    /// The column the next question is asked at (0-based).
    tag: u16,
    /// Bytes per second the link carried, from the last timed frames (f64: a rate, not a pixel).
    throughput: Option<f64>,
    /// The bytes of the last frame sent whole (the first pass after a change).
    full_frame_bytes: usize,
    /// Every byte written to the terminal.
    bytes_sent: u64,
}

impl Default for FramePacer {
    fn default() -> Self {
        FramePacer {
            answers: Answers::Unknown,
            tag: 0,
            throughput: None,
            full_frame_bytes: 0,
            bytes_sent: 0,
        }
    }
}

impl FramePacer {
    /// Asks once, with nothing in flight, whether the terminal answers at all: a first frame can
    /// take longer than any time-out to cross a slow link.
    pub fn probe(&mut self, (cols, rows): (u16, u16)) {
        if cols == 0 || rows == 0 || ask_at((0, rows - 1)).is_err() {
            self.answers = Answers::None;
            return;
        }
        self.answers = match self.wait_for_answer((0, rows - 1), &|| false) {
            true => Answers::Given,
            false => Answers::None,
        };
    }

    /// After `bytes` of a frame were written (from `sent` on) to a screen of `cols` × `rows`:
    /// returns once the terminal has drawn them, at once where it does not answer, or soon after
    /// `stop` says to (a shutdown signal).
    pub fn frame_sent(
        &mut self,
        bytes: usize,
        sent: Instant,
        (cols, rows): (u16, u16),
        stop: &dyn Fn() -> bool,
    ) {
        if bytes == 0 {
            return;
        }
        self.bytes_sent += bytes as u64;
        if self.answers != Answers::Given || cols == 0 || rows == 0 {
            return;
        }
        self.tag = (self.tag + 1) % cols;
        let asked = (self.tag, rows - 1);
        if ask_at(asked).is_err() {
            return;
        }
        if self.wait_for_answer(asked, stop) {
            self.time(bytes, sent.elapsed());
        }
    }

    /// Waits for the answer to the question asked at `asked`; false after the time-out.
    fn wait_for_answer(&self, asked: (u16, u16), stop: &dyn Fn() -> bool) -> bool {
        let limit = match self.answers {
            Answers::Unknown => FIRST_ANSWER,
            _ => LONGEST_WAIT,
        };
        let start = Instant::now();
        while start.elapsed() < limit && !stop() {
            // Each call asks again from the same place, so any answer from there will do.
            match crossterm::cursor::position() {
                Ok(at) if at == asked => return true,
                Ok(_) => {}
                Err(_) if self.answers == Answers::Unknown => return false,
                Err(_) => {}
            }
        }
        false
    }

    fn time(&mut self, bytes: usize, took: Duration) {
        if bytes < TIMED_FRAME_BYTES || took.is_zero() {
            return;
        }
        let rate = bytes as f64 / took.as_secs_f64();
        self.throughput = Some(match self.throughput {
            Some(before) => 0.5 * before + 0.5 * rate,
            None => rate,
        });
    }

    /// Takes `bytes` as the size of a whole new picture, the yardstick of [`Self::slow`].
    pub fn whole_frame(&mut self, bytes: usize) {
        if bytes > 0 {
            self.full_frame_bytes = bytes;
        }
    }

    /// Whether a whole picture takes the link long enough that only the settled picture is
    /// worth sending after the first: intermediate passes would only delay it.
    pub fn slow(&self) -> bool {
        self.throughput.is_some_and(|rate| {
            Duration::from_secs_f64(self.full_frame_bytes as f64 / rate) > SLOW_FRAME
        })
    }

    /// The link's measured throughput in bytes per second, while it is the bottleneck.
    pub fn bottleneck(&self) -> Option<f64> {
        self.throughput.filter(|_| self.slow())
    }

    /// Every byte written to the terminal so far.
    pub fn bytes_sent(&self) -> u64 {
        self.bytes_sent
    }
}

/// Moves the hidden cursor to `(col, row)` (0-based) and asks nothing yet: the question goes out
/// with [`crossterm::cursor::position`].
fn ask_at((col, row): (u16, u16)) -> io::Result<()> {
    let mut out = io::stdout().lock();
    write!(out, "\x1b[{};{}H", row + 1, col + 1)?;
    out.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_is_slow_when_a_whole_picture_takes_longer_than_a_frame_budget() {
        let mut pacer = FramePacer::default();
        assert!(!pacer.slow(), "nothing measured");
        pacer.whole_frame(560_000);
        pacer.time(560_000, Duration::from_millis(2240)); // 2 Mbit/s
        assert!(pacer.slow());
        assert_eq!(pacer.bottleneck().map(|r| r.round()), Some(250_000.0));
        let mut fast = FramePacer::default();
        fast.whole_frame(560_000);
        fast.time(560_000, Duration::from_millis(20));
        assert!(!fast.slow() && fast.bottleneck().is_none());
    }

    #[test]
    fn small_frames_do_not_time_the_link() {
        let mut pacer = FramePacer::default();
        pacer.time(2_000, Duration::from_millis(100));
        assert_eq!(pacer.throughput, None);
    }
}
