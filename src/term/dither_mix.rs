//! A dither mix: up to three palette entries shown in fractions that average to a colour, and the
//! search for the mix that looks most like a given colour.
//!
//! Colours are compared in weighted sRGB with an extra weight on the part of an error that is off
//! the grey axis, so a dull orange is not rounded to the grey nearest it in RGB: it keeps its hue
//! as red, yellow and grey in the right proportions. f32: the values are bytes and the sums small.

use super::palette::WEIGHTS;

/// Palette entries and the ordered-dither thresholds that pick them: a pixel whose threshold is
/// below `until[0]` shows `entries[1]`, one below `until[1]` shows `entries[2]`, any other the
/// nearest entry, `entries[0]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DitherMix {
    entries: [u8; 3],
    until: [u8; 2],
}

impl DitherMix {
    /// The entry a pixel with dither `threshold` (0..=255) shows.
    pub fn pick(self, threshold: u8) -> u8 {
        if threshold < self.until[0] {
            self.entries[1]
        } else if threshold < self.until[1] {
            self.entries[2]
        } else {
            self.entries[0]
        }
    }
}

/// How mixes are judged.
#[derive(Clone, Copy, Debug)]
pub struct MixRules {
    /// How much a mix's visible spread costs, as a fraction of its variance: keeps the dither from
    /// mixing far-apart colours (red and cyan for grey) when closer ones do, and from breaking a
    /// dark background into a checker. At 1 no mix would ever win (a mix's mean squared error is
    /// its residual plus its whole variance).
    pub spread_penalty: f32,
    /// How much more an error off the grey axis (a change of hue or saturation) counts than one
    /// along it.
    pub hue_weight: f32,
    /// Whether three entries may mix, or two at most.
    pub three: bool,
}

/// Of `candidates` (palette index, colour): the mix around the nearest that best reproduces `rgb`
/// once its visible spread is counted. The fractions make the mix's average as near `rgb` as the
/// entries allow; the spread penalty only decides between mixes.
pub fn best_dither_mix(rgb: [u8; 3], candidates: &[(u8, [u8; 3])], rules: MixRules) -> DitherMix {
    let metric = Metric {
        hue_weight: rules.hue_weight,
    };
    let target = rgb.map(f32::from);
    let error = |c: [u8; 3]| {
        let e = sub(target, c.map(f32::from));
        metric.dot(e, e)
    };
    let &(near, near_rgb) = candidates
        .iter()
        .min_by(|a, b| error(a.1).total_cmp(&error(b.1)))
        .expect("candidates");
    let fit = Fit::new(target, near_rgb, candidates, metric);
    let mut best = (fit.ee, [near; 3], [0.0f32; 2]);
    // The partners' two-entry costs, best first: a three-entry mix is sought among the best few.
    let mut partners = [(f32::INFINITY, 0usize); MAX_CANDIDATES];
    for (i, &(far, _)) in candidates.iter().enumerate() {
        if let Some((cost, t)) = fit.two(i, rules.spread_penalty) {
            partners[i] = (cost, i);
            if cost < best.0 {
                best = (cost, [near, far, far], [t, 0.0]);
            }
        }
    }
    if rules.three {
        let partners = &mut partners[..candidates.len()];
        partners.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let few = &partners[..THREE_AMONG.min(partners.len())];
        for (k, &(_, i)) in few.iter().enumerate() {
            for &(_, j) in &few[k + 1..] {
                if let Some((cost, t)) = fit.three(i, j, rules.spread_penalty)
                    && cost < best.0
                {
                    best = (cost, [near, candidates[i].0, candidates[j].0], t);
                }
            }
        }
    }
    let (_, entries, [t1, t2]) = best;
    let until0 = (t1 * 255.0).round();
    DitherMix {
        entries,
        until: [until0 as u8, (until0 + t2 * 255.0).round().min(255.0) as u8],
    }
}

/// The products a mix's cost is made of, with the nearest entry as origin: `e` is the colour,
/// `d[i]` candidate `i`, both as offsets from the nearest.
struct Fit {
    offsets: [[f32; 3]; MAX_CANDIDATES],
    metric: Metric,
    /// e·e, e·d[i] and d[i]·d[i] in the metric; d[i]·d[i] in plain weighted sRGB, for the spread.
    ee: f32,
    ed: [f32; MAX_CANDIDATES],
    dd: [f32; MAX_CANDIDATES],
    dd_weighted: [f32; MAX_CANDIDATES],
}

const MAX_CANDIDATES: usize = 16;

/// How many of the best two-entry partners a three-entry mix is sought among: a colour between
/// grey and two hues has both hues among its best partners.
const THREE_AMONG: usize = 5;

impl Fit {
    fn new(target: [f32; 3], near: [u8; 3], candidates: &[(u8, [u8; 3])], metric: Metric) -> Fit {
        assert!(
            candidates.len() <= MAX_CANDIDATES,
            "a palette of at most 16 candidates"
        );
        let origin = near.map(f32::from);
        let e = sub(target, origin);
        let mut fit = Fit {
            offsets: [[0.0; 3]; MAX_CANDIDATES],
            metric,
            ee: metric.dot(e, e),
            ed: [0.0; MAX_CANDIDATES],
            dd: [0.0; MAX_CANDIDATES],
            dd_weighted: [0.0; MAX_CANDIDATES],
        };
        for (i, (_, c)) in candidates.iter().enumerate() {
            let d = sub(c.map(f32::from), origin);
            fit.offsets[i] = d;
            fit.ed[i] = metric.dot(e, d);
            fit.dd[i] = metric.dot(d, d);
            fit.dd_weighted[i] = dot_w(d, d);
        }
        fit
    }

