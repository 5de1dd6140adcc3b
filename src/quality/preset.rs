//! The named quality presets, cheapest first: what `--quality` takes and the workbench's `Q`
//! cycles through.

use super::Quality;
use strum::VariantArray;

/// A named preset.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, strum::VariantArray, strum::IntoStaticStr)]
#[strum(serialize_all = "lowercase")]
pub enum Preset {
    Draft,
    #[default]
    Interactive,
    High,
    Exact,
}

impl Preset {
    pub fn name(self) -> &'static str {
        self.into()
    }

    pub fn quality(self) -> Quality {
        match self {
            Preset::Draft => Quality::draft(),
            Preset::Interactive => Quality::interactive(),
            Preset::High => Quality::high(),
            Preset::Exact => Quality::exact(),
        }
    }

    /// The preset of this name, or a message listing the names (a command-line value parser).
    pub fn named(name: &str) -> Result<Preset, String> {
        let found = Preset::VARIANTS.iter().find(|p| p.name() == name);
        found.copied().ok_or_else(|| {
            let names: Vec<&str> = Preset::VARIANTS.iter().map(|p| p.name()).collect();
            format!(
                "unknown quality preset '{}'; the presets are {}",
                crate::diagnostic::shown_input(name),
                names.join(", ")
            )
        })
    }

    /// The next dearer preset, after `exact` the cheapest.
    pub fn next(self) -> Preset {
        let index = Preset::VARIANTS.iter().position(|&p| p == self);
        Preset::VARIANTS[(index.expect("a variant") + 1) % Preset::VARIANTS.len()]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quality::NormalForm;
    use crate::shade::GradientMethod;
    use crate::texture::Filter;

    #[test]
    fn every_name_finds_its_preset_and_they_differ() {
        for (i, a) in Preset::VARIANTS.iter().enumerate() {
            assert_eq!(Preset::named(a.name()), Ok(*a));
            for b in &Preset::VARIANTS[i + 1..] {
                assert_ne!(a.quality(), b.quality(), "{a:?} and {b:?}");
            }
        }
        assert_eq!(Preset::default().quality(), Quality::default());
        assert_eq!(Quality::default(), Quality::interactive());
    }

    #[test]
    fn presets_grow_in_samples_and_shrink_in_tolerance() {
        let [draft, interactive, high, exact] = [
            Preset::Draft,
            Preset::Interactive,
            Preset::High,
            Preset::Exact,
        ]
        .map(Preset::quality);
        assert!(draft.tessellation < interactive.tessellation);
        assert!(draft.samples <= interactive.samples);
        assert!(interactive.samples < high.samples && high.samples < exact.samples);
        assert!(exact.adaptive_tolerance_px < high.adaptive_tolerance_px);
        assert!(interactive.tessellation < high.tessellation);
        assert!(high.tessellation < exact.tessellation);
        assert_eq!(draft.filter, Some(Filter::Nearest));
        assert_eq!(exact.normal_form, NormalForm::Full);
        assert_eq!(exact.gradient, GradientMethod::Exact);
    }

    #[test]
    fn an_unknown_name_lists_the_presets() {
        let message = Preset::named("ultra").unwrap_err();
        assert!(message.contains("'ultra'"), "{message}");
        for preset in Preset::VARIANTS {
            assert!(message.contains(preset.name()), "{message}");
        }
        assert_eq!(Quality::named("ultra").unwrap_err(), message);
    }

    #[test]
    fn cycling_visits_every_preset_from_interactive() {
        let mut preset = Preset::default();
        let mut seen = Vec::new();
        for _ in Preset::VARIANTS {
            preset = preset.next();
            seen.push(preset.name());
        }
        assert_eq!(seen, ["high", "exact", "draft", "interactive"]);
    }
}
