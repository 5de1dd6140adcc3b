//! What the bench runs: the presets, then `interactive` with one knob changed at a time.

use crate::pattern::Precision;
use crate::quality::{Coverage, NormalSource, Preset, Quality, ShadowEdges};
use crate::raster::Interpolation;
use crate::shade::{GradientMethod, NormalForm};
use crate::texture::Filter;
use strum::VariantArray;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VariantKind {
    Preset,
    /// `interactive` with one knob changed.
    Knob,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    pub name: String,
    pub kind: VariantKind,
    pub quality: Quality,
}

/// Every preset, then every single-knob variation of `interactive`.
pub fn variants() -> Vec<Variant> {
    let presets = Preset::VARIANTS.iter().map(|preset| Variant {
        name: preset.name().to_string(),
        kind: VariantKind::Preset,
        quality: preset.quality(),
    });
    let knobs = knob_variations()
        .into_iter()
        .map(|(name, quality)| Variant {
            name: name.to_string(),
            kind: VariantKind::Knob,
            quality,
        });
    presets.chain(knobs).collect()
}

fn knob_variations() -> Vec<(&'static str, Quality)> {
    let base = Quality::interactive();
    let with = |change: fn(&mut Quality)| {
        let mut quality = base;
        change(&mut quality);
        quality
    };
    vec![
        ("tessellation=16", with(|q| q.tessellation = 16)),
        ("tessellation=256", with(|q| q.tessellation = 256)),
        (
            "adaptive<0.5px",
            with(|q| q.adaptive_tolerance_px = Some(0.5)),
        ),
        ("samples=4", with(|q| q.samples = 4)),
        ("filter=nearest", with(|q| q.filter = Some(Filter::Nearest))),
        (
            "filter=bilinear",
            with(|q| q.filter = Some(Filter::Bilinear)),
        ),
        (
            "filter=trilinear",
            with(|q| q.filter = Some(Filter::Trilinear)),
        ),
        (
            "gradient=central(h=0.5)",
            with(|q| q.gradient = GradientMethod::CentralDifference { step: 0.5 }),
        ),
        (
            "gradient=seed-lattice",
            with(|q| q.gradient = GradientMethod::SeedLattice),
        ),
        (
            "patterns=double",
            with(|q| q.pattern_precision = Precision::Double),
        ),
        ("normal=seed", with(|q| q.normal_form = NormalForm::Seed)),
        ("normal=blinn", with(|q| q.normal_form = NormalForm::Blinn)),
        (
            "normals=interpolated",
            with(|q| q.normals = NormalSource::InterpolatedVertex),
        ),
        ("coverage=mesh", with(|q| q.coverage = Coverage::Mesh)),
        (
            "uv=affine",
            with(|q| q.interpolation = Interpolation::Affine),
        ),
        ("shadow-map=512", with(|q| q.shadow_map = 512)),
        ("shadow-map=4096", with(|q| q.shadow_map = 4096)),
        ("shadow-taps=1", with(|q| q.shadow_taps = 1)),
        ("shadow-taps=16", with(|q| q.shadow_taps = 16)),
        ("shadow-bias=2", with(|q| q.shadow_bias = 2.0)),
        (
            "shadow-edges=filtered",
            with(|q| q.shadow_edges = ShadowEdges::Filtered),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_knob_variation_changes_exactly_one_field_of_interactive() {
        let base = Quality::interactive();
        for (name, q) in knob_variations() {
            let changed = [
                q.tessellation != base.tessellation,
                q.adaptive_tolerance_px != base.adaptive_tolerance_px,
                q.samples != base.samples,
                q.filter != base.filter,
                q.gradient != base.gradient,
                q.pattern_precision != base.pattern_precision,
                q.normal_form != base.normal_form,
                q.normals != base.normals,
                q.surface_point != base.surface_point,
                q.coverage != base.coverage,
                q.interpolation != base.interpolation,
                q.shadow_map != base.shadow_map,
                q.shadow_taps != base.shadow_taps,
                q.shadow_bias != base.shadow_bias,
                q.shadow_edges != base.shadow_edges,
            ];
            let count = changed.iter().filter(|&&c| c).count();
            assert_eq!(count, 1, "{name} changes {count} knobs");
        }
    }
}
