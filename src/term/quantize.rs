//! Mapping an sRGB colour to a palette index: the palette's best [`DitherMix`] for the colour, and an
//! ordered-dither threshold picking one of its entries.

use super::dither_mix::{DitherMix, MixRules, best_dither_mix};
use super::palette::{ANSI16, CUBE_LEVELS, GREY_RAMP_START, WEIGHTS, cube_index};

/// The palettes a colour can be quantised to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Palette {
    /// xterm indices 16..256: the 6×6×6 cube and the 24-step grey ramp.
    Xterm256,
    /// The 16 ANSI colours.
    Ansi16,
}

/// The palette index for `rgb`; `threshold` (0..=255, see [`super::dither`]) picks between the bracketing
/// entries so that a flat area averages to its true colour. A threshold of 128 is plain nearest-ish rounding.
pub fn quantize(rgb: [u8; 3], palette: Palette, threshold: u8) -> u8 {
    match palette {
        Palette::Xterm256 => quantize_xterm256(rgb, threshold),
        Palette::Ansi16 => quantize_ansi16(rgb, threshold),
    }
}

/// Grey ladder of the 256-colour palette: cube black, the 24 ramp steps, cube white.
const GREY_LADDER: [u8; 26] = [
    0, 8, 18, 28, 38, 48, 58, 68, 78, 88, 98, 108, 118, 128, 138, 148, 158, 168, 178, 188, 198,
    208, 218, 228, 238, 255,
];

fn grey_ladder_index(step: usize) -> u8 {
    match step {
        0 => cube_index(0, 0, 0),
        25 => cube_index(5, 5, 5),
        k => GREY_RAMP_START + (k - 1) as u8,
    }
}

/// The segment `levels[i]..=levels[i+1]` holding `v`, and how far along it `v` lies (0..=255).
const fn bracket(levels: &[u8], v: u8) -> (usize, u8) {
    let mut i = levels.len() - 2;
    while i > 0 && levels[i] > v {
        i -= 1;
    }
    let (lo, hi) = (levels[i] as u32, levels[i + 1] as u32);
    let above = (v as u32).saturating_sub(lo);
    let t = (above * 255 + (hi - lo) / 2) / (hi - lo);
    (i, if t > 255 { 255 } else { t as u8 })
}

/// [`bracket`] for every byte value, so the per-pixel work is a lookup.
const fn bracket_table(levels: &[u8]) -> [(u8, u8); 256] {
    let mut table = [(0u8, 0u8); 256];
    let mut v = 0;
    while v < 256 {
        let (i, t) = bracket(levels, v as u8);
        table[v] = (i as u8, t);
        v += 1;
    }
    table
}

const CUBE_BRACKETS: [(u8, u8); 256] = bracket_table(&CUBE_LEVELS);
const GREY_BRACKETS: [(u8, u8); 256] = bracket_table(&GREY_LADDER);

fn quantize_xterm256(rgb: [u8; 3], threshold: u8) -> u8 {
    best_xterm256_mix(rgb).pick(threshold)
}

/// The best mix of two of the palette entries around `rgb`: the eight corners of its cube cell and
/// the two grey steps around its grey. Two, as dithering each channel on its own mixes up to eight
/// cube entries into colour noise, and choosing the grey ramp or the cube per pixel blotches a dull
/// colour (a cat's fur) where the choice flips; a mix may join the two.
fn best_xterm256_mix(rgb: [u8; 3]) -> DitherMix {
    let cell = rgb.map(|v| CUBE_BRACKETS[v as usize].0 as usize);
    let grey_step = GREY_BRACKETS[weighted_grey(rgb) as usize].0 as usize;
    let corners = (0..8).map(|k| {
        let [r, g, b] = [
            cell[0] + (k & 1),
            cell[1] + (k >> 1 & 1),
            cell[2] + (k >> 2 & 1),
        ];
        (
            cube_index(r, g, b),
            [CUBE_LEVELS[r], CUBE_LEVELS[g], CUBE_LEVELS[b]],
        )
    });
    let greys = (grey_step..grey_step + 2).map(|k| (grey_ladder_index(k), [GREY_LADDER[k]; 3]));
    let mut candidates = [(0u8, [0u8; 3]); 10];
    for (slot, candidate) in candidates.iter_mut().zip(corners.chain(greys)) {
        *slot = candidate;
    }
    best_dither_mix(rgb, &candidates, XTERM256_RULES)
}

