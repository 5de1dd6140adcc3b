//! Knobs set one at a time (a scene file's `[quality]` table, `--set quality.KNOB=VALUE`), and
//! the ranges every quality read from outside the program must keep.

use super::Quality;
use crate::scene::KnobSetting;
use crate::shade::GradientMethod;

/// The most samples per pixel a still may ask for.
pub const MAX_SAMPLES: u32 = 1024;
/// The largest tessellation density (cells per half turn).
pub const MAX_DENSITY: u32 = 4096;
pub use crate::shadow::MAP_SIZES as SHADOW_MAP_SIZES;
/// The depth comparisons a shadow lookup may make: a square of taps.
pub const SHADOW_TAPS: [u32; 4] = [1, 4, 9, 16];
/// The largest normal offset of a shadow lookup, in texels.
pub const MAX_SHADOW_BIAS: f32 = 16.0;

impl Quality {
    /// This quality with each setting applied in turn (the value `"none"` clears an optional
    /// knob), each result checked; an error names the setting's place and the knobs there are.
    pub fn with_settings(self, settings: &[KnobSetting]) -> Result<Quality, String> {
        let mut quality = self;
        for setting in settings {
            quality = quality
                .with_knob(&setting.knob, &setting.value)
                .map_err(|message| setting.error(&message))?;
        }
        Ok(quality)
    }

    fn with_knob(self, knob: &str, value: &toml::Value) -> Result<Quality, String> {
        let mut table = toml::Table::try_from(self).expect("a quality is a TOML table");
        if !knob_names().iter().any(|k| k == knob) {
            return Err(format!(
                "no quality knob '{}'; the knobs are {}",
                crate::diagnostic::shown_input(knob),
                knob_names().join(", ")
            ));
        }
        match value.as_str() {
            Some("none") => table.remove(knob),
            _ => table.insert(knob.to_string(), value.clone()),
        };
        let quality = toml::Value::Table(table)
            .try_into::<Quality>()
            .map_err(|e| crate::scene::user_words::in_user_words(e.message()))?;
        check_quality(&quality)?;
        Ok(quality)
    }
}

/// Every knob's name, as a recipe writes it (from a quality with every optional knob set).
pub fn knob_names() -> Vec<String> {
    let every_knob_set = Quality {
        adaptive_tolerance_px: Some(0.5),
        adaptive_samples: Some(0.02),
        filter: Some(crate::texture::Filter::Nearest),
        ..Quality::interactive()
    };
    let table = toml::Table::try_from(every_knob_set).expect("a quality is a TOML table");
    table.keys().cloned().collect()
}

/// The ranges the command line enforces, for a quality read from a file.
pub fn check_quality(quality: &Quality) -> Result<(), String> {
    if !(1..=MAX_SAMPLES).contains(&quality.samples) {
        return Err(format!(
            "samples {} is outside 1..={MAX_SAMPLES}",
            quality.samples
        ));
    }
    if !(1..=MAX_DENSITY).contains(&quality.tessellation) {
        return Err(format!(
            "tessellation {} is outside 1..={MAX_DENSITY}",
            quality.tessellation
        ));
    }
    let positive = |x: f32| x.is_finite() && x > 0.0;
    if quality.adaptive_tolerance_px.is_some_and(|t| !positive(t)) {
        return Err("the adaptive tolerance must be a positive number of pixels".into());
    }
    if !positive(quality.displace_tolerance_px) {
        return Err("the displacement tolerance must be a positive number of pixels".into());
    }
    if quality
        .adaptive_samples
        .is_some_and(|c| !(0.0..=1.0).contains(&c))
    {
        return Err("the adaptive-samples contrast must be from 0 to 1".into());
    }
    if let GradientMethod::CentralDifference { step } = quality.gradient
        && !positive(step)
    {
        return Err("the central-difference step must be positive".into());
    }
    check_shadow_knobs(quality)
}

fn check_shadow_knobs(quality: &Quality) -> Result<(), String> {
    if !SHADOW_MAP_SIZES.contains(&quality.shadow_map) {
        return Err(format!(
            "shadow-map {} is outside {}..={} texels",
            quality.shadow_map,
            SHADOW_MAP_SIZES.start(),
            SHADOW_MAP_SIZES.end()
        ));
    }
    if !SHADOW_TAPS.contains(&quality.shadow_taps) {
        return Err(format!(
            "shadow-taps must be one of 1, 4, 9 or 16, not {}",
            quality.shadow_taps
        ));
    }
    if !(0.0..=MAX_SHADOW_BIAS).contains(&quality.shadow_bias) {
        return Err(format!(
            "shadow-bias must be from 0 to {MAX_SHADOW_BIAS} texels"
        ));
    }
    Ok(())
}
