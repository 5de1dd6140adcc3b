//! The workbench's quality: the crate's named presets (`crate::quality`), cycled by a key.
//! Samples are capped for the terminal: the workbench supersamples on a square grid, and
//! `exact`'s 64 samples would make every frame 64 renders, too slow to orbit with.

use crate::quality::{QUALITY_NAMES, Quality, preset};

/// Most samples per picture pixel the workbench takes: 2×2.
pub const MAX_TERMINAL_SAMPLES: u32 = 4;

/// One of `QUALITY_NAMES`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QualityPreset {
    index: usize,
}

impl Default for QualityPreset {
    /// `interactive`.
    fn default() -> Self {
        QualityPreset { index: 1 }
    }
}

impl QualityPreset {
    /// The preset of this name, or a message listing the names.
    pub fn named(name: &str) -> Result<QualityPreset, String> {
        Quality::named(name)?;
        let index = QUALITY_NAMES.iter().position(|&n| n == name);
        Ok(QualityPreset {
            index: index.expect("a preset is listed"),
        })
    }

    pub fn name(self) -> &'static str {
        QUALITY_NAMES[self.index]
    }

    pub fn quality(self) -> Quality {
        preset(self.name()).expect("every listed name is a preset")
    }

    pub fn next(self) -> QualityPreset {
        QualityPreset {
            index: (self.index + 1) % QUALITY_NAMES.len(),
        }
    }
}

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
    fn cycling_visits_every_preset_from_interactive() {
        let mut preset = QualityPreset::default();
        assert_eq!(preset.name(), "interactive");
        let mut seen = Vec::new();
        for _ in 0..QUALITY_NAMES.len() {
            preset = preset.next();
            seen.push(preset.name());
        }
        assert_eq!(seen, ["high", "exact", "draft", "interactive"]);
    }

    #[test]
    fn presets_are_found_by_name() {
        assert_eq!(QualityPreset::named("exact").unwrap().name(), "exact");
        assert!(
            QualityPreset::named("normal")
                .unwrap_err()
                .contains("draft")
        );
    }

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
