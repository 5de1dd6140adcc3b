//! Mapping an sRGB colour to a palette index, with an ordered-dither threshold deciding between the two
//! palette entries that bracket it.

use super::palette::{ANSI16, CUBE_LEVELS, GREY_RAMP_START, WEIGHTS, cube_index, distance2};

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
    choose(best_xterm256_mix(rgb), threshold)
}

/// The nearest of the palette entries around `rgb` (the eight corners of its cube cell and the
/// two grey steps around its grey), the partner whose mix with it best reproduces `rgb`, and the
/// mix fraction. One mix of two entries, as for the 16 colours: dithering each channel on its own
/// mixes up to eight cube entries into colour noise, and choosing the grey ramp or the cube per
/// pixel blotches a dull colour (a cat's fur) where the choice flips; a mix may join the two.
fn best_xterm256_mix(rgb: [u8; 3]) -> (u8, u8, u8) {
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
    best_mix(rgb, &candidates, XTERM256_MIX_VARIANCE_PENALTY)
}

fn weighted_grey(rgb: [u8; 3]) -> u8 {
    let sum: i32 = (0..3).map(|i| WEIGHTS[i] * rgb[i] as i32).sum();
    let total: i32 = WEIGHTS.iter().sum();
    ((sum + total / 2) / total) as u8
}

/// How much a visible two-colour mix is penalised, as a fraction of its variance: keeps the dither from
/// mixing far-apart colours (say red and cyan for grey) when a closer pair exists, and from breaking a
/// dark background into a checker of black and grey. (At 1 no mix would ever win: a mix's mean squared
/// error is its residual plus its whole variance; half keeps the dither where partners are close.
/// `cargo bench --bench tui_latency` measures the 16-colour picture against the area average.)
const MIX_VARIANCE_PENALTY: f32 = 0.5;

/// The same for the 256 colours, whose entries are close: a colour less than 0.41 of the way from
/// an entry to the next shows as that entry, flat (a mix wins where t² > 0.7·t·(1 − t)). Less
/// grain, and nearer the area average both sub-pixel by sub-pixel and in mean ΔE than at 0.5
/// (`cargo bench --bench tui_latency` measures both, beside chafa).
const XTERM256_MIX_VARIANCE_PENALTY: f32 = 0.7;

fn quantize_ansi16(rgb: [u8; 3], threshold: u8) -> u8 {
    choose(best_ansi16_mix(rgb), threshold)
}

fn choose((near, far, t): (u8, u8, u8), threshold: u8) -> u8 {
    if threshold < t { far } else { near }
}

/// [`quantize`] with a memo of the 16-colour mix search, which costs ~16 projections per colour while
/// rendered frames repeat colours a lot. One per frame or per thread: it is not shared.
#[derive(Clone, Debug)]
pub struct Quantizer {
    palette: Palette,
    /// Direct-mapped: (packed rgb | VALID, near, far, t).
    ansi16_mixes: Vec<(u32, u8, u8, u8)>,
}

const MEMO_SLOTS: usize = 4096;
const VALID: u32 = 1 << 24;

impl Quantizer {
    pub fn new(palette: Palette) -> Self {
        let slots = if palette == Palette::Ansi16 {
            MEMO_SLOTS
        } else {
            0
        };
        Quantizer {
            palette,
            ansi16_mixes: vec![(0, 0, 0, 0); slots],
        }
    }

    /// Same result as [`quantize`] with this quantizer's palette.
    pub fn quantize(&mut self, rgb: [u8; 3], threshold: u8) -> u8 {
        if self.palette == Palette::Xterm256 {
            return quantize_xterm256(rgb, threshold);
        }
        let key = VALID | (rgb[0] as u32) << 16 | (rgb[1] as u32) << 8 | rgb[2] as u32;
        let slot = (key.wrapping_mul(0x9E37_79B1) >> 20) as usize % MEMO_SLOTS;
        let entry = &mut self.ansi16_mixes[slot];
        if entry.0 != key {
            let (near, far, t) = best_ansi16_mix(rgb);
            *entry = (key, near, far, t);
        }
        choose((entry.1, entry.2, entry.3), threshold)
    }
}

/// The nearest ANSI colour, the partner whose mix with it best reproduces `rgb`, and the mix fraction.
fn best_ansi16_mix(rgb: [u8; 3]) -> (u8, u8, u8) {
    let mut candidates = [(0u8, [0u8; 3]); 16];
    for (i, slot) in candidates.iter_mut().enumerate() {
        *slot = (i as u8, ANSI16[i]);
    }
    best_mix(rgb, &candidates, MIX_VARIANCE_PENALTY)
}

/// Of `candidates` (palette index, colour): the nearest to `rgb`, the partner whose mix with it
/// best reproduces `rgb` once the mix's visible spread is counted, and the mix fraction (0..=255).
fn best_mix(rgb: [u8; 3], candidates: &[(u8, [u8; 3])], penalty: f32) -> (u8, u8, u8) {
    let &(near, near_rgb) = candidates
        .iter()
        .min_by_key(|(_, c)| distance2(rgb, *c))
        .expect("candidates");
    let p1 = near_rgb.map(|v| v as f32);
    let c = rgb.map(|v| v as f32);
    let e = [c[0] - p1[0], c[1] - p1[1], c[2] - p1[2]];
    let mut best = (near, 0.0f32, dot_w(e, e));
    for &(far, p2) in candidates {
        let d = [
            p2[0] as f32 - p1[0],
            p2[1] as f32 - p1[1],
            p2[2] as f32 - p1[2],
        ];
        let dd = dot_w(d, d);
        if dd == 0.0 {
            continue;
        }
        let t = (dot_w(e, d) / dd).clamp(0.0, 1.0);
        let r = [e[0] - t * d[0], e[1] - t * d[1], e[2] - t * d[2]];
        let cost = dot_w(r, r) + penalty * t * (1.0 - t) * dd;
        if cost < best.2 {
            best = (far, t, cost);
        }
    }
    (near, best.0, (best.1 * 255.0).round() as u8)
}

fn dot_w(a: [f32; 3], b: [f32; 3]) -> f32 {
    (0..3).map(|i| WEIGHTS[i] as f32 * a[i] * b[i]).sum()
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

    #[test]
    fn bracket_ends_are_exact() {
        assert_eq!(bracket(&CUBE_LEVELS, 0), (0, 0));
        assert_eq!(bracket(&CUBE_LEVELS, 95), (1, 0));
        assert_eq!(bracket(&CUBE_LEVELS, 255), (4, 255));
    }

    #[test]
    fn memoised_quantizer_agrees_with_quantize() {
        let mut quantizer = Quantizer::new(Palette::Ansi16);
        for v in (0..=255u32).step_by(3) {
            for rgb in [[v as u8, 40, 200], [10, v as u8, v as u8], [v as u8; 3]] {
                for threshold in [2, 100, 254] {
                    assert_eq!(
                        quantizer.quantize(rgb, threshold),
                        quantize(rgb, Palette::Ansi16, threshold)
                    );
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
