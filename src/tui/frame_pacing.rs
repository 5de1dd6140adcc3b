//! At most one frame in flight. After each frame the terminal is asked where its cursor is (a
//! cursor position report); it answers only once it has drawn everything before the question. The
//! next frame waits for that answer, so over a slow link keys pile up meanwhile and are coalesced
//! into one frame of the newest state, instead of a megabyte of pictures the user has already
//! moved past queuing in the link. The answers also time each frame, which gives the link's
//! throughput.
//!
//! Each question is asked with the (hidden) cursor at a column of its own, so an answer that comes
//! late, after a time-out, is told from the answer to the frame just sent.
//!
//! Over a slow link a frame is written a step at a time at the link's pace, with input read
//! between the steps, so that little waits in the link (`q` is not queued behind a whole frame),
//! and a frame the user has moved past is cut short at the next row.

use crate::term::CUT_FRAME_END;
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

/// How often a frame going out at the link's pace looks for input.
const PACE_STEP: Duration = Duration::from_millis(20);

/// A frame the link carries in less than this goes out whole: `q` waits for it at most this
/// long, and pacing it would only add to its time.
const PACED_FRAME: Duration = Duration::from_millis(150);

/// The least a paced frame writes at a time.
const LEAST_STEP_BYTES: usize = 2048;

/// How much faster than the bytes went out the link is taken to be when it kept up with them,
/// so that pacing finds a faster link again.
const KEPT_UP_RAISE: f64 = 1.2;

