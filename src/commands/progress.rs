//! A progress bar on stderr for renders that take more than a moment, and only when stderr is a
//! terminal (never in pipes, logs or CI).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// How long a render runs before its bar appears.
const QUIET_FOR: Duration = Duration::from_millis(400);
const STEPS: u64 = 10_000;

pub struct RenderProgress {
    bar: ProgressBar,
    started: Instant,
    shown: bool,
    terminal: bool,
}

impl RenderProgress {
    pub fn new(label: &str) -> RenderProgress {
        let bar = ProgressBar::with_draw_target(Some(STEPS), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template("{msg} [{bar:40}] {percent:>3}% eta {eta}")
            .expect("a valid template")
            .progress_chars("=> ");
        bar.set_style(style);
        bar.set_message(crate::commands::sanitized(label));
        RenderProgress {
            bar,
            started: Instant::now(),
            shown: false,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    /// `fraction` of the work is done.
    pub fn update(&mut self, fraction: f64) {
        if !self.shown && self.terminal && self.started.elapsed() > QUIET_FOR {
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
            self.shown = true;
        }
        self.bar
            .set_position((fraction.clamp(0.0, 1.0) * STEPS as f64) as u64);
    }

    pub fn finish(self) {
        self.bar.finish_and_clear();
    }
}