    /// The cost and fraction of the nearest mixed with candidate `i`, if it differs from the nearest.
    fn two(&self, i: usize, spread_penalty: f32) -> Option<(f32, f32)> {
        if self.dd[i] == 0.0 {
            return None;
        }
        let t = (self.ed[i] / self.dd[i]).clamp(0.0, 1.0);
        let residual = self.ee - 2.0 * t * self.ed[i] + t * t * self.dd[i];
        let variance = t * (1.0 - t) * self.dd_weighted[i];
        Some((residual + spread_penalty * variance, t))
    }

    /// The cost and fractions of the nearest mixed with candidates `i` and `j`, if the best fit
    /// lies strictly inside their triangle (on an edge it is a two-entry mix).
    fn three(&self, i: usize, j: usize, spread_penalty: f32) -> Option<(f32, [f32; 2])> {
        let (a, c) = (self.dd[i], self.dd[j]);
        let b = self.metric.dot(self.offsets[i], self.offsets[j]);
        let det = a * c - b * b;
        if det <= 1e-3 * a * c {
            return None;
        }
        let (p, q) = (self.ed[i], self.ed[j]);
        let [t1, t2] = [(c * p - b * q) / det, (a * q - b * p) / det];
        if !(t1 > 0.0 && t2 > 0.0 && t1 + t2 < 1.0) {
            return None;
        }
        let residual =
            self.ee - 2.0 * (t1 * p + t2 * q) + t1 * t1 * a + 2.0 * t1 * t2 * b + t2 * t2 * c;
        let (wa, wc) = (self.dd_weighted[i], self.dd_weighted[j]);
        let wb = dot_w(self.offsets[i], self.offsets[j]);
        let mean2 = t1 * t1 * wa + 2.0 * t1 * t2 * wb + t2 * t2 * wc;
        let variance = t1 * wa + t2 * wc - mean2;
        Some((residual + spread_penalty * variance, [t1, t2]))
    }
}

/// The inner product colours are compared with: weighted sRGB plus `hue_weight` times the product
/// of the parts off the grey axis.
#[derive(Clone, Copy)]
struct Metric {
    hue_weight: f32,
}

impl Metric {
    fn dot(self, a: [f32; 3], b: [f32; 3]) -> f32 {
        let (mean_a, mean_b) = ((a[0] + a[1] + a[2]) / 3.0, (b[0] + b[1] + b[2]) / 3.0);
        let off_grey = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] - 3.0 * mean_a * mean_b;
        dot_w(a, b) + self.hue_weight * off_grey
    }
}

fn dot_w(a: [f32; 3], b: [f32; 3]) -> f32 {
    (0..3).map(|i| WEIGHTS[i] as f32 * a[i] * b[i]).sum()
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn add(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
        [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
    }

    fn scale(a: [f32; 3], s: f32) -> [f32; 3] {
        a.map(|v| v * s)
    }

    const PRIMARIES: [(u8, [u8; 3]); 4] = [
        (0, [0, 0, 0]),
        (1, [255, 0, 0]),
        (2, [0, 255, 0]),
        (3, [255, 255, 255]),
    ];

    fn shown_average(mix: DitherMix) -> [f32; 3] {
        let mut sum = [0.0f32; 3];
        for threshold in 0..=255u8 {
            let c = PRIMARIES[mix.pick(threshold) as usize].1;
            sum = add(sum, c.map(f32::from));
        }
        scale(sum, 1.0 / 256.0)
    }

    #[test]
    fn a_colour_inside_a_triangle_of_entries_is_matched_by_three() {
        let rules = MixRules {
            spread_penalty: 0.0,
            hue_weight: 0.0,
            three: true,
        };
        let mix = best_dither_mix([128, 64, 0], &PRIMARIES, rules);
        let shown = shown_average(mix);
        let error = sub(shown, [128.0, 64.0, 0.0]);
        assert!(
            error.iter().all(|v| v.abs() < 1.5),
            "{mix:?} shows {shown:?}"
        );
    }

    #[test]
    fn two_entries_at_most_when_three_are_not_allowed() {
        let rules = MixRules {
            spread_penalty: 0.0,
            hue_weight: 0.0,
            three: false,
        };
        let mix = best_dither_mix([128, 64, 0], &PRIMARIES, rules);
        let used: std::collections::BTreeSet<u8> = (0..=255).map(|t| mix.pick(t)).collect();
        assert_eq!(used.len(), 2, "{mix:?}");
    }

    #[test]
    fn an_entry_shows_flat() {
        for (index, rgb) in PRIMARIES {
            let rules = MixRules {
                spread_penalty: 0.5,
                hue_weight: 9.0,
                three: true,
            };
            let mix = best_dither_mix(rgb, &PRIMARIES, rules);
            assert!((0..=255).all(|t| mix.pick(t) == index), "{mix:?}");
        }
    }
}