/// How a frame went out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sent {
    /// The bytes written.
    pub bytes: usize,
    /// The row the frame was cut short before, if it was.
    pub cut_before: Option<usize>,
    /// When the first byte was written.
    pub began: Instant,
    /// When the last byte was written.
    pub ended: Instant,
}

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
    /// The shortest time an answer took: the link's round trip, which a frame's time less it
    /// leaves the time its bytes took.
    round_trip: Option<Duration>,
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
            round_trip: None,
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
        let asked = Instant::now();
        self.answers = match self.wait_for_answer((0, rows - 1), &|| false) {
            true => Answers::Given,
            false => Answers::None,
        };
        if self.answers == Answers::Given {
            self.round_trip = Some(asked.elapsed());
        }
    }

    /// After a frame was `sent` to a screen of `cols` × `rows`: returns once the terminal has
    /// drawn it, at once where it does not answer, or soon after `stop` says to (a shutdown
    /// signal).
    pub fn frame_sent(&mut self, sent: Sent, (cols, rows): (u16, u16), stop: &dyn Fn() -> bool) {
        if sent.bytes == 0 {
            return;
        }
        self.bytes_sent += sent.bytes as u64;
        if self.answers != Answers::Given || cols == 0 || rows == 0 {
            return;
        }
        self.tag = (self.tag + 1) % cols;
        let asked = (self.tag, rows - 1);
        if ask_at(asked).is_err() {
            return;
        }
        if self.wait_for_answer(asked, stop) {
            self.time(sent.bytes, sent.began.elapsed(), sent.ended - sent.began);
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

    /// Learns from a frame of `bytes` that took `writing` to write and `took` until the terminal
    /// answered. What the answer waited for beyond a round trip after the last byte is what the
    /// link held back: then the link's throughput is the bytes over the time they took to cross;
    /// where nothing was held back, the link kept up with the pace, and may be faster.
    fn time(&mut self, bytes: usize, took: Duration, writing: Duration) {
        let round_trip = self.round_trip.map_or(took, |before| before.min(took));
        self.round_trip = Some(round_trip);
        let carrying = took.saturating_sub(round_trip);
        if bytes < TIMED_FRAME_BYTES || carrying.is_zero() {
            return;
        }
        // A link that keeps up still takes a step's time to carry the last step.
        let held_back = carrying.saturating_sub(writing);
        let kept_up = held_back < PACE_STEP + PACE_STEP / 2 + writing / 8;
        let rate = bytes as f64 / carrying.as_secs_f64();
        self.throughput = Some(match (self.throughput, kept_up) {
            (Some(before), true) => before.max(rate) * KEPT_UP_RAISE,
            _ => rate,
        });
    }

    /// Writes `frame` with `write`: at once where the link carries it quickly; over a slow link
    /// a step at a time at the link's pace, so little waits in the link when the user acts. Between
    /// steps `input(wait)` waits up to `wait` for input, handles it, and says whether the rest of
    /// the frame is no longer wanted; the frame is then cut at the next of its `cut_points`
    /// (offset, row) and ended with [`CUT_FRAME_END`].
    pub fn send(
        &self,
        frame: &[u8],
        cut_points: &[(usize, usize)],
        write: &mut dyn FnMut(&[u8]) -> io::Result<()>,
        input: &mut dyn FnMut(Duration) -> io::Result<bool>,
    ) -> io::Result<Sent> {
        let began = Instant::now();
        let pace = self
            .bottleneck()
            .filter(|&rate| Duration::from_secs_f64(frame.len() as f64 / rate) > PACED_FRAME);
        let Some(pace) = pace else {
            write(frame)?;
            return Ok(whole(frame, began));
        };
        let step = ((pace * PACE_STEP.as_secs_f64()) as usize).max(LEAST_STEP_BYTES);
        let mut written = 0;
        while written < frame.len() {
            let end = (written + step).min(frame.len());
            write(&frame[written..end])?;
            written = end;
            let due = began + Duration::from_secs_f64(written as f64 / pace);
            while written < frame.len() {
                if input(due.saturating_duration_since(Instant::now()))? {
                    return cut(frame, written, cut_points, write, began);
                }
                if Instant::now() >= due {
                    break;
                }
            }
        }
        Ok(whole(frame, began))
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

/// `frame` went out whole, from `began` until now.
fn whole(frame: &[u8], began: Instant) -> Sent {
    Sent {
        bytes: frame.len(),
        cut_before: None,
        began,
        ended: Instant::now(),
    }
}

/// Ends `frame`, of which `written` bytes are out, at its first cut point from there.
fn cut(
    frame: &[u8],
    written: usize,
    cut_points: &[(usize, usize)],
    write: &mut dyn FnMut(&[u8]) -> io::Result<()>,
    began: Instant,
) -> io::Result<Sent> {
    let Some(&(at, row)) = cut_points.iter().find(|&&(at, _)| at >= written) else {
        write(&frame[written..])?;
        return Ok(whole(frame, began));
    };
    write(&frame[written..at])?;
    write(CUT_FRAME_END)?;
    Ok(Sent {
        bytes: at + CUT_FRAME_END.len(),
        cut_before: Some(row),
        began,
        ended: Instant::now(),
    })
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

    /// A pacer that has seen a round trip of 50 ms (a small frame) and then `bytes` in `took`.
    fn measured(bytes: usize, took: Duration) -> FramePacer {
        let mut pacer = FramePacer::default();
        pacer.time(100, Duration::from_millis(50), Duration::ZERO);
        pacer.whole_frame(bytes);
        pacer.time(bytes, took, Duration::ZERO);
        pacer
    }

    #[test]
    fn a_link_is_slow_when_a_whole_picture_takes_longer_than_a_frame_budget() {
        assert!(!FramePacer::default().slow(), "nothing measured");
        let slow = measured(560_000, Duration::from_millis(2290)); // 2 Mbit/s
        assert!(slow.slow());
        assert_eq!(slow.bottleneck().map(|r| r.round()), Some(250_000.0));
        let fast = measured(560_000, Duration::from_millis(70));
        assert!(!fast.slow() && fast.bottleneck().is_none());
    }

    #[test]
    fn the_round_trip_is_not_taken_for_the_link_carrying_bytes() {
        // 40 kB in 210 ms, of which 50 ms is the round trip: 250 kB/s, not 190.
        let pacer = measured(40_000, Duration::from_millis(210));
        assert_eq!(pacer.bottleneck().map(|r| r.round()), Some(250_000.0));
        let mut unmeasured = FramePacer::default();
        unmeasured.time(40_000, Duration::from_millis(210), Duration::ZERO);
        assert_eq!(unmeasured.throughput, None, "no round trip known yet");
    }

    #[test]
    fn a_link_that_kept_up_with_the_pace_is_taken_to_be_faster_and_one_that_held_back_as_it_is() {
        let mut pacer = measured(100_000, Duration::from_millis(450)); // 250 kB/s
        // Paced at 250 kB/s, answered a round trip after the last byte: the link kept up.
        let paced = Duration::from_millis(400);
        pacer.time(100_000, paced + Duration::from_millis(55), paced);
        assert_eq!(pacer.bottleneck().map(|r| r.round()), Some(300_000.0));
        // Paced at 300 kB/s, the answer 70 ms later than that: the link held back, 200 kB/s.
        let paced = Duration::from_millis(333);
        pacer.time(100_000, Duration::from_millis(550), paced);
        assert_eq!(pacer.bottleneck().map(|r| r.round()), Some(200_000.0));
    }

    fn slow_pacer() -> FramePacer {
        measured(100_000, Duration::from_millis(450)) // 250 kB/s
    }

    #[test]
    fn over_a_slow_link_a_frame_goes_out_in_steps_and_input_cuts_it_at_a_row() {
        let frame: Vec<u8> = (0..100_000).map(|i| b'a' + (i % 26) as u8).collect();
        let rows: Vec<(usize, usize)> = (0..34).map(|row| (row * 3000, row)).collect();
        let mut out = Vec::new();
        let mut steps = 0;
        let sent = slow_pacer()
            .send(
                &frame,
                &rows,
                &mut |bytes| {
                    out.extend_from_slice(bytes);
                    Ok(())
                },
                &mut |wait| {
                    std::thread::sleep(wait);
                    steps += 1;
                    Ok(steps == 2)
                },
            )
            .unwrap();
        // Steps of 250 kB/s × 20 ms = 5 000 B: cut after the second, at the next row.
        assert_eq!(sent.bytes, 12_000 + CUT_FRAME_END.len());
        assert_eq!(sent.cut_before, Some(4));
        assert!(
            sent.ended - sent.began >= Duration::from_millis(40),
            "{sent:?}"
        );
        assert_eq!(&out[..12_000], &frame[..12_000]);
        assert_eq!(&out[12_000..], CUT_FRAME_END);
    }

    #[test]
    fn a_frame_with_no_row_left_to_cut_at_goes_out_whole() {
        let frame = vec![b'x'; 100_000];
        let mut out = Vec::new();
        let mut asked = false;
        let sent = slow_pacer()
            .send(
                &frame,
                &[(0, 0)],
                &mut |bytes| {
                    out.extend_from_slice(bytes);
                    Ok(())
                },
                &mut |_wait| {
                    asked = true;
                    Ok(true)
                },
            )
            .unwrap();
        assert!(asked, "the frame was paced");
        assert_eq!((sent.bytes, sent.cut_before), (100_000, None));
        assert_eq!(out, frame);
    }

    /// `frame` sent by `pacer` with input that must not be looked at: what went out, and in
    /// how many writes.
    fn sent_without_input(pacer: &FramePacer, frame: &[u8]) -> (Sent, usize) {
        let mut writes = 0;
        let cut_points = [(0, 0), (frame.len() / 2, 1)];
        let mut write = |_: &[u8]| {
            writes += 1;
            Ok(())
        };
        let mut input = |_| panic!("input looked at");
        let sent = pacer.send(frame, &cut_points, &mut write, &mut input);
        (sent.unwrap(), writes)
    }

    #[test]
    fn where_the_link_keeps_up_a_frame_goes_out_in_one_write_without_looking_at_input() {
        let (sent, writes) = sent_without_input(&FramePacer::default(), &[b'x'; 100_000]);
        assert_eq!((sent.bytes, sent.cut_before, writes), (100_000, None, 1));
    }

    #[test]
    fn a_frame_the_link_carries_quickly_goes_out_whole_even_over_a_slow_link() {
        // 80 ms at 250 kB/s.
        let (sent, writes) = sent_without_input(&slow_pacer(), &[b'x'; 20_000]);
        assert_eq!((sent.bytes, writes), (20_000, 1));
    }

    #[test]
    fn small_frames_do_not_time_the_link() {
        let mut pacer = FramePacer::default();
        pacer.time(2_000, Duration::from_millis(100), Duration::ZERO);
        assert_eq!(pacer.throughput, None);
    }
}