fn weighted_grey(rgb: [u8; 3]) -> u8 {
    let sum: i32 = (0..3).map(|i| WEIGHTS[i] * rgb[i] as i32).sum();
    let total: i32 = WEIGHTS.iter().sum();
    ((sum + total / 2) / total) as u8
}

/// The 16 colours are far apart: a dull colour lies between grey and two hues (an orange between
/// grey, red and yellow), so three may mix, and an error off the grey axis weighs 9 on top of the
/// channel weights (2–4). Half the spread is penalised, which keeps the dither where partners are close and a dark
/// background black. (`cargo bench --bench tui_latency` measures the picture against the area
/// average, beside chafa.)
const ANSI16_RULES: MixRules = MixRules {
    spread_penalty: 0.5,
    hue_weight: 9.0,
    three: true,
};

/// The 256 colours are close: a colour less than 0.41 of the way from an entry to the next shows
/// as that entry, flat (a mix wins where t² > 0.7·t·(1 − t)). Less grain, and nearer the area
/// average both sub-pixel by sub-pixel and in mean ΔE than at 0.5. An error off the grey axis
/// weighs 1 on top of the channel weights, so a dull tan mixes from the cube rather than showing
/// as the grey ramp; more costs grain (and ΔE) for the hue it gains.
const XTERM256_RULES: MixRules = MixRules {
    spread_penalty: 0.7,
    hue_weight: 1.0,
    three: false,
};

fn quantize_ansi16(rgb: [u8; 3], threshold: u8) -> u8 {
    best_ansi16_mix(rgb).pick(threshold)
}

/// [`quantize`] with a memo of the mix search, which weighs up to ~120 mixes per colour while
/// rendered frames repeat colours a lot. One per frame or per thread: it is not shared.
#[derive(Clone, Debug)]
pub struct Quantizer {
    palette: Palette,
    /// Direct-mapped: (packed rgb | VALID, its mix).
    mixes: Vec<(u32, DitherMix)>,
}

const MEMO_SLOTS: usize = 8192;
const VALID: u32 = 1 << 24;

impl Quantizer {
    pub fn new(palette: Palette) -> Self {
        Quantizer {
            palette,
            mixes: vec![(0, DitherMix::default()); MEMO_SLOTS],
        }
    }

    /// Same result as [`quantize`] with this quantizer's palette.
    pub fn quantize(&mut self, rgb: [u8; 3], threshold: u8) -> u8 {
        let key = VALID | (rgb[0] as u32) << 16 | (rgb[1] as u32) << 8 | rgb[2] as u32;
        let slot = (key.wrapping_mul(0x9E37_79B1) >> 19) as usize % MEMO_SLOTS;
        let entry = &mut self.mixes[slot];
        if entry.0 != key {
            let mix = match self.palette {
                Palette::Xterm256 => best_xterm256_mix(rgb),
                Palette::Ansi16 => best_ansi16_mix(rgb),
            };
            *entry = (key, mix);
        }
        entry.1.pick(threshold)
    }
}

fn best_ansi16_mix(rgb: [u8; 3]) -> DitherMix {
    let mut candidates = [(0u8, [0u8; 3]); 16];
    for (i, slot) in candidates.iter_mut().enumerate() {
        *slot = (i as u8, ANSI16[i]);
    }
    best_dither_mix(rgb, &candidates, ANSI16_RULES)
}

