//! The animation clock: scene time that runs, pauses and steps, at a capped frame rate.

use std::time::{Duration, Instant};

#[derive(Clone, Debug)]
pub struct Clock {
    /// Scene time in seconds.
    time: f64,
    running_since: Option<Instant>,
    frame: Duration,
}

impl Clock {
    /// A running clock at `time` seconds.
    pub fn new(fps: u32, time: f64) -> Clock {
        Clock {
            time,
            running_since: Some(Instant::now()),
            frame: Duration::from_secs_f64(1.0 / fps.max(1) as f64),
        }
    }

    /// Scene time now, in seconds.
    pub fn time(&self) -> f64 {
        self.time
            + self
                .running_since
                .map_or(0.0, |t| t.elapsed().as_secs_f64())
    }

    pub fn is_running(&self) -> bool {
        self.running_since.is_some()
    }

    pub fn toggle(&mut self) {
        match self.running_since.take() {
            Some(since) => self.time += since.elapsed().as_secs_f64(),
            None => self.running_since = Some(Instant::now()),
        }
    }

    /// Pauses and advances by one frame.
    pub fn step(&mut self) {
        if self.is_running() {
            self.toggle();
        }
        self.time += self.frame.as_secs_f64();
    }

    /// The shortest time between animation frames.
    pub fn frame_interval(&self) -> Duration {
        self.frame
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stepping_pauses_and_advances_one_frame() {
        let mut clock = Clock::new(25, 0.0);
        clock.step();
        let t = clock.time();
        clock.step();
        assert!(!clock.is_running());
        assert!((clock.time() - t - 0.04).abs() < 1e-9);
    }
}
