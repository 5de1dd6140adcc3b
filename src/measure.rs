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

    /// Runs `works` in turn, round after round: `warmup` unmeasured rounds, then `runs`
    /// measured ones. Side by side, so a machine whose speed drifts (as virtual machines' does,
    /// within minutes) slows them alike. Each work is a number of unmeasured runs to settle
    /// before its measured one (a virtual machine may run a short task slowly after an idle or
    /// a switch of task) and the work. Each work's times, in round order.
    pub fn interleaved(
        warmup: usize,
        runs: usize,
        works: &mut [(usize, &mut dyn FnMut())],
    ) -> Vec<Vec<Duration>> {
        let mut samples = vec![Vec::new(); works.len()];
        for round in 0..warmup + runs.max(1) {
            for ((settle, work), samples) in works.iter_mut().zip(&mut samples) {
                (0..*settle).for_each(|_| work());
                let start = Instant::now();
                work();
                if round >= warmup {
                    samples.push(start.elapsed());
                }
            }
        }
        samples
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

/// How many times faster `fast` was than `slow`, round by round (times from
/// `Timing::interleaved`): the median of the rounds' ratios, with their least and greatest.
pub fn ratio_by_round(slow: &[Duration], fast: &[Duration]) -> (f64, f64, f64) {
    let mut ratios: Vec<f64> = slow
        .iter()
        .zip(fast)
        .map(|(s, f)| s.as_secs_f64() / f.as_secs_f64())
        .collect();
    assert!(!ratios.is_empty(), "at least one round");
    ratios.sort_by(f64::total_cmp);
    (
        ratios[ratios.len() / 2],
        ratios[0],
        ratios[ratios.len() - 1],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interleaved_works_take_turns_and_warm_up_unmeasured() {
        let order = std::cell::RefCell::new(Vec::new());
        let (mut a, mut b) = (
            || order.borrow_mut().push('a'),
            || order.borrow_mut().push('b'),
        );
        let samples = Timing::interleaved(1, 3, &mut [(0, &mut a), (1, &mut b)]);
        assert_eq!(
            order.into_inner(),
            "abbabbabbabb".chars().collect::<Vec<_>>()
        );
        assert_eq!(samples.iter().map(Vec::len).collect::<Vec<_>>(), [3, 3]);
    }

    #[test]
    fn ratios_by_round_take_the_median_round() {
        let ms = |v: &[u64]| {
            v.iter()
                .map(|&m| Duration::from_millis(m))
                .collect::<Vec<_>>()
        };
        // Rounds 10x, 2x and 4x faster: the median round is 4x, whatever the medians of each.
        let (median, least, most) = ratio_by_round(&ms(&[100, 20, 40]), &ms(&[10, 10, 10]));
        assert_eq!((median, least, most), (4.0, 2.0, 10.0));
    }

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
