//! The workbench's quality: the crate's named presets (`crate::quality::Preset`), cycled by a
//! key. Samples are capped for the terminal: the workbench supersamples on a square grid, and
//! `exact`'s 64 samples would make every frame 64 renders, too slow to orbit with.

use crate::quality::Quality;

/// Most samples per picture pixel the workbench takes: 2×2.
pub const MAX_TERMINAL_SAMPLES: u32 = 4;

/// Samples along each axis of a picture pixel: `quality`'s, capped at `MAX_TERMINAL_SAMPLES`, as
/// the largest square grid that fits.
pub fn terminal_supersampling(quality: &Quality) -> usize {
    let samples = quality.samples.clamp(1, MAX_TERMINAL_SAMPLES);
    (samples as f64).sqrt().floor() as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_takes_at_most_the_terminal_cap_of_samples() {
        assert_eq!(terminal_supersampling(&Quality::exact()), 2);
        assert_eq!(terminal_supersampling(&Quality::interactive()), 1);
        let nine = Quality {
            samples: 9,
            ..Quality::interactive()
        };
        assert_eq!(terminal_supersampling(&nine), 2);
    }
}
