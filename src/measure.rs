//! Timing statistics for the benchmarks: medians with spread, never a single run.

use std::time::{Duration, Instant};

/// Summary of repeated timings.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    pub median: Duration,
    pub min: Duration,
    pub max: Duration,
    pub p95: Duration,
    pub runs: usize,
}

impl Timing {
    pub fn from_samples(mut samples: Vec<Duration>) -> Timing {
        assert!(!samples.is_empty(), "at least one sample");
        samples.sort();
        let at = |q: f64| samples[((samples.len() - 1) as f64 * q).round() as usize];
        Timing {
            median: at(0.5),
            min: samples[0],
            max: samples[samples.len() - 1],
            p95: at(0.95),
            runs: samples.len(),
        }
    }

    /// Runs `work` `warmup` times unmeasured, then `runs` times measured.
    pub fn measure(warmup: usize, runs: usize, mut work: impl FnMut()) -> Timing {
        for _ in 0..warmup {
            work();
        }
        let samples = (0..runs.max(1))
            .map(|_| {
                let start = Instant::now();
                work();
                start.elapsed()
            })
            .collect();
        Timing::from_samples(samples)
    }

    /// `median ms (min–max)`.
    pub fn summary_ms(&self) -> String {
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        format!(
            "{:.2} ms ({:.2}–{:.2})",
            ms(self.median),
            ms(self.min),
            ms(self.max)
        )
    }

    /// Items per second at the median.
    pub fn rate(&self, items: f64) -> f64 {
        items / self.median.as_secs_f64()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_and_spread_of_known_samples() {
        let t = Timing::from_samples([5, 1, 4, 2, 3].map(Duration::from_millis).to_vec());
        assert_eq!(t.median, Duration::from_millis(3));
        assert_eq!(
            (t.min, t.max),
            (Duration::from_millis(1), Duration::from_millis(5))
        );
    }
}