/// Whether a pixel is lit in monochrome mode: its luma (Rec. 709 weights on the sRGB values) against the
/// dither threshold.
pub fn monochrome_lit(rgb: [u8; 3], threshold: u8) -> bool {
    let luma = (54 * rgb[0] as u32 + 183 * rgb[1] as u32 + 19 * rgb[2] as u32 + 128) >> 8;
    luma as u8 > threshold
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::term::cielab::chroma_and_hue;
    use crate::term::palette::xterm256_rgb;

    #[test]
    fn a_dark_background_stays_black_in_16_colours() {
        for threshold in (2..=254).step_by(4) {
            assert_eq!(quantize([38, 38, 38], Palette::Ansi16, threshold), 0);
        }
        // Between two close entries the dither still mixes: grey 165 is a third of 127 to 229.
        let mixed: std::collections::HashSet<u8> = (2..=254)
            .step_by(4)
            .map(|t| quantize([165, 165, 165], Palette::Ansi16, t))
            .collect();
        assert_eq!(mixed.len(), 2, "{mixed:?}");
    }

    /// The colour a flat patch of `rgb` shows as: the dithered entries averaged over every threshold.
    fn dithered_average(rgb: [u8; 3], palette: Palette) -> [u8; 3] {
        let shown: Vec<[u8; 3]> = (0..64)
            .map(|k| xterm256_rgb(quantize(rgb, palette, (4 * k + 2) as u8)))
            .collect();
        std::array::from_fn(|c| {
            (shown.iter().map(|p| p[c] as u32).sum::<u32>() / shown.len() as u32) as u8
        })
    }

    /// A lit orange sphere, a cat's fur in light and in shade, a teal, an olive, a slate blue and a
    /// dusty rose: none of them near a palette entry, all of them nearer a grey in RGB than in hue.
    const DULL_COLOURS: [[u8; 3]; 8] = [
        [200, 140, 115],
        [160, 110, 70],
        [114, 87, 65],
        [180, 100, 50],
        [80, 140, 150],
        [130, 140, 70],
        [100, 110, 160],
        [170, 110, 120],
    ];

    #[test]
    fn dull_colours_keep_their_hue() {
        // The 16 colours hold no dark yellow: a dark brown shows as dark red, 43° off. In the 256
        // the cube's darkest steps (0, 95) are too far apart for a mix of two to hold a dark
        // brown's hue without visible grain: it shows as a dull grey rose.
        let dark_brown = [114, 87, 65];
        for (palette, most_off) in [(Palette::Ansi16, 45.0), (Palette::Xterm256, 25.0)] {
            for rgb in DULL_COLOURS {
                if palette == Palette::Xterm256 && rgb == dark_brown {
                    continue;
                }
                let (chroma, hue) = chroma_and_hue(rgb);
                let (shown_chroma, shown_hue) = chroma_and_hue(dithered_average(rgb, palette));
                let hue_error = (shown_hue - hue + 180.0).rem_euclid(360.0) - 180.0;
                assert!(
                    hue_error.abs() < most_off && shown_chroma > 0.5 * chroma,
                    "{palette:?}: {rgb:?} (C {chroma:.0}, h {hue:.0}°) shows as C {shown_chroma:.0}, h {shown_hue:.0}°"
                );
            }
        }
    }

    #[test]
    fn bracket_ends_are_exact() {
        assert_eq!(bracket(&CUBE_LEVELS, 0), (0, 0));
        assert_eq!(bracket(&CUBE_LEVELS, 95), (1, 0));
        assert_eq!(bracket(&CUBE_LEVELS, 255), (4, 255));
    }

    #[test]
    fn memoised_quantizer_agrees_with_quantize() {
        for palette in [Palette::Ansi16, Palette::Xterm256] {
            let mut quantizer = Quantizer::new(palette);
            for v in (0..=255u32).step_by(3) {
                for rgb in [[v as u8, 40, 200], [10, v as u8, v as u8], [v as u8; 3]] {
                    for threshold in [2, 100, 254] {
                        assert_eq!(
                            quantizer.quantize(rgb, threshold),
                            quantize(rgb, palette, threshold)
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn xterm256_entries_are_fixed_points_at_every_threshold() {
        for index in 16..=255u8 {
            for threshold in [2, 128, 254] {
                assert_eq!(
                    quantize(xterm256_rgb(index), Palette::Xterm256, threshold),
                    index
                );
            }
        }
    }
}
